// Dead code elimination: removes instructions whose results are never read
// anywhere in the shader (operands, If conditions, load_ind ranges, output
// bindings), code after an unconditional exit, and empty If/Scope nodes;
// repeats until nothing changes.
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

struct Eliminator {
    Shader& shader;
    std::vector<bool> read;
    bool changed = false;

    void mark(Reg r) {
        if (r < read.size()) read[r] = true;
    }

    void collect_reads() {
        read.assign(shader.regs.size(), false);
        auto visit = [&](const Node& n) { flow::for_each_read(n, [&](Reg r) { mark(r); }); };
        flow::walk(shader.prologue, visit);
        flow::walk(shader.body, visit);
        for (const Function& f : shader.functions) flow::walk(f.body, visit);
        for (const Binding& b : shader.outputs)
            for (uint32_t i = 0; i < b.count; ++i) mark(b.first + i);
    }

    bool dead(const Instr& in) const {
        if (in.op == Op::mov && in.src[0] == in.dst) return true;
        if (has(in.op, OpProp::Effect)) return false;  // check_undef: its effect is the record it makes
        bool any_read = false;
        flow::for_each_write(in, [&](Reg r) { any_read = any_read || (r < read.size() && read[r]); });
        return !any_read;
    }

    bool removable(const Node& n) const {
        switch (n.kind) {
        case NodeKind::Instr: return dead(n.instr);
        case NodeKind::If: return n.body.empty() && n.alt.empty();
        case NodeKind::Scope: return n.body.empty();
        default: return false;
        }
    }

    void sweep(Block& block) {
        size_t out = 0;
        bool exited = false;
        for (size_t i = 0; i < block.size(); ++i) {
            Node& n = block[i];
            if (exited) continue;  // unreachable: an exit came before it
            sweep(n.body);
            sweep(n.alt);
            if (removable(n)) continue;
            exited = flow::is_exit(n.kind);
            if (out != i) block[out] = std::move(n);
            ++out;
        }
        if (out != block.size()) {
            changed = true;
            block.resize(out);
        }
    }

    bool pass() {
        changed = false;
        collect_reads();
        sweep(shader.prologue);
        sweep(shader.body);
        for (Function& f : shader.functions) sweep(f.body);
        return changed;
    }
};

}  // namespace

void eliminate_dead_code(Shader& shader) {
    Eliminator e{shader, {}};
    while (e.pass()) {
    }
}

}  // namespace glslrun::ir
