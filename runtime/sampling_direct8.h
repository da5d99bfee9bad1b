// The eight-lane steps of one colour lookup in one image, AVX2 intrinsics
// from the coordinates to the result in registers: each axis's rule (the
// wrap mode as NEAREST or LINEAR reads it, normalized or a rectangle's
// texels), the indices, the texel loads and the bilinear blend. Shared by
// the one-image kernels (sampling_direct.cpp) and the mipmapped 2D ones
// (sampling_mip2d.cpp), which run them once per level. The index
// arithmetic is sampling_rules.h's written with intrinsics, operation for
// operation:
//   clamp_or_low(x, lo, hi)  = min(max(x, lo), hi)  (maxps returns lo for NaN)
//   floor_t<true>(x)         = roundps(x, down) + 0
//   floor_int<true>(x)       = cvttps(floor of clamp_or_low(x, -2^24, 2^24))
// REPEAT's far lanes (NaN or huge coordinates) take repeat_index() lane by
// lane, as the other samplers do.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__)
#include <limits>

#include "runtime/sampling_avx2.h"
#include "runtime/sampling_batch.h"
#include "runtime/sampling_rules.h"

namespace glslrun::rt::direct8 {

using namespace sampling;

#define GLSLRUN_AVX2 __attribute__((target("avx2")))

// How one axis turns a coordinate into texel indices: the wrap mode, for
// normalized coordinates (s * size) or a rectangle's (u in texels, where
// only the clamping rules exist: rect_nearest_index(), rect_linear_axis()).
enum class Rule : uint8_t { Repeat, Mirror, Edge, Clamp, Border, RectEdge, RectClamp, RectBorder };

constexpr bool is_rect(Rule r) { return r == Rule::RectEdge || r == Rule::RectClamp || r == Rule::RectBorder; }

// The rule of a wrap mode; a rectangle's wraps as sampling_rules.h reads them.
inline Rule rule_of(TextureWrap wrap, bool rect, bool linear) {
    using enum TextureWrap;
    if (rect) {
        if (wrap == ClampToBorder) return Rule::RectBorder;
        if (!linear || wrap == ClampToEdge) return Rule::RectEdge;  // NEAREST clamps whatever the wrap
        return wrap == Clamp ? Rule::RectClamp : Rule::RectBorder;  // REPEAT, MIRRORED_REPEAT: CLAMP_TO_BORDER's
    }
    switch (wrap) {
    case Repeat: return Rule::Repeat;
    case MirroredRepeat: return Rule::Mirror;
    case ClampToEdge: return Rule::Edge;
    case Clamp: return linear ? Rule::Clamp : Rule::Edge;  // NEAREST's CLAMP is CLAMP_TO_EDGE's
    case ClampToBorder: break;
    }
    return Rule::Border;
}

// rule_of() of a wrap that keeps every LINEAR texel in the image (REPEAT,
// MIRRORED_REPEAT, CLAMP_TO_EDGE), for template arguments.
constexpr Rule inner_rule(TextureWrap wrap) {
    return wrap == TextureWrap::Repeat ? Rule::Repeat : (wrap == TextureWrap::MirroredRepeat ? Rule::Mirror : Rule::Edge);
}

// Whether an axis's indices can be the border's (kBorder).
constexpr bool may_border(Rule r, bool linear) {
    if (r == Rule::Border || r == Rule::RectBorder) return true;
    return linear && (r == Rule::Clamp || r == Rule::RectClamp);
}

using V = __m256;
using I = __m256i;

struct Axis {
    int n;    // the image's size on the axis
    V size;   // float(n)
};

[[gnu::always_inline]] GLSLRUN_AVX2 inline V splat(float x) { return _mm256_set1_ps(x); }
[[gnu::always_inline]] GLSLRUN_AVX2 inline I splat_i(int x) { return _mm256_set1_epi32(x); }

// The first lanes of the eight quads of lanes p[0..31], in the order
// (0, 2, 4, 6, 1, 3, 5, 7): three shuffles of the four groups' registers
// (in place of four gathers a lookup).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V quad_leaders8(const float* p) {
    const V q01 = _mm256_shuffle_ps(_mm256_loadu_ps(p), _mm256_loadu_ps(p + 8), 0x00);  // (0, 0, 2, 2 | 1, 1, 3, 3)
    const V q23 = _mm256_shuffle_ps(_mm256_loadu_ps(p + 16), _mm256_loadu_ps(p + 24), 0x00);
    return _mm256_shuffle_ps(q01, q23, _MM_SHUFFLE(2, 0, 2, 0));
}

