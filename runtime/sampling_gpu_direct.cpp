// The kernels of sampling_gpu_direct.h. One lambda_base per quad
// (gpu_rho() and gpu::lambda_of_rho() of its first lane's derivatives),
// eight quads a register (as two scalar calls per group of eight lanes, a
// tenth of two_units' Fast frame: perf), their first lanes read by
// shuffles and the results kept in registers (a copy of the leaders'
// derivatives through memory was 3% of mip_floor's Fast frame: perf);
// then per group of eight lanes:
// - lambda as sample_gpu_batch()'s lambdas() gives it: each lane's bias
//   and the texture's, each gpu::quantize_bias()'d, the clamps and
//   gpu::quantize_lambda() (truncated to 8 fraction bits);
// - each lane's level(s) and 8-bit mipmap weight as gpu::filter16() picks
//   them, then one pass per first level the group's lanes hold (one on a
//   smooth surface), as sampling_mip2d.cpp does;
// - each level's indices by sampling_direct8.h's steps (the GPU's indices
//   are the Common rules'), the texels as 16-bit values (gpu::unorm16():
//   257 k for an RGBA8 texel k/255, rounded to nearest in one instruction,
//   as sampling_gpu_batch.cpp's load16x8(); the border's value computed
//   once as the per-lane path does), the 8-bit bilinear weights and the
//   (sum + 128) >> 8 blends as float integers below 2^24, so exact in any
//   order; a blend of two levels is one sum over both levels' texels, each
//   level's share (256 - w, w) split by gpu::level_weights(), rounded
//   once; then r / 65535.
// A cube map's lanes take their face and (s, t) on it first, and one pass
// per face and first level (gpu_cube()); a texture without mipmaps
// samples several groups of eight together (gpu_one()).
// Before this, Fast's lookups went through the batched sampler's lane
// arrays step by step: two thirds of two_units' frame (perf), and Fast was
// 0.6x to 0.9x Precise's speed on textured programs.
#include "runtime/sampling_gpu_direct.h"

#include <array>
#include <bit>

#include "runtime/interp_kernels.h"
#include "runtime/sampling_cube8.h"
#include "runtime/sampling_direct8.h"
#include "runtime/sampling_gpu.h"
#include "runtime/sampling_gpu_batch.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

// One level's image as the GPU's fetches read it.
struct Image16 {
    Source src;    // its border is unused: the 16-bit `border` replaces the texel
    Axis w, h;
    V border[4];   // gpu::unorm16() of border_texel()
};

// Each member set once: the aggregate's `{}` of the source's (unused)
// border was a `rep stos` of 448 bytes at every lookup and level pass
// (perf: 4% of post's Fast frame, in run_bound()).
[[gnu::always_inline]] GLSLRUN_AVX2 inline Image16 image16(const glm::vec4* texels, int width, int height,
                                                           const V* border) {
    Image16 im;
    im.src.texels = texels;
    im.src.width = width;
    im.w = {width, splat(float(width))};
    im.h = {height, splat(float(height))};
    for (int c = 0; c < 4; ++c) im.border[c] = border[c];
    return im;
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline Image16 image16(const TextureImage& image, const V* border) {
    return image16(image.texels.data(), image.width, image.height, border);
}

[[gnu::always_inline]] GLSLRUN_AVX2 inline V unorm16x8(V t) {
    return _mm256_round_ps(_mm256_mul_ps(t, splat(65535.0f)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}

// The texels at (x, y) of eight lanes as 16-bit values by channel; where
// kBorder, lanes whose index is kBorder take the border's value (and load texel 0).
template <bool kBorder>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void fetch16(const Image16& im, I x, I y, V* ch) {
    if constexpr (!kBorder) {
        fetch8<false>(im.src, x, y, ch);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) ch[c] = unorm16x8(ch[c]);
    } else {
        const I outside = _mm256_cmpgt_epi32(_mm256_setzero_si256(), _mm256_or_si256(x, y));
        fetch8<false>(im.src, _mm256_andnot_si256(outside, x), _mm256_andnot_si256(outside, y), ch);
        const V take = _mm256_castsi256_ps(outside);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) ch[c] = _mm256_blendv_ps(unorm16x8(ch[c]), im.border[c], take);
    }
}

// gpu::weight8() of eight lanes: a NaN or a <= 0 weighs 0.
[[gnu::always_inline]] GLSLRUN_AVX2 inline I weight8x8(V a) {
    const V zero = _mm256_setzero_ps();
    const V c = _mm256_blendv_ps(zero, _mm256_min_ps(a, splat(1.0f)), _mm256_cmp_ps(a, zero, _CMP_GT_OQ));
    return _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(c, splat(256.0f)), splat(0.5f)));
}

