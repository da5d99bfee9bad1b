// The batched sampler (runtime/sampling_batch.h) against the per-lane one
// (sample_complete_lane), bit for bit (NaN results included: both name one
// NaN, canonical_nan()): random and extreme coordinates
// (NaN, infinities, huge, denormal, texel edges), random derivatives, every
// target it takes, every filter pair, every wrap mode, shadow compares,
// explicit and biased LODs, lanes partly masked; the baseline and the AVX2
// builds of its loops.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "runtime/interp_kernels.h"
#include "runtime/sampling_batch.h"
#include "runtime/sampling_direct.h"
#include "runtime/sampling_direct3d.h"
#include "runtime/sampling_mip2d.h"
#include "runtime/sampling_rules.h"
#include "runtime/sampling_shadow8.h"
#include "runtime/texture_levels.h"
#include "tests/runtime/sampling_inputs.h"

using namespace glslrun;

namespace {

using namespace sampling_inputs;

TextureImage random_image(std::mt19937& rng, int w, int h, int d = 1) {
    std::uniform_real_distribution<float> value(-0.25f, 1.25f);
    TextureImage img{w, h, d, {}};
    for (int i = 0; i < w * h * d; ++i) img.texels.push_back({value(rng), value(rng), value(rng), value(rng)});
    return img;
}

Texture make(std::mt19937& rng, TextureTarget target, TextureFormat format, int w, int h, int d = 1) {
    std::vector<TextureImage> faces;
    for (int f = 0; f < (target == TextureTarget::Cube ? 6 : 1); ++f) faces.push_back(random_image(rng, w, h, d));
    auto t = Texture::create(target, std::move(faces), format);
    if (!t) FAIL(t.error().str());
    t->generate_mipmaps();
    return std::move(*t);
}

struct Operands {
    alignas(32) float coord[3][rt::kLanes], ddx[3][rt::kLanes], ddy[3][rt::kLanes], ref[rt::kLanes], lod[rt::kLanes];
};

// A rectangle's coordinates are in texels: spread over the image and past
// its edges, often on a texel's edge or centre, sometimes an extreme.
float rect_coordinate(std::mt19937& rng, int size) {
    std::uniform_int_distribution<int> pick(0, 3);
    const int p = pick(rng);
    if (p == 0) return coordinate(rng);
    if (p == 1) return 0.5f * float(std::uniform_int_distribution<int>(-3, 2 * size + 3)(rng));
    return std::uniform_real_distribution<float>(-2.0f, float(size) + 2.0f)(rng);
}

// Compares sample_batch() with sample_complete_lane() on one batch.
// How its lanes relate (`spread`): independent; sharing lane 0's derivatives and
// LOD (a cube map's lanes on the +X face: one face and level(s), one image
// per level for the batch); or a smooth surface's, whose LOD
// drifts from lane to lane across level boundaries and whose cube
// directions fan out around an edge or a corner of the cube, so that groups
// of lanes straddle levels and faces; or a quad's, each four lanes from a
// multiple of 4 sharing their first lane's derivatives, as the tex kernel
// gives them (the mipmapped 2D kernel then takes one log2 per quad); or
// Quads' whose other lanes' rows hold NaN where the sampler says it reads
// each quad's first lane (batch_reads_quad_leaders(): the tex kernel then
// makes no copy).
enum class Spread { Random, Shared, Smooth, Quads, Leaders };

// Lane i's operands of a Smooth batch: lane 0's derivatives scaled by 2^(i * step)
// (so lambda steps by `step`), cube directions near `corner` spread by `fan`.
void smooth_lanes(std::mt19937& rng, const Texture& texture, Operands& ops) {
    const float step = std::uniform_real_distribution<float>(0.0f, 0.3f)(rng);
    const float fan = std::exp2(std::uniform_real_distribution<float>(-8.0f, 0.0f)(rng));
    glm::vec3 corner(1.0f);
    const int axes = std::uniform_int_distribution<int>(1, 3)(rng);  // a face's centre, an edge, a corner
    for (int c = 0; c < 3; ++c) {
        if (c >= axes) corner[c] = std::uniform_real_distribution<float>(-0.5f, 0.5f)(rng);
        if (std::uniform_int_distribution<int>(0, 1)(rng)) corner[c] = -corner[c];
    }
    std::uniform_real_distribution<float> jitter(-1.0f, 1.0f);
    for (int i = 1; i < rt::kLanes; ++i) {
        const float scale = std::exp2(step * float(i));
        for (int c = 0; c < 3; ++c) {
            ops.ddx[c][i] = ops.ddx[c][0] * scale;
            ops.ddy[c][i] = ops.ddy[c][0] * scale;
        }
        ops.lod[i] = ops.lod[0] + step * float(i);
    }
    if (texture.target() != TextureTarget::Cube) return;
    for (int i = 0; i < rt::kLanes; ++i)
        for (int c = 0; c < 3; ++c)  // now and then an extreme (NaN, infinite, huge, zero) component
            ops.coord[c][i] = i % 11 == 5 ? coordinate(rng) : corner[c] + fan * jitter(rng);
}

void check_batch(std::mt19937& rng, const Texture& texture, bool shadow, ir::TexLod lod_kind,
                 Spread spread = Spread::Random) {
    const bool shared = spread == Spread::Shared;
    const bool rect = texture.target() == TextureTarget::Rect;
    const int dims = rt::texture_dims(texture.target());
    const int size[2] = {texture.levels(0)[0].width, texture.levels(0)[0].height};
    Operands ops{};
    for (int i = 0; i < rt::kLanes; ++i) {
        for (int c = 0; c < dims; ++c) {
            ops.coord[c][i] = rect ? rect_coordinate(rng, size[c]) : coordinate(rng);
            ops.ddx[c][i] = derivative(rng);
            ops.ddy[c][i] = derivative(rng);
        }
        ops.ref[i] = coordinate(rng);
        ops.lod[i] = std::uniform_real_distribution<float>(-3.0f, 6.0f)(rng);
        if (shared && i > 0) {
            for (int c = 0; c < dims; ++c) {
                ops.ddx[c][i] = ops.ddx[c][0];
                ops.ddy[c][i] = ops.ddy[c][0];
            }
            ops.lod[i] = ops.lod[0];
        }
        if (spread == Spread::Quads || spread == Spread::Leaders)
            for (int c = 0; c < dims; ++c) {
                ops.ddx[c][i] = ops.ddx[c][i & ~3];
                ops.ddy[c][i] = ops.ddy[c][i & ~3];
            }
        if (shared && texture.target() == TextureTarget::Cube) {
            ops.coord[0][i] = 2.0f;
            for (int c = 1; c < 3; ++c) ops.coord[c][i] = std::uniform_real_distribution<float>(-1.9f, 1.9f)(rng);
        }
    }
    if (spread == Spread::Smooth) smooth_lanes(rng, texture, ops);
    rt::BatchLookup lk;
    lk.implicit = lod_kind != ir::TexLod::Explicit;
    lk.bias = lod_kind == ir::TexLod::ImplicitBias;
    for (int c = 0; c < 3; ++c) {
        lk.coord[c] = ops.coord[c];
        lk.ddx[c] = ops.ddx[c];
        lk.ddy[c] = ops.ddy[c];
    }
    if (shadow) lk.ref = ops.ref;
    if (lod_kind != ir::TexLod::Implicit) lk.lod = ops.lod;
    const rt::LaneMask lanes = std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;

    for (bool avx2 : {false, true}) {
        if (avx2 && !rt::cpu_has_avx2()) continue;
        alignas(64) float out[4][rt::kLanes];
        for (auto& channel : out)
            for (float& v : channel) v = -7.0f;  // what lanes outside the mask must keep
        rt::BatchLookup seen = lk;
        alignas(32) float leaders[2][3][rt::kLanes];
        if (spread == Spread::Leaders && rt::batch_reads_quad_leaders(texture, avx2)) {
            seen.quad_derivatives = true;
            for (int c = 0; c < 3; ++c) {
                for (int i = 0; i < rt::kLanes; ++i) {
                    leaders[0][c][i] = i % 4 ? kNaN : ops.ddx[c][i];
                    leaders[1][c][i] = i % 4 ? kNaN : ops.ddy[c][i];
                }
                seen.ddx[c] = leaders[0][c];
                seen.ddy[c] = leaders[1][c];
            }
        }
        rt::sample_batch(texture, seen, lanes, out, avx2);
        for (int i = 0; i < rt::kLanes; ++i) {
            float want[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
            if ((lanes >> i) & 1) {
                rt::LaneLookup lane;
                lane.coord = {ops.coord[0][i], ops.coord[1][i], ops.coord[2][i]};
                lane.ddx = {ops.ddx[0][i], ops.ddx[1][i], ops.ddx[2][i]};
                lane.ddy = {ops.ddy[0][i], ops.ddy[1][i], ops.ddy[2][i]};
                lane.ref = shadow ? ops.ref[i] : 0.0f;
                lane.lod = lod_kind != ir::TexLod::Implicit ? ops.lod[i] : 0.0f;
                lane.implicit = lk.implicit;
                lane.bias = lk.bias;
                if (rect) rt::sample_rect_lane(texture, lane, want);
                else rt::sample_complete_lane(texture, lane, want);
            }
            for (int c = 0; c < 4; ++c) {
                INFO("avx2 " << avx2 << " lane " << i << " channel " << c << " coord (" << ops.coord[0][i] << ", "
                             << ops.coord[1][i] << ", " << ops.coord[2][i] << ") got " << out[c][i] << " want "
                             << want[c]);
                REQUIRE(std::bit_cast<uint32_t>(out[c][i]) == std::bit_cast<uint32_t>(want[c]));
            }
        }
    }
}

// Every filter pair, wrap pair and LOD kind on `texture`, a few batches
// each; a 3D texture's r takes a wrap mode of its own.
void sweep(std::mt19937& rng, Texture& texture, bool shadow) {
    for (TextureFilter min : kFilters)
        for (TextureFilter mag : {TextureFilter::Nearest, TextureFilter::Linear})
            for (TextureWrap s : kWraps)
                for (TextureWrap t : {TextureWrap::Repeat, TextureWrap::ClampToBorder, TextureWrap::MirroredRepeat, s})
                    for (ir::TexLod lod : kLods) {
                        texture.sampler.min_filter = min;
                        texture.sampler.mag_filter = mag;
                        texture.sampler.wrap_s = s;
                        texture.sampler.wrap_t = t;
                        texture.sampler.wrap_r = t == s ? TextureWrap::ClampToEdge : s;
                        REQUIRE(texture.complete());
                        if (!rt::batch_samples(texture)) continue;
                        for (Spread spread : {Spread::Random, Spread::Shared, Spread::Smooth, Spread::Quads, Spread::Leaders})
                            for (int batch = 0; batch < 2; ++batch) check_batch(rng, texture, shadow, lod, spread);
                    }
}

// One filter for minification and magnification, and the wraps of s, t and r.
void set_filter_wraps(Texture& t, TextureFilter filter, TextureWrap s, TextureWrap u, TextureWrap r) {
    t.sampler.min_filter = t.sampler.mag_filter = filter;
    t.sampler.wrap_s = s;
    t.sampler.wrap_t = u;
    t.sampler.wrap_r = r;
}

}  // namespace

TEST_CASE("batched sampling equals per-lane sampling: 1D and 2D, every filter and wrap", "[sampling][batch]") {
    std::mt19937 rng(1234);
    Texture one = make(rng, TextureTarget::Tex1D, TextureFormat::RGBA32F, 7, 1);
    sweep(rng, one, false);
    // Not a power of two (REPEAT's and the mipmap chain's odd sizes), with a border colour out of [0, 1].
    Texture two = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA32F, 13, 6);
    two.sampler.border_color = {0.25f, -1.0f, 2.0f, 0.5f};
    sweep(rng, two, false);
    // The texture object's own LOD bias and clamps, and a base level above 0.
    two.sampler.lod_bias = 0.75f;
    two.sampler.min_lod = -0.5f;
    two.sampler.max_lod = 2.25f;
    two.sampler.base_level = 1;
    two.sampler.max_level = 2;
    sweep(rng, two, false);
}

