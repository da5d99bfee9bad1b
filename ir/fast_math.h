// Float-only approximations for the Fast mode, in the style of GPUs and of
// llvmpipe (Mesa gallivm, lp_bld_arit.c): reciprocal and inverse square root
// estimates refined by Newton steps, polynomial exp2/log2 on the float's
// exponent and mantissa, pow as exp2(y * log2 x), and sin/cos with a short
// float range reduction.
//
// Everything is float arithmetic (+ - * / and bit manipulation, no FMA, no
// libm, no rcpps/rsqrtps), branch-free, so GCC vectorizes the interpreter's
// lane loops 8 wide under AVX2 and every x86-64 machine computes the same
// bits. rcpps and rsqrtps were rejected because their estimates differ
// between Intel and AMD: the bit-trick estimates below are exact integer
// arithmetic.
//
// Measured error bounds (tests/ir/fast_math_test.cpp asserts them; the
// measured values are in docs/precision.md, "Built-in functions"):
//   rcp              relative 2^-22 (about 2 ULP)
//   rsqrt            relative 2^-23 (two IEEE roundings)
//   exp2             relative 2^-21.5
//   log2, log        relative 2^-21.5, absolute where |result| < 1
//   exp              relative 2^-21 (1 + |x|): x log2(e) is rounded to float
//   pow              relative 2^-21 (1 + |y log2 x|)
//   sin, cos         absolute 2^-23 for |x| <= 2^12, 2^-19.5 for
//                    |x| <= 2^16, growing with |x| beyond (the reduction
//                    is exact while |x| < 2^13 pi/2)
// Special cases follow IEEE like the Precise functions, except pow, which
// follows llvmpipe (docs/extremes.md): pow(0, y) = 0 for every y (so
// pow(0, 0) = 0), pow(x < 0, y) = NaN, pow(NaN, y) = 0.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glslrun::math::fast {

namespace detail {

inline constexpr float kInf = std::numeric_limits<float>::infinity();
inline constexpr float kRoundMagic = 0x1.8p23f;  // x + this - this rounds x to an integer (|x| < 2^22)

// Written as a template recursion, not a loop: the interpreter's lane loops
// vectorize only when no inner loop is left in them.
template <size_t I = 0, size_t N>
inline float poly(float x, const float (&c)[N]) {
    if constexpr (I + 1 == N) return c[I];
    else return poly<I + 1>(x, c) * x + c[I];
}

// Coefficients from tools/mathfit/fit.py, rounded to float.
inline constexpr float kExp2Poly[] = {1.0000000754548972f, 0.6931471880262288f, 0.2402210748530834f,
                                      0.05550357114219078f, 0.009676031918322054f, 0.0013390863364671234f};
inline constexpr float kLog2Poly[] = {2.8853900798033365f, 0.96179883880211f, 0.5767151860190234f,
                                      0.43171769745887384f};
inline constexpr float kSinPoly[] = {0.9999999969152438f, -0.16666650664434116f, 0.008332035269120316f,
                                     -0.00019503837293885775f};
inline constexpr float kCosPoly[] = {0.999999999952442f, -0.49999999614550283f, 0.041666616662651895f,
                                     -0.0013886617095704495f, 2.4379747535470243e-05f};

// 2^k for an integer k in [-126, 127], built on the exponent field.
inline float pow2i(int32_t k) { return std::bit_cast<float>(uint32_t(k + 127) << 23); }

}  // namespace detail

// 1/x: the integer estimate 0x7EF311C3 - bits(x) (within 12.5%) and three
// Newton steps y' = y (2 - x y). The estimate of |x| >= 2^125 would be a
// denormal, so such x are scaled by 2^-4 first. 0, Inf and NaN are selected
// explicitly: the iteration would give Inf - Inf there.
inline float rcp(float x) {
    using namespace detail;
    const float ax = std::fabs(x);
    const bool huge = ax >= 0x1p125f;
    const float xs = huge ? x * 0x1p-4f : x;
    float y = std::bit_cast<float>(0x7EF311C3u - std::bit_cast<uint32_t>(xs));
    y = y * (2.0f - xs * y);
    y = y * (2.0f - xs * y);
    y = y * (2.0f - xs * y);
    y = huge ? y * 0x1p-4f : y;  // a denormal result, flushed under FTZ as any other
    y = ax == 0.0f ? std::copysign(kInf, x) : y;
    y = ax == kInf ? std::copysign(0.0f, x) : y;
    return std::isnan(x) ? x + x : y;
}