// (sum + 128) >> 8 of exact non-negative float integers (gpu::round_blend()): a floor, in one rounding.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V round_blend8(V sum) {
    return _mm256_round_ps(_mm256_mul_ps(_mm256_add_ps(sum, splat(128.0f)), splat(1.0f / 256.0f)),
                           _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

// The stored texels at (x, y) of eight lanes by channel; where kBorder, a
// lane whose index is kBorder reads 0 (and texel 0's address), and
// `outside` gets its mask (all ones).
template <bool kBorder>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void raw8(const Image16& im, I x, I y, V* ch, V& outside) {
    if constexpr (!kBorder) {
        fetch8<false>(im.src, x, y, ch);
    } else {
        const I o = _mm256_cmpgt_epi32(_mm256_setzero_si256(), _mm256_or_si256(x, y));
        fetch8<false>(im.src, _mm256_andnot_si256(o, x), _mm256_andnot_si256(o, y), ch);
        outside = _mm256_castsi256_ps(o);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) ch[c] = _mm256_andnot_ps(outside, ch[c]);
    }
}

// A row's two texels of LINEAR (columns x.i0 and x.i1, row y) as raw8()
// gives them, into `left` and `right` (their border masks into `out_left`,
// `out_right`); `pairs` (never with kBorder): every lane's two columns are
// neighbours, so each lane's two texels are one load.
template <bool kBorder>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void raw_row8(const Image16& im, const Linear8& x, I y, bool pairs,
                                                         V* left, V* right, V& out_left, V& out_right) {
    if (!kBorder && pairs) return fetch_pairs8(im.src, x.i0, y, left, right);
    raw8<kBorder>(im, x.i0, y, left, out_left);
    raw8<kBorder>(im, x.i1, y, right, out_right);
}

// The 16-bit sum (not yet rounded) of a bilinear footprint from the sum S
// of its stored texels by weights 255 w (border texels 0), the sum `wb` of
// its border texels' weights w and the border's 16-bit value b: 257 K +
// wb b, K = S rounded (see linear_sum16x8()); every term an integer below
// 2^24 (the weights sum to 256 at most), so exact.
template <bool kBorder>
[[gnu::always_inline]] GLSLRUN_AVX2 inline V sum16x8(V sum, V wb, V b) {
    V total = _mm256_mul_ps(_mm256_round_ps(sum, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC), splat(257.0f));
    if constexpr (kBorder) total = _mm256_add_ps(total, _mm256_mul_ps(wb, b));
    return total;
}

// round_blend8(sum16x8<false>(S)) in fewer steps: (257 K + 128) >> 8 is
// K + ((K + 128) >> 8), taken from the bits of S + 2^23, which are
// 0x4B000000 + K (S, below 2^17, is within 0.02 of the integer K, so the
// addition rounds it to K: no tie), then back to float by subtracting
// 2^23 (exact: the result is below 2^16). Five operations, three on the
// float ports, instead of seven (roundps is two), per channel.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V blend16_of_sum8(V sum) {
    const I k = _mm256_castps_si256(_mm256_add_ps(sum, splat(0x1p23f)));
    const I carry = _mm256_srli_epi32(_mm256_sub_epi32(k, splat_i(0x4B000000 - 128)), 8);  // (K + 128) >> 8
    return _mm256_sub_ps(_mm256_castsi256_ps(_mm256_add_epi32(k, carry)), splat(0x1p23f));
}

