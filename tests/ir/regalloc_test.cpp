// Dead store elimination and register allocation: what they remove or
// share, what they must keep apart (lanes that read before writing, indexed
// ranges, loops), and that outputs keep every bit on every lane.
#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

void dead_stores(ir::Shader& s) { ir::eliminate_dead_stores(s); }
void regalloc(ir::Shader& s) { ir::allocate_registers(s); }

// A chain of `n` temporaries, each used once by the next: two registers suffice.
Reg chain(Builder& b, Reg from, int n) {
    Reg v = from;
    for (int i = 0; i < n; ++i) v = b.alu(i % 2 ? Op::fadd : Op::fmul, {v, b.kf(1.5f + float(i))});
    return v;
}

}  // namespace

TEST_CASE("dead_stores removes writes overwritten before any read", "[ir][dead_stores]") {
    Builder b;
    Reg x = input(b, "x"), y = input(b, "y");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg v = b.reg(Kind::F32);
    b.mov(v, x);                         // dead: overwritten below, nothing reads v between
    Reg sum = b.alu(Op::fadd, {x, y});
    b.mov(v, sum);
    Reg kept = b.alu(Op::fmul, {v, y});  // reads the second value
    b.mov(v, y);                         // kept: the If below may read it
    b.if_(cond, [&] { b.alu_to(kept, Op::fadd, {kept, v}); });
    b.mov(v, x);
    b.output("v", v);
    b.output("kept", kept);
    ir::Shader t = check_pass(b.sh, dead_stores);
    CHECK(count_op(t, Op::mov) == 3);
}

TEST_CASE("dead_stores keeps a write that lanes leaving early still see", "[ir][dead_stores]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg v = b.reg(Kind::F32);
    b.scope([&] {
        b.mov(v, x);
        b.if_(cond, [&] { b.ret(); });  // returning lanes keep this v
        b.set_konst(v, bits(2.0f));
    });
    b.output("v", v);
    ir::Shader t = check_pass(b.sh, dead_stores);
    CHECK(count_op(t, Op::mov) == 1);
    CHECK(count_op(t, Op::konst) == 1);
}

TEST_CASE("dead_stores looks into scopes that cannot return early", "[ir][dead_stores]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg zeroed = b.reg(Kind::F32), kept = b.reg(Kind::F32);
    b.set_konst(zeroed, bits(5.0f));  // dead: the scope overwrites it first
    b.set_konst(kept, bits(5.0f));    // kept: lanes returning early still see it
    b.scope([&] { b.alu_to(zeroed, Op::fmul, {x, x}); });
    b.scope([&] {
        b.if_(cond, [&] { b.ret(); });
        b.alu_to(kept, Op::fadd, {x, x});
    });
    b.output("zeroed", zeroed);
    b.output("kept", kept);
    ir::Shader t = check_pass(b.sh, dead_stores);
    REQUIRE(count_op(t, Op::konst) == 1);
    CHECK(count_nodes(t.body, [&](const ir::Node& n) { return n.instr.op == Op::konst && n.instr.dst == kept; }) == 1);
}

TEST_CASE("dead_stores passes over branches that neither read nor leave", "[ir][dead_stores]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg v = b.reg(Kind::F32), w = b.reg(Kind::F32);
    b.set_konst(v, bits(5.0f));  // dead: the If only writes v, then v is overwritten
    b.set_konst(w, bits(6.0f));  // kept: the second If reads it
    b.if_(cond, [&] {
        b.alu_to(v, Op::fmul, {x, x});
        b.discard();
    });
    b.if_(cond, [&] { b.alu_to(x, Op::fadd, {w, x}); });
    b.alu_to(v, Op::fadd, {x, x});
    b.alu_to(w, Op::fadd, {x, x});
    b.output("v", v);
    b.output("w", w);
    ir::Shader t = check_pass(b.sh, dead_stores);
    REQUIRE(count_op(t, Op::konst) == 1);
    CHECK(count_nodes(t.body, [&](const ir::Node& n) { return n.instr.op == Op::konst && n.instr.dst == w; }) == 1);
}

TEST_CASE("regalloc shares registers between disjoint live ranges", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x");
    Reg out = b.reg(Kind::F32);
    b.mov(out, chain(b, x, 40));
    b.output("out", out);
    size_t before = b.sh.regs.size();
    ir::Shader t = check_pass(b.sh, regalloc);
    CHECK(before > 80);
    CHECK(t.regs.size() <= 6);
    CHECK(t.inputs[0].name == "x");
    CHECK(t.outputs[0].name == "out");
}

