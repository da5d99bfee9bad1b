// The Fast mode's approximations (ir/fast_math.h): their documented error
// bounds over the float range, their special values (llvmpipe's for pow), and
// that the AVX2 lane loops give the scalar bits for them and for the Precise
// built-ins. Compiled with the interpreter's flags (CMakeLists.txt), so the
// lane loops vectorize as the interpreter's kernels do.
//
// The hidden test "[.precision_table]" prints the table of docs/precision.md
// ("Built-in functions"): ./build/test_ir "[.precision_table]".
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>

#include "ir/fast_math.h"
#include "ir/precise_math.h"
#include "ir/scalar_ops.h"
#include "tests/ir/math_lanes.h"
#include "tests/ir/math_sweep.h"

using namespace glslrun;
using namespace glslrun::test::mathsweep;
using namespace glslrun::test::mathlanes;

namespace {

// Relative error, or absolute where |ref| < `abs_below` (near zeros).
double rel_error(float got, double ref, double abs_below = 0.0) {
    if (std::isnan(ref) || std::isnan(got)) return std::isnan(ref) == std::isnan(got) ? 0.0 : 1e9;
    const double diff = std::fabs(double(got) - ref);
    return std::fabs(ref) < abs_below ? diff : diff / std::fabs(ref);
}

struct MaxError {
    double max = 0.0;
    float at = 0.0f;
    void add(double e, float x) {
        if (e > max) max = e, at = x;
    }
};

// Hides a constant from the compiler, which would fold the call without
// the denormal flushing the test runs under.
float opaque(float x) {
    volatile float v = x;
    return v;
}

bool normal(double v) { return std::fabs(v) >= 0x1p-126 && std::fabs(v) <= double(std::numeric_limits<float>::max()); }

}  // namespace

TEST_CASE("fast approximations stay within their documented bounds", "[ir][math]") {
    ir::FlushDenormals flush;  // as the interpreter runs them
    MaxError rcp, rsqrt, exp2, log2, exp, log, sin_near, sin_far, cos_near;
    every_float(509, [&](float x) {
        const double xd = x;
        if (normal(xd)) {
            // Below 2^-125 the result may round to a denormal (flushed): not counted.
            if (std::fabs(1.0 / xd) >= 0x1p-125) rcp.add(rel_error(math::fast::rcp(x), 1.0 / xd), x);
            if (x > 0.0f) rsqrt.add(rel_error(math::fast::rsqrt(x), 1.0 / std::sqrt(xd)), x);
            if (x > 0.0f) log2.add(rel_error(math::fast::log2(x), std::log2(xd), 1.0), x);
            if (x > 0.0f) log.add(rel_error(math::fast::log(x), std::log(xd), 1.0), x);
        }
        if (normal(std::exp2(xd))) exp2.add(rel_error(math::fast::exp2(x), std::exp2(xd)), x);
        // exp rounds x * log2(e) to float first: an error growing with |x|.
        if (normal(std::exp(xd))) exp.add(rel_error(math::fast::exp(x), std::exp(xd)) / (1.0 + std::fabs(xd)), x);
        if (std::fabs(x) <= 4096.0f) {
            sin_near.add(std::fabs(double(math::fast::sin(x)) - std::sin(xd)), x);
            cos_near.add(std::fabs(double(math::fast::cos(x)) - std::cos(xd)), x);
        } else if (std::fabs(x) <= 65536.0f) {
            sin_far.add(std::fabs(double(math::fast::sin(x)) - std::sin(xd)), x);
        }
    });
    // pow = exp2(y log2 x): log2's absolute error is multiplied by |y|.
    MaxError pow;
    Lcg rng{5};
    for (int i = 0; i < 300000; ++i) {
        const float x = std::bit_cast<float>(rng.next() % 0x7F000000u + 0x00800000u);
        const uint32_t h = rng.next();
        const float y = std::bit_cast<float>((h & 0x807FFFFFu) | ((119u + (h >> 24) % 18u) << 23));
        const double ref = std::pow(double(x), double(y));
        if (normal(ref)) pow.add(rel_error(math::fast::pow(x, y), ref) / (1.0 + std::fabs(double(y) * std::log2(double(x)))), x);
    }
    const std::pair<const char*, std::pair<MaxError*, double>> bounds[] = {
        {"rcp", {&rcp, 0x1p-22}},
        {"rsqrt", {&rsqrt, 0x1p-23}},  // two IEEE roundings
        {"exp2", {&exp2, 3.37e-7}},  // 2^-21.5
        {"log2 (absolute below 1)", {&log2, 3.37e-7}},
        {"log (absolute below 1)", {&log, 3.37e-7}},
        {"exp / (1+|x|)", {&exp, 0x1p-21}},
        {"pow / (1+|y log2 x|)", {&pow, 0x1p-21}},
        {"sin |x|<=2^12 (absolute)", {&sin_near, 0x1p-23}},
        {"cos |x|<=2^12 (absolute)", {&cos_near, 0x1p-23}},
        {"sin |x|<=2^16 (absolute)", {&sin_far, 1.35e-6}},  // 2^-19.5
    };
    for (const auto& [name, b] : bounds) {
        INFO(name << ": max error " << b.first->max << " (bound " << b.second << ") at x = " << b.first->at);
        CHECK(b.first->max > 0.0);  // the sweep ran
        CHECK(b.first->max <= b.second);
    }
}

