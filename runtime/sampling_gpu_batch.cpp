// The batched sampler of Fast's GPU rules (see sampling_gpu_batch.h). The
// steps of gpu::sample_complete() with each one's texture state hoisted out
// of a loop over all kLanes lanes: the cube face, lambda (one per quad), the
// level(s) and filter, the wrapped indices and 8-bit weights per axis, then
// the 16-bit blends: eight lanes at a time, channel by channel, under AVX2
// where no texel can be the border's (exact integers in float, so any order
// of the sums gives gpu::linear16()'s values), else lane by lane through
// the very functions the per-lane path calls. Lanes outside the mask
// compute too on whatever their registers hold (every step is safe for any
// float) but are not stored.
#include "runtime/sampling_gpu_batch.h"

#include "runtime/interp_kernels.h"
#include "runtime/sampling_cube8.h"
#include "runtime/sampling_gpu.h"
#include "runtime/sampling_rules.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace glslrun::rt {

using namespace sampling;

namespace {

// What each lane carries from one step to the next.
struct GpuLanes {
    alignas(32) float lambda[kLanes];
    alignas(32) int level[2][kLanes];  // level[1] < 0: one level only
    alignas(32) int mip_weight[kLanes];  // 8-bit weight of level[1]
    alignas(32) int linear[kLanes];    // LINEAR within the level (else NEAREST)
    // Cube maps: each lane's face and (s, t) on it.
    alignas(32) int face[kLanes];
    alignas(32) float s[kLanes], t[kLanes];
    // Per level pass: the lane's image, its size, texel indices and 8-bit weights.
    const glm::vec4* texels[kLanes];
    alignas(32) int width[kLanes], height[kLanes];
    alignas(32) int x0[kLanes], x1[kLanes], y0[kLanes], y1[kLanes];
    alignas(32) int wx[kLanes], wy[kLanes];
    // Each level's weight of the lookup (gpu::level_weights()'s share) and
    // its texels' sum by it, not yet rounded (an integer in a float), channel by channel.
    alignas(32) int share[2][kLanes];
    alignas(32) float first[4][kLanes], second[4][kLanes];
};

// lambda for every lane as sample_complete_lane() computes it under the
// GPU's rules: lambda_base from the quad's first lane's derivatives, the
// shader's bias, the texture's bias and clamps, quantized to 8 fraction bits.
void lambdas(const Texture& texture, const BatchLookup& lk, GpuLanes& l) {
    const SamplerState& st = texture.sampler;
    float* lambda = l.lambda;
    if (lk.implicit && lod_matters(st)) {
        if (texture.target() == TextureTarget::Cube) {
            gpu_cube_lambdas(texture, lk, lambda);
        } else {
            const glm::vec3 size = image_size(*level_image(texture, 0, st.base_level));
            const int dims = texture_dims(texture.target());
            // One lambda_base per quad (lanes 4q..4q+3), from its first lane's derivatives.
            for (int q = 0; q < kLanes; q += 4) {
                const glm::vec3 dx(lk.ddx[0][q], lk.ddx[1][q], 0.0f), dy(lk.ddy[0][q], lk.ddy[1][q], 0.0f);
                const float base = gpu::lambda_of_rho(gpu_rho(dx, dy, size, dims));
                for (int i = q; i < q + 4; ++i) lambda[i] = base;
            }
        }
        if (lk.bias)
            for (int i = 0; i < kLanes; ++i) lambda[i] = lambda[i] + gpu::quantize_bias(lk.lod[i]);
    } else if (lk.lod) {
        for (int i = 0; i < kLanes; ++i) lambda[i] = lk.lod[i];
    } else {
        for (int i = 0; i < kLanes; ++i) lambda[i] = 0.0f;
    }
    const float texture_bias = gpu::quantize_bias(st.lod_bias);
    for (int i = 0; i < kLanes; ++i) lambda[i] = gpu::quantize_lambda(clamp_lambda(lambda[i] + texture_bias, st));
}

// gpu::filter16()'s choices for every lane: magnification or minification,
// the filter within the level, the level(s) and the 8-bit mipmap weight.
template <bool kRound>
void choose_levels(const Texture& texture, GpuLanes& l) {
    const SamplerState& st = texture.sampler;
    const int base = st.base_level;
    const int linear_mag = linear_within_level(st.mag_filter), linear_min = linear_within_level(st.min_filter);
    const bool mipmap = is_mipmap_filter(st.min_filter);
    const bool nearest_mip =
        st.min_filter == TextureFilter::NearestMipmapNearest || st.min_filter == TextureFilter::LinearMipmapNearest;
    const int q = mipmap ? last_mip_level(texture.levels(0)[size_t(base)], st) : base;
    for (int i = 0; i < kLanes; ++i) {
        const float lambda = l.lambda[i];
        const bool mag = lambda <= 0.0f;
        const bool minify = !mag && mipmap;
        const bool last = float(base) + lambda >= float(q);
        const float whole = floor_t<kRound>(lambda);
        const int linear_level = last ? q : base + int(whole);
        const int d0 = !minify ? base : (nearest_mip ? gpu::nearest_level(lambda, base, q) : linear_level);
        const bool two = minify && !nearest_mip && !last;
        l.linear[i] = mag ? linear_mag : linear_min;
        l.level[0][i] = d0;
        l.level[1][i] = two ? d0 + 1 : -1;
        l.mip_weight[i] = two ? gpu::weight8(lambda - whole) : 0;
    }
}

// gpu::weight8() written without a branch, so that the lane loops
// vectorise: a NaN or a <= 0 weighs 0, as there.
inline int weight8_lanes(float a) {
    const float c = a > 0.0f ? std::min(a, 1.0f) : 0.0f;
    return int(c * 256.0f + 0.5f);
}

// One axis's indices for every lane: NEAREST's in i0, or LINEAR's two and
// the 8-bit weight of i1. `kRound`: floor_t()'s roundps in the AVX2 build
// (the same bits).
template <TextureWrap kWrap, bool kRound>
void axis_lanes(bool linear, const float* __restrict s, const int* __restrict n, int* __restrict i0,
                int* __restrict i1, int* __restrict w) {
    if (!linear) {
        for (int i = 0; i < kLanes; ++i) i0[i] = nearest_index<kWrap, kRound>(s[i], n[i]);
        return;
    }
    for (int i = 0; i < kLanes; ++i) {
        const LinearAxis axis = linear_axis<kWrap, kRound>(s[i], n[i]);
        i0[i] = axis.i0;
        i1[i] = axis.i1;
        w[i] = weight8_lanes(axis.a);
    }
}


// Whether a wrap mode's indices can be the border's (kBorder).
bool may_border(TextureWrap wrap) { return wrap == TextureWrap::Clamp || wrap == TextureWrap::ClampToBorder; }

// Texel (i, j) of a lane's image as 16-bit values, or the border's where either is kBorder.
[[gnu::always_inline]] inline Texel texel16(const glm::vec4* texels, int width, int i, int j, Texel border) {
    return i < 0 || j < 0 ? border : gpu::unorm16(texel_of(texels[size_t(i) + size_t(width) * size_t(j)]));
}

inline void put(float (*out)[kLanes], int i, Texel t) {
    const glm::vec4 v = vec_of(t);
    for (int c = 0; c < 4; ++c) out[c][i] = v[c];
}

// gpu::linear_sum() of lane i from its indices and weights: the same calls.
[[gnu::always_inline]] inline Texel linear_lane(const GpuLanes& l, int i, int share, Texel border) {
    const glm::vec4* texels = l.texels[i];
    const int w = l.width[i];
    // A 1D lane has wy = 0: its second row weighs 0, and the sum is the 1D blend's exactly.
    const gpu::TexelWeights k = gpu::level_weights(l.wx[i], l.wy[i], share);
    const Texel t00 = texel16(texels, w, l.x0[i], l.y0[i], border);
    const Texel t01 = texel16(texels, w, l.x1[i], l.y0[i], border);
    const Texel t10 = texel16(texels, w, l.x0[i], l.y1[i], border);
    const Texel t11 = texel16(texels, w, l.x1[i], l.y1[i], border);
    const Texel row0 = gpu::plus(gpu::scaled(t00, float(k.w00)), gpu::scaled(t01, float(k.w01)));
    const Texel row1 = gpu::plus(gpu::scaled(t10, float(k.w10)), gpu::scaled(t11, float(k.w11)));
    return gpu::plus(row0, row1);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))
