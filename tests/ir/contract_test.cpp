// Multiply-add contraction (ir/contract.cpp): which products become ffma,
// ffms and ffnma, by the rule measured on the GPU (tools/gpu_probes/fma.frag,
// fma2.frag), and that Precise's outputs keep every bit on every lane
// (check_pass runs the interpreter in Precise before and after).
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

void contract(ir::Shader& s) {
    ir::contract_multiply_add(s);
    ir::eliminate_dead_code(s);
}

}  // namespace

TEST_CASE("contract fuses a product into each add that reads it", "[ir][contract]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c"), e = input(b, "e");
    Reg p = b.alu(Op::fmul, {x, y});
    Reg plus = b.alu(Op::fadd, {c, p});
    Reg minus = b.alu(Op::fsub, {p, e});
    Reg from = b.alu(Op::fsub, {e, p});
    b.output("plus", plus);
    b.output("minus", minus);
    b.output("from", from);
    ir::Shader t = check_pass(b.sh, contract);
    CHECK(count_op(t, Op::fmul) == 0);  // every read contracted: the product is gone
    const ir::Instr* w = writer_of(t, plus);
    CHECK((w->op == Op::ffma && w->src[0] == x && w->src[1] == y && w->src[2] == c));
    w = writer_of(t, minus);
    CHECK((w->op == Op::ffms && w->src[0] == x && w->src[1] == y && w->src[2] == e));
    w = writer_of(t, from);
    CHECK((w->op == Op::ffnma && w->src[0] == x && w->src[1] == y && w->src[2] == e));
}

TEST_CASE("contract takes the left product of a sum of two", "[ir][contract]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y");
    Reg d = b.alu(Op::fsub, {b.alu(Op::fmul, {x, x}), b.alu(Op::fmul, {y, y})});  // x*x - y*y
    b.output("d", d);
    ir::Shader t = check_pass(b.sh, contract);
    const ir::Instr* w = writer_of(t, d);
    REQUIRE(w);
    CHECK((w->op == Op::ffms && w->src[0] == x && w->src[1] == x));
    CHECK(count_op(t, Op::fmul) == 1);  // y*y, rounded
}

TEST_CASE("contract takes the right product of a built-in's sum of two", "[ir][contract]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y");
    Reg d = b.alu(Op::fadd, {b.alu(Op::fmul, {x, x}), b.alu(Op::fmul, {y, y})});  // dot(v, v)
    for (ir::Node& n : b.sh.body) n.loc = ir::SourceLoc{7, 12, 0};  // one call's location
    b.output("d", d);
    ir::Shader t = check_pass(b.sh, contract);
    const ir::Instr* w = writer_of(t, d);
    REQUIRE(w);
    CHECK((w->op == Op::ffma && w->src[0] == y && w->src[1] == y));
}

TEST_CASE("contract leaves products with other reads, other blocks and scaled factors alone", "[ir][contract]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c");
    Reg cond = input(b, "cond", Kind::Bool);
    // Read by an add and by a compare: the GPU rounds it for both.
    Reg compared = b.alu(Op::fmul, {x, y});
    Reg sum = b.alu(Op::fadd, {compared, c});
    Reg big = b.alu(Op::fgt, {compared, c});
    // The product outside the branch, the sum inside it.
    Reg outside = b.alu(Op::fmul, {c, y});
    Reg inside = b.reg(Kind::F32);
    b.set_konst(inside, bits(0.0f));
    b.if_(cond, [&] { b.alu_to(inside, Op::fadd, {outside, x}); });
    // (2x) * y + c: the GPU moves the 2 out and rounds x*y.
    Reg two = b.kf(2.0f);
    Reg scaled = b.alu(Op::fadd, {b.alu(Op::fmul, {b.alu(Op::fmul, {two, x}), y}), c});
    // x changes between the product and the sum.
    Reg v = b.reg(Kind::F32);
    b.mov(v, x);
    Reg pv = b.alu(Op::fmul, {v, y});
    b.alu_to(v, Op::fadd, {v, c});
    Reg after_write = b.alu(Op::fadd, {pv, v});
    b.output("sum", sum);
    b.output("big", big);
    b.output("inside", inside);
    b.output("scaled", scaled);
    b.output("after_write", after_write);
    ir::Shader t = check_pass(b.sh, contract);
    CHECK(count_op(t, Op::ffma) == 0);
    CHECK(count_op(t, Op::ffms) == 0);
    CHECK(count_op(t, Op::ffnma) == 0);
}

TEST_CASE("contract fuses a product scaled by a power of two, and (3x) * y", "[ir][contract]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c");
    // (x*y) * 2 + c: the add fuses with the exact scaling (as the GPU's ((x*y)*2) + c).
    Reg outer = b.alu(Op::fadd, {b.alu(Op::fmul, {b.alu(Op::fmul, {x, y}), b.kf(2.0f)}), c});
    // (3x) * y + c: 3 is no power of two.
    Reg three = b.alu(Op::fadd, {b.alu(Op::fmul, {b.alu(Op::fmul, {b.kf(3.0f), x}), y}), c});
    b.output("outer", outer);
    b.output("three", three);
    ir::Shader t = check_pass(b.sh, contract);
    CHECK(writer_of(t, outer)->op == Op::ffma);
    CHECK(writer_of(t, three)->op == Op::ffma);
}

// The debugger's IR keeps every variable: `float v = x * y; v += c;` copies the product into v's
// register, which nothing reads after copyprop. With display_copies that copy is no read (the
// optimized program drops it), so the add fuses and v still shows the rounded product; a copy
// that something reads keeps the product rounded, as before.
TEST_CASE("contract sees through a product's unread copy into a variable", "[ir][contract]") {
    for (bool read_copy : {false, true})
        for (bool display_copies : {false, true}) {
            INFO("copy read " << read_copy << ", display_copies " << display_copies);
            Builder b;
            Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c");
            Reg p = b.alu(Op::fmul, {x, y});
            Reg v = b.reg(Kind::F32);
            b.mov(v, p);
            b.sh.variables.push_back(ir::Variable{"v", "main", "float", v, 1});
            Reg sum = b.alu(Op::fadd, {p, c});
            b.output("sum", sum);
            if (read_copy) b.output("v", v);
            // No dce: the debugger keeps v's writes (its variables count as outputs there).
            ir::Shader t = check_pass(b.sh, [&](ir::Shader& s) { ir::contract_multiply_add(s, display_copies); });
            const bool fused = display_copies && !read_copy;
            CHECK((writer_of(t, sum)->op == Op::ffma) == fused);
            REQUIRE(writer_of(t, v));
            CHECK((writer_of(t, v)->op == Op::mov && writer_of(t, v)->src[0] == p));  // the rounded product
            CHECK(writer_of(t, p)->op == Op::fmul);
        }
}
