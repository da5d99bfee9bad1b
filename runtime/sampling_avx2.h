// AVX2 helpers shared by the batched sampler's eight-lane blends
// (sampling_batch.cpp) and its one-pass kernels (sampling_direct.cpp).
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

namespace glslrun::rt::sampling {

// Four registers, r[j] = (texel of lane j | texel of lane 4 + j), four
// channels each, transposed into channels: ch[c] holds channel c of lanes
// 0..7 (a 4x4 transpose within each 128-bit half).
[[gnu::always_inline]] __attribute__((target("avx2"))) inline void transpose8(const __m256* r, __m256* ch) {
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    ch[0] = _mm256_shuffle_ps(t0, t2, 0x44);
    ch[1] = _mm256_shuffle_ps(t0, t2, 0xee);
    ch[2] = _mm256_shuffle_ps(t1, t3, 0x44);
    ch[3] = _mm256_shuffle_ps(t1, t3, 0xee);
}

}  // namespace glslrun::rt::sampling
#endif
