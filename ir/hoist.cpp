// Hoisting of uniform code: an instruction whose value depends only on
// uniforms and constants is the same in every lane of every batch of a draw,
// so it moves into Shader::prologue, which the interpreter runs once for all
// lanes when it is built (uniforms do not change during its life).
//
// An instruction moves when
//   - it is pure and lane-wise (Alu, konst, mov, sel, uniform, uniform_ind),
//   - its operands were all hoisted before it,
//   - its destination is written nowhere else, is no input or output, and
//     is not addressed by position (indexed ranges, tex blocks, derivatives),
//   - and every read of the destination happens, in each lane, after the lane
//     ran the instruction (definite assignment). A read that may come first
//     would see an older value, which hoisting would change.
// Then the prologue computes exactly the bits that each lane computed before,
// with the same operations, and a lane cannot observe the difference.
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

bool hoistable_op(Op op) {
    return op_info(op).kind == OpKind::Alu || op == Op::konst || op == Op::mov || op == Op::sel ||
           op == Op::uniform || op == Op::uniform_ind;
}

bool ends_in_exit(const Block& block) { return !block.empty() && flow::is_exit(block.back().kind); }

// Marks the registers that some lane may read before writing them, walking
// each block with the set of registers every lane reaching it has written.
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
            if (!flow::writes_range(n.instr.op)) flow::for_each_write(n.instr, [&](Reg r) { set[r] = true; });
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

struct Hoister {
    Shader& shader;
    std::vector<uint32_t> writes;
    std::vector<bool> pinned;   // never hoisted: see the file comment
    std::vector<bool> hoisted;  // destination of a hoisted instruction

    void pin(Reg r) {
        if (r < pinned.size()) pinned[r] = true;
    }

    void survey(const Block& block) {
        flow::walk(block, [&](const Node& n) {
            if (n.kind != NodeKind::Instr) return;
            const Instr& in = n.instr;
            flow::for_each_write(in, [&](Reg r) { ++writes[r]; });
            if (flow::reads_range(in.op) || flow::writes_range(in.op)) flow::for_each_in_range(in, [&](Reg r) { pin(r); });
            if (in.op == Op::tex) {
                flow::for_each_tex_operand(in, [&](Reg r) { pin(r); });
                flow::for_each_tex_result(in, [&](Reg r) { pin(r); });
            }
            if (in.op == Op::ddx || in.op == Op::ddy) pin(in.src[0]);
        });
    }

    bool can_hoist(const Instr& in) const {
        if (!hoistable_op(in.op) || in.dst == kNoReg || in.dst >= pinned.size()) return false;
        if (pinned[in.dst] || writes[in.dst] != 1) return false;
        bool operands_hoisted = true;
        flow::for_each_operand(in, [&](Reg r) { operands_hoisted = operands_hoisted && r < hoisted.size() && hoisted[r]; });
        return operands_hoisted;
    }

    // Moves the hoistable instructions of `block` (nested ones too) to the
    // prologue, in program order, so operands come before their readers.
    void extract(Block& block) {
        size_t out = 0;
        for (size_t i = 0; i < block.size(); ++i) {
            Node& n = block[i];
            if (n.kind == NodeKind::Instr && can_hoist(n.instr)) {
                hoisted[n.instr.dst] = true;
                shader.prologue.push_back(std::move(n));
                continue;
            }
            extract(n.body);
            extract(n.alt);
            if (out != i) block[out] = std::move(n);
            ++out;
        }
        block.resize(out);
    }
};

}  // namespace

void hoist_uniform_code(Shader& shader) {
    size_t regs = shader.regs.size();
    Hoister h{shader, std::vector<uint32_t>(regs, 0), std::vector<bool>(regs, false), std::vector<bool>(regs, false)};
    h.survey(shader.prologue);
    h.survey(shader.body);
    for (const Function& f : shader.functions) h.survey(f.body);
    for (const auto* list : {&shader.inputs, &shader.outputs})
        for (const Binding& b : *list)
            for (uint32_t i = 0; i < b.count; ++i) h.pin(b.first + i);

    Assignment a{std::vector<bool>(regs, false)};
    std::vector<bool> set(regs, false);
    for (const Node& n : shader.prologue) flow::for_each_write(n.instr, [&](Reg r) { set[r] = h.hoisted[r] = true; });
    a.block(shader.body, set);
    // Function bodies may run before or after anything: all their reads count as maybe unset.
    for (const Function& f : shader.functions) {
        std::vector<bool> none(regs, false);
        a.block(f.body, none);
    }
    for (size_t r = 0; r < regs; ++r)
        if (a.maybe_unset[r]) h.pinned[r] = true;
    h.extract(shader.body);
}

}  // namespace glslrun::ir
