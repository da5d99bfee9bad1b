// The random lookups that the batched samplers' tests (sampling_batch_test,
// sampling_gpu_batch_test) compare with the per-lane sampler: coordinates and
// derivatives with their edge cases, close lanes as the rasterizer packs
// them, and the filter, wrap and LOD kinds they sweep.
#pragma once
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <random>

#include "runtime/sampling.h"

namespace glslrun::sampling_inputs {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

constexpr TextureFilter kFilters[] = {TextureFilter::Nearest,           TextureFilter::Linear,
                                      TextureFilter::NearestMipmapNearest, TextureFilter::LinearMipmapNearest,
                                      TextureFilter::NearestMipmapLinear,  TextureFilter::LinearMipmapLinear};
constexpr TextureWrap kWraps[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::Clamp,
                                  TextureWrap::ClampToBorder, TextureWrap::MirroredRepeat};
constexpr ir::TexLod kLods[] = {ir::TexLod::Implicit, ir::TexLod::ImplicitBias, ir::TexLod::Explicit};

// A coordinate: mostly ordinary, sometimes an edge case.
inline float coordinate(std::mt19937& rng) {
    static constexpr float kSpecial[] = {kNaN, kInf, -kInf, 1e30f, -1e30f, 0.0f, -0.0f, 1e-40f, 0.5f, 1.0f,
                                         -1.0f, 0.125f, 0.875f, 2.0f, 16777216.0f, -8388609.0f, 3.0e9f};
    std::uniform_int_distribution<int> pick(0, 9);
    if (pick(rng) == 0) return kSpecial[std::uniform_int_distribution<size_t>(0, std::size(kSpecial) - 1)(rng)];
    return std::uniform_real_distribution<float>(-3.0f, 3.0f)(rng);
}

// A derivative spanning magnification to strong minification, in every
// direction; sometimes 0, NaN or infinite.
inline float derivative(std::mt19937& rng) {
    std::uniform_int_distribution<int> pick(0, 19);
    const int p = pick(rng);
    if (p == 0) return 0.0f;
    if (p == 1) return kNaN;
    if (p == 2) return kInf;
    const float magnitude = std::exp2(std::uniform_real_distribution<float>(-12.0f, 4.0f)(rng));
    return pick(rng) < 10 ? magnitude : -magnitude;
}

// A magnified image's lanes, as the rasterizer packs them: quad q = i / 4
// at pixel (2 (q % 4), 2 (q / 4)) of an 8x4 block, lane i at (i & 1, i >> 1
// & 1) within it, each pixel `scale` texels wide from `origin` (in texels;
// a rectangle's coordinates, else divided by the size). Neighbouring lanes
// then share texels and rows, and groups of eight take the kernels' paired
// row loads (random coordinates seldom do), straddle the image's edges and
// corners, or under magnification all read one texel.
inline void close_lanes(std::mt19937& rng, const Texture& texture, float scale, float (*coord)[rt::kLanes]) {
    const bool rect = texture.target() == TextureTarget::Rect;
    const int size[2] = {texture.levels(0)[0].width, texture.levels(0)[0].height};
    for (int c = 0; c < 2; ++c) {
        // Around the image, past its edges by up to two texels, often on a texel's edge.
        float origin = std::uniform_real_distribution<float>(-2.0f, float(size[c]) + 2.0f)(rng);
        if (std::uniform_int_distribution<int>(0, 3)(rng) == 0) origin = std::floor(origin);
        for (int i = 0; i < rt::kLanes; ++i) {
            const int q = i / 4;
            const int pixel = c == 0 ? 2 * (q % 4) + (i & 1) : 2 * (q / 4) + ((i >> 1) & 1);
            const float u = origin + (float(pixel) + 0.5f) * scale;
            coord[c][i] = rect ? u : u / float(size[c]);
        }
    }
    if (std::uniform_int_distribution<int>(0, 7)(rng) == 0)  // now and then an extreme lane
        coord[std::uniform_int_distribution<int>(0, 1)(rng)][std::uniform_int_distribution<int>(0, rt::kLanes - 1)(rng)] =
            coordinate(rng);
}

}  // namespace glslrun::sampling_inputs