TEST_CASE("batched sampling equals per-lane sampling: cube maps", "[sampling][batch]") {
    std::mt19937 rng(99);
    Texture cube = make(rng, TextureTarget::Cube, TextureFormat::RGBA8, 8, 8);
    sweep(rng, cube, false);
}

TEST_CASE("batched sampling equals per-lane sampling: depth textures and compares", "[sampling][batch]") {
    std::mt19937 rng(7);
    Texture depth = make(rng, TextureTarget::Tex2D, TextureFormat::Depth, 9, 8);
    depth.sampler.border_color = {0.6f, 0.0f, 0.0f, 0.0f};
    for (bool compare : {false, true})
        for (CompareFunc func : {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::Lequal,
                                 CompareFunc::Greater, CompareFunc::Notequal, CompareFunc::Gequal, CompareFunc::Always})
            for (DepthTextureMode mode : {DepthTextureMode::Luminance, DepthTextureMode::Intensity, DepthTextureMode::Alpha}) {
                depth.sampler.compare = compare;
                depth.sampler.compare_func = func;
                depth.sampler.depth_mode = mode;
                for (TextureFilter min : {TextureFilter::Nearest, TextureFilter::Linear,
                                          TextureFilter::LinearMipmapLinear, TextureFilter::NearestMipmapNearest})
                    for (TextureWrap wrap : kWraps) {
                        depth.sampler.min_filter = min;
                        // NEAREST for both: every lane one image, compared texel by texel.
                        depth.sampler.mag_filter = min == TextureFilter::Nearest ? min : TextureFilter::Linear;
                        depth.sampler.wrap_s = depth.sampler.wrap_t = wrap;
                        for (ir::TexLod lod : kLods)
                            for (Spread spread : {Spread::Random, Spread::Shared, Spread::Smooth})
                                check_batch(rng, depth, true, lod, spread);
                    }
            }
}

