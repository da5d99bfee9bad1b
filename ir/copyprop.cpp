// Copy propagation: after `mov d, s`, reads of d become reads of s until
// either is written again. Same conservativeness as the folder: facts flow
// through straight-line code, nested blocks see a copy, and joins forget
// every register the nested block may write (store_ind: its whole range).
#include <unordered_map>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// copy_of[d] = s: d currently holds the same value as s.
struct Copies {
    std::unordered_map<Reg, Reg> copy_of;

    Reg resolve(Reg r) const {
        auto it = copy_of.find(r);
        return it == copy_of.end() ? r : it->second;
    }
    void kill(Reg r) {
        copy_of.erase(r);
        for (auto it = copy_of.begin(); it != copy_of.end();)
            it = it->second == r ? copy_of.erase(it) : std::next(it);
    }
    void kill(const flow::Writes& writes) {
        if (writes.calls) {
            copy_of.clear();
            return;
        }
        for (Reg r : writes.regs) kill(r);
    }
};

void rewrite_operands(Instr& in, const Copies& copies) {
    int arity = op_info(in.op).arity;
    for (int k = 0; k < arity; ++k)
        if (in.src[k] != kNoReg) in.src[k] = copies.resolve(in.src[k]);
}

void instr(Instr& in, Copies& copies) {
    rewrite_operands(in, copies);
    flow::for_each_write(in, [&](Reg r) { copies.kill(r); });
    if (in.op == Op::mov && in.src[0] != in.dst) copies.copy_of[in.dst] = in.src[0];
}

void run_block(Block& block, Copies& copies) {
    for (Node& n : block) {
        switch (n.kind) {
        case NodeKind::Instr: instr(n.instr, copies); break;
        case NodeKind::If: {
            n.cond = copies.resolve(n.cond);
            Copies then_copies = copies, else_copies = copies;
            run_block(n.body, then_copies);
            run_block(n.alt, else_copies);
            copies.kill(flow::writes_of(n.body));
            copies.kill(flow::writes_of(n.alt));
            break;
        }
        case NodeKind::Loop: {
            copies.kill(flow::writes_of(n.body));
            copies.kill(flow::writes_of(n.alt));
            Copies body_copies = copies, cont_copies = copies;
            run_block(n.body, body_copies);
            run_block(n.alt, cont_copies);
            break;
        }
        case NodeKind::Scope:
            if (flow::returns_early(n.body)) {
                Copies inner = copies;
                run_block(n.body, inner);
                copies.kill(flow::writes_of(n.body));
            } else {
                run_block(n.body, copies);
            }
            break;
        case NodeKind::Call: copies.copy_of.clear(); break;
        default: break;
        }
    }
}

}  // namespace

void propagate_copies(Shader& shader) {
    for (Function& f : shader.functions) {
        Copies copies;
        run_block(f.body, copies);
    }
    Copies copies;
    run_block(shader.body, copies);
}

}  // namespace glslrun::ir
