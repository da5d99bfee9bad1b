// The batched sampler (see sampling_batch.h). Each step is a loop over all
// kLanes lanes with the texture's state hoisted out of it: the wrap modes
// are template arguments, the filters and the target are decided once per
// batch. Lanes outside the mask compute too (their operands are whatever the
// registers hold: every step is safe for any float), but fetch nothing.
#include "runtime/sampling_batch.h"

#include "runtime/interp_kernels.h"
#include "runtime/sampling_avx2.h"
#include "runtime/sampling_cube8.h"
#include "runtime/sampling_direct.h"
#include "runtime/sampling_direct1d.h"
#include "runtime/sampling_direct3d.h"
#include "runtime/sampling_direct8.h"
#include "runtime/sampling_levels.h"
#include "runtime/sampling_mip2d.h"
#include "runtime/sampling_rules.h"
#include "runtime/sampling_shadow8.h"

namespace glslrun::rt {

using namespace sampling;

namespace {

// What each lane carries from one step to the next.
struct Lanes {
    alignas(32) float s[kLanes], t[kLanes], r[kLanes];  // (s, t, r) on the image (cube: (s, t) on the face)
    alignas(32) int face[kLanes];
    alignas(32) float lambda[kLanes];
    alignas(32) int level[2][kLanes];    // level[1] < 0: one level only
    alignas(32) float mip_weight[kLanes];  // of level[1]
    alignas(32) int linear[kLanes];        // LINEAR within the level (else NEAREST)
    alignas(32) float ref[kLanes];         // the depth reference, clamped to [0, 1]
    // Per level pass: the lane's image, its size, and the texel indices and weights.
    const TextureImage* image[kLanes];  // null where the lane is skipped
    const TextureImage* sized[kLanes];  // the image whose size the lane's indices use: never null
    alignas(32) int width[kLanes], height[kLanes], depth[kLanes];
    alignas(32) int x0[kLanes], x1[kLanes], y0[kLanes], y1[kLanes], z0[kLanes], z1[kLanes];
    alignas(32) float ax[kLanes], ay[kLanes], az[kLanes];
    alignas(32) float rgba[4][kLanes], second[4][kLanes];  // results, channel by channel
};

// §3.8.6 for every lane: the face and (s, t) on it, the selects written
// out so that the loop vectorises; cube_coord()'s arithmetic.
void cube_coords(const BatchLookup& lk, Lanes& l) {
    const float* __restrict cx = lk.coord[0];
    const float* __restrict cy = lk.coord[1];
    const float* __restrict cz = lk.coord[2];
    for (int i = 0; i < kLanes; ++i) {
        const float x = cx[i], y = cy[i], z = cz[i];
        const int face = cube_face(glm::vec3(x, y, z));
        const float major = face < 2 ? x : (face < 4 ? y : z);
        const float sc = face < 2 ? z : x, s_sign = face == 0 || face == 5 ? -1.0f : 1.0f;
        const float tc = face == 2 || face == 3 ? z : y, t_sign = face == 2 ? 1.0f : -1.0f;
        const float ma = std::fabs(major);
        l.face[i] = face;
        l.s[i] = 0.5f * (s_sign * sc / ma + 1.0f);
        l.t[i] = 0.5f * (t_sign * tc / ma + 1.0f);
    }
}

void plain_coords(const BatchLookup& lk, Lanes& l) {
    const float* __restrict cs = lk.coord[0];
    const float* __restrict ct = lk.coord[1];
    const float* __restrict cr = lk.coord[2];
    for (int i = 0; i < kLanes; ++i) {
        l.face[i] = 0;
        l.s[i] = cs[i];
        l.t[i] = ct[i];
        l.r[i] = cr[i];
    }
}

// lambda_base for every lane, as sample_complete_lane() computes it, then
// lambda with the texture's bias and clamps.
void lambdas(const Texture& texture, const BatchLookup& lk, Lanes& l) {
    const SamplerState& st = texture.sampler;
    float* lambda = l.lambda;
    if (lk.implicit && lod_matters(st)) {
        if (texture.target() == TextureTarget::Cube) {
            for (int i = 0; i < kLanes; ++i)
                lambda[i] = lod_of(texture, {lk.coord[0][i], lk.coord[1][i], lk.coord[2][i]},
                                   {lk.ddx[0][i], lk.ddx[1][i], lk.ddx[2][i]}, {lk.ddy[0][i], lk.ddy[1][i], lk.ddy[2][i]});
        } else {
            // A rectangle's (u, v) are in texels already: the size factors of §3.8.8 are 1.
            const bool rect = texture.target() == TextureTarget::Rect;
            const glm::vec3 size = rect ? glm::vec3(1.0f) : image_size(*level_image(texture, 0, st.base_level));
            const int dims = texture_dims(texture.target());
            const float* __restrict dxs = lk.ddx[0];
            const float* __restrict dxt = lk.ddx[1];
            const float* __restrict dxr = lk.ddx[2];
            const float* __restrict dys = lk.ddy[0];
            const float* __restrict dyt = lk.ddy[1];
            const float* __restrict dyr = lk.ddy[2];
            // r's derivatives count for 3D textures only (scaled_length() drops the axes past dims).
            for (int i = 0; i < kLanes; ++i)
                lambda[i] = lod_rule({dxs[i], dxt[i], dxr[i]}, {dys[i], dyt[i], dyr[i]}, size, dims);
        }
        if (lk.bias)
            for (int i = 0; i < kLanes; ++i) lambda[i] = lambda[i] + lk.lod[i];
    } else if (lk.lod) {  // tested outside the loop: vectorised, a masked load from null faulted (assists: slow)
        for (int i = 0; i < kLanes; ++i) lambda[i] = lk.lod[i];
    } else {
        for (int i = 0; i < kLanes; ++i) lambda[i] = 0.0f;
    }
    for (int i = 0; i < kLanes; ++i) lambda[i] = clamp_lambda(lambda[i] + st.lod_bias, st);
}

// §3.8.8/§3.8.9 for every lane, as filter() decides: magnification or
// minification, the filter within the level, and the level(s).
void choose_levels(const Texture& texture, Lanes& l) {
    const LevelRule rule(texture);
    for (int i = 0; i < kLanes; ++i) {
        const LevelChoice d = choose_level(rule, l.lambda[i]);
        l.linear[i] = d.linear;
        l.level[0][i] = d.d0;
        l.level[1][i] = d.d1;
        l.mip_weight[i] = d.weight;
    }
}

// The image size on one axis: per lane (each lane's level), or one for
// every lane (one image): the index loops below take either.
struct LaneSizes {
    const int* __restrict n;
    int operator[](int i) const { return n[i]; }
};
struct OneSize {
    int n;
    int operator[](int) const { return n; }
};

// REPEAT's indices for every lane from the unwrapped ones (`raw`, and
// raw + 1 where `second`): repeat_near() in a vectorised loop, then
// repeat_index() where some lane is far out (NaN or huge coordinates).
// Separate loops: together, the vectoriser refused them.
template <class N>
void repeat_lanes(const int* __restrict raw, N n, int offset, int* __restrict out) {
    int far = 0;
    for (int i = 0; i < kLanes; ++i) {
        const int r = raw[i] + offset;
        out[i] = repeat_near(r, n[i]);
        far |= int(r < -n[i]) | int(r >= 2 * n[i]);
    }
    if (far)
        for (int i = 0; i < kLanes; ++i) out[i] = repeat_index(raw[i] + offset, n[i]);
}

// NEAREST's index on one axis for every lane: nearest_index<kWrap>().
template <TextureWrap kWrap, bool kRound, class N>
void nearest_lanes(const float* __restrict s, N n, int* __restrict out) {
    if constexpr (kWrap == TextureWrap::Repeat) {
        alignas(32) int raw[kLanes];
        for (int i = 0; i < kLanes; ++i) raw[i] = floor_int<kRound>((s[i] - floor_t<kRound>(s[i])) * float(n[i]));
        repeat_lanes(raw, n, 0, out);
    } else {
        for (int i = 0; i < kLanes; ++i) out[i] = nearest_index<kWrap, kRound>(s[i], n[i]);
    }
}

// LINEAR's two indices and weight on one axis for every lane: linear_axis<kWrap>().
template <TextureWrap kWrap, bool kRound, class N>
void linear_lanes(const float* __restrict s, N n, int* __restrict i0, int* __restrict i1, float* __restrict a) {
    if constexpr (kWrap == TextureWrap::Repeat) {
        alignas(32) int raw[kLanes];
        for (int i = 0; i < kLanes; ++i) {
            const float u = repeat_position<kRound>(s[i], float(n[i]));
            raw[i] = floor_int<kRound>(u);
            a[i] = u - floor_t<kRound>(u);
        }
        repeat_lanes(raw, n, 0, i0);
        repeat_lanes(raw, n, 1, i1);
    } else {
        for (int i = 0; i < kLanes; ++i) {
            const LinearAxis axis = linear_axis<kWrap, kRound>(s[i], n[i]);
            i0[i] = axis.i0;
            i1[i] = axis.i1;
            a[i] = axis.a;
        }
    }
}

// A rectangle's NEAREST and LINEAR indices on one axis for every lane:
// rect_nearest_index<kWrap>() and rect_linear_axis<kWrap>() (u unnormalized).
template <TextureWrap kWrap, bool kRound>
void rect_lanes(bool linear, const float* __restrict u, int n, int* __restrict i0, int* __restrict i1,
                float* __restrict a) {
    if (!linear) {
        for (int i = 0; i < kLanes; ++i) i0[i] = rect_nearest_index<kWrap, kRound>(u[i], n);
        return;
    }
    for (int i = 0; i < kLanes; ++i) {
        const LinearAxis axis = rect_linear_axis<kWrap, kRound>(u[i], n);
        i0[i] = axis.i0;
        i1[i] = axis.i1;
        a[i] = axis.a;
    }
}

// `kRound`: floor_t()'s roundps, in the AVX2 build only (the same bits).
// `kRect`: a rectangle's unnormalized coordinates (one image: OneSize).
template <bool kRound = false, bool kRect = false, class N>
void axis_indices(TextureWrap wrap, bool linear, const float* s, N n, int* i0, int* i1, float* a) {
    with_wrap(wrap, [&]<TextureWrap kWrap>() {
        if constexpr (kRect) rect_lanes<kWrap, kRound>(linear, s, n.n, i0, i1, a);
        else if (linear) linear_lanes<kWrap, kRound>(s, n, i0, i1, a);
        else nearest_lanes<kWrap, kRound>(s, n, i0);
    });
}

// Lane i's texel into channel arrays.
inline void put(float (*out)[kLanes], int i, Texel t) {
    const glm::vec4 v = vec_of(t);
    for (int c = 0; c < 4; ++c) out[c][i] = v[c];
}

// Whether a wrap mode's indices can be the border's (kBorder).
bool may_border(TextureWrap wrap) { return wrap == TextureWrap::Clamp || wrap == TextureWrap::ClampToBorder; }

#if defined(__SSE2__)
// The texels of lanes g..g+3 at offsets at[g..g+3], transposed into
// channels: ch[c] holds channel c of the four lanes. `src(i)`: lane i's texels.
template <class Src>
[[gnu::always_inline]] inline void load4(Src src, const int* at, int g, __m128* ch) {
    __m128 t0 = _mm_loadu_ps(&src(g)[at[g]].x);
    __m128 t1 = _mm_loadu_ps(&src(g + 1)[at[g + 1]].x);
    __m128 t2 = _mm_loadu_ps(&src(g + 2)[at[g + 2]].x);
    __m128 t3 = _mm_loadu_ps(&src(g + 3)[at[g + 3]].x);
    _MM_TRANSPOSE4_PS(t0, t1, t2, t3);
    ch[0] = t0;
    ch[1] = t1;
    ch[2] = t2;
    ch[3] = t3;
}

// mix() of four lanes side by side: x * (1 - a) + y * a, as Texel's mix().
inline __m128 mix4(__m128 x, __m128 y, __m128 a, __m128 b) { return _mm_add_ps(_mm_mul_ps(x, b), _mm_mul_ps(y, a)); }

// sample_linear()'s bilinear blend of the plane whose corners' offsets
// start at at[0] (corners (x0, y0), (x1, y0), (x0, y1), (x1, y1)) for the
// four lanes from g, channel by channel: the same products and sums as
// mix() of four-channel texels, with the lanes side by side. None is the
// border's. Skipped lanes read texels of the image their indices were
// computed for.
template <class Src>
[[gnu::always_inline]] inline void plane4(Src src, const int (*at)[kLanes], const float* ax, const float* ay, int g,
                                          __m128* plane) {
    __m128 corner[4][4];  // [corner][channel]
    for (int k = 0; k < 4; ++k) load4(src, at[k], g, corner[k]);
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 a = _mm_loadu_ps(&ax[g]), b = _mm_loadu_ps(&ay[g]);
    const __m128 ia = _mm_sub_ps(one, a), ib = _mm_sub_ps(one, b);
    for (int c = 0; c < 4; ++c)
        plane[c] = mix4(mix4(corner[0][c], corner[1][c], a, ia), mix4(corner[2][c], corner[3][c], a, ia), b, ib);
}

template <class Src>
[[gnu::always_inline]] inline void bilinear4(Src src, const int (*at)[kLanes], const float* ax, const float* ay, int g,
                                             float (*out)[kLanes]) {
    __m128 plane[4];
    plane4(src, at, ax, ay, g, plane);
    for (int c = 0; c < 4; ++c) _mm_storeu_ps(&out[c][g], plane[c]);
}

// The trilinear blend: the planes at z0 (at[0..3]) and z1 (at[4..7]) mixed by az.
template <class Src>
[[gnu::always_inline]] inline void trilinear4(Src src, const int (*at)[kLanes], const float* ax, const float* ay,
                                              const float* az, int g, float (*out)[kLanes]) {
    __m128 near[4], far[4];
    plane4(src, at, ax, ay, g, near);
    plane4(src, at + 4, ax, ay, g, far);
    const __m128 a = _mm_loadu_ps(&az[g]), ia = _mm_sub_ps(_mm_set1_ps(1.0f), a);
    for (int c = 0; c < 4; ++c) _mm_storeu_ps(&out[c][g], mix4(near[c], far[c], a, ia));
}
#endif

#if defined(__x86_64__) && defined(__GNUC__)
// The blends of bilinear4()/trilinear4() eight lanes at a time for the
// AVX2 build: lanes g..g+3 in the low halves of the registers, g+4..g+7 in
// the high ones, transposed within each half; the same products and sums
// per lane, so the same bits. Only one image (every lane's texels). The
// loops over channels and corners are unrolled by pragma: at -O2 GCC kept
// their __m256 arrays on the stack (perf: the blends went through memory).
#define GLSLRUN_AVX2 __attribute__((target("avx2")))
[[gnu::always_inline]] GLSLRUN_AVX2 inline void load8(const glm::vec4* texels, const int* at, int g, __m256* ch) {
    __m256 r[4];
    #pragma GCC unroll 4
    for (int j = 0; j < 4; ++j)
        r[j] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(&texels[at[g + j]].x)),
                                    _mm_loadu_ps(&texels[at[g + 4 + j]].x), 1);
    transpose8(r, ch);
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline __m256 mix8(__m256 x, __m256 y, __m256 a, __m256 b) {
    return _mm256_add_ps(_mm256_mul_ps(x, b), _mm256_mul_ps(y, a));
}

// One row's two corners (offsets at0, at1) mixed by a: row by row, so that
// the corners fit in the 16 registers (the four corners at once spilled).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void row8(const glm::vec4* texels, const int* at0, const int* at1, int g,
                                                     __m256 a, __m256 ia, __m256* row) {
    __m256 x[4], y[4];
    load8(texels, at0, g, x);
    load8(texels, at1, g, y);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) row[c] = mix8(x[c], y[c], a, ia);
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline void plane8(const glm::vec4* texels, const int (*at)[kLanes],
                                                       const float* ax, const float* ay, int g, __m256* plane) {
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 a = _mm256_loadu_ps(&ax[g]), b = _mm256_loadu_ps(&ay[g]);
    const __m256 ia = _mm256_sub_ps(one, a), ib = _mm256_sub_ps(one, b);
    __m256 row0[4], row1[4];
    row8(texels, at[0], at[1], g, a, ia, row0);
    row8(texels, at[2], at[3], g, a, ia, row1);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) plane[c] = mix8(row0[c], row1[c], b, ib);
}