// Rectangles against sample_rect_lane(): the clamping wraps (the others
// make a rectangle incomplete), NEAREST and LINEAR each side of the
// magnification switch (the lanes then choose their filter), explicit and
// biased LODs, the texture's LOD bias and clamps, depth compares.
TEST_CASE("batched sampling equals per-lane sampling: rectangles", "[sampling][batch][rectangle]") {
    std::mt19937 rng(2718);
    Texture rect = make(rng, TextureTarget::Rect, TextureFormat::RGBA32F, 13, 7);
    rect.sampler.border_color = {0.25f, -1.0f, 2.0f, 0.5f};
    constexpr TextureWrap kClamps[] = {TextureWrap::ClampToEdge, TextureWrap::Clamp, TextureWrap::ClampToBorder};
    auto sweep_rect = [&](Texture& t, bool shadow) {
        for (TextureFilter min : {TextureFilter::Nearest, TextureFilter::Linear})
            for (TextureFilter mag : {TextureFilter::Nearest, TextureFilter::Linear})
                for (TextureWrap s : kClamps)
                    for (TextureWrap w : kClamps)
                        for (ir::TexLod lod : kLods) {
                            t.sampler.min_filter = min;
                            t.sampler.mag_filter = mag;
                            t.sampler.wrap_s = s;
                            t.sampler.wrap_t = w;
                            REQUIRE(t.complete());
                            REQUIRE(rt::batch_samples(t));
                            for (int batch = 0; batch < 4; ++batch)
                                check_batch(rng, t, shadow, lod, batch >= 2 ? Spread::Shared : Spread::Random);
                        }
    };
    sweep_rect(rect, false);
    rect.sampler.lod_bias = -0.75f;
    rect.sampler.min_lod = -0.5f;
    rect.sampler.max_lod = 1.25f;
    sweep_rect(rect, false);
    Texture depth = make(rng, TextureTarget::Rect, TextureFormat::Depth, 6, 9);
    depth.sampler.border_color = {0.6f, 0.0f, 0.0f, 0.0f};
    for (CompareFunc func : {CompareFunc::Less, CompareFunc::Gequal})
        for (DepthTextureMode mode : {DepthTextureMode::Intensity, DepthTextureMode::Alpha}) {
            depth.sampler.compare = func == CompareFunc::Less;
            depth.sampler.compare_func = func;
            depth.sampler.depth_mode = mode;
            sweep_rect(depth, true);
        }
}

