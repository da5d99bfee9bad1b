// runtime/jit/charges.h: the charges made at a block's entry.
#include "runtime/jit/charges.h"

#include "ir/flow.h"

namespace glslrun::rt::jit {

using ir::NodeKind;

Charges::Charges(const ir::Shader& shader) : output_(shader.regs.size()) {
    for (const ir::Binding& b : shader.outputs)
        for (uint32_t i = 0; i < b.count; ++i)
            if (b.first + i < output_.size()) output_[b.first + i] = true;
}

bool Charges::writes_output(const ir::Instr& instr) const {
    bool writes = false;
    ir::flow::for_each_write(instr, [&](ir::Reg r) { writes = writes || (r < output_.size() && output_[r]); });
    return writes;
}

bool Charges::passes(const ir::Node& node) {
    if (node.kind == NodeKind::Instr) return !writes_output(node.instr);
    if (node.kind != NodeKind::If && node.kind != NodeKind::Scope) return false;
    auto [at, fresh] = passes_.try_emplace(&node, false);
    if (!fresh) return at->second;
    // (A Return of a Scope nested in an If would be harmless: refused, rare.)
    const bool in_if = node.kind == NodeKind::If;
    bool ok = true;
    auto check = [&](const ir::Node& n) {
        switch (n.kind) {
        case NodeKind::Instr: ok = ok && !writes_output(n.instr); break;
        case NodeKind::Break: case NodeKind::Continue: case NodeKind::Return: ok = ok && !in_if; break;
        case NodeKind::Discard: case NodeKind::Loop: case NodeKind::Call: ok = false; break;
        case NodeKind::If: case NodeKind::Scope: break;
        }
    };
    ir::flow::walk(node.body, check);
    ir::flow::walk(node.alt, check);
    at->second = ok;
    return ok;
}

uint64_t Charges::on_entry(const ir::Block& block) {
    uint64_t total = block.size();
    for (const ir::Node& n : block) {
        // Reached under a nonzero mask: run_call enters its block, which charges.
        if (n.kind == NodeKind::Scope && !n.body.empty()) {
            total += on_entry(n.body);
            charged_.insert(&n.body);
        }
        if (!passes(n)) break;
    }
    return total;
}

}  // namespace glslrun::rt::jit
