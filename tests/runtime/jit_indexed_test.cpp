// The JIT's generated indexed access (uniform_ind, load_ind, store_ind as
// gathers and a scatter, runtime/jit/alu.cpp) against the interpreter's
// kernels: indices below, inside and beyond the arrays (clamped), under
// full and partial masks, every register compared after the run.
#include <catch2/catch.hpp>

#include <climits>
#include <vector>

#include "runtime/backend_factory.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("generated indexed access gives the kernels' words", "[runtime][backend][jit_indexed]") {
    if (!jit_available()) return;
    const int32_t indices[] = {0, 1, 2, 3, 4, 5, 6, -1, -7, INT_MIN, INT_MAX, 1 << 30};
    constexpr int kIndices = sizeof indices / sizeof indices[0];
    Builder b;
    Reg idx = b.reg(Kind::I32), idx2 = b.reg(Kind::I32), val = b.reg(Kind::F32), cond = b.reg(Kind::Bool);
    Reg arr = b.range(Kind::F32, 5);
    Reg from_uniform = b.reg(Kind::F32), loaded = b.reg(Kind::F32), loaded_after = b.reg(Kind::F32);
    b.instr(Op::uniform_ind, Kind::F32, from_uniform, {idx}, {1, 4, 2});  // uniforms 1, 3, 5, 7
    b.instr(Op::load_ind, Kind::F32, loaded, {idx}, {arr, 5, 1});
    b.if_(cond, [&] { b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx2, val}, {arr + 1, 2, 2}); });
    b.instr(Op::load_ind, Kind::F32, loaded_after, {idx2}, {arr, 5, 1});
    for (Reg r = arr; r < arr + 5; ++r) b.output("arr", r);
    for (Reg r : {from_uniform, loaded, loaded_after}) b.output("r", r);
    std::vector<uint32_t> uniforms(12);
    for (size_t i = 0; i < uniforms.size(); ++i) uniforms[i] = bits(float(i) + 0.5f);
    rt::ExecParams params{uniforms.data(), 10, nullptr, Precision::Precise, rt::kAllFastOps};
    for (bool avx2 : {false, true}) {
        if (avx2 && !rt::cpu_has_avx2()) continue;
        auto interp = rt::compile_shader(b.sh, rt::Runner::Interp, Precision::Precise, params.fast_ops, avx2);
        auto jit = rt::compile_shader(b.sh, rt::Runner::Jit, Precision::Precise, params.fast_ops, avx2);
        REQUIRE(jit);
        auto ia = interp->instantiate(params), ja = jit->instantiate(params);
        for (int round = 0; round < 2 * kIndices; ++round) {
            const rt::LaneMask live = round % 2 ? rt::LaneMask(0x6c6c6c6c6c6c6c6cull) & rt::kAllLanes : rt::kAllLanes;
            for (rt::Executor* e : {ia.get(), ja.get()})
                for (int lane = 0; lane < rt::kLanes; ++lane) {
                    e->lanes(idx)[lane] = bits(indices[(lane + round) % kIndices]);
                    e->lanes(idx2)[lane] = bits(indices[(lane * 5 + round / 2) % kIndices]);
                    e->lanes(val)[lane] = bits(-float(lane + 100 * round));
                    e->lanes(cond)[lane] = (lane + round) % 3 != 0;
                    for (Reg r = arr; r < arr + 5; ++r) e->lanes(r)[lane] = bits(float(r * 1000 + lane));
                    for (Reg r : {from_uniform, loaded, loaded_after}) e->lanes(r)[lane] = 0xdeadbeefu;
                }
            REQUIRE(ia->run(live, nullptr));
            REQUIRE(ja->run(live, nullptr));
            for (const ir::Binding& out : b.sh.outputs)
                for (int lane = 0; lane < rt::kLanes; ++lane) {
                    const Reg r = out.first;
                    INFO("register " << r << " lane " << lane << " round " << round << (avx2 ? " avx2" : " baseline"));
                    CHECK(ia->lanes(r)[lane] == ja->lanes(r)[lane]);
                }
        }
    }
}
