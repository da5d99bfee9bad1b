// Helpers for the built-in math tests: float ranges to sweep, ULP error
// against a double reference, and the special inputs every function meets.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace glslrun::test::mathsweep {

inline constexpr float kInf = std::numeric_limits<float>::infinity();

// On the bits: under DAZ a denormal compares equal to 0.
inline bool is_denormal(float x) {
    const uint32_t b = std::bit_cast<uint32_t>(x);
    return (b & 0x7F800000u) == 0 && (b & 0x007FFFFFu) != 0;
}

// Error of `got` in units in the last place of the float nearest `ref`
// (ULPs of the denormal spacing below 2^-126). A float overflow of `ref`
// counts as exact when `got` is the matching infinity.
inline double ulp_error(float got, double ref) {
    if (std::isnan(ref)) return std::isnan(got) ? 0.0 : 1e9;
    if (std::fabs(ref) > double(std::numeric_limits<float>::max()))
        return std::isinf(got) && std::signbit(got) == std::signbit(ref) ? 0.0 : 1e9;
    if (std::isnan(got) || std::isinf(got)) return 1e9;
    int e = 0;
    std::frexp(ref, &e);  // |ref| = f 2^e, f in [0.5, 1)
    return std::fabs(double(got) - ref) / std::ldexp(1.0, std::max(e - 24, -149));
}

struct UlpStats {
    double max = 0.0, sum = 0.0;
    long count = 0;
    float worst = 0.0f;
    void add(double ulps, float at) {
        if (ulps > max) max = ulps, worst = at;
        sum += ulps;
        ++count;
    }
    double mean() const { return count ? sum / double(count) : 0.0; }
};

// Every `stride`-th float bit pattern (NaNs skipped), both signs.
template <class F>
void every_float(uint32_t stride, F&& f) {
    for (uint64_t b = 0; b < (uint64_t(1) << 32); b += stride) {
        const float x = std::bit_cast<float>(uint32_t(b));
        if (!std::isnan(x)) f(x);
    }
}

// Floats ordered as integers: -Inf < ... < -0 = +0 < ... < +Inf.
inline int64_t float_order(float x) {
    const uint32_t b = std::bit_cast<uint32_t>(x);
    return (b & 0x80000000u) ? -int64_t(b & 0x7FFFFFFFu) : int64_t(b);
}
inline float order_float(int64_t o) {
    return o < 0 ? std::bit_cast<float>(uint32_t(-o) | 0x80000000u) : std::bit_cast<float>(uint32_t(o));
}

// `count` floats spread evenly (in float order) over [lo, hi].
template <class F>
void floats_in(float lo, float hi, int64_t count, F&& f) {
    const int64_t a = float_order(lo), b = float_order(hi);
    const int64_t step = std::max<int64_t>(1, (b - a) / count);
    for (int64_t o = a; o <= b; o += step) f(order_float(o));
}

// A deterministic stream of 32-bit words (a 64-bit LCG's high half).
struct Lcg {
    uint64_t state;
    uint32_t next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state >> 32);
    }
};

// The inputs where the functions' special cases live.
inline std::vector<float> special_inputs() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> v = {0.0f, 1.0f, 0.5f, 2.0f, 3.0f, 2.5f, 1.0000001f, 0.99999994f, 1e-30f, 1e30f,
                            0x1p-126f, 0x1p-149f, std::numeric_limits<float>::max(), kInf, 88.72283f,
                            88.722839f, 89.0f, 103.97f, 126.0f, 127.99999f, 128.0f, 149.0f, 150.0f,
                            1.5707964f, 3.1415927f, 1e10f, 0x1p29f, 0x1p24f, 0x1p24f + 2.0f, 0x1p23f + 1.0f};
    const size_t positive = v.size();
    for (size_t i = 0; i < positive; ++i) v.push_back(-v[i]);
    v.push_back(nan);
    v.push_back(-nan);
    v.push_back(std::bit_cast<float>(0x7FC12345u));  // a payload
    v.push_back(std::bit_cast<float>(0xFF812345u));  // a signalling NaN with the sign set
    return v;
}

}  // namespace glslrun::test::mathsweep
