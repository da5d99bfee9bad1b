// filter()'s level decisions (§3.8.8, §3.8.9) for one lane, written
// branch-free so that the batched samplers' lane loops vectorise: whether
// the lane magnifies, the level(s) it reads and the weight of the second.
// The texture's state is taken once (LevelRule); choose_level() is the
// per-lane step. The batched sampler's steps (sampling_batch.cpp) and the
// mipmapped 2D kernels (sampling_mip2d.cpp) both call it, so they decide
// alike; filter() (sampling_rules.h) is the per-lane form they follow.
#pragma once
#include "runtime/sampling_rules.h"

namespace glslrun::rt::sampling {

struct LevelRule {
    int base, q;           // level_base and q of §3.8.8 (base where there are no mipmaps)
    float c;               // mag_threshold()
    int linear_mag, linear_min;
    bool mipmap, nearest_mip;
    explicit LevelRule(const Texture& texture)
        : base(texture.sampler.base_level), c(mag_threshold(texture.sampler)),
          linear_mag(linear_within_level(texture.sampler.mag_filter)),
          linear_min(linear_within_level(texture.sampler.min_filter)),
          mipmap(is_mipmap_filter(texture.sampler.min_filter)),
          nearest_mip(texture.sampler.min_filter == TextureFilter::NearestMipmapNearest ||
                      texture.sampler.min_filter == TextureFilter::LinearMipmapNearest) {
        q = mipmap ? last_mip_level(texture.levels(0)[size_t(base)], texture.sampler) : base;
    }
};

struct LevelChoice {
    int d0, d1;    // d1 < 0: one level only
    float weight;  // of d1
    int linear;    // LINEAR within the level (else NEAREST)
};

// lambda (clamped: finite) to the lane's levels: every candidate computed, then selected.
[[gnu::always_inline]] inline LevelChoice choose_level(const LevelRule& r, float lambda) {
    const bool mag = lambda <= r.c;
    const bool minify = !mag && r.mipmap;
    const bool last = float(r.base) + lambda >= float(r.q);
    const float whole = floor_f(lambda);
    const int linear_level = last ? r.q : r.base + int(whole);
    const int d0 = !minify ? r.base : (r.nearest_mip ? nearest_mip_level(lambda, r.base, r.q) : linear_level);
    const bool two = minify && !r.nearest_mip && !last;
    return {d0, two ? d0 + 1 : -1, two ? lambda - whole : 0.0f, mag ? r.linear_mag : r.linear_min};
}

}  // namespace glslrun::rt::sampling
