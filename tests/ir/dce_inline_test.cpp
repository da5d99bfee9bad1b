// Dead code elimination, inlining and the whole pipeline.
#include <chrono>

#include "tests/ir/pass_helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {
void dce(ir::Shader& s) { ir::eliminate_dead_code(s); }
}  // namespace

TEST_CASE("dce removes unread results transitively and keeps outputs", "[ir][dce]") {
    Builder b;
    Reg x = b.reg(Kind::F32);
    b.input("x", x);
    Reg dead1 = b.alu(Op::fmul, {x, x});
    Reg dead2 = b.alu(Op::fsin, {dead1});  // only read by nothing
    (void)dead2;
    Reg live = b.alu(Op::fadd, {x, x});
    Reg out = b.reg(Kind::F32);
    b.mov(out, live);
    b.mov(out, out);  // a self-move does nothing
    b.output("out", out);
    ir::Shader t = check_pass(b.sh, dce);
    CHECK(count_op(t, Op::fmul) == 0);
    CHECK(count_op(t, Op::fsin) == 0);
    CHECK(count_op(t, Op::fadd) == 1);
    CHECK(count_op(t, Op::mov) == 1);
}

TEST_CASE("dce keeps writes read through load_ind ranges and functions", "[ir][dce]") {
    Builder b;
    Reg idx = b.reg(Kind::I32), x = b.reg(Kind::F32);
    b.input("idx", idx);
    b.input("x", x);
    Reg arr = b.range(Kind::F32, 3);
    Reg arr2 = b.range(Kind::F32, 3);
    Reg fn_in = b.reg(Kind::F32), fn_out = b.reg(Kind::F32);
    for (int e = 0; e < 3; ++e) {
        b.alu_to(arr + e, Op::fadd, {x, b.kf(float(e))});
        b.alu_to(arr2 + e, Op::fadd, {x, b.kf(float(e))});  // arr2 is never read
    }
    uint32_t f = b.function("f", [&] { b.alu_to(fn_out, Op::fneg, {fn_in}); });
    b.mov(fn_in, x);
    b.call(f);
    Reg a = b.reg(Kind::F32);
    b.instr(Op::load_ind, Kind::F32, a, {idx}, {arr, 3, 1});
    b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx, x}, {arr2, 3, 1});  // dead store
    Reg out = b.alu(Op::fadd, {a, fn_out});
    b.output("out", out);
    ir::Shader t = check_pass(b.sh, dce);
    CHECK(count_op(t, Op::fadd) == 4);  // three arr elements and out
    CHECK(count_op(t, Op::store_ind) == 0);
    CHECK(count_op(t, Op::fneg) == 1);
    CHECK(writer_of(t, fn_in) != nullptr);
}

TEST_CASE("dce removes empty control flow and code after exits", "[ir][dce]") {
    Builder b;
    Reg c = b.reg(Kind::Bool), x = b.reg(Kind::F32), out = b.reg(Kind::F32);
    b.input("c", c);
    b.input("x", x);
    b.mov(out, x);
    b.if_(c, [&] { b.alu(Op::fmul, {x, x}); }, [&] {});
    b.scope([&] { b.alu(Op::fadd, {x, x}); });
    b.loop([&] {
        b.brk();
        b.alu_to(out, Op::fneg, {x});  // unreachable
    });
    b.output("out", out);
    ir::Shader t = check_pass(b.sh, dce);
    CHECK(count_kind(t, NodeKind::If) == 0);
    CHECK(count_kind(t, NodeKind::Scope) == 0);
    CHECK(count_kind(t, NodeKind::Loop) == 1);
    CHECK(count_op(t, Op::fneg) == 0);
}