// gpu::weight8() of eight LINEAR fractions as float integers (0..256).
// kMayNaN: the rule's fraction may be NaN (REPEAT's and MIRRORED_REPEAT's
// of an infinite or NaN coordinate: weight8x8()'s selects); else it lies
// in [0, 1] (a clamped position's: u - floor(u)), where int(a 256 + 1/2)
// is floor(a 256 + 1/2), one rounding in float instead of a conversion to
// integers and back.
template <bool kMayNaN>
[[gnu::always_inline]] GLSLRUN_AVX2 inline V weight8f(V a) {
    if constexpr (kMayNaN) {
        const V zero = _mm256_setzero_ps();
        a = _mm256_blendv_ps(zero, _mm256_min_ps(a, splat(1.0f)), _mm256_cmp_ps(a, zero, _CMP_GT_OQ));
    }
    return _mm256_round_ps(_mm256_add_ps(_mm256_mul_ps(a, splat(256.0f)), splat(0.5f)),
                           _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

// (x + bias) >> 8 of float integers x + bias in [0, 2^24): the product by
// 2^-8 is exact, so its floor is the shift's.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V shift8f(V x, V bias) {
    return _mm256_round_ps(_mm256_mul_ps(_mm256_add_ps(x, bias), splat(1.0f / 256.0f)),
                           _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}

// A footprint's four integer weights, as floats.
struct Weights8 {
    V w00, w01, w10, w11;
};

// gpu::level_weights(wx, wy, share) of eight lanes, from the 8-bit weights
// and the share as float integers: every product is at most 256 * 256, so
// exact, and each shift is shift8f()'s (in integers, the multiplies and
// the conversions to float were the head of each group's chain: perf).
// Without kShare the share is 256, whose weights are the bilinear ones
// (w11 = round(wx wy / 256), the rest by difference: level_weights()'s
// exactly, in fewer steps).
template <bool kShare>
[[gnu::always_inline]] GLSLRUN_AVX2 inline Weights8 weights8(V wx, V wy, V share) {
    const V half = splat(128.0f);
    if constexpr (!kShare) {
        const V w11 = shift8f(_mm256_mul_ps(wx, wy), half);
        return {_mm256_add_ps(_mm256_sub_ps(_mm256_sub_ps(splat(256.0f), wx), wy), w11), _mm256_sub_ps(wx, w11),
                _mm256_sub_ps(wy, w11), w11};
    } else {
        const V x1 = shift8f(_mm256_mul_ps(wx, share), half);
        const V x0 = _mm256_sub_ps(share, x1);
        // Ties down in the second column where wx = 256 (then a first column): 128 - 1.
        const V tie = _mm256_blendv_ps(half, splat(127.0f), _mm256_cmp_ps(wx, splat(256.0f), _CMP_EQ_OQ));
        const V w11 = shift8f(_mm256_mul_ps(x1, wy), tie);
        const V w10 = shift8f(_mm256_mul_ps(x0, wy), splat(127.0f));
        return {_mm256_sub_ps(x0, w10), _mm256_sub_ps(x1, w11), w10, w11};
    }
}

// What linear_sum16x8() gives per channel: the 16-bit sum not yet rounded
// (sum16x8()), that sum rounded as gpu::round_blend() (the lane's 16-bit
// value), or the byte sum S itself, not rounded (only where no index can
// be the border's: a border texel's 16-bit value is no byte's).
enum class Out { Sum, Rounded, Bytes };

template <bool kBorder, Out kOut>
[[gnu::always_inline]] GLSLRUN_AVX2 inline V out_of_sum8(V sum, V wb, V b) {
    static_assert(kOut != Out::Bytes || !kBorder, "a border texel's value is no byte sum");
    if constexpr (kOut == Out::Bytes) return sum;
    else if constexpr (kOut == Out::Rounded && !kBorder) return blend16_of_sum8(sum);
    else if constexpr (kOut == Out::Rounded) return round_blend8(sum16x8<true>(sum, wb, b));
    else return sum16x8<kBorder>(sum, wb, b);
}

// linear_sum16x8()'s sums of the footprint at columns x, rows y by weights
// w (kBorder: some index may be the border's).
template <bool kBorder, bool kOneD, Out kOut>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void footprint_sum16x8(const Image16& im, const Linear8& x, const Linear8& y,
                                                                  const Weights8& w, V* sum) {
    const V k = splat(255.0f);  // 255 w: exact
    // Where every lane's two columns are neighbours, each row's two texels are one load.
    const bool pairs = !kBorder && _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(
                                       x.i1, _mm256_add_epi32(x.i0, splat_i(1))))) == 0xff;
    V p[4], q[4], row0[4];
    V op = _mm256_setzero_ps(), oq = _mm256_setzero_ps();
    raw_row8<kBorder>(im, x, y.i0, pairs, p, q, op, oq);
    const V a00 = _mm256_mul_ps(w.w00, k), a01 = _mm256_mul_ps(w.w01, k);
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) row0[c] = _mm256_add_ps(_mm256_mul_ps(p[c], a00), _mm256_mul_ps(q[c], a01));
    V wb = _mm256_add_ps(_mm256_and_ps(op, w.w00), _mm256_and_ps(oq, w.w01));
    if constexpr (kOneD) {
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) sum[c] = out_of_sum8<kBorder, kOut>(row0[c], wb, im.border[c]);
        return;
    }
    raw_row8<kBorder>(im, x, y.i1, pairs, p, q, op, oq);
    wb = _mm256_add_ps(wb, _mm256_add_ps(_mm256_and_ps(op, w.w10), _mm256_and_ps(oq, w.w11)));
    const V a10 = _mm256_mul_ps(w.w10, k), a11 = _mm256_mul_ps(w.w11, k);
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
        const V row1 = _mm256_add_ps(_mm256_mul_ps(p[c], a10), _mm256_mul_ps(q[c], a11));
        sum[c] = out_of_sum8<kBorder, kOut>(_mm256_add_ps(row0[c], row1), wb, im.border[c]);
    }
}

// gpu::linear_sum() of one image for eight lanes at (s, t) with each
// lane's share (kShare; else 256): 16-bit sums by channel, not yet
// rounded (kOut: see Out). `kOneD`: a 1D image (row 0; t and kT unused), whose blend is
// the bilinear one with wy = 0.
//
// It sums the stored texels, not their 16-bit values: each is k/255 for
// its byte k (store_texel() keeps RGBA8 so), and the sum of 16-bit values,
// sum w_i 257 k_i, is 257 K for the bytes' K = sum w_i k_i, which S = sum
// (255 w_i) t_i gives within 0.02 (each t_i is within 2^-24 relative of
// k_i / 255; each product and partial sum, below 2^16, is rounded within
// 2^-9): rounded to nearest, exactly K. A border texel's 16-bit value b
// (not a byte's 257 k) is added apart, b times its weight. One rounding
// per channel instead of one per texel, the same bits.
template <Rule kS, Rule kT, bool kOneD, bool kShare, Out kOut = Out::Sum>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void linear_sum16x8(const Image16& im, V s, V t, V share, V* sum) {
    constexpr bool kBorder = may_border(kS, true) || (!kOneD && may_border(kT, true));
    const I zero = _mm256_setzero_si256();
    const Linear8 x = linear8<kS>(s, im.w);
    const Linear8 y = kOneD ? Linear8{zero, zero, _mm256_setzero_ps()} : linear8<kT>(t, im.h);
    const V wx = weight8f<weight_may_be_nan(kS)>(x.a);
    const Weights8 w = weights8<kShare>(wx, kOneD ? _mm256_setzero_ps() : weight8f<weight_may_be_nan(kT)>(y.a), share);
    if constexpr (kBorder) {
        // A group none of whose indices is the border's (kBorder, the only
        // negative ones: most groups of a clamped image) sums as the inner
        // rules' do, with the pair loads: the border's masks would be 0 and
        // its weight sum 0, which adds +0 to each channel's sum (the same bits).
        const I any = _mm256_or_si256(_mm256_or_si256(x.i0, x.i1), _mm256_or_si256(y.i0, y.i1));
        if (!_mm256_movemask_ps(_mm256_castsi256_ps(any))) return footprint_sum16x8<false, kOneD, kOut>(im, x, y, w, sum);
    }
    footprint_sum16x8<kBorder, kOneD, kOut>(im, x, y, w, sum);
}

