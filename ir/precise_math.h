// glslrun's own float built-ins for the Precise mode: exp, exp2, log, log2,
// pow, sin, cos, tan, asin, acos, atan, atan2.
//
// Why not libm: glibc's float functions are accurate, but their bits may
// change with the glibc version, and other libms differ. These functions use
// only IEEE-exact operations (+ - * / sqrt, conversions, bit manipulation), so
// every x86-64 machine computes the same bits, in the baseline and in the
// AVX2 kernels (-ffp-contract=off: no FMA contraction).
//
// How: each float function evaluates in double - range reduction, then a
// Chebyshev-fitted polynomial (tools/mathfit/fit.py) accurate to 2^-45 or
// better - and rounds once to float, so results are within ~0.5 ULP (measured
// bounds: tests/ir/precise_math_test.cpp and docs/precision.md).
//
// Speed: the interpreter inlines these per lane inside a lane loop
// (runtime/interp_kernels.h), so they are branch-free: special cases are
// computed and selected, rounding to an integer is the 1.5 * 2^52
// magic-number addition, and exponents are built with std::bit_cast. GCC
// vectorizes the lane loops (4 doubles per AVX2 register).
//
// Special values (NaN payloads, signs of zeros, infinities, domain errors)
// match glibc's float functions bit for bit: docs/extremes.md pins them.
//
// The double overloads are the Reference mode's: libm's double functions.
#pragma once
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glslrun::math {

namespace detail {

inline constexpr double kRoundMagic = 0x1.8p52;  // x + this - this rounds x to an integer (|x| < 2^51)
inline constexpr double kLn2 = 0.6931471805599453;
inline constexpr double kLog2e = 1.4426950408889634;
inline constexpr double kPi = 3.141592653589793;
inline constexpr double kPi2 = 1.5707963267948966;
inline constexpr double kPi4 = 0.7853981633974483;
inline constexpr double kTanPi8 = 0.41421356237309503;
inline constexpr double kTan3Pi8 = 2.414213562373095;
inline constexpr float kInf = std::numeric_limits<float>::infinity();

// The NaNs glibc returns for domain errors: x86's default NaN (sign set) from
// log, pow, sin, cos, tan; a positive quiet NaN from asin and acos.
inline float invalid_nan() { return std::bit_cast<float>(0xFFC00000u); }
inline float positive_nan() { return std::bit_cast<float>(0x7FC00000u); }

// Polynomial evaluation, coefficients lowest degree first, by Estrin's
// scheme: P(x) = L(x) + x^h H(x), h the largest power of two below the term
// count, each half split again. As many operations as Horner's rule, but a
// dependency chain of about log2(N) multiply-adds instead of N: the
// interpreter runs one batch at a time and waits for its result, so the
// chain's latency, not the operation count, is what a kernel costs (the
// spot shader alone: 5% more invocations per second than with Horner).
// The different roundings are double ones (2^-53 relative), far below the
// fits' errors: no output of the pinned hash changed. Template recursion,
// not a loop: the lane loops vectorize only when no inner loop is left.
struct Powers {
    double x1, x2, x4, x8;
    explicit Powers(double x) : x1(x), x2(x * x), x4(x2 * x2), x8(x4 * x4) {}
    double of(size_t h) const { return h == 1 ? x1 : (h == 2 ? x2 : (h == 4 ? x4 : x8)); }
};
template <size_t I, size_t N, size_t M>
inline double estrin(const Powers& p, const double (&c)[M]) {
    static_assert(N >= 1 && N <= 16 && I + N <= M);
    if constexpr (N == 1) return c[I];
    else {
        constexpr size_t h = std::bit_floor(N - 1);
        return estrin<I, h>(p, c) + p.of(h) * estrin<I + h, N - h>(p, c);
    }
}
template <size_t M>
inline double estrin(double x, const double (&c)[M]) { return estrin<0, M>(Powers(x), c); }

// Coefficients from tools/mathfit/fit.py (max absolute error of the fit).
// 2^r, |r| <= 1/2 (2^-46.0).
inline constexpr double kExp2Poly[] = {
    1.0000000000000135,    0.6931471805599462,    0.24022650695640124,   0.05550410866465154,
    0.009618129193986148,  0.001333355820082724,  0.00015403433712550652, 1.52526729004753e-05,
    1.3259654090085932e-06, 1.0205910984889862e-07};
// log2(m) = s * P(s^2), s = (m-1)/(m+1), |s| <= 3 - 2 sqrt 2 (2^-50.8).
inline constexpr double kLog2Poly[] = {2.885390081777927,   0.9617966939243325,  0.577078017247236,
                                       0.41219840190016577, 0.3206163989221177,  0.26144389073771435,
                                       0.24292051755312075};
// sin(r) = r * P(r^2) and cos(r) = P(r^2), |r| <= pi/4 (2^-47.7, 2^-54.2).
inline constexpr double kSinPoly[] = {0.9999999999999957,    -0.16666666666616636, 0.008333333323870599,
                                      -0.00019841263294474436, 2.7555271077319583e-06, -2.47564999842978e-08};
inline constexpr double kCosPoly[] = {1.0, -0.4999999999999925, 0.04166666666647211, -0.0013888888869963557,
                                      2.4801578533318056e-05, -2.755523305360796e-07, 2.063040538544112e-09};
// atan(u) = u * P(u^2), |u| <= tan(pi/8) (2^-45.1).
inline constexpr double kAtanPoly[] = {0.9999999999999731,  -0.3333333333079971, 0.19999999604387272,
                                       -0.14285690398092427, 0.11110384405903147, -0.09078383481487198,
                                       0.07563640028050404,  -0.058742621945218634, 0.03065866630240884};

// 2^t for any double t (NaN and +-Inf included). Clamping first keeps k and
// the scale factor in range: 2^+-200 already rounds to float Inf / 0.
inline double exp2_core(double t) {
    const double tc = t < -200.0 ? -200.0 : (t > 200.0 ? 200.0 : t);  // NaN passes
    const double shifted = tc + kRoundMagic;
    const double k = shifted - kRoundMagic;
    // The low mantissa bits of `shifted` hold k; (k + 1023) << 52 is 2^k.
    const uint64_t kbits = std::bit_cast<uint64_t>(shifted);
    const double scale = std::bit_cast<double>((kbits + 1023u) << 52);
    return estrin(tc - k, kExp2Poly) * scale;
}

// log2(x) for a positive finite float x (denormals included), in double.
// x = m * 2^e with m in [sqrt(2)/2, sqrt(2)), found on the float's bits.
inline double log2_core(float x) {
    const bool denormal = x < 0x1p-126f;
    const float xn = denormal ? x * 0x1p23f : x;
    const uint32_t bits = std::bit_cast<uint32_t>(xn);
    const int32_t e = int32_t(bits - 0x3F3504F3u) >> 23;  // 0x3F3504F3: sqrt(2)/2
    const double m = std::bit_cast<float>(bits - (uint32_t(e) << 23));
    const double s = (m - 1.0) / (m + 1.0);  // m - 1 and m + 1 are exact
    const double exponent = double(e) - (denormal ? 23.0 : 0.0);
    return exponent + s * estrin(s * s, kLog2Poly);
}

// Results for non-positive, infinite and NaN inputs of log and log2.
inline float log_special(float x) {
    if (x == 0.0f) return -kInf;
    return x < 0.0f ? invalid_nan() : x + x;  // NaN stays itself (quieted); +Inf stays +Inf
}

// atan2(ay, ax) for ay, ax >= 0 (either may be 0 or Inf, not both), in
// [0, pi/2]. One division: the ratio is mapped into |u| <= tan(pi/8).
inline double atan2_core(double ay, double ax) {
    const bool low = ay <= kTanPi8 * ax;
    const bool high = ay > kTan3Pi8 * ax;
    const double num = low ? ay : (high ? -ax : ay - ax);  // ay - ax and ay + ax are exact for floats
    const double den = low ? ax : (high ? ay : ay + ax);
    const double offset = low ? 0.0 : (high ? kPi2 : kPi4);
    const double u = num / den;
    return offset + u * estrin(u * u, kAtanPoly);
}

// Quadrant and remainder of x modulo pi/2: x = k pi/2 + r, |r| <= ~pi/4.
// pi/2 is split into three 24-bit parts and a double (Cody-Waite), so every
// k * part is exact while k < 2^29: exact reduction for |x| < 2^29 pi/2.
struct Reduced {
    double r;
    uint32_t quadrant;  // k mod 4
};
inline Reduced reduce_pi2(float x) {
    const double xd = x;
    const double q = xd * 0.6366197723675814;                  // 2/pi
    const double qc = q < -0x1p50 ? -0x1p50 : (q > 0x1p50 ? 0x1p50 : q);  // keep the magic valid
    const double shifted = qc + kRoundMagic;
    const double k = shifted - kRoundMagic;
    double r = xd - k * 0x1.921fb6p+0;
    r = r - k * -0x1.777a5cp-25;
    r = r - k * -0x1.ee59dap-50;
    r = r - k * 0x1.98a2e03707345p-77;
    // Only beyond the exact range can |r| exceed pi/4 by more than a rounding:
    // the clamp keeps sin and cos within [-1, 1] and tan finite there.
    r = r < -0.786 ? -0.786 : (r > 0.786 ? 0.786 : r);
    return {r, uint32_t(std::bit_cast<uint64_t>(shifted)) & 3u};
}

// a if it is a NaN, else b, quieted. Not a + b: the compiler may swap the
// operands of a commutative addition, and with two NaNs x86 returns the first.
inline float first_nan(float a, float b) { return std::isnan(a) ? a + a : b + b; }

inline bool signalling(float x) { return std::isnan(x) & ((std::bit_cast<uint32_t>(x) & 0x00400000u) == 0); }

// Odd integers decide pow's sign for x < 0. In float and uint32_t only (the
// lane loops do not vectorize when double and float masks meet): below 2^23
// adding 2^23 rounds to an integer whose parity is the last mantissa bit;
// floats in [2^23, 2^24) are integers with their own parity; above, even.
inline bool is_integer(float y) {
    const float ay = std::fabs(y);
    return (ay >= 0x1p23f) | (((ay + 0x1p23f) - 0x1p23f) == ay);  // NaN: false
}
// The sign bit for pow(x, y): x's when y is an odd integer, else 0.
inline uint32_t odd_power_sign(float x, float y) {
    const float ay = std::fabs(y);
    const uint32_t low = std::bit_cast<uint32_t>(ay + 0x1p23f) & 1u;
    const uint32_t odd = ay < 0x1p23f ? low : (ay < 0x1p24f ? std::bit_cast<uint32_t>(ay) & 1u : 0u);
    return (is_integer(y) ? odd << 31 : 0u) & std::bit_cast<uint32_t>(x);
}
inline float flip_sign(float v, uint32_t sign) { return std::bit_cast<float>(std::bit_cast<uint32_t>(v) ^ sign); }

}  // namespace detail

// ---- exponentials and logarithms -------------------------------------------

inline float exp2(float x) { return float(detail::exp2_core(double(x))); }

// x * log2(e) in double: its rounding error (<= 2^-46 absolute below the
// overflow threshold) is far below float precision.
inline float exp(float x) { return float(detail::exp2_core(double(x) * detail::kLog2e)); }

inline float log2(float x) {
    const float core = float(detail::log2_core(x));
    return x > 0.0f && x < detail::kInf ? core : detail::log_special(x);
}

inline float log(float x) {
    const float core = float(detail::log2_core(x) * detail::kLn2);
    return x > 0.0f && x < detail::kInf ? core : detail::log_special(x);
}

// C99 Annex F powf, as glibc implements it: pow(x, +-0) = 1 and pow(1, y) = 1
// even for a quiet NaN (not a signalling one); pow(-1, +-Inf) = 1; x < 0
// takes the sign of odd integer y and is NaN for a finite non-integer y;
// pow(+-0, y < 0) = +-Inf; a NaN x with the sign set loses it for odd y (glibc
// squares x and negates). y * log2|x| in double has a relative error near
// 2^-50, so 2^(y log2|x|) stays within float rounding.
inline float pow(float x, float y) {
    using namespace detail;
    const float ax = std::fabs(x);
    const double l = ax == 0.0f ? -double(kInf) : (ax == kInf ? double(kInf) : log2_core(ax));
    const double magnitude = exp2_core(double(y) * l);
    const uint32_t sign = odd_power_sign(x, y);
    float r = flip_sign(float(magnitude), sign);
    r = (x < 0.0f) & (ax < kInf) & !is_integer(y) & (std::fabs(y) < kInf) ? invalid_nan() : r;
    const float nan = first_nan(x, y);
    r = std::isnan(x) || std::isnan(y) ? flip_sign(nan, sign) : r;
    r = x == -1.0f && std::fabs(y) == kInf ? 1.0f : r;
    r = x == 1.0f ? (signalling(y) ? nan : 1.0f) : r;
    return y == 0.0f ? (signalling(x) ? nan : 1.0f) : r;
}

// pow's common case, x in [+0, Inf) with y finite and nonzero (x^y > 0, or
// 0 or +Inf for x = 0): no sign, NaN or Annex F rule applies, so pow is
// just 2^(y log2 x) there - bit for bit what pow above returns (the tests
// check it). pow_batch evaluates it for every lane and pow only where needed.
inline bool pow_is_common(float x, float y) {
    return (std::bit_cast<uint32_t>(x) < 0x7F800000u) & (std::fabs(y) < detail::kInf) & (y != 0.0f);
}
inline float pow_common(float x, float y) {
    const double l = x == 0.0f ? -double(detail::kInf) : detail::log2_core(x);
    return float(detail::exp2_core(double(y) * l));
}

// pow over a batch of N lanes, as the interpreter's kernel runs it: the
// branch-free pow pays for its special cases (signs, NaNs, integer y) in
// every lane, a third of its time, although shaders hardly ever need them.
// Pass one computes pow_common in every lane (vectorized) and notes whether
// some lane is not common; only then does pass two recompute those lanes
// with pow. The same bits as pow, lane by lane. `out` may alias x or y.
// (The result goes through a local array: written straight to `out`, which
// may alias, GCC's vector code was 25% slower.)
template <int N>
inline void pow_batch(const float* x, const float* y, float* out) {
    float r[N];
    uint32_t rare = 0;
    for (int i = 0; i < N; ++i) {
        r[i] = pow_common(x[i], y[i]);
        rare |= uint32_t(!pow_is_common(x[i], y[i]));
    }
    if (rare != 0) [[unlikely]]
        for (int i = 0; i < N; ++i)
            if (!pow_is_common(x[i], y[i])) r[i] = pow(x[i], y[i]);
    for (int i = 0; i < N; ++i) out[i] = r[i];
}

// ---- trigonometry ------------------------------------------------------------
// Accurate (within the documented ULP bound) for |x| < 2^29 pi/2 ~ 8.4e8,
// where the reduction is exact. Beyond it results are deterministic but
// meaningless (there a float's spacing is 64 or more, many periods); sin and
// cos stay within [-1, 1] and tan finite. NaN and +-Inf give glibc's NaNs.

namespace detail {
// sin(r + (k + shift) pi/2) for x = k pi/2 + r: shift 0 gives sin x, 1 gives cos x.
inline double sin_quadrant(const Reduced& red, uint32_t shift) {
    const double z = red.r * red.r;
    const double s = red.r * estrin(z, kSinPoly);
    const double c = estrin(z, kCosPoly);
    const uint32_t q = red.quadrant + shift;
    const double v = (q & 1u) ? c : s;
    return (q & 2u) ? -v : v;
}
}  // namespace detail

inline float sin(float x) {
    using namespace detail;
    const float r = x == 0.0f ? x : float(sin_quadrant(reduce_pi2(x), 0));  // keeps -0
    return std::fabs(x) < kInf ? r : x - x;  // Inf - Inf: the default NaN; NaN stays itself
}

inline float cos(float x) {
    using namespace detail;
    const float r = float(sin_quadrant(reduce_pi2(x), 1));
    return std::fabs(x) < kInf ? r : x - x;
}

inline float tan(float x) {
    using namespace detail;
    const Reduced red = reduce_pi2(x);
    const double z = red.r * red.r;
    const double s = red.r * estrin(z, kSinPoly);
    const double c = estrin(z, kCosPoly);
    const bool odd = (red.quadrant & 1u) != 0;
    const float r = x == 0.0f ? x : float((odd ? -c : s) / (odd ? s : c));
    return std::fabs(x) < kInf ? r : x - x;
}

// ---- inverse trigonometry ------------------------------------------------------

inline float atan(float x) {
    const float a = float(detail::atan2_core(std::fabs(double(x)), 1.0));
    return std::copysign(a, x);  // keeps a NaN's payload and sign
}

// C99 Annex F atan2f: signed zeros pick +-0 or +-pi, infinities give
// multiples of pi/4, NaN gives x's NaN, else y's (as glibc).
inline float atan2(float y, float x) {
    using namespace detail;
    const double ay = std::fabs(double(y)), ax = std::fabs(double(x));
    double a = atan2_core(ay, ax);
    a = ay == 0.0 && ax == 0.0 ? 0.0 : a;
    a = ay == double(kInf) && ax == double(kInf) ? kPi4 : a;
    a = std::signbit(x) ? kPi - a : a;
    const float r = std::copysign(float(a), y);
    return std::isnan(x) || std::isnan(y) ? first_nan(x, y) : r;
}

// asin(x) = atan2(x, sqrt(1 - x^2)); (1-x)(1+x) loses nothing in double.
inline float asin(float x) {
    using namespace detail;
    const double ax = std::fabs(double(x));
    const double c = std::sqrt((1.0 - ax) * (1.0 + ax));
    const float r = std::copysign(float(atan2_core(ax, c)), x);
    return std::fabs(x) <= 1.0f ? r : (std::isnan(x) ? x + x : positive_nan());
}

// acos(x) = atan2(sqrt(1 - x^2), x): no cancellation near x = +-1.
inline float acos(float x) {
    using namespace detail;
    const double xd = x, ax = std::fabs(xd);
    const double a = atan2_core(std::sqrt((1.0 - ax) * (1.0 + ax)), ax);
    const float r = float(xd < 0.0 ? kPi - a : a);
    return std::fabs(x) <= 1.0f ? r : (std::isnan(x) ? x + x : positive_nan());
}

// ---- Reference mode: the same names in double, libm's double functions ------
inline double exp(double x) { return std::exp(x); }
inline double exp2(double x) { return std::exp2(x); }
inline double log(double x) { return std::log(x); }
inline double log2(double x) { return std::log2(x); }
inline double pow(double x, double y) { return std::pow(x, y); }
inline double sin(double x) { return std::sin(x); }
inline double cos(double x) { return std::cos(x); }
inline double tan(double x) { return std::tan(x); }
inline double asin(double x) { return std::asin(x); }
inline double acos(double x) { return std::acos(x); }
inline double atan(double x) { return std::atan(x); }
inline double atan2(double y, double x) { return std::atan2(y, x); }

}  // namespace glslrun::math