namespace {
// f(a) { t = a * a; if (t > 4) return t; return t + 1 } via static frame regs.
struct TwoCalls {
    Builder b;
    Reg x, p, r, tmp, out1, out2;
    uint32_t f;
    TwoCalls() {
        x = b.reg(Kind::F32);
        b.input("x", x);
        p = b.reg(Kind::F32);
        r = b.reg(Kind::F32);
        tmp = b.reg(Kind::F32);
        Reg four = b.kf(4.0f), one = b.kf(1.0f);
        f = b.function("f", [&] {
            b.alu_to(tmp, Op::fmul, {p, p});
            b.if_(b.alu(Op::fgt, {tmp, four}), [&] {
                b.mov(r, tmp);
                b.ret();
            });
            b.alu_to(r, Op::fadd, {tmp, one});
        });
        out1 = b.reg(Kind::F32);
        out2 = b.reg(Kind::F32);
        b.mov(p, x);
        b.call(f);
        b.mov(out1, r);
        b.alu_to(p, Op::fadd, {x, one});
        b.call(f);
        b.mov(out2, r);
        b.output("out1", out1);
        b.output("out2", out2);
    }
};
}  // namespace

TEST_CASE("inline turns calls into scopes with private temporaries renamed", "[ir][inline]") {
    TwoCalls tc;
    ir::Shader t = check_pass(tc.b.sh, [](ir::Shader& s) { ir::inline_calls(s, 4000); });
    CHECK(t.functions.empty());
    CHECK(count_kind(t, NodeKind::Call) == 0);
    CHECK(count_kind(t, NodeKind::Scope) == 2);
    CHECK(count_kind(t, NodeKind::Return) == 2);
    // the temporary got a fresh register per copy; parameters stay shared
    std::vector<Reg> tmp_writers;
    ir::flow::walk(t.body, [&](const ir::Node& n) {
        if (n.kind == NodeKind::Instr && n.instr.op == Op::fmul) tmp_writers.push_back(n.instr.dst);
    });
    REQUIRE(tmp_writers.size() == 2);
    CHECK(tmp_writers[0] != tmp_writers[1]);
    CHECK(tmp_writers[0] != tc.tmp);
    CHECK(count_nodes(t.body, [&](const ir::Node& n) {
              return n.kind == NodeKind::Instr && n.instr.op == Op::fmul && n.instr.src[0] == tc.p;
          }) == 2);
}

TEST_CASE("inline keeps calls beyond the budget", "[ir][inline]") {
    TwoCalls tc;
    ir::Shader t = check_pass(tc.b.sh, [](ir::Shader& s) { ir::inline_calls(s, 0); });
    CHECK(count_kind(t, NodeKind::Call) == 2);
    CHECK(t.functions.size() == 1);
    uint64_t one_copy = ir::flow::node_count(tc.b.sh.functions[0].body);
    ir::Shader u = check_pass(tc.b.sh, [&](ir::Shader& s) { ir::inline_calls(s, uint32_t(one_copy + 1)); });
    CHECK(count_kind(u, NodeKind::Call) == 1);
    CHECK(count_kind(u, NodeKind::Scope) == 1);
}

// main calls a function of `size` chained multiplications `calls` times.
ir::Shader chain_calls(int size, int calls) {
    Builder b;
    Reg x = b.reg(Kind::F32), p = b.reg(Kind::F32), r = b.reg(Kind::F32);
    b.input("x", x);
    Reg k = b.kf(1.0001f);
    uint32_t f = b.function("long", [&] {
        Reg v = p;
        for (int i = 0; i < size; ++i) v = b.alu(Op::fmul, {v, k});
        b.mov(r, v);
    });
    for (int c = 0; c < calls; ++c) {
        b.alu_to(p, Op::fadd, {x, b.kf(float(c))});
        b.call(f);
        Reg out = b.reg(Kind::F32);
        b.mov(out, r);
        b.output("out", out);
    }
    return b.sh;
}

