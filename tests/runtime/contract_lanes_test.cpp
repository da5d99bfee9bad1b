// The contracted multiply-adds (ffma, ffms, ffnma; ir/contract.cpp): one
// rounding in Fast, two in Precise, and the interpreter's kernels and the
// JIT's code give the same bits on every lane, with the baseline and the AVX2
// code (GLSLRUN_NO_AVX2=1 picks the baseline), on operands where one rounding
// and two differ, on special values (NaNs in every position) and on random ones.
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

struct Triples {
    std::vector<uint32_t> a, b, c;
    void add(uint32_t x, uint32_t y, uint32_t z) {
        a.push_back(x);
        b.push_back(y);
        c.push_back(z);
    }
};

// a = 1 + u/4096, b = 1 + v/4096 and c = ±(1 + (u + v)/4096) are exact, and
// a*b = |c| + u*v/2^24: one rounding keeps u*v/2^24, two lose it where u*v
// is odd (tools/gpu_probes/fma.frag's construction).
float unit(int k) { return 1.0f + float(k) / 4096.0f; }

// Operands for `op` where the exact result is u*v/2^24 (ffma, ffms) or
// -u*v/2^24 (ffnma).
Triples differing(Op op) {
    Triples t;
    for (int u = 1; u < 256; u += 2)
        for (int v = 1; v < 256; v += 6) {
            const float p = unit(u + v);
            t.add(bits(unit(u)), bits(unit(v)), bits(op == Op::ffma ? -p : p));
        }
    return t;
}

Triples specials_and_randoms() {
    const uint32_t special[] = {0x00000000u, 0x80000000u, 0x00000001u, 0x807fffffu, 0x00800000u, 0x3f800000u,
                                0xbf800000u, 0x7f7fffffu, 0xff7fffffu, 0x7f800000u, 0xff800000u, 0x7fc00000u,
                                0xffc01234u, 0x7f800001u, 0x1f800000u, 0x5f800000u, 0x3f800001u, 0xbf7fffffu};
    Triples t;
    for (uint32_t x : special)
        for (uint32_t y : special)
            for (uint32_t z : special) t.add(x, y, z);
    std::mt19937 rng(25);
    std::uniform_real_distribution<float> range(-4.0f, 4.0f);
    for (int i = 0; i < 1 << 15; ++i) {
        const float x = range(rng), y = range(rng);
        // Half the sums cancel most of the product, where the rounding shows.
        const float z = i % 2 ? range(rng) : -(x * y) * (1.0f + float(i % 7) * 0x1p-22f);
        t.add(bits(x), bits(y), bits(z));
    }
    return t;
}

// Runs `op` on every triple in both backends; returns the interpreter's
// results and checks that the JIT's are the same words, also under a partial
// mask (every fourth batch), where the other lanes keep their old words.
std::vector<uint32_t> run_both(Op op, Precision precision, bool avx2, const Triples& in) {
    Builder b;
    Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32), z = b.reg(Kind::F32), r = b.reg(Kind::F32);
    b.instr(op, Kind::F32, r, {x, y, z});
    b.output("r", r);
    std::vector<uint32_t> uniforms(4);
    rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
    test::BackendPair pair = test::both_backends(b.sh, precision, params, avx2);
    rt::Executor *ia = pair.interp.get(), *ja = pair.jit.get();
    std::vector<uint32_t> out(in.a.size());
    size_t mismatches = 0;
    for (size_t k = 0; k < in.a.size(); k += rt::kLanes) {
        const bool partial = (k / rt::kLanes) % 4 == 3;
        const rt::LaneMask live = partial ? rt::LaneMask(0x5a5a5a5a5a5a5a5aull) & rt::kAllLanes : rt::kAllLanes;
        for (rt::Executor* e : {ia, ja})
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                const size_t i = (k + size_t(lane)) % in.a.size();
                e->lanes(x)[lane] = in.a[i];
                e->lanes(y)[lane] = in.b[i];
                e->lanes(z)[lane] = in.c[i];
                e->lanes(r)[lane] = 0xdeadbeefu + uint32_t(lane);
            }
        REQUIRE(ia->run(live, nullptr));
        REQUIRE(ja->run(live, nullptr));
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            const size_t i = k + size_t(lane);
            if (i < out.size() && !partial) out[i] = ia->lanes(r)[lane];
            if (ia->lanes(r)[lane] == ja->lanes(r)[lane] || ++mismatches > 8) continue;
            INFO(ir::op_info(op).name << " " << precision_name(precision) << (avx2 ? " avx2" : " baseline") << std::hex
                                      << " a " << ia->lanes(x)[lane] << " b " << ia->lanes(y)[lane] << " c "
                                      << ia->lanes(z)[lane] << " interp " << ia->lanes(r)[lane] << " jit "
                                      << ja->lanes(r)[lane]);
            CHECK(ia->lanes(r)[lane] == ja->lanes(r)[lane]);
        }
    }
    CHECK(mismatches == 0);
    return out;
}