// `az` null: bilinear (corners at[0..3]); else trilinear (at[4..7] the plane at z1).
GLSLRUN_AVX2 void blend8(const glm::vec4* texels, const int (*at)[kLanes], const float* ax, const float* ay,
                         const float* az, int g, float (*out)[kLanes]) {
    __m256 near[4];
    plane8(texels, at, ax, ay, g, near);
    if (!az) {
        #pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) _mm256_storeu_ps(&out[c][g], near[c]);
        return;
    }
    __m256 far[4];
    plane8(texels, at + 4, ax, ay, g, far);
    const __m256 a = _mm256_loadu_ps(&az[g]), ia = _mm256_sub_ps(_mm256_set1_ps(1.0f), a);
    #pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) _mm256_storeu_ps(&out[c][g], mix8(near[c], far[c], a, ia));
}

// One axis's LINEAR indices and weight for lanes g..g+7: linear_lanes()'s
// (or rect_lanes()'s) values, REPEAT's far lanes (NaN, huge coordinates)
// through repeat_index() as there.
template <TextureWrap kWrap, bool kRect>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void linear8(const float* __restrict s, int n, int g, int* __restrict i0,
                                                        int* __restrict i1, float* __restrict a) {
    if constexpr (!kRect && kWrap == TextureWrap::Repeat) {
        alignas(32) int raw[8];
        int far = 0;
        for (int k = 0; k < 8; ++k) {
            const float u = repeat_position<true>(s[g + k], float(n));
            raw[k] = floor_int<true>(u);
            a[g + k] = u - floor_t<true>(u);
            i0[g + k] = repeat_near(raw[k], n);
            i1[g + k] = repeat_near(raw[k] + 1, n);
            far |= int(!repeat_is_near(raw[k], n)) | int(!repeat_is_near(raw[k] + 1, n));
        }
        if (far)
            for (int k = 0; k < 8; ++k) {
                i0[g + k] = repeat_index(raw[k], n);
                i1[g + k] = repeat_index(raw[k] + 1, n);
            }
    } else {
        for (int k = g; k < g + 8; ++k) {
            const LinearAxis axis = kRect ? rect_linear_axis<kWrap, true>(s[k], n) : linear_axis<kWrap, true>(s[k], n);
            i0[k] = axis.i0;
            i1[k] = axis.i1;
            a[k] = axis.a;
        }
    }
}