// gpu::level16() of one image for eight lanes at (s, t): 16-bit values by
// channel (a 1D image as linear_sum16x8()'s kOneD).
template <bool kLinear, Rule kS, Rule kT, bool kOneD>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void level16x8(const Image16& im, V s, V t, V* value) {
    if constexpr (!kLinear) {
        constexpr bool kBorder = may_border(kS, false) || (!kOneD && may_border(kT, false));
        fetch16<kBorder>(im, nearest8<kS>(s, im.w), kOneD ? _mm256_setzero_si256() : nearest8<kT>(t, im.h), value);
    } else {
        linear_sum16x8<kS, kT, kOneD, false, Out::Rounded>(im, s, t, _mm256_setzero_ps(), value);
    }
}

// gpu::level_sum() of one image for eight lanes with each lane's share:
// 16-bit sums by channel, not yet rounded.
template <bool kLinear, Rule kS, Rule kT, bool kOneD>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void level_sum16x8(const Image16& im, V s, V t, V share, V* sum) {
    if constexpr (kLinear) {
        linear_sum16x8<kS, kT, kOneD, true>(im, s, t, share, sum);
    } else {
        level16x8<false, kS, kT, kOneD>(im, s, t, sum);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) sum[c] = _mm256_mul_ps(sum[c], share);
    }
}

// The texture's state that every group reads.
struct State {
    const SamplerState* st;
    const std::vector<TextureImage>* levels;
    V border[4];
    int base, q;
    float texture_bias;  // gpu::quantize_bias() of the sampler's lod_bias
    bool nearest_mip;
    glm::vec3 size;  // level_base's
    int dims;        // 1 or 2
};

// float(kLog2Fraction[k]) / 256, as gpu::lambda_of_rho() adds it.
constexpr std::array<float, 256> kLog2Table = [] {
    std::array<float, 256> t{};
    for (size_t k = 0; k < t.size(); ++k) t[k] = float(gpu::kLog2Fraction[k]) * (1.0f / 256.0f);
    return t;
}();

// gpu_length() of eight lanes; std::max(a, b) is maxps(b, a), std::min(a, b) minps(b, a) (NaN and
// signed zeros alike).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V gpu_length8(V du, V dv) {
    const V u = _mm256_andnot_ps(splat(-0.0f), du), v = _mm256_andnot_ps(splat(-0.0f), dv);
    return _mm256_add_ps(_mm256_max_ps(v, u), _mm256_mul_ps(splat(0.34375f), _mm256_min_ps(v, u)));
}

// gpu::lambda_of_rho(gpu_rho()) of eight quads' derivatives (u = s * width, v = t * height).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V quad_lambda8(V dxs, V dxt, V dys, V dyt, V w, V h, bool two_d) {
    const V ux = _mm256_mul_ps(dxs, w), uy = _mm256_mul_ps(dys, w);
    const V vx = two_d ? _mm256_mul_ps(dxt, h) : _mm256_setzero_ps();
    const V vy = two_d ? _mm256_mul_ps(dyt, h) : _mm256_setzero_ps();
    const V axes = _mm256_max_ps(gpu_length8(uy, vy), gpu_length8(ux, vx));
    const V diagonals = _mm256_max_ps(gpu_length8(_mm256_sub_ps(ux, uy), _mm256_sub_ps(vx, vy)),
                                      gpu_length8(_mm256_add_ps(ux, uy), _mm256_add_ps(vx, vy)));
    const V rho = _mm256_max_ps(_mm256_mul_ps(splat(0.6875f), diagonals), axes);
    const I bits = _mm256_castps_si256(rho);
    const V exponent = _mm256_cvtepi32_ps(_mm256_sub_epi32(_mm256_srli_epi32(bits, 23), splat_i(127)));
    const I k = _mm256_and_si256(_mm256_srli_epi32(bits, 15), splat_i(255));
    const V lambda = _mm256_min_ps(splat(kLodLimit), _mm256_add_ps(exponent, _mm256_i32gather_ps(kLog2Table.data(), k, 4)));
    const V small = _mm256_cmp_ps(rho, splat(0x1p-126f), _CMP_NGE_UQ);  // !(rho >= 2^-126): NaN too
    return _mm256_blendv_ps(lambda, splat(-kLodLimit), small);
}

