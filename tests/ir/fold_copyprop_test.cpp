// Constant folding and copy propagation: what they change, what they must
// leave alone because registers are not SSA, and that outputs never change.
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {
void fold(ir::Shader& s) { ir::fold_constants(s); }
void copyprop(ir::Shader& s) { ir::propagate_copies(s); }
}  // namespace

TEST_CASE("fold evaluates constant Alu chains with the table", "[ir][fold]") {
    Builder b;
    Reg x = b.reg(Kind::F32);
    b.input("x", x);
    Reg two = b.kf(2.0f), three = b.kf(3.0f);
    Reg sum = b.alu(Op::fadd, {two, three});
    Reg sq = b.alu(Op::fmul, {sum, sum});
    Reg i = b.alu(Op::f2i, {sq});
    Reg m = b.alu(Op::imod, {i, b.ki(7)});
    Reg out = b.alu(Op::fadd, {x, b.alu(Op::i2f, {m})});
    b.output("out", out);
    b.output("sq", sq);
    ir::Shader t = check_pass(b.sh, fold);
    const ir::Instr* w = writer_of(t, sq);
    REQUIRE(w);
    CHECK(w->op == Op::konst);
    CHECK(as_float(w->imm[0]) == 25.0f);
    CHECK(writer_of(t, m)->imm[0] == 4u);
    CHECK(writer_of(t, out)->op == Op::fadd);  // depends on an input
    CHECK(count_op(t, Op::fmul) == 0);
}

TEST_CASE("fold forgets registers written in a branch or a loop", "[ir][fold]") {
    Builder b;
    Reg c = b.reg(Kind::Bool), n = b.reg(Kind::I32);
    b.input("c", c);
    b.input("n", n);
    Reg x = b.kf(1.0f);
    b.if_(c, [&] { b.set_konst(x, bits(2.0f)); });
    Reg y = b.alu(Op::fadd, {x, x});
    Reg i = b.ki(0);
    Reg one = b.ki(1);
    b.loop([&] {
        b.if_(b.alu(Op::ige, {i, n}), [&] { b.brk(); });
        b.alu_to(i, Op::iadd, {i, one});
    });
    Reg j = b.alu(Op::iadd, {i, one});
    b.output("y", y);
    b.output("j", j);
    ir::Shader t = check_pass(b.sh, fold);
    CHECK(writer_of(t, y)->op == Op::fadd);
    CHECK(writer_of(t, j)->op == Op::iadd);
    CHECK(count_op(t, Op::iadd) == 2);  // the loop increment is not folded either
}

TEST_CASE("fold keeps facts through branches that do not write", "[ir][fold]") {
    Builder b;
    Reg c = b.reg(Kind::Bool);
    b.input("c", c);
    Reg x = b.kf(1.5f), z = b.reg(Kind::F32);
    b.if_(c, [&] { b.alu_to(z, Op::fadd, {x, x}); });  // folded inside the branch
    Reg y = b.alu(Op::fmul, {x, x});                   // and after it
    b.output("y", y);
    b.output("z", z);
    ir::Shader t = check_pass(b.sh, fold);
    CHECK(writer_of(t, y)->op == Op::konst);
    CHECK(writer_of(t, z)->op == Op::konst);
    CHECK(as_float(writer_of(t, z)->imm[0]) == 3.0f);
}

TEST_CASE("fold removes If on a constant condition and folds sel", "[ir][fold]") {
    Builder b;
    Reg x = b.reg(Kind::F32);
    b.input("x", x);
    Reg t_ = b.kb(true), y = b.reg(Kind::F32);
    b.if_(t_, [&] { b.alu_to(y, Op::fadd, {x, x}); }, [&] { b.alu_to(y, Op::fsub, {x, x}); });
    Reg f_ = b.alu(Op::bnot, {t_});
    Reg s = b.reg(Kind::F32);
    b.instr(Op::sel, Kind::F32, s, {f_, x, y});
    b.output("s", s);
    ir::Shader t = check_pass(b.sh, fold);
    CHECK(count_kind(t, NodeKind::If) == 0);
    CHECK(count_op(t, Op::fsub) == 0);
    CHECK(count_op(t, Op::sel) == 0);
    CHECK(writer_of(t, s)->op == Op::mov);
    CHECK(writer_of(t, s)->src[0] == y);
}

TEST_CASE("fold turns constant-index accesses into direct ones and respects store_ind", "[ir][fold]") {
    Builder b;
    Reg idx = b.reg(Kind::I32), v = b.reg(Kind::F32);
    b.input("idx", idx);
    b.input("v", v);
    Reg arr = b.range(Kind::F32, 4);
    for (int e = 0; e < 4; ++e) b.set_konst(arr + e, bits(float(e)));
    Reg k9 = b.ki(9);  // clamps to element 3
    Reg a = b.reg(Kind::F32);
    b.instr(Op::load_ind, Kind::F32, a, {k9}, {arr, 4, 1});
    Reg a2 = b.alu(Op::fadd, {a, a});  // 3 + 3
    b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx, v}, {arr, 4, 1});
    Reg after = b.alu(Op::fadd, {arr + 3, arr + 3});  // unknown: the store may hit it
    Reg u = b.reg(Kind::F32);
    b.instr(Op::uniform_ind, Kind::F32, u, {b.ki(1)}, {0, 2, 2});
    b.output("a2", a2);
    b.output("after", after);
    b.output("u", u);
    ir::Shader t = check_pass(b.sh, fold, {bits(1.0f), bits(2.0f), bits(3.0f), bits(4.0f)});
    CHECK(count_op(t, Op::load_ind) == 0);
    CHECK(writer_of(t, a2)->op == Op::konst);
    CHECK(as_float(writer_of(t, a2)->imm[0]) == 6.0f);
    CHECK(writer_of(t, after)->op == Op::fadd);
    CHECK(writer_of(t, u)->op == Op::uniform);
    CHECK(writer_of(t, u)->imm[0] == 2u);
}

