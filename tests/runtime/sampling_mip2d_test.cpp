// The mipmapped 2D kernel (runtime/sampling_mip2d.h) and its level of
// detail against the lane sampler (sample_complete_lane(), which shares no
// code with them), bit for bit: Precise's log2 of rho in registers
// (sampling_lod8.h) over every class of float; batches of close lanes as
// the rasterizer packs them, each quad's rho at a power of two (lambda on a
// level boundary, 0 included), a few ulps either side of one, or anywhere,
// so that groups of eight lanes straddle levels; quads whose derivatives
// are read from their first lane only (the other lanes' rows hold NaN);
// biases and explicit LODs near whole numbers; masked lanes and groups;
// every wrap pair with border colours outside [0, 1]; RGBA8 and float
// texels; base levels and LOD clamps.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

#include "runtime/interp_kernels.h"
#include "runtime/sampling_batch.h"
#include "runtime/sampling_lod8.h"
#include "runtime/sampling_mip2d.h"
#include "runtime/sampling_rules.h"
#include "runtime/texture_levels.h"
#include "tests/runtime/sampling_inputs.h"

using namespace glslrun;
using namespace glslrun::sampling_inputs;

#if defined(__x86_64__) && defined(__GNUC__)
namespace {

__attribute__((target("avx2"))) void lod8(const float* rho, float* lambda) {
    _mm256_storeu_ps(lambda, rt::sampling::lod_from_rho8(_mm256_loadu_ps(rho)));
}

void check_lods(const std::vector<float>& rhos) {
    for (size_t k = 0; k + 8 <= rhos.size(); k += 8) {
        float got[8];
        lod8(&rhos[k], got);
        for (int j = 0; j < 8; ++j) {
            const float want = rt::sampling::lod_from_rho(rhos[k + j]);
            INFO("rho " << rhos[k + j] << " (bits " << std::bit_cast<uint32_t>(rhos[k + j]) << ") got " << got[j]
                        << " want " << want);
            REQUIRE(std::bit_cast<uint32_t>(got[j]) == std::bit_cast<uint32_t>(want));
        }
    }
}

Texture mipmapped(std::mt19937& rng, int w, int h, TextureFormat format) {
    std::uniform_real_distribution<float> value(format == TextureFormat::RGBA8 ? 0.0f : -0.5f, 1.5f);
    TextureImage img{w, h, 1, {}};
    for (int i = 0; i < w * h; ++i) img.texels.push_back({value(rng), value(rng), value(rng), value(rng)});
    auto t = Texture::create(TextureTarget::Tex2D, {std::move(img)}, format);
    if (!t) FAIL(t.error().str());
    t->generate_mipmaps();
    return std::move(*t);
}

// A quad's rho: a power of two (lambda a whole number, 0 for 1), a few
// ulps off one, anywhere from magnification to past the last level, or a
// special value (0, NaN, infinite, denormal).
float quad_rho(std::mt19937& rng) {
    const float power = std::exp2(float(std::uniform_int_distribution<int>(-3, 7)(rng)));
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0: return power;
    case 1: return 1.0f;
    case 2: {
        float r = power;
        const float toward = rng() & 1 ? 0.0f : kInf;
        for (int n = std::uniform_int_distribution<int>(1, 3)(rng); n > 0; --n) r = std::nextafter(r, toward);
        return r;
    }
    case 3: {
        static constexpr float kSpecial[] = {0.0f, kNaN, kInf, 1e-40f, 1e30f};
        return kSpecial[std::uniform_int_distribution<int>(0, 4)(rng)];
    }
    default: return std::exp2(std::uniform_real_distribution<float>(-3.0f, 8.0f)(rng));
    }
}

// A LOD operand: near a whole number (either side by an ulp or two), 0, or anywhere.
float lod_operand(std::mt19937& rng) {
    const float whole = float(std::uniform_int_distribution<int>(-2, 6)(rng));
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0: return whole;
    case 1: return rng() & 1 ? 0.0f : -0.0f;
    case 2: return std::nextafter(whole, rng() & 1 ? -kInf : kInf);
    default: return std::uniform_real_distribution<float>(-3.0f, 8.0f)(rng);
    }
}