// The texels of lanes g..g+7 at offsets at[g..g+7] of each lane's image,
// as 16-bit values transposed into channels (lanes g..g+3 in the low
// halves, g+4..g+7 in the high ones). gpu::unorm16() is floor(t 65535 +
// 1/2); an RGBA8 image's texel is k/255 (Texture stores every one so), so
// t 65535 is within 0.01 of 257 k and rounding it to nearest (one
// instruction instead of three) gives the same 257 k.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void load16x8(const glm::vec4* const* texels, const int* at, int g,
                                                          __m256* ch) {
    __m256 r[4];
    #pragma GCC unroll 4
    for (int j = 0; j < 4; ++j)
        r[j] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(&texels[g + j][at[g + j]].x)),
                                    _mm_loadu_ps(&texels[g + 4 + j][at[g + 4 + j]].x), 1);
    const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    const __m256 scale = _mm256_set1_ps(65535.0f);
    const __m256 c[4] = {_mm256_shuffle_ps(t0, t2, 0x44), _mm256_shuffle_ps(t0, t2, 0xee),
                         _mm256_shuffle_ps(t1, t3, 0x44), _mm256_shuffle_ps(t1, t3, 0xee)};
    #pragma GCC unroll 4
    for (int k = 0; k < 4; ++k)
        ch[k] = _mm256_round_ps(_mm256_mul_ps(c[k], scale), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}