TEST_CASE("fold forgets writes of a scope that returns early", "[ir][fold]") {
    Builder b;
    Reg c = b.reg(Kind::Bool);
    b.input("c", c);
    Reg x = b.kf(1.0f), w = b.reg(Kind::F32);
    b.scope([&] {
        b.if_(c, [&] { b.ret(); });
        b.set_konst(x, bits(2.0f));
        b.alu_to(w, Op::fadd, {x, x});  // known inside: x is 2 for the lanes still here
    });
    Reg y = b.alu(Op::fadd, {x, x});
    b.output("y", y);
    b.output("w", w);
    ir::Shader t = check_pass(b.sh, fold);
    CHECK(writer_of(t, y)->op == Op::fadd);
    CHECK(writer_of(t, w)->op == Op::konst);
}

TEST_CASE("copyprop forwards copies and stops at redefinitions", "[ir][copyprop]") {
    Builder b;
    Reg a = b.reg(Kind::F32), c = b.reg(Kind::Bool);
    b.input("a", a);
    b.input("c", c);
    Reg m = b.reg(Kind::F32);
    b.mov(m, a);
    Reg m2 = b.reg(Kind::F32);
    b.mov(m2, m);
    Reg s = b.alu(Op::fadd, {m2, m});  // -> fadd a, a
    b.set_konst(a, bits(5.0f));        // a changes: m, m2 no longer copies of it
    Reg s2 = b.alu(Op::fmul, {m2, a});
    Reg n = b.reg(Kind::F32);
    b.mov(n, s);
    b.if_(c, [&] { b.alu_to(n, Op::fneg, {n}); });  // n is now unknown
    Reg s3 = b.alu(Op::fadd, {n, n});
    b.output("s", s);
    b.output("s2", s2);
    b.output("s3", s3);
    ir::Shader t = check_pass(b.sh, copyprop);
    CHECK(writer_of(t, s)->src[0] == a);
    CHECK(writer_of(t, s)->src[1] == a);
    CHECK(writer_of(t, s2)->src[0] == m2);
    CHECK(writer_of(t, s3)->src[0] == n);
}

TEST_CASE("copyprop treats store_ind as writing its whole range", "[ir][copyprop]") {
    Builder b;
    Reg idx = b.reg(Kind::I32), v = b.reg(Kind::F32);
    b.input("idx", idx);
    b.input("v", v);
    Reg arr = b.range(Kind::F32, 3);
    b.mov(arr + 1, v);
    Reg before = b.alu(Op::fadd, {arr + 1, arr + 1});
    b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx, before}, {arr, 3, 1});
    Reg after = b.alu(Op::fadd, {arr + 1, arr + 1});
    b.output("after", after);
    ir::Shader t = check_pass(b.sh, copyprop);
    CHECK(writer_of(t, before)->src[0] == v);
    CHECK(writer_of(t, after)->src[0] == arr + 1);
}

TEST_CASE("copyprop inside loops forgets loop-carried registers", "[ir][copyprop]") {
    Builder b;
    Reg n = b.reg(Kind::I32);
    b.input("n", n);
    Reg i = b.ki(0), one = b.ki(1), prev = b.reg(Kind::I32), acc = b.ki(0);
    b.loop([&] {
        b.if_(b.alu(Op::ige, {i, n}), [&] { b.brk(); });
        b.alu_to(acc, Op::iadd, {acc, prev});  // prev is the previous iteration's i
        b.mov(prev, i);
        b.alu_to(i, Op::iadd, {i, one});
    });
    b.output("acc", acc);
    ir::Shader t = check_pass(b.sh, copyprop);
    CHECK(writer_of(t, acc)->src[1] == prev);
}

TEST_CASE("copyprop reuses values a register still holds", "[ir][copyprop][cse]") {
    Builder b;
    Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32), c = b.reg(Kind::Bool);
    b.input("x", x);
    b.input("y", y);
    b.input("c", c);
    Reg u1 = b.reg(Kind::F32), u2 = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::F32, u1, {}, {1});
    Reg s1 = b.alu(Op::fadd, {x, u1});
    b.instr(Op::uniform, Kind::F32, u2, {}, {1});  // same slot: becomes a copy of u1
    Reg s2 = b.alu(Op::fadd, {u2, x});             // commuted: becomes a copy of s1
    Reg in_branch = b.reg(Kind::F32);
    b.if_(c, [&] { b.alu_to(in_branch, Op::fadd, {x, u1}); });  // still available inside
    b.set_konst(x, bits(2.0f));                                  // x changes
    Reg s3 = b.alu(Op::fadd, {x, u1});                           // a new value
    Reg o = b.alu(Op::fmul, {b.alu(Op::fmul, {s1, s2}), b.alu(Op::fadd, {s3, in_branch})});
    b.output("o", o);
    ir::Shader t = check_pass(b.sh, copyprop, {0, bits(1.5f)});
    CHECK(writer_of(t, u2)->op == Op::mov);
    CHECK(writer_of(t, s2)->op == Op::mov);
    CHECK(writer_of(t, s2)->src[0] == s1);
    CHECK(writer_of(t, in_branch)->op == Op::mov);
    CHECK(writer_of(t, s3)->op == Op::fadd);
}
