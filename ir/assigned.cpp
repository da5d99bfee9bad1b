// Definite assignment over structured control flow: each block is walked
// with the set of registers that every lane reaching it has written.
#include "ir/assigned.h"

#include <cstddef>
#include <cstdint>
#include <utility>

#include "ir/flow.h"

namespace glslrun::ir {
namespace {

bool ends_in_exit(const Block& block) { return !block.empty() && flow::is_exit(block.back().kind); }

// The set of definitely written registers, with a log of what was added:
// a nested block starts from its parent's set and is undone after, so an If
// costs what its branches write, not a copy of the set (a copy made a chain
// of 10,000 `if`s quadratic).
struct Assignment {
    std::vector<bool> maybe_unset;
    std::vector<bool> set;
    std::vector<Reg> added;  // registers set, in order
    std::vector<uint64_t> in_other;  // == generation: set by the other branch too
    uint64_t generation = 0;

    explicit Assignment(size_t regs) : maybe_unset(regs, false), set(regs, false), in_other(regs, 0) {}

    void read(Reg r) {
        if (r < set.size() && !set[r]) maybe_unset[r] = true;
    }
    void write(Reg r) {
        if (r < set.size() && !set[r]) {
            set[r] = true;
            added.push_back(r);
        }
    }
    // Unsets what was set since `mark` and returns it.
    std::vector<Reg> undo(size_t mark) {
        std::vector<Reg> undone(added.begin() + std::ptrdiff_t(mark), added.end());
        for (Reg r : undone) set[r] = false;
        added.resize(mark);
        return undone;
    }

    void block(const Block& b) {
        for (const Node& n : b) node(n);
    }

    void branches(const Node& n) {
        size_t mark = added.size();
        block(n.body);
        std::vector<Reg> then_set = undo(mark);
        block(n.alt);
        // Lanes that leave in a branch never reach the join.
        if (ends_in_exit(n.body)) return;
        std::vector<Reg> else_set = undo(mark);
        if (ends_in_exit(n.alt)) {
            for (Reg r : then_set) write(r);
            return;
        }
        ++generation;
        for (Reg r : else_set) in_other[r] = generation;
        for (Reg r : then_set)
            if (in_other[r] == generation) write(r);
    }

    void node(const Node& n) {
        flow::for_each_read(n, [&](Reg r) { read(r); });
        switch (n.kind) {
        case NodeKind::Instr:
            // One store_ind writes one element per lane: no element is definitely set.
            if (!flow::writes_range(n.instr.op)) flow::for_each_write(n.instr, [&](Reg r) { write(r); });
            break;
        case NodeKind::If: branches(n); break;
        case NodeKind::Loop: {
            // Visited once with the entry set: a read that depends on an
            // earlier iteration's write stays "maybe unset". The loop may
            // end before any write, so the exit keeps the entry set.
            size_t mark = added.size();
            block(n.body);
            undo(mark);
            block(n.alt);
            undo(mark);
            break;
        }
        case NodeKind::Scope:
            if (!flow::returns_early(n.body)) {
                block(n.body);
            } else {
                size_t mark = added.size();
                block(n.body);
                undo(mark);
            }
            break;
        default: break;  // Call: the callee's writes are not counted as definite
        }
    }
};

}  // namespace

std::vector<bool> maybe_read_unset(const Shader& shader) {
    Assignment a(shader.regs.size());
    a.block(shader.prologue);
    a.block(shader.body);
    for (const Function& f : shader.functions) {
        a.undo(0);
        a.block(f.body);
    }
    return std::move(a.maybe_unset);
}

}  // namespace glslrun::ir
