// Part of sampling_batch.cpp's translation unit, included inside its
// anonymous namespace after the AVX2 blends (load8(), mix8(), linear8())
// and sampling_batch_lanes8.h: the AVX2 build's bilinear lookups of one
// colour 2D image whose wraps reach the border (CLAMP, CLAMP_TO_BORDER: a
// projected slide or a decal outside which the border colour shows), eight
// lanes at a time.
//
// linear_axis() gives kBorder for an index outside the image; sample_linear()
// then blends the border colour in that corner's place. Here every corner is
// loaded at an index clamped into the image and replaced by the border
// colour where either of its indices is the border's; the blends are the
// same products and sums, so the bits are the lane sampler's. Before this,
// these lookups went lane by lane through fetch() (a test of each index per
// texel).

// One row's two corners, the border colour where `out0`/`out1` (all ones) says so.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void border_row8(const glm::vec4* texels, const int* at0, const int* at1,
                                                            __m256i out0, __m256i out1, const __m256* border, int g,
                                                            __m256 a, __m256 ia, __m256* row) {
    __m256 x[4], y[4];
    load8(texels, at0, g, x);
    load8(texels, at1, g, y);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c)
        row[c] = mix8(_mm256_blendv_ps(x[c], border[c], _mm256_castsi256_ps(out0)),
                      _mm256_blendv_ps(y[c], border[c], _mm256_castsi256_ps(out1)), a, ia);
}

template <TextureWrap kWrap>
GLSLRUN_AVX2 void border_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[size_t(st.base_level)];
    const int w = image.width, h = image.height;  // w * h below 2^24 (limits.md): no overflow
    const glm::vec4* texels = image.texels.data();
    const Lookup proto{&texture, &st, 0, 2, glm::vec3(0.0f), false, 0.0f};
    const glm::vec4 b = border_texel(proto);
    const __m256 border[4] = {_mm256_set1_ps(b.r), _mm256_set1_ps(b.g), _mm256_set1_ps(b.b), _mm256_set1_ps(b.a)};
    const __m256i zero = _mm256_setzero_si256();
    alignas(32) int x0[kLanes], x1[kLanes], y0[kLanes], y1[kLanes], at[4][kLanes];
    alignas(32) float ax[kLanes], ay[kLanes];
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        linear8<kWrap, false>(lk.coord[0], w, g, x0, x1, ax);
        linear8<kWrap, false>(lk.coord[1], h, g, y0, y1, ay);
        for (int k = g; k < g + 8; ++k) {  // kBorder (-1) read as texel 0, replaced below
            const int row0 = std::max(y0[k], 0) * w, row1 = std::max(y1[k], 0) * w;
            at[0][k] = row0 + std::max(x0[k], 0);
            at[1][k] = row0 + std::max(x1[k], 0);
            at[2][k] = row1 + std::max(x0[k], 0);
            at[3][k] = row1 + std::max(x1[k], 0);
        }
        const __m256i out_x0 = _mm256_cmpgt_epi32(zero, ints8(&x0[g])), out_x1 = _mm256_cmpgt_epi32(zero, ints8(&x1[g]));
        const __m256i out_y0 = _mm256_cmpgt_epi32(zero, ints8(&y0[g])), out_y1 = _mm256_cmpgt_epi32(zero, ints8(&y1[g]));
        const __m256 a = _mm256_loadu_ps(&ax[g]), bw = _mm256_loadu_ps(&ay[g]);
        const __m256 one = _mm256_set1_ps(1.0f);
        const __m256 ia = _mm256_sub_ps(one, a), ib = _mm256_sub_ps(one, bw);
        __m256 row0[4], row1[4];
        border_row8(texels, at[0], at[1], _mm256_or_si256(out_x0, out_y0), _mm256_or_si256(out_x1, out_y0), border, g,
                    a, ia, row0);
        border_row8(texels, at[2], at[3], _mm256_or_si256(out_x0, out_y1), _mm256_or_si256(out_x1, out_y1), border, g,
                    a, ia, row1);
        __m256 plane[4];
        #pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) plane[c] = mix8(row0[c], row1[c], bw, ib);
        store8(plane, mask8(bits), g, out);
    }
}

// border_direct() where the texture takes it: a colour 2D texture, one image
// (no level-of-detail decision), LINEAR, both wraps CLAMP or both
// CLAMP_TO_BORDER. False: the steps.
GLSLRUN_AVX2 bool sample_border_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                       float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Tex2D || texture.depth() || lod_matters(st) ||
        !linear_within_level(st.mag_filter) || st.wrap_s != st.wrap_t)
        return false;
    if (st.wrap_s == TextureWrap::ClampToBorder) border_direct<TextureWrap::ClampToBorder>(texture, lk, lanes, out);
    else if (st.wrap_s == TextureWrap::Clamp) border_direct<TextureWrap::Clamp>(texture, lk, lanes, out);
    else return false;
    return true;
}