// clamp_or_low(x, lo, hi) of eight lanes: NaN to lo, as there.
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256 clamp_or_low8(__m256 x, __m256 lo, __m256 hi) {
    const __m256 below_hi = _mm256_blendv_ps(hi, x, _mm256_cmp_ps(x, hi, _CMP_LT_OQ));
    return _mm256_blendv_ps(lo, below_hi, _mm256_cmp_ps(x, lo, _CMP_GT_OQ));
}

// weight8_lanes() of eight lanes.
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256i weight8x8(__m256 a) {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 c = _mm256_blendv_ps(zero, _mm256_min_ps(a, _mm256_set1_ps(1.0f)), _mm256_cmp_ps(a, zero, _CMP_GT_OQ));
    return _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(256.0f)), _mm256_set1_ps(0.5f)));
}

// repeat_near() of eight lanes: i < 0 ? i + n : (i >= n ? i - n : i).
[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256i repeat_near8(__m256i i, __m256i n) {
    const __m256i neg = _mm256_cmpgt_epi32(_mm256_setzero_si256(), i);
    const __m256i over = _mm256_cmpgt_epi32(i, _mm256_sub_epi32(n, _mm256_set1_epi32(1)));
    return _mm256_add_epi32(i, _mm256_sub_epi32(_mm256_and_si256(neg, n), _mm256_and_si256(over, n)));
}

// LINEAR's indices and 8-bit weights on one axis for every lane, eight at a
// time: linear_axis<kWrap, true>()'s arithmetic for REPEAT and
// CLAMP_TO_EDGE (floor_int()'s clamp is kept: u may be NaN or huge under
// REPEAT), REPEAT's far lanes through repeat_index() as there. False for
// the other wraps (the lane loop's).
template <TextureWrap kWrap>
GLSLRUN_AVX2 bool linear_axis8(const float* __restrict s, const int* __restrict n, int* __restrict i0,
                               int* __restrict i1, int* __restrict w) {
    if constexpr (kWrap != TextureWrap::Repeat && kWrap != TextureWrap::ClampToEdge) {
        return false;
    } else {
        const __m256 half = _mm256_set1_ps(0.5f), zero = _mm256_setzero_ps();
        const __m256 limit = _mm256_set1_ps(kIndexLimit), low = _mm256_set1_ps(-kIndexLimit);
        const __m256i one = _mm256_set1_epi32(1);
        int far = 0;
        for (int g = 0; g < kLanes; g += 8) {
            const __m256i size_i = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(n + g));
            const __m256 size = _mm256_cvtepi32_ps(size_i);
            const __m256 x = _mm256_loadu_ps(s + g);
            __m256 u;
            if constexpr (kWrap == TextureWrap::Repeat) {
                const __m256 fl = _mm256_add_ps(_mm256_floor_ps(x), zero);
                u = _mm256_sub_ps(_mm256_mul_ps(_mm256_sub_ps(x, fl), size), half);
            } else {
                u = _mm256_sub_ps(clamp_or_low8(_mm256_mul_ps(x, size), half, _mm256_sub_ps(size, half)), half);
            }
            const __m256 fu = _mm256_add_ps(_mm256_floor_ps(clamp_or_low8(u, low, limit)), zero);
            const __m256i a0 = _mm256_cvttps_epi32(fu);
            const __m256 a = _mm256_sub_ps(u, _mm256_add_ps(_mm256_floor_ps(u), zero));
            __m256i j0 = a0, j1 = _mm256_add_epi32(a0, one);
            if constexpr (kWrap == TextureWrap::Repeat) {
                const __m256i lo_n = _mm256_sub_epi32(_mm256_setzero_si256(), size_i);
                const __m256i hi_n = _mm256_add_epi32(size_i, size_i);
                const __m256i out_lo = _mm256_cmpgt_epi32(lo_n, a0);  // a0 < -n
                const __m256i out_hi = _mm256_cmpgt_epi32(j1, _mm256_sub_epi32(hi_n, one));  // a0 + 1 >= 2n
                far |= _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(out_lo, out_hi)));
                j0 = repeat_near8(j0, size_i);
                j1 = repeat_near8(j1, size_i);
            } else {
                const __m256i last = _mm256_sub_epi32(size_i, one);
                j0 = _mm256_min_epi32(j0, last);
                j1 = _mm256_min_epi32(j1, last);
            }
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(i0 + g), j0);
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(i1 + g), j1);
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(w + g), weight8x8(a));
        }
        if constexpr (kWrap == TextureWrap::Repeat)
            if (far)  // NaN or huge coordinates: linear_axis()'s own indices
                for (int i = 0; i < kLanes; ++i) {
                    const LinearAxis axis = linear_axis<kWrap, true>(s[i], n[i]);
                    i0[i] = axis.i0;
                    i1[i] = axis.i1;
                }
        return true;
    }
}

