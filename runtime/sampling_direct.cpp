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

// The lookups of kLanes lanes, kTogether groups of eight at a time: their
// lookups are written one after the other with no branch between them, so
// the CPU overlaps one group's chain from the coordinates through the
// indices and the loads to the blend with the next ones' (perf: that
// chain's latency, not the arithmetic, bounded the kernel one group at a
// time: post's frame 66 -> 63 ms). A group with no lane of `lanes` is
// sampled too, on whatever its coordinates hold (every rule keeps every
// index in the image, for any float), and not stored.
template <bool kLinear, Rule kS, Rule kT>
GLSLRUN_AVX2 void direct(const Source& src, const Axis& w, const Axis& h, const BatchLookup& lk, LaneMask lanes,
                         float (*out)[kLanes]) {
    // The border's rules load each corner apart (fetch8()), twice the
    // registers' worth: four such groups in flight measured no faster
    // (two_units' decal: 3% slower in one set of runs, within the noise).
    constexpr bool kBorder = may_border(kS, kLinear) || may_border(kT, kLinear);
    constexpr int kTogether = kBorder ? 1 : kLanes % 32 == 0 ? 4 : kLanes % 16 == 0 ? 2 : 1;
    for (int g = 0; g < kLanes; g += 8 * kTogether) {
        if (!uint32_t(lanes >> g)) continue;  // none of these groups' lanes (a 64-lane build's other half)
        V value[kTogether][4];
#pragma GCC unroll 4
        for (int k = 0; k < kTogether; ++k)
            lookup8<kLinear, kS, kT>(src, w, h, _mm256_loadu_ps(lk.coord[0] + g + 8 * k),
                                     _mm256_loadu_ps(lk.coord[1] + g + 8 * k), value[k]);
#pragma GCC unroll 4
        for (int k = 0; k < kTogether; ++k) {
            const int bits = int(uint32_t(lanes >> (g + 8 * k)) & 0xffu);
            if (bits) store_lookup8<kLinear, kS, kT>(src.finite, value[k], bits, g + 8 * k, out);
        }
    }
}

using Kernel = void (*)(const Source&, const Axis&, const Axis&, const BatchLookup&, LaneMask, float (*)[kLanes]);

}  // namespace

bool direct_samples(const Texture& texture) {
    const TextureTarget target = texture.target();
    return (target == TextureTarget::Tex2D || target == TextureTarget::Rect) && !texture.depth() &&
           !lod_matters(texture.sampler);
}

namespace {

// The kernel and the image of a texture that direct_samples() takes.
DirectSampler choose(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    const bool rect = texture.target() == TextureTarget::Rect;
    const TextureImage& image = texture.levels(0)[rect ? 0 : size_t(st.base_level)];
    Kernel k = nullptr;
    const auto pick = [&]<bool kLinear, Rule kS, Rule kT>() { k = direct<kLinear, kS, kT>; };
    const bool linear = linear_within_level(st.mag_filter);
    if (rect) with_rules<true>(st, linear, pick);
    else with_rules<false>(st, linear, pick);
    DirectSampler d;
    d.kernel = reinterpret_cast<void (*)()>(k);
    d.texels = image.texels.data();
    d.finite = texture.format() == TextureFormat::RGBA8;
    d.width = image.width;
    d.height = image.height;
    const glm::vec4& b = st.border_color;  // border_texel() of a colour texture
    for (int c = 0; c < 4; ++c) d.border[c] = unorm(b[c]);
    return d;
}

GLSLRUN_AVX2 void run_chosen(const DirectSampler& d, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]) {
    // Each member set once: an aggregate's zero fill of the border (`{}`) was
    // a `rep stos` at every lookup, 6% of post's frame (perf).
    Source src;
    src.texels = static_cast<const glm::vec4*>(d.texels);
    src.width = d.width;
    src.finite = d.finite;
    for (int c = 0; c < 4; ++c) src.border[c] = splat(d.border[c]);
    reinterpret_cast<Kernel>(d.kernel)(src, {d.width, splat(float(d.width))}, {d.height, splat(float(d.height))},
                                       lookup, lanes, out);
}

GLSLRUN_AVX2 void run_bound(const DirectSampler& d, const float* s, const float* t, LaneMask lanes,
                            float (*out)[kLanes]) {
    BatchLookup lookup;  // the kernels read the first two coordinates only
    lookup.coord[0] = s;
    lookup.coord[1] = t;
    run_chosen(d, lookup, lanes, out);
}

}  // namespace

GLSLRUN_AVX2 void sample_direct(const Texture& texture, const BatchLookup& lookup, LaneMask lanes,
                                float (*out)[kLanes]) {
    run_chosen(choose(texture), lookup, lanes, out);
}

DirectSampler bind_direct(const Texture* texture) {
    if (!texture || !__builtin_cpu_supports("avx2") || !texture->complete() || !direct_samples(*texture)) return {};
    DirectSampler d = choose(*texture);
    d.run = run_bound;
    return d;
}
#undef GLSLRUN_AVX2

#else
bool direct_samples(const Texture&) { return false; }
void sample_direct(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
DirectSampler bind_direct(const Texture*) { return {}; }
#endif

}  // namespace glslrun::rt
