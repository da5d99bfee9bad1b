// Each lane's cube face and (s, t) on it, eight lanes at a time: the
// batched samplers' cube step under AVX2 (Precise's, sampling_batch_cube.h,
// and Fast's GPU-rule one, sampling_gpu_batch.cpp), the same bits as
// cube_face() and cube_coord() lane by lane.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// cube_coords() of every lane, eight at a time: cube_face()'s comparisons
// as masks and its choices as blends (no branch or table per lane), then
// cube_coord()'s products and quotient in its order, s_sign * sc / ma (the
// sign a multiplication, as there, so that a NaN keeps its bits). GCC left
// cube_coords()'s loop scalar (perf: a third of cube_refract's lookups, on
// its divisions and selects).
__attribute__((target("avx2"))) inline void cube_coords8(const BatchLookup& lk, int* face_out, float* s_out,
                                                         float* t_out) {
    const __m256 zero = _mm256_setzero_ps(), sign = _mm256_set1_ps(-0.0f);
    const __m256 one = _mm256_set1_ps(1.0f), minus = _mm256_set1_ps(-1.0f), half = _mm256_set1_ps(0.5f);
    for (int g = 0; g < kLanes; g += 8) {
        const __m256 x = _mm256_loadu_ps(lk.coord[0] + g), y = _mm256_loadu_ps(lk.coord[1] + g);
        const __m256 z = _mm256_loadu_ps(lk.coord[2] + g);
        const __m256 ax = _mm256_andnot_ps(sign, x), ay = _mm256_andnot_ps(sign, y), az = _mm256_andnot_ps(sign, z);
        const __m256 x_major = _mm256_and_ps(_mm256_cmp_ps(ax, ay, _CMP_GE_OQ), _mm256_cmp_ps(ax, az, _CMP_GE_OQ));
        const __m256 y_major = _mm256_andnot_ps(x_major, _mm256_cmp_ps(ay, az, _CMP_GE_OQ));
        const __m256 x_pos = _mm256_cmp_ps(x, zero, _CMP_GE_OQ), y_pos = _mm256_cmp_ps(y, zero, _CMP_GE_OQ);
        const __m256 z_pos = _mm256_cmp_ps(z, zero, _CMP_GE_OQ);
        // +X 0, -X 1, +Y 2, -Y 3, +Z 4, -Z 5: the odd face plus the mask (-1 where positive).
        const __m256i fx = _mm256_add_epi32(_mm256_set1_epi32(1), _mm256_castps_si256(x_pos));
        const __m256i fy = _mm256_add_epi32(_mm256_set1_epi32(3), _mm256_castps_si256(y_pos));
        const __m256i fz = _mm256_add_epi32(_mm256_set1_epi32(5), _mm256_castps_si256(z_pos));
        const __m256 fyz = _mm256_blendv_ps(_mm256_castsi256_ps(fz), _mm256_castsi256_ps(fy), y_major);
        const __m256i face = _mm256_castps_si256(_mm256_blendv_ps(fyz, _mm256_castsi256_ps(fx), x_major));
        const __m256 major = _mm256_blendv_ps(_mm256_blendv_ps(z, y, y_major), x, x_major);
        const __m256 sc = _mm256_blendv_ps(x, z, x_major), tc = _mm256_blendv_ps(y, z, y_major);
        // s_sign -1 on +X and -Z, t_sign +1 on +Y only (kCubeFaces).
        const __m256 all = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        const __m256 z_major = _mm256_andnot_ps(_mm256_or_ps(x_major, y_major), all);
        const __m256 z_minus = _mm256_andnot_ps(z_pos, z_major);
        const __m256 s_sign = _mm256_blendv_ps(one, minus, _mm256_or_ps(_mm256_and_ps(x_major, x_pos), z_minus));
        const __m256 t_sign = _mm256_blendv_ps(minus, one, _mm256_and_ps(y_major, y_pos));
        const __m256 ma = _mm256_andnot_ps(sign, major);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(face_out + g), face);
        const __m256 s = _mm256_add_ps(_mm256_div_ps(_mm256_mul_ps(s_sign, sc), ma), one);
        const __m256 t = _mm256_add_ps(_mm256_div_ps(_mm256_mul_ps(t_sign, tc), ma), one);
        _mm256_storeu_ps(s_out + g, _mm256_mul_ps(half, s));
        _mm256_storeu_ps(t_out + g, _mm256_mul_ps(half, t));
    }
}

}  // namespace glslrun::rt
#endif