// The bilinear sums of lanes g..g+7 (none on the border): linear_lane()'s
// products and sums, exact integers in float, so the same values in any
// order (run() rounds them, as gpu::round_blend()).
// `on_border` (null where no texel can be the border's): per corner, -1
// where the lane's texel is the border's, whose 16-bit value `border` is
// then taken instead of the one at offset 0.
GLSLRUN_AVX2 void blend16x8(const GpuLanes& l, const int (*at)[kLanes], const float (*w)[kLanes],
                            const int (*on_border)[kLanes], const float* border, int g, float (*out)[kLanes]) {
    __m256 sum[4];
    #pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
        __m256 t[4];
        load16x8(l.texels, at[k], g, t);
        if (on_border) {
            const __m256i lanes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&on_border[k][g]));
            const __m256 take = _mm256_castsi256_ps(lanes);
            #pragma GCC unroll 4
            for (int c = 0; c < 4; ++c) t[c] = _mm256_blendv_ps(t[c], _mm256_set1_ps(border[c]), take);
        }
        const __m256 weight = _mm256_loadu_ps(&w[k][g]);
        #pragma GCC unroll 4
        for (int c = 0; c < 4; ++c)
            sum[c] = k == 0 ? _mm256_mul_ps(t[c], weight) : _mm256_add_ps(sum[c], _mm256_mul_ps(t[c], weight));
    }
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) _mm256_storeu_ps(&out[c][g], sum[c]);
}
// NEAREST's texels of lanes g..g+7 (at[0]; border lanes as blend16x8()'s)
// as 16-bit values (gpu::unorm16() of the texel, as load16x8() gives it)
// times each lane's share.
GLSLRUN_AVX2 void nearest16x8(const GpuLanes& l, const int (*at)[kLanes], const int (*on_border)[kLanes],
                              const float* border, const int* share, int g, float (*out)[kLanes]) {
    __m256 t[4];
    load16x8(l.texels, at[0], g, t);
    const __m256i lanes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&on_border[0][g]));
    const __m256 take = _mm256_castsi256_ps(lanes);
    const __m256 weight = _mm256_cvtepi32_ps(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(share + g)));
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c)
        _mm256_storeu_ps(&out[c][g], _mm256_mul_ps(_mm256_blendv_ps(t[c], _mm256_set1_ps(border[c]), take), weight));
}

