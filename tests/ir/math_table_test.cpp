// Prints the built-in function table of docs/precision.md: the Precise
// functions' max and mean ULP error over a dense sweep (every 97th float of
// the domain, 2^24 random pairs for pow and atan2), glibc's float functions'
// on the same inputs, and the time per lane of glibc, of the Precise functions
// (baseline x86-64 and AVX2 lane loops, as the interpreter's kernels) and of
// the Fast ones. Hidden (about a minute): ./build/test_ir "[.precision_table]".
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "ir/fast_math.h"
#include "ir/precise_math.h"
#include "ir/scalar_ops.h"
#include "tests/ir/math_lanes.h"
#include "tests/ir/math_sweep.h"

using namespace glslrun;
using namespace glslrun::test::mathsweep;
using namespace glslrun::test::mathlanes;

namespace {

constexpr size_t kBatch = 4096;

// Nanoseconds per lane of `run` over kBatch lanes, the best of 200 runs.
double ns_per_lane(const std::function<void()>& run) {
    double best = 1e30;
    for (int rep = 0; rep < 200; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        run();
        const auto t1 = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / double(kBatch));
    }
    return best;
}

std::vector<float> uniform(float lo, float hi, uint64_t seed) {
    Lcg rng{seed};
    std::vector<float> v(kBatch);
    for (float& x : v) x = lo + (hi - lo) * float(rng.next() >> 8) * 0x1p-24f;
    return v;
}

struct Row {
    const char* name;
    const char* range;  // of the ULP sweep
    UlpStats precise, glibc;
    double t_glibc = 0, t_base = 0, t_avx2 = 0, t_fast = -1;
};

template <class P, class G, class R>
void sweep(Row& row, float lo, float hi, P precise, G glibc, R reference) {
    every_float(97, [&](float x) {
        if (!(x >= lo && x <= hi) || is_denormal(x)) return;
        const double ref = reference(double(x));
        if (ref != 0.0 && std::fabs(ref) < 0x1p-126) return;  // flushed
        row.precise.add(ulp_error(precise(x), ref), x);
        row.glibc.add(ulp_error(glibc(x), ref), x);
    });
}

template <class P, class G, class F>
void time_unary(Row& row, const std::vector<float>& in, P precise, G glibc, F fast) {
    std::vector<float> out(kBatch);
    row.t_glibc = ns_per_lane([&] {
        for (size_t i = 0; i < kBatch; ++i) out[i] = glibc(in[i]);
    });
    row.t_base = ns_per_lane([&] { unary_lanes(in.data(), out.data(), kBatch, precise); });
#ifdef GLSLRUN_TEST_AVX2_LANES
    if (has_avx2()) {
        row.t_avx2 = ns_per_lane([&] { unary_lanes_avx2(in.data(), out.data(), kBatch, precise); });
        if constexpr (!std::is_same_v<F, std::nullptr_t>)
            row.t_fast = ns_per_lane([&] { unary_lanes_avx2(in.data(), out.data(), kBatch, fast); });
    }
#endif
}

template <class P, class G, class F>
void time_binary(Row& row, const std::vector<float>& a, const std::vector<float>& b, P precise, G glibc, F fast) {
    std::vector<float> out(kBatch);
    row.t_glibc = ns_per_lane([&] {
        for (size_t i = 0; i < kBatch; ++i) out[i] = glibc(a[i], b[i]);
    });
    row.t_base = ns_per_lane([&] { binary_lanes(a.data(), b.data(), out.data(), kBatch, precise); });
#ifdef GLSLRUN_TEST_AVX2_LANES
    if (has_avx2()) {
        row.t_avx2 = ns_per_lane([&] { binary_lanes_avx2(a.data(), b.data(), out.data(), kBatch, precise); });
        if constexpr (!std::is_same_v<F, std::nullptr_t>)
            row.t_fast = ns_per_lane([&] { binary_lanes_avx2(a.data(), b.data(), out.data(), kBatch, fast); });
    }
#endif
}

// Precise pow's lane timings again, as the interpreter's fpow kernel runs it:
// math::pow_batch (common case in every lane, special cases only if needed).
void time_pow_batch(Row& row, const std::vector<float>& a, const std::vector<float>& b) {
    std::vector<float> out(kBatch);
    const auto batch = [](const float* x, const float* y, float* r) { math::pow_batch<kLanes>(x, y, r); };
    row.t_base = ns_per_lane([&] { batch_lanes(a.data(), b.data(), out.data(), kBatch, batch); });
#ifdef GLSLRUN_TEST_AVX2_LANES
    if (has_avx2()) row.t_avx2 = ns_per_lane([&] { batch_lanes_avx2(a.data(), b.data(), out.data(), kBatch, batch); });
#endif
}

