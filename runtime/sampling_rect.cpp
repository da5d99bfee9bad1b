// Rectangle textures (ARB_texture_rectangle), one lane at a time: the rules
// of GL 2.1 §3.8 with the extension's changes. Coordinates are unnormalized:
// u = s and v = t, not s * width; there is one level; the wraps are the
// clamping ones only (GL refuses REPEAT and MIRRORED_REPEAT, so the texture
// is incomplete with them and never reaches here):
//
//   CLAMP            NEAREST: floor(clamp(u, 0, w)), at most w - 1
//                    LINEAR:  clamp(u, 0, w) - 1/2, the border blends in
//   CLAMP_TO_EDGE    NEAREST: floor(u) clamped to [0, w - 1]
//                    LINEAR:  clamp(u, 1/2, w - 1/2) - 1/2
//   CLAMP_TO_BORDER  NEAREST: floor(u), outside [0, w) the border
//                    LINEAR:  clamp(u, -1/2, w + 1/2) - 1/2
//
// The magnification/minification switch (§3.8.9, c = 0 as no mipmap filter
// is allowed) reads lambda = log2(rho) with rho from the derivatives of
// (u, v) themselves. Everything else (the depth comparison, the border
// colour, DEPTH_TEXTURE_MODE, the filters' blend) is sampling_rules.h's.
// The batched sampler (sampling_batch.cpp) takes rectangles too, with the
// same index functions (sampling_rules.h); this is the lane-by-lane oracle
// and sample_texture()'s path.
#include "runtime/sampling.h"

#include "runtime/sampling_rules.h"

namespace glslrun::rt {

using namespace sampling;

namespace {

int rect_nearest_index(TextureWrap wrap, float u, int n) {
    return with_wrap(wrap, [&]<TextureWrap kWrap>() { return sampling::rect_nearest_index<kWrap>(u, n); });
}

LinearAxis rect_linear_axis(TextureWrap wrap, float u, int n) {
    return with_wrap(wrap, [&]<TextureWrap kWrap>() { return sampling::rect_linear_axis<kWrap>(u, n); });
}

Texel rect_level(const Lookup& lk, const TextureImage& image, bool linear) {
    const SamplerState& st = *lk.st;
    if (!linear)
        return fetch(lk, image, rect_nearest_index(st.wrap_s, lk.str.x, image.width),
                     rect_nearest_index(st.wrap_t, lk.str.y, image.height), 0);
    const LinearAxis x = rect_linear_axis(st.wrap_s, lk.str.x, image.width);
    const LinearAxis y = rect_linear_axis(st.wrap_t, lk.str.y, image.height);
    const Texel row0 = mix(fetch(lk, image, x.i0, y.i0, 0), fetch(lk, image, x.i1, y.i0, 0), x.a);
    const Texel row1 = mix(fetch(lk, image, x.i0, y.i1, 0), fetch(lk, image, x.i1, y.i1, 0), x.a);
    return mix(row0, row1, y.a);
}

}  // namespace

void sample_rect_lane(const Texture& texture, const LaneLookup& lookup, float* rgba) {
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[0];
    float lambda = lookup.lod;  // the explicit LOD (a vertex shader's 0)
    if (lookup.implicit && lod_matters(st)) {
        // rho from (du, dv) directly: the size factors of §3.8.8 are 1.
        const float rho_lod = lod_rule(lookup.ddx, lookup.ddy, glm::vec3(1.0f), 2);
        lambda = lookup.bias ? rho_lod + lookup.lod : rho_lod;
    } else if (lookup.implicit) {
        lambda = 0.0f;  // one filter either side: lambda is not read
    }
    const bool magnify = clamp_lambda(lambda + st.lod_bias, st) <= 0.0f;
    const Lookup lk = make_lookup(texture, lookup.coord, lookup.ref);
    const glm::vec4 v = vec_of(rect_level(lk, image, linear_within_level(magnify ? st.mag_filter : st.min_filter)));
    const glm::vec4 out = texture.depth() ? expand_depth(st.depth_mode, v.r) : v;
    for (int c = 0; c < 4; ++c) rgba[c] = canonical_nan(out[c]);
}

}  // namespace glslrun::rt
