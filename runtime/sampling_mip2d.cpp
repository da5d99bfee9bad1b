// The mipmapped 2D kernels of sampling_mip2d.h.
// - lambda of every lane as lambdas() (sampling_batch.cpp) computes it: rho
//   from the derivatives in registers (glm::length()'s products, sum and
//   sqrt, the larger of the two as std::max picks it), lod_from_rho()'s
//   double log2 in registers (sampling_lod8.h), once per quad where the
//   quad's lanes share rho (read from each quad's first lane where the
//   lookup says they do), then the biases and clamp_lambda()'s selects;
// - per group of eight lanes, each lane's levels and weight from
//   choose_level() (sampling_levels.h), then one pass per first level the
//   group's lanes hold (one for a smooth surface: a quad's lanes share
//   their derivatives), each level's lookup by sampling_direct8.h's steps
//   with the sizes hoisted, the second level's where a lane has one, mixed
//   by filter()'s mix(); LINEAR footprints that stay in the image blended
//   lane by lane (blend_rows8(): fewer shuffles than transposing each row).
// Before this, the lookups went through the batched sampler's lane arrays
// step by step (coordinates, lambda, levels, indices, corners, blends).
#include "runtime/sampling_mip2d.h"

#include <cstring>

#include "runtime/sampling_direct8.h"
#include "runtime/sampling_levels.h"
#include "runtime/sampling_lod8.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

[[gnu::always_inline]] GLSLRUN_AVX2 inline V load8(const float* p) { return _mm256_loadu_ps(p); }

// |(du, dv, 0)| of eight lanes: scaled_length()'s for 2D (u = s * width,
// v = t * height; the third product is +0, which adds nothing to a sum of squares).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V length8(V ds, V dt, V w, V h) {
    const V u = _mm256_mul_ps(ds, w), v = _mm256_mul_ps(dt, h);
    return _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(u, u), _mm256_mul_ps(v, v)));
}

// The quads' lambda_base, lanes q..q+7 of `quad` for quads q..q+7 (each
// quad's first lane, lanes 4q..4q+31), lod_from_rho8() of rho: the same
// function of the same rho as each of the quad's lanes would take.
GLSLRUN_AVX2 void quad_lods(const float* const* ddx, const float* const* ddy, V w, V h, float* quad) {
    const I first = _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28);
    for (int q = 0; q < kLanes / 4; q += 8) {
        const V lx = length8(_mm256_i32gather_ps(ddx[0] + 4 * q, first, 4), _mm256_i32gather_ps(ddx[1] + 4 * q, first, 4), w, h);
        const V ly = length8(_mm256_i32gather_ps(ddy[0] + 4 * q, first, 4), _mm256_i32gather_ps(ddy[1] + 4 * q, first, 4), w, h);
        _mm256_store_ps(quad + q, lod_from_rho8(_mm256_blendv_ps(lx, ly, _mm256_cmp_ps(lx, ly, _CMP_LT_OQ))));
    }
}

// Every lane's lambda_base, lod_from_rho() of its rho (glm::length()'s
// products, sum and sqrt, the larger of the two as std::max picks it).
// Where each quad's four lanes have one rho (the tex kernel gives a quad
// its first lane's derivatives: Precise's one LOD per quad), the log2 runs
// once per quad: read from the first lanes alone where the lookup says so
// (BatchLookup::quad_derivatives: the tex kernel then makes no copy of
// them), else where every quad's rho bits agree.
GLSLRUN_AVX2 void lambda_bases(const BatchLookup& lk, V w, V h, float* lambda) {
    static_assert(kLanes % 32 == 0);
    alignas(32) float quad[kLanes / 4];
    if (lk.quad_derivatives) {
        quad_lods(lk.ddx, lk.ddy, w, h, quad);
    } else {
        alignas(32) float rho[kLanes];
        for (int g = 0; g < kLanes; g += 8) {
            const V lx = length8(load8(lk.ddx[0] + g), load8(lk.ddx[1] + g), w, h);
            const V ly = length8(load8(lk.ddy[0] + g), load8(lk.ddy[1] + g), w, h);
            _mm256_store_ps(rho + g, _mm256_blendv_ps(lx, ly, _mm256_cmp_ps(lx, ly, _CMP_LT_OQ)));  // std::max(lx, ly)
        }
        alignas(32) uint32_t bits[kLanes];
        std::memcpy(bits, rho, sizeof bits);
        uint32_t differ = 0;
        for (int i = 0; i < kLanes; ++i) differ |= bits[i] ^ bits[i & ~3];
        if (differ) {
            for (int g = 0; g < kLanes; g += 8) _mm256_store_ps(lambda + g, lod_from_rho8(_mm256_load_ps(rho + g)));
            return;
        }
        const I first = _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28);
        for (int q = 0; q < kLanes / 4; q += 8)
            _mm256_store_ps(quad + q, lod_from_rho8(_mm256_i32gather_ps(rho + 4 * q, first, 4)));
    }
    for (int g = 0; g < kLanes; g += 8) {  // quads g/4 and g/4 + 1
        const V q = _mm256_load_ps(quad + (g / 32) * 8);
        const int k = (g % 32) / 4;
        _mm256_store_ps(lambda + g, _mm256_permutevar8x32_ps(q, _mm256_setr_epi32(k, k, k, k, k + 1, k + 1, k + 1, k + 1)));
    }
}

