// Multiply-add fusion and uniform hoisting: what they rewrite, what they must
// leave alone (registers are not SSA, lanes are masked), and that outputs keep
// every bit on every lane.
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

void fuse(ir::Shader& s) {
    ir::fuse_multiply_add(s);
    ir::eliminate_dead_code(s);
}
void hoist(ir::Shader& s) {
    ir::hoist_uniform_code(s);
    ir::eliminate_dead_code(s);
}

const ir::Instr* prologue_writer(const ir::Shader& s, Reg dst) {
    for (const ir::Node& n : s.prologue)
        if (n.instr.dst == dst) return &n.instr;
    return nullptr;
}

// Uniform words with fractions, a huge value and a negative one, so products
// round and overflow differently in each position.
const std::vector<uint32_t> kUniforms = {bits(0.1f), bits(-3.3f), bits(3e38f), bits(7.0f)};

}  // namespace

TEST_CASE("fuse_mad turns a dot product into multiply-adds", "[ir][fuse]") {
    Builder b;
    Reg x0 = input(b, "x0"), x1 = input(b, "x1"), x2 = input(b, "x2");
    Reg y0 = input(b, "y0"), y1 = input(b, "y1"), y2 = input(b, "y2");
    Reg s = b.alu(Op::fadd, {b.alu(Op::fmul, {x0, y0}), b.alu(Op::fmul, {x1, y1})});
    Reg d = b.alu(Op::fadd, {s, b.alu(Op::fmul, {x2, y2})});
    b.output("d", d);
    ir::Shader t = check_pass(b.sh, fuse);
    CHECK(count_op(t, Op::fmad) == 2);
    CHECK(count_op(t, Op::fmul) == 1);
    CHECK(count_op(t, Op::fadd) == 0);
    const ir::Instr* w = writer_of(t, d);
    REQUIRE(w);
    CHECK((w->op == Op::fmad && w->src[0] == x2 && w->src[1] == y2 && w->src[2] == s));
}

TEST_CASE("fuse_mad keeps the order of a subtraction", "[ir][fuse]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c");
    Reg p_minus_c = b.alu(Op::fsub, {b.alu(Op::fmul, {x, y}), c});
    Reg c_minus_p = b.alu(Op::fsub, {c, b.alu(Op::fmul, {y, c})});
    b.output("a", p_minus_c);
    b.output("b", c_minus_p);
    ir::Shader t = check_pass(b.sh, fuse);
    CHECK(writer_of(t, p_minus_c)->op == Op::fmsub);
    CHECK(writer_of(t, c_minus_p)->op == Op::fnmadd);
    CHECK(count_op(t, Op::fmul) == 0);
}

TEST_CASE("fuse_mad leaves shared products, changed operands and other blocks alone", "[ir][fuse]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y"), c = input(b, "c");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg shared = b.alu(Op::fmul, {x, y});
    Reg twice = b.alu(Op::fadd, {shared, c});
    Reg again = b.alu(Op::fadd, {shared, twice});
    // x changes between the product and the sum: the sum must see the old x*y.
    Reg v = b.reg(Kind::F32);
    b.mov(v, x);
    Reg pv = b.alu(Op::fmul, {v, y});
    b.alu_to(v, Op::fadd, {v, c});
    Reg after_write = b.alu(Op::fadd, {pv, v});
    // The product outside the branch, the sum inside it.
    Reg outside = b.alu(Op::fmul, {c, y});
    Reg inside = b.reg(Kind::F32);
    b.set_konst(inside, bits(0.0f));
    b.if_(cond, [&] { b.alu_to(inside, Op::fadd, {outside, x}); });
    b.output("again", again);
    b.output("after_write", after_write);
    b.output("inside", inside);
    ir::Shader t = check_pass(b.sh, fuse);
    CHECK(count_op(t, Op::fmad) == 0);
    CHECK(count_op(t, Op::fmul) == 3);
}