// The one-pass kernels (sampling_direct.h) on the sizes where their
// clamps meet: one texel (size - 1/2 = 1/2), one row or column, odd sizes;
// RGBA8 texels; every wrap pair and both filters, normalized and rectangle.
// The sweeps above reach them too; this says they are the ones taken.
TEST_CASE("batched sampling equals per-lane sampling: one-pass 2D and rectangle kernels", "[sampling][batch]") {
    std::mt19937 rng(4242);
    for (auto [w, h] : {std::pair{1, 1}, {1, 5}, {7, 1}, {3, 17}}) {
        for (TextureTarget target : {TextureTarget::Tex2D, TextureTarget::Rect}) {
            Texture t = make(rng, target, TextureFormat::RGBA8, w, h);
            t.sampler.border_color = {0.5f, 1.5f, -0.25f, 0.75f};
            const bool rect = target == TextureTarget::Rect;
            for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear})
                for (TextureWrap s : kWraps)
                    for (TextureWrap u : kWraps) {
                        if (rect && (s == TextureWrap::Repeat || s == TextureWrap::MirroredRepeat ||
                                     u == TextureWrap::Repeat || u == TextureWrap::MirroredRepeat))
                            continue;  // incomplete rectangles
                        t.sampler.min_filter = t.sampler.mag_filter = filter;
                        t.sampler.wrap_s = s;
                        t.sampler.wrap_t = u;
                        REQUIRE(t.complete());
#if defined(__x86_64__) && defined(__GNUC__)
                        REQUIRE(rt::direct_samples(t));
#endif
                        for (int batch = 0; batch < 3; ++batch) check_batch(rng, t, false, ir::TexLod::Implicit);
                    }
            t.sampler.min_filter = TextureFilter::Nearest;
            t.sampler.mag_filter = TextureFilter::Linear;
            CHECK_FALSE(rt::direct_samples(t));  // the lanes choose a filter: the steps
        }
    }
}