// Every lane's lambda, clamped: clamp_lambda(lambda_base + bias +
// TEXTURE_LOD_BIAS); w and h are level_base's sizes. The lanes of `lanes`
// skipped compute too, on whatever their operands hold (every step is safe
// for any float).
GLSLRUN_AVX2 void lambdas(const BatchLookup& lk, const SamplerState& st, V w, V h, float* lambda) {
    if (lk.implicit) lambda_bases(lk, w, h, lambda);
    const V bias = splat(st.lod_bias);
    for (int g = 0; g < kLanes; g += 8) {
        V x = _mm256_setzero_ps();
        if (lk.implicit) {
            x = _mm256_load_ps(lambda + g);
            if (lk.bias) x = _mm256_add_ps(x, load8(lk.lod + g));
        } else if (lk.lod) {
            x = load8(lk.lod + g);
        }
        _mm256_store_ps(lambda + g, clamp_lambda8(_mm256_add_ps(x, bias), st));
    }
}

// One level's lookups of lanes g..g+7 at (s, t).
template <bool kLinear, Rule kS, Rule kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void level8(const TextureImage& image, const SamplerState& st, V s, V t,
                                                       V* value) {
    lookup8<kLinear, kS, kT>(source_of(image, st), {image.width, splat(float(image.width))},
                             {image.height, splat(float(image.height))}, s, t, value);
}

// choose_level() of eight lanes: the first level, all ones where a second
// one is mixed in, and its weight. *_MIPMAP_LINEAR (the usual filter) in
// registers, its selects as choose_level() makes them for a mipmap filter
// (lambda is finite: clamped); *_MIPMAP_NEAREST lane by lane (as a lane
// loop, GCC left choose_level() scalar: a tenth of the lookup, perf).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void levels8(const LevelRule& rule, const float* lambda, int* first,
                                                        int* second, float* weight) {
    if (rule.nearest_mip) {
        for (int k = 0; k < 8; ++k) {
            const LevelChoice d = choose_level(rule, lambda[k]);
            first[k] = d.d0;
            second[k] = d.d1 >= 0 ? -1 : 0;
            weight[k] = d.weight;
        }
        return;
    }
    const V l = _mm256_loadu_ps(lambda);
    const V mag = _mm256_cmp_ps(l, splat(rule.c), _CMP_LE_OQ);  // minify = !mag: a mipmap filter
    const V last = _mm256_cmp_ps(_mm256_add_ps(splat(float(rule.base)), l), splat(float(rule.q)), _CMP_GE_OQ);
    const V whole = floor8(l);
    const I linear_level = _mm256_blendv_epi8(_mm256_add_epi32(splat_i(rule.base), _mm256_cvttps_epi32(whole)),
                                              splat_i(rule.q), _mm256_castps_si256(last));
    const I d0 = _mm256_blendv_epi8(linear_level, splat_i(rule.base), _mm256_castps_si256(mag));
    const V two = _mm256_andnot_ps(_mm256_or_ps(mag, last), _mm256_castsi256_ps(splat_i(-1)));
    _mm256_store_si256(reinterpret_cast<I*>(first), d0);
    _mm256_store_ps(reinterpret_cast<float*>(second), two);
    _mm256_store_ps(weight, _mm256_and_ps(two, _mm256_sub_ps(l, whole)));  // else +0
}

