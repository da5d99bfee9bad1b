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

template <TextureWrap kS, TextureWrap kT>
GLSLRUN_AVX2 void cube_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    Lanes l;
    cube_coords8(lk, l.face, l.s, l.t);
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

// cube_direct()'s kernel where the texture takes it: a cube map, colour
// (no depth), LINEAR within every level (both filters), wraps that keep
// every texel in the image; else null (the steps of
// sample_levels_of_lanes()).
BatchKernel cube_direct_kernel(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Cube || texture.depth() || !linear_within_level(st.mag_filter) ||
        !linear_within_level(st.min_filter))
        return nullptr;
    BatchKernel kernel = nullptr;
    with_inner_wraps(st, [&]<TextureWrap kS, TextureWrap kT>() { kernel = cube_direct<kS, kT>; });
    return kernel;
}

GLSLRUN_AVX2 bool sample_cube_direct(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                     float (*out)[kLanes]) {
    const BatchKernel kernel = cube_direct_kernel(texture);
    if (kernel) kernel(texture, lk, lanes, out);
    return kernel != nullptr;
}
