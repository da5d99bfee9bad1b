// The JIT's generated transcendental built-ins (runtime/jit/math.cpp) against
// the interpreter's kernels, bit for bit: every lane of every op, in Precise
// and Fast, with the baseline and the AVX2 code, on special values (signed
// zeros, denormals, infinities, NaNs with payloads and signs, signalling
// NaNs), the functions' range-reduction and special-case boundaries and their
// neighbours, and random bit patterns and random values in the ops' ranges.
// Integer division and remainder likewise, on their edge cases (0, -1, INT_MIN).
// CI runs this at 8, 16 and 64 lanes (tools/setup.sh).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "runtime/interp_kernels.h"
#include "tests/runtime/backend_pair.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

// Values where the functions change behaviour, and one float either side.
std::vector<uint32_t> boundary_words() {
    const float pi2 = 1.5707963267948966f;
    const float values[] = {
        0.0f, 1.0f, 0.5f, 2.0f, 3.0f, 10.0f, 0.1f, 1e-3f, 1.17549435e-38f, 1e-37f, 1e-30f, 1e30f, 3.4e38f,
        0x1p23f, 0x1p23f + 1.0f, 0x1p24f, 0x1p24f + 2.0f, 0x1p23f - 0.5f, 0x1p22f, 8388607.5f,
        0.49999997f, 1.5f, 2.5f, 126.0f, 127.0f, 128.0f, 129.0f, 149.0f, 150.0f, 151.0f, 152.0f, 200.0f,
        88.72283f, 87.33654f, 103.97208f, 0.70710677f, 1.4142135f, 0.6931472f, 1.442695f,
        pi2 / 2, pi2, 2 * pi2, 3 * pi2, 4 * pi2, 100 * pi2, 8192 * pi2, 0x1p13f * pi2, 0x1p22f * pi2,
        0x1p29f * pi2, 0x1p50f, 1e10f, 12345.678f, 0.786f, 0.41421357f, 2.4142137f, 0.99999994f, 0.7853982f};
    std::vector<uint32_t> words;
    for (float v : values)
        for (float s : {v, -v}) {
            words.push_back(bits(s));
            words.push_back(bits(std::nextafter(s, INFINITY)));
            words.push_back(bits(std::nextafter(s, -INFINITY)));
        }
    for (uint32_t w : {0x3F3504F3u, 0x3FB504F3u})  // log2's mantissa split, sqrt(2)/2 and sqrt(2)
        for (uint32_t d : {0u, 1u, 2u}) words.insert(words.end(), {w + d, w - d});
    const uint32_t special[] = {0x00000001u, 0x80000001u, 0x007fffffu, 0x807fffffu, 0x00400000u, 0x7f800000u,
                                0xff800000u, 0x7fc00000u, 0xffc00000u, 0x7fc01234u, 0xffd00001u, 0x7f800001u,
                                0xff812345u, 0x7fa00000u, 0x7f7fffffu, 0xff7fffffu};
    words.insert(words.end(), std::begin(special), std::end(special));
    return words;
}

// Operand pairs for a unary (b unused) or binary op: every boundary value as
// a, against every boundary value as b for binary ops; then random ones.
struct Inputs {
    std::vector<uint32_t> a, b;
};
Inputs inputs(bool binary, int randoms) {
    const std::vector<uint32_t> edge = boundary_words();
    Inputs in;
    for (uint32_t x : edge)
        for (size_t j = 0; j < (binary ? edge.size() : 1); ++j) {
            in.a.push_back(x);
            in.b.push_back(edge[j]);
        }
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> range(-160.0f, 160.0f), exponent(-40.0f, 40.0f), unit(-1.1f, 1.1f);
    for (int i = 0; i < randoms; ++i) {
        const int kind = i / 64 % 4;  // runs of one kind fill whole batches (pow: all lanes common)
        auto pick = [&]() -> uint32_t {
            if (kind == 0) return uint32_t(rng());  // any bit pattern
            if (kind == 1) return bits(range(rng));
            if (kind == 3) return bits(unit(rng));  // asin's and acos's domain
            return bits(std::exp2(exponent(rng)));  // positive, many magnitudes (pow's x)
        };
        in.a.push_back(pick());
        in.b.push_back(kind == 2 ? bits(range(rng) / 16) : pick());
    }
    return in;
}

// Runs `op` on every (a[i], b[i]) in both backends and compares the results
// word for word; every fourth batch runs under a partial mask, where the
// other lanes must keep r's old words.
void compare_backends(Op op, Precision precision, bool avx2, const Inputs& in, uint32_t fast_ops = rt::kAllFastOps) {
    const bool binary = ir::op_info(op).arity == 2;
    Builder b;
    const Kind kind = ir::op_info(op).operand == ir::TypeClass::F ? Kind::F32 : Kind::I32;
    Reg x = b.reg(kind), y = b.reg(kind), r = b.reg(kind);
    b.instr(op, kind, r, binary ? std::initializer_list<Reg>{x, y} : std::initializer_list<Reg>{x});
    b.output("r", r);
    std::vector<uint32_t> uniforms(4);
    rt::ExecParams params{uniforms.data(), 10, nullptr, precision, fast_ops};
    test::BackendPair pair = test::both_backends(b.sh, precision, params, avx2);
    rt::Executor *ia = pair.interp.get(), *ja = pair.jit.get();
    size_t mismatches = 0;
    for (size_t k = 0; k < in.a.size(); k += rt::kLanes) {
        const rt::LaneMask live =
            (k / rt::kLanes) % 4 == 3 ? rt::LaneMask(0x5a5a5a5a5a5a5a5aull) & rt::kAllLanes : rt::kAllLanes;
        for (rt::Executor* e : {ia, ja})
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                const size_t i = (k + size_t(lane)) % in.a.size();
                e->lanes(x)[lane] = in.a[i];
                e->lanes(y)[lane] = in.b[i];
                e->lanes(r)[lane] = 0xdeadbeefu + uint32_t(lane);
            }
        REQUIRE(ia->run(live, nullptr));
        REQUIRE(ja->run(live, nullptr));
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            if (ia->lanes(r)[lane] == ja->lanes(r)[lane] || ++mismatches > 8) continue;
            INFO(ir::op_info(op).name << " " << precision_name(precision) << (avx2 ? " avx2" : " baseline") << std::hex
                                      << " a " << ia->lanes(x)[lane] << " b " << ia->lanes(y)[lane] << " interp "
                                      << ia->lanes(r)[lane] << " jit " << ja->lanes(r)[lane]);
            CHECK(ia->lanes(r)[lane] == ja->lanes(r)[lane]);
        }
    }
    CHECK(mismatches == 0);
}

}  // namespace

