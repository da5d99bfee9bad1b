// Which NaN an op returns when its operands are NaNs of different signs or
// payloads: both backends must return the same word (the interpreter is the
// JIT's oracle), whatever order the compilers put the operands in.
#include <catch2/catch.hpp>

#include "runtime/backend_factory.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("backends return the same NaN for NaN operands", "[runtime][backend][nan]") {
    if (!jit_available()) return;
    // Quiet NaNs, signalling ones (an op returns them quieted), numbers.
    const uint32_t words[] = {0x7fc00000u, 0xffc00000u, 0x7fc01234u, 0xffd00001u, 0x7fa00001u, 0xff800123u,
                              bits(1.0f),  bits(-0.0f), 0x7f800000u, 0xff800000u};
    constexpr int n = int(std::size(words));
    const Op ops[] = {Op::fadd, Op::fsub, Op::fmul, Op::fdiv, Op::fmod, Op::fmin, Op::fmax, Op::fmad, Op::fmsub,
                      Op::fnmadd, Op::ffract, Op::fdiv_by_sqrt, Op::fneg, Op::fabs, Op::fsqrt, Op::ddx, Op::ddy};
    for (Op op : ops)
        for (Precision precision : {Precision::Precise, Precision::Fast})
            for (bool avx2 : {false, true}) {
                if (avx2 && !rt::cpu_has_avx2()) continue;
                Builder b;
                Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32), z = b.reg(Kind::F32), r = b.reg(Kind::F32);
                const int arity = ir::op_info(op).arity;
                b.output("r", r);
                b.instr(op, Kind::F32, r, arity == 1 ? std::initializer_list<Reg>{x} : arity == 2 ? std::initializer_list<Reg>{x, y} : std::initializer_list<Reg>{x, y, z});
                std::vector<uint32_t> uniforms(4);
                rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
                auto interp = rt::compile_shader(b.sh, rt::Runner::Interp, precision, params.fast_ops, avx2);
                auto jit = rt::compile_shader(b.sh, rt::Runner::Jit, precision, params.fast_ops, avx2);
                auto ia = interp->instantiate(params), ja = jit->instantiate(params);
                for (int k = 0; k < n * n * n; k += rt::kLanes) {
                    for (rt::Executor* e : {ia.get(), ja.get()})
                        for (int lane = 0; lane < rt::kLanes; ++lane) {
                            const int c = (k + lane) % (n * n * n);
                            e->lanes(x)[lane] = words[c % n];
                            e->lanes(y)[lane] = words[c / n % n];
                            e->lanes(z)[lane] = words[c / (n * n)];
                        }
                    REQUIRE(ia->run(rt::kAllLanes, nullptr));
                    REQUIRE(ja->run(rt::kAllLanes, nullptr));
                    for (int lane = 0; lane < rt::kLanes; ++lane) {
                        INFO(ir::op_info(op).name << " " << precision_name(precision) << (avx2 ? " avx2" : " baseline")
                                                  << std::hex << " x " << ia->lanes(x)[lane] << " y " << ia->lanes(y)[lane]
                                                  << " z " << ia->lanes(z)[lane]);
                        CHECK(ia->lanes(r)[lane] == ja->lanes(r)[lane]);
                    }
                }
            }
}

// The JIT writes + and * as plain LLVM operations where its operands cannot
// be two different NaNs (runtime/jit/alu.cpp: the same register twice, or
// one operand a prologue constant compiled in): the interpreter's words
// still, for NaN, infinite, denormal and overflowing operands.
TEST_CASE("backends agree on + and * of a register with itself or a constant", "[runtime][backend][nan]") {
    if (!jit_available()) return;
    const uint32_t words[] = {0x7fc00000u, 0xffc00000u, 0x7fc01234u, 0xffd00001u, 0x7fa00001u, 0xff800123u,
                              bits(1.0f),  bits(-0.0f), 0x7f800000u, 0xff800000u, 0x00000001u, 0x80400000u,
                              bits(3.0e38f), bits(-1.5e-38f), bits(0.3f), bits(-7.25f)};
    constexpr int n = int(std::size(words));
    const float constants[] = {2.0f, 0.3f, -6.0f, 1.5e-38f, 3.0e38f, -1e-30f};
    // Operand patterns: 'x', 'y' registers, 'k', 'm' constants.
    const struct {
        Op op;
        const char* operands;
    } cases[] = {{Op::fadd, "xk"}, {Op::fadd, "kx"}, {Op::fadd, "xx"}, {Op::fmul, "xk"}, {Op::fmul, "kx"},
                 {Op::fmul, "xx"}, {Op::fmad, "xxk"}, {Op::fmad, "kxy"}, {Op::fmad, "xky"}, {Op::fmad, "xyk"},
                 {Op::fmad, "xxy"}, {Op::fmad, "kmx"}, {Op::fmad, "xkx"}, {Op::fmad, "xyx"}};
    for (const auto& c : cases)
        for (float constant : constants)
            for (Precision precision : {Precision::Precise, Precision::Fast})
                for (bool avx2 : {false, true}) {
                    if (avx2 && !rt::cpu_has_avx2()) continue;
                    Builder b;
                    Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32), k = b.reg(Kind::F32), m = b.reg(Kind::F32);
                    Reg r = b.reg(Kind::F32);
                    b.cur = &b.sh.prologue;  // as ir/hoist.cpp leaves a source's literal
                    b.set_konst(k, bits(constant));
                    b.set_konst(m, bits(-0.75f));
                    b.cur = &b.sh.body;
                    b.output("r", r);
                    auto operand = [&](char o) { return o == 'x' ? x : o == 'y' ? y : o == 'k' ? k : m; };
                    const std::string ops = c.operands;
                    if (ops.size() == 2) b.instr(c.op, Kind::F32, r, {operand(ops[0]), operand(ops[1])});
                    else b.instr(c.op, Kind::F32, r, {operand(ops[0]), operand(ops[1]), operand(ops[2])});
                    std::vector<uint32_t> uniforms(4);
                    rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
                    auto interp = rt::compile_shader(b.sh, rt::Runner::Interp, precision, params.fast_ops, avx2);
                    auto jit = rt::compile_shader(b.sh, rt::Runner::Jit, precision, params.fast_ops, avx2);
                    auto ia = interp->instantiate(params), ja = jit->instantiate(params);
                    REQUIRE(ja->runner() == rt::Runner::Jit);
                    for (int j = 0; j < n * n; j += rt::kLanes) {
                        for (rt::Executor* e : {ia.get(), ja.get()})
                            for (int lane = 0; lane < rt::kLanes; ++lane) {
                                e->lanes(x)[lane] = words[(j + lane) % n];
                                e->lanes(y)[lane] = words[(j + lane) / n % n];
                            }
                        REQUIRE(ia->run(rt::kAllLanes, nullptr));
                        REQUIRE(ja->run(rt::kAllLanes, nullptr));
                        for (int lane = 0; lane < rt::kLanes; ++lane) {
                            INFO(ir::op_info(c.op).name << " " << ops << " k " << constant << " "
                                                        << precision_name(precision) << (avx2 ? " avx2" : " baseline")
                                                        << std::hex << " x " << ia->lanes(x)[lane] << " y "
                                                        << ia->lanes(y)[lane]);
                            CHECK(ia->lanes(r)[lane] == ja->lanes(r)[lane]);
                        }
                    }
                }
}