static_assert(kLanes % 8 == 0, "the kernels take lanes eight at a time");

// Lanes g..g+7's lambda_base, each quad's (lanes 4q..4q+3 take quad q's
// first lane's derivatives) in registers, with no copy of the derivatives:
// at 32 lanes and more, eight quads' log2 at once at each g % 32 == 0
// (quad_leaders8(): `quads` carries them to the next three groups), spread
// to their lanes; at 8 or 16 lanes, each group's two quads' leaders in
// every lane (the bits are the same: each lane's value is its quad's).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V lambda_bases8(const State& s, const BatchLookup& lk, int g, V& quads) {
    const V w = splat(s.size.x), h = splat(s.size.y);
    if constexpr (kLanes % 32 == 0) {
        if (g % 32 == 0)
            quads = quad_lambda8(quad_leaders8(lk.ddx[0] + g), quad_leaders8(lk.ddx[1] + g),
                                 quad_leaders8(lk.ddy[0] + g), quad_leaders8(lk.ddy[1] + g), w, h, s.dims > 1);
        return spread_quads8(quads, (g % 32) / 8);
    } else {
        return quad_lambda8(group_leaders8(lk.ddx[0] + g), group_leaders8(lk.ddx[1] + g),
                            group_leaders8(lk.ddy[0] + g), group_leaders8(lk.ddy[1] + g), w, h, s.dims > 1);
    }
}

// gpu::quantize_bias() of eight lanes: roundps toward zero is std::trunc()
// for every float (NaN and infinities kept).
[[gnu::always_inline]] GLSLRUN_AVX2 inline V quantize_bias8(V bias) {
    return _mm256_mul_ps(_mm256_round_ps(_mm256_mul_ps(bias, splat(256.0f)), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC),
                         splat(1.0f / 256.0f));
}

// Lanes g..g+7's lambda (see the file's comment), as sample_gpu_batch()'s
// lambdas(), from their lambda_base `base` (read where the LOD is
// implicit); `texture_bias` is gpu::quantize_bias() of the texture's.
// gpu::quantize_lambda()'s floor_f() is floor8()'s there: the clamped
// lambda is finite and small.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V lambdas8(const State& s, const BatchLookup& lk, V base, int g) {
    V l = _mm256_setzero_ps();
    if (lk.implicit) {
        l = base;
        if (lk.bias) l = _mm256_add_ps(l, quantize_bias8(_mm256_loadu_ps(lk.lod + g)));
    } else if (lk.lod) {
        l = _mm256_loadu_ps(lk.lod + g);
    }
    l = clamp_lambda8(_mm256_add_ps(l, splat(s.texture_bias)), *s.st);
    return _mm256_mul_ps(floor8(_mm256_mul_ps(l, splat(256.0f))), splat(1.0f / 256.0f));
}

// gpu::filter16()'s levels of eight lanes (a mipmap filter): the first,
// all ones where a second one (first + 1) is mixed in, and its 8-bit
// weight. *_MIPMAP_LINEAR in registers (lambda is finite), *_MIPMAP_NEAREST
// lane by lane.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void levels8(const State& s, V lambda, int* first, int* second,
                                                        int* weight) {
    if (s.nearest_mip) {
        alignas(32) float l[8];
        _mm256_store_ps(l, lambda);
        for (int k = 0; k < 8; ++k) {
            first[k] = l[k] <= 0.0f ? s.base : gpu::nearest_level(l[k], s.base, s.q);
            second[k] = weight[k] = 0;
        }
        return;
    }
    const V mag = _mm256_cmp_ps(lambda, _mm256_setzero_ps(), _CMP_LE_OQ);
    const V last = _mm256_cmp_ps(_mm256_add_ps(splat(float(s.base)), lambda), splat(float(s.q)), _CMP_GE_OQ);
    const V whole = floor8(lambda);
    const I linear_level = _mm256_blendv_epi8(_mm256_add_epi32(splat_i(s.base), _mm256_cvttps_epi32(whole)),
                                              splat_i(s.q), _mm256_castps_si256(last));
    const I d0 = _mm256_blendv_epi8(linear_level, splat_i(s.base), _mm256_castps_si256(mag));
    const I two = _mm256_castps_si256(_mm256_andnot_ps(_mm256_or_ps(mag, last), _mm256_castsi256_ps(splat_i(-1))));
    _mm256_store_si256(reinterpret_cast<I*>(first), d0);
    _mm256_store_si256(reinterpret_cast<I*>(second), two);
    _mm256_store_si256(reinterpret_cast<I*>(weight), _mm256_and_si256(two, weight8x8(_mm256_sub_ps(lambda, whole))));
}

// r / 65535 (gpu::over_unorm16()) of the lanes of `bits` into out. For
// every integer r in [0, 65535] (each 16-bit result), r 2^-16 + r (2^-32 +
// 2^-48) rounds to the quotient's float (checked over all of them:
// r 2^-16 + r 2^-32 alone misses 512), in two products and a sum instead
// of a division (a tenth of a nine-tap frame: perf). The results are
// finite: no NaN to make canonical, as store8() would.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void store16(const V* value, int bits, int g, float (*out)[kLanes]) {
    const V hi = splat(0x1p-16f), lo = splat(0x1p-32f + 0x1p-48f);
    const I bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const V take = _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(splat_i(bits), bit), bit));
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) {
        const V r = _mm256_add_ps(_mm256_mul_ps(value[c], hi), _mm256_mul_ps(value[c], lo));
        if (bits == 0xff) _mm256_storeu_ps(&out[c][g], r);  // every lane: nothing to keep
        else _mm256_storeu_ps(&out[c][g], _mm256_blendv_ps(_mm256_loadu_ps(&out[c][g]), r, take));
    }
}