TEST_CASE("hoist moves uniform-only code to the prologue", "[ir][hoist]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg u0 = b.reg(Kind::F32), u1 = b.reg(Kind::F32), u2 = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::F32, u0, {}, {0});
    b.instr(Op::uniform, Kind::F32, u1, {}, {1});
    Reg m = b.alu(Op::fmul, {u0, u1});
    Reg lit = b.alu(Op::fadd, {x, m});  // depends on an input: stays
    Reg in_branch = b.reg(Kind::F32);
    b.set_konst(in_branch, bits(1.0f));
    b.if_(cond, [&] {
        b.instr(Op::uniform, Kind::F32, u2, {}, {2});  // read only inside the branch
        Reg big = b.alu(Op::fmul, {u2, b.kf(10.0f)});
        b.alu_to(in_branch, Op::fadd, {big, x});
    });
    b.output("lit", lit);
    b.output("in_branch", in_branch);
    ir::Shader t = check_pass(b.sh, hoist, kUniforms);
    REQUIRE(prologue_writer(t, m));
    CHECK(prologue_writer(t, m)->op == Op::fmul);
    CHECK(prologue_writer(t, u2));
    CHECK(count_op(t, Op::uniform) == 0);  // count_op walks the body only
    CHECK(writer_of(t, lit)->op == Op::fadd);
    CHECK(!prologue_writer(t, lit));
    CHECK(!prologue_writer(t, in_branch));  // an output, written twice
}

TEST_CASE("hoist keeps code whose register a lane may read before it is written", "[ir][hoist]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    // Set in one branch only, read after the join: lanes that skipped the
    // branch read the register's older value, which hoisting would replace.
    Reg maybe = b.reg(Kind::F32);
    b.if_(cond, [&] { b.instr(Op::uniform, Kind::F32, maybe, {}, {3}); });
    Reg r1 = b.alu(Op::fadd, {maybe, x});
    // Written twice: not a function of the uniforms alone.
    Reg twice = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::F32, twice, {}, {0});
    b.if_(cond, [&] { b.alu_to(twice, Op::fmul, {twice, x}); });
    // Set in both branches: definitely set at the join, but written twice.
    Reg both = b.reg(Kind::F32);
    b.if_(cond, [&] { b.instr(Op::uniform, Kind::F32, both, {}, {1}); },
          [&] { b.instr(Op::uniform, Kind::F32, both, {}, {2}); });
    Reg r2 = b.alu(Op::fadd, {both, twice});
    b.output("r1", r1);
    b.output("r2", r2);
    ir::Shader t = check_pass(b.sh, hoist, kUniforms);
    CHECK(t.prologue.empty());
    CHECK(count_op(t, Op::uniform) == 4);
}

TEST_CASE("hoist takes invariants out of loops and keeps the loop's results", "[ir][hoist]") {
    Builder b;
    Reg n = input(b, "n", Kind::I32);
    Reg i = b.ki(0), acc = b.kf(0.0f);
    b.loop([&] {
        b.if_(b.alu(Op::ige, {i, n}), [&] { b.brk(); });
        Reg u = b.reg(Kind::F32);
        b.instr(Op::uniform, Kind::F32, u, {}, {0});
        Reg step = b.alu(Op::fmul, {u, b.kf(3.0f)});
        b.alu_to(acc, Op::fadd, {acc, step});
        b.alu_to(i, Op::iadd, {i, b.ki(1)});
    });
    b.output("acc", acc);
    ir::Shader t = check_pass(b.sh, hoist, kUniforms);
    CHECK(t.prologue.size() >= 3);  // uniform, 3.0, the product (and 1, the increment)
    CHECK(count_op(t, Op::uniform) == 0);
    CHECK(count_op(t, Op::fadd) == 1);
}

TEST_CASE("hoist takes a function's constants and uniform code to the prologue", "[ir][hoist]") {
    Builder b;
    Reg x = input(b, "x");
    Reg p = b.reg(Kind::F32), r = b.reg(Kind::F32), k = b.reg(Kind::F32), u = b.reg(Kind::F32);
    uint32_t f = b.function("f", [&] {
        b.set_konst(k, bits(128.0f));
        b.instr(Op::uniform, Kind::F32, u, {}, {1});
        Reg scale = b.alu(Op::fmul, {k, u});
        b.alu_to(r, Op::fmul, {p, scale});  // reads a parameter: stays
    });
    b.mov(p, x);
    b.call(f);
    Reg first = b.reg(Kind::F32);
    b.mov(first, r);
    b.alu_to(p, Op::fadd, {x, x});
    b.call(f);
    b.output("first", first);
    b.output("r", r);
    ir::Shader t = check_pass(b.sh, hoist, kUniforms);
    CHECK(prologue_writer(t, k));
    CHECK(prologue_writer(t, u));
    REQUIRE(t.functions.size() == 1);
    CHECK(t.functions[0].body.size() == 1);
}