TEST_CASE("generated built-ins give the kernels' bits", "[runtime][backend][jit_math]") {
    if (!jit_available()) return;
    // Every op the JIT generates (runtime/jit/math.cpp), from the table's
    // columns: its Libm ops and those Fast approximates.
    int generated = 0;
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {
        const Op op = Op(o);
        if (!ir::has(op, ir::OpProp::Libm) && ir::op_info(op).fast == ir::FastClass::Exact) continue;
        if (ir::op_info(op).fast == ir::FastClass::Fma) continue;  // ternary: contract_lanes_test.cpp
        ++generated;
        const Inputs in = inputs(ir::op_info(op).arity == 2, 1 << 20);
        for (Precision precision : {Precision::Precise, Precision::Fast})
            for (bool avx2 : {false, true})
                if (!avx2 || rt::cpu_has_avx2()) compare_backends(op, precision, avx2, in);
    }
    CHECK(generated >= 15);  // as many as when this test was written
}

// Every Fast op over a dense sweep of all 2^32 words (every 1021st: all
// exponents, signs, denormals, infinities and NaN payloads, the mantissas
// well mixed); a binary op's second operand from a set that covers its
// cases (pow's integer, fractional, huge, tiny, negative and NaN exponents).
TEST_CASE("generated Fast built-ins give the kernels' bits over a dense sweep of floats", "[runtime][backend][jit_math]") {
    if (!jit_available()) return;
    const float seconds[] = {2.0f, 0.5f, 48.0f, -1.3f, 1e-3f, 100.0f, -0.0f, 0x1p-130f, INFINITY, NAN};
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {
        const Op op = Op(o);
        const ir::FastClass fast_class = ir::op_info(op).fast;
        if (fast_class == ir::FastClass::Exact || fast_class == ir::FastClass::Fma) continue;  // Fma: contract_lanes_test.cpp
        const bool binary = ir::op_info(op).arity == 2;
        Inputs in;
        for (uint64_t w = 0; w < (uint64_t(1) << 32); w += binary ? 16381 : 1021)
            for (size_t j = 0; j < (binary ? std::size(seconds) : 1); ++j) {
                in.a.push_back(uint32_t(w));
                in.b.push_back(bits(seconds[j]));
            }
        for (bool avx2 : {false, true})
            if (!avx2 || rt::cpu_has_avx2()) compare_backends(op, Precision::Fast, avx2, in);
    }
}

// Fast's rsqrt class is native code, not generated math: 1/sqrt and a
// multiply in Fast, Precise's square root and division where the error
// report's ablation leaves the class out of the fast ops.
TEST_CASE("Fast's inline rsqrt class gives the kernels' bits, with the class on and off", "[runtime][backend][jit_math]") {
    if (!jit_available()) return;
    for (Op op : {Op::frsqrt, Op::fsqrt_divisor, Op::fdiv_by_sqrt}) {
        const Inputs in = inputs(ir::op_info(op).arity == 2, 1 << 16);
        for (uint32_t fast_ops : {uint32_t(rt::kAllFastOps), uint32_t(rt::kAllFastOps & ~rt::kFastRsqrt)})
            for (bool avx2 : {false, true})
                if (!avx2 || rt::cpu_has_avx2()) compare_backends(op, Precision::Fast, avx2, in, fast_ops);
    }
}

TEST_CASE("generated integer division gives the kernels' words", "[runtime][backend][jit_math]") {
    if (!jit_available()) return;
    const int32_t edge[] = {0, 1, -1, 2, -2, 3, 7, -7, 100, INT32_MAX, INT32_MIN, INT32_MIN + 1, INT32_MAX - 1};
    Inputs in;
    for (int32_t a : edge)
        for (int32_t b : edge) in.a.push_back(bits(a)), in.b.push_back(bits(b));
    std::mt19937 rng(5);
    for (int i = 0; i < 1 << 16; ++i) {
        in.a.push_back(uint32_t(rng()));
        in.b.push_back(i % 2 ? uint32_t(rng()) : uint32_t(int32_t(rng() % 33) - 16));  // small divisors, 0 and -1
    }
    for (Op op : {Op::idiv, Op::imod})
        for (bool avx2 : {false, true})
            if (!avx2 || rt::cpu_has_avx2()) compare_backends(op, Precision::Precise, avx2, in);
}