// store_unorm16() eight lanes at a time.
GLSLRUN_AVX2 void store_unorm16x8(const float* v, const int* active, float* out) {
    const __m256 scale = _mm256_set1_ps(65535.0f);
    for (int i = 0; i < kLanes; i += 8) {
        const __m256 take = _mm256_castsi256_ps(_mm256_cmpgt_epi32(
            _mm256_load_si256(reinterpret_cast<const __m256i*>(active + i)), _mm256_setzero_si256()));
        const __m256 r = _mm256_div_ps(_mm256_load_ps(v + i), scale);
        _mm256_storeu_ps(out + i, _mm256_blendv_ps(_mm256_loadu_ps(out + i), r, take));
    }
}
#undef GLSLRUN_AVX2
#endif

// One axis's indices for every lane (axis_lanes()), eight lanes at a time
// for LINEAR under REPEAT and CLAMP_TO_EDGE in the AVX2 build.
template <bool kAvx2>
void axis(TextureWrap wrap, bool linear, const float* s, const int* n, int* i0, int* i1, int* w) {
    with_wrap(wrap, [&]<TextureWrap kWrap>() {
#if defined(__x86_64__) && defined(__GNUC__)
        if constexpr (kAvx2)
            if (linear && linear_axis8<kWrap>(s, n, i0, i1, w)) return;
#endif
        axis_lanes<kWrap, kAvx2>(linear, s, n, i0, i1, w);
    });
}

// Every lane's image is `image`.
void one_image(const TextureImage& image, GpuLanes& l) {
    for (int i = 0; i < kLanes; ++i) {
        l.texels[i] = image.texels.data();
        l.width[i] = image.width;
        l.height[i] = image.height;
    }
}

// Each lane's image for a level pass: level[i] of its face (a skipped lane
// its first level, which exists). Usually every lane has one.
void lane_images(const Texture& texture, GpuLanes& l, const int* level, const int* take) {
    alignas(32) int lane_level[kLanes];
    int differ = 0;
    for (int i = 0; i < kLanes; ++i) {
        lane_level[i] = take[i] ? level[i] : l.level[0][i];
        differ |= (lane_level[i] ^ lane_level[0]) | (l.face[i] ^ l.face[0]);
    }
    if (!differ) return one_image(texture.levels(l.face[0])[size_t(lane_level[0])], l);
    for (int i = 0; i < kLanes; ++i) {
        const TextureImage& image = texture.levels(l.face[i])[size_t(lane_level[i])];
        l.texels[i] = image.texels.data();
        l.width[i] = image.width;
        l.height[i] = image.height;
    }
}

