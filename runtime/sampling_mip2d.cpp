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

// rho of eight lanes: max(|ddx|, |ddy|) as std::max picks it, taken on the
// squares: sqrt is monotonic and correctly rounded, so the larger root is
// the root of the larger square (a NaN picks as before: |ddx| where either is NaN).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V square8(V u, V v) {
    return _mm256_add_ps(_mm256_mul_ps(u, u), _mm256_mul_ps(v, v));
}
[[gnu::always_inline]] GLSLRUN_AVX2 inline V rho8(V xs, V xt, V ys, V yt, V w, V h) {
    const V lx = square8(_mm256_mul_ps(xs, w), _mm256_mul_ps(xt, h));
    const V ly = square8(_mm256_mul_ps(ys, w), _mm256_mul_ps(yt, h));
    return _mm256_sqrt_ps(_mm256_blendv_ps(lx, ly, _mm256_cmp_ps(lx, ly, _CMP_LT_OQ)));
}

// Every lane's lambda_base, lod_from_rho() of its rho. Where each quad's
// four lanes have one rho (the tex kernel gives a quad its first lane's
// derivatives: Precise's one LOD per quad), the log2 runs once per quad:
// read from the first lanes alone where the lookup says so
// (BatchLookup::quad_derivatives: the tex kernel then makes no copy of
// them), else where every quad's rho bits agree.
GLSLRUN_AVX2 void lambda_bases(const BatchLookup& lk, V w, V h, float* lambda) {
    if constexpr (kLanes % 32 != 0) {  // 8 or 16 lanes: each lane's log2 (the same bits as its quad's)
        for (int g = 0; g < kLanes; g += 8) {
            const V rho = lk.quad_derivatives
                              ? rho8(group_leaders8(lk.ddx[0] + g), group_leaders8(lk.ddx[1] + g),
                                     group_leaders8(lk.ddy[0] + g), group_leaders8(lk.ddy[1] + g), w, h)
                              : rho8(load8(lk.ddx[0] + g), load8(lk.ddx[1] + g), load8(lk.ddy[0] + g),
                                     load8(lk.ddy[1] + g), w, h);
            _mm256_store_ps(lambda + g, lod_from_rho8(rho));
        }
        return;
    }
    alignas(32) float quad[kLanes / 4];  // quad_leaders8()'s order in each eight
    if (lk.quad_derivatives) {
        for (int g = 0; g < kLanes; g += 32)
            _mm256_store_ps(quad + g / 4, lod_from_rho8(rho8(quad_leaders8(lk.ddx[0] + g), quad_leaders8(lk.ddx[1] + g),
                                                             quad_leaders8(lk.ddy[0] + g), quad_leaders8(lk.ddy[1] + g), w, h)));
    } else {
        alignas(32) float rho[kLanes];
        for (int g = 0; g < kLanes; g += 8)
            _mm256_store_ps(rho + g, rho8(load8(lk.ddx[0] + g), load8(lk.ddx[1] + g), load8(lk.ddy[0] + g),
                                          load8(lk.ddy[1] + g), w, h));
        alignas(32) uint32_t bits[kLanes];
        std::memcpy(bits, rho, sizeof bits);
        uint32_t differ = 0;
        for (int i = 0; i < kLanes; ++i) differ |= bits[i] ^ bits[i & ~3];
        if (differ) {
            for (int g = 0; g < kLanes; g += 8) _mm256_store_ps(lambda + g, lod_from_rho8(_mm256_load_ps(rho + g)));
            return;
        }
        for (int g = 0; g < kLanes; g += 32) _mm256_store_ps(quad + g / 4, lod_from_rho8(quad_leaders8(rho + g)));
    }
    for (int g = 0; g < kLanes; g += 8) {  // quads g/4 and g/4 + 1: at k and 4 + k of their eight
        _mm256_store_ps(lambda + g, spread_quads8(_mm256_load_ps(quad + (g / 32) * 8), (g % 32) / 8));
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

// LINEAR's two rows of one level for lanes g..g+7 at (s, t), and the
// weights; true where every lane's x1 is x0 + 1 (no edge clamp or REPEAT
// wrap between its two columns: blend_pairs8() may read them as one pair).
template <Rule kS, Rule kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline bool linear_rows(const TextureImage& image, V s, V t, Row8* rows, V& ax,
                                                            V& ay) {
    const Linear8 x = linear8<kS>(s, {image.width, splat(float(image.width))});
    const Linear8 y = linear8<kT>(t, {image.height, splat(float(image.height))});
    row_of(image.texels.data(), image.width, x, y.i0, rows[0]);
    row_of(image.texels.data(), image.width, x, y.i1, rows[1]);
    ax = x.a;
    ay = y.a;
    const I next = _mm256_cmpeq_epi32(x.i1, _mm256_add_epi32(x.i0, splat_i(1)));
    return _mm256_movemask_ps(_mm256_castsi256_ps(next)) == 0xff;
}

// Lane j's and lane j + 4's texels (x0, y) into `left` and (x0 + 1, y) into
// `right`, as texel_pair() of x0 and x1 would give them where x1 is x0 + 1:
// each lane's two texels are one 32-byte load (texel x0 + 1 is in the row).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void texel_pairs(const Row8& row, int j, V& left, V& right) {
    const V a = _mm256_loadu_ps(reinterpret_cast<const float*>(row.base + row.x0[j]));
    const V b = _mm256_loadu_ps(reinterpret_cast<const float*>(row.base + row.x0[j + 4]));
    left = _mm256_permute2f128_ps(a, b, 0x20);
    right = _mm256_permute2f128_ps(a, b, 0x31);
}

// blend_rows8<kPlanes>() where linear_rows() said every row's columns are
// neighbours: the same products and sums from half the loads and offsets
// (perf: the texel loads' offsets and inserts were the kernel's hottest
// instructions).
template <int kPlanes>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void blend_pairs8(const Row8* rows, const V* ax, const V* ay, V az, V mixed,
                                                             V* value) {
    V lanes[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) {
        V plane[kPlanes];
#pragma GCC unroll 2
        for (int p = 0; p < kPlanes; ++p) {
            const V a = splat_pair(ax[p], j);
            V l0, r0, l1, r1;
            texel_pairs(rows[2 * p], j, l0, r0);
            texel_pairs(rows[2 * p + 1], j, l1, r1);
            plane[p] = lerp_pair(lerp_pair(l0, r0, a), lerp_pair(l1, r1, a), splat_pair(ay[p], j));
        }
        if constexpr (kPlanes == 1) lanes[j] = plane[0];
        else lanes[j] = _mm256_blendv_ps(plane[0], lerp_pair(plane[0], plane[1], splat_pair(az, j)), splat_pair(mixed, j));
    }
    transpose8(lanes, value);
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
                const bool pairs = linear_rows<kS, kT>(levels[size_t(level)], s, t, rows, ax[0], ay[0]);
                if (two & take) {  // their second level is level + 1, which exists: level < q
                    const bool next_pairs = linear_rows<kS, kT>(levels[size_t(level) + 1], s, t, rows + 2, ax[1], ay[1]);
                    const V wt = _mm256_load_ps(weight), mixed = _mm256_load_ps(reinterpret_cast<const float*>(second));
                    if (pairs && next_pairs) blend_pairs8<2>(rows, ax, ay, wt, mixed, value);
                    else blend_rows8<2>(rows, ax, ay, wt, mixed, value);
                } else if (pairs) {
                    blend_pairs8<1>(rows, ax, ay, ax[0], ax[0], value);
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