// The first lanes of p[0..7]'s two quads, each in its quad's lanes:
// (0, 0, 0, 0, 4, 4, 4, 4).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V group_leaders8(const float* p) {
    const V x = _mm256_loadu_ps(p);
    return _mm256_shuffle_ps(x, x, 0x00);
}

// Lanes 8k..8k+7 of those 32 from quad_leaders8()'s register of eight
// per-quad values: each quad's value in its four lanes.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V spread_quads8(V quads, int k) {
    return _mm256_permutevar8x32_ps(quads, _mm256_setr_epi32(k, k, k, k, k + 4, k + 4, k + 4, k + 4));
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline V clamp_or_low8(V x, V lo, V hi) {
    return _mm256_min_ps(_mm256_max_ps(x, lo), hi);
}
[[gnu::always_inline]] GLSLRUN_AVX2 inline V floor8(V x) {
    return _mm256_add_ps(_mm256_round_ps(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC), _mm256_setzero_ps());
}
[[gnu::always_inline]] GLSLRUN_AVX2 inline I floor_int8(V x) {
    const V limit = splat(kIndexLimit);
    return _mm256_cvttps_epi32(floor8(clamp_or_low8(x, _mm256_sub_ps(_mm256_setzero_ps(), limit), limit)));
}
// floor_int8() of an x known to lie within a size of the image (a clamped
// LINEAR position: never NaN), where the clamp to 2^24 changes nothing.
[[gnu::always_inline]] GLSLRUN_AVX2 inline I floor_int8_bounded(V x) { return _mm256_cvttps_epi32(floor8(x)); }

// clamp_lambda() of eight lanes, its selects in its order (as a lane loop
// its branches and isnan() kept GCC from vectorising it: perf, a third of
// the level of detail's time).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V clamp_lambda8(V lambda, const SamplerState& st) {
    const V min = splat(st.min_lod), max = splat(st.max_lod);
    V x = _mm256_blendv_ps(min, lambda, _mm256_cmp_ps(lambda, min, _CMP_GE_OQ));  // !(lambda >= min_lod): min_lod
    x = _mm256_blendv_ps(x, max, _mm256_cmp_ps(x, max, _CMP_GT_OQ));
    const V clamped = clamp_or_low8(x, splat(-kLodLimit), splat(kLodLimit));
    return _mm256_blendv_ps(clamped, _mm256_setzero_ps(), _mm256_cmp_ps(x, x, _CMP_UNORD_Q));
}

// mirror<true>(): frac(s) where floor(s) is even, 1 - frac(s) where odd
// (floors from 2^24 on, and NaN, count as even).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V mirror8(V s) {
    const V fl = floor8(s);
    const V f = _mm256_sub_ps(s, fl);
    const V abs = _mm256_andnot_ps(splat(-0.0f), fl);
    const V in_range = _mm256_and_ps(fl, _mm256_cmp_ps(abs, splat(16777216.0f), _CMP_LT_OQ));
    const I odd = _mm256_slli_epi32(_mm256_cvttps_epi32(in_range), 31);
    return _mm256_blendv_ps(f, _mm256_sub_ps(splat(1.0f), f), _mm256_castsi256_ps(odd));
}

// border_or_index(): i where 0 <= i < n, else kBorder (-1).
[[gnu::always_inline]] GLSLRUN_AVX2 inline I border_or_index8(I i, int n) {
    const I inside = _mm256_andnot_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), i), _mm256_cmpgt_epi32(splat_i(n), i));
    return _mm256_or_si256(_mm256_and_si256(inside, i), _mm256_andnot_si256(inside, splat_i(kBorder)));
}

