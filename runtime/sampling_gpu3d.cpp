// The kernels of sampling_gpu3d.h, from sampling_direct8.h's index steps
// (the GPU's indices are the Common rules'): per group of eight lanes the
// three axes' indices and 8-bit weights (gpu::weight8(): frac rounded to
// 8 bits, ties up), the planes' shares 256 - wz and wz, each plane's four
// integer weights (gpu::level_weights()), the texels as 16-bit values
// (gpu::unorm16(): 257 k for an RGBA8 texel k/255, rounded to nearest in
// one instruction), the sum of the eight products as exact float integers
// and (sum + 128) >> 8; then r / 65535. The texel (x, y, z) of an image
// w x h x d is texel (x, z h + y) of a w x (h d) one.
#include "runtime/sampling_gpu3d.h"

#include "runtime/sampling_direct3d.h"
#include "runtime/sampling_direct8.h"
#include "runtime/sampling_gpu.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

[[gnu::always_inline]] GLSLRUN_AVX2 inline V unorm16x8(V t) {
    return _mm256_round_ps(_mm256_mul_ps(t, splat(65535.0f)), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}

// gpu::weight8() of eight lanes: a NaN or a <= 0 weighs 0.
[[gnu::always_inline]] GLSLRUN_AVX2 inline I weight8x8(V a) {
    const V zero = _mm256_setzero_ps();
    const V c = _mm256_blendv_ps(zero, _mm256_min_ps(a, splat(1.0f)), _mm256_cmp_ps(a, zero, _CMP_GT_OQ));
    return _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(c, splat(256.0f)), splat(0.5f)));
}

// (x * y + bias) >> 8 of eight lanes' integers.
[[gnu::always_inline]] GLSLRUN_AVX2 inline I share8(I x, I y, I bias) {
    return _mm256_srai_epi32(_mm256_add_epi32(_mm256_mullo_epi32(x, y), bias), 8);
}

// gpu::level_weights(wx, wy, share) of eight lanes, as floats: w00, w01 (row 0), w10, w11 (row 1).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void plane_weights8(I wx, I wy, I share, V* w) {
    const I x1 = share8(wx, share, splat_i(128)), x0 = _mm256_sub_epi32(share, x1);
    // Ties down in the second column where wx = 256 (then a first column): 128 - 1.
    const I w11 = share8(x1, wy, _mm256_add_epi32(splat_i(128), _mm256_cmpeq_epi32(wx, splat_i(256))));
    const I w10 = share8(x0, wy, splat_i(127));
    w[0] = _mm256_cvtepi32_ps(_mm256_sub_epi32(x0, w10));
    w[1] = _mm256_cvtepi32_ps(_mm256_sub_epi32(x1, w11));
    w[2] = _mm256_cvtepi32_ps(w10);
    w[3] = _mm256_cvtepi32_ps(w11);
}

// sum[c] += 16-bit texels times w: `left` (column x0) by w0, `right` (x1) by w1.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void add_row(const V* left, const V* right, V w0, V w1, V* sum) {
#pragma GCC unroll 4
    for (int c = 0; c < 4; ++c)
        sum[c] = _mm256_add_ps(sum[c], _mm256_add_ps(_mm256_mul_ps(unorm16x8(left[c]), w0),
                                                     _mm256_mul_ps(unorm16x8(right[c]), w1)));
}

// One row's two texels (columns x.i0, x.i1; image row `row`) into `left` and `right`.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void row_texels(const Source& src, const Linear8& x, I row, bool pairs,
                                                           V* left, V* right) {
    if (pairs) return fetch_pairs8(src, x.i0, row, left, right);
    fetch8<false>(src, x.i0, row, left);
    fetch8<false>(src, x.i1, row, right);
}

// (sum + 128) >> 8 (gpu::round_blend(): a floor, in one rounding, of an exact sum), then r / 65535.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V result16(V sum) {
    const V r = _mm256_round_ps(_mm256_mul_ps(_mm256_add_ps(sum, splat(128.0f)), splat(1.0f / 256.0f)),
                                _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    return _mm256_div_ps(r, splat(65535.0f));
}

// The sums where every lane's footprint is the cell of texels (x0..x0+1,
// y0..y0+1, z0..z0+1), lane by lane: lanes j and j + 4 side by side in
// one register (four channels each), each row's two texels one 32-byte load
// at a fixed distance from the lane's first texel (dy: a row, dz: a plane,
// in bytes), the weights splat from the lanes' registers, and the results
// transposed into channels once (as sampling_direct3d.cpp's blend_cells8();
// transposing every row's texels kept the shuffle port busy).
[[gnu::always_inline]] GLSLRUN_AVX2 inline void cells8(const char* base, I first, size_t dy, size_t dz,
                                                       const V (*w)[4], V* value) {
    alignas(32) uint32_t off[8];
    offsets8(first, off);
    V lanes[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) {
        const char* p = base + off[j];
        const char* q = base + off[j + 4];
        V sum = _mm256_setzero_ps();
#pragma GCC unroll 4
        for (int r = 0; r < 4; ++r) {  // rows y0, y1 of plane z0, then of z1
            const size_t at = (r >> 1) * dz + (r & 1) * dy;
            const V u = _mm256_loadu_ps(reinterpret_cast<const float*>(p + at));
            const V v = _mm256_loadu_ps(reinterpret_cast<const float*>(q + at));
            const V x0 = unorm16x8(_mm256_permute2f128_ps(u, v, 0x20)), x1 = unorm16x8(_mm256_permute2f128_ps(u, v, 0x31));
            const V* pw = w[r >> 1] + 2 * (r & 1);
            sum = _mm256_add_ps(sum, _mm256_add_ps(_mm256_mul_ps(x0, splat_pair(pw[0], j)),
                                                   _mm256_mul_ps(x1, splat_pair(pw[1], j))));
        }
        lanes[j] = result16(sum);
    }
    transpose8(lanes, value);
}