TEST_CASE("fast approximations' special values", "[ir][math]") {
    ir::FlushDenormals flush;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    using namespace math::fast;
    // IEEE, as the Precise functions.
    CHECK(rcp(0.0f) == kInf);
    CHECK(rcp(-0.0f) == -kInf);
    CHECK(rcp(kInf) == 0.0f);
    CHECK(std::signbit(rcp(-kInf)));
    CHECK(rcp(opaque(0x1p127f)) == 0.0f);  // a denormal, flushed
    CHECK(rcp(opaque(-0x1p124f)) == Approx(-0x1p-124f).epsilon(2.4e-7));
    CHECK(std::isnan(rcp(nan)));
    CHECK(rsqrt(0.0f) == kInf);
    CHECK(rsqrt(kInf) == 0.0f);
    CHECK(std::isnan(rsqrt(-1.0f)));
    CHECK(std::isnan(rsqrt(nan)));
    CHECK(exp2(128.0f) == kInf);
    CHECK(exp2(opaque(-150.0f)) == 0.0f);
    CHECK(exp2(kInf) == kInf);
    CHECK(exp2(-kInf) == 0.0f);
    CHECK(std::isnan(exp2(nan)));
    CHECK(exp2(127.9f) < kInf);  // 2^k split in two factors: no early overflow
    CHECK(exp2(-125.5f) > 0.0f);
    CHECK(log2(0.0f) == -kInf);
    CHECK(log2(opaque(0x1p-140f)) == -kInf);  // a denormal reads as 0
    CHECK(log2(kInf) == kInf);
    CHECK(std::isnan(log2(-1.0f)));
    CHECK(std::isnan(log2(nan)));
    CHECK(std::isnan(sin(kInf)));
    CHECK(std::isnan(cos(-kInf)));
    CHECK(std::isnan(sin(nan)));
    CHECK(exp2(3.0f) == Approx(8.0f).epsilon(3e-7));
    CHECK(log2(8.0f) == 3.0f);
    // pow follows llvmpipe (docs/extremes.md).
    CHECK(pow(0.0f, 0.0f) == 0.0f);
    CHECK(pow(0.0f, -1.0f) == 0.0f);
    CHECK(std::isnan(pow(-2.0f, 2.0f)));
    CHECK(pow(nan, 2.0f) == 0.0f);
    CHECK(std::isnan(pow(2.0f, nan)));
    CHECK(pow(kInf, 2.0f) == kInf);
    CHECK(pow(2.0f, -kInf) == 0.0f);
}

#ifdef GLSLRUN_TEST_AVX2_LANES
namespace {

// Random floats of every magnitude, with the special inputs mixed in.
std::vector<float> mixed_inputs(uint64_t seed, size_t n) {
    const std::vector<float> special = special_inputs();
    Lcg rng{seed};
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = i % 4 == 0 ? special[rng.next() % special.size()] : std::bit_cast<float>(rng.next());
    return v;
}

template <class F>
void check_unary_lanes(const char* name, F f) {
    const std::vector<float> in = mixed_inputs(7, 1 << 14);
    std::vector<float> scalar(in.size()), avx2(in.size());
    for (size_t i = 0; i < in.size(); ++i) scalar[i] = f(in[i]);
    unary_lanes_avx2(in.data(), avx2.data(), in.size(), f);
    size_t differ = 0;
    for (size_t i = 0; i < in.size(); ++i) differ += std::bit_cast<uint32_t>(scalar[i]) != std::bit_cast<uint32_t>(avx2[i]);
    INFO(name);
    CHECK(differ == 0);
}

template <class F>
void check_binary_lanes(const char* name, F f) {
    const std::vector<float> a = mixed_inputs(8, 1 << 14), b = mixed_inputs(9, 1 << 14);
    std::vector<float> scalar(a.size()), avx2(a.size());
    for (size_t i = 0; i < a.size(); ++i) scalar[i] = f(a[i], b[i]);
    binary_lanes_avx2(a.data(), b.data(), avx2.data(), a.size(), f);
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) differ += std::bit_cast<uint32_t>(scalar[i]) != std::bit_cast<uint32_t>(avx2[i]);
    INFO(name);
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("AVX2 lane loops give the scalar bits", "[ir][math]") {
    if (!has_avx2()) return;
    ir::FlushDenormals flush;
    check_unary_lanes("fast rcp", [](float x) { return math::fast::rcp(x); });
    check_unary_lanes("fast rsqrt", [](float x) { return math::fast::rsqrt(x); });
    check_unary_lanes("fast exp2", [](float x) { return math::fast::exp2(x); });
    check_unary_lanes("fast log2", [](float x) { return math::fast::log2(x); });
    check_unary_lanes("fast exp", [](float x) { return math::fast::exp(x); });
    check_unary_lanes("fast log", [](float x) { return math::fast::log(x); });
    check_unary_lanes("fast sin", [](float x) { return math::fast::sin(x); });
    check_unary_lanes("fast cos", [](float x) { return math::fast::cos(x); });
    check_binary_lanes("fast pow", [](float x, float y) { return math::fast::pow(x, y); });
    // Without denormal flushing too: the functions themselves must not rely on it.
    _mm_setcsr(_mm_getcsr() & ~0x8040u);
    check_unary_lanes("precise exp", [](float x) { return math::exp(x); });
    check_unary_lanes("precise sin", [](float x) { return math::sin(x); });
    check_unary_lanes("precise asin", [](float x) { return math::asin(x); });
    check_binary_lanes("precise pow", [](float x, float y) { return math::pow(x, y); });
    check_binary_lanes("precise atan2", [](float y, float x) { return math::atan2(y, x); });
}
#endif