// gpu::level_sum() of every lane in `take` on its image (l.texels, set by
// lane_images() or one_image()) with its weight share[i], not yet rounded,
// into out[c][i]; `linear`
// is the same for all of them (the caller splits). Eight lanes at a time
// where the build has AVX2, else lane by lane; skipped lanes of a group
// fetch too (their indices are in their images) and are written.
template <bool kAvx2>
void sample_level(const Texture& texture, GpuLanes& l, const BatchLookup& lk, const int* take, const int* share,
                  bool linear, int dims, float (*out)[kLanes]) {
    const bool cube = texture.target() == TextureTarget::Cube;
    const SamplerState& st = texture.sampler;
    axis<kAvx2>(st.wrap_s, linear, cube ? l.s : lk.coord[0], l.width, l.x0, l.x1, l.wx);
    if (dims > 1) {
        axis<kAvx2>(st.wrap_t, linear, cube ? l.t : lk.coord[1], l.height, l.y0, l.y1, l.wy);
    } else {
        for (int i = 0; i < kLanes; ++i) l.y0[i] = l.y1[i] = l.wy[i] = 0;
    }
    const Lookup proto{&texture, &st, 0, dims, glm::vec3(0.0f), false, 0.0f};
    const Texel border = gpu::unorm16(texel_of(border_texel(proto)));
    const bool border_free = !may_border(st.wrap_s) && (dims == 1 || !may_border(st.wrap_t));
    const glm::vec4 border16 = vec_of(border);
#if defined(__x86_64__) && defined(__GNUC__)
    if constexpr (kAvx2) {
        if (!linear) {
            alignas(32) int at[1][kLanes], on_border[1][kLanes];
            for (int i = 0; i < kLanes; ++i) {
                const int x = l.x0[i], y = l.y0[i], outside = (x | y) >> 31;  // -1 for kBorder
                on_border[0][i] = outside;
                at[0][i] = (y * l.width[i] + x) & ~outside;
            }
            for (int g = 0; g < kLanes; g += 8) {
                int any = 0;
                for (int i = g; i < g + 8; ++i) any |= take[i];
                if (any) nearest16x8(l, at, on_border, &border16.x, share, g, out);
            }
            return;
        }
        {
            alignas(32) int at[4][kLanes], on_border[4][kLanes];
            alignas(32) float w[4][kLanes];
            for (int i = 0; i < kLanes; ++i) {
                // kBorder indices (the only negative ones) read offset 0 and take the border's
                // value (blend16x8()); i >> 31 is -1 for them, 0 for the others.
                const int x0 = l.x0[i], x1 = l.x1[i], y0 = l.y0[i], y1 = l.y1[i], width = l.width[i];
                const int b00 = (x0 | y0) >> 31, b01 = (x1 | y0) >> 31, b10 = (x0 | y1) >> 31, b11 = (x1 | y1) >> 31;
                on_border[0][i] = b00;
                on_border[1][i] = b01;
                on_border[2][i] = b10;
                on_border[3][i] = b11;
                at[0][i] = (y0 * width + x0) & ~b00;  // below 2^28: no overflow
                at[1][i] = (y0 * width + x1) & ~b01;
                at[2][i] = (y1 * width + x0) & ~b10;
                at[3][i] = (y1 * width + x1) & ~b11;
                const gpu::TexelWeights k = gpu::level_weights(l.wx[i], l.wy[i], share[i]);
                w[0][i] = float(k.w00);
                w[1][i] = float(k.w01);
                w[2][i] = float(k.w10);
                w[3][i] = float(k.w11);
            }
            static_assert(kLanes % 8 == 0, "the blends take lanes 8 at a time");
            for (int g = 0; g < kLanes; g += 8) {
                int any = 0;
                for (int i = g; i < g + 8; ++i) any |= take[i];
                // Skipped lanes blend too, on indices in their images, and are not kept.
                if (any) blend16x8(l, at, w, border_free ? nullptr : on_border, &border16.x, g, out);
            }
            return;
        }
    }
#endif
    for (int i = 0; i < kLanes; ++i) {
        if (!take[i]) continue;
        put(out, i,
            linear ? linear_lane(l, i, share[i], border)
                   : gpu::scaled(texel16(l.texels[i], l.width[i], l.x0[i], l.y0[i], border), float(share[i])));
    }
}