// 1/sqrt(x) as the CPU's square root and divider compute it: both are IEEE
// (correctly rounded, the same bits on every x86-64 machine), so the result
// is within 2^-23 relative, and vsqrtps + vdivps cost less than the integer
// estimate 0x5F375A86 - bits(x)/2 with three Newton steps and the selects
// for 0, Inf, x < 0 and NaN that it needed (measured: the spot frame under
// the JIT, docs/performance.md "Fast against Precise, rsqrt"). The special
// cases come out of the IEEE operations: 1/sqrt(+-0) = +-Inf, 1/sqrt(Inf) =
// 0, x < 0 gives the default NaN, a NaN stays itself, quieted. GPUs
// estimate (NVIDIA's MUFU.RSQ is within about 2^-22.9); an estimate whose
// bits are fixed costs more here than the exact answer.
inline float rsqrt(float x) { return 1.0f / std::sqrt(x); }

// 2^x = 2^k * 2^r, |r| <= 1/2, with 2^r a degree-5 polynomial. The scale is
// applied in two halves so that 2^k below 2^-126 or above 2^127 needs no
// denormal or infinite factor.
inline float exp2(float x) {
    using namespace detail;
    const float xc = x < -151.0f ? -151.0f : (x > 129.0f ? 129.0f : x);  // NaN passes
    const float k = (xc + kRoundMagic) - kRoundMagic;
    const int32_t ki = int32_t(std::bit_cast<uint32_t>(xc + kRoundMagic) << 10) >> 10;  // k's two's complement
    const int32_t half = ki >> 1;
    return poly(xc - k, kExp2Poly) * pow2i(half) * pow2i(ki - half);
}

// log2(x) = e + s P(s^2), s = (m - 1)/(m + 1), m in [sqrt(2)/2, sqrt(2)):
// the same form as llvmpipe's lp_build_log2_approx, with a degree-3 P.
inline float log2(float x) {
    using namespace detail;
    const uint32_t bits = std::bit_cast<uint32_t>(x);
    const int32_t e = int32_t(bits - 0x3F3504F3u) >> 23;
    const float m = std::bit_cast<float>(bits - (uint32_t(e) << 23));
    const float s = (m - 1.0f) / (m + 1.0f);
    const float r = float(e) + s * poly(s * s, kLog2Poly);
    const float special = x == 0.0f ? -kInf : (x < 0.0f ? std::bit_cast<float>(0xFFC00000u) : x + x);
    return x > 0.0f && x < kInf ? r : special;  // x == 0 includes flushed denormals (DAZ)
}

inline float exp(float x) { return exp2(x * 1.44269504f); }
inline float log(float x) { return log2(x) * 0.693147181f; }

// llvmpipe's pow: exp2(y * log2 x), 0 where x = 0 (lp_build_pow) and where x
// is NaN (measured on llvmpipe, docs/extremes.md).
// y * log2 x with both NaN (y NaN, x < 0) is y's NaN, quieted, chosen here:
// x86 returns the first operand's NaN, and GCC and clang order the operands
// differently (runtime/jit/math.cpp's fast_pow picks the same).
inline float pow(float x, float y) {
    const float quiet_y = std::bit_cast<float>(std::bit_cast<uint32_t>(y) | 0x00400000u);
    const float r = exp2(std::isnan(y) ? quiet_y : y * log2(x));
    return x == 0.0f || std::isnan(x) ? 0.0f : r;
}

namespace detail {

// x = k pi/2 + r in float: pi/2 in three parts (8, 11 and 24 bits, as
// cephes's DP1..DP3); k * part is exact for the first two while |k| < 2^13,
// so the reduction is exact for |x| < 2^13 pi/2 and degrades beyond.
struct Reduced {
    float r;
    uint32_t quadrant;
};
inline Reduced reduce_pi2(float x) {
    const float q = x * 0.636619772f;
    const float qc = q < -0x1p22f ? -0x1p22f : (q > 0x1p22f ? 0x1p22f : q);
    const float shifted = qc + kRoundMagic;
    const float k = shifted - kRoundMagic;
    float r = x - k * 1.5703125f;
    r = r - k * 4.837512969970703125e-4f;
    r = r - k * 7.54978995489188216e-8f;
    return {r, std::bit_cast<uint32_t>(shifted) & 3u};
}

}  // namespace detail

inline float sin(float x) {
    using namespace detail;
    const Reduced red = reduce_pi2(x);
    const float z = red.r * red.r;
    const float v = (red.quadrant & 1u) ? poly(z, kCosPoly) : red.r * poly(z, kSinPoly);
    const float r = (red.quadrant & 2u) ? -v : v;
    return std::fabs(x) < kInf ? r : x - x;
}

inline float cos(float x) {
    using namespace detail;
    const Reduced red = reduce_pi2(x);
    const float z = red.r * red.r;
    const float v = (red.quadrant & 1u) ? red.r * poly(z, kSinPoly) : poly(z, kCosPoly);
    const float r = ((red.quadrant + 1u) & 2u) ? -v : v;
    return std::fabs(x) < kInf ? r : x - x;
}

}  // namespace glslrun::math::fast