#include "runtime/sampling_batch_lanes8.h"  // the eight-lane steps of the lookups below

#include "runtime/sampling_batch_cube.h"  // cube maps, eight lanes at a time
#undef GLSLRUN_AVX2
#endif

// Lane i's linear lookup of `image` (dims 1 to 3) from the indices and
// weights in l, lane by lane: sample_linear()'s arithmetic.
[[gnu::always_inline]] inline Texel linear_lane(const Lookup& lk, const TextureImage& image, const Lanes& l, int i,
                                                int dims) {
    if (dims == 1) return mix(fetch(lk, image, l.x0[i], 0, 0), fetch(lk, image, l.x1[i], 0, 0), l.ax[i]);
    auto plane = [&](int k) {
        const Texel row0 = mix(fetch(lk, image, l.x0[i], l.y0[i], k), fetch(lk, image, l.x1[i], l.y0[i], k), l.ax[i]);
        const Texel row1 = mix(fetch(lk, image, l.x0[i], l.y1[i], k), fetch(lk, image, l.x1[i], l.y1[i], k), l.ax[i]);
        return mix(row0, row1, l.ay[i]);
    };
    if (dims == 2) return plane(0);
    return mix(plane(l.z0[i]), plane(l.z1[i]), l.az[i]);
}

// One level per lane (`level`; lanes whose `take` is 0 are skipped) into
// out[c][i]: sample_level()'s filtering. Four lanes at a time where all
// four blend bilinearly and no texel can be the border or a comparison;
// the others lane by lane.
void sample_levels(const Texture& texture, const Lookup& proto, Lanes& l, const int* level, const int* take,
                   float (*out)[kLanes]) {
    const int dims = texture_dims(texture.target());
    const bool dims2 = dims > 1;
    const TextureImage* faces[6] = {};
    for (int f = 0; f < texture.faces() && f < 6; ++f) faces[f] = texture.levels(f).data();
    int any_linear = 0, any_nearest = 0;
    for (int i = 0; i < kLanes; ++i) {
        // A skipped lane reads the size of its first level, which exists (the sizes must not be 0).
        const TextureImage* image = faces[l.face[i]] + (take[i] ? level[i] : l.level[0][i]);
        l.image[i] = take[i] ? image : nullptr;
        l.sized[i] = image;
        l.width[i] = image->width;
        l.height[i] = image->height;
        l.depth[i] = image->depth;
        any_linear |= take[i] & l.linear[i];
        any_nearest |= take[i] & (l.linear[i] ^ 1);
    }
    const SamplerState& st = texture.sampler;
    alignas(32) int nx[kLanes], ny[kLanes], nz[kLanes];
    if (any_nearest) {
        axis_indices(st.wrap_s, false, l.s, LaneSizes{l.width}, nx, nullptr, nullptr);
        if (dims2) axis_indices(st.wrap_t, false, l.t, LaneSizes{l.height}, ny, nullptr, nullptr);
        if (dims > 2) axis_indices(st.wrap_r, false, l.r, LaneSizes{l.depth}, nz, nullptr, nullptr);
    }
    if (any_linear) {
        axis_indices(st.wrap_s, true, l.s, LaneSizes{l.width}, l.x0, l.x1, l.ax);
        if (dims2) axis_indices(st.wrap_t, true, l.t, LaneSizes{l.height}, l.y0, l.y1, l.ay);
        if (dims > 2) axis_indices(st.wrap_r, true, l.r, LaneSizes{l.depth}, l.z0, l.z1, l.az);
    }
#if defined(__SSE2__)
    const bool four = any_linear && dims == 2 && !proto.compare && !may_border(st.wrap_s) && !may_border(st.wrap_t);
#else
    const bool four = false;
#endif
    alignas(32) int at[4][kLanes];
    if (four)
        for (int i = 0; i < kLanes; ++i) {
            const int row0 = l.y0[i] * l.width[i], row1 = l.y1[i] * l.width[i];  // below 2^28: no overflow
            at[0][i] = row0 + l.x0[i];
            at[1][i] = row0 + l.x1[i];
            at[2][i] = row1 + l.x0[i];
            at[3][i] = row1 + l.x1[i];
        }
    Lookup lk = proto;
    for (int g = 0; g < kLanes; g += 4) {
#if defined(__SSE2__)
        // A skipped lane blends too, on its own indices (in range: no border), and is selected away.
        const auto blends = [&](int i) { return (take[i] ^ 1) | l.linear[i]; };
        if (four && (blends(g) & blends(g + 1) & blends(g + 2) & blends(g + 3)) &&
            (take[g] | take[g + 1] | take[g + 2] | take[g + 3])) {
            const auto src = [&](int i) { return l.sized[i]->texels.data(); };
            bilinear4(src, at, l.ax, l.ay, g, out);
            continue;
        }
#endif
        for (int i = g; i < g + 4; ++i) {
            if (!l.image[i]) {
                put(out, i, splat_texel(0.0f));  // defined, for the channel loops that select it away
                continue;
            }
            const TextureImage& image = *l.image[i];
            lk.ref = l.ref[i];
            if (!l.linear[i]) put(out, i, fetch(lk, image, nx[i], dims2 ? ny[i] : 0, dims > 2 ? nz[i] : 0));
            else put(out, i, linear_lane(lk, image, l, i, dims));
        }
    }
}

