// Definite assignment over structured control flow: each block is walked
// with the set of registers that every lane reaching it has written.
#include "ir/assigned.h"

#include "ir/flow.h"

namespace glslrun::ir {
namespace {

bool ends_in_exit(const Block& block) { return !block.empty() && flow::is_exit(block.back().kind); }

struct Assignment {
    std::vector<bool> maybe_unset;

    void read(Reg r, const std::vector<bool>& set) {
        if (r < set.size() && !set[r]) maybe_unset[r] = true;
    }

    void block(const Block& b, std::vector<bool>& set) {
        for (const Node& n : b) node(n, set);
    }

    void node(const Node& n, std::vector<bool>& set) {
        flow::for_each_read(n, [&](Reg r) { read(r, set); });
        switch (n.kind) {
        case NodeKind::Instr:
            // One store_ind writes one element per lane: no element is definitely set.
            if (!flow::writes_range(n.instr.op))
                flow::for_each_write(n.instr, [&](Reg r) {
                    if (r < set.size()) set[r] = true;
                });
            break;
        case NodeKind::If: {
            std::vector<bool> then_set = set, else_set = set;
            block(n.body, then_set);
            block(n.alt, else_set);
            // Lanes that leave in a branch never reach the join.
            if (ends_in_exit(n.body)) set = else_set;
            else if (ends_in_exit(n.alt)) set = then_set;
            else for (size_t r = 0; r < set.size(); ++r) set[r] = then_set[r] && else_set[r];
            break;
        }
        case NodeKind::Loop: {
            // Visited once with the entry set: a read that depends on an
            // earlier iteration's write stays "maybe unset". The loop may
            // end before any write, so the exit keeps the entry set.
            std::vector<bool> body_set = set, cont_set = set;
            block(n.body, body_set);
            block(n.alt, cont_set);
            break;
        }
        case NodeKind::Scope:
            if (!flow::returns_early(n.body)) {
                block(n.body, set);
            } else {
                std::vector<bool> inner = set;
                block(n.body, inner);
            }
            break;
        default: break;  // Call: the callee's writes are not counted as definite
        }
    }
};

}  // namespace

std::vector<bool> maybe_read_unset(const Shader& shader) {
    size_t regs = shader.regs.size();
    Assignment a{std::vector<bool>(regs, false)};
    std::vector<bool> set(regs, false);
    a.block(shader.prologue, set);
    a.block(shader.body, set);
    for (const Function& f : shader.functions) {
        std::vector<bool> none(regs, false);
        a.block(f.body, none);
    }
    return a.maybe_unset;
}

}  // namespace glslrun::ir