// Random pairs (x, y) for pow (x > 0, |y| in [2^-8, 2^9)) or atan2 (any).
template <class P, class G, class R>
void sweep_pairs(Row& row, bool pow, P precise, G glibc, R reference) {
    Lcg rng{11};
    for (int i = 0; i < (1 << 24); ++i) {
        float a = std::bit_cast<float>(rng.next()), b = std::bit_cast<float>(rng.next());
        if (pow) {
            a = std::bit_cast<float>(std::bit_cast<uint32_t>(a) % 0x7F000000u + 0x00800000u);
            const uint32_t h = std::bit_cast<uint32_t>(b);
            b = std::bit_cast<float>((h & 0x807FFFFFu) | ((119u + (h >> 24) % 18u) << 23));
        }
        if (std::isnan(a) || std::isnan(b) || is_denormal(a) || is_denormal(b)) continue;
        const double ref = reference(double(a), double(b));
        if (ref != 0.0 && std::fabs(ref) < 0x1p-126) continue;
        row.precise.add(ulp_error(precise(a, b), ref), a);
        row.glibc.add(ulp_error(glibc(a, b), ref), a);
    }
}

// Max relative error (absolute where |ref| < abs_below) of a Fast function
// over every 97th float of [lo, hi] whose input and result are normal.
template <class F, class R>
double fast_max_error(float lo, float hi, double abs_below, F fast, R reference) {
    double worst = 0.0;
    every_float(97, [&](float x) {
        if (!(x >= lo && x <= hi) || is_denormal(x)) return;
        const double ref = reference(double(x));
        if (!(std::fabs(ref) >= 0x1p-125 && std::fabs(ref) <= 0x1p127)) return;
        const double err = std::fabs(double(fast(x)) - ref);
        worst = std::max(worst, std::fabs(ref) < abs_below ? err : err / std::fabs(ref));
    });
    return worst;
}

}  // namespace

TEST_CASE("table of the Fast approximations", "[.precision_table]") {
    ir::FlushDenormals flush;
    struct FastRow {
        const char* name;
        const char* range;
        const char* kind;
        double error;
    };
    const float huge = std::numeric_limits<float>::max();
    const FastRow rows[] = {
        {"rcp", "all normal x", "relative",
         fast_max_error(-huge, huge, 0.0, [](float x) { return math::fast::rcp(x); }, [](double x) { return 1.0 / x; })},
        {"rsqrt", "x > 0", "relative",
         fast_max_error(0.0f, huge, 0.0, [](float x) { return math::fast::rsqrt(x); },
                        [](double x) { return 1.0 / std::sqrt(x); })},
        {"exp2", "all x", "relative",
         fast_max_error(-huge, huge, 0.0, [](float x) { return math::fast::exp2(x); }, [](double x) { return std::exp2(x); })},
        {"log2", "x > 0", "relative, absolute where |log2 x| < 1",
         fast_max_error(0.0f, huge, 1.0, [](float x) { return math::fast::log2(x); }, [](double x) { return std::log2(x); })},
        {"exp", "|x| <= 1", "relative",
         fast_max_error(-1.0f, 1.0f, 0.0, [](float x) { return math::fast::exp(x); }, [](double x) { return std::exp(x); })},
        {"exp", "all x", "relative",
         fast_max_error(-huge, huge, 0.0, [](float x) { return math::fast::exp(x); }, [](double x) { return std::exp(x); })},
        {"log", "x > 0", "relative, absolute where |log x| < 1",
         fast_max_error(0.0f, huge, 1.0, [](float x) { return math::fast::log(x); }, [](double x) { return std::log(x); })},
        {"sin", "|x| <= 2^12", "absolute",
         fast_max_error(-4096.0f, 4096.0f, 2.0, [](float x) { return math::fast::sin(x); }, [](double x) { return std::sin(x); })},
        {"cos", "|x| <= 2^12", "absolute",
         fast_max_error(-4096.0f, 4096.0f, 2.0, [](float x) { return math::fast::cos(x); }, [](double x) { return std::cos(x); })},
        {"sin", "|x| <= 2^16", "absolute",
         fast_max_error(-65536.0f, 65536.0f, 2.0, [](float x) { return math::fast::sin(x); },
                        [](double x) { return std::sin(x); })},
        {"sin", "|x| <= 2^20", "absolute",
         fast_max_error(-1048576.0f, 1048576.0f, 2.0, [](float x) { return math::fast::sin(x); },
                        [](double x) { return std::sin(x); })},
    };
    std::printf("| function | range | error | max error | log2 |\n|---|---|---|---|---|\n");
    for (const FastRow& r : rows)
        std::printf("| %s | %s | %s | %.3g | %.1f |\n", r.name, r.range, r.kind, r.error, std::log2(r.error));
    CHECK(rows[0].error < 1e-6);
}