// Whether every lane of a lookup reads one image with one filter: not a
// cube map (a face per lane), and no level-of-detail decision (no mipmaps,
// one filter within a level for both sides of §3.8.9): filter() then samples
// level_base with that filter whatever lambda is.
bool one_image(const Texture& texture) {
    return texture.target() != TextureTarget::Cube && !lod_matters(texture.sampler);
}

// fetch() of every lane's texel (nx, ny, nz) where none is the border's,
// into l.rgba: skipped lanes read in-range texels too, selected away later.
// A comparison reads the depths alone and compares them in a lane loop, the
// function chosen once.
void nearest_in_image(const TextureImage& image, const Lookup& proto, int dims, const int* nx, const int* ny,
                      const int* nz, const Lanes& l, float (*out)[kLanes]) {
    alignas(32) int at[kLanes];
    const int w = image.width, h = image.height;  // w * h * d below 2^24 (limits.md): no overflow
    for (int i = 0; i < kLanes; ++i) at[i] = ((dims > 2 ? nz[i] : 0) * h + (dims > 1 ? ny[i] : 0)) * w + nx[i];
    const glm::vec4* texels = image.texels.data();
    if (!proto.compare) {
        for (int i = 0; i < kLanes; ++i) put(out, i, texel_of(texels[at[i]]));
        return;
    }
    alignas(32) float depth[kLanes];
    for (int i = 0; i < kLanes; ++i) depth[i] = texels[at[i]].r;
    float* __restrict result = out[0];
    const float* __restrict ref = l.ref;
    const auto compare = [&](auto func) {
        for (int i = 0; i < kLanes; ++i) result[i] = compare_depth(func(), ref[i], depth[i]);
    };
    switch (proto.st->compare_func) {
    case CompareFunc::Never: compare([] { return CompareFunc::Never; }); break;
    case CompareFunc::Less: compare([] { return CompareFunc::Less; }); break;
    case CompareFunc::Equal: compare([] { return CompareFunc::Equal; }); break;
    case CompareFunc::Lequal: compare([] { return CompareFunc::Lequal; }); break;
    case CompareFunc::Greater: compare([] { return CompareFunc::Greater; }); break;
    case CompareFunc::Notequal: compare([] { return CompareFunc::Notequal; }); break;
    case CompareFunc::Gequal: compare([] { return CompareFunc::Gequal; }); break;
    case CompareFunc::Always: compare([] { return CompareFunc::Always; }); break;
    }
    for (int c = 1; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) out[c][i] = result[i];  // fetch()'s splat
}