TEST_CASE("regalloc keeps values alive across branches and loops", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x"), n = input(b, "n", Kind::I32);
    Reg cond = input(b, "cond", Kind::Bool);
    Reg across = chain(b, x, 3);  // read after the If and inside the loop
    Reg acc = b.kf(0.0f);
    b.if_(cond, [&] { b.alu_to(acc, Op::fadd, {acc, chain(b, x, 5)}); }, [&] { b.alu_to(acc, Op::fsub, {acc, chain(b, x, 4)}); });
    Reg i = b.ki(0);
    b.loop([&] {
        b.if_(b.alu(Op::ige, {i, n}), [&] { b.brk(); });
        Reg t = chain(b, across, 3);  // temporaries of one iteration
        b.alu_to(acc, Op::fadd, {acc, t});
        b.alu_to(i, Op::iadd, {i, b.ki(1)});
    });
    Reg after = b.alu(Op::fmul, {acc, across});
    b.output("after", after);
    ir::Shader t = check_pass(b.sh, regalloc);
    CHECK(t.regs.size() < b.sh.regs.size());
}

TEST_CASE("regalloc leaves registers that a lane may read before writing", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg early = chain(b, x, 6);  // temporaries that could take maybe's register
    Reg maybe = b.reg(Kind::F32);
    b.if_(cond, [&] { b.alu_to(maybe, Op::fmul, {early, b.kf(2.0f)}); });
    Reg out = b.alu(Op::fadd, {maybe, b.kf(1.0f)});  // lanes with !cond read the old maybe (0)
    b.output("out", out);
    ir::Shader t = check_pass(b.sh, regalloc);
    CHECK(t.regs.size() < b.sh.regs.size());
}

TEST_CASE("regalloc keeps indexed ranges contiguous", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x"), idx = input(b, "idx", Kind::I32);
    Reg tmp = chain(b, x, 6);
    Reg arr = b.range(Kind::F32, 4);
    for (uint32_t e = 0; e < 4; ++e) b.mov(arr + e, chain(b, tmp, int(e) + 1));
    b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx, x}, {arr, 4, 1});
    Reg loaded = b.reg(Kind::F32);
    b.instr(Op::load_ind, Kind::F32, loaded, {b.alu(Op::iadd, {idx, b.ki(1)})}, {arr, 4, 1});
    b.output("loaded", loaded);
    ir::Shader t = check_pass(b.sh, regalloc);
    CHECK(t.regs.size() < b.sh.regs.size());
}

TEST_CASE("regalloc lets the single write of a shared register skip the mask", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg early = chain(b, x, 4);  // temporaries whose registers the branch reuses
    Reg var = b.reg(Kind::F32);
    b.mov(var, x);
    Reg t = b.reg(Kind::F32);
    b.if_(cond, [&] {
        b.alu_to(t, Op::fmul, {early, x});  // written once, read in the branch: unmasked
        b.alu_to(var, Op::fadd, {var, t});  // var's second write: lanes outside keep x
    });
    Reg out = b.alu(Op::fadd, {var, early});
    b.output("out", out);
    ir::Shader s = check_pass(b.sh, regalloc);
    const ir::Node* branch = nullptr;
    for (const ir::Node& n : s.body)
        if (n.kind == NodeKind::If) branch = &n;
    REQUIRE(branch);
    REQUIRE(branch->body.size() == 2);
    CHECK(branch->body[0].instr.unmasked);        // the fmul
    CHECK_FALSE(branch->body[1].instr.unmasked);  // var's second write
    CHECK_FALSE(s.body.back().instr.unmasked);    // the output
}

TEST_CASE("regalloc lets a function's own temporaries skip the mask", "[ir][regalloc]") {
    Builder b;
    Reg x = input(b, "x");
    Reg cond = input(b, "cond", Kind::Bool);
    Reg p = b.reg(Kind::F32), r = b.reg(Kind::F32), t = b.reg(Kind::F32);
    uint32_t f = b.function("f", [&] {
        b.alu_to(t, Op::fmul, {p, p});  // its own, written once and read after: unmasked
        b.alu_to(r, Op::fadd, {t, p});  // the result, read by main: masked
    });
    Reg out = b.reg(Kind::F32);
    b.mov(out, x);
    b.mov(p, x);
    b.if_(cond, [&] {
        b.call(f);
        b.mov(out, r);
    });
    b.call(f);
    Reg sum = b.alu(Op::fadd, {out, r});
    b.output("sum", sum);
    ir::Shader s = check_pass(b.sh, regalloc);
    REQUIRE(s.functions.size() == 1);
    const ir::Block& body = s.functions[0].body;
    REQUIRE(body.size() == 2);
    CHECK(body[0].instr.unmasked);
    CHECK_FALSE(body[1].instr.unmasked);
    CHECK(body[0].instr.dst != body[1].instr.dst);
}