// LINEAR's two rows of one level for lanes g..g+7 at (s, t), and the weights.
template <Rule kS, Rule kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void linear_rows(const TextureImage& image, V s, V t, Row8* rows, V& ax,
                                                            V& ay) {
    const Linear8 x = linear8<kS>(s, {image.width, splat(float(image.width))});
    const Linear8 y = linear8<kT>(t, {image.height, splat(float(image.height))});
    row_of(image.texels.data(), image.width, x, y.i0, rows[0]);
    row_of(image.texels.data(), image.width, x, y.i1, rows[1]);
    ax = x.a;
    ay = y.a;
}

template <bool kLinear, Rule kS, Rule kT>
GLSLRUN_AVX2 void mip2d(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    const std::vector<TextureImage>& levels = texture.levels(0);
    const LevelRule rule(texture);
    const bool finite = texture.format() == TextureFormat::RGBA8;  // k/255: no NaN to canonicalise
    const TextureImage& base = levels[size_t(rule.base)];
    const V w = splat(float(base.width)), h = splat(float(base.height));
    alignas(32) float lambda[kLanes];
    lambdas(lk, st, w, h, lambda);
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        alignas(32) float weight[8];
        alignas(32) int first_level[8], second[8];
        levels8(rule, lambda + g, first_level, second, weight);
        const I d0 = _mm256_load_si256(reinterpret_cast<const I*>(first_level));
        const int two = _mm256_movemask_ps(_mm256_load_ps(reinterpret_cast<const float*>(second)));
        const V s = load8(lk.coord[0] + g), t = load8(lk.coord[1] + g);
        for (int left = bits; left;) {
            const int level = first_level[std::countr_zero(unsigned(left))];
            const int take = left & _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(d0, splat_i(level))));
            left &= ~take;
            V value[4];
            if constexpr (kLinear && !may_border(kS, true) && !may_border(kT, true)) {
                // Every texel in the image: the lane-by-lane blends (blend_rows8()).
                Row8 rows[4];
                V ax[2], ay[2];
                linear_rows<kS, kT>(levels[size_t(level)], s, t, rows, ax[0], ay[0]);
                if (two & take) {  // their second level is level + 1, which exists: level < q
                    linear_rows<kS, kT>(levels[size_t(level) + 1], s, t, rows + 2, ax[1], ay[1]);
                    blend_rows8<2>(rows, ax, ay, _mm256_load_ps(weight),
                                   _mm256_load_ps(reinterpret_cast<const float*>(second)), value);
                } else {
                    blend_rows8<1>(rows, ax, ay, ax[0], ax[0], value);
                }
                store_lookup8<kLinear, kS, kT>(finite, value, take, g, out);
                continue;
            }
            level8<kLinear, kS, kT>(levels[size_t(level)], st, s, t, value);
            if (two & take) {  // their second level is level + 1, which exists: level < q
                V next[4];
                level8<kLinear, kS, kT>(levels[size_t(level) + 1], st, s, t, next);
                const V wt = _mm256_load_ps(weight), iw = _mm256_sub_ps(splat(1.0f), wt);
                const V mixed = _mm256_load_ps(reinterpret_cast<const float*>(second));
#pragma GCC unroll 4
                for (int c = 0; c < 4; ++c) value[c] = _mm256_blendv_ps(value[c], mix8(value[c], next[c], wt, iw), mixed);
            }
            store_lookup8<kLinear, kS, kT>(finite, value, take, g, out);
        }
    }
}

}  // namespace

bool mip2d_samples(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    return texture.target() == TextureTarget::Tex2D && !texture.depth() && is_mipmap_filter(st.min_filter) &&
           linear_within_level(st.mag_filter) == linear_within_level(st.min_filter);
}

GLSLRUN_AVX2 void sample_mip2d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes,
                               float (*out)[kLanes]) {
    with_rules<false>(texture.sampler, linear_within_level(texture.sampler.mag_filter),
                      [&]<bool kLinear, Rule kS, Rule kT>() { mip2d<kLinear, kS, kT>(texture, lookup, lanes, out); });
}
#undef GLSLRUN_AVX2

#else
bool mip2d_samples(const Texture&) { return false; }
void sample_mip2d(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
#endif

}  // namespace glslrun::rt