// The lookups of every lane in one image with one filter (LINEAR or
// NEAREST within the level) into out (the lanes whose `active` is 0 too:
// they are selected away). The sizes are the image's, not the lanes', and
// nothing per lane decides a level or a filter. Linear blends without the
// border or a comparison go four or eight lanes at a time; the others lane
// by lane. `coord`: the lanes' (s, t, r) on the image; `kRect`: a
// rectangle's unnormalized (u, v).
template <bool kAvx2, bool kRect = false>
[[gnu::always_inline]] inline void sample_image(const TextureImage& image, Lookup proto, bool linear, const float* const* coord, const int* active,
                  Lanes& l, float (*out)[kLanes]) {
    const SamplerState& st = *proto.st;
    const int dims = proto.dims;
    const OneSize w{image.width}, h{image.height}, d{image.depth};
    if (!linear) {
        alignas(32) int nx[kLanes], ny[kLanes], nz[kLanes];
        axis_indices<kAvx2, kRect>(st.wrap_s, false, coord[0], w, nx, nullptr, nullptr);
        if (dims > 1) axis_indices<kAvx2, kRect>(st.wrap_t, false, coord[1], h, ny, nullptr, nullptr);
        if (dims > 2) axis_indices<kAvx2, kRect>(st.wrap_r, false, coord[2], d, nz, nullptr, nullptr);
        // NEAREST meets the border under CLAMP_TO_BORDER only (CLAMP clamps to the edge texels).
        const bool border = st.wrap_s == TextureWrap::ClampToBorder ||
                            (dims > 1 && st.wrap_t == TextureWrap::ClampToBorder) ||
                            (dims > 2 && st.wrap_r == TextureWrap::ClampToBorder);
        // The axes the target lacks read nx (selected away): never an unset array.
        if (!border) return nearest_in_image(image, proto, dims, nx, dims > 1 ? ny : nx, dims > 2 ? nz : nx, l, out);
        for (int i = 0; i < kLanes; ++i) {
            proto.ref = l.ref[i];
            if (!active[i]) put(out, i, splat_texel(0.0f));  // defined, for the loops that select it away
            else put(out, i, fetch(proto, image, nx[i], dims > 1 ? ny[i] : 0, dims > 2 ? nz[i] : 0));
        }
        return;
    }
    axis_indices<kAvx2, kRect>(st.wrap_s, true, coord[0], w, l.x0, l.x1, l.ax);
    if (dims > 1) axis_indices<kAvx2, kRect>(st.wrap_t, true, coord[1], h, l.y0, l.y1, l.ay);
    if (dims > 2) axis_indices<kAvx2, kRect>(st.wrap_r, true, coord[2], d, l.z0, l.z1, l.az);
    const bool border = may_border(st.wrap_s) || (dims > 1 && may_border(st.wrap_t)) ||
                        (dims > 2 && may_border(st.wrap_r));
#if defined(__SSE2__)
    if (dims > 1 && !border && !proto.compare) {
        // Every index is in the image: corner k's offsets, x0/x1 by bit 0, y0/y1 by bit 1, z0/z1 by bit 2.
        alignas(32) int at[8][kLanes];
        const int wi = w.n, hi = h.n;  // w * h * d below 2^24 (limits.md): no overflow
        for (int i = 0; i < kLanes; ++i) {
            const int z0 = dims > 2 ? l.z0[i] * hi : 0;
            const int r00 = (z0 + l.y0[i]) * wi, r01 = (z0 + l.y1[i]) * wi;
            at[0][i] = r00 + l.x0[i];
            at[1][i] = r00 + l.x1[i];
            at[2][i] = r01 + l.x0[i];
            at[3][i] = r01 + l.x1[i];
        }
        if (dims > 2)
            for (int i = 0; i < kLanes; ++i) {
                const int z1 = l.z1[i] * hi;
                const int r10 = (z1 + l.y0[i]) * wi, r11 = (z1 + l.y1[i]) * wi;
                at[4][i] = r10 + l.x0[i];
                at[5][i] = r10 + l.x1[i];
                at[6][i] = r11 + l.x0[i];
                at[7][i] = r11 + l.x1[i];
            }
        const glm::vec4* texels = image.texels.data();
        static_assert(kLanes % 8 == 0, "the blends take lanes 4 or 8 at a time");
        const int step = kAvx2 ? 8 : 4;
        for (int g = 0; g < kLanes; g += step) {
            int any = 0;
            for (int i = g; i < g + step; ++i) any |= active[i];
            if (!any) {
                for (int i = g; i < g + step; ++i) put(out, i, splat_texel(0.0f));  // selected away
                continue;
            }
#if defined(__x86_64__) && defined(__GNUC__)
            if constexpr (kAvx2) {
                blend8(texels, at, l.ax, l.ay, dims > 2 ? l.az : nullptr, g, out);
                continue;
            }
#endif
            const auto src = [texels](int) { return texels; };
            if (dims == 2) bilinear4(src, at, l.ax, l.ay, g, out);
            else trilinear4(src, at, l.ax, l.ay, l.az, g, out);
        }
        return;
    }
#endif
    for (int i = 0; i < kLanes; ++i) {
        proto.ref = l.ref[i];
        if (!active[i]) put(out, i, splat_texel(0.0f));
        else put(out, i, linear_lane(proto, image, l, i, dims));
    }
}