template <bool kLinear, Rule kS, Rule kT, Rule kR>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void lookup8(const Image3& im, V s, V t, V r, V* value) {
    const I h = splat_i(im.h.n);
    if constexpr (!kLinear) {  // gpu::level16() of one texel: 257 k * 256 rounded back, k / 255
        const I row = _mm256_add_epi32(_mm256_mullo_epi32(nearest8<kR>(r, im.d), h), nearest8<kT>(t, im.h));
        fetch8<false>(im.src, nearest8<kS>(s, im.w), row, value);
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) value[c] = _mm256_div_ps(unorm16x8(value[c]), splat(65535.0f));
    } else {
        const Linear8 x = linear8<kS>(s, im.w), y = linear8<kT>(t, im.h), z = linear8<kR>(r, im.d);
        const I wx = weight8x8(x.a), wy = weight8x8(y.a);
        const I z1 = weight8x8(z.a);  // share 256: round(wz 256 / 256) = wz
        V w[2][4];
        plane_weights8(wx, wy, _mm256_sub_epi32(splat_i(256), z1), w[0]);
        plane_weights8(wx, wy, z1, w[1]);
        const I planes[2] = {_mm256_mullo_epi32(z.i0, h), _mm256_mullo_epi32(z.i1, h)};  // w * h * d below 2^24
        const bool pairs = neighbours8(x);
        if (pairs && neighbours8(y) && neighbours8(z)) {
            const I first = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_add_epi32(planes[0], y.i0), splat_i(im.w.n)), x.i0);
            const size_t row = size_t(im.w.n) * sizeof(glm::vec4);
            return cells8(reinterpret_cast<const char*>(im.src.texels), first, row, row * size_t(im.h.n), w, value);
        }
        V sum[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
#pragma GCC unroll 2
        for (int p = 0; p < 2; ++p) {
            V left[4], right[4];
            row_texels(im.src, x, _mm256_add_epi32(planes[p], y.i0), pairs, left, right);
            add_row(left, right, w[p][0], w[p][1], sum);
            row_texels(im.src, x, _mm256_add_epi32(planes[p], y.i1), pairs, left, right);
            add_row(left, right, w[p][2], w[p][3], sum);
        }
#pragma GCC unroll 4
        for (int c = 0; c < 4; ++c) value[c] = result16(sum[c]);
    }
}

// One texture state's kernel (a BatchKernel: gpu3d_kernel() picks it once per state).
template <bool kLinear, Rule kS, Rule kT, Rule kR>
GLSLRUN_AVX2 void gpu3d(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    const TextureImage& image = texture.levels(0)[size_t(texture.sampler.base_level)];
    const Image3 im{source_of(image, texture.sampler),
                    {image.width, splat(float(image.width))},
                    {image.height, splat(float(image.height))},
                    {image.depth, splat(float(image.depth))}};
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        V value[4];
        lookup8<kLinear, kS, kT, kR>(im, _mm256_loadu_ps(lk.coord[0] + g), _mm256_loadu_ps(lk.coord[1] + g),
                                     _mm256_loadu_ps(lk.coord[2] + g), value);
        store8<false>(value, bits, g, out);
    }
}

// f.template operator()<kRule>() for a wrap that keeps every texel in the image.
template <class F>
[[gnu::always_inline]] inline void with_inner(TextureWrap wrap, F&& f) {
    switch (inner_rule(wrap)) {
    case Rule::Repeat: f.template operator()<Rule::Repeat>(); return;
    case Rule::Mirror: f.template operator()<Rule::Mirror>(); return;
    default: f.template operator()<Rule::Edge>(); return;
    }
}

template <bool kLinear>
BatchKernel kernel_of(const SamplerState& st) {
    BatchKernel kernel = nullptr;
    with_inner(st.wrap_s, [&]<Rule kS>() {
        with_inner(st.wrap_t, [&]<Rule kT>() {
            with_inner(st.wrap_r, [&]<Rule kR>() { kernel = gpu3d<kLinear, kS, kT, kR>; });
        });
    });
    return kernel;
}

}  // namespace

bool gpu3d_samples(const Texture& texture) {
    return direct3d_samples(texture) && sampling::gpu::filtered(texture);  // Precise's one-pass cases, RGBA8
}

BatchKernel gpu3d_kernel(const Texture& texture) {
    if (!gpu3d_samples(texture)) return nullptr;
    const SamplerState& st = texture.sampler;
    return linear_within_level(st.mag_filter) ? kernel_of<true>(st) : kernel_of<false>(st);
}

void sample_gpu3d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]) {
    gpu3d_kernel(texture)(texture, lookup, lanes, out);
}
#undef GLSLRUN_AVX2

#else
bool gpu3d_samples(const Texture&) { return false; }
BatchKernel gpu3d_kernel(const Texture&) { return nullptr; }
void sample_gpu3d(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
#endif

}  // namespace glslrun::rt
