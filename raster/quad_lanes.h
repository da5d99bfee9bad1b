// The four lanes of one 2x2 quad as one SIMD register (GCC/Clang vector
// extensions: SSE on baseline x86-64, whatever the target has elsewhere), for
// the fragment stage's per-quad plumbing: plane equations, the depth test,
// RGBA8 conversion. Each operation is the scalar code's, in its order (the
// build never contracts to FMA), so results are bit-identical to it.
#pragma once
#include <cstdint>
#include <cstring>

#include "glslrun/glslrun.h"
#include "raster/framebuffer.h"

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

// Four lanes' RGBA8 pixels as words (R in the lowest byte: memory order on
// little-endian machines).
inline QuadI pack_unorm8(QuadF r, QuadF g, QuadF b, QuadF a, ColorRounding rounding) {
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
    auto steps = [rounding](QuadF v) {
        return rounding == ColorRounding::Gpu ? gpu_unorm8<QuadI>(v) : __builtin_convertvector(unorm8_steps(v), QuadI);
    };
    return steps(r) | steps(g) << 8 | steps(b) << 16 | steps(a) << 24;
}

}  // namespace glslrun::raster