// The level pass of `level` for the lanes of `take`, split by filter where
// the lanes differ (magnified and minified lanes of one batch).
template <bool kAvx2>
void sample_levels(const Texture& texture, GpuLanes& l, const BatchLookup& lk, const int* level, const int* take,
                   const int* share, int dims, float (*out)[kLanes]) {
    alignas(32) int by_filter[2][kLanes];
    int any[2] = {0, 0};
    for (int i = 0; i < kLanes; ++i) {
        by_filter[1][i] = take[i] & l.linear[i];
        by_filter[0][i] = take[i] & (l.linear[i] ^ 1);
        any[1] |= by_filter[1][i];
        any[0] |= by_filter[0][i];
    }
    lane_images(texture, l, level, take);
    if (!(any[0] & any[1])) return sample_level<kAvx2>(texture, l, lk, take, share, any[1] != 0, dims, out);
    // Both filters: each pass writes whole groups of lanes, so the second goes
    // to its own arrays and its lanes are merged.
    alignas(32) float nearest[4][kLanes];
    sample_level<kAvx2>(texture, l, lk, by_filter[1], share, true, dims, out);
    sample_level<kAvx2>(texture, l, lk, by_filter[0], share, false, dims, nearest);
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) out[c][i] = by_filter[0][i] ? nearest[c][i] : out[c][i];
}

// out[i] = v[i] / 65535 (gpu::over_unorm16()) for the active lanes, four
// divisions at once (one at a time, they were a fifth of a lookup: perf).
[[gnu::always_inline]] inline void store_unorm16(const float* v, const int* active, float* out) {
#if defined(__SSE2__)
    const __m128 scale = _mm_set1_ps(65535.0f);
    for (int i = 0; i < kLanes; i += 4) {
        const __m128 take = _mm_castsi128_ps(
            _mm_cmpgt_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(active + i)), _mm_setzero_si128()));
        const __m128 r = _mm_div_ps(_mm_load_ps(v + i), scale);
        _mm_storeu_ps(out + i, _mm_or_ps(_mm_and_ps(take, r), _mm_andnot_ps(take, _mm_loadu_ps(out + i))));
    }
#else
    for (int i = 0; i < kLanes; ++i) out[i] = active[i] ? v[i] / 65535.0f : out[i];
#endif
}

// gpu::round_blend() of each lane's sum in place: first + second where
// `second` (else null) has the lane's second level. The sums are integers
// below 2^24 in float, exact; a skipped lane's may be anything, and any
// float gives some value here that is not kept.
[[gnu::always_inline]] inline void round_sums(float (*first)[kLanes], const float (*second)[kLanes], const int* two) {
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) {
            const float sum = second && two[i] ? first[c][i] + second[c][i] : first[c][i];
            first[c][i] = floor_f((sum + 128.0f) * (1.0f / 256.0f));
        }
}

// make_lookup()'s face and cube_coord() for every lane; eight lanes at a
// time in the AVX2 build, where GCC leaves the lane loop scalar (Fast's
// cube_refract frame: 0.59x -> 0.70x Precise's speed), the same bits.
template <bool kAvx2>
[[gnu::always_inline]] inline void cube_lanes(const BatchLookup& lk, GpuLanes& l) {
#if defined(__x86_64__) && defined(__GNUC__)
    if constexpr (kAvx2) return cube_coords8(lk, l.face, l.s, l.t);
#endif
    for (int i = 0; i < kLanes; ++i) {
        const glm::vec3 r(lk.coord[0][i], lk.coord[1][i], lk.coord[2][i]);
        const int face = cube_face(r);
        const glm::vec3 st = cube_coord(kCubeFaces[face], r);
        l.face[i] = face;
        l.s[i] = st.x;
        l.t[i] = st.y;
    }
}

