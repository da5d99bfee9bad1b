// ir/sqrt_divisor.cpp: which square roots it marks (only those whose every
// read is a divisor, written once, never read unset), and that the marked
// shader computes the same bits as before in the fp32 modes' Precise kernels.
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

void mark(ir::Shader& s) { ir::mark_sqrt_divisors(s); }

// normalize(x, y, z) as the frontend lowers it: three divisions by one root.
struct Normalize {
    Reg x, y, z, len, nx, ny, nz;
};
Normalize normalize3(Builder& b) {
    Normalize n{};
    n.x = input(b, "x"), n.y = input(b, "y"), n.z = input(b, "z");
    Reg d = b.alu(Op::fadd, {b.alu(Op::fadd, {b.alu(Op::fmul, {n.x, n.x}), b.alu(Op::fmul, {n.y, n.y})}),
                             b.alu(Op::fmul, {n.z, n.z})});
    n.len = b.alu(Op::fsqrt, {d});
    n.nx = b.alu(Op::fdiv, {n.x, n.len});
    n.ny = b.alu(Op::fdiv, {n.y, n.len});
    n.nz = b.alu(Op::fdiv, {n.z, n.len});
    return n;
}

}  // namespace

TEST_CASE("sqrt_divisor marks normalize's root and its divisions", "[ir][sqrt_divisor]") {
    Builder b;
    Normalize n = normalize3(b);
    for (Reg r : {n.nx, n.ny, n.nz}) b.output("n", r);
    ir::Shader t = check_pass(b.sh, mark);
    CHECK(writer_of(t, n.len)->op == Op::fsqrt_divisor);
    for (Reg r : {n.nx, n.ny, n.nz}) CHECK(writer_of(t, r)->op == Op::fdiv_by_sqrt);
    CHECK(count_op(t, Op::fsqrt) == 0);
    CHECK(count_op(t, Op::fdiv) == 0);
}

TEST_CASE("sqrt_divisor marks a root divided by in a branch and in a loop", "[ir][sqrt_divisor]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c", Kind::Bool);
    Reg t = b.alu(Op::fsqrt, {y});
    Reg q = b.reg(Kind::F32);
    b.alu_to(q, Op::fmul, {x, x});
    b.if_(c, [&] { b.alu_to(q, Op::fdiv, {x, t}); });
    b.output("q", q);
    ir::Shader s = check_pass(b.sh, mark);
    CHECK(writer_of(s, t)->op == Op::fsqrt_divisor);
    CHECK(count_op(s, Op::fdiv_by_sqrt) == 1);
}

TEST_CASE("sqrt_divisor leaves roots with any other reader alone", "[ir][sqrt_divisor]") {
    SECTION("read as a length too (length(l) and normalize(l) sharing the root)") {
        Builder b;
        Normalize n = normalize3(b);
        b.output("n", n.nx);
        b.output("att", b.alu(Op::fadd, {n.len, n.x}));
        ir::Shader t = check_pass(b.sh, mark);
        CHECK(count_op(t, Op::fsqrt_divisor) == 0);
        CHECK(count_op(t, Op::fdiv_by_sqrt) == 0);
    }
    SECTION("the dividend of a division") {
        Builder b;
        Normalize n = normalize3(b);
        b.output("n", n.nx);
        b.output("r", b.alu(Op::fdiv, {n.len, n.y}));
        CHECK(count_op(check_pass(b.sh, mark), Op::fsqrt_divisor) == 0);
    }
    SECTION("t / t") {
        Builder b;
        Reg y = input(b, "y");
        Reg t = b.alu(Op::fsqrt, {y});
        b.output("r", b.alu(Op::fdiv, {t, t}));
        CHECK(count_op(check_pass(b.sh, mark), Op::fsqrt_divisor) == 0);
    }
    SECTION("an output") {
        Builder b;
        Normalize n = normalize3(b);
        b.output("n", n.nx);
        b.output("len", n.len);
        CHECK(count_op(check_pass(b.sh, mark), Op::fsqrt_divisor) == 0);
    }
    SECTION("a register with a second write") {
        Builder b;
        Normalize n = normalize3(b);
        b.output("n", n.nx);
        b.alu_to(n.len, Op::fsqrt, {n.y});
        b.output("m", b.alu(Op::fdiv, {n.z, n.len}));
        CHECK(count_op(check_pass(b.sh, mark), Op::fsqrt_divisor) == 0);
    }
    SECTION("a root that may be read before it is written (a loop's earlier iteration)") {
        Builder b;
        Reg x = input(b, "x"), y = input(b, "y");
        Reg t = b.reg(Kind::F32), q = b.reg(Kind::F32), i = b.kf(0.0f);
        Reg one = b.kf(1.0f), three = b.kf(3.0f);
        b.alu_to(q, Op::fmul, {x, x});
        b.loop([&] {
            b.alu_to(q, Op::fdiv, {q, t});  // the first iteration reads t unset
            b.alu_to(t, Op::fsqrt, {b.alu(Op::fmul, {y, y})});
            b.alu_to(i, Op::fadd, {i, one});
            b.if_(b.alu(Op::flt, {three, i}), [&] { b.brk(); });
        });
        b.output("q", q);
        CHECK(count_op(check_pass(b.sh, mark), Op::fsqrt_divisor) == 0);
    }
}
