// The one-pass 3D kernels of sampling_direct3d.h, built from
// sampling_direct8.h's steps: each axis's indices (and LINEAR's weight) in
// registers, the texel (x, y, z) of an image w x h x d read as texel
// (x, z * h + y) of a w x (h * d) one (every index in the image: the wraps
// taken keep it there), LINEAR's four rows (y0, y1 on the planes z0, z1)
// blended lane by lane (blend_rows8()) in sample_linear()'s order: the
// rows by ax, the planes' rows by ay, the planes by az.
// Before this, 3D lookups went through the batched sampler's lane arrays
// (indices per axis, eight corner offsets, then the blends).
#include "runtime/sampling_direct3d.h"

#include "runtime/sampling_direct8.h"

namespace glslrun::rt {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))

namespace {

using namespace direct8;

// Texels (x0, x1) of lanes j and j + 4 (first texels at p and q) on the
// row `at` bytes on, lerped by the lanes' x weights `a`.
[[gnu::always_inline]] GLSLRUN_AVX2 inline V cell_row(const char* p, const char* q, size_t at, V a) {
    const V u = _mm256_loadu_ps(reinterpret_cast<const float*>(p + at));
    const V v = _mm256_loadu_ps(reinterpret_cast<const float*>(q + at));
    return lerp_pair(_mm256_permute2f128_ps(u, v, 0x20), _mm256_permute2f128_ps(u, v, 0x31), a);
}

// blend_rows8<2>()'s blends where every lane's footprint is the cell of
// texels (x0..x0+1, y0..y0+1, z0..z0+1): each lane's eight texels are four
// 32-byte loads at fixed distances from its first (dy: a row, dz: a
// plane, in bytes), so one offset per lane is taken out of the registers
// instead of eight (perf: the offsets' extracts and spills were a third of
// the trilinear kernel), with the same products and sums in the same order.
[[gnu::always_inline]] GLSLRUN_AVX2 inline void blend_cells8(const char* base, I first, size_t dy, size_t dz,
                                                             V ax, V ay, V az, V* value) {
    alignas(32) uint32_t off[8];
    offsets8(first, off);
    V lanes[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j) {
        const char* p = base + off[j];
        const char* q = base + off[j + 4];
        const V a = splat_pair(ax, j), b = splat_pair(ay, j);
        const V plane0 = lerp_pair(cell_row(p, q, 0, a), cell_row(p, q, dy, a), b);
        const V plane1 = lerp_pair(cell_row(p, q, dz, a), cell_row(p, q, dz + dy, a), b);
        lanes[j] = lerp_pair(plane0, plane1, splat_pair(az, j));
    }
    transpose8(lanes, value);
}

template <bool kLinear, Rule kS, Rule kT, Rule kR>
[[gnu::always_inline]] GLSLRUN_AVX2 inline void lookup3d8(const Image3& im, V s, V t, V r, V* value) {
    const I h = splat_i(im.h.n);
    if constexpr (!kLinear) {
        const I row = _mm256_add_epi32(_mm256_mullo_epi32(nearest8<kR>(r, im.d), h), nearest8<kT>(t, im.h));
        fetch8<false>(im.src, nearest8<kS>(s, im.w), row, value);
    } else {
        const Linear8 x = linear8<kS>(s, im.w), y = linear8<kT>(t, im.h), z = linear8<kR>(r, im.d);
        const I z0 = _mm256_mullo_epi32(z.i0, h), z1 = _mm256_mullo_epi32(z.i1, h);  // w * h * d below 2^24
        if (neighbours8(x) && neighbours8(y) && neighbours8(z)) {
            const I first = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_add_epi32(z0, y.i0), splat_i(im.w.n)), x.i0);
            const size_t row = size_t(im.w.n) * sizeof(glm::vec4);
            blend_cells8(reinterpret_cast<const char*>(im.src.texels), first, row, row * size_t(im.h.n), x.a, y.a,
                         z.a, value);
            return;
        }
        Row8 rows[4];
        row_of(im.src.texels, im.w.n, x, _mm256_add_epi32(z0, y.i0), rows[0]);
        row_of(im.src.texels, im.w.n, x, _mm256_add_epi32(z0, y.i1), rows[1]);
        row_of(im.src.texels, im.w.n, x, _mm256_add_epi32(z1, y.i0), rows[2]);
        row_of(im.src.texels, im.w.n, x, _mm256_add_epi32(z1, y.i1), rows[3]);
        const V ax[2] = {x.a, x.a}, ay[2] = {y.a, y.a};
        const V all = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        blend_rows8<2>(rows, ax, ay, z.a, all, value);
    }
}

template <bool kLinear, Rule kS, Rule kT, Rule kR>
GLSLRUN_AVX2 void direct3d(const Texture& texture, const BatchLookup& lk, LaneMask lanes, float (*out)[kLanes]) {
    const SamplerState& st = texture.sampler;
    const TextureImage& image = texture.levels(0)[size_t(st.base_level)];
    const Image3 im{source_of(image, st),
                    {image.width, splat(float(image.width))},
                    {image.height, splat(float(image.height))},
                    {image.depth, splat(float(image.depth))}};
    for (int g = 0; g < kLanes; g += 8) {
        const int bits = int(uint32_t(lanes >> g) & 0xffu);
        if (!bits) continue;
        V value[4];
        lookup3d8<kLinear, kS, kT, kR>(im, _mm256_loadu_ps(lk.coord[0] + g), _mm256_loadu_ps(lk.coord[1] + g),
                                       _mm256_loadu_ps(lk.coord[2] + g), value);
        store8(value, bits, g, out);
    }
}

// f.template operator()<kR>() for r's rule, one that keeps every texel in the image.
template <class F>
[[gnu::always_inline]] inline void with_inner_rule(Rule r, F&& f) {
    switch (r) {
    case Rule::Repeat: f.template operator()<Rule::Repeat>(); return;
    case Rule::Mirror: f.template operator()<Rule::Mirror>(); return;
    case Rule::Edge: f.template operator()<Rule::Edge>(); return;
    default: return;
    }
}

}  // namespace

bool direct3d_samples(const Texture& texture) {
    const SamplerState& st = texture.sampler;
    if (texture.target() != TextureTarget::Tex3D || texture.depth() || lod_matters(st)) return false;
    const bool linear = linear_within_level(st.mag_filter);
    for (TextureWrap wrap : {st.wrap_s, st.wrap_t, st.wrap_r})
        if (may_border(rule_of(wrap, false, linear), linear)) return false;
    return true;
}

BatchKernel direct3d_kernel(const Texture& texture) {
    if (!direct3d_samples(texture)) return nullptr;
    const SamplerState& st = texture.sampler;
    BatchKernel kernel = nullptr;
    with_rules<false>(st, linear_within_level(st.mag_filter), [&]<bool kLinear, Rule kS, Rule kT>() {
        if constexpr (!may_border(kS, kLinear) && !may_border(kT, kLinear))
            with_inner_rule(rule_of(st.wrap_r, false, kLinear),
                            [&]<Rule kR>() { kernel = direct3d<kLinear, kS, kT, kR>; });
    });
    return kernel;
}

void sample_direct3d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]) {
    direct3d_kernel(texture)(texture, lookup, lanes, out);
}
#undef GLSLRUN_AVX2

#else
BatchKernel direct3d_kernel(const Texture&) { return nullptr; }
bool direct3d_samples(const Texture&) { return false; }
void sample_direct3d(const Texture&, const BatchLookup&, LaneMask, float (*)[kLanes]) {}
#endif

}  // namespace glslrun::rt
