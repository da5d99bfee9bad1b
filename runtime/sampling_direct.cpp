// The one-pass lookups of sampling_direct.h: one kernel per texture state,
// each axis's rule (the wrap mode as NEAREST or LINEAR, normalized or a
// rectangle's texels applies it) a template argument, so no branch on the
// state runs inside the lane loop. The eight-lane steps are
// sampling_direct8.h's.
#include "runtime/sampling_direct.h"

#include "runtime/sampling_direct8.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

template <bool kLinear, Rule kS, Rule kT>
GLSLRUN_AVX2 void direct(const Source& src, const Axis& w, const Axis& h, const BatchLookup& lk, LaneMask lanes,
                         float (*out)[kLanes]) {
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        V value[4];
        lookup8<kLinear, kS, kT>(src, w, h, _mm256_loadu_ps(lk.coord[0] + g), _mm256_loadu_ps(lk.coord[1] + g), value);
        store8(value, bits, g, out);
    }
}

using Kernel = void (*)(const Source&, const Axis&, const Axis&, const BatchLookup&, LaneMask, float (*)[kLanes]);

}  // namespace

bool direct_samples(const Texture& texture) {
    const TextureTarget target = texture.target();
    return (target == TextureTarget::Tex2D || target == TextureTarget::Rect) && !texture.depth() &&
           !lod_matters(texture.sampler);
}

GLSLRUN_AVX2 void sample_direct(const Texture& texture, const BatchLookup& lookup, LaneMask lanes,
                                float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    const bool rect = texture.target() == TextureTarget::Rect;
    const TextureImage& image = texture.levels(0)[rect ? 0 : size_t(st.base_level)];
    Kernel k = nullptr;
    const auto pick = [&]<bool kLinear, Rule kS, Rule kT>() { k = direct<kLinear, kS, kT>; };
    const bool linear = linear_within_level(st.mag_filter);
    if (rect) with_rules<true>(st, linear, pick);
    else with_rules<false>(st, linear, pick);
    k(source_of(image, st), {image.width, splat(float(image.width))}, {image.height, splat(float(image.height))}, lookup, lanes, out);
}
#undef GLSLRUN_AVX2

#else
bool direct_samples(const Texture&) { return false; }
void sample_direct(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
#endif

}  // namespace glslrun::rt
