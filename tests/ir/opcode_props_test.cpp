// The opcode table's property columns (ir/opcodes.def) against what the ops
// compute, and the passes against the columns: a property given to an op
// that lacks it, or left off one that has it, fails here.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ir/alu_eval.h"
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

// Operand words of each type class: signed zeros, infinities, a denormal,
// a quiet NaN; integer extremes; both bools.
std::vector<uint32_t> samples(ir::TypeClass c) {
    if (c == ir::TypeClass::I)
        return {0u, 1u, bits(-1), 7u, bits(-7), bits(INT32_MAX), bits(INT32_MIN), 0x12345678u};
    if (c == ir::TypeClass::B) return {0u, 1u};
    const float inf = std::numeric_limits<float>::infinity();
    return {bits(0.0f), bits(-0.0f), bits(1.0f), bits(-2.5f), bits(inf), bits(-inf), bits(1e-40f),
            bits(3.0e38f), bits(0.1f), bits(std::numeric_limits<float>::quiet_NaN())};
}

bool is_nan(ir::TypeClass c, uint32_t w) { return c == ir::TypeClass::F && std::isnan(std::bit_cast<float>(w)); }

Kind kind_of(ir::TypeClass c) {
    return c == ir::TypeClass::I ? Kind::I32 : c == ir::TypeClass::B ? Kind::Bool : Kind::F32;
}

}  // namespace

TEST_CASE("the ops the table calls commutative commute", "[ir][opcodes]") {
    int commutative = 0;
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {
        const Op op = Op(o);
        if (!ir::has(op, ir::OpProp::Commutative)) continue;
        ++commutative;
        const ir::OpInfo& info = ir::op_info(op);
        for (uint32_t a : samples(info.operand))
            for (uint32_t b : samples(info.operand)) {
                // Which of two NaNs a sum names is not pinned (docs/architecture.md).
                if (is_nan(info.operand, a) && is_nan(info.operand, b)) continue;
                INFO(info.name << std::hex << " " << a << " " << b);
                CHECK(ir::alu::eval<uint32_t>(op, a, b, 0) == ir::alu::eval<uint32_t>(op, b, a, 0));
            }
    }
    CHECK(commutative > 0);
}

// copyprop reuses op(a, b) for op(b, a) exactly where the table says the op
// commutes (check_pass: the outputs stay the same).
TEST_CASE("copyprop swaps the operands of the table's commutative ops only", "[ir][opcodes][copyprop]") {
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {
        const Op op = Op(o);
        const ir::OpInfo& info = ir::op_info(op);
        if (info.kind != ir::OpKind::Alu || info.arity != 2) continue;
        INFO(info.name);
        Builder b;
        const Reg x = input(b, "x", kind_of(info.operand)), y = input(b, "y", kind_of(info.operand));
        const Reg first = b.alu(op, {x, y}), second = b.alu(op, {y, x});
        b.output("first", first);
        b.output("second", second);
        ir::Shader t = check_pass(b.sh, [](ir::Shader& s) { ir::propagate_copies(s); });
        const ir::Instr* w = writer_of(t, second);
        REQUIRE(w);
        CHECK((w->op == Op::mov) == ir::has(op, ir::OpProp::Commutative));
    }
}

// A derivative of a uniform reads the other lanes of its quad, which the
// prologue (run once, for all lanes) cannot give it: hoist moves the table's
// pure lane-wise ops of uniforms and leaves the CrossLane ones.
TEST_CASE("hoist moves the table's pure lane-wise ops only", "[ir][opcodes][hoist]") {
    const std::vector<uint32_t> uniforms = {bits(0.5f), bits(-3.0f)};
    Builder b;
    const Reg u0 = b.reg(Kind::F32), u1 = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::F32, u0, {}, {0});
    b.instr(Op::uniform, Kind::F32, u1, {}, {1});
    const Reg product = b.alu(Op::fmul, {u1, u1});
    const Reg slope = b.reg(Kind::F32);
    b.instr(Op::ddx, Kind::F32, slope, {u0});
    const Reg x = input(b, "x");
    b.output("lit", b.alu(Op::fadd, {product, x}));  // outputs stay in the body
    b.output("slope", b.alu(Op::fadd, {slope, x}));
    ir::Shader t = check_pass(b.sh, [](ir::Shader& s) { ir::hoist_uniform_code(s); }, uniforms);
    CHECK(count_op(t, Op::fmul) == 0);  // count_op walks the body: the product went to the prologue
    CHECK(count_op(t, Op::ddx) == 1);
    CHECK(count_nodes(t.prologue, [](const ir::Node& n) { return n.instr.op == Op::fmul; }) == 1);
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {  // the columns that decide it
        const Op op = Op(o);
        INFO(ir::op_info(op).name);
        if (ir::op_info(op).kind == ir::OpKind::Alu) CHECK(ir::has(op, ir::OpProp::Pure));
        if (ir::has(op, ir::OpProp::CrossLane)) CHECK(ir::op_info(op).arity == 1);
    }
}