namespace {

// sample_direct() (or, for a mipmapped texture, sample_mip2d()) against
// the lane sampler on one batch of close lanes; the derivatives are the
// magnification's (lambda log2(scale)), every lane's the same.
void check_close_batch(std::mt19937& rng, const Texture& texture, float scale) {
    const bool rect = texture.target() == TextureTarget::Rect;
    const bool mip = rt::mip2d_samples(texture);
    Operands ops{};
    close_lanes(rng, texture, scale, ops.coord);
    for (int i = 0; i < rt::kLanes; ++i) {
        ops.ddx[0][i] = rect ? scale : scale / float(texture.levels(0)[0].width);
        ops.ddy[1][i] = rect ? scale : scale / float(texture.levels(0)[0].height);
    }
    rt::BatchLookup lk;
    lk.implicit = true;
    for (int c = 0; c < 3; ++c) {
        lk.coord[c] = ops.coord[c];
        lk.ddx[c] = ops.ddx[c];
        lk.ddy[c] = ops.ddy[c];
    }
    // Every lane; some; whole groups of eight on and others off.
    rt::LaneMask lanes = rt::kAllLanes;
    const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
    if (kind == 1) lanes = std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    if (kind == 2) {
        lanes = 0;
        while (!lanes)
            for (int g = 0; g < rt::kLanes; g += 8)
                if (rng() & 1) lanes |= rt::LaneMask(0xff) << g;
    }
    {
        alignas(64) float out[4][rt::kLanes];
        for (auto& channel : out)
            for (float& v : channel) v = -7.0f;  // what lanes outside the mask must keep
        if (mip) rt::sample_mip2d(texture, lk, lanes, out);
        else rt::sample_direct(texture, lk, lanes, out);
        for (int i = 0; i < rt::kLanes; ++i) {
            float want[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
            if ((lanes >> i) & 1) {
                rt::LaneLookup lane;
                lane.coord = {ops.coord[0][i], ops.coord[1][i], 0.0f};
                lane.ddx = {ops.ddx[0][i], ops.ddx[1][i], 0.0f};
                lane.ddy = {ops.ddy[0][i], ops.ddy[1][i], 0.0f};
                lane.implicit = true;
                if (rect) rt::sample_rect_lane(texture, lane, want);
                else rt::sample_complete_lane(texture, lane, want);
            }
            for (int c = 0; c < 4; ++c) {
                INFO("scale " << scale << " lane " << i << " channel " << c << " coord ("
                               << ops.coord[0][i] << ", " << ops.coord[1][i] << ") got " << out[c][i] << " want "
                               << want[c]);
                REQUIRE(std::bit_cast<uint32_t>(out[c][i]) == std::bit_cast<uint32_t>(want[c]));
            }
        }
    }
}

}  // namespace

// The one-pass and mipmapped kernels' LINEAR lookups of close lanes, as a
// magnified or slightly minified image's are (the sweeps above draw every
// lane apart): at the image's edges and corners and inside, the kernels'
// four groups of eight sampled together with some groups masked off; sizes
// of four texels, odd ones and under four; every wrap pair, normalized and
// rectangle; RGBA8 texels (whose results the kernels store with no NaN
// test where the weights are finite); a mipmap's one and two levels.
TEST_CASE("LINEAR lookups of close lanes equal per-lane sampling", "[sampling][batch][close]") {
#if defined(__x86_64__) && defined(__GNUC__)
    if (!rt::cpu_has_avx2()) return;
    std::mt19937 rng(8642);
    for (auto [w, h] : {std::pair{4, 4}, {5, 9}, {16, 16}, {37, 21}, {3, 12}}) {
        for (TextureTarget target : {TextureTarget::Tex2D, TextureTarget::Rect}) {
            Texture t = make(rng, target, TextureFormat::RGBA8, w, h);
            t.sampler.border_color = {0.3f, 1.5f, -0.25f, 0.7f};  // 0.3 (1 - a) + 0.3 a is not always 0.3
            t.sampler.min_filter = t.sampler.mag_filter = TextureFilter::Linear;
            const bool rect = target == TextureTarget::Rect;
            for (TextureWrap s : kWraps)
                for (TextureWrap u : kWraps) {
                    if (rect && (s == TextureWrap::Repeat || s == TextureWrap::MirroredRepeat ||
                                 u == TextureWrap::Repeat || u == TextureWrap::MirroredRepeat))
                        continue;  // incomplete rectangles
                    t.sampler.wrap_s = s;
                    t.sampler.wrap_t = u;
                    REQUIRE(t.complete());
                    REQUIRE(rt::direct_samples(t));
                    for (float scale : {0.0f, 0.1f, 0.27f, 0.45f, 0.7f, 1.5f})
                        for (int batch = 0; batch < 6; ++batch) check_close_batch(rng, t, scale);
                    if (rect) continue;
                    t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
                    REQUIRE(rt::mip2d_samples(t));
                    for (float scale : {0.3f, 0.7f, 1.2f, 1.6f, 2.5f, 5.0f})
                        for (int batch = 0; batch < 6; ++batch) check_close_batch(rng, t, scale);
                    t.sampler.min_filter = TextureFilter::Linear;
                }
        }
    }
#endif
}

// The mipmapped 2D kernels (sampling_mip2d.h): odd sizes and one-texel
// levels, every wrap pair, the four mipmap filters with the magnification
// filter of the same kind, every LOD kind and lane spread (quads sharing
// derivatives take one log2 per quad), the texture's LOD bias, clamps
// (min_lod above max_lod, and NaN, too) and base level. The sweeps above reach them
// too; this says they are the ones taken.
TEST_CASE("batched sampling equals per-lane sampling: mipmapped 2D kernels", "[sampling][batch]") {
    std::mt19937 rng(2468);
    struct Lod {
        float bias, min, max;
        int base;
    };
    const Lod lods[] = {{0.0f, -1000.0f, 1000.0f, 0}, {0.75f, -0.5f, 2.25f, 1}, {-2.5f, 3.0f, 1.0f, 0},
                        {1e30f, -1000.0f, 1000.0f, 0}, {0.0f, kNaN, 1000.0f, 0}};
    for (auto [w, h] : {std::pair{1, 1}, {1, 5}, {7, 1}, {13, 6}, {16, 16}}) {
        Texture t = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA8, w, h);
        t.sampler.border_color = {0.5f, 1.5f, -0.25f, 0.75f};
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
                        t.sampler.lod_bias = lod.bias;
                        t.sampler.min_lod = lod.min;
                        t.sampler.max_lod = lod.max;
                        t.sampler.base_level = std::min(lod.base, rt::levels_below(t.levels(0)[0]));
                        REQUIRE(t.complete());
#if defined(__x86_64__) && defined(__GNUC__)
                        REQUIRE(rt::mip2d_samples(t));
#endif
                        for (ir::TexLod kind : kLods)
                            for (Spread spread : {Spread::Random, Spread::Shared, Spread::Smooth, Spread::Quads, Spread::Leaders})
                                check_batch(rng, t, false, kind, spread);
                    }
        t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
        t.sampler.mag_filter = TextureFilter::Nearest;
        CHECK_FALSE(rt::mip2d_samples(t));  // the lanes choose a filter: the steps
    }
}

