// One texture lookup as GL 2.1 §3.8 defines it (see sampling.h), one lane
// at a time; the rules themselves are in sampling_rules.h.
#include "runtime/sampling.h"

#include "runtime/sampling_rules.h"

namespace glslrun::rt {

using namespace sampling;

float implicit_lod(const Texture& texture, const glm::vec3& coord, const glm::vec3& ddx, const glm::vec3& ddy) {
    return lod_of(texture, coord, ddx, ddy);
}

glm::vec4 sample_texture(const Texture& texture, const glm::vec3& coord, float ref, float lod) {
    if (!texture.complete()) return {0.0f, 0.0f, 0.0f, 1.0f};
    if (texture.target() == TextureTarget::Rect) {
        LaneLookup lookup;
        lookup.coord = coord;
        lookup.ref = ref;
        lookup.lod = lod;
        lookup.implicit = false;
        glm::vec4 v;
        sample_rect_lane(texture, lookup, &v.x);
        return v;
    }
    return sample_complete(texture, coord, ref, lod);
}

void sample_complete_lane(const Texture& texture, const LaneLookup& lookup, float* rgba) {
    float lod = lookup.lod;
    const bool lod_matters = sampling::lod_matters(texture.sampler);
    if (lookup.implicit && lod_matters) lod = lookup.bias ? lod_of(texture, lookup.coord, lookup.ddx, lookup.ddy) + lookup.lod
                                           : lod_of(texture, lookup.coord, lookup.ddx, lookup.ddy);
    const glm::vec4 v = sample_complete(texture, lookup.coord, lookup.ref, lod);
    for (int c = 0; c < 4; ++c) rgba[c] = canonical_nan(v[c]);
}

}  // namespace glslrun::rt
