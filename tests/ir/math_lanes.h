// Lane loops over the built-ins compiled the way the interpreter's kernels
// are (runtime/interp_kernels.h): 16 lanes, the function inlined, in a
// baseline x86-64 version and in an AVX2 one (`flatten`), so tests can check
// that both give the same bits and time them.
#pragma once
#include <cstddef>

namespace glslrun::test::mathlanes {

inline constexpr int kLanes = 16;

template <class F>
inline void unary_lanes(const float* __restrict in, float* __restrict out, size_t n, F f) {
    for (size_t base = 0; base + kLanes <= n; base += kLanes) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[base + i] = f(in[base + i]);
    }
}

template <class F>
inline void binary_lanes(const float* __restrict a, const float* __restrict b, float* __restrict out, size_t n, F f) {
    for (size_t base = 0; base + kLanes <= n; base += kLanes) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[base + i] = f(a[base + i], b[base + i]);
    }
}

// Precise pow as the interpreter's fpow kernel runs it (math::pow_batch).
template <class Batch>
inline void batch_lanes(const float* a, const float* b, float* out, size_t n, Batch batch) {
    for (size_t base = 0; base + kLanes <= n; base += kLanes) batch(a + base, b + base, out + base);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_TEST_AVX2_LANES 1
template <class F>
__attribute__((target("avx2"), flatten)) void unary_lanes_avx2(const float* __restrict in, float* __restrict out,
                                                               size_t n, F f) {
    unary_lanes(in, out, n, f);
}
template <class F>
__attribute__((target("avx2"), flatten)) void binary_lanes_avx2(const float* __restrict a, const float* __restrict b,
                                                                float* __restrict out, size_t n, F f) {
    binary_lanes(a, b, out, n, f);
}
template <class Batch>
__attribute__((target("avx2"), flatten)) void batch_lanes_avx2(const float* a, const float* b, float* out, size_t n,
                                                               Batch batch) {
    batch_lanes(a, b, out, n, batch);
}
inline bool has_avx2() { return __builtin_cpu_supports("avx2"); }
#endif

}  // namespace glslrun::test::mathlanes
