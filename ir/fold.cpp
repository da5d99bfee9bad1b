// Constant folding. Registers are not SSA, so a register is known to hold a
// constant at a point only when its reaching definition is known: facts flow
// through straight-line code, a nested block starts from its parent's facts,
// and at the join every register the block may write is forgotten
// (ir/scoped_facts.h: linear in the IR). Facts hold for the
// lanes active at that point, which are the only lanes an instruction there
// touches.
#include <algorithm>
#include <cstddef>
#include <unordered_map>

#include "ir/alu_eval.h"
#include "ir/flow.h"
#include "ir/passes.h"
#include "ir/scoped_facts.h"

namespace glslrun::ir {
namespace {

// The constant each register holds, while it holds it (ir/scoped_facts.h).
using Facts = RegisterFacts<uint32_t>;

// Same clamp as the interpreter's indexed accesses.
uint32_t clamp_index(uint32_t raw, uint32_t count) {
    int32_t i = static_cast<int32_t>(raw);
    if (i < 0) return 0;
    return std::min(static_cast<uint32_t>(i), count - 1);
}

void make_konst(Instr& in, uint32_t value) {
    in.op = Op::konst;
    in.src[0] = in.src[1] = in.src[2] = kNoReg;
    in.imm[0] = value;
    in.imm[1] = in.imm[2] = 0;
}

void make_mov(Instr& in, Reg dst, Reg src) {
    in.op = Op::mov;
    in.dst = dst;
    in.src[0] = src;
    in.src[1] = in.src[2] = kNoReg;
    in.imm[0] = in.imm[1] = in.imm[2] = 0;
}

struct Folder {
    const Shader& shader;
    const FoldOptions& options;

    const uint32_t* known(const Facts& facts, Reg r) const { return facts.find(r); }

    // Indexed accesses with a constant index become direct ones.
    void fold_indexed(Instr& in, const Facts& facts) {
        const uint32_t* index = known(facts, in.src[0]);
        if (!index) return;
        uint32_t element = in.imm[0] + clamp_index(*index, in.imm[1]) * in.imm[2];
        if (in.op == Op::load_ind) {
            make_mov(in, in.dst, element);
        } else if (in.op == Op::store_ind) {
            make_mov(in, element, in.src[1]);
        } else if (in.op == Op::uniform_ind) {
            in.op = Op::uniform;
            in.src[0] = kNoReg;
            in.imm[0] = element;
            in.imm[1] = in.imm[2] = 0;
        }
    }

    void instr(Instr& in, Facts& facts) {
        if (in.op == Op::load_ind || in.op == Op::store_ind || in.op == Op::uniform_ind) fold_indexed(in, facts);
        if (in.op == Op::uniform && options.uniforms && in.imm[0] < options.uniforms->size())
            make_konst(in, (*options.uniforms)[in.imm[0]]);
        if (in.op == Op::sel) {
            if (const uint32_t* c = known(facts, in.src[0])) make_mov(in, in.dst, *c ? in.src[1] : in.src[2]);
        }
        if (in.op == Op::mov) {
            if (const uint32_t* v = known(facts, in.src[0])) make_konst(in, *v);
        } else if (alu::is_alu(in.op) && !(options.approximated & fast_class_bit(op_info(in.op).fast))) {
            int arity = op_info(in.op).arity;
            uint32_t values[3] = {0, 0, 0};
            bool all_known = true;
            for (int k = 0; k < arity && all_known; ++k) {
                const uint32_t* v = known(facts, in.src[k]);
                all_known = v != nullptr;
                if (v) values[k] = *v;
            }
            if (all_known) make_konst(in, alu::eval(in.op, values[0], values[1], values[2]));
        }
        flow::for_each_write(in, [&](Reg r) {
            if (in.op == Op::konst && r == in.dst) facts.write(r, in.imm[0]);
            else facts.write(r);
        });
    }

    // Replaces block[i] (an If with a known condition) by the taken branch.
    void splice_taken_branch(Block& block, size_t i, bool cond) {
        Block taken = std::move(cond ? block[i].body : block[i].alt);
        block.erase(block.begin() + std::ptrdiff_t(i));
        block.insert(block.begin() + std::ptrdiff_t(i), std::make_move_iterator(taken.begin()),
                     std::make_move_iterator(taken.end()));
    }

    void run_block(Block& block, Facts& facts) {
        for (size_t i = 0; i < block.size();) {
            Node& n = block[i];
            switch (n.kind) {
            case NodeKind::Instr: instr(n.instr, facts); break;
            case NodeKind::If: {
                if (const uint32_t* c = known(facts, n.cond)) {
                    splice_taken_branch(block, i, *c != 0);
                    continue;  // the spliced nodes are folded next
                }
                size_t before = facts.mark();
                BlockWrites written;
                run_block(n.body, facts);
                facts.undo(before, written);
                run_block(n.alt, facts);
                facts.undo(before, written);
                facts.forget(written);
                break;
            }
            case NodeKind::Loop: {
                // Later iterations see the loop's own writes.
                facts.forget(flow::writes_of(n.body));
                facts.forget(flow::writes_of(n.alt));
                size_t before = facts.mark();
                BlockWrites ignored;  // already forgotten
                run_block(n.body, facts);
                facts.undo(before, ignored);
                run_block(n.alt, facts);
                facts.undo(before, ignored);
                break;
            }
            case NodeKind::Scope:
                if (flow::returns_early(n.body)) {
                    size_t before = facts.mark();
                    BlockWrites written;
                    run_block(n.body, facts);
                    facts.undo(before, written);
                    facts.forget(written);
                } else {
                    run_block(n.body, facts);
                }
                break;
            case NodeKind::Call: facts.forget_all(); break;
            default: break;
            }
            ++i;
        }
    }
};

}  // namespace

void fold_constants(Shader& shader, const FoldOptions& options) {
    FlushDenormals ftz;
    Folder folder{shader, options};
    for (Function& f : shader.functions) {
        Facts facts(shader.regs.size());
        folder.run_block(f.body, facts);
    }
    Facts facts(shader.regs.size());
    folder.run_block(shader.body, facts);
}

}  // namespace glslrun::ir