// The lookups of a one_image() texture into l.rgba: its level_base with
// the mag filter (the min filter's too).
template <bool kAvx2>
void sample_one_image(const Texture& texture, const BatchLookup& lk, const int* active, Lanes& l) {
    const SamplerState& st = texture.sampler;
    const Lookup proto{&texture, &st, 0, texture_dims(texture.target()), glm::vec3(0.0f),
                       texture.depth() && st.compare, 0.0f};
    sample_image<kAvx2>(texture.levels(0)[size_t(st.base_level)], proto, linear_within_level(st.mag_filter),
                        lk.coord, active, l, l.rgba);
}

// A rectangle's lookups into l.rgba (sample_rect_lane()'s rules): one image,
// one level; the magnification switch (c = 0) per lane only where the two
// filters differ, each filter's lanes then sampled apart and selected.
template <bool kAvx2>
void sample_rect(const Texture& texture, const BatchLookup& lk, const int* active, Lanes& l) {
    const SamplerState& st = texture.sampler;
    const Lookup proto{&texture, &st, 0, 2, glm::vec3(0.0f), texture.depth() && st.compare, 0.0f};
    const TextureImage& image = texture.levels(0)[0];
    const bool mag_linear = linear_within_level(st.mag_filter);
    if (mag_linear == linear_within_level(st.min_filter))
        return sample_image<kAvx2, true>(image, proto, mag_linear, lk.coord, active, l, l.rgba);
    lambdas(texture, lk, l);
    alignas(32) int mag[kLanes], min[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        const int magnified = int(l.lambda[i] <= 0.0f);
        mag[i] = active[i] & magnified;
        min[i] = active[i] & (magnified ^ 1);
    }
    sample_image<kAvx2, true>(image, proto, mag_linear, lk.coord, mag, l, l.rgba);
    sample_image<kAvx2, true>(image, proto, !mag_linear, lk.coord, min, l, l.second);
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) l.rgba[c][i] = min[i] ? l.second[c][i] : l.rgba[c][i];
}

