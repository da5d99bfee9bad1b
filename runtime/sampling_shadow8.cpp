// The shadow-map kernels of sampling_shadow8.h, on sampling_direct8.h's
// index steps: each texel's depth (its .r) gathered, compared with the
// lane's reference by one vector compare (compare_depth()'s predicate;
// C++'s != is the unordered one), and LINEAR's four results blended by
// sample_linear()'s mix(): the rows by the x weight, then the rows by the
// y weight. Before this, LINEAR's indices and results went through lane
// arrays, each comparison was a scalar call, and only CLAMP_TO_EDGE maps
// were taken.
#include "runtime/sampling_shadow8.h"

#include "runtime/sampling_direct8.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

struct Map {
    const glm::vec4* texels;  // a depth texture keeps its depth in .r
    Axis w, h;
    DepthTextureMode mode;
};

// compare_depth(kFunc, ref, d) of eight lanes: 1 or 0.
template <CompareFunc kFunc>
[[gnu::always_inline]] GLSLRUN_AVX2 inline V compare8(V ref, V d) {
    using enum CompareFunc;
    const V one = splat(1.0f);
    if constexpr (kFunc == Never) return _mm256_setzero_ps();
    else if constexpr (kFunc == Always) return one;
    else {
        constexpr int kPredicate = kFunc == Less ? _CMP_LT_OQ : kFunc == Equal ? _CMP_EQ_OQ : kFunc == Lequal ? _CMP_LE_OQ
                                   : kFunc == Greater ? _CMP_GT_OQ : kFunc == Notequal ? _CMP_NEQ_UQ : _CMP_GE_OQ;
        return _mm256_and_ps(_mm256_cmp_ps(ref, d, kPredicate), one);
    }
}

// The comparison results at texels `at` (indices in the image; their byte
// offsets below 2^28: w * h below 2^24, limits.md).
template <CompareFunc kFunc>
[[gnu::always_inline]] GLSLRUN_AVX2 inline V compare_at8(const glm::vec4* texels, I at, V ref) {
    if constexpr (kFunc == CompareFunc::Never || kFunc == CompareFunc::Always) return compare8<kFunc>(ref, ref);
    else return compare8<kFunc>(ref, _mm256_i32gather_ps(&texels[0].x, _mm256_slli_epi32(at, 4), 1));
}

template <bool kLinear, Rule kS, Rule kT, CompareFunc kFunc>
GLSLRUN_AVX2 void shadow8(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    static_assert(kLanes % 8 == 0, "eight lanes at a time");
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[size_t(st.base_level)];
    const Map map{image.texels.data(),
                  {image.width, splat(float(image.width))},
                  {image.height, splat(float(image.height))},
                  st.depth_mode};
    const V zero = _mm256_setzero_ps(), one = splat(1.0f);
    const I width = splat_i(map.w.n);
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        const V ref = clamp_or_low8(_mm256_loadu_ps(lk.ref + g), zero, one);  // §3.8.14: R clamped to [0, 1]
        const V s = _mm256_loadu_ps(lk.coord[0] + g), t = _mm256_loadu_ps(lk.coord[1] + g);
        V d;
        if constexpr (!kLinear) {
            const I at = _mm256_add_epi32(_mm256_mullo_epi32(nearest8<kT>(t, map.h), width), nearest8<kS>(s, map.w));
            d = compare_at8<kFunc>(map.texels, at, ref);
        } else {
            const Linear8 x = linear8<kS>(s, map.w), y = linear8<kT>(t, map.h);
            const I row0 = _mm256_mullo_epi32(y.i0, width), row1 = _mm256_mullo_epi32(y.i1, width);  // w * h below 2^24
            const V c00 = compare_at8<kFunc>(map.texels, _mm256_add_epi32(row0, x.i0), ref);
            const V c10 = compare_at8<kFunc>(map.texels, _mm256_add_epi32(row0, x.i1), ref);
            const V c01 = compare_at8<kFunc>(map.texels, _mm256_add_epi32(row1, x.i0), ref);
            const V c11 = compare_at8<kFunc>(map.texels, _mm256_add_epi32(row1, x.i1), ref);
            const V ia = _mm256_sub_ps(one, x.a), ib = _mm256_sub_ps(one, y.a);
            d = mix8(mix8(c00, c10, x.a, ia), mix8(c01, c11, x.a, ia), y.a, ib);
        }
        // expand_depth(): (d, d, d, 1), (d, d, d, d) or (0, 0, 0, d).
        const V rgb = map.mode == DepthTextureMode::Alpha ? zero : d;
        const V value[4] = {rgb, rgb, rgb, map.mode == DepthTextureMode::Luminance ? one : d};
        store8(value, bits, g, out);
    }
}

template <bool kLinear, Rule kS, Rule kT>
BatchKernel with_func(CompareFunc func) {
    using enum CompareFunc;
    switch (func) {
    case Never: return shadow8<kLinear, kS, kT, Never>;
    case Less: return shadow8<kLinear, kS, kT, Less>;
    case Equal: return shadow8<kLinear, kS, kT, Equal>;
    case Lequal: return shadow8<kLinear, kS, kT, Lequal>;
    case Greater: return shadow8<kLinear, kS, kT, Greater>;
    case Notequal: return shadow8<kLinear, kS, kT, Notequal>;
    case Gequal: return shadow8<kLinear, kS, kT, Gequal>;
    case Always: return shadow8<kLinear, kS, kT, Always>;
    }
    return nullptr;
}

}  // namespace

BatchKernel shadow8_kernel(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Tex2D || !texture.depth() || !st.compare || lod_matters(st)) return nullptr;
    BatchKernel kernel = nullptr;
    with_rules<false>(st, linear_within_level(st.mag_filter), [&]<bool kLinear, Rule kS, Rule kT>() {
        if constexpr (!may_border(kS, kLinear) && !may_border(kT, kLinear))
            kernel = with_func<kLinear, kS, kT>(st.compare_func);
    });
    return kernel;
}

bool shadow8_samples(const Texture& texture, const BatchLookup& lookup) {
    return lookup.ref && shadow8_kernel(texture);
}

void sample_shadow8(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]) {
    shadow8_kernel(texture)(texture, lookup, lanes, out);
}
#undef GLSLRUN_AVX2

#else
BatchKernel shadow8_kernel(const Texture&) { return nullptr; }
bool shadow8_samples(const Texture&, const BatchLookup&) { return false; }
void sample_shadow8(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
#endif

}  // namespace glslrun::rt
