// The rules of a texture lookup (GL 2.1 §3.8), as inline functions shared by
// the per-lane sampler (sampling.cpp) and the batched one (sampling_batch.cpp):
// both compute every value with these same operations, so their bits agree
// by construction. Internal to those two files.
//
// The order follows the specification: completeness (§3.8.10), cube-face
// selection (§3.8.6), lambda with bias and clamps (§3.8.8), magnification vs.
// minification (§3.8.9), the mipmap level(s) (§3.8.8), the wrap of each
// coordinate (§3.8.7), NEAREST/LINEAR filtering, depth comparison and
// DEPTH_TEXTURE_MODE (§3.8.14).
//
// Per-pixel code: no allocation, and every texel index is either in range or
// the border marker, whatever the coordinates (NaN and infinities included).
// The helpers are inlined into the entry points: called, their small
// structs and vectors went back through memory, and the loads stalled on
// the stores (perf: a third of a textured frame).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <glm/glm.hpp>

#include "glslrun/glslrun.h"
#include "ir/precise_math.h"
#include "runtime/sampling.h"
#include "runtime/texture_levels.h"

namespace glslrun::rt::sampling {

// |lambda| beyond this changes nothing (levels are at most log2(16384) = 14
// apart); keeping it finite keeps the arithmetic below NaN-free.
inline constexpr float kLodLimit = 1000.0f;
// Coordinates beyond this many texels saturate before they become ints.
inline constexpr float kIndexLimit = 1 << 24;
// A texel index on the border (outside [0, size) under CLAMP or CLAMP_TO_BORDER).
inline constexpr int kBorder = -1;

// A lookup's NaN results as one NaN: a NaN's sign is the first operand's of
// the multiply or add that made it, and the compiler orders those operands
// as it likes in each inlined copy (the batched and per-lane samplers, the
// baseline and AVX2 builds); naming one NaN keeps their bits the same.
inline float canonical_nan(float x) { return x != x ? std::numeric_limits<float>::quiet_NaN() : x; }

// x clamped to [lo, hi], NaN to lo.
inline float clamp_or_low(float x, float lo, float hi) { return x > lo ? (x < hi ? x : hi) : lo; }

// floor() without a libm call (the baseline x86-64 target has no roundss):
// beyond 2^23 every float is an integer already, and NaN stays NaN. No
// branch, and int() only of floats in range, so that lane loops vectorise.
inline float floor_f(float x) {
    const bool small = std::fabs(x) < 8388608.0f;
    const float in_range = small ? x : 0.0f;
    const float t = float(int(in_range));
    const float floored = t > in_range ? t - 1.0f : t;
    return small ? floored : x;
}

// floor_f() where the caller is compiled for SSE4.1 or later (`kRound`: the
// batched sampler's AVX2 build): roundps, and + 0 makes floor(-0) = -0 the
// +0 that floor_f() gives; every other value (NaN included) is floor_f()'s.
template <bool kRound>
[[gnu::always_inline]] inline float floor_t(float x) {
    if constexpr (kRound) return __builtin_floorf(x) + 0.0f;
    else return floor_f(x);
}

// floor() as an int for any float: NaN and huge magnitudes saturate, so the
// wraps below always reduce it to an index in range.
template <bool kRound = false>
inline int floor_int(float x) { return int(floor_t<kRound>(clamp_or_low(x, -kIndexLimit, kIndexLimit))); }

// i mod n in [0, n). The wraps' indices lie within a size of the image
// except where the coordinate was huge or NaN: no division for those (two
// per axis and level were a quarter of a trilinear lookup: perf).
// i mod n for i in [-n, 2n), without a branch (the batched sampler's lanes).
inline int repeat_near(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }
inline bool repeat_is_near(int i, int n) { return (i >= -n) & (i < 2 * n); }
inline int repeat_index(int i, int n) {
    if (repeat_is_near(i, n)) return repeat_near(i, n);
    i %= n;
    return i < 0 ? i + n : i;
}

inline int border_or_index(int i, int n) { return i >= 0 && i < n ? i : kBorder; }

// §3.8.7 MIRRORED_REPEAT: mirror(f) = frac(f) where floor(f) is even,
// 1 - frac(f) where it is odd; the result is then clamped as CLAMP_TO_EDGE.
template <bool kRound = false>
inline float mirror(float s) {
    const float fl = floor_t<kRound>(s);
    const float f = s - fl;
    // Floats from 2^24 on are all even; NaN counts as even (and stays NaN).
    const float in_range = std::fabs(fl) < 16777216.0f ? fl : 0.0f;
    const bool odd = (int32_t(in_range) & 1) != 0;
    return odd ? 1.0f - f : f;
}

// ------------------------------------------------------ texel indices ---
// NEAREST (§3.8.8): i = floor(u) with u = s * size, s wrapped first.
// CLAMP and CLAMP_TO_EDGE both end in [0, size-1] (CLAMP reaches the border
// only when filtering linearly); CLAMP_TO_BORDER's s in [-1/2N, 1+1/2N] makes
// -1 or N, the border.
template <TextureWrap kWrap, bool kRound = false>
[[gnu::always_inline]] inline int nearest_index(float s, int n) {
    switch (kWrap) {
    case TextureWrap::Repeat: return repeat_index(floor_int<kRound>((s - floor_t<kRound>(s)) * float(n)), n);
    case TextureWrap::MirroredRepeat: s = mirror<kRound>(s); [[fallthrough]];
    case TextureWrap::ClampToEdge:
    case TextureWrap::Clamp: return std::clamp(floor_int<kRound>(s * float(n)), 0, n - 1);
    case TextureWrap::ClampToBorder: return border_or_index(floor_int<kRound>(s * float(n)), n);
    }
    return 0;
}

// Calls f.template operator()<kWrap>() for the run-time wrap mode.
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_wrap(TextureWrap wrap, F&& f) {
    switch (wrap) {
    case TextureWrap::Repeat: return f.template operator()<TextureWrap::Repeat>();
    case TextureWrap::MirroredRepeat: return f.template operator()<TextureWrap::MirroredRepeat>();
    case TextureWrap::ClampToEdge: return f.template operator()<TextureWrap::ClampToEdge>();
    case TextureWrap::Clamp: return f.template operator()<TextureWrap::Clamp>();
    case TextureWrap::ClampToBorder: break;
    }
    return f.template operator()<TextureWrap::ClampToBorder>();
}

[[gnu::always_inline]] inline int nearest_index(TextureWrap wrap, float s, int n) {
    return with_wrap(wrap, [&]<TextureWrap kWrap>() { return nearest_index<kWrap>(s, n); });
}

// Returned by linear_axis(), which is inlined: returned from a call, the
// struct went through memory and its load stalled (perf: half of the call).
struct LinearAxis {
    int i0, i1;  // texel indices or kBorder
    float a;     // weight of i1
};

// LINEAR (§3.8.8): i0 = floor(u - 1/2), i1 = i0 + 1,
// alpha = frac(u - 1/2), with u from the wrapped s. REPEAT takes both
// indices mod size; CLAMP lets them leave [0, size) so the border blends in;
// CLAMP_TO_EDGE (and the mirrored coordinate) keeps u in [1/2, size - 1/2],
// so only texels of the image take part.
// REPEAT's u for LINEAR: the fraction of s in texels, less half a texel.
template <bool kRound = false>
inline float repeat_position(float s, float size) { return (s - floor_t<kRound>(s)) * size - 0.5f; }

template <TextureWrap kWrap, bool kRound = false>
[[gnu::always_inline]] inline LinearAxis linear_axis(float s, int n) {
    const float size = float(n);
    float u = 0.0f;
    bool edge = false;
    switch (kWrap) {
    case TextureWrap::Repeat: {
        u = repeat_position<kRound>(s, size);
        const int i0 = floor_int<kRound>(u);
        return {repeat_index(i0, n), repeat_index(i0 + 1, n), u - floor_t<kRound>(u)};
    }
    case TextureWrap::MirroredRepeat: s = mirror<kRound>(s); [[fallthrough]];
    case TextureWrap::ClampToEdge:
        u = clamp_or_low(s * size, 0.5f, size - 0.5f) - 0.5f;
        edge = true;
        break;
    case TextureWrap::Clamp: u = clamp_or_low(s, 0.0f, 1.0f) * size - 0.5f; break;
    case TextureWrap::ClampToBorder: u = clamp_or_low(s * size, -0.5f, size + 0.5f) - 0.5f; break;
    }
    const int i0 = floor_int<kRound>(u);
    const float a = u - floor_t<kRound>(u);
    // At u = size - 1/2 the edge modes' i1 is past the image with weight 0: keep it on the last texel.
    if (edge) return {std::min(i0, n - 1), std::min(i0 + 1, n - 1), a};
    return {border_or_index(i0, n), border_or_index(i0 + 1, n), a};
}

[[gnu::always_inline]] inline LinearAxis linear_axis(TextureWrap wrap, float s, int n) {
    return with_wrap(wrap, [&]<TextureWrap kWrap>() { return linear_axis<kWrap>(s, n); });
}

// ARB_texture_rectangle's indices (sampling_rect.cpp says the rules): u is
// the unnormalized coordinate, not s * size. Only the clamping wraps are
// complete for a rectangle; the others take CLAMP's NEAREST and
// CLAMP_TO_BORDER's LINEAR, as every sampler of rectangles does.
template <TextureWrap kWrap, bool kRound = false>
[[gnu::always_inline]] inline int rect_nearest_index(float u, int n) {
    const int i = floor_int<kRound>(u);
    return kWrap == TextureWrap::ClampToBorder ? border_or_index(i, n) : std::clamp(i, 0, n - 1);
}

template <TextureWrap kWrap, bool kRound = false>
[[gnu::always_inline]] inline LinearAxis rect_linear_axis(float u, int n) {
    const float size = float(n);
    float x = 0.0f;
    switch (kWrap) {
    case TextureWrap::ClampToEdge: {
        x = clamp_or_low(u, 0.5f, size - 0.5f) - 0.5f;
        const int i0 = floor_int<kRound>(x);
        // At u = w - 1/2, i1 is past the image with weight 0: kept on the last texel.
        return {std::min(i0, n - 1), std::min(i0 + 1, n - 1), x - floor_t<kRound>(x)};
    }
    case TextureWrap::Clamp: x = clamp_or_low(u, 0.0f, size) - 0.5f; break;
    default: x = clamp_or_low(u, -0.5f, size + 0.5f) - 0.5f; break;  // CLAMP_TO_BORDER
    }
    const int i0 = floor_int<kRound>(x);
    return {border_or_index(i0, n), border_or_index(i0 + 1, n), x - floor_t<kRound>(x)};
}

// ------------------------------------------------------------ lookup ---
// The table of §3.8.6: per face, the major axis and which component (with which
// sign) becomes sc and tc.
struct CubeFace {
    int major, s_axis, t_axis;
    float s_sign, t_sign;
};
inline constexpr CubeFace kCubeFaces[6] = {
    {0, 2, 1, -1, -1},  // +X: sc = -rz, tc = -ry
    {0, 2, 1, +1, -1},  // -X: sc = +rz, tc = -ry
    {1, 0, 2, +1, +1},  // +Y: sc = +rx, tc = +rz
    {1, 0, 2, +1, -1},  // -Y: sc = +rx, tc = -rz
    {2, 0, 1, +1, -1},  // +Z: sc = +rx, tc = -ry
    {2, 0, 1, -1, -1},  // -Z: sc = -rx, tc = -ry
};

// §3.8.6: the face of the largest-magnitude component. GL leaves ties to the
// implementation; like Mesa, X wins over Y and Z, Y over Z. NaN ends on Z.
inline int cube_face(const glm::vec3& r) {
    const float ax = std::fabs(r.x), ay = std::fabs(r.y), az = std::fabs(r.z);
    // Selects, not branches: the batched sampler's lane loop vectorises.
    const bool x_major = (ax >= ay) & (ax >= az);
    const bool y_major = !x_major & (ay >= az);
    const int fx = r.x >= 0.0f ? 0 : 1, fy = r.y >= 0.0f ? 2 : 3, fz = r.z >= 0.0f ? 4 : 5;
    return x_major ? fx : (y_major ? fy : fz);
}

// s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2 (§3.8.6). A zero
// direction gives NaN, which the wraps turn into some texel of the face.
[[gnu::always_inline]] inline glm::vec3 cube_coord(const CubeFace& f, const glm::vec3& r) {
    const float ma = std::fabs(r[f.major]);
    return {0.5f * (f.s_sign * r[f.s_axis] / ma + 1.0f), 0.5f * (f.t_sign * r[f.t_axis] / ma + 1.0f), 0.0f};
}

// §3.8.14: the comparison's result, 1 or 0, of R (the reference) against D_t.
inline float compare_depth(CompareFunc func, float ref, float d) {
    switch (func) {
    case CompareFunc::Never: return 0.0f;
    case CompareFunc::Less: return ref < d ? 1.0f : 0.0f;
    case CompareFunc::Equal: return ref == d ? 1.0f : 0.0f;
    case CompareFunc::Lequal: return ref <= d ? 1.0f : 0.0f;
    case CompareFunc::Greater: return ref > d ? 1.0f : 0.0f;
    case CompareFunc::Notequal: return ref != d ? 1.0f : 0.0f;
    case CompareFunc::Gequal: return ref >= d ? 1.0f : 0.0f;
    case CompareFunc::Always: return 1.0f;
    }
    return 0.0f;
}

// What one lookup needs at every texel: the face and its (s, t, r), and the
// depth comparison. For a depth texture with compare on, every texel (the
// border too) reads as its comparison result, so the filters average
// results: compare first, then filter, as Mesa does. An array's layer is a
// fixed texel row (1D array: j) or slice (2D array: k) of every level.
struct Lookup {
    const Texture* texture;
    const SamplerState* st;
    int face, dims;
    glm::vec3 str;
    bool compare;
    float ref;
    int layer_j = 0, layer_k = 0;
    SamplingRules rules = SamplingRules::Common;
};

// EXT_texture_array: the layer of coordinate r is clamp(floor(r + 1/2), 0,
// layers - 1), the same at every level (NaN: layer 0).
inline int array_layer(float r, int layers) { return std::clamp(floor_int(r + 0.5f), 0, layers - 1); }

inline float unorm(float x) { return clamp_or_low(x, 0.0f, 1.0f); }

[[gnu::always_inline]] inline Lookup make_lookup(const Texture& texture, const glm::vec3& coord, float ref,
                                                 SamplingRules rules = SamplingRules::Common) {
    const SamplerState& st = texture.sampler;
    Lookup lk{&texture, &st, 0, texture_dims(texture.target()), coord, false, 0.0f};
    lk.rules = rules;
    if (texture.target() == TextureTarget::Cube) {
        lk.face = cube_face(coord);
        lk.str = cube_coord(kCubeFaces[lk.face], coord);
    }
    // §3.8.14: the comparison applies to depth textures only; R is clamped to [0, 1].
    lk.compare = texture.depth() && st.compare;
    lk.ref = unorm(ref);
    if (texture.target() == TextureTarget::Tex1DArray || texture.target() == TextureTarget::Tex2DArray) {
        const TextureImage& base = texture.levels(0)[size_t(st.base_level)];
        if (texture.target() == TextureTarget::Tex1DArray)
            lk.layer_j = array_layer(coord.y, base.height);
        else
            lk.layer_k = array_layer(coord.z, base.depth);
    }
    return lk;
}

#if defined(__SSE2__)
// A texel's four channels in one register. As glm::vec4, the filters'
// values came back from calls in two halves and were put together through
// the stack, where the load waited on the two stores (perf: a fifth of the
// cube-map scene's lookup). mix() is glm::mix's arithmetic, x * (1 - a) +
// y * a, channel by channel, so the bits are the same.
using Texel = __m128;
inline Texel texel_of(const glm::vec4& v) { return _mm_loadu_ps(&v.x); }
inline Texel splat_texel(float v) { return _mm_set1_ps(v); }
inline glm::vec4 vec_of(Texel t) {
    glm::vec4 v;
    _mm_storeu_ps(&v.x, t);
    return v;
}
inline Texel mix(Texel x, Texel y, float a) {
    return _mm_add_ps(_mm_mul_ps(x, _mm_set1_ps(1.0f - a)), _mm_mul_ps(y, _mm_set1_ps(a)));
}
#else
using Texel = glm::vec4;
inline Texel texel_of(const glm::vec4& v) { return v; }
inline Texel splat_texel(float v) { return glm::vec4(v); }
inline glm::vec4 vec_of(Texel t) { return t; }
inline Texel mix(Texel x, Texel y, float a) { return glm::mix(x, y, a); }
#endif

// GL 2.1 clamps TEXTURE_BORDER_COLOR to [0, 1] when it is set (§3.8.4); a
// depth texture's border is the depth border_color.r.
[[gnu::always_inline]] inline glm::vec4 border_texel(const Lookup& lk) {
    const glm::vec4& b = lk.st->border_color;
    if (lk.compare) return glm::vec4(compare_depth(lk.st->compare_func, lk.ref, unorm(b.r)));
    return {unorm(b.r), unorm(b.g), unorm(b.b), unorm(b.a)};
}

// What the steps below tell an observer (the shader debugger's texture
// lookups: rt::explain_lookup): the lambda and the filter chosen, each level
// sampled, and each texel fetched with the value it gave (the border's
// included, after the depth comparison). The samplers use NoObserver, whose
// empty calls compile to nothing.
struct NoObserver {
    void filter(float /*lambda*/, bool /*magnified*/) {}
    void level(int /*level*/, const TextureImage& /*image*/, bool /*linear*/) {}
    void texel(int /*i*/, int /*j*/, int /*k*/, Texel /*value*/) {}
};

// Texel (i, j, k) of `image`; any index kBorder means the border colour.
template <class Obs = NoObserver>
[[gnu::always_inline]] inline Texel fetch(const Lookup& lk, const TextureImage& image, int i, int j, int k,
                                          Obs&& obs = Obs{}) {
    if (i < 0 || j < 0 || k < 0) {
        const Texel border = texel_of(border_texel(lk));
        obs.texel(i, j, k, border);
        return border;
    }
    const size_t at = size_t(i) + size_t(image.width) * (size_t(j) + size_t(image.height) * size_t(k));
    const glm::vec4& texel = image.texels[at];
    const Texel value = lk.compare ? splat_texel(compare_depth(lk.st->compare_func, lk.ref, texel.r)) : texel_of(texel);
    obs.texel(i, j, k, value);
    return value;
}

template <class Obs = NoObserver>
[[gnu::always_inline]] inline Texel sample_nearest(const Lookup& lk, const TextureImage& image, Obs&& obs = Obs{}) {
    const int i = nearest_index(lk.st->wrap_s, lk.str.x, image.width);
    const int j = lk.dims > 1 ? nearest_index(lk.st->wrap_t, lk.str.y, image.height) : lk.layer_j;
    const int k = lk.dims > 2 ? nearest_index(lk.st->wrap_r, lk.str.z, image.depth) : lk.layer_k;
    return fetch(lk, image, i, j, k, obs);
}

// §3.8.8: the (bi/tri)linear blend of the 2, 4 or 8 texels around u.
template <class Obs = NoObserver>
[[gnu::always_inline]] inline Texel sample_linear(const Lookup& lk, const TextureImage& image, Obs&& obs = Obs{}) {
    const LinearAxis x = linear_axis(lk.st->wrap_s, lk.str.x, image.width);
    if (lk.dims == 1)
        return mix(fetch(lk, image, x.i0, lk.layer_j, lk.layer_k, obs), fetch(lk, image, x.i1, lk.layer_j, lk.layer_k, obs),
                   x.a);
    const LinearAxis y = linear_axis(lk.st->wrap_t, lk.str.y, image.height);
    auto plane = [&](int k) {
        const Texel row0 = mix(fetch(lk, image, x.i0, y.i0, k, obs), fetch(lk, image, x.i1, y.i0, k, obs), x.a);
        const Texel row1 = mix(fetch(lk, image, x.i0, y.i1, k, obs), fetch(lk, image, x.i1, y.i1, k, obs), x.a);
        return mix(row0, row1, y.a);
    };
    if (lk.dims == 2) return plane(lk.layer_k);
    const LinearAxis z = linear_axis(lk.st->wrap_r, lk.str.z, image.depth);
    return mix(plane(z.i0), plane(z.i1), z.a);
}

// `level` is within [level_base, q], which completeness guarantees exist.
template <class Obs = NoObserver>
[[gnu::always_inline]] inline Texel sample_level(const Lookup& lk, int level, bool linear, Obs&& obs = Obs{}) {
    const TextureImage& image = lk.texture->levels(lk.face)[size_t(level)];
    obs.level(level, image, linear);
    return linear ? sample_linear(lk, image, obs) : sample_nearest(lk, image, obs);
}

// ------------------------------------------------- level of detail ---
// Whether a filter blends texels within a level (LINEAR, LINEAR_MIPMAP_*).
inline bool linear_within_level(TextureFilter f) {
    return f == TextureFilter::Linear || f == TextureFilter::LinearMipmapNearest ||
           f == TextureFilter::LinearMipmapLinear;
}

// §3.8.8: lambda = clamp(lambda_base + bias, TEXTURE_MIN_LOD, TEXTURE_MAX_LOD).
// NaN (from NaN coordinates or derivatives) becomes min_lod; if min_lod >
// max_lod (undefined in GL) max_lod wins.
inline float clamp_lambda(float lambda, const SamplerState& st) {
    if (!(lambda >= st.min_lod)) lambda = st.min_lod;
    if (lambda > st.max_lod) lambda = st.max_lod;
    return std::isnan(lambda) ? 0.0f : clamp_or_low(lambda, -kLodLimit, kLodLimit);
}

// §3.8.8, *_MIPMAP_NEAREST: d = level_base for lambda <= 1/2,
// level_base + ceil(lambda + 1/2) - 1 up to q + 1/2, else q.
inline int nearest_mip_level(float lambda, int base, int q) {
    // lambda is finite (clamp_lambda), so the conversion is defined; selects for the lane loops.
    const int d = std::clamp(base + int(std::ceil(lambda + 0.5f)) - 1, base, q);
    return lambda <= 0.5f ? base : (float(base) + lambda > float(q) + 0.5f ? q : d);
}

// §3.8.9: c, the switch-over between magnification and minification. The
// specification's c = 1/2 for LINEAR magnification with a NEAREST_MIPMAP_*
// minification filter is taken by Reference alone: llvmpipe and NVIDIA's
// driver both switch at 0 (docs/semantics.md, measured by tools/gpu_probes).
inline bool spec_switch_over(const SamplerState& st) {
    const bool nearest_mipmap = st.min_filter == TextureFilter::NearestMipmapNearest ||
                                st.min_filter == TextureFilter::NearestMipmapLinear;
    return st.mag_filter == TextureFilter::Linear && nearest_mipmap;
}
inline float mag_threshold(const SamplerState& st, SamplingRules rules = SamplingRules::Common) {
    return rules == SamplingRules::Spec && spec_switch_over(st) ? 0.5f : 0.0f;
}

template <class Obs = NoObserver>
[[gnu::always_inline]] inline Texel filter(const Lookup& lk, float lambda, Obs&& obs = Obs{}) {
    const SamplerState& st = *lk.st;
    const int base = st.base_level;
    // §3.8.9: lambda <= c magnifies: the mag filter on level_base.
    const bool magnified = lambda <= mag_threshold(st, lk.rules);
    obs.filter(lambda, magnified);
    if (magnified) return sample_level(lk, base, linear_within_level(st.mag_filter), obs);
    const bool linear = linear_within_level(st.min_filter);
    if (!is_mipmap_filter(st.min_filter)) return sample_level(lk, base, linear, obs);
    const int q = last_mip_level(lk.texture->levels(lk.face)[size_t(base)], st, lk.dims);
    if (st.min_filter == TextureFilter::NearestMipmapNearest || st.min_filter == TextureFilter::LinearMipmapNearest)
        return sample_level(lk, nearest_mip_level(lambda, base, q), linear, obs);
    // §3.8.8, *_MIPMAP_LINEAR: levels d1 = floor(level_base + lambda)
    // and d1 + 1 blended by frac(lambda); both are q from level_base + lambda >= q on.
    if (float(base) + lambda >= float(q)) return sample_level(lk, q, linear, obs);
    const float whole = floor_f(lambda);
    const int d1 = base + int(whole);
    const Texel first = sample_level(lk, d1, linear, obs);
    return mix(first, sample_level(lk, d1 + 1, linear, obs), lambda - whole);
}

// §3.8.14 DEPTH_TEXTURE_MODE: how a depth (or comparison result) becomes RGBA.
[[gnu::always_inline]] inline glm::vec4 expand_depth(DepthTextureMode mode, float d) {
    switch (mode) {
    case DepthTextureMode::Luminance: return {d, d, d, 1.0f};
    case DepthTextureMode::Intensity: return {d, d, d, d};
    case DepthTextureMode::Alpha: return {0.0f, 0.0f, 0.0f, d};
    }
    return {d, d, d, 1.0f};
}

// The derivative of s = (sc/|ma| + 1) / 2 on the face: (dsc |ma| - sc d|ma|) / (2 ma^2).
inline float face_derivative(float sc, float dsc, float ama, float dama) {
    return 0.5f * (dsc * ama - sc * dama) / (ama * ama);
}

// (ds, dt) on the cube face `r` selects, from the derivative d of the direction.
[[gnu::always_inline]] inline glm::vec3 cube_derivative(const CubeFace& f, const glm::vec3& r, const glm::vec3& d) {
    const float ama = std::fabs(r[f.major]);
    const float dama = r[f.major] >= 0.0f ? d[f.major] : -d[f.major];
    return {face_derivative(f.s_sign * r[f.s_axis], f.s_sign * d[f.s_axis], ama, dama),
            face_derivative(f.t_sign * r[f.t_axis], f.t_sign * d[f.t_axis], ama, dama), 0.0f};
}

// |(du, dv, dw)| for the derivative d of (s, t, r), u = s * w_t etc.: only
// the target's dimensions count.
[[gnu::always_inline]] inline float scaled_length(const glm::vec3& d, const glm::vec3& size, int dims) {
    const glm::vec3 uvw(d.x * size.x, dims > 1 ? d.y * size.y : 0.0f, dims > 2 ? d.z * size.z : 0.0f);
    return glm::length(uvw);
}

// The level-of-detail rule, lambda_base = log2(rho) of §3.8.8, from the
// derivatives of (s, t, r) over the screen (on the face, for a cube map) and
// the sizes of level_base. The one place the rule is written: the per-lane
// and the batched samplers both call it, lane by lane.
// rho = max of the lengths of (du/dx, dv/dx, dw/dx) and (du/dy, dv/dy, dw/dy).
[[gnu::always_inline]] inline float rho_rule(const glm::vec3& dx, const glm::vec3& dy, const glm::vec3& size,
                                             int dims) {
    return std::max(scaled_length(dx, size, dims), scaled_length(dy, size, dims));
}

// The GPU's length of a texel-space vector (du, dv) (sampling_gpu.h): max + 11/32 min of the magnitudes.
inline float gpu_length(float du, float dv) {
    const float u = std::fabs(du), v = std::fabs(dv);
    return std::max(u, v) + 0.34375f * std::min(u, v);
}

// The GPU's rho (sampling_gpu.h): the lengths of J x, J y and 11/16 of
// J (x + y), J (x - y), so an ellipse whose axis is diagonal on the screen
// counts too (tools/gpu_probes/lodrand.frag).
// A 3D derivative's length as the GPU takes it: max + 11/32 mid + 1/4 min of
// |du|, |dv|, |dw| (tools/gpu_probes/lod3d.frag: 97.5% of 117,648 quads'
// lambdas; the exact lengths 0.9%).
inline float gpu_length3(float du, float dv, float dw) {
    float a = std::fabs(du), b = std::fabs(dv), c = std::fabs(dw);
    if (a < b) std::swap(a, b);
    if (b < c) std::swap(b, c);
    if (a < b) std::swap(a, b);
    return a + 0.34375f * b + 0.25f * c;
}

inline float gpu_rho(const glm::vec3& dx, const glm::vec3& dy, const glm::vec3& size, int dims) {
    if (dims == 3) {
        const glm::vec3 x = dx * size, y = dy * size, p = x + y, m = x - y;
        const float axes = std::max(gpu_length3(x.x, x.y, x.z), gpu_length3(y.x, y.y, y.z));
        return std::max(axes, 0.6875f * std::max(gpu_length3(p.x, p.y, p.z), gpu_length3(m.x, m.y, m.z)));
    }
    const float ux = dx.x * size.x, uy = dy.x * size.x;
    const float vx = dims > 1 ? dx.y * size.y : 0.0f, vy = dims > 1 ? dy.y * size.y : 0.0f;
    const float axes = std::max(gpu_length(ux, vx), gpu_length(uy, vy));
    const float diagonals = std::max(gpu_length(ux + uy, vx + vy), gpu_length(ux - uy, vx - vy));
    return std::max(axes, 0.6875f * diagonals);
}

// lambda_base = log2(rho).
inline float lod_from_rho(float rho) {
    if (!(rho > 0.0f)) return -kLodLimit;  // no change across the pixel (or NaN): magnification
    return std::min(math::log2(rho), kLodLimit);
}

[[gnu::always_inline]] inline float lod_rule(const glm::vec3& dx, const glm::vec3& dy, const glm::vec3& size,
                                             int dims) {
    return lod_from_rho(rho_rule(dx, dy, size, dims));
}

inline glm::vec3 image_size(const TextureImage& image) {
    return {float(image.width), float(image.height), float(image.depth)};
}

// rho of §3.8.8 for a lookup's derivatives; 0 where the texture is incomplete.
// `gpu`: the GPU's rho (gpu_rho) for 1D and 2D images.
[[gnu::always_inline]] inline float rho_of(const Texture& texture, const glm::vec3& coord, const glm::vec3& ddx,
                                           const glm::vec3& ddy, bool gpu = false) {
    const TextureImage* base = level_image(texture, 0, texture.sampler.base_level);
    if (!base) return 0.0f;  // incomplete: the lookup gives (0, 0, 0, 1) whatever the LOD
    glm::vec3 dx = ddx, dy = ddy;
    if (texture.target() == TextureTarget::Cube) {
        const CubeFace& face = kCubeFaces[cube_face(coord)];
        dx = cube_derivative(face, coord, ddx);
        dy = cube_derivative(face, coord, ddy);
    }
    const int dims = texture_dims(texture.target());
    if (gpu) return gpu_rho(dx, dy, image_size(*base), dims);
    return rho_rule(dx, dy, image_size(*base), dims);
}

[[gnu::always_inline]] inline float lod_of(const Texture& texture, const glm::vec3& coord, const glm::vec3& ddx,
                                           const glm::vec3& ddy) {
    if (!level_image(texture, 0, texture.sampler.base_level)) return 0.0f;  // incomplete: any LOD gives (0, 0, 0, 1)
    return lod_from_rho(rho_of(texture, coord, ddx, ddy));
}

// Without mipmaps and with one filter within a level for both, both sides
// of §3.8.9 sample level_base alike: the implicit LOD (a log2 and, for cube
// maps, the derivatives on the face) is not needed (perf: most of the
// cube-map scene's lookup).
inline bool lod_matters(const SamplerState& st) {
    return is_mipmap_filter(st.min_filter) || linear_within_level(st.min_filter) != linear_within_level(st.mag_filter);
}

template <class Obs = NoObserver>
[[gnu::always_inline]] inline glm::vec4 sample_complete(const Texture& texture, const glm::vec3& coord, float ref,
                                                         float lod, Obs&& obs = Obs{},
                                                         SamplingRules rules = SamplingRules::Common) {
    const SamplerState& st = texture.sampler;
    const Lookup lk = make_lookup(texture, coord, ref, rules);
    const glm::vec4 v = vec_of(filter(lk, clamp_lambda(lod + st.lod_bias, st), obs));
    return texture.depth() ? expand_depth(st.depth_mode, v.r) : v;
}


}  // namespace glslrun::rt::sampling
