// Colour and depth writes, shared by the fragment stage and the tests.
// Inline: the fragment stage calls them per lane.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "glslrun/glslrun.h"

namespace glslrun::raster {

// RGBA8 storage of one channel: clamped to [0,1] and rounded to the nearest
// n/255, ties to even (NaN -> 0); n is the stored byte.
inline float unorm8_steps(float v) {
    // Branch-free, so that loops over a batch vectorize. Adding 2^23 rounds
    // to an integer, ties to even: nearbyint() without a library call.
    constexpr float kRound = 8388608.0f;
    float c = v > 0.0f ? v : 0.0f;  // also NaN
    c = c < 1.0f ? c : 1.0f;
    return (c * 255.0f + kRound) - kRound;
}
inline uint8_t to_unorm8(float v) { return uint8_t(unorm8_steps(v)); }
// The value that RGBA8 storage reads back: n / 255.
inline float quantize_unorm8(float v) { return unorm8_steps(v) / 255.0f; }

// One pixel's RGBA8 bytes (R, G, B, A in memory order) as one word, for
// stores of whole pixels.
inline uint32_t pack_unorm8(const uint8_t rgba[4]) {
    uint32_t word;
    std::memcpy(&word, rgba, 4);
    return word;
}

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c);

// A clear's values as the framebuffer stores them: the colour quantised for
// RGBA8 (`c` holds n/255, `c8` the bytes), the depth clamped to [0, 1] (NaN -> 0).
struct StoredClear {
    bool color = false, depth = false, stencil = false;
    glm::vec4 c{0.0f};
    std::array<uint8_t, 4> c8{};
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

inline bool depth_passes(GLState::DepthFunc func, float incoming, float stored) {
    using F = GLState::DepthFunc;
    switch (func) {
    case F::Never: return false;
    case F::Less: return incoming < stored;
    case F::Equal: return incoming == stored;
    case F::Lequal: return incoming <= stored;
    case F::Greater: return incoming > stored;
    case F::Notequal: return incoming != stored;
    case F::Gequal: return incoming >= stored;
    case F::Always: return true;
    }
    return false;
}

}  // namespace glslrun::raster
