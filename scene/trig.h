// sin and cos in double for the scene's camera, rotations and meshes, made of
// IEEE + - * only. libm's double sin/cos may differ in the last bit between C
// library versions and between its FMA and non-FMA variants, and such a bit
// can survive the rounding to float of a matrix or a vertex; these give the
// same bits everywhere, so a Precise image does not depend on the machine
// (docs/precision.md, "Guarantees"). Accurate to about 1 ULP of a double for
// |x| < 2^20, far beyond the angles a scene uses.
#pragma once
#include <utility>

namespace glslrun::scene {

namespace trig_detail {

// Horner evaluation of the Taylor series in r^2: with |r| <= pi/4 the first
// omitted terms are below 2^-60 relative.
inline double sin_series(double r) {
    const double z = r * r;
    double p = -1.0 / 1307674368000.0;            // -1/15!
    p = p * z + 1.0 / 6227020800.0;               //  1/13!
    p = p * z - 1.0 / 39916800.0;                 // -1/11!
    p = p * z + 1.0 / 362880.0;                   //  1/9!
    p = p * z - 1.0 / 5040.0;                     // -1/7!
    p = p * z + 1.0 / 120.0;                      //  1/5!
    p = p * z - 1.0 / 6.0;                        // -1/3!
    return r + r * z * p;
}

inline double cos_series(double r) {
    const double z = r * r;
    double p = 1.0 / 20922789888000.0;            //  1/16!
    p = p * z - 1.0 / 87178291200.0;              // -1/14!
    p = p * z + 1.0 / 479001600.0;                //  1/12!
    p = p * z - 1.0 / 3628800.0;                  // -1/10!
    p = p * z + 1.0 / 40320.0;                    //  1/8!
    p = p * z - 1.0 / 720.0;                      // -1/6!
    p = p * z + 1.0 / 24.0;                       //  1/4!
    return 1.0 - 0.5 * z + z * z * p;
}

}  // namespace trig_detail

// {sin x, cos x}.
inline std::pair<double, double> sin_cos(double x) {
    using namespace trig_detail;
    // pi/2 in three parts, the first two with trailing zero bits so that
    // k * part is exact for the k this range needs (Cody and Waite).
    constexpr double kPio2Hi = 1.57079632673412561417e+00;
    constexpr double kPio2Mid = 6.07710050630396597660e-11;
    constexpr double kPio2Lo = 2.02226624879595063154e-21;
    constexpr double kTwoOverPi = 6.36619772367581382433e-01;
    constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52: x + it - it rounds to an integer
    const double k = (x * kTwoOverPi + kRound) - kRound;
    const double r = ((x - k * kPio2Hi) - k * kPio2Mid) - k * kPio2Lo;
    const double s = sin_series(r), c = cos_series(r);
    switch (static_cast<long long>(k) & 3) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
    }
}

}  // namespace glslrun::scene
