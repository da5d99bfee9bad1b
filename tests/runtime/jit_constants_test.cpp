// The JIT compiles the prologue's constants into the body's code, and a
// division or mod() by a constant power of two as a multiplication by its
// reciprocal: the interpreter divides, and both must give the same word for
// every dividend (denormals, the largest floats, infinities, NaNs, zeros)
// and every divisor, including those where the multiplication would not be
// exact (a reciprocal that is denormal or infinite, a divisor that is not a
// power of two).
#include <catch2/catch.hpp>

#include <limits>

#include "runtime/interp_kernels.h"
#include "tests/runtime/backend_pair.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("division and mod by prologue constants agree with the interpreter", "[runtime][backend][jit_constants]") {
    if (!jit_available()) return;
    const float divisors[] = {256.0f, 4.0f, 16.0f, 0.5f, -0.25f, 1.0f, -1.0f, 0x1p-126f, 0x1p126f, 0x1p127f,
                              0x1p-127f /* denormal */, 0x1p-149f, 3.0f, -6.0f, 0.1f, 0.0f, -0.0f,
                              std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()};
    const uint32_t dividends[] = {bits(1.0f), bits(-1.0f), bits(0.0f), bits(-0.0f), bits(255.5f), bits(-1000.25f),
                                  bits(3.0e38f), bits(-3.4028235e38f), bits(1.1754944e-38f), 0x00000001u,
                                  0x807fffffu, 0x00400000u, bits(7.0e-39f), bits(1.0e-30f), bits(12345.678f),
                                  bits(-0.3f), 0x7f800000u, 0xff800000u, 0x7fc00000u, 0xffd00001u, 0x7fa00001u,
                                  bits(16777215.0f), bits(-16777216.0f), bits(0.0625f)};
    constexpr int n = int(std::size(dividends));
    for (float divisor : divisors)
        for (Precision precision : {Precision::Precise, Precision::Fast})
            for (bool avx2 : {false, true}) {
                if (avx2 && !rt::cpu_has_avx2()) continue;
                Builder b;
                Reg x = b.reg(Kind::F32), d = b.reg(Kind::F32), q = b.reg(Kind::F32), m = b.reg(Kind::F32);
                b.cur = &b.sh.prologue;  // as ir/hoist.cpp leaves a source's literal
                b.set_konst(d, bits(divisor));
                b.cur = &b.sh.body;
                b.output("q", q);
                b.output("m", m);
                b.instr(Op::fdiv, Kind::F32, q, {x, d});
                b.instr(Op::fmod, Kind::F32, m, {x, d});
                std::vector<uint32_t> uniforms(4);
                rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
                test::BackendPair pair = test::both_backends(b.sh, precision, params, avx2);
                rt::Executor *ia = pair.interp.get(), *ja = pair.jit.get();
                REQUIRE(ja->runner() == rt::Runner::Jit);
                for (int k = 0; k < n; k += rt::kLanes) {
                    for (rt::Executor* e : {ia, ja})
                        for (int lane = 0; lane < rt::kLanes; ++lane) e->lanes(x)[lane] = dividends[(k + lane) % n];
                    REQUIRE(ia->run(rt::kAllLanes, nullptr));
                    REQUIRE(ja->run(rt::kAllLanes, nullptr));
                    for (int lane = 0; lane < rt::kLanes; ++lane) {
                        INFO(precision_name(precision) << (avx2 ? " avx2" : " baseline") << " divisor " << divisor
                                                       << std::hex << " x " << ia->lanes(x)[lane]);
                        CHECK(ia->lanes(q)[lane] == ja->lanes(q)[lane]);
                        CHECK(ia->lanes(m)[lane] == ja->lanes(m)[lane]);
                    }
                }
            }
}
