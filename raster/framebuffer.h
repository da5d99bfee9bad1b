// Colour and depth writes, shared by the fragment stage and the tests.
// Inline: the fragment stage calls them per lane.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "glslrun/glslrun.h"
#include "runtime/half_float.h"

namespace glslrun::raster {

// RGBA8 storage of one channel: clamped to [0,1] and rounded to the nearest
// n/255, ties to even (NaN -> 0); n is the stored byte. T is float, or a
// vector of floats (raster/quad_lanes.h).
template <class T>
inline T unorm8_steps(T v) {
    // Branch-free, so that loops over a batch vectorize. Adding 2^23 rounds
    // to an integer, ties to even: nearbyint() without a library call.
    constexpr float kRound = 8388608.0f;
    const T zero{};
    T c = v > 0.0f ? v : zero;  // also NaN
    c = c < 1.0f ? c : zero + 1.0f;
    return (c * 255.0f + kRound) - kRound;
}
inline uint8_t to_unorm8(float v) { return uint8_t(unorm8_steps(v)); }

// ColorRounding::Gpu's byte of one channel, as an integer of I's lanes (I is
// int32_t, or a vector of them matching T): v clamped to [0, 1] (NaN -> 0),
// t = floor(v * 4096) (exact: v * 4096 is, and truncation is floor for v >= 0),
// then ceil(t * 255 / 4096 - 1/2) = ceil((510 t - 4096) / 8192), which for
// 510 t - 4096 > -8192 is (510 t + 4095) >> 13.
template <class I, class T>
inline I gpu_unorm8(T v) {
    const T zero{};
    T c = v > 0.0f ? v : zero;
    c = c < 1.0f ? c : zero + 1.0f;
    I t;
    if constexpr (std::is_same_v<T, float>) t = I(c * 4096.0f);
    else t = __builtin_convertvector(c * 4096.0f, I);
    return (t * 510 + 4095) >> 13;
}
// The stored byte of one channel under `rounding`.
inline uint8_t to_unorm8(float v, ColorRounding rounding) {
    return rounding == ColorRounding::Gpu ? uint8_t(gpu_unorm8<int32_t>(v)) : to_unorm8(v);
}

// A colour as a float colour buffer stores it: halves where fb.half_float,
// truncated as llvmpipe stores them (runtime/half_float.h).
inline glm::vec4 stored_float(const Framebuffer& fb, glm::vec4 c) {
    if (!fb.half_float) return c;
    return {rt::truncate_to_half(c.r), rt::truncate_to_half(c.g), rt::truncate_to_half(c.b),
            rt::truncate_to_half(c.a)};
}

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c);

// A clear's values as the framebuffer stores them: the colour in the
// framebuffer's format (RGBA8 bytes or floats) repeated over 16 bytes (four
// RGBA8 pixels or one float pixel), the depth clamped to [0, 1] (NaN -> 0).
struct StoredClear {
    bool color = false, depth = false, stencil = false;
    std::array<uint8_t, 16> color_pattern{};
    float d = 1.0f;
    uint8_t s = 0;
};
StoredClear stored_clear(const Framebuffer& fb, const ClearValues& clear);
// Whether the framebuffer's storage matches its size (draw() refuses it otherwise).
bool storage_matches(const Framebuffer& fb);
// Clears the pixels [x0, x1) x [y0, y1), which must lie in the framebuffer.
void clear_rect(Framebuffer& fb, const StoredClear& clear, int x0, int y0, int x1, int y1);

// std::clamp(v, 0, 1), NaN and -0 kept, without branches (they mispredicted
// per fragment: perf). maxss/minss return their second operand on NaN and
// on ties, which is what std::clamp returns.
inline float clamp01(float v) {
#if defined(__SSE2__)
    return _mm_cvtss_f32(_mm_min_ss(_mm_set_ss(1.0f), _mm_max_ss(_mm_set_ss(0.0f), _mm_set_ss(v))));
#else
    return std::clamp(v, 0.0f, 1.0f);
#endif
}

// Whether `incoming` passes against `stored`: bool for floats, all-ones
// lanes for vectors of them (raster/quad_lanes.h).
template <class T>
inline auto depth_passes(GLState::DepthFunc func, T incoming, T stored) {
    using Passes = decltype(incoming < stored);
    using F = GLState::DepthFunc;
    switch (func) {
    case F::Never: return Passes{};
    case F::Less: return incoming < stored;
    case F::Equal: return incoming == stored;
    case F::Lequal: return incoming <= stored;
    case F::Greater: return incoming > stored;
    case F::Notequal: return incoming != stored;
    case F::Gequal: return incoming >= stored;
    case F::Always: return Passes{} == Passes{};
    }
    return Passes{};
}

}  // namespace glslrun::raster