// The lookups of a texture without mipmaps (one image and one filter
// whatever lambda is) at (s[i], t[i]). As sampling_direct.cpp's direct():
// kTogether groups of eight lanes sampled one after the other with no
// branch between them, so that the CPU overlaps one group's chain
// (coordinates, indices, loads, blends) with the next ones' (one group at a
// time, post's Fast frame was 0.74x Precise's); the border's rules, whose
// groups branch on their footprints, one group at a time. A group with no
// lane of `lanes` is sampled too (every rule keeps its indices in the
// image, for any float) and not stored.
template <bool kLinear, Rule kS, Rule kT, bool kOneD>
GLSLRUN_AVX2 void gpu_one(const Image16& im, const float* s, const float* t, LaneMask lanes, float (*out)[kLanes]) {
    constexpr bool kBorder = may_border(kS, kLinear) || (!kOneD && may_border(kT, kLinear));
    constexpr int kTogether = kBorder ? 1 : kLanes % 32 == 0 ? 4 : kLanes % 16 == 0 ? 2 : 1;
    for (int g = 0; g < kLanes; g += 8 * kTogether) {
        if (!uint32_t(lanes >> g)) continue;  // none of these groups' lanes
        V value[kTogether][4];
#pragma GCC unroll 4
        for (int k = 0; k < kTogether; ++k)
            level16x8<kLinear, kS, kT, kOneD>(im, _mm256_loadu_ps(s + g + 8 * k), _mm256_loadu_ps(t + g + 8 * k),
                                              value[k]);
#pragma GCC unroll 4
        for (int k = 0; k < kTogether; ++k) {
            const int bits = int(uint32_t(lanes >> (g + 8 * k)) & 0xffu);
            if (bits) store16(value[k], bits, g + 8 * k, out);
        }
    }
}

using OneKernel = void (*)(const Image16&, const float*, const float*, LaneMask, float (*)[kLanes]);

// The lookups of a group's lanes that share a first level: `level` of
// `levels`, with level + 1 mixed in by `weight` where `two` (a lane's
// second level; level < q then, so it exists).
template <bool kLinear, Rule kS, Rule kT, bool kOneD>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void level_pass8(const State& s, const std::vector<TextureImage>& levels,
                                                            int level, bool two, V sc, V tc, const int* weight,
                                                            V* value) {
    const Image16 im = image16(levels[size_t(level)], s.border);
    if (!two) return level16x8<kLinear, kS, kT, kOneD>(im, sc, tc, value);
    // One sum over both levels' texels, rounded once: level weighs 256 -
    // w, level + 1 w (0 in the lanes without a second level, whose sum is
    // then level16()'s).
    const V w = _mm256_cvtepi32_ps(_mm256_load_si256(reinterpret_cast<const I*>(weight)));
    V next[4];
    constexpr bool kBorder = may_border(kS, kLinear) || (!kOneD && may_border(kT, kLinear));
    if constexpr (kLinear && !kBorder) {
        // Both levels' byte sums, each within 0.02 of its bytes' integer
        // sum K1, K2 (see linear_sum16x8()), so their sum (one more
        // rounding, below 2^-8) within 0.05 of K1 + K2: rounded once with
        // the blend (blend16_of_sum8()), the bits of 257 K1 + 257 K2
        // rounded as gpu::round_blend(), in fewer steps.
        linear_sum16x8<kS, kT, kOneD, true, Out::Bytes>(im, sc, tc, _mm256_sub_ps(splat(256.0f), w), value);
        linear_sum16x8<kS, kT, kOneD, true, Out::Bytes>(image16(levels[size_t(level) + 1], s.border), sc, tc, w,
                                                        next);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) value[c] = blend16_of_sum8(_mm256_add_ps(value[c], next[c]));
        return;
    }
    level_sum16x8<kLinear, kS, kT, kOneD>(im, sc, tc, _mm256_sub_ps(splat(256.0f), w), value);
    level_sum16x8<kLinear, kS, kT, kOneD>(image16(levels[size_t(level) + 1], s.border), sc, tc, w, next);
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c) value[c] = round_blend8(_mm256_add_ps(value[c], next[c]));
}