// 3D textures, mipmapped too (each lane's lambda from the derivatives of
// s, t and r); batch_samples() refuses only array textures.
TEST_CASE("batched sampling equals per-lane sampling: 3D textures", "[sampling][batch]") {
    std::mt19937 rng(5);
    Texture two = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA8, 4, 4);
    CHECK(rt::batch_samples(two));
    Texture three = make(rng, TextureTarget::Tex3D, TextureFormat::RGBA32F, 5, 3, 6);
    three.sampler.border_color = {0.75f, -0.5f, 1.5f, 0.25f};
    for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear}) {
        three.sampler.min_filter = three.sampler.mag_filter = filter;
        CHECK(rt::batch_samples(three));
    }
    three.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    CHECK(rt::batch_samples(three));
    three.sampler.min_filter = TextureFilter::Nearest;
    three.sampler.mag_filter = TextureFilter::Linear;
    CHECK(rt::batch_samples(three));
    sweep(rng, three, false);
    // The three wraps alike (the sweep's r differs from s and t but for CLAMP_TO_EDGE): a volume's usual state.
    three.sampler.min_filter = three.sampler.mag_filter = TextureFilter::Linear;
    for (TextureWrap wrap : kWraps) {
        three.sampler.wrap_s = three.sampler.wrap_t = three.sampler.wrap_r = wrap;
        for (ir::TexLod lod : kLods)
            for (Spread spread : {Spread::Random, Spread::Shared, Spread::Smooth})
                for (int batch = 0; batch < 4; ++batch) check_batch(rng, three, false, lod, spread);
    }
}

// The one-pass 3D kernels (sampling_direct3d.h): odd sizes and one-texel
// axes, every wrap triple that keeps the texels in the image (each axis
// its own), NEAREST and LINEAR, RGBA8 and float texels. The sweep above
// reaches them too; this says they are the ones taken, and that a wrap
// that may meet the border is not.
TEST_CASE("batched sampling equals per-lane sampling: one-pass 3D kernels", "[sampling][batch]") {
    std::mt19937 rng(1357);
    constexpr TextureWrap kInner[] = {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge,
                                      TextureWrap::Clamp};
    for (auto [w, h, d] : {std::tuple{1, 1, 1}, {3, 1, 5}, {5, 3, 6}, {1, 7, 2}})
        for (TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA32F}) {
            Texture t = make(rng, TextureTarget::Tex3D, format, w, h, d);
            for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear})
                for (TextureWrap s : kInner)
                    for (TextureWrap u : kInner)
                        for (TextureWrap r : kInner) {
                            set_filter_wraps(t, filter, s, u, r);
                            const bool border = filter == TextureFilter::Linear &&
                                                (s == TextureWrap::Clamp || u == TextureWrap::Clamp ||
                                                 r == TextureWrap::Clamp);
#if defined(__x86_64__) && defined(__GNUC__)
                            REQUIRE(rt::direct3d_samples(t) == !border);
#endif
                            check_batch(rng, t, false, ir::TexLod::Implicit);
                            check_batch(rng, t, false, ir::TexLod::Explicit, Spread::Shared);
                        }
            t.sampler.wrap_r = TextureWrap::ClampToBorder;
            CHECK_FALSE(rt::direct3d_samples(t));
        }
}

