// Part of sampling_batch.cpp's translation unit, included inside its
// anonymous namespace after the AVX2 blends (load8() ... linear8()) and
// sampling_batch_lanes8.h, whose helpers and per-lane steps (cube_coords(), lambdas(), choose_levels()) it
// uses: the AVX2 build's lookups of cube maps (mipmapped or not), eight
// lanes at a time from the levels to the result.
//
// The lanes' steps up to the level decision are the batched sampler's own
// (each lane's face and (s, t) on it, lambda with Precise's log2, level(s)
// and mip weight, as filter() decides them). Then, per group of eight
// lanes, the lanes that share a face and a first level are sampled together
// against that face's level image (the sizes and the texel source hoisted,
// the blends eight lanes wide), their second level likewise, and the two
// mixed by each lane's weight; a group whose lanes straddle a cube edge or
// a level boundary takes one such pass per (face, level) it holds. Every
// value comes from the same index functions and the same products and sums
// as the lane sampler's, so the bits are the same
// (tests/runtime/sampling_batch_test.cpp). Before this, a batch whose 32
// lanes did not all read one face (a reflection or refraction: nearly
// always) took the per-lane image path (sizes and texel pointers per lane,
// four lanes at a time). Mipmapped 2D textures take the steps: their
// batches nearly always read one level pair, which the steps already
// sample one image at a time, and this code measured no faster there.

// The bilinear plane of `image` for lanes g..g+7 at (l.s, l.t): sample_linear()'s
// indices (wraps that keep every texel in the image) and blends.
template <TextureWrap kS, TextureWrap kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void level_plane8(const TextureImage& image, const Lanes& l, int g,
                                                             __m256* plane) {
    // sampling_direct8.h's steps: the indices in registers, the blend lane by lane (blend_rows8()).
    namespace d8 = direct8;
    const d8::Axis w{image.width, _mm256_set1_ps(float(image.width))};
    const d8::Axis h{image.height, _mm256_set1_ps(float(image.height))};
    const d8::Linear8 x = d8::linear8<d8::inner_rule(kS)>(_mm256_loadu_ps(l.s + g), w);
    const d8::Linear8 y = d8::linear8<d8::inner_rule(kT)>(_mm256_loadu_ps(l.t + g), h);
    d8::Row8 rows[2];
    d8::row_of(image.texels.data(), image.width, x, y.i0, rows[0]);
    d8::row_of(image.texels.data(), image.width, x, y.i1, rows[1]);
    d8::blend_rows8<1>(rows, &x.a, &y.a, x.a, x.a, plane);
}

// The lanes of lanes g..g+7 (bit k: lane g + k) whose `value` is lane first's.
[[gnu::always_inline]] GLSLRUN_AVX2 inline int lanes_equal8(const int* value, int g, int first) {
    const __m256i same = _mm256_cmpeq_epi32(ints8(value + g), _mm256_set1_epi32(value[first]));
    return _mm256_movemask_ps(_mm256_castsi256_ps(same));
}