// A mipmapped texture's lookups.
template <bool kLinear, Rule kS, Rule kT, bool kOneD>
GLSLRUN_AVX2 void gpu_mip(const State& s, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    V quads = _mm256_setzero_ps();
    for (int g = 0; g < kLanes; g += 8) {
        // Before the skip: the next groups may take this one's quads.
        const V base = lk.implicit ? lambda_bases8(s, lk, g, quads) : _mm256_setzero_ps();
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        const V sc = _mm256_loadu_ps(lk.coord[0] + g), tc = _mm256_loadu_ps(lk.coord[1] + g);
        alignas(32) int first[8], second[8], weight[8];
        levels8(s, lambdas8(s, lk, base, g), first, second, weight);
        const I d0 = _mm256_load_si256(reinterpret_cast<const I*>(first));
        const int two = _mm256_movemask_ps(_mm256_load_ps(reinterpret_cast<const float*>(second)));
        for (int left = bits; left;) {
            const int level = first[std::countr_zero(unsigned(left))];
            const int take = left & _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(d0, splat_i(level))));
            left &= ~take;
            V value[4];
            level_pass8<kLinear, kS, kT, kOneD>(s, *s.levels, level, (two & take) != 0, sc, tc, weight, value);
            store16(value, take, g, out);
        }
    }
}

// A cube map's lookups: each lane's face and (s, t) on it eight lanes at a
// time (cube_coords8(), as the batched samplers'), its lambda_base from rho
// on that face (gpu_cube_lambdas(), lane by lane, the batched sampler's
// own), then per group of eight lanes one pass per face and first level
// its lanes hold (one on most groups: a quad's lanes share their face but
// at the cube's edges), each as gpu_mip()'s. Before this, Fast's cube
// lookups went through the batched sampler's lane arrays (each lane's image,
// indices, offsets and weights stored and reloaded): cube_refract's Fast
// frame was 0.70x Precise's.
template <bool kLinear, Rule kS, Rule kT>
GLSLRUN_AVX2 void gpu_cube(const State& s, const Texture& texture, const BatchLookup& lk, LaneMask lanes,
                           float (*out)[kLanes]) {
    alignas(32) int face[kLanes];
    alignas(32) float fs[kLanes], ft[kLanes], base[kLanes];
    cube_coords8(lk, face, fs, ft);
    const bool mip = is_mipmap_filter(s.st->min_filter);
    if (mip && lk.implicit) gpu_cube_lambdas(texture, lk, base);
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        const V sc = _mm256_loadu_ps(fs + g), tc = _mm256_loadu_ps(ft + g);
        alignas(32) int first[8], second[8], weight[8];
        if (mip) {
            levels8(s, lambdas8(s, lk, lk.implicit ? _mm256_load_ps(base + g) : _mm256_setzero_ps(), g), first, second,
                    weight);
        } else {  // level_base, one filter (gpu_direct_samples())
            _mm256_store_si256(reinterpret_cast<I*>(first), splat_i(s.base));
            _mm256_store_si256(reinterpret_cast<I*>(second), _mm256_setzero_si256());
            _mm256_store_si256(reinterpret_cast<I*>(weight), _mm256_setzero_si256());
        }
        // (face, first level) as one integer: fewer than 256 levels.
        const I key = _mm256_add_epi32(_mm256_slli_epi32(_mm256_load_si256(reinterpret_cast<const I*>(face + g)), 8),
                                       _mm256_load_si256(reinterpret_cast<const I*>(first)));
        const int two = _mm256_movemask_ps(_mm256_load_ps(reinterpret_cast<const float*>(second)));
        for (int left = bits; left;) {
            const int k = std::countr_zero(unsigned(left));
            const int f = face[g + k];
            const int take = left & _mm256_movemask_ps(_mm256_castsi256_ps(
                                        _mm256_cmpeq_epi32(key, splat_i((f << 8) + first[k]))));
            left &= ~take;
            V value[4];
            level_pass8<kLinear, kS, kT, false>(s, texture.levels(f), first[k], (two & take) != 0, sc, tc, weight,
                                                value);
            store16(value, take, g, out);
        }
    }
}

// f.template operator()<kLinear, kS, kT>() for a cube map's filter within
// the level and wraps where no index can be the border's (REPEAT,
// MIRRORED_REPEAT, CLAMP_TO_EDGE, NEAREST's CLAMP): false, f not called,
// for the others (the batched path's; a cube map's edges are usually
// CLAMP_TO_EDGE).
template <bool kLinear, class F>
[[gnu::always_inline]] inline bool with_inner_rules(Rule s, Rule t, F&& f) {
    const auto inner = [](Rule r) { return r == Rule::Repeat || r == Rule::Mirror || r == Rule::Edge; };
    if (!inner(s) || !inner(t)) return false;
    return with_rules_of<false, kLinear>(s, t, [&]<bool kL, Rule kS, Rule kT>() {
        if constexpr ((kS == Rule::Repeat || kS == Rule::Mirror || kS == Rule::Edge) &&
                      (kT == Rule::Repeat || kT == Rule::Mirror || kT == Rule::Edge))
            f.template operator()<kL, kS, kT>();
    });
}

template <class F>
[[gnu::always_inline]] inline bool with_cube_rules(const SamplerState& st, F&& f) {
    if (linear_within_level(st.mag_filter))
        return with_inner_rules<true>(rule_of(st.wrap_s, false, true), rule_of(st.wrap_t, false, true), f);
    return with_inner_rules<false>(rule_of(st.wrap_s, false, false), rule_of(st.wrap_t, false, false), f);
}