// The shadow-map kernels (sampling_shadow8.h): odd sizes and a one-texel
// axis, every compare function and depth mode, NEAREST and LINEAR, every
// wrap pair (those that may meet the border refused), a base level above 0
// (the depths of the level read, not level 0's).
TEST_CASE("batched sampling equals per-lane sampling: shadow-map kernels", "[sampling][batch]") {
    std::mt19937 rng(2468);
    constexpr CompareFunc kFuncs[] = {CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,
                                      CompareFunc::Lequal,  CompareFunc::Greater,  CompareFunc::Notequal,
                                      CompareFunc::Gequal,  CompareFunc::Always};
    for (auto [w, h] : {std::pair{13, 7}, {1, 5}, {6, 1}}) {
        Texture t = make(rng, TextureTarget::Tex2D, TextureFormat::Depth, w, h);
        t.sampler.compare = true;
        t.sampler.border_color = {0.4f, 0.0f, 0.0f, 0.0f};
        for (int base : {0, 1}) {
            t.sampler.base_level = base;
            for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear})
                for (TextureWrap s : kWraps)
                    for (TextureWrap u : kWraps)
                        for (CompareFunc func : kFuncs) {
                            set_filter_wraps(t, filter, s, u, TextureWrap::Repeat);
                            t.sampler.compare_func = func;
                            t.sampler.depth_mode = DepthTextureMode(int(func) % 3);
                            const bool linear = filter == TextureFilter::Linear;
                            const auto border = [&](TextureWrap wrap) {
                                return wrap == TextureWrap::ClampToBorder || (linear && wrap == TextureWrap::Clamp);
                            };
#if defined(__x86_64__) && defined(__GNUC__)
                            rt::BatchLookup lk;
                            float ref[rt::kLanes] = {};
                            lk.ref = ref;
                            REQUIRE(rt::shadow8_samples(t, lk) == !(border(s) || border(u)));
#endif
                            check_batch(rng, t, true, ir::TexLod::Implicit);
                            check_batch(rng, t, true, ir::TexLod::Explicit, Spread::Shared);
                        }
        }
    }
}

TEST_CASE("the tex kernel samples each unit's lanes and leaves the others", "[sampling][batch][kernel]") {
    std::mt19937 rng(31);
    std::array<GLState::TextureUnit, kMaxTextureUnits> units{};
    auto bind = [&](int unit, Texture t) {
        units[size_t(unit)].bound[size_t(TextureTarget::Tex2D)] = std::make_shared<const Texture>(std::move(t));
    };
    Texture trilinear = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA8, 16, 8);
    trilinear.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    bind(0, std::move(trilinear));
    Texture border = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA32F, 5, 7);
    border.sampler.min_filter = TextureFilter::Nearest;
    border.sampler.wrap_s = border.sampler.wrap_t = TextureWrap::ClampToBorder;
    border.sampler.border_color = {1.0f, 0.0f, 0.5f, 1.0f};
    bind(3, std::move(border));
    auto incomplete = Texture::create(TextureTarget::Tex2D, {random_image(rng, 4, 4)});  // mipmap filter, one level
    REQUIRE(incomplete.ok());
    bind(4, std::move(*incomplete));

    ir::TexInfo info;
    info.target = ir::TexTarget::T2D;
    info.lod = ir::TexLod::ImplicitBias;
    constexpr int32_t kUnits[] = {0, 3, 0, 4, 5, -1, 99, 3};
    for (int round = 0; round < 32; ++round) {
        // From round 20 the results overwrite the operand block (a register
        // reused), half of those a whole batch of mixed units.
        const bool alias = round >= 20, mixed_whole = alias && round % 2;
        // Screen derivatives are shared by a 2x2 quad; the program's own
        // gradients (texture*GradARB) are each lane's.
        info.grad = round % 5 == 1;
        std::vector<uint32_t> block(size_t(info.operand_count()) * rt::kLanes);
        auto operand = [&](uint32_t k, int lane) -> float& {
            return *reinterpret_cast<float*>(&block[size_t(k) * rt::kLanes + size_t(lane)]);
        };
        alignas(64) uint32_t unit[rt::kLanes];
        alignas(64) uint32_t dst[ir::kTexResults * rt::kLanes];
        for (int i = 0; i < rt::kLanes; ++i) {
            for (uint32_t k = 0; k < info.operand_count(); ++k)
                operand(k, i) = k < 2 ? coordinate(rng) : k == info.lod_at() ? 0.5f : derivative(rng);
            // Mostly one unit for the batch, as a uniform gives; now and then one per lane.
            unit[i] = uint32_t(round % 2 ? kUnits[std::uniform_int_distribution<size_t>(0, 7)(rng)]
                                         : kUnits[size_t(round / 2) % std::size(kUnits)]);
        }
        for (uint32_t& w : dst) w = 0xdeadbeefu;
        const std::vector<uint32_t> before = block;
        rt::Step<uint32_t> step;
        step.dst = alias ? block.data() : dst;
        step.src[0] = unit;
        step.src[1] = block.data();
        step.imm[2] = info.encode();
        rt::Machine<uint32_t> m;
        m.textures = units.data();
        // Every fourth round a whole batch: sampled whole (an incomplete or unbound unit's defaults then come afterwards).
        const rt::LaneMask active =
            round % 4 == 0 || mixed_whole ? rt::kAllLanes : std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng);
        m.mask.reset(active);
        m.lookups = round % 3 || mixed_whole ? rt::kAllLanes
                                             : std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng);
        const auto operand_before = [&](uint32_t k, int lane) {
            return std::bit_cast<float>(before[size_t(k) * rt::kLanes + size_t(lane)]);
        };
        rt::kernels::tex<uint32_t>(step, m);
        for (int i = 0; i < rt::kLanes; ++i) {
            float want[4] = {0.0f, 0.0f, 0.0f, 1.0f};
            const int32_t u = int32_t(unit[i]);
            const Texture* texture =
                u >= 0 && u < kMaxTextureUnits ? units[size_t(u)].bound[size_t(TextureTarget::Tex2D)].get() : nullptr;
            if (!((m.lookups >> i) & 1)) {
                want[3] = 0.0f;
            } else if (texture && texture->complete()) {
                rt::LaneLookup lane;
                lane.coord = {operand_before(0, i), operand_before(1, i), 0.0f};
                // Precise's one level of detail per 2x2 quad: its first lane's derivatives.
                const int d = rt::derivative_lane(i, rt::SamplingRules::Common, info.grad);
                lane.ddx = {operand_before(info.ddx_at(), d), operand_before(info.ddx_at() + 1, d), 0.0f};
                lane.ddy = {operand_before(info.ddy_at(), d), operand_before(info.ddy_at() + 1, d), 0.0f};
                lane.lod = operand_before(info.lod_at(), i);
                lane.bias = true;
                rt::sample_complete_lane(*texture, lane, want);
            }
            for (uint32_t c = 0; c < ir::kTexResults; ++c) {
                INFO("round " << round << " lane " << i << " unit " << u << " channel " << c);
                const size_t at = c * rt::kLanes + size_t(i);
                const uint32_t got = step.dst[at];
                if ((active >> i) & 1) REQUIRE(got == std::bit_cast<uint32_t>(want[c]));
                else REQUIRE(got == (alias ? before[at] : 0xdeadbeefu));
            }
        }
    }
}

