// One texture lookup as GL 2.1 §3.8 defines it (see sampling.h), one lane
// at a time; the rules themselves are in sampling_rules.h.
#include "runtime/sampling.h"

#include <algorithm>
#include <tuple>

#include "runtime/sampling_gpu.h"
#include "runtime/sampling_rules.h"

namespace glslrun::rt {

using namespace sampling;

float implicit_lod(const Texture& texture, const glm::vec3& coord, const glm::vec3& ddx, const glm::vec3& ddy) {
    return lod_of(texture, coord, ddx, ddy);
}

bool lanes_only(const Texture& texture, SamplingRules rules) {
    return (rules == SamplingRules::Gpu && gpu::filtered(texture)) ||
           (rules == SamplingRules::Spec && spec_switch_over(texture.sampler));
}

namespace {

// Whether this lookup follows the GPU's arithmetic (sampling_gpu.h).
bool gpu_lookup(const Texture& texture, const LaneLookup& lookup) {
    return lookup.rules == SamplingRules::Gpu && gpu::filtered(texture);
}

// lambda_base from the lookup's derivatives, by the lookup's rules.
float implicit_lambda(const Texture& texture, const LaneLookup& lookup) {
    if (gpu_lookup(texture, lookup)) return gpu::lambda_of_rho(rho_of(texture, lookup.coord, lookup.ddx, lookup.ddy, true));
    return lod_of(texture, lookup.coord, lookup.ddx, lookup.ddy);
}

// The shader's LOD bias as the lookup's rules add it (the GPU's: 8 fraction bits, toward zero).
float shader_bias(const Texture& texture, const LaneLookup& lookup) {
    return gpu_lookup(texture, lookup) ? gpu::quantize_bias(lookup.lod) : lookup.lod;
}

template <class Obs>
glm::vec4 sample_by_rules(const Texture& texture, const LaneLookup& lookup, float lod, Obs&& obs) {
    if (gpu_lookup(texture, lookup)) return gpu::sample_complete(texture, lookup.coord, lookup.ref, lod, obs);
    return sample_complete(texture, lookup.coord, lookup.ref, lod, obs, lookup.rules);
}

}  // namespace

glm::vec4 sample_texture(const Texture& texture, const glm::vec3& coord, float ref, float lod, SamplingRules rules) {
    if (!texture.complete()) return {0.0f, 0.0f, 0.0f, 1.0f};
    LaneLookup lookup;
    lookup.coord = coord;
    lookup.ref = ref;
    lookup.lod = lod;
    lookup.implicit = false;
    lookup.rules = rules;
    if (texture.target() == TextureTarget::Rect) {
        glm::vec4 v;
        sample_rect_lane(texture, lookup, &v.x);
        return v;
    }
    return sample_by_rules(texture, lookup, lod, NoObserver{});
}

void sample_complete_lane(const Texture& texture, const LaneLookup& lookup, float* rgba) {
    float lod = lookup.lod;
    const bool lod_matters = sampling::lod_matters(texture.sampler);
    if (lookup.implicit && lod_matters)
        lod = lookup.bias ? implicit_lambda(texture, lookup) + shader_bias(texture, lookup) : implicit_lambda(texture, lookup);
    const glm::vec4 v = sample_by_rules(texture, lookup, lod, NoObserver{});
    for (int c = 0; c < 4; ++c) rgba[c] = canonical_nan(v[c]);
}

namespace {

// Notes sampling_rules.h's steps into LookupDetails.
struct Recorder {
    LookupDetails& out;
    int current = 0;  // the level being sampled
    void filter(float lambda, bool magnified) {
        out.lambda = lambda;
        out.magnified = magnified;
    }
    void level(int l, const TextureImage& image, bool linear) {
        current = l;
        out.levels.push_back({l, image.width, image.height, image.depth, linear});
    }
    void texel(int i, int j, int k, Texel value) {
        const glm::vec4 v = vec_of(value);
        out.texels.push_back({current, i, j, k, v});
    }
};

}  // namespace

LookupDetails explain_lookup(const Texture* texture, const LaneLookup& lookup) {
    LookupDetails d;
    if (!texture || !texture->complete()) return d;
    d.complete = true;
    if (texture->target() == TextureTarget::Cube) {
        d.face = cube_face(lookup.coord);
        d.face_coord = cube_coord(kCubeFaces[d.face], lookup.coord);
    }
    // As sample_complete_lane(): the implicit LOD only where it matters.
    d.lod_implicit = lookup.implicit ? implicit_lambda(*texture, lookup) : std::numeric_limits<float>::quiet_NaN();
    d.lod_used = !lookup.implicit || sampling::lod_matters(texture->sampler);
    float lod = lookup.lod;
    if (lookup.implicit && d.lod_used) lod = lookup.bias ? d.lod_implicit + shader_bias(*texture, lookup) : d.lod_implicit;
    const glm::vec4 v = sample_by_rules(*texture, lookup, lod, Recorder{d});
    // The filters fetch in the order the compiler evaluates their operands
    // (GCC and clang differ): each level's texels are listed sorted instead.
    std::stable_sort(d.texels.begin(), d.texels.end(), [&](const LookupTexel& a, const LookupTexel& b) {
        auto level_at = [&](int level) {
            return std::find_if(d.levels.begin(), d.levels.end(), [&](const LookupLevel& l) { return l.level == level; });
        };
        return std::tuple(level_at(a.level), a.k, a.j, a.i) < std::tuple(level_at(b.level), b.k, b.j, b.i);
    });
    for (int c = 0; c < 4; ++c) d.result[c] = canonical_nan(v[c]);
    return d;
}

}  // namespace glslrun::rt
