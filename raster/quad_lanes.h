// The four lanes of one 2x2 quad as one SIMD register (GCC/Clang vector
// extensions: SSE on baseline x86-64, whatever the target has elsewhere), for
// the fragment stage's per-quad plumbing: plane equations, the depth test,
// RGBA8 conversion. Each operation is the scalar code's, in its order (the
// build never contracts to FMA), so results are bit-identical to it.
#pragma once
#include <cstdint>
#include <cstring>

#include "glslrun/glslrun.h"

namespace glslrun::raster {

using QuadF = float __attribute__((vector_size(16)));
using QuadI = int32_t __attribute__((vector_size(16)));

// Lane i of a quad is pixel (x + kQuadDx[i], y + kQuadDy[i]) (raster/triangle.h).
inline constexpr QuadF kQuadDxF{0, 1, 0, 1}, kQuadDyF{0, 0, 1, 1};
inline constexpr QuadI kQuadDxI{0, 1, 0, 1}, kQuadDyI{0, 0, 1, 1};
inline constexpr QuadI kQuadBits{1, 2, 4, 8};

inline QuadF load_quad(const float* p) {
    QuadF v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store_quad(float* p, QuadF v) { std::memcpy(p, &v, sizeof v); }
inline void store_quad(int* p, QuadI v) { std::memcpy(p, &v, sizeof v); }

// The lanes of coverage bits `mask` as all-ones lanes, and back.
inline QuadI lanes_of(unsigned mask) { return ((QuadI{} + int32_t(mask)) & kQuadBits) != 0; }
inline unsigned mask_of(QuadI lanes) {
    QuadI bits = lanes & kQuadBits;
    return unsigned(bits[0] | bits[1] | bits[2] | bits[3]);
}

// raster/framebuffer.h's clamp01 per lane: NaN and -0 kept.
inline QuadF clamp01(QuadF v) {
    QuadF low = v < 0.0f ? QuadF{} : v;
    return low > 1.0f ? QuadF{} + 1.0f : low;
}

// depth_passes() per lane: all ones where `incoming` passes.
inline QuadI depth_passes(CompareFunc func, QuadF incoming, QuadF stored) {
    switch (func) {
    case CompareFunc::Never: return QuadI{};
    case CompareFunc::Less: return incoming < stored;
    case CompareFunc::Equal: return incoming == stored;
    case CompareFunc::Lequal: return incoming <= stored;
    case CompareFunc::Greater: return incoming > stored;
    case CompareFunc::Notequal: return incoming != stored;
    case CompareFunc::Gequal: return incoming >= stored;
    case CompareFunc::Always: return QuadI{} == 0;
    }
    return QuadI{};
}

// The quad's values of a buffer of floats (depth) with rows `stride` apart:
// (x, y), (x+1, y), (x, y+1), (x+1, y+1) from `at` = (x, y). All four must exist.
inline QuadF gather_quad(const float* at, size_t stride) {
    QuadF v;
    std::memcpy(&v, at, 2 * sizeof(float));
    std::memcpy(reinterpret_cast<float*>(&v) + 2, at + stride, 2 * sizeof(float));
    return v;
}
inline void scatter_quad(float* at, size_t stride, QuadF v) {
    std::memcpy(at, &v, 2 * sizeof(float));
    std::memcpy(at + stride, reinterpret_cast<const float*>(&v) + 2, 2 * sizeof(float));
}

// raster/framebuffer.h's unorm8_steps per lane, as integers 0..255.
inline QuadI unorm8_steps(QuadF v) {
    constexpr float kRound = 8388608.0f;
    QuadF c = v > 0.0f ? v : QuadF{};  // also NaN
    c = c < 1.0f ? c : QuadF{} + 1.0f;
    return __builtin_convertvector((c * 255.0f + kRound) - kRound, QuadI);
}

// Four lanes' RGBA8 pixels as words (R in the lowest byte: memory order on
// little-endian machines, as pack_unorm8).
inline QuadI pack_unorm8(QuadF r, QuadF g, QuadF b, QuadF a) {
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
    return unorm8_steps(r) | unorm8_steps(g) << 8 | unorm8_steps(b) << 16 | unorm8_steps(a) << 24;
}

}  // namespace glslrun::raster
