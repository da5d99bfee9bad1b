// Part of sampling_batch.cpp's translation unit, included inside its
// anonymous namespace after the AVX2 blends (linear8(), mix8()) and
// sampling_batch_lanes8.h: the AVX2 build's depth-comparison lookups of a 2D
// depth texture with one image (a shadow map: sampler2DShadow,
// shadow2D/shadow2DProj, one lookup or several PCF taps), eight lanes at a
// time from the coordinates to the result.
//
// Per lane, as the lane sampler: the texel indices of nearest_index() or
// linear_axis() (wraps that keep every texel in the image), each texel's
// depth compared with the lane's reference (compare_depth(), the function
// chosen once), LINEAR's four results blended by the same products and sums
// as sample_linear()'s mix(), and DEPTH_TEXTURE_MODE's expansion. Before
// this, the steps went through the lane arrays: the indices, the depths, the
// results, then each lane's expansion one lane at a time; LINEAR's
// comparisons lane by lane through fetch().

// The depths of texels at[g..g+7] (offsets in texels) of `texels`.
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256 depths8(const glm::vec4* texels, const int* at, int g) {
    const __m256i offset = _mm256_slli_epi32(ints8(at + g), 2);
    return _mm256_i32gather_ps(&texels[0].x, offset, 4);  // the r of each texel: 4 floats per texel
}

template <TextureWrap kS, TextureWrap kT, CompareFunc kFunc, bool kLinear>
GLSLRUN_AVX2 void shadow_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[size_t(st.base_level)];
    const int w = image.width, h = image.height;  // w * h below 2^24 (limits.md): no overflow
    const glm::vec4* texels = image.texels.data();
    const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
    alignas(32) int x0[kLanes], x1[kLanes], y0[kLanes], y1[kLanes], at[4][kLanes];
    alignas(32) float ax[kLanes], ay[kLanes], ref[kLanes], result[4][kLanes];
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        for (int k = g; k < g + 8; ++k) ref[k] = unorm(lk.ref[k]);  // §3.8.14: R clamped to [0, 1]
        int corners = 1;
        if constexpr (kLinear) {
            linear8<kS, false>(lk.coord[0], w, g, x0, x1, ax);
            linear8<kT, false>(lk.coord[1], h, g, y0, y1, ay);
            corners8(x0, x1, y0, y1, w, g, at);
            corners = 4;
        } else {
            // nearest_index<CLAMP_TO_EDGE, true>() of the eight lanes in registers (sampling_direct8.h):
            // lane by lane, the two indices were a third of the shadow scene's lookups (perf).
            static_assert(kS == TextureWrap::ClampToEdge && kT == TextureWrap::ClampToEdge);
            using direct8::Rule;
            const __m256i x = direct8::nearest8<Rule::Edge>(_mm256_loadu_ps(lk.coord[0] + g), {w, _mm256_set1_ps(float(w))});
            const __m256i y = direct8::nearest8<Rule::Edge>(_mm256_loadu_ps(lk.coord[1] + g), {h, _mm256_set1_ps(float(h))});
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(&at[0][g]),
                                _mm256_add_epi32(_mm256_mullo_epi32(y, _mm256_set1_epi32(w)), x));
        }
        for (int c = 0; c < corners; ++c) {
            alignas(32) float depth[8];
            _mm256_store_ps(depth, depths8(texels, at[c], g));
            for (int k = 0; k < 8; ++k) result[c][g + k] = compare_depth(kFunc, ref[g + k], depth[k]);
        }
        __m256 d = _mm256_loadu_ps(&result[0][g]);
        if constexpr (kLinear) {  // sample_linear()'s mix() of the four results
            const __m256 a = _mm256_loadu_ps(&ax[g]), b = _mm256_loadu_ps(&ay[g]);
            const __m256 ia = _mm256_sub_ps(one, a), ib = _mm256_sub_ps(one, b);
            const __m256 row0 = mix8(d, _mm256_loadu_ps(&result[1][g]), a, ia);
            const __m256 row1 = mix8(_mm256_loadu_ps(&result[2][g]), _mm256_loadu_ps(&result[3][g]), a, ia);
            d = mix8(row0, row1, b, ib);
        }
        // expand_depth(): (d, d, d, 1), (d, d, d, d) or (0, 0, 0, d).
        const bool alpha = st.depth_mode == DepthTextureMode::Alpha;
        const __m256 rgb = alpha ? zero : d;
        const __m256 a = st.depth_mode == DepthTextureMode::Luminance ? one : d;
        const __m256 channel[4] = {rgb, rgb, rgb, a};
        store8(channel, mask8(bits), g, out);
    }
}

// shadow_direct() where the texture takes it: a 2D depth texture with the
// comparison on, one image and one filter (no level-of-detail decision),
// both wraps CLAMP_TO_EDGE (a shadow map's; the other wraps take the
// steps). False: the steps.
GLSLRUN_AVX2 bool sample_shadow_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                       float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    using enum TextureWrap;
    if (texture.target() != TextureTarget::Tex2D || !texture.depth() || !st.compare || !lk.ref || lod_matters(st) ||
        st.wrap_s != ClampToEdge || st.wrap_t != ClampToEdge)
        return false;
    const auto with_func = [&]<bool kLinear>() {
        using enum CompareFunc;
        switch (st.compare_func) {
        case Never: return shadow_direct<ClampToEdge, ClampToEdge, Never, kLinear>(texture, lk, lanes, out);
        case Less: return shadow_direct<ClampToEdge, ClampToEdge, Less, kLinear>(texture, lk, lanes, out);
        case Equal: return shadow_direct<ClampToEdge, ClampToEdge, Equal, kLinear>(texture, lk, lanes, out);
        case Lequal: return shadow_direct<ClampToEdge, ClampToEdge, Lequal, kLinear>(texture, lk, lanes, out);
        case Greater: return shadow_direct<ClampToEdge, ClampToEdge, Greater, kLinear>(texture, lk, lanes, out);
        case Notequal: return shadow_direct<ClampToEdge, ClampToEdge, Notequal, kLinear>(texture, lk, lanes, out);
        case Gequal: return shadow_direct<ClampToEdge, ClampToEdge, Gequal, kLinear>(texture, lk, lanes, out);
        case Always: return shadow_direct<ClampToEdge, ClampToEdge, Always, kLinear>(texture, lk, lanes, out);
        }
    };
    if (linear_within_level(st.mag_filter)) with_func.template operator()<true>();
    else with_func.template operator()<false>();
    return true;
}
