// NVIDIA's texture filtering, which Precision::Fast follows (SamplingRules::Gpu):
// the rules tools/gpu_probes measured on an H200 with driver 580.159, each
// matching every probe sample (docs/precision.md, "The GPU's texture
// filtering"). Internal to sampling.cpp; the steps are sampling_rules.h's
// (wraps, cube faces, levels), only the arithmetic differs:
//
// - A LINEAR weight is frac(u - 1/2) rounded to 8 bits, ties up: w in 0..256.
// - A bilinear blend weighs the four texels with integers that sum to 256:
//   w11 = round(wx wy / 256) (ties up), w01 = wx - w11, w10 = wy - w11,
//   w00 = 256 - wx - wy + w11.
// - Texels enter as 16-bit values (byte b as 257 b, 1.0 as 65535); a blend is
//   rounded to 16 bits ((sum + 128) >> 8), and the lookup returns r / 65535.
// - lambda = log2(rho) from a table: the exponent of rho plus T[k] / 256 for
//   the top 8 bits k of its significand (kLog2Fraction). The LOD biases are
//   added in 8 fraction bits (toward zero), and lambda after the clamps is
//   truncated to 8 fraction bits.
// - A mipmap blend is one sum over both levels' texels: level d1 weighs
//   256 - w and d1 + 1 weighs w = floor(256 frac(lambda)), each level's
//   share split among its texels by level_weights(), and the sum of 16-bit
//   texels times those integers (256 in all) is rounded once
//   (trilin.frag, trimp.frag: every sample).
//
// - One lambda per 2x2 quad: the implicit LOD takes the quad's first lane's
//   derivatives (its lower row's d/dx, its left column's d/dy) for all four
//   lanes, as coarse derivatives (derivative_lane in sampling.h, which
//   Precise shares with llvmpipe; lod.frag band 4).
// - A *_MIPMAP_NEAREST level is level_base + floor(lambda + 1/2) (ties up).
//
// - rho = max(|J x|, |J y|, 11/16 |J (x + y)|, 11/16 |J (x - y)|) for the
//   texel-space Jacobian J, each length |(a, b)| as max + 11/32 min
//   (gpu_rho() in sampling_rules.h): the screen's diagonals count, so a
//   footprint stretched along one is not underestimated (lodrand.frag: every
//   quad whose derivatives are half texels; 92% of those in steps of 11/16,
//   the rest one or two table steps off).
//
// - A 3D LINEAR lookup is one sum of its eight texels: the planes z0 and z1
//   weigh 256 - wz and wz, each split among its 2x2 texels by
//   level_weights(), as two mipmap levels are (tex3dw.frag: every sample).
//
// The switch-over (c = 0) and texel indices are the Common rules'. Float
// and depth textures keep those rules (their probe, texkinds.frag, showed
// 8-bit weights but not every blend), and so do the unmeasured rectangles:
// filtered() says which follow this file. A 3D texture's rho takes its
// lengths as max + 11/32 mid + 1/4 min (gpu_rho(); lod3d.frag: every pixel).
#pragma once
#include <bit>
#include <cstdint>

#include "runtime/sampling_rules.h"