// repeat_index() of eight raw indices: repeat_near() in registers, lane by
// lane where some index is far out (NaN or huge coordinates).
[[gnu::always_inline]] GLSLRUN_AVX2 inline I repeat8(I raw, int n) {
    const I nn = splat_i(n);
    const I below = _mm256_cmpgt_epi32(_mm256_setzero_si256(), raw);
    const I above = _mm256_cmpgt_epi32(raw, splat_i(n - 1));
    const I near = _mm256_blendv_epi8(_mm256_blendv_epi8(raw, _mm256_sub_epi32(raw, nn), above), _mm256_add_epi32(raw, nn),
                                      below);
    // repeat_is_near(): -n <= raw < 2n.
    const I far = _mm256_or_si256(_mm256_cmpgt_epi32(splat_i(-n), raw), _mm256_cmpgt_epi32(raw, splat_i(2 * n - 1)));
    if (_mm256_testz_si256(far, far)) return near;
    alignas(32) int lanes[8];
    _mm256_store_si256(reinterpret_cast<I*>(lanes), raw);
    for (int& i : lanes) i = repeat_index(i, n);
    return _mm256_load_si256(reinterpret_cast<const I*>(lanes));
}

// nearest_index<kWrap, true>() / rect_nearest_index<kWrap, true>() of eight lanes.
template <Rule kRule>
[[gnu::always_inline]] GLSLRUN_AVX2 inline I nearest8(V s, const Axis& ax) {
    if constexpr (kRule == Rule::Repeat) return repeat8(floor_int8(_mm256_mul_ps(_mm256_sub_ps(s, floor8(s)), ax.size)), ax.n);
    const V u = is_rect(kRule) ? s : _mm256_mul_ps(kRule == Rule::Mirror ? mirror8(s) : s, ax.size);
    const I i = floor_int8(u);
    if constexpr (kRule == Rule::Border || kRule == Rule::RectBorder) return border_or_index8(i, ax.n);
    return _mm256_max_epi32(_mm256_min_epi32(i, splat_i(ax.n - 1)), _mm256_setzero_si256());  // std::clamp
}

struct Linear8 {
    I i0, i1;
    V a;
};

// Whether every lane's second index on the axis is its first + 1 (not
// the edge's clamp or a wrap).
[[gnu::always_inline]] GLSLRUN_AVX2 inline bool neighbours8(const Linear8& l) {
    const I next = _mm256_cmpeq_epi32(l.i1, _mm256_add_epi32(l.i0, splat_i(1)));
    return _mm256_movemask_ps(_mm256_castsi256_ps(next)) == 0xff;
}

// linear_axis<kWrap, true>() / rect_linear_axis<kWrap, true>() of eight lanes.
template <Rule kRule>
[[gnu::always_inline]] GLSLRUN_AVX2 inline Linear8 linear8(V s, const Axis& ax) {
    const V half = splat(0.5f);
    V u;
    if constexpr (kRule == Rule::Repeat) {
        u = _mm256_sub_ps(_mm256_mul_ps(_mm256_sub_ps(s, floor8(s)), ax.size), half);  // repeat_position()
        const I i0 = floor_int8(u);
        return {repeat8(i0, ax.n), repeat8(_mm256_add_epi32(i0, splat_i(1)), ax.n), _mm256_sub_ps(u, floor8(u))};
    } else if constexpr (kRule == Rule::Mirror || kRule == Rule::Edge || kRule == Rule::RectEdge) {
        const V x = kRule == Rule::RectEdge ? s : _mm256_mul_ps(kRule == Rule::Mirror ? mirror8(s) : s, ax.size);
        u = _mm256_sub_ps(clamp_or_low8(x, half, _mm256_sub_ps(ax.size, half)), half);
        const I i0 = floor_int8_bounded(u), last = splat_i(ax.n - 1);
        // At u = size - 1/2, i1 is past the image with weight 0: kept on the last texel.
        return {_mm256_min_epi32(i0, last), _mm256_min_epi32(_mm256_add_epi32(i0, splat_i(1)), last),
                _mm256_sub_ps(u, floor8(u))};
    } else {
        if constexpr (kRule == Rule::Clamp)
            u = _mm256_sub_ps(_mm256_mul_ps(clamp_or_low8(s, _mm256_setzero_ps(), splat(1.0f)), ax.size), half);
        else if constexpr (kRule == Rule::RectClamp)
            u = _mm256_sub_ps(clamp_or_low8(s, _mm256_setzero_ps(), ax.size), half);
        else  // Border, RectBorder
            u = _mm256_sub_ps(clamp_or_low8(kRule == Rule::Border ? _mm256_mul_ps(s, ax.size) : s, splat(-0.5f),
                                            _mm256_add_ps(ax.size, half)),
                              half);
        const I i0 = floor_int8_bounded(u);
        return {border_or_index8(i0, ax.n), border_or_index8(_mm256_add_epi32(i0, splat_i(1)), ax.n),
                _mm256_sub_ps(u, floor8(u))};
    }
}