// f.template operator()<kLinear, kS, kT, kOneD>() for the texture's
// filter within the level and wraps; a 1D texture's kT is fixed (unused).
template <class F>
[[gnu::always_inline]] inline void with_gpu_rules(const Texture& texture, F&& f) {
    const SamplerState& st = texture.sampler;
    const bool linear = linear_within_level(st.mag_filter);
    if (texture.target() == TextureTarget::Tex2D) {
        with_rules<false>(st, linear, [&]<bool kLinear, Rule kS, Rule kT>() { f.template operator()<kLinear, kS, kT, false>(); });
        return;
    }
    const auto one_d = [&]<bool kLinear, Rule kS, Rule>() { f.template operator()<kLinear, kS, Rule::Edge, true>(); };
    if (linear) with_rules_of<false, true>(rule_of(st.wrap_s, false, true), Rule::Edge, one_d);
    else with_rules_of<false, false>(rule_of(st.wrap_s, false, false), Rule::Edge, one_d);
}

// The kernel of a texture without mipmaps that gpu_direct_samples() takes.
OneKernel one_kernel(const Texture& texture) {
    OneKernel k = nullptr;
    with_gpu_rules(texture, [&]<bool kLinear, Rule kS, Rule kT, bool kOneD>() { k = gpu_one<kLinear, kS, kT, kOneD>; });
    return k;
}

// gpu::unorm16() of border_texel() of a colour texture.
glm::vec4 border16(const Texture& texture) {
    const Lookup proto{&texture, &texture.sampler, 0, 2, glm::vec3(0.0f), false, 0.0f};
    return vec_of(gpu::unorm16(texel_of(border_texel(proto))));
}

GLSLRUN_AVX2 void run_bound(const DirectSampler& d, const float* s, const float* t, LaneMask lanes,
                            float (*out)[kLanes]) {
    V border[4];
    for (int c = 0; c < 4; ++c) border[c] = splat(d.border[c]);
    reinterpret_cast<OneKernel>(d.kernel)(image16(static_cast<const glm::vec4*>(d.texels), d.width, d.height, border),
                                          s, t, lanes, out);
}

}  // namespace

bool gpu_direct_samples(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    const TextureTarget target = texture.target();
    if (!gpu_batch_samples(texture)) return false;
    if (target == TextureTarget::Cube && !with_cube_rules(st, []<bool, Rule, Rule>() {})) return false;
    if (target != TextureTarget::Tex2D && target != TextureTarget::Tex1D && target != TextureTarget::Cube) return false;
    if (!lod_matters(st)) return true;
    return is_mipmap_filter(st.min_filter) && linear_within_level(st.mag_filter) == linear_within_level(st.min_filter);
}

GLSLRUN_AVX2 void sample_gpu_direct(const Texture& texture, const BatchLookup& lookup, LaneMask lanes,
                                    float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    State s;  // each field set below (zeroing it first, rep stos, was half of this function: perf)
    s.st = &st;
    s.levels = &texture.levels(0);
    s.base = st.base_level;
    const TextureImage& base = (*s.levels)[size_t(s.base)];
    const glm::vec4 border = border16(texture);
    for (int c = 0; c < 4; ++c) s.border[c] = splat(border[c]);
    const bool cube = texture.target() == TextureTarget::Cube;
    if (!is_mipmap_filter(st.min_filter) && !cube)
        return one_kernel(texture)(image16(base, s.border), lookup.coord[0], lookup.coord[1], lanes, out);
    s.q = last_mip_level(base, st);
    s.texture_bias = gpu::quantize_bias(st.lod_bias);
    s.nearest_mip =
        st.min_filter == TextureFilter::NearestMipmapNearest || st.min_filter == TextureFilter::LinearMipmapNearest;
    s.size = image_size(base);
    s.dims = texture_dims(texture.target());
    if (cube) {
        with_cube_rules(st, [&]<bool kLinear, Rule kS, Rule kT>() { gpu_cube<kLinear, kS, kT>(s, texture, lookup, lanes, out); });
        return;
    }
    with_gpu_rules(texture, [&]<bool kLinear, Rule kS, Rule kT, bool kOneD>() {
        gpu_mip<kLinear, kS, kT, kOneD>(s, lookup, lanes, out);
    });
}

DirectSampler bind_gpu_direct(const Texture* texture) {
    if (!texture || !cpu_has_avx2() || !texture->complete()) return {};
    if (!gpu_batch_samples(*texture)) return bind_direct(texture);  // the Common rules', as the tex kernel's
    if (texture->target() != TextureTarget::Tex2D || !gpu_direct_samples(*texture) || lod_matters(texture->sampler))
        return {};
    const TextureImage& image = texture->levels(0)[size_t(texture->sampler.base_level)];
    DirectSampler d;
    d.run = run_bound;
    d.kernel = reinterpret_cast<void (*)()>(one_kernel(*texture));
    d.texels = image.texels.data();
    d.width = image.width;
    d.height = image.height;
    const glm::vec4 border = border16(*texture);
    for (int c = 0; c < 4; ++c) d.border[c] = border[c];
    return d;
}
#undef GLSLRUN_AVX2

#else
bool gpu_direct_samples(const Texture&) { return false; }
void sample_gpu_direct(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
DirectSampler bind_gpu_direct(const Texture*) { return {}; }
#endif

}  // namespace glslrun::rt
