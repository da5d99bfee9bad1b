// The JIT makes the budget charges of inlined functions' blocks at the
// entry of an enclosing block (runtime/jit/charges.h). Under every budget
// from nothing to more than the run needs, it must stop where the
// interpreter stops as far as a caller can see: the same error, alive lanes
// and outputs, so never past a write of an output, a discard, a loop or a
// call; and it must charge the same total (a budget of exactly that total
// suffices, one less does not).
#include <catch2/catch.hpp>

#include "runtime/interp_kernels.h"
#include "tests/runtime/backend_pair.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

// main: an output written, nested inlined functions (one with an early
// return in an If, one discarding, one with a loop), another output
// between them, and an If whose blocks hold inlined functions.
void build(Builder& b, Reg x, Reg out1, Reg out2, Reg out3) {
    Reg one = b.kf(1.0f), limit = b.ki(3), k1 = b.ki(1);
    Reg t = b.reg(Kind::F32), n = b.reg(Kind::I32), c = b.reg(Kind::Bool), stop = b.reg(Kind::Bool);
    b.output("out1", out1);
    b.output("out2", out2);
    b.output("out3", out3);
    b.alu_to(t, Op::fadd, {x, one});
    b.scope([&] {
        b.alu_to(t, Op::fmul, {t, t});
        b.scope([&] {
            b.alu_to(t, Op::fadd, {t, one});
            b.ret();
        });
        b.alu_to(out1, Op::fadd, {t, x});  // an output: what follows charges after it
        b.scope([&] {
            b.alu_to(t, Op::fsub, {t, one});
            b.alu_to(c, Op::flt, {t, x});
            b.if_(c, [&] { b.ret(); });
            b.alu_to(t, Op::fmul, {t, x});
            b.ret();
        });
        b.ret();
    });
    b.scope([&] {
        b.alu_to(c, Op::fgt, {t, one});
        b.if_(c, [&] { b.discard(); });
        b.alu_to(t, Op::fadd, {t, t});
    });
    b.scope([&] {
        b.alu_to(out2, Op::fmul, {t, one});
        b.instr(Op::konst, Kind::I32, n, {}, {0});
        b.loop([&] {
            b.alu_to(stop, Op::ige, {n, limit});
            b.if_(stop, [&] { b.brk(); });
            b.scope([&] { b.alu_to(t, Op::fadd, {t, one}); });
        }, [&] { b.alu_to(n, Op::iadd, {n, k1}); });
    });
    b.if_(c, [&] { b.scope([&] { b.alu_to(out3, Op::fadd, {t, t}); }); },
          [&] { b.scope([&] { b.alu_to(out3, Op::fsub, {t, one}); }); });
    b.scope([&] { b.alu_to(out1, Op::fadd, {out1, t}); });
}

}  // namespace

TEST_CASE("the JIT's merged charges stop a run where the interpreter stops it", "[runtime][backend][jit_charges]") {
    if (!jit_available()) return;
    Builder b;
    Reg x = b.reg(Kind::F32), out1 = b.reg(Kind::F32), out2 = b.reg(Kind::F32), out3 = b.reg(Kind::F32);
    b.input("x", x);
    build(b, x, out1, out2, out3);
    std::vector<uint32_t> uniforms(4);
    uint64_t succeeded_from = 0;
    for (uint64_t budget = 1; budget < 120 && !succeeded_from; ++budget) {
        rt::ExecParams params{uniforms.data(), 100, nullptr, Precision::Precise, rt::kAllFastOps};
        params.limits.max_instructions = budget;
        BackendPair pair = both_backends(b.sh, Precision::Precise, params, rt::cpu_has_avx2());
        REQUIRE(pair.jit->runner() == rt::Runner::Jit);
        std::string logs[2];
        int k = 0;
        for (rt::Executor* e : {pair.interp.get(), pair.jit.get()}) {
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                e->lanes(x)[lane] = bits(float(lane % 7) * 0.25f - 0.5f);
                for (Reg o : {out1, out2, out3}) e->lanes(o)[lane] = 0xdeadbeefu;
            }
            rt::RunError error;
            const bool ok = e->run(rt::kAllLanes, &error);
            logs[k++] = ok ? "ok" : error.message;
        }
        INFO("budget " << budget);
        REQUIRE(logs[0] == logs[1]);
        CHECK(pair.interp->alive() == pair.jit->alive());
        for (Reg o : {out1, out2, out3})
            for (int lane = 0; lane < rt::kLanes; ++lane) CHECK(pair.interp->lanes(o)[lane] == pair.jit->lanes(o)[lane]);
        if (logs[0] == "ok") succeeded_from = budget;
    }
    // Every budget below the run's total fails; the total is well inside the sweep.
    CHECK(succeeded_from > 20);
    CHECK(succeeded_from < 119);
}