// The image and its border colour, as fetch() reads them.
struct Source {
    const glm::vec4* texels;
    int width;
    V border[4];          // border_texel(): the colour clamped to [0, 1]
    bool finite = false;  // every texel finite (RGBA8's are k/255)
};

// An image as fetch8() reads it: the border colour is border_texel()'s of a
// colour texture (clamped to [0, 1]).
[[gnu::always_inline]] GLSLRUN_AVX2 inline Source source_of(const TextureImage& image, const SamplerState& st) {
    Source src;  // each member set once: no zero fill (sampling_direct.cpp's run_chosen())
    src.texels = image.texels.data();
    src.width = image.width;
    for (int c = 0; c < 4; ++c) src.border[c] = splat(unorm(st.border_color[c]));
    return src;
}

// Each lane's byte offset of texel (x, y) (below 2^28, unsigned: each load
// takes its offset as it is, with no sign extension or scaling in between).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void offsets8(I at, uint32_t* off) {
    _mm256_store_si256(reinterpret_cast<I*>(off), _mm256_slli_epi32(at, 4));
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline I texel_index8(const Source& src, I x, I y) {
    return _mm256_add_epi32(_mm256_mullo_epi32(y, splat_i(src.width)), x);  // w * h below 2^24 (limits.md)
}

// The texels at (x, y) of eight lanes, transposed into channels: ch[c]
// holds channel c of the eight. `kBorder`: an index may be kBorder, whose
// lanes take the border colour (and load texel 0).
template <bool kBorder>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void fetch8(const Source& src, I x, I y, V* ch) {
    I at = texel_index8(src, x, y);
    I border = _mm256_setzero_si256();
    if constexpr (kBorder) {
        border = _mm256_cmpgt_epi32(_mm256_setzero_si256(), _mm256_or_si256(x, y));  // either index negative
        at = _mm256_andnot_si256(border, at);
    }
    alignas(32) uint32_t off[8];
    offsets8(at, off);
    const char* base = reinterpret_cast<const char*>(src.texels);
    const auto texel = [&](int j) { return _mm_loadu_ps(reinterpret_cast<const float*>(base + off[j])); };
    V r[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) r[j] = _mm256_insertf128_ps(_mm256_castps128_ps256(texel(j)), texel(4 + j), 1);
    transpose8(r, ch);
    if constexpr (kBorder) {
        const V b = _mm256_castsi256_ps(border);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) ch[c] = _mm256_blendv_ps(ch[c], src.border[c], b);
    }
}

// The texels at (x, y) and (x + 1, y) of eight lanes (every x + 1 in the
// row), into `left` and `right` by channel: each lane's two texels are one
// 32-byte load, half the loads of two fetch8() calls.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void fetch_pairs8(const Source& src, I x, I y, V* left, V* right) {
    alignas(32) uint32_t off[8];
    offsets8(texel_index8(src, x, y), off);
    const char* base = reinterpret_cast<const char*>(src.texels);
    V l[4], r[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) {
        const V a = _mm256_loadu_ps(reinterpret_cast<const float*>(base + off[j]));
        const V b = _mm256_loadu_ps(reinterpret_cast<const float*>(base + off[4 + j]));
        l[j] = _mm256_permute2f128_ps(a, b, 0x20);
        r[j] = _mm256_permute2f128_ps(a, b, 0x31);
    }
    transpose8(l, left);
    transpose8(r, right);
}

