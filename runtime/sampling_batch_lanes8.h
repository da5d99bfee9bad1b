// Part of sampling_batch.cpp's translation unit, included inside its
// anonymous namespace after the AVX2 blends: the small eight-lane steps
// of the AVX2 lookups of cube maps (sampling_batch_cube.h).

// An eight-lane mask from bits 0..7 (bit k: lane g + k).
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256 mask8(int bits) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(bits), bit), bit));
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256i ints8(const int* p) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

// Lanes g..g+7's four channels into out where `store` (all ones) says so,
// a NaN as canonical_nan()'s.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void store8(const __m256* channel, __m256 store, int g,
                                                       float (*out)[kLanes]) {
    const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
        const __m256 v = _mm256_blendv_ps(channel[c], nan, _mm256_cmp_ps(channel[c], channel[c], _CMP_UNORD_Q));
        _mm256_storeu_ps(&out[c][g], _mm256_blendv_ps(_mm256_loadu_ps(&out[c][g]), v, store));
    }
}

// f.template operator()<kS, kT>() for a wrap pair that keeps every texel of
// a LINEAR footprint in the image (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE);
// false, f not called, where CLAMP or CLAMP_TO_BORDER may meet the border.
template <class F>
[[gnu::always_inline]] inline bool with_inner_wraps(const SamplerState& st, F&& f) {
    using enum TextureWrap;
    const auto with_t = [&]<TextureWrap kS>() {
        switch (st.wrap_t) {
        case Repeat: f.template operator()<kS, Repeat>(); return true;
        case MirroredRepeat: f.template operator()<kS, MirroredRepeat>(); return true;
        case ClampToEdge: f.template operator()<kS, ClampToEdge>(); return true;
        default: return false;
        }
    };
    switch (st.wrap_s) {
    case Repeat: return with_t.template operator()<Repeat>();
    case MirroredRepeat: return with_t.template operator()<MirroredRepeat>();
    case ClampToEdge: return with_t.template operator()<ClampToEdge>();
    default: return false;
    }
}