// cube_coords() of every lane, eight at a time: cube_face()'s comparisons
// as masks and its choices as blends (no branch or table per lane), then
// cube_coord()'s products and quotient in its order, s_sign * sc / ma (the
// sign a multiplication, as there, so that a NaN keeps its bits). GCC left
// cube_coords()'s loop scalar (perf: a third of cube_refract's lookups, on
// its divisions and selects).
GLSLRUN_AVX2 inline void cube_coords8(const BatchLookup& lk, Lanes& l) {
    const __m256 zero = _mm256_setzero_ps(), sign = _mm256_set1_ps(-0.0f);
    const __m256 one = _mm256_set1_ps(1.0f), minus = _mm256_set1_ps(-1.0f), half = _mm256_set1_ps(0.5f);
    for (int g = 0; g < kLanes; g += 8) {
        const __m256 x = _mm256_loadu_ps(lk.coord[0] + g), y = _mm256_loadu_ps(lk.coord[1] + g);
        const __m256 z = _mm256_loadu_ps(lk.coord[2] + g);
        const __m256 ax = _mm256_andnot_ps(sign, x), ay = _mm256_andnot_ps(sign, y), az = _mm256_andnot_ps(sign, z);
        const __m256 x_major = _mm256_and_ps(_mm256_cmp_ps(ax, ay, _CMP_GE_OQ), _mm256_cmp_ps(ax, az, _CMP_GE_OQ));
        const __m256 y_major = _mm256_andnot_ps(x_major, _mm256_cmp_ps(ay, az, _CMP_GE_OQ));
        const __m256 x_pos = _mm256_cmp_ps(x, zero, _CMP_GE_OQ), y_pos = _mm256_cmp_ps(y, zero, _CMP_GE_OQ);
        const __m256 z_pos = _mm256_cmp_ps(z, zero, _CMP_GE_OQ);
        // +X 0, -X 1, +Y 2, -Y 3, +Z 4, -Z 5: the odd face plus the mask (-1 where positive).
        const __m256i fx = _mm256_add_epi32(_mm256_set1_epi32(1), _mm256_castps_si256(x_pos));
        const __m256i fy = _mm256_add_epi32(_mm256_set1_epi32(3), _mm256_castps_si256(y_pos));
        const __m256i fz = _mm256_add_epi32(_mm256_set1_epi32(5), _mm256_castps_si256(z_pos));
        const __m256 fyz = _mm256_blendv_ps(_mm256_castsi256_ps(fz), _mm256_castsi256_ps(fy), y_major);
        const __m256i face = _mm256_castps_si256(_mm256_blendv_ps(fyz, _mm256_castsi256_ps(fx), x_major));
        const __m256 major = _mm256_blendv_ps(_mm256_blendv_ps(z, y, y_major), x, x_major);
        const __m256 sc = _mm256_blendv_ps(x, z, x_major), tc = _mm256_blendv_ps(y, z, y_major);
        // s_sign -1 on +X and -Z, t_sign +1 on +Y only (kCubeFaces).
        const __m256 all = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        const __m256 z_major = _mm256_andnot_ps(_mm256_or_ps(x_major, y_major), all);
        const __m256 z_minus = _mm256_andnot_ps(z_pos, z_major);
        const __m256 s_sign = _mm256_blendv_ps(one, minus, _mm256_or_ps(_mm256_and_ps(x_major, x_pos), z_minus));
        const __m256 t_sign = _mm256_blendv_ps(minus, one, _mm256_and_ps(y_major, y_pos));
        const __m256 ma = _mm256_andnot_ps(sign, major);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(l.face + g), face);
        const __m256 s = _mm256_add_ps(_mm256_div_ps(_mm256_mul_ps(s_sign, sc), ma), one);
        const __m256 t = _mm256_add_ps(_mm256_div_ps(_mm256_mul_ps(t_sign, tc), ma), one);
        _mm256_storeu_ps(l.s + g, _mm256_mul_ps(half, s));
        _mm256_storeu_ps(l.t + g, _mm256_mul_ps(half, t));
    }
}

template <TextureWrap kS, TextureWrap kT>
GLSLRUN_AVX2 void cube_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    Lanes l;
    cube_coords8(lk, l);
    const SamplerState& st = texture.sampler;
    if (lod_matters(st)) {
        lambdas(texture, lk, l);
        choose_levels(texture, l);
    } else {  // choose_levels()'s result whatever lambda is: level_base, one level
        for (int i = 0; i < kLanes; ++i) {
            l.level[0][i] = st.base_level;
            l.level[1][i] = -1;
        }
    }
    for (int g = 0; g < kLanes; g += 8) {
        int left = int(uint32_t(lanes >> g) & 0xffu);
        while (left) {
            const int first = g + std::countr_zero(unsigned(left));
            const int face = l.face[first], d0 = l.level[0][first];
            const int take = left & lanes_equal8(l.face, g, first) & lanes_equal8(l.level[0], g, first);
            left &= ~take;
            int two = 0;
            for (int k = 0; k < 8; ++k) two |= int(l.level[1][g + k] >= 0) << k;
            two &= take;  // their second level is d0 + 1, which exists: d0 < q
            const std::vector<TextureImage>& levels = texture.levels(face);
            __m256 plane[4];
            level_plane8<kS, kT>(levels[size_t(d0)], l, g, plane);
            if (two) {
                __m256 second[4];
                level_plane8<kS, kT>(levels[size_t(d0) + 1], l, g, second);
                // filter()'s mix() of the two levels by each lane's weight.
                const __m256 w = _mm256_loadu_ps(&l.mip_weight[g]), iw = _mm256_sub_ps(_mm256_set1_ps(1.0f), w);
                const __m256 mixed = mask8(two);
                #pragma GCC unroll 4
                for (int c = 0; c < 4; ++c) plane[c] = _mm256_blendv_ps(plane[c], mix8(plane[c], second[c], w, iw), mixed);
            }
            store8(plane, mask8(take), g, out);
        }
    }
}

// cube_direct() where the texture takes it: a cube map, colour (no
// depth), LINEAR within every level (both filters), wraps that keep every
// texel in the image. False: the steps of sample_levels_of_lanes().
GLSLRUN_AVX2 bool sample_cube_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                     float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Cube || texture.depth() || !linear_within_level(st.mag_filter) ||
        !linear_within_level(st.min_filter))
        return false;
    return with_inner_wraps(st, [&]<TextureWrap kS, TextureWrap kT>() { cube_direct<kS, kT>(texture, lk, lanes, out); });
}