std::vector<bool> isas() {
    std::vector<bool> v{false};
    if (rt::cpu_has_avx2()) v.push_back(true);
    return v;
}

}  // namespace

TEST_CASE("contracted multiply-adds round once in Fast and twice in Precise", "[runtime][backend][contract]") {
    if (!jit_available()) return;
    for (Op op : {Op::ffma, Op::ffms, Op::ffnma}) {
        const Triples in = differing(op);
        for (bool avx2 : isas()) {
            const std::vector<uint32_t> fast = run_both(op, Precision::Fast, avx2, in);
            const std::vector<uint32_t> precise = run_both(op, Precision::Precise, avx2, in);
            size_t fused_differs = 0, checked = 0;
            for (size_t i = 0; i + rt::kLanes <= in.a.size(); ++i) {
                if ((i / rt::kLanes) % 4 == 3) continue;  // the partial batches: not every lane ran
                const float a = as_float(in.a[i]), b = as_float(in.b[i]), c = as_float(in.c[i]);
                const double exact = double(a) * double(b) - std::fabs(double(c));  // u*v / 2^24, exact in float
                const float want_fast = float(op == Op::ffnma ? -exact : exact);
                const float ab = a * b;  // rounded, as two roundings do
                const float want_precise = op == Op::ffma ? ab + c : op == Op::ffms ? ab - c : c - ab;
                INFO(ir::op_info(op).name << (avx2 ? " avx2" : " baseline") << " a " << a << " b " << b << " c " << c);
                CHECK(fast[i] == bits(want_fast));
                CHECK(precise[i] == bits(want_precise));
                fused_differs += want_fast != want_precise;
                ++checked;
            }
            CHECK(checked > 1000);
            CHECK(fused_differs * 2 > checked);  // the inputs do tell one rounding from two
        }
    }
}

TEST_CASE("contracted multiply-adds give the same bits in the interpreter and the JIT", "[runtime][backend][contract]") {
    if (!jit_available()) return;
    const Triples in = specials_and_randoms();
    for (Op op : {Op::ffma, Op::ffms, Op::ffnma})
        for (bool avx2 : isas())
            for (Precision precision : {Precision::Fast, Precision::Precise}) {
                const std::vector<uint32_t> r = run_both(op, precision, avx2, in);
                if (precision != Precision::Fast) continue;
                // Fast passes a NaN operand on quieted, a's before b's before c's
                // (ffms negates c, ffnma a, first), as an FMA instruction with a first.
                for (size_t i = 0; i < r.size(); ++i) {
                    if ((i / rt::kLanes) % 4 == 3) continue;
                    const uint32_t sign = 0x80000000u;
                    const uint32_t a = in.a[i] ^ (op == Op::ffnma ? sign : 0), c = in.c[i] ^ (op == Op::ffms ? sign : 0);
                    for (uint32_t w : {a, in.b[i], c})
                        if (std::isnan(as_float(w))) {
                            INFO(std::hex << in.a[i] << " " << in.b[i] << " " << in.c[i] << " " << r[i]);
                            CHECK(r[i] == (w | 0x00400000u));
                            break;
                        }
                }
            }
}