// mix() of eight lanes: x * (1 - a) + y * a, with ia = 1 - a.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V mix8(V x, V y, V a, V ia) {
    return _mm256_add_ps(_mm256_mul_ps(x, ia), _mm256_mul_ps(y, a));
}

// The lane-by-lane form of LINEAR's blends, for footprints whose texels
// are all in the image: each lane's texels stay four channels wide (lanes
// j and j + 4 side by side in one register, each half one load), its
// weights are splat from the lanes' registers, and the result is
// transposed into channels once. The same products and sums per channel as
// lookup8()'s: row = t(x0) (1 - a) + t(x1) a, plane = row0 (1 - b) + row1 b,
// the two planes (a 3D texture's z0 and z1, or two mipmap levels) likewise
// by c. lookup8() transposes every row's texels (fetch_pairs8(): eight
// permutes and two transposes a row), and the shuffle port bounded it
// (perf, the trilinear volume: 96 shuffles per eight lanes, now 20).
struct Row8 {
    const char* base;                   // the image's texels
    alignas(32) uint32_t x0[8], x1[8];  // byte offsets of (x0, y) and (x1, y) of each lane
};

// A row's offsets from LINEAR's x indices and the row's (y, or z * h + y) of an image `width` wide.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void row_of(const glm::vec4* texels, int width, const Linear8& x, I y,
                                                       Row8& row) {
    row.base = reinterpret_cast<const char*>(texels);
    const I start = _mm256_mullo_epi32(y, splat_i(width));  // w * h below 2^24 (limits.md)
    offsets8(_mm256_add_epi32(start, x.i0), row.x0);
    offsets8(_mm256_add_epi32(start, x.i1), row.x1);
}

// Texels at offsets off[j] and off[j + 4]: (lane j | lane j + 4).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V texel_pair(const char* base, const uint32_t* off, int j) {
    const __m128 lo = _mm_loadu_ps(reinterpret_cast<const float*>(base + off[j]));
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), _mm_loadu_ps(reinterpret_cast<const float*>(base + off[j + 4])), 1);
}

// Lane j's and lane j + 4's weights splat over their halves.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V splat_pair(V w, int j) {
    return _mm256_permutevar8x32_ps(w, _mm256_setr_epi32(j, j, j, j, j + 4, j + 4, j + 4, j + 4));
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline V lerp_pair(V x, V y, V a) {  // mix8() of splat weights
    return _mm256_add_ps(_mm256_mul_ps(x, _mm256_sub_ps(splat(1.0f), a)), _mm256_mul_ps(y, a));
}

// The bilinear planes of rows[0..1] (by ax[0], ay[0]) and, where kPlanes
// is 2, rows[2..3] (by ax[1], ay[1]) mixed by az in the lanes of `mixed`
// (all ones; the other lanes take the first plane), into value[c].
template <int kPlanes>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void blend_rows8(const Row8* rows, const V* ax, const V* ay, V az, V mixed,
                                                            V* value) {
    V lanes[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) {
        V plane[kPlanes];
#pragma GCC unroll 2
        for (int p = 0; p < kPlanes; ++p) {
            const V a = splat_pair(ax[p], j);
            const Row8& r0 = rows[2 * p];
            const Row8& r1 = rows[2 * p + 1];
            const V row0 = lerp_pair(texel_pair(r0.base, r0.x0, j), texel_pair(r0.base, r0.x1, j), a);
            const V row1 = lerp_pair(texel_pair(r1.base, r1.x0, j), texel_pair(r1.base, r1.x1, j), a);
            plane[p] = lerp_pair(row0, row1, splat_pair(ay[p], j));
        }
        if constexpr (kPlanes == 1) lanes[j] = plane[0];
        else lanes[j] = _mm256_blendv_ps(plane[0], lerp_pair(plane[0], plane[1], splat_pair(az, j)), splat_pair(mixed, j));
    }
    transpose8(lanes, value);
}

