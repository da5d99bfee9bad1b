// The batched sampler (see sampling_batch.h). Each step is a loop over all
// kLanes lanes with the texture's state hoisted out of it: the wrap modes
// are template arguments, the filters and the target are decided once per
// batch. Lanes outside the mask compute too (their operands are whatever the
// registers hold: every step is safe for any float), but fetch nothing.
#include "runtime/sampling_batch.h"

#include "runtime/sampling_rules.h"

namespace glslrun::rt {

using namespace sampling;

namespace {

// What each lane carries from one step to the next.
struct Lanes {
    alignas(32) float s[kLanes], t[kLanes];  // (s, t) on the image (cube: on the face)
    alignas(32) int face[kLanes];
    alignas(32) float lambda[kLanes];
    alignas(32) int level[2][kLanes];    // level[1] < 0: one level only
    alignas(32) float mip_weight[kLanes];  // of level[1]
    alignas(32) int linear[kLanes];        // LINEAR within the level (else NEAREST)
    alignas(32) float ref[kLanes];         // the depth reference, clamped to [0, 1]
    // Per level pass: the lane's image, its size, and the texel indices and weights.
    const TextureImage* image[kLanes];  // null where the lane is skipped
    const TextureImage* sized[kLanes];  // the image whose size the lane's indices use: never null
    alignas(32) int width[kLanes], height[kLanes];
    alignas(32) int x0[kLanes], x1[kLanes], y0[kLanes], y1[kLanes];
    alignas(32) float ax[kLanes], ay[kLanes];
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
    for (int i = 0; i < kLanes; ++i) {
        l.face[i] = 0;
        l.s[i] = cs[i];
        l.t[i] = ct[i];
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
            const glm::vec3 size = image_size(*level_image(texture, 0, st.base_level));
            const int dims = texture_dims(texture.target());
            const float* __restrict dxs = lk.ddx[0];
            const float* __restrict dxt = lk.ddx[1];
            const float* __restrict dys = lk.ddy[0];
            const float* __restrict dyt = lk.ddy[1];
            for (int i = 0; i < kLanes; ++i)
                lambda[i] = lod_rule({dxs[i], dxt[i], 0.0f}, {dys[i], dyt[i], 0.0f}, size, dims);
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
    const SamplerState& st = texture.sampler;
    const int base = st.base_level;
    const float c = mag_threshold(st);
    const int linear_mag = linear_within_level(st.mag_filter), linear_min = linear_within_level(st.min_filter);
    const bool mipmap = is_mipmap_filter(st.min_filter);
    const bool nearest_mip =
        st.min_filter == TextureFilter::NearestMipmapNearest || st.min_filter == TextureFilter::LinearMipmapNearest;
    const int q = mipmap ? last_mip_level(texture.levels(0)[size_t(base)], st) : base;
    for (int i = 0; i < kLanes; ++i) {
        const float lambda = l.lambda[i];
        const bool mag = lambda <= c;
        const bool minify = !mag && mipmap;
        const bool last = float(base) + lambda >= float(q);
        const float whole = floor_f(lambda);
        // lambda is finite: every candidate is computed, then selected (the loop vectorises).
        const int linear_level = last ? q : base + int(whole);
        const int d0 = !minify ? base : (nearest_mip ? nearest_mip_level(lambda, base, q) : linear_level);
        const bool two = minify && !nearest_mip && !last;
        l.linear[i] = mag ? linear_mag : linear_min;
        l.level[0][i] = d0;
        l.level[1][i] = two ? d0 + 1 : -1;
        l.mip_weight[i] = two ? lambda - whole : 0.0f;
    }
}

// REPEAT's indices for every lane from the unwrapped ones (`raw`, and
// raw + 1 where `second`): repeat_near() in a vectorised loop, then
// repeat_index() where some lane is far out (NaN or huge coordinates).
// Separate loops: together, the vectoriser refused them.
void repeat_lanes(const int* __restrict raw, const int* __restrict n, int offset, int* __restrict out) {
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
template <TextureWrap kWrap>
void nearest_lanes(const float* __restrict s, const int* __restrict n, int* __restrict out) {
    if constexpr (kWrap == TextureWrap::Repeat) {
        alignas(32) int raw[kLanes];
        for (int i = 0; i < kLanes; ++i) raw[i] = floor_int((s[i] - floor_f(s[i])) * float(n[i]));
        repeat_lanes(raw, n, 0, out);
    } else {
        for (int i = 0; i < kLanes; ++i) out[i] = nearest_index<kWrap>(s[i], n[i]);
    }
}

// LINEAR's two indices and weight on one axis for every lane: linear_axis<kWrap>().
template <TextureWrap kWrap>
void linear_lanes(const float* __restrict s, const int* __restrict n, int* __restrict i0, int* __restrict i1,
                  float* __restrict a) {
    if constexpr (kWrap == TextureWrap::Repeat) {
        alignas(32) int raw[kLanes];
        for (int i = 0; i < kLanes; ++i) {
            const float u = repeat_position(s[i], float(n[i]));
            raw[i] = floor_int(u);
            a[i] = u - floor_f(u);
        }
        repeat_lanes(raw, n, 0, i0);
        repeat_lanes(raw, n, 1, i1);
    } else {
        for (int i = 0; i < kLanes; ++i) {
            const LinearAxis axis = linear_axis<kWrap>(s[i], n[i]);
            i0[i] = axis.i0;
            i1[i] = axis.i1;
            a[i] = axis.a;
        }
    }
}

void axis_indices(TextureWrap wrap, bool linear, const float* s, const int* n, int* i0, int* i1, float* a) {
    with_wrap(wrap, [&]<TextureWrap kWrap>() {
        if (linear) linear_lanes<kWrap>(s, n, i0, i1, a);
        else nearest_lanes<kWrap>(s, n, i0);
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
// sample_linear()'s bilinear blend for the four lanes from g, channel by
// channel: the same products and sums as mix() of four-channel texels, with
// the lanes side by side. `at[k]`: the offsets of corner k, (x0, y0), (x1, y0),
// (x0, y1), (x1, y1), in texels; none is the border's. Skipped lanes read
// texels of the image their indices were computed for.
void bilinear4(const Lanes& l, const int (*at)[kLanes], int g, float (*out)[kLanes]) {
    __m128 corner[4][4];  // [corner][channel]
    for (int k = 0; k < 4; ++k) {
        __m128 t0 = _mm_loadu_ps(&l.sized[g]->texels[size_t(at[k][g])].x);
        __m128 t1 = _mm_loadu_ps(&l.sized[g + 1]->texels[size_t(at[k][g + 1])].x);
        __m128 t2 = _mm_loadu_ps(&l.sized[g + 2]->texels[size_t(at[k][g + 2])].x);
        __m128 t3 = _mm_loadu_ps(&l.sized[g + 3]->texels[size_t(at[k][g + 3])].x);
        _MM_TRANSPOSE4_PS(t0, t1, t2, t3);
        corner[k][0] = t0;
        corner[k][1] = t1;
        corner[k][2] = t2;
        corner[k][3] = t3;
    }
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 ax = _mm_loadu_ps(&l.ax[g]), ay = _mm_loadu_ps(&l.ay[g]);
    const __m128 bx = _mm_sub_ps(one, ax), by = _mm_sub_ps(one, ay);
    for (int c = 0; c < 4; ++c) {
        const __m128 row0 = _mm_add_ps(_mm_mul_ps(corner[0][c], bx), _mm_mul_ps(corner[1][c], ax));
        const __m128 row1 = _mm_add_ps(_mm_mul_ps(corner[2][c], bx), _mm_mul_ps(corner[3][c], ax));
        _mm_storeu_ps(&out[c][g], _mm_add_ps(_mm_mul_ps(row0, by), _mm_mul_ps(row1, ay)));
    }
}
#endif

// One level per lane (`level`; lanes whose `take` is 0 are skipped) into
// out[c][i]: sample_level()'s filtering. Four lanes at a time where all
// four blend bilinearly and no texel can be the border or a comparison;
// the others lane by lane.
void sample_levels(const Texture& texture, const Lookup& proto, Lanes& l, const int* level, const int* take,
                   float (*out)[kLanes]) {
    const bool dims2 = texture_dims(texture.target()) > 1;
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
        any_linear |= take[i] & l.linear[i];
        any_nearest |= take[i] & (l.linear[i] ^ 1);
    }
    const SamplerState& st = texture.sampler;
    alignas(32) int nx[kLanes], ny[kLanes];
    if (any_nearest) {
        axis_indices(st.wrap_s, false, l.s, l.width, nx, nullptr, nullptr);
        if (dims2) axis_indices(st.wrap_t, false, l.t, l.height, ny, nullptr, nullptr);
    }
    if (any_linear) {
        axis_indices(st.wrap_s, true, l.s, l.width, l.x0, l.x1, l.ax);
        if (dims2) axis_indices(st.wrap_t, true, l.t, l.height, l.y0, l.y1, l.ay);
    }
#if defined(__SSE2__)
    const bool four = any_linear && dims2 && !proto.compare && !may_border(st.wrap_s) && !may_border(st.wrap_t);
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
            bilinear4(l, at, g, out);
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
            if (!l.linear[i]) {
                put(out, i, fetch(lk, image, nx[i], dims2 ? ny[i] : 0, 0));
            } else if (!dims2) {
                put(out, i, mix(fetch(lk, image, l.x0[i], 0, 0), fetch(lk, image, l.x1[i], 0, 0), l.ax[i]));
            } else {
                const Texel row0 =
                    mix(fetch(lk, image, l.x0[i], l.y0[i], 0), fetch(lk, image, l.x1[i], l.y0[i], 0), l.ax[i]);
                const Texel row1 =
                    mix(fetch(lk, image, l.x0[i], l.y1[i], 0), fetch(lk, image, l.x1[i], l.y1[i], 0), l.ax[i]);
                put(out, i, mix(row0, row1, l.ay[i]));
            }
        }
    }
}

[[gnu::always_inline]] inline void run(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                       float (*out)[kLanes]) {
    Lanes l;
    if (texture.target() == TextureTarget::Cube) cube_coords(lk, l);
    else plain_coords(lk, l);
    lambdas(texture, lk, l);
    choose_levels(texture, l);
    if (lk.ref)
        for (int i = 0; i < kLanes; ++i) l.ref[i] = unorm(lk.ref[i]);
    else
        for (int i = 0; i < kLanes; ++i) l.ref[i] = 0.0f;  // unorm(0)
    alignas(32) int active[kLanes], second[kLanes];
    int two = 0;
    for (int i = 0; i < kLanes; ++i) {
        active[i] = int((lanes >> i) & 1);
        second[i] = active[i] & int(l.level[1][i] >= 0);
        two |= second[i];
    }

    // make_lookup()'s state of every lane; the face and (s, t) are the lanes'.
    const SamplerState& st = texture.sampler;
    const Lookup proto{&texture, &st, 0, texture_dims(texture.target()), glm::vec3(0.0f),
                       texture.depth() && st.compare, 0.0f};
    sample_levels(texture, proto, l, l.level[0], active, l.rgba);
    if (two) {
        sample_levels(texture, proto, l, l.level[1], second, l.second);
        // filter()'s mix() of the two levels, channel by channel.
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < kLanes; ++i) {
                const float w = l.mip_weight[i];
                const float blend = l.rgba[c][i] * (1.0f - w) + l.second[c][i] * w;
                l.rgba[c][i] = second[i] ? blend : l.rgba[c][i];
            }
    }
    if (texture.depth())
        for (int i = 0; i < kLanes; ++i)
            if (active[i]) put(l.rgba, i, texel_of(expand_depth(st.depth_mode, l.rgba[0][i])));
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kLanes; ++i) out[c][i] = active[i] ? l.rgba[c][i] : out[c][i];
}

void run_baseline(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    run(texture, lk, lanes, out);
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same code compiled for AVX2 (no FMA: the same bits), as the
// interpreter's kernels are (runtime/interp_kernels.h).
__attribute__((target("avx2"), flatten)) void run_avx2(const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                                                       float (*out)[kLanes]) {
    run(texture, lk, lanes, out);
}
#endif

}  // namespace

bool batch_samples(const Texture& texture) {
    // 3D textures (a third axis and eight texels) keep the per-lane path.
    return texture.target() != TextureTarget::Tex3D;
}

void sample_batch(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes], bool avx2) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (avx2) return run_avx2(texture, lookup, lanes, out);
#endif
    (void)avx2;
    run_baseline(texture, lookup, lanes, out);
}

}  // namespace glslrun::rt