// The first active lane where every active lane has its face, its level(s)
// and its filter: one image per level for the whole batch (a smooth
// surface's common case); else -1.
int uniform_lane(const Lanes& l, const int* active) {
    int first = -1;
    for (int i = 0; i < kLanes && first < 0; ++i)
        if (active[i]) first = i;
    if (first < 0) return -1;
    const int face = l.face[first], d0 = l.level[0][first], d1 = l.level[1][first], linear = l.linear[first];
    int differ = 0;
    for (int i = 0; i < kLanes; ++i)
        differ |= active[i] & int((l.face[i] != face) | (l.level[0][i] != d0) | (l.level[1][i] != d1) |
                                  (l.linear[i] != linear));
    return differ ? -1 : first;
}

// Lanes of several levels or faces: each lane's level(s) from its lambda
// (filter()'s decisions), sampled level by level, then mixed. Where every
// active lane reads the same face and level(s) with one filter, each level
// is one image for the batch (sample_image(): the same indices and blends,
// the sizes hoisted, eight lanes at a time under AVX2).
template <bool kAvx2>
void sample_levels_of_lanes(const Texture& texture, const BatchLookup& lk, const int* active, Lanes& l) {
    if (texture.target() == TextureTarget::Cube) cube_coords(lk, l);
    else plain_coords(lk, l);
    lambdas(texture, lk, l);
    choose_levels(texture, l);
    alignas(32) int second[kLanes];
    int two = 0;
    for (int i = 0; i < kLanes; ++i) {
        second[i] = active[i] & int(l.level[1][i] >= 0);
        two |= second[i];
    }
    // make_lookup()'s state of every lane; the face and (s, t) are the lanes'.
    const SamplerState& st = texture.sampler;
    const Lookup proto{&texture, &st, 0, texture_dims(texture.target()), glm::vec3(0.0f),
                       texture.depth() && st.compare, 0.0f};
    const int u = uniform_lane(l, active);
    const float* const coord[3] = {l.s, l.t, l.r};
    const auto level = [&](int k, const int* take, float (*out)[kLanes]) {
        if (u < 0) return sample_levels(texture, proto, l, l.level[k], take, out);
        const TextureImage& image = texture.levels(l.face[u])[size_t(l.level[k][u])];
        sample_image<kAvx2>(image, proto, l.linear[u] != 0, coord, take, l, out);
    };
    level(0, active, l.rgba);
    if (!two) return;
    level(1, second, l.second);
    // filter()'s mix() of the two levels, channel by channel.
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) {
            const float w = l.mip_weight[i];
            const float blend = l.rgba[c][i] * (1.0f - w) + l.second[c][i] * w;
            l.rgba[c][i] = second[i] ? blend : l.rgba[c][i];
        }
}