struct Batch {
    alignas(32) float coord[2][rt::kLanes], ddx[2][rt::kLanes], ddy[2][rt::kLanes], lod[rt::kLanes];
    alignas(32) float seen_ddx[2][rt::kLanes], seen_ddy[2][rt::kLanes];  // the kernel's: NaN off each quad's first lane
};

// Close lanes as the rasterizer packs them (quad q's pixels at 2 (q % 4) +
// (i & 1), 2 (q / 4) + (i >> 1 & 1)), stepped by each quad's rho, now and
// then an extreme coordinate.
void fill(std::mt19937& rng, const Texture& t, Batch& b) {
    const TextureImage& base = t.levels(0)[size_t(t.sampler.base_level)];
    const float size[2] = {float(base.width), float(base.height)};
    const float origin[2] = {std::uniform_real_distribution<float>(-1.5f, 2.5f)(rng),
                             std::uniform_real_distribution<float>(-1.5f, 2.5f)(rng)};
    for (int q = 0; q < rt::kLanes / 4; ++q) {
        const float rho = quad_rho(rng);
        const int axis = int(rng() & 1);  // along s or along t
        for (int i = 4 * q; i < 4 * q + 4; ++i) {
            const int pixel[2] = {2 * (q % 4) + (i & 1), 2 * (q / 4 % 4) + ((i >> 1) & 1)};
            for (int c = 0; c < 2; ++c) {
                const float step = std::isfinite(rho) && rho < 1e6f ? rho : 1.0f;
                b.coord[c][i] = origin[c] + float(pixel[c]) * step / size[c];
                b.ddx[c][i] = c == axis ? rho / size[c] : 0.0f;
                b.ddy[c][i] = c == axis ? 0.0f : 0.5f * rho / size[c];
                b.seen_ddx[c][i] = i % 4 ? kNaN : b.ddx[c][i];
                b.seen_ddy[c][i] = i % 4 ? kNaN : b.ddy[c][i];
            }
            b.lod[i] = lod_operand(rng);
        }
    }
    if (rng() % 4 == 0) b.coord[rng() & 1][rng() % rt::kLanes] = coordinate(rng);
}

rt::LaneMask lane_mask(std::mt19937& rng) {
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0: return rt::kAllLanes;
    case 1: return std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    case 2: return rt::LaneMask(1) << (rng() % rt::kLanes);  // one lane
    case 3: return rt::LaneMask(0xff) << (8 * (rng() % (rt::kLanes / 8)));  // one group
    default: {
        rt::LaneMask lanes = 0;
        while (!lanes)
            for (int g = 0; g < rt::kLanes; g += 8)
                if (rng() & 1) lanes |= rt::LaneMask(0xff) << g;
        return lanes;
    }
    }
}

// sample_mip2d() of one batch against the lane sampler: the kernel reads the
// quads' first lanes (quad_derivatives), the lanes each their quad's.
void check_batch(std::mt19937& rng, const Texture& t, ir::TexLod kind) {
    Batch b;
    fill(rng, t, b);
    rt::BatchLookup lk;
    lk.implicit = kind != ir::TexLod::Explicit;
    lk.bias = kind == ir::TexLod::ImplicitBias;
    lk.quad_derivatives = true;
    for (int c = 0; c < 2; ++c) {
        lk.coord[c] = b.coord[c];
        lk.ddx[c] = b.seen_ddx[c];
        lk.ddy[c] = b.seen_ddy[c];
    }
    alignas(32) static constexpr float zeros[rt::kLanes] = {};
    lk.coord[2] = lk.ddx[2] = lk.ddy[2] = zeros;
    if (kind != ir::TexLod::Implicit) lk.lod = b.lod;
    const rt::LaneMask lanes = lane_mask(rng);
    alignas(64) float out[4][rt::kLanes];
    for (auto& channel : out)
        for (float& v : channel) v = -7.0f;  // what lanes outside the mask must keep
    rt::sample_mip2d(t, lk, lanes, out);
    for (int i = 0; i < rt::kLanes; ++i) {
        float want[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
        if ((lanes >> i) & 1) {
            rt::LaneLookup lane;
            lane.coord = {b.coord[0][i], b.coord[1][i], 0.0f};
            lane.ddx = {b.ddx[0][i], b.ddx[1][i], 0.0f};
            lane.ddy = {b.ddy[0][i], b.ddy[1][i], 0.0f};
            lane.implicit = lk.implicit;
            lane.bias = lk.bias;
            lane.lod = kind != ir::TexLod::Implicit ? b.lod[i] : 0.0f;
            rt::sample_complete_lane(t, lane, want);
        }
        for (int c = 0; c < 4; ++c) {
            INFO("lane " << i << " channel " << c << " coord (" << b.coord[0][i] << ", " << b.coord[1][i] << ") ddx ("
                         << b.ddx[0][i] << ", " << b.ddx[1][i] << ") lod " << b.lod[i] << " got " << out[c][i]
                         << " want " << want[c]);
            REQUIRE(std::bit_cast<uint32_t>(out[c][i]) == std::bit_cast<uint32_t>(want[c]));
        }
    }
}

}  // namespace