// Lanes g..g+7's channels into out[c][g..g+7] where bit k of `bits` is
// set (lane g + k), a NaN as canonical_nan()'s; the other lanes' entries
// are left as they are. kMayNaN false: the values are known not to be NaN
// (finite texels and weights), so none is replaced.
template <bool kMayNaN = true>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void store8(const V* value, int bits, int g, float (*out)[kLanes]) {
    const I bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const V nan = splat(std::numeric_limits<float>::quiet_NaN());  // canonical_nan()'s
    const V take = _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(splat_i(bits), bit), bit));
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
        V v = value[c];
        if constexpr (kMayNaN) v = _mm256_blendv_ps(v, nan, _mm256_cmp_ps(v, v, _CMP_UNORD_Q));
        if (bits == 0xff) _mm256_storeu_ps(&out[c][g], v);  // every lane: nothing to keep
        else _mm256_storeu_ps(&out[c][g], _mm256_blendv_ps(_mm256_loadu_ps(&out[c][g]), v, take));
    }
}

// Whether LINEAR's weights on an axis of this rule may be NaN: REPEAT's and
// MIRRORED_REPEAT's fraction of an infinite or NaN coordinate. The
// clamping rules clamp the position first (a NaN to the low bound).
constexpr bool weight_may_be_nan(Rule r) { return r == Rule::Repeat || r == Rule::Mirror; }

// store8() of a lookup's values, with no NaN to canonicalise where the
// texels are finite (`finite_texels`) and so are the filter's weights: a
// blend of finite values by finite weights in [0, 1] is finite.
template <bool kLinear, Rule kS, Rule kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void store_lookup8(bool finite_texels, const V* value, int bits, int g,
                                                              float (*out)[kLanes]) {
    constexpr bool kWeightsFinite = !kLinear || (!weight_may_be_nan(kS) && !weight_may_be_nan(kT));
    if (kWeightsFinite && finite_texels) store8<false>(value, bits, g, out);
    else store8(value, bits, g, out);
}

// The lookups of lanes g..g+7: `value` gets each channel's result.
template <bool kLinear, Rule kS, Rule kT>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void lookup8(const Source& src, const Axis& w, const Axis& h, V s, V t,
                                                        V* value) {
    constexpr bool kBorder = may_border(kS, kLinear) || may_border(kT, kLinear);
    if constexpr (!kLinear) {
        fetch8<kBorder>(src, nearest8<kS>(s, w), nearest8<kT>(t, h), value);
        return;
    } else {
        // sample_linear()'s blend, row by row so that the corners fit in the registers.
        const Linear8 x = linear8<kS>(s, w), y = linear8<kT>(t, h);
        const V one = splat(1.0f), ia = _mm256_sub_ps(one, x.a), ib = _mm256_sub_ps(one, y.a);
        V p[4], q[4], row0[4];
        // Where every lane's two columns are neighbours (not the edge's
        // clamp or REPEAT's wrap), each row's two texels are one load; under
        // the border's rules, where moreover no index is kBorder (the
        // footprints inside the image: a decal's or a projected slide's
        // but near their edges), whose texels fetch8() would take as they are.
        bool pairs = _mm256_movemask_ps(_mm256_castsi256_ps(
                         _mm256_cmpeq_epi32(x.i1, _mm256_add_epi32(x.i0, splat_i(1))))) == 0xff;
        if constexpr (kBorder) {  // kBorder is -1: the sign bit of any index
            const I indices = _mm256_or_si256(_mm256_or_si256(x.i0, y.i0), y.i1);
            pairs = pairs && _mm256_testz_si256(indices, splat_i(INT32_MIN));
            // Every corner of every lane the border's (both columns or both
            // rows out): fetch8() would load texel 0 and take the border
            // colour for each; the same blends of it, with no load (a
            // projected slide's surroundings).
            const I out = _mm256_or_si256(_mm256_and_si256(x.i0, x.i1), _mm256_and_si256(y.i0, y.i1));
            if (_mm256_movemask_ps(_mm256_castsi256_ps(out)) == 0xff) {
#pragma GCC unroll 4
                for (int c = 0; c < 4; ++c) {
                    const V row = mix8(src.border[c], src.border[c], x.a, ia);
                    value[c] = mix8(row, row, y.a, ib);
                }
                return;
            }
        }
        if (pairs) fetch_pairs8(src, x.i0, y.i0, p, q);
        else {
            fetch8<kBorder>(src, x.i0, y.i0, p);
            fetch8<kBorder>(src, x.i1, y.i0, q);
        }
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) row0[c] = mix8(p[c], q[c], x.a, ia);
        if (pairs) fetch_pairs8(src, x.i0, y.i1, p, q);
        else {
            fetch8<kBorder>(src, x.i0, y.i1, p);
            fetch8<kBorder>(src, x.i1, y.i1, q);
        }
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) value[c] = mix8(row0[c], mix8(p[c], q[c], x.a, ia), y.a, ib);
    }
}

