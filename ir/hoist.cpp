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

#include "ir/assigned.h"
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// A lane's result from its own operands and the uniforms alone.
bool hoistable_op(Op op) { return has(op, OpProp::Pure) && !has(op, OpProp::CrossLane); }

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
            flow::for_each_write(in, [&](Reg r) {
                if (r < writes.size()) ++writes[r];
            });
            if (flow::reads_range(in.op) || flow::writes_range(in.op)) flow::for_each_in_range(in, [&](Reg r) { pin(r); });
            if (flow::texture(in.op)) {
                flow::for_each_tex_operand(in, [&](Reg r) { pin(r); });
                flow::for_each_tex_result(in, [&](Reg r) { pin(r); });
            }
            if (has(in.op, OpProp::CrossLane)) pin(in.src[0]);
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

    for (const Node& n : shader.prologue) flow::for_each_write(n.instr, [&](Reg r) { h.hoisted[r] = true; });
    std::vector<bool> unset = maybe_read_unset(shader);
    for (size_t r = 0; r < regs; ++r)
        if (unset[r]) h.pin(Reg(r));
    h.extract(shader.body);
    for (Function& f : shader.functions) h.extract(f.body);
}

}  // namespace glslrun::ir