// `kAvx2`: the AVX2 build (run_avx2), which blends eight lanes at a time.
template <bool kAvx2>
[[gnu::always_inline]] inline void run(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                       float (*out)[kLanes]) {
#if defined(__x86_64__) && defined(__GNUC__)
    if constexpr (kAvx2)
        if (sample_cube_direct(texture, lk, lanes, out)) return;
#endif
    Lanes l;
    if (lk.ref)
        for (int i = 0; i < kLanes; ++i) l.ref[i] = unorm(lk.ref[i]);
    else
        for (int i = 0; i < kLanes; ++i) l.ref[i] = 0.0f;  // unorm(0)
    alignas(32) int active[kLanes];
    for (int base = 0; base < kLanes; base += 32) {  // bit tests against a table: the loop vectorises
        const uint32_t bits = uint32_t(lanes >> base);
        for (int i = 0; i < std::min(32, kLanes - base); ++i) active[base + i] = (bits & kLaneBit[size_t(i)]) != 0;
    }
    if (texture.target() == TextureTarget::Rect) sample_rect<kAvx2>(texture, lk, active, l);
    else if (one_image(texture)) sample_one_image<kAvx2>(texture, lk, active, l);
    else sample_levels_of_lanes<kAvx2>(texture, lk, active, l);
    const SamplerState& st = texture.sampler;
    if (texture.depth())
        for (int i = 0; i < kLanes; ++i)
            if (active[i]) put(l.rgba, i, texel_of(expand_depth(st.depth_mode, l.rgba[0][i])));
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) out[c][i] = active[i] ? canonical_nan(l.rgba[c][i]) : out[c][i];
}

void run_baseline(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    run<false>(texture, lk, lanes, out);
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same code compiled for AVX2 (no FMA: the same bits), as the
// interpreter's kernels are (runtime/interp_kernels.h).
__attribute__((target("avx2"), flatten)) void run_avx2(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                                       float (*out)[kLanes]) {
    run<true>(texture, lk, lanes, out);
}
#endif

}  // namespace

bool batch_samples(const Texture& texture) {
    // Array textures (a layer per lane) keep the per-lane path.
    return texture.target() != TextureTarget::Tex1DArray && texture.target() != TextureTarget::Tex2DArray;
}

BatchKernel cube_kernel(const Texture& texture) {
#if defined(__x86_64__) && defined(__GNUC__)
    return cube_direct_kernel(texture);
#else
    (void)texture;
    return nullptr;
#endif
}

void sample_batch(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes], bool avx2) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (avx2 && direct_samples(texture)) return sample_direct(texture, lookup, lanes, out);
    if (avx2)
        if (const BatchKernel kernel = direct1d_kernel(texture)) return kernel(texture, lookup, lanes, out);
    if (avx2 && mip2d_samples(texture)) return sample_mip2d(texture, lookup, lanes, out);
    if (avx2 && direct3d_samples(texture)) return sample_direct3d(texture, lookup, lanes, out);
    if (avx2 && shadow8_samples(texture, lookup)) return sample_shadow8(texture, lookup, lanes, out);
    if (avx2) return run_avx2(texture, lookup, lanes, out);
#endif
    (void)avx2;
    run_baseline(texture, lookup, lanes, out);
}

bool batch_reads_quad_leaders(const Texture& texture, bool avx2) {
#if defined(__x86_64__) && defined(__GNUC__)
    return avx2 && !direct_samples(texture) && mip2d_samples(texture);  // sample_batch()'s order
#else
    (void)texture;
    (void)avx2;
    return false;
#endif
}

}  // namespace glslrun::rt