TEST_CASE("inline keeps a large function that main calls more than once as a call", "[ir][inline]") {
    auto calls_left = [](int size, int calls) {
        ir::Shader t = check_pass(chain_calls(size, calls), [](ir::Shader& s) { ir::inline_calls(s, 4000); });
        return count_kind(t, NodeKind::Call);
    };
    CHECK(calls_left(200, 2) == 2);  // the JIT compiles it once
    CHECK(calls_left(200, 3) == 3);
    CHECK(calls_left(200, 1) == 0);  // one copy: inlined
    CHECK(calls_left(40, 3) == 0);   // small: inlined
    // Through a caller that is itself inlined: two paths to `long`.
    Builder b;
    Reg x = b.reg(Kind::F32), r = b.reg(Kind::F32);
    b.input("x", x);
    uint32_t big = b.function("big", [&] {
        Reg v = x;
        for (int i = 0; i < 160; ++i) v = b.alu(Op::fadd, {v, x});
        b.mov(r, v);
    });
    uint32_t mid = b.function("mid", [&] { b.call(big); });
    b.call(mid);
    b.call(mid);
    b.output("r", r);
    ir::Shader t = check_pass(b.sh, [](ir::Shader& s) { ir::inline_calls(s, 4000); });
    CHECK(count_kind(t, NodeKind::Call) == 2);
    CHECK(t.functions.size() == 1);
}

TEST_CASE("inline does not share a callee's state-carrying registers", "[ir][inline]") {
    // g() { counter = counter + 1; } called three times: counter is read first.
    Builder b;
    Reg counter = b.reg(Kind::I32), out = b.reg(Kind::I32);
    Reg one = b.ki(1);
    uint32_t g = b.function("g", [&] { b.alu_to(counter, Op::iadd, {counter, one}); });
    b.call(g);
    b.call(g);
    b.call(g);
    b.mov(out, counter);
    b.output("out", out);
    ir::Shader t = check_pass(b.sh, [](ir::Shader& s) { ir::inline_calls(s, 4000); });
    CHECK(count_kind(t, NodeKind::Call) == 0);
    CHECK(run_outputs(t)[0] == 3u);
}

TEST_CASE("inline explosion: 2^64 call paths stay bounded", "[ir][inline]") {
    Builder b;
    Reg c = b.reg(Kind::Bool), y = b.reg(Kind::I32), out = b.reg(Kind::I32);
    b.input("c", c);
    Reg one = b.ki(1);
    std::vector<uint32_t> ids(64);
    ids[63] = b.function("f63", [&] { b.alu_to(y, Op::iadd, {y, one}); });
    for (int k = 62; k >= 0; --k)
        ids[k] = b.function("f", [&, k] {
            b.call(ids[k + 1]);
            b.call(ids[k + 1]);
        });
    Reg never = b.alu(Op::band, {c, b.alu(Op::bnot, {c})});
    b.if_(never, [&] { b.call(ids[0]); });
    b.call(ids[58]);  // 32 increments
    b.mov(out, y);
    b.output("out", out);
    auto start = std::chrono::steady_clock::now();
    ir::Shader t = b.sh;
    CHECK(ir::optimize(t, {}) == "");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
    CHECK(ir::flow::node_count(t.body) < 6000);
    CHECK(count_kind(t, NodeKind::Call) > 0);
    CHECK(run_outputs(t) == run_outputs(b.sh));
    CHECK(run_outputs(t)[0] == 32u);
}

TEST_CASE("optimize runs the pipeline and preserves outputs", "[ir][optimize]") {
    TwoCalls tc;
    Builder& b = tc.b;
    // extra foldable and dead work on top of the calls
    Reg k = b.alu(Op::fmul, {b.kf(2.0f), b.kf(0.5f)});
    Reg scaled = b.alu(Op::fmul, {tc.out1, k});
    b.alu(Op::fsin, {scaled});  // dead
    b.output("scaled", scaled);
    ir::Shader t = check_pass(b.sh, [](ir::Shader& s) { CHECK(ir::optimize(s, {}) == ""); });
    CHECK(t.functions.empty());
    CHECK(count_op(t, Op::fsin) == 0);
    CHECK(writer_of(t, k) == nullptr);  // folded to 1.0, a copy of the other 1.0, then dead
    ir::Shader off = b.sh;
    CHECK(ir::optimize(off, {false, 4000}) == "");
    CHECK(ir::print(off) == ir::print(b.sh));
}
