// lod_from_rho() (sampling_rules.h) of eight lanes in AVX2 registers:
// Precise's exact log2 of rho, math::log2()'s double polynomial
// (ir/precise_math.h's log2_core(): the float's exponent and mantissa from
// its bits, s = (m - 1) / (m + 1), s P(s^2) by Estrin's scheme) written
// with intrinsics, operation for operation, four doubles at a time, so the
// bits are the scalar function's (tests/runtime/sampling_batch_test.cpp
// compares every class of float). The mipmapped 2D kernel's level of
// detail: as a lane loop over the inline function, GCC left the log2
// scalar (perf: `lambdas` was 9% of mip_floor's frame).
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "ir/precise_math.h"
#include "runtime/sampling_rules.h"

namespace glslrun::rt::sampling {

#define GLSLRUN_AVX2 __attribute__((target("avx2")))

[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256d log2_term(int k) { return _mm256_set1_pd(math::detail::kLog2Poly[k]); }

// c_k + x c_(k+1), the Estrin tree's leaves.
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256d log2_pair(__m256d x, int k) {
    return _mm256_add_pd(log2_term(k), _mm256_mul_pd(x, log2_term(k + 1)));
}

// log2_core() of four lanes: e the exponents (denormals' already less 23,
// as an integer: the same double), m the mantissas in [sqrt(2)/2, sqrt(2)).
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256d log2_core4(__m128i e, __m128 m) {
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256d md = _mm256_cvtps_pd(m);
    const __m256d s = _mm256_div_pd(_mm256_sub_pd(md, one), _mm256_add_pd(md, one));
    // estrin(s * s, kLog2Poly): ((c0 + x c1) + x^2 (c2 + x c3)) + x^4 ((c4 + x c5) + x^2 c6).
    const __m256d x = _mm256_mul_pd(s, s), x2 = _mm256_mul_pd(x, x), x4 = _mm256_mul_pd(x2, x2);
    const __m256d low = _mm256_add_pd(log2_pair(x, 0), _mm256_mul_pd(x2, log2_pair(x, 2)));
    const __m256d high = _mm256_add_pd(log2_pair(x, 4), _mm256_mul_pd(x2, log2_term(6)));
    const __m256d poly = _mm256_add_pd(low, _mm256_mul_pd(x4, high));
    return _mm256_add_pd(_mm256_cvtepi32_pd(e), _mm256_mul_pd(s, poly));
}

// lod_from_rho() of eight lanes: -kLodLimit where !(rho > 0) (NaN too),
// kLodLimit where rho is +Inf, else min(float(log2_core(rho)), kLodLimit).
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256 lod_from_rho8(__m256 rho) {
    static_assert(sizeof(math::detail::kLog2Poly) / sizeof(double) == 7, "the Estrin tree above is for 7 terms");
    const __m256 denormal = _mm256_cmp_ps(rho, _mm256_set1_ps(0x1p-126f), _CMP_LT_OQ);
    const __m256 xn = _mm256_blendv_ps(rho, _mm256_mul_ps(rho, _mm256_set1_ps(0x1p23f)), denormal);
    const __m256i bits = _mm256_castps_si256(xn);
    const __m256i e = _mm256_srai_epi32(_mm256_sub_epi32(bits, _mm256_set1_epi32(0x3F3504F3)), 23);
    const __m256 m = _mm256_castsi256_ps(_mm256_sub_epi32(bits, _mm256_slli_epi32(e, 23)));
    // double(e) - 23.0 is double(e - 23): both exact.
    const __m256i exponent = _mm256_sub_epi32(e, _mm256_and_si256(_mm256_castps_si256(denormal), _mm256_set1_epi32(23)));
    const __m256d lo = log2_core4(_mm256_castsi256_si128(exponent), _mm256_castps256_ps128(m));
    const __m256d hi = log2_core4(_mm256_extracti128_si256(exponent, 1), _mm256_extractf128_ps(m, 1));
    const __m256 core = _mm256_set_m128(_mm256_cvtpd_ps(hi), _mm256_cvtpd_ps(lo));
    const __m256 limit = _mm256_set1_ps(kLodLimit);
    const __m256 finite = _mm256_cmp_ps(rho, _mm256_set1_ps(math::detail::kInf), _CMP_LT_OQ);
    const __m256 value = _mm256_blendv_ps(limit, _mm256_min_ps(limit, core), finite);  // std::min(core, limit)
    return _mm256_blendv_ps(_mm256_set1_ps(-kLodLimit), value, _mm256_cmp_ps(rho, _mm256_setzero_ps(), _CMP_GT_OQ));
}

#undef GLSLRUN_AVX2

}  // namespace glslrun::rt::sampling
#endif