TEST_CASE("the level of detail in registers equals lod_from_rho()", "[sampling][mip2d]") {
    if (!rt::cpu_has_avx2()) return;
    std::vector<float> rhos = {0.0f, -0.0f, 1.0f, kNaN, -kNaN, kInf, -kInf, -1.0f, 1e-45f, 1e-40f,
                               0x1p-126f, std::nextafter(0x1p-126f, 0.0f), std::numeric_limits<float>::max()};
    for (int e = -149; e <= 127; ++e) {  // every power of two and its neighbours: lambda at a whole number
        const float p = std::exp2(float(e));
        rhos.insert(rhos.end(), {p, std::nextafter(p, 0.0f), std::nextafter(p, kInf), 0.70710677f * p,
                                 0.70710683f * p, 1.4142135f * p});
    }
    std::mt19937 rng(97);
    for (int k = 0; k < 200000; ++k) rhos.push_back(std::bit_cast<float>(uint32_t(rng())));  // every class of float
    for (int k = 0; k < 20000; ++k) rhos.push_back(std::exp2(std::uniform_real_distribution<float>(-10.0f, 14.0f)(rng)));
    while (rhos.size() % 8) rhos.push_back(1.0f);
    check_lods(rhos);
}

TEST_CASE("mipmapped 2D lookups of close quads equal per-lane sampling", "[sampling][mip2d]") {
    if (!rt::cpu_has_avx2()) return;
    std::mt19937 rng(1357);
    struct Lod {
        float bias, min, max;
        int base;
    };
    const Lod lods[] = {{0.0f, -1000.0f, 1000.0f, 0}, {0.5f, -0.5f, 3.0f, 1}, {-1.0f, 1.0f, 1.0f, 0}};
    for (auto [w, h, format] : {std::tuple{16, 16, TextureFormat::RGBA8}, {13, 6, TextureFormat::RGBA32F},
                                {64, 32, TextureFormat::RGBA8}, {1, 9, TextureFormat::RGBA8}}) {
        Texture t = mipmapped(rng, w, h, format);
        for (TextureFilter min : {TextureFilter::LinearMipmapLinear, TextureFilter::LinearMipmapNearest,
                                  TextureFilter::NearestMipmapLinear, TextureFilter::NearestMipmapNearest})
            for (TextureWrap s : kWraps)
                for (TextureWrap u : kWraps)
                    for (const Lod& lod : lods) {
                        t.sampler.min_filter = min;
                        t.sampler.mag_filter = rt::sampling::linear_within_level(min) ? TextureFilter::Linear
                                                                                      : TextureFilter::Nearest;
                        t.sampler.wrap_s = s;
                        t.sampler.wrap_t = u;
                        std::uniform_real_distribution<float> colour(-0.5f, 1.5f);
                        t.sampler.border_color = {colour(rng), colour(rng), colour(rng), colour(rng)};
                        t.sampler.lod_bias = lod.bias;
                        t.sampler.min_lod = lod.min;
                        t.sampler.max_lod = lod.max;
                        t.sampler.base_level = std::min(lod.base, rt::levels_below(t.levels(0)[0]));
                        REQUIRE(t.complete());
                        REQUIRE(rt::mip2d_samples(t));
                        REQUIRE(rt::batch_reads_quad_leaders(t, true));
                        for (ir::TexLod kind : kLods)
                            for (int batch = 0; batch < 3; ++batch) check_batch(rng, t, kind);
                    }
    }
}
#endif