TEST_CASE("table of the built-in functions", "[.precision_table]") {
    ir::FlushDenormals flush;
    std::vector<Row> rows;
    auto unary = [&](const char* name, const char* range, float lo, float hi, auto precise, auto glibc, auto ref,
                     auto fast, float tlo, float thi) {
        Row row{name, range, {}, {}};
        sweep(row, lo, hi, precise, glibc, ref);
        time_unary(row, uniform(tlo, thi, 21), precise, glibc, fast);
        rows.push_back(row);
    };
    const float huge = std::numeric_limits<float>::max(), trig = 8.4e8f;
    unary("exp", "all floats", -kInf, kInf, [](float x) { return math::exp(x); }, [](float x) { return std::exp(x); },
          [](double x) { return std::exp(x); }, [](float x) { return math::fast::exp(x); }, -20.0f, 20.0f);
    unary("exp2", "all floats", -kInf, kInf, [](float x) { return math::exp2(x); }, [](float x) { return std::exp2(x); },
          [](double x) { return std::exp2(x); }, [](float x) { return math::fast::exp2(x); }, -20.0f, 20.0f);
    unary("log", "x > 0", 0.0f, kInf, [](float x) { return math::log(x); }, [](float x) { return std::log(x); },
          [](double x) { return std::log(x); }, [](float x) { return math::fast::log(x); }, 1e-3f, 1e3f);
    unary("log2", "x > 0", 0.0f, kInf, [](float x) { return math::log2(x); }, [](float x) { return std::log2(x); },
          [](double x) { return std::log2(x); }, [](float x) { return math::fast::log2(x); }, 1e-3f, 1e3f);
    unary("sin", "|x| < 8.4e8", -trig, trig, [](float x) { return math::sin(x); }, [](float x) { return std::sin(x); },
          [](double x) { return std::sin(x); }, [](float x) { return math::fast::sin(x); }, -100.0f, 100.0f);
    unary("cos", "|x| < 8.4e8", -trig, trig, [](float x) { return math::cos(x); }, [](float x) { return std::cos(x); },
          [](double x) { return std::cos(x); }, [](float x) { return math::fast::cos(x); }, -100.0f, 100.0f);
    unary("tan", "|x| < 8.4e8", -trig, trig, [](float x) { return math::tan(x); }, [](float x) { return std::tan(x); },
          [](double x) { return std::tan(x); }, nullptr, -100.0f, 100.0f);
    unary("asin", "|x| <= 1", -1.0f, 1.0f, [](float x) { return math::asin(x); }, [](float x) { return std::asin(x); },
          [](double x) { return std::asin(x); }, nullptr, -1.0f, 1.0f);
    unary("acos", "|x| <= 1", -1.0f, 1.0f, [](float x) { return math::acos(x); }, [](float x) { return std::acos(x); },
          [](double x) { return std::acos(x); }, nullptr, -1.0f, 1.0f);
    unary("atan", "all floats", -huge, huge, [](float x) { return math::atan(x); }, [](float x) { return std::atan(x); },
          [](double x) { return std::atan(x); }, nullptr, -100.0f, 100.0f);
    Row pow{"pow", "x > 0, 2^-8 <= |y| < 2^9", {}, {}};
    sweep_pairs(pow, true, [](float x, float y) { return math::pow(x, y); }, [](float x, float y) { return std::pow(x, y); },
                [](double x, double y) { return std::pow(x, y); });
    time_binary(pow, uniform(0.0f, 4.0f, 22), uniform(0.0f, 64.0f, 23), [](float x, float y) { return math::pow(x, y); },
                [](float x, float y) { return std::pow(x, y); }, [](float x, float y) { return math::fast::pow(x, y); });
    time_pow_batch(pow, uniform(0.0f, 4.0f, 22), uniform(0.0f, 64.0f, 23));
    rows.push_back(pow);
    Row atan2{"atan2", "all pairs", {}, {}};
    sweep_pairs(atan2, false, [](float y, float x) { return math::atan2(y, x); },
                [](float y, float x) { return std::atan2(y, x); }, [](double y, double x) { return std::atan2(y, x); });
    time_binary(atan2, uniform(-10.0f, 10.0f, 24), uniform(-10.0f, 10.0f, 25),
                [](float y, float x) { return math::atan2(y, x); }, [](float y, float x) { return std::atan2(y, x); },
                nullptr);
    rows.push_back(atan2);

    std::printf("| function | swept range | max ULP | mean ULP | glibc max ULP | glibc mean ULP | ns/lane glibc | "
                "ns/lane precise (baseline) | ns/lane precise (AVX2) | ns/lane fast (AVX2) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row& r : rows) {
        char fast[32] = "-";
        if (r.t_fast >= 0) std::snprintf(fast, sizeof fast, "%.2f", r.t_fast);
        std::printf("| %s | %s | %.6f | %.4f | %.4f | %.4f | %.2f | %.2f | %.2f | %s |\n", r.name, r.range,
                    r.precise.max, r.precise.mean(), r.glibc.max, r.glibc.mean(), r.t_glibc, r.t_base, r.t_avx2, fast);
        CHECK(r.precise.max <= 0.5 + 0x1p-16);
    }
}
