// The JIT drops the denormal flush before floor, ceil, neg and abs where
// the operand is an arithmetic result, which FTZ flushed already
// (runtime/jit/flushed.h), and keeps it elsewhere: inputs, picks (min, max,
// sel) of inputs, moves. Every case against the interpreter, with denormal,
// zero, NaN and ordinary operands.
#include <catch2/catch.hpp>

#include "runtime/interp_kernels.h"
#include "tests/runtime/backend_pair.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("flushes before floor, ceil, neg and abs agree with the interpreter", "[runtime][backend][jit_flush]") {
    if (!jit_available()) return;
    const uint32_t words[] = {0x00000001u, 0x80000001u, 0x807fffffu, 0x00400000u, bits(-1.5e-38f), bits(1.2e-38f),
                              bits(0.0f),  bits(-0.0f),  bits(-2.5f),  bits(3.75f),  0x7fc00000u,     0xff800000u,
                              bits(1e-20f), bits(-1e-20f), bits(0.5f), bits(-1.0f)};
    constexpr int n = int(std::size(words));
    for (Op op : {Op::ffloor, Op::fceil, Op::fneg, Op::fabs})
        for (Precision precision : {Precision::Precise, Precision::Fast})
            for (bool avx2 : {false, true}) {
                if (avx2 && !rt::cpu_has_avx2()) continue;
                Builder b;
                Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32);
                Reg product = b.alu(Op::fmul, {x, y}), sum = b.alu(Op::fadd, {x, y});
                Reg low = b.alu(Op::fmin, {x, y}), moved = b.reg(Kind::F32), neg = b.alu(Op::fneg, {x});
                b.mov(moved, y);
                const Reg operands[] = {x, product, sum, low, moved, neg, b.alu(Op::fneg, {product})};
                std::vector<Reg> results;
                for (Reg a : operands) {
                    results.push_back(b.alu(op, {a}));
                    b.output("r", results.back());
                }
                std::vector<uint32_t> uniforms(4);
                rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
                BackendPair pair = both_backends(b.sh, precision, params, avx2);
                REQUIRE(pair.jit->runner() == rt::Runner::Jit);
                for (int k = 0; k < n * n; k += rt::kLanes) {
                    for (rt::Executor* e : {pair.interp.get(), pair.jit.get()})
                        for (int lane = 0; lane < rt::kLanes; ++lane) {
                            e->lanes(x)[lane] = words[(k + lane) % n];
                            e->lanes(y)[lane] = words[(k + lane) / n % n];
                        }
                    REQUIRE(pair.interp->run(rt::kAllLanes, nullptr));
                    REQUIRE(pair.jit->run(rt::kAllLanes, nullptr));
                    for (size_t i = 0; i < results.size(); ++i)
                        for (int lane = 0; lane < rt::kLanes; ++lane) {
                            INFO(ir::op_info(op).name << " operand " << i << " " << precision_name(precision)
                                                      << (avx2 ? " avx2" : " baseline") << std::hex << " x "
                                                      << pair.interp->lanes(x)[lane] << " y "
                                                      << pair.interp->lanes(y)[lane]);
                            CHECK(pair.interp->lanes(results[i])[lane] == pair.jit->lanes(results[i])[lane]);
                        }
                }
            }
}
