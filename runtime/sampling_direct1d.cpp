// The one-pass 1D kernels of sampling_direct1d.h, on sampling_direct8.h's
// steps with the row index 0: sample_nearest()'s texel, or
// sample_linear()'s one mix of the two texels by the axis's weight,
// t(x0) (1 - a) + t(x1) a; the border's texels (CLAMP_TO_BORDER, LINEAR's
// CLAMP) where the index is kBorder.
#include "runtime/sampling_direct1d.h"

#include "runtime/sampling_direct8.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

template <bool kLinear, Rule kS>
GLSLRUN_AVX2 void direct1d(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    constexpr bool kBorder = may_border(kS, kLinear);
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[size_t(st.base_level)];
    Source src = source_of(image, st);
    src.finite = texture.format() == TextureFormat::RGBA8;
    const Axis w{image.width, splat(float(image.width))};
    const I row = _mm256_setzero_si256();
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        const V s = _mm256_loadu_ps(lk.coord[0] + g);
        V value[4];
        if constexpr (!kLinear) {
            fetch8<kBorder>(src, nearest8<kS>(s, w), row, value);
        } else {
            const Linear8 x = linear8<kS>(s, w);
            V left[4], right[4];
            fetch8<kBorder>(src, x.i0, row, left);
            fetch8<kBorder>(src, x.i1, row, right);
            const V ia = _mm256_sub_ps(splat(1.0f), x.a);
#pragma GCC unroll 4
            for (int c = 0; c < 4; ++c) value[c] = mix8(left[c], right[c], x.a, ia);
        }
        store_lookup8<kLinear, kS, Rule::Edge>(src.finite, value, bits, g, out);
    }
}

template <bool kLinear>
BatchKernel with_rule(Rule s) {
    switch (s) {
    case Rule::Repeat: return direct1d<kLinear, Rule::Repeat>;
    case Rule::Mirror: return direct1d<kLinear, Rule::Mirror>;
    case Rule::Edge: return direct1d<kLinear, Rule::Edge>;
    case Rule::Clamp: return direct1d<kLinear, Rule::Clamp>;
    case Rule::Border: return direct1d<kLinear, Rule::Border>;
    default: return nullptr;
    }
}

}  // namespace

BatchKernel direct1d_kernel(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Tex1D || texture.depth() || lod_matters(st)) return nullptr;
    const bool linear = linear_within_level(st.mag_filter);
    const Rule s = rule_of(st.wrap_s, false, linear);
    return linear ? with_rule<true>(s) : with_rule<false>(s);
}
#undef GLSLRUN_AVX2

#else
BatchKernel direct1d_kernel(const Texture&) { return nullptr; }
#endif

}  // namespace glslrun::rt