// Fast's lookups take each 2x2 quad's derivatives from its first lane: a
// result written over the operand block (a register reused) before the
// quad's other lanes are sampled would change their lookups. The kernel
// must give the same bits whether its destination is the operand block or
// a register of its own.
TEST_CASE("the Fast tex kernel gives the same results into its operand block", "[sampling][batch][kernel]") {
    std::mt19937 rng(77);
    std::array<GLState::TextureUnit, kMaxTextureUnits> units{};
    Texture texture = make(rng, TextureTarget::Tex2D, TextureFormat::RGBA8, 16, 8);
    texture.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    units[0].bound[size_t(TextureTarget::Tex2D)] = std::make_shared<const Texture>(std::move(texture));
    ir::TexInfo info;
    info.target = ir::TexTarget::T2D;
    info.lod = ir::TexLod::Implicit;
    for (int round = 0; round < 8; ++round) {
        std::vector<uint32_t> block(size_t(info.operand_count()) * rt::kLanes);
        for (int i = 0; i < rt::kLanes; ++i)
            for (uint32_t k = 0; k < info.operand_count(); ++k) {
                const float v = k < 2 ? coordinate(rng) : derivative(rng);
                block[size_t(k) * rt::kLanes + size_t(i)] = std::bit_cast<uint32_t>(v);
            }
        alignas(64) uint32_t unit[rt::kLanes] = {};
        alignas(64) uint32_t own[ir::kTexResults * rt::kLanes];
        auto run = [&](uint32_t* dst, std::vector<uint32_t> operands) {
            rt::Step<uint32_t> step;
            step.dst = dst ? dst : operands.data();
            step.src[0] = unit;
            step.src[1] = operands.data();
            step.imm[2] = info.encode();
            rt::Machine<uint32_t> m;
            m.textures = units.data();
            m.mask.reset(rt::kAllLanes);
            m.lookups = rt::kAllLanes;
            rt::kernels::tex_gpu(step, m);
            return std::vector<uint32_t>(step.dst, step.dst + ir::kTexResults * rt::kLanes);
        };
        const std::vector<uint32_t> apart = run(own, block);
        const std::vector<uint32_t> over = run(nullptr, block);
        for (size_t w = 0; w < apart.size(); ++w) {
            INFO("round " << round << " word " << w);
            REQUIRE(apart[w] == over[w]);
        }
    }
}