// f.template operator()<kLinear, kS, kT>() for a filter within the level
// and two wrap rules of one kind (a rectangle's where kRect, else
// normalized); false, f not called, for a rule of the other kind.
template <bool kRect, bool kLinear, Rule kS, class F>
[[gnu::always_inline]] inline bool with_rule_t(Rule t, F&& f) {
    const auto call = [&]<Rule kT>() { f.template operator()<kLinear, kS, kT>(); return true; };
    if constexpr (kRect) {
        switch (t) {
        case Rule::RectEdge: return call.template operator()<Rule::RectEdge>();
        case Rule::RectClamp: return call.template operator()<Rule::RectClamp>();
        case Rule::RectBorder: return call.template operator()<Rule::RectBorder>();
        default: return false;
        }
    } else {
        switch (t) {
        case Rule::Repeat: return call.template operator()<Rule::Repeat>();
        case Rule::Mirror: return call.template operator()<Rule::Mirror>();
        case Rule::Edge: return call.template operator()<Rule::Edge>();
        case Rule::Clamp: return call.template operator()<Rule::Clamp>();
        case Rule::Border: return call.template operator()<Rule::Border>();
        default: return false;
        }
    }
}

template <bool kRect, bool kLinear, class F>
[[gnu::always_inline]] inline bool with_rules_of(Rule s, Rule t, F&& f) {
    if constexpr (kRect) {
        switch (s) {
        case Rule::RectEdge: return with_rule_t<kRect, kLinear, Rule::RectEdge>(t, f);
        case Rule::RectClamp: return with_rule_t<kRect, kLinear, Rule::RectClamp>(t, f);
        case Rule::RectBorder: return with_rule_t<kRect, kLinear, Rule::RectBorder>(t, f);
        default: return false;
        }
    } else {
        switch (s) {
        case Rule::Repeat: return with_rule_t<kRect, kLinear, Rule::Repeat>(t, f);
        case Rule::Mirror: return with_rule_t<kRect, kLinear, Rule::Mirror>(t, f);
        case Rule::Edge: return with_rule_t<kRect, kLinear, Rule::Edge>(t, f);
        case Rule::Clamp: return with_rule_t<kRect, kLinear, Rule::Clamp>(t, f);
        case Rule::Border: return with_rule_t<kRect, kLinear, Rule::Border>(t, f);
        default: return false;
        }
    }
}

// with_rules_of() for a texture's state: `linear` the filter within the
// level, the rules from the wraps (a rectangle's where kRect).
template <bool kRect, class F>
[[gnu::always_inline]] inline bool with_rules(const SamplerState& st, bool linear, F&& f) {
    if (linear) return with_rules_of<kRect, true>(rule_of(st.wrap_s, kRect, true), rule_of(st.wrap_t, kRect, true), f);
    return with_rules_of<kRect, false>(rule_of(st.wrap_s, kRect, false), rule_of(st.wrap_t, kRect, false), f);
}

// A 3D image's texels and its three axes (the 3D kernels' record).
struct Image3 {
    Source src;
    Axis w, h, d;
};

}  // namespace glslrun::rt::direct8
#undef GLSLRUN_AVX2
#endif