namespace glslrun::rt::sampling::gpu {

// Whether a lookup of `texture` follows the GPU's rules.
inline bool filtered(const Texture& texture) {
    const TextureTarget target = texture.target();
    return texture.format() == TextureFormat::RGBA8 && target != TextureTarget::Rect;
}

// 256 * frac(lambda) for a significand 1 + k/256 of rho, as the GPU's level
// of detail gives it (tools/gpu_probes/lod.frag, band 0: rho = 1 + q/8192).
inline constexpr uint8_t kLog2Fraction[256] = {
    0,   2,   4,   5,   6,   8,   9,   11,  12,  13,  15,  16,  18,  19,  20,  22,  23,  24,  26,  27,  28,  30,
    31,  32,  34,  35,  36,  38,  39,  40,  42,  43,  44,  45,  47,  48,  49,  50,  52,  53,  54,  55,  57,  58,
    59,  60,  62,  63,  64,  65,  66,  68,  69,  70,  71,  72,  74,  75,  76,  77,  78,  79,  81,  82,  83,  84,
    85,  86,  88,  89,  90,  91,  92,  93,  94,  95,  97,  98,  99,  100, 101, 102, 103, 104, 105, 106, 107, 109,
    110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131,
    132, 133, 135, 136, 137, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149, 150, 151, 152, 153,
    154, 155, 156, 157, 158, 159, 160, 161, 162, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 173,
    174, 175, 176, 177, 178, 179, 180, 181, 181, 182, 183, 184, 185, 186, 187, 188, 188, 189, 190, 191, 192, 193,
    194, 195, 195, 196, 197, 198, 199, 200, 200, 201, 202, 203, 204, 205, 205, 206, 207, 208, 209, 210, 210, 211,
    212, 213, 214, 214, 215, 216, 217, 218, 218, 219, 220, 221, 222, 222, 223, 224, 225, 226, 226, 227, 228, 229,
    229, 230, 231, 232, 233, 233, 234, 235, 236, 236, 237, 238, 239, 239, 240, 241, 242, 242, 243, 244, 245, 245,
    246, 247, 248, 248, 249, 250, 251, 251, 252, 253, 253, 254, 255, 255,
};

// lambda_base from rho: the exponent plus the table's fraction. Below the
// smallest normal float (and for 0 or NaN) magnification, as lod_from_rho().
inline float lambda_of_rho(float rho) {
    if (!(rho >= 0x1p-126f)) return -kLodLimit;
    const uint32_t bits = std::bit_cast<uint32_t>(rho);
    const int exponent = int(bits >> 23) - 127;  // rho is positive; Inf gives 128
    return std::min(float(exponent) + float(kLog2Fraction[(bits >> 15) & 255u]) * (1.0f / 256.0f), kLodLimit);
}

// lambda after the biases and clamps, truncated to the GPU's 8 fraction bits
// (trilin.frag mode 0: textureLod at every 1/65536 in [-1/2, 7/2) takes
// level floor(lambda) and weight floor(256 frac(lambda)); rounding to
// nearest gave half of them).
inline float quantize_lambda(float lambda) { return floor_f(lambda * 256.0f) * (1.0f / 256.0f); }

// A LOD bias (the shader's, the texture object's) as the GPU adds it: in 8
// fraction bits, truncated toward zero (tribias.frag: shader biases in 1/1024
// steps over [-1, 3), with and without GL_TEXTURE_LOD_BIAS 0.3, every pixel;
// truncating toward -infinity, 84% and 78%; negative object biases were not
// measured). A NaN stays NaN.
inline float quantize_bias(float bias) { return std::trunc(bias * 256.0f) * (1.0f / 256.0f); }

// An 8-bit weight 0..256 for a fraction a in [0, 1]. A NaN coordinate's
// fraction (NaN) weighs 0: the first texel, on every backend (a NaN cast to
// int is undefined behaviour, not the CPU's INT_MIN).
inline int weight8(float a) { return a > 0.0f ? int(std::min(a, 1.0f) * 256.0f + 0.5f) : 0; }

// Channel arithmetic on Texel; every value is a non-negative integer below
// 2^24, so each operation is exact and truncation is floor.
#if defined(__SSE2__)
inline Texel scaled(Texel t, float k) { return _mm_mul_ps(t, _mm_set1_ps(k)); }
inline Texel plus(Texel a, Texel b) { return _mm_add_ps(a, b); }
inline Texel floor_nonneg(Texel t) { return _mm_cvtepi32_ps(_mm_cvttps_epi32(t)); }
inline Texel over_unorm16(Texel t) { return _mm_div_ps(t, _mm_set1_ps(65535.0f)); }
#else
inline Texel scaled(Texel t, float k) { return t * k; }
inline Texel plus(Texel a, Texel b) { return a + b; }
inline Texel floor_nonneg(Texel t) { return glm::floor(t); }
inline Texel over_unorm16(Texel t) { return t / 65535.0f; }
#endif

// A texel (in [0, 1]: k/255, or the clamped border colour) as a 16-bit value.
inline Texel unorm16(Texel t) { return floor_nonneg(plus(scaled(t, 65535.0f), splat_texel(0.5f))); }

// (sum + 128) >> 8: a blend of 16-bit values by weights summing to 256.
inline Texel round_blend(Texel sum) { return floor_nonneg(scaled(plus(sum, splat_texel(128.0f)), 1.0f / 256.0f)); }

// The integer weights of a level's 2x2 texels (t00, t01 in the first row,
// t10, t11 in the second) when the level weighs `share` (0..256) of the
// lookup, from its 8-bit weights wx, wy: the columns take round(wx share /
// 256) and the rest, then each column's second row round(column wy / 256),
// ties up in the second column and down in the first. wx = 256 starts the
// footprint at the second column (its first is then t01's), which rounds as
// a first column. trimp.frag read each texel's weight of a two-level lookup
// (all 8 weights of 262,144 samples at each of textureLod, textureGrad and
// texture() on quads); share 256 gives linear16()'s bilinear weights exactly.
struct TexelWeights {
    int w00, w01, w10, w11;
};
inline TexelWeights level_weights(int wx, int wy, int share) {
    const int x1 = (wx * share + 128) >> 8, x0 = share - x1;
    const int w11 = (x1 * wy + (wx == 256 ? 127 : 128)) >> 8, w10 = (x0 * wy + 127) >> 8;
    return {x0 - w10, x1 - w11, w10, w11};
}

// Plane k's 2x2 texels (columns x, rows y) as 16-bit values times `w`.
template <class Obs>
[[gnu::always_inline]] inline Texel plane_sum(const Lookup& lk, const TextureImage& image, const LinearAxis& x,
                                              const LinearAxis& y, int k, const TexelWeights& w, Obs&& obs) {
    const Texel t00 = unorm16(fetch(lk, image, x.i0, y.i0, k, obs));
    const Texel t01 = unorm16(fetch(lk, image, x.i1, y.i0, k, obs));
    const Texel t10 = unorm16(fetch(lk, image, x.i0, y.i1, k, obs));
    const Texel t11 = unorm16(fetch(lk, image, x.i1, y.i1, k, obs));
    const Texel row0 = plus(scaled(t00, float(w.w00)), scaled(t01, float(w.w01)));
    const Texel row1 = plus(scaled(t10, float(w.w10)), scaled(t11, float(w.w11)));
    return plus(row0, row1);
}

// A level's LINEAR texels as 16-bit values times level_weights(): the sum,
// not yet rounded (exact: below 65535 * 256 < 2^24). A 3D image's planes z0
// and z1 take share - z1 and z1 = round(wz share / 256) (ties up), each
// split over its 2x2 texels as a mipmap level's share is (tex3dw.frag: all
// eight weights of 524,288 lookups of one level; a 3D mipmap blend's
// shares below 256 were not measured).
template <class Obs>
[[gnu::always_inline]] inline Texel linear_sum(const Lookup& lk, const TextureImage& image, int share, Obs&& obs) {
    const LinearAxis x = linear_axis(lk.st->wrap_s, lk.str.x, image.width);
    const int wx = weight8(x.a);
    if (lk.dims == 1) {
        const TexelWeights w = level_weights(wx, 0, share);
        return plus(scaled(unorm16(fetch(lk, image, x.i0, lk.layer_j, lk.layer_k, obs)), float(w.w00)),
                    scaled(unorm16(fetch(lk, image, x.i1, lk.layer_j, lk.layer_k, obs)), float(w.w01)));
    }
    const LinearAxis y = linear_axis(lk.st->wrap_t, lk.str.y, image.height);
    const int wy = weight8(y.a);
    if (lk.dims == 2) return plane_sum(lk, image, x, y, lk.layer_k, level_weights(wx, wy, share), obs);
    const LinearAxis z = linear_axis(lk.st->wrap_r, lk.str.z, image.depth);
    const int z1 = (weight8(z.a) * share + 128) >> 8;
    return plus(plane_sum(lk, image, x, y, z.i0, level_weights(wx, wy, share - z1), obs),
                plane_sum(lk, image, x, y, z.i1, level_weights(wx, wy, z1), obs));
}

// A level's texels (LINEAR or NEAREST) weighing `share` of the lookup, not yet rounded.
template <class Obs>
[[gnu::always_inline]] inline Texel level_sum(const Lookup& lk, int level, bool linear, int share, Obs&& obs) {
    const TextureImage& image = lk.texture->levels(lk.face)[size_t(level)];
    obs.level(level, image, linear);
    return linear ? linear_sum(lk, image, share, obs)
                  : scaled(unorm16(sampling::sample_nearest(lk, image, obs)), float(share));
}

// One level's 16-bit result.
template <class Obs>
[[gnu::always_inline]] inline Texel level16(const Lookup& lk, int level, bool linear, Obs&& obs) {
    return round_blend(level_sum(lk, level, linear, 256, obs));
}

// *_MIPMAP_NEAREST's level: level_base + floor(lambda + 1/2), so that
// lambda = 1/2 takes level_base + 1, where §3.8.8 (ceil(lambda + 1/2) - 1)
// keeps level_base (lod.frag, bands 5 and 7).
inline int nearest_level(float lambda, int base, int q) {
    return std::clamp(base + int(floor_f(lambda + 0.5f)), base, q);
}

// filter() of sampling_rules.h with the GPU's lambda and blends, in 16-bit values.
template <class Obs>
[[gnu::always_inline]] inline Texel filter16(const Lookup& lk, float lambda, Obs&& obs) {
    const SamplerState& st = *lk.st;
    const int base = st.base_level;
    lambda = quantize_lambda(lambda);
    const bool magnified = lambda <= 0.0f;
    obs.filter(lambda, magnified);
    if (magnified) return level16(lk, base, linear_within_level(st.mag_filter), obs);
    const bool linear = linear_within_level(st.min_filter);
    if (!is_mipmap_filter(st.min_filter)) return level16(lk, base, linear, obs);
    const int q = last_mip_level(lk.texture->levels(lk.face)[size_t(base)], st);
    if (st.min_filter == TextureFilter::NearestMipmapNearest || st.min_filter == TextureFilter::LinearMipmapNearest)
        return level16(lk, nearest_level(lambda, base, q), linear, obs);
    if (float(base) + lambda >= float(q)) return level16(lk, q, linear, obs);
    const float whole = floor_f(lambda);
    const int d1 = base + int(whole);
    const int w = weight8(lambda - whole);
    const Texel first = level_sum(lk, d1, linear, 256 - w, obs);
    return round_blend(plus(first, level_sum(lk, d1 + 1, linear, w, obs)));
}

// sample_complete() for a texture that filtered() takes.
template <class Obs = NoObserver>
[[gnu::always_inline]] inline glm::vec4 sample_complete(const Texture& texture, const glm::vec3& coord, float ref,
                                                         float lod, Obs&& obs = Obs{}) {
    const SamplerState& st = texture.sampler;
    const Lookup lk = make_lookup(texture, coord, ref, SamplingRules::Gpu);
    return vec_of(over_unorm16(filter16(lk, clamp_lambda(lod + quantize_bias(st.lod_bias), st), obs)));
}

}  // namespace glslrun::rt::sampling::gpu