template <bool kAvx2>
[[gnu::always_inline]] inline void run(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                       float (*out)[kLanes]) {
    GpuLanes l;
    alignas(32) int active[kLanes], second[kLanes];
    for (int base = 0; base < kLanes; base += 32) {  // bit tests against a table: the loop vectorises
        const uint32_t bits = uint32_t(lanes >> base);
        for (int i = 0; i < std::min(32, kLanes - base); ++i) active[base + i] = (bits & kLaneBit[size_t(i)]) != 0;
    }
    if (texture.target() == TextureTarget::Cube) {
        cube_lanes<kAvx2>(lk, l);
    } else {
        for (int i = 0; i < kLanes; ++i) l.face[i] = 0;
    }
    const int dims = texture_dims(texture.target());
    const SamplerState& st = texture.sampler;
    if (!lod_matters(st) && texture.target() != TextureTarget::Cube) {
        // One image and one filter whatever lambda is (gpu::filter16()'s
        // magnified and unmipmapped branches sample level_base alike).
        one_image(texture.levels(0)[size_t(st.base_level)], l);
        for (int i = 0; i < kLanes; ++i) l.share[0][i] = 256;
        sample_level<kAvx2>(texture, l, lk, active, l.share[0], linear_within_level(st.min_filter), dims, l.first);
        round_sums(l.first, nullptr, nullptr);
    } else {
        if (lod_matters(st)) {
            lambdas(texture, lk, l);
            choose_levels<kAvx2>(texture, l);
        } else {
            const int linear = linear_within_level(st.min_filter);
            for (int i = 0; i < kLanes; ++i) {
                l.level[0][i] = st.base_level;
                l.level[1][i] = -1;
                l.linear[i] = linear;
            }
        }
        int two = 0;
        for (int i = 0; i < kLanes; ++i) {
            second[i] = active[i] & int(l.level[1][i] >= 0);
            two |= second[i];
            // gpu::filter16()'s shares: 256 - w and w of a mipmap blend, else all.
            l.share[0][i] = second[i] ? 256 - l.mip_weight[i] : 256;
            l.share[1][i] = second[i] ? l.mip_weight[i] : 0;
        }
        sample_levels<kAvx2>(texture, l, lk, l.level[0], active, l.share[0], dims, l.first);
        if (two) sample_levels<kAvx2>(texture, l, lk, l.level[1], second, l.share[1], dims, l.second);
        round_sums(l.first, two ? l.second : nullptr, second);
    }
    // gpu::over_unorm16(); the results are finite, canonical_nan() keeps them.
#if defined(__x86_64__) && defined(__GNUC__)
    if constexpr (kAvx2) {
        for (int c = 0; c < 4; ++c) store_unorm16x8(l.first[c], active, out[c]);
        return;
    }
#endif
    for (int c = 0; c < 4; ++c) store_unorm16(l.first[c], active, out[c]);
}

void run_baseline(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    run<false>(texture, lk, lanes, out);
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same code compiled for AVX2 (no FMA: the same bits).
__attribute__((target("avx2"), flatten)) void run_avx2(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                                       float (*out)[kLanes]) {
    run<true>(texture, lk, lanes, out);
}
#endif

}  // namespace

void gpu_cube_lambdas(const Texture& texture, const BatchLookup& lk, float* lambda) {
    // On the face each lane's direction selects: rho_of() lane by lane,
    // with its quad's first lane's derivatives.
    for (int i = 0; i < kLanes; ++i) {
        const int q = i & ~3;
        const glm::vec3 coord(lk.coord[0][i], lk.coord[1][i], lk.coord[2][i]);
        const glm::vec3 dx(lk.ddx[0][q], lk.ddx[1][q], lk.ddx[2][q]);
        const glm::vec3 dy(lk.ddy[0][q], lk.ddy[1][q], lk.ddy[2][q]);
        lambda[i] = gpu::lambda_of_rho(rho_of(texture, coord, dx, dy, true));
    }
}

bool gpu_batch_samples(const Texture& texture) {
    const TextureTarget target = texture.target();
    return gpu::filtered(texture) &&
           (target == TextureTarget::Tex1D || target == TextureTarget::Tex2D || target == TextureTarget::Cube);
}

void sample_gpu_batch(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes],
                      bool avx2) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (avx2) return run_avx2(texture, lookup, lanes, out);
#endif
    (void)avx2;
    run_baseline(texture, lookup, lanes, out);
}

}  // namespace glslrun::rt
