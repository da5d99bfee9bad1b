// Fast's batched sampler (runtime/sampling_gpu_batch.h) against the per-lane
// one under the GPU's rules (sample_complete_lane with SamplingRules::Gpu),
// bit for bit: random and extreme coordinates, random derivatives (one set
// per 2x2 quad, the first lane's, as the tex kernel hands the lanes), RGBA8
// 1D, 2D and cube-map textures with the GPU's mipmaps, every filter pair and wrap
// mode, implicit, biased and explicit LODs, the texture's bias and clamps,
// lanes partly masked; the baseline and the AVX2 builds of its loops.
// Fast's one-pass 1D and 2D kernels (runtime/sampling_gpu_direct.h) against the
// batched sampler's baseline build over the same sweep.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "runtime/interp_kernels.h"
#include "runtime/mipmap_gpu.h"
#include "runtime/sampling_gpu_batch.h"
#include "runtime/sampling_gpu_direct.h"
#include "runtime/sampling_rules.h"
#include "runtime/texture_levels.h"
#include "tests/runtime/sampling_inputs.h"

using namespace glslrun;

namespace {

using namespace sampling_inputs;

// RGBA8 texels are k/255; the GPU's mipmaps are made from them where the
// sizes halve exactly, the box filter's otherwise.
Texture make(std::mt19937& rng, TextureTarget target, int w, int h) {
    std::uniform_int_distribution<int> byte(0, 255);
    TextureImage img{w, h, 1, {}};
    for (int i = 0; i < w * h; ++i)
        img.texels.push_back({byte(rng) / 255.0f, byte(rng) / 255.0f, byte(rng) / 255.0f, byte(rng) / 255.0f});
    std::vector<TextureImage> faces(target == TextureTarget::Cube ? 6 : 1, img);
    for (size_t f = 1; f < faces.size(); ++f) std::shuffle(faces[f].texels.begin(), faces[f].texels.end(), rng);
    auto t = Texture::create(target, std::move(faces), TextureFormat::RGBA8);
    if (!t) FAIL(t.error().str());
    if (!rt::generate_gpu_mipmaps(*t)) t->generate_mipmaps();
    return std::move(*t);
}

// The texture object's LOD bias and clamps, and a base level above 0.
void bias_and_clamp(Texture& texture) {
    texture.sampler.lod_bias = 0.75f;
    texture.sampler.min_lod = -0.5f;
    texture.sampler.max_lod = 2.25f;
    texture.sampler.base_level = 1;
    texture.sampler.max_level = 2;
}

struct Operands {
    alignas(32) float coord[3][rt::kLanes], ddx[3][rt::kLanes], ddy[3][rt::kLanes], lod[rt::kLanes];
};

// Random operands of one batch; `lk` points into `ops`.
rt::BatchLookup random_lookup(std::mt19937& rng, const Texture& texture, ir::TexLod lod_kind, Operands& ops) {
    // A cube map's lookup takes a direction and its derivatives.
    const int dims = texture.target() == TextureTarget::Cube ? 3 : rt::texture_dims(texture.target());
    for (int i = 0; i < rt::kLanes; ++i) {
        for (int c = 0; c < dims; ++c) {
            ops.coord[c][i] = coordinate(rng);
            ops.ddx[c][i] = derivative(rng);
            ops.ddy[c][i] = derivative(rng);
        }
        ops.lod[i] = std::uniform_real_distribution<float>(-3.0f, 6.0f)(rng);
    }
    rt::BatchLookup lk;
    lk.implicit = lod_kind != ir::TexLod::Explicit;
    lk.bias = lod_kind == ir::TexLod::ImplicitBias;
    for (int c = 0; c < 3; ++c) {
        lk.coord[c] = ops.coord[c];
        lk.ddx[c] = ops.ddx[c];
        lk.ddy[c] = ops.ddy[c];
    }
    if (lod_kind != ir::TexLod::Implicit) lk.lod = ops.lod;
    return lk;
}

// The per-lane sampler's result for lane i of a batch (the oracle): the
// quad's first lane's derivatives, as the tex kernel hands the lanes.
void lane_result(const Texture& texture, const Operands& ops, const rt::BatchLookup& lk, int i, float* want) {
    const int from = i & ~3;
    rt::LaneLookup lane;
    lane.rules = rt::SamplingRules::Gpu;
    lane.coord = {ops.coord[0][i], ops.coord[1][i], ops.coord[2][i]};
    lane.ddx = {ops.ddx[0][from], ops.ddx[1][from], ops.ddx[2][from]};
    lane.ddy = {ops.ddy[0][from], ops.ddy[1][from], ops.ddy[2][from]};
    lane.lod = lk.lod ? ops.lod[i] : 0.0f;
    lane.implicit = lk.implicit;
    lane.bias = lk.bias;
    rt::sample_complete_lane(texture, lane, want);
}

// out against the per-lane sampler in the lanes of `lanes`, and -7 (what
// the caller filled) in the others, bit for bit.
void expect_lanes(const Texture& texture, const Operands& ops, const rt::BatchLookup& lk, rt::LaneMask lanes,
                  const float (*out)[rt::kLanes], const char* what) {
    for (int i = 0; i < rt::kLanes; ++i) {
        float want[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
        if ((lanes >> i) & 1) lane_result(texture, ops, lk, i, want);
        for (int c = 0; c < 4; ++c) {
            INFO(what << " lane " << i << " channel " << c << " coord (" << ops.coord[0][i] << ", " << ops.coord[1][i]
                      << ", " << ops.coord[2][i] << ") lod " << ops.lod[i] << " got " << out[c][i] << " want "
                      << want[c]);
            REQUIRE(std::bit_cast<uint32_t>(out[c][i]) == std::bit_cast<uint32_t>(want[c]));
        }
    }
}

void check_batch(std::mt19937& rng, const Texture& texture, ir::TexLod lod_kind) {
    Operands ops{};
    const rt::BatchLookup lk = random_lookup(rng, texture, lod_kind, ops);
    const rt::LaneMask lanes = std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    for (bool avx2 : {false, true}) {
        if (avx2 && !rt::cpu_has_avx2()) continue;
        alignas(64) float out[4][rt::kLanes];
        for (auto& channel : out)
            for (float& v : channel) v = -7.0f;  // what lanes outside the mask must keep
        rt::sample_gpu_batch(texture, lk, lanes, out, avx2);
        expect_lanes(texture, ops, lk, lanes, out, avx2 ? "batch avx2" : "batch");
    }
}

void sweep(std::mt19937& rng, Texture& texture) {
    for (TextureFilter min : kFilters)
        for (TextureFilter mag : {TextureFilter::Nearest, TextureFilter::Linear})
            for (TextureWrap s : kWraps)
                for (TextureWrap t : {TextureWrap::Repeat, TextureWrap::ClampToBorder, s})
                    for (ir::TexLod lod : kLods) {
                        texture.sampler.min_filter = min;
                        texture.sampler.mag_filter = mag;
                        texture.sampler.wrap_s = s;
                        texture.sampler.wrap_t = t;
                        REQUIRE(texture.complete());
                        REQUIRE(rt::gpu_batch_samples(texture));
                        for (int batch = 0; batch < 3; ++batch) check_batch(rng, texture, lod);
                    }
}

}  // namespace

TEST_CASE("Fast's batched GPU-rule sampling equals its per-lane sampling", "[sampling][batch][gpu]") {
    std::mt19937 rng(2511);
    Texture one = make(rng, TextureTarget::Tex1D, 8, 1);
    sweep(rng, one);
    Texture square = make(rng, TextureTarget::Tex2D, 16, 8);
    sweep(rng, square);
    // Not a power of two, a border colour, then the object's bias and clamps and a base level above 0.
    Texture two = make(rng, TextureTarget::Tex2D, 13, 6);
    two.sampler.border_color = {0.25f, 0.0f, 1.0f, 0.5f};
    sweep(rng, two);
    bias_and_clamp(two);
    sweep(rng, two);
}

namespace {

// sample_gpu_direct() against the per-lane sampler, bit for bit, where it takes the texture.
void check_direct(std::mt19937& rng, const Texture& texture, ir::TexLod lod_kind) {
    Operands ops{};
    const rt::BatchLookup lk = random_lookup(rng, texture, lod_kind, ops);
    const rt::LaneMask lanes = std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    alignas(64) float got[4][rt::kLanes];
    for (auto& channel : got)
        for (float& v : channel) v = -7.0f;  // kept outside the mask
    rt::sample_gpu_direct(texture, lk, lanes, got);
    expect_lanes(texture, ops, lk, lanes, got, "direct");
}

// Whether the one-pass kernels take a texture of this filter pair and wraps
// (the test's own statement of gpu_direct_samples()): one filter within
// every level; a cube map's wraps those whose indices stay in the face.
bool direct_expected(const Texture& texture, TextureFilter min, TextureFilter mag, TextureWrap s, TextureWrap t) {
    const bool linear = rt::sampling::linear_within_level(mag);
    if (linear != rt::sampling::linear_within_level(min)) return false;
    if (texture.target() != TextureTarget::Cube) return true;
    const auto inner = [&](TextureWrap w) {
        return w == TextureWrap::Repeat || w == TextureWrap::MirroredRepeat || w == TextureWrap::ClampToEdge ||
               (w == TextureWrap::Clamp && !linear);
    };
    return inner(s) && inner(t);
}

// Every filter pair and wrap pair: the direct kernels where they take the
// texture (and they must take every same-filter pair, a cube map's inner
// wraps), returning how many.
int sweep_direct(std::mt19937& rng, Texture& texture) {
    int taken = 0;
    for (TextureFilter min : kFilters)
        for (TextureFilter mag : {TextureFilter::Nearest, TextureFilter::Linear})
            for (TextureWrap s : kWraps)
                for (TextureWrap t : kWraps) {
                    texture.sampler.min_filter = min;
                    texture.sampler.mag_filter = mag;
                    texture.sampler.wrap_s = s;
                    texture.sampler.wrap_t = t;
                    REQUIRE(texture.complete());
                    const bool taking = direct_expected(texture, min, mag, s, t);
                    REQUIRE(rt::gpu_direct_samples(texture) == taking);
                    if (!taking) continue;
                    ++taken;
                    for (ir::TexLod lod : kLods)
                        for (int batch = 0; batch < 3; ++batch) check_direct(rng, texture, lod);
                }
    return taken;
}

}  // namespace

TEST_CASE("Fast's one-pass 1D and 2D lookups equal its per-lane ones", "[sampling][batch][gpu]") {
    if (!rt::cpu_has_avx2()) return;  // the one-pass kernels need AVX2
    std::mt19937 rng(1924);
    Texture square = make(rng, TextureTarget::Tex2D, 16, 8);
    CHECK(sweep_direct(rng, square) == 6 * 25);
    // Not a power of two (the box filter's mipmaps), a border colour whose
    // 16-bit value is a tie, the object's bias and clamps, a base level above 0.
    Texture odd = make(rng, TextureTarget::Tex2D, 13, 6);
    odd.sampler.border_color = {0.25f, 0.0f, 1.0f, 0.5f};
    sweep_direct(rng, odd);
    bias_and_clamp(odd);
    sweep_direct(rng, odd);
    Texture one = make(rng, TextureTarget::Tex1D, 8, 1);
    CHECK(sweep_direct(rng, one) == 6 * 25);
    Texture odd_one = make(rng, TextureTarget::Tex1D, 7, 1);
    odd_one.sampler.border_color = {1.0f, 0.5f, 0.0f, 0.25f};
    sweep_direct(rng, odd_one);
}

TEST_CASE("Fast's one-pass lookups add the texture's LOD bias in 8 bits as its batched ones", "[sampling][batch][gpu]") {
    if (!rt::cpu_has_avx2()) return;
    std::mt19937 rng(311);
    // Off the 1/256 grid on both sides of zero (gpu::quantize_bias() truncates toward zero).
    for (float bias : {0.3f, -0.3f}) {
        Texture square = make(rng, TextureTarget::Tex2D, 16, 8);
        square.sampler.lod_bias = bias;
        CHECK(sweep_direct(rng, square) == 6 * 25);
        Texture one = make(rng, TextureTarget::Tex1D, 8, 1);
        one.sampler.lod_bias = bias;
        CHECK(sweep_direct(rng, one) == 6 * 25);
    }
}

TEST_CASE("Fast's batched GPU-rule sampling equals its per-lane sampling: cube maps", "[sampling][batch][gpu]") {
    std::mt19937 rng(66);
    Texture cube = make(rng, TextureTarget::Cube, 8, 8);
    sweep(rng, cube);
}

TEST_CASE("Fast's batched GPU-rule sampling takes RGBA8 1D, 2D and cube maps only", "[sampling][batch][gpu]") {
    std::mt19937 rng(7);
    CHECK(rt::gpu_batch_samples(make(rng, TextureTarget::Tex2D, 4, 4)));
    std::vector<TextureImage> faces{TextureImage{2, 2, 1, std::vector<glm::vec4>(4, glm::vec4(0.5f))}};
    auto f = Texture::create(TextureTarget::Tex2D, std::move(faces), TextureFormat::RGBA32F);
    REQUIRE(f);
    CHECK_FALSE(rt::gpu_batch_samples(*f));
}

namespace {

// Every lane; some; whole groups of eight on and others off.
rt::LaneMask some_lanes(std::mt19937& rng) {
    const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
    if (kind == 0) return rt::kAllLanes;
    if (kind == 1) return std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    rt::LaneMask lanes = 0;
    while (!lanes)
        for (int g = 0; g < rt::kLanes; g += 8)
            if (rng() & 1) lanes |= rt::LaneMask(0xff) << g;
    return lanes;
}

// sample_gpu_direct() against the per-lane sampler on one batch whose
// coordinates and derivatives `ops` holds, with an implicit LOD.
void check_implicit(std::mt19937& rng, const Texture& texture, const Operands& ops, const char* what) {
    rt::BatchLookup lk;
    lk.implicit = true;
    for (int c = 0; c < 3; ++c) {
        lk.coord[c] = ops.coord[c];
        lk.ddx[c] = ops.ddx[c];
        lk.ddy[c] = ops.ddy[c];
    }
    const rt::LaneMask lanes = some_lanes(rng);
    alignas(64) float got[4][rt::kLanes];
    for (auto& channel : got)
        for (float& v : channel) v = -7.0f;  // kept outside the mask
    rt::sample_gpu_direct(texture, lk, lanes, got);
    expect_lanes(texture, ops, lk, lanes, got, what);
}

// Close lanes of a 2D texture (close_lanes()), each pixel `scale` texels:
// whole groups inside a clamped image (the border's rules' groups without
// a border texel), on its edges and corners, paired row loads. Each lane's
// derivatives are scaled by their own factor, as a receding surface's
// quads each have their level of detail: the mipmapped kernel must take
// every quad's from its first lane, whatever the other lanes and the
// masked groups hold.
void check_close(std::mt19937& rng, const Texture& texture, float scale) {
    Operands ops{};
    close_lanes(rng, texture, scale, ops.coord);
    std::uniform_real_distribution<float> slope(0.5f, 2.0f);
    for (int i = 0; i < rt::kLanes; ++i) {
        const float k = slope(rng);
        ops.ddx[0][i] = k * scale / float(texture.levels(0)[0].width);
        ops.ddy[1][i] = k * scale / float(texture.levels(0)[0].height);
    }
    check_implicit(rng, texture, ops, "close");
}

// Close directions on a cube map, as a reflection's are: the lanes laid out
// as close_lanes()'s pixels, `step` apart on a face (whose side is 2) from
// a point near its edges or corners, so that a group reads one face or
// straddles two or three; the derivatives one pixel's step.
void check_close_cube(std::mt19937& rng, const Texture& texture, float step) {
    Operands ops{};
    const int axis = std::uniform_int_distribution<int>(0, 2)(rng), u = (axis + 1) % 3, v = (axis + 2) % 3;
    const float major = rng() & 1 ? 1.0f : -1.0f;
    std::uniform_real_distribution<float> near(-1.3f, 1.3f);
    const float u0 = near(rng), v0 = near(rng);
    for (int i = 0; i < rt::kLanes; ++i) {
        const int q = i / 4;
        ops.coord[axis][i] = major;
        ops.coord[u][i] = u0 + float(2 * (q % 4) + (i & 1)) * step;
        ops.coord[v][i] = v0 + float(2 * (q / 4) + ((i >> 1) & 1)) * step;
        ops.ddx[u][i] = step;
        ops.ddy[v][i] = step;
    }
    check_implicit(rng, texture, ops, "close cube");
}

// The filter pairs of one filter within the level, without and with mipmaps.
constexpr std::pair<TextureFilter, TextureFilter> kSameFilters[] = {
    {TextureFilter::Linear, TextureFilter::Linear},
    {TextureFilter::Nearest, TextureFilter::Nearest},
    {TextureFilter::LinearMipmapLinear, TextureFilter::Linear},
    {TextureFilter::NearestMipmapLinear, TextureFilter::Nearest},
    {TextureFilter::LinearMipmapNearest, TextureFilter::Linear},
};

}  // namespace

// Fast's one-pass kernels on lanes close together, as the rasterizer packs
// a magnified or slightly minified image's (the sweeps above draw every
// lane apart): several groups in flight, whole groups masked off, the
// border's rules' groups that hold no border texel, each against the
// per-lane sampler; sizes of four texels, odd ones and under four.
TEST_CASE("Fast's one-pass lookups of close lanes equal its per-lane ones", "[sampling][batch][gpu][close]") {
    if (!rt::cpu_has_avx2()) return;
    std::mt19937 rng(5150);
    for (auto [w, h] : {std::pair{4, 4}, {5, 9}, {16, 16}, {37, 21}, {3, 12}}) {
        Texture t = make(rng, TextureTarget::Tex2D, w, h);
        t.sampler.border_color = {0.25f, 0.0f, 1.0f, 0.5f};
        for (TextureWrap s : kWraps)
            for (TextureWrap u : kWraps)
                for (auto [min, mag] : kSameFilters) {
                    t.sampler.wrap_s = s;
                    t.sampler.wrap_t = u;
                    t.sampler.min_filter = min;
                    t.sampler.mag_filter = mag;
                    REQUIRE(rt::gpu_direct_samples(t));
                    const bool mip = rt::is_mipmap_filter(min);
                    for (float scale : {0.0f, 0.1f, 0.45f, 0.7f, 1.2f, 2.5f})
                        for (int batch = 0; batch < 3; ++batch) check_close(rng, t, mip ? 2.0f * scale + 0.3f : scale);
                }
    }
}

// Fast's one-pass cube-map kernel against the per-lane sampler: the random
// sweep (directions apart: groups over several faces), then close
// directions at the faces' edges and corners, mipmapped or not.
TEST_CASE("Fast's one-pass cube-map lookups equal its per-lane ones", "[sampling][batch][gpu]") {
    if (!rt::cpu_has_avx2()) return;
    std::mt19937 rng(4242);
    Texture cube = make(rng, TextureTarget::Cube, 8, 8);
    // 3 NEAREST pairs x 16 wrap pairs (CLAMP is CLAMP_TO_EDGE's there) + 3 LINEAR pairs x 9.
    CHECK(sweep_direct(rng, cube) == 75);
    Texture odd = make(rng, TextureTarget::Cube, 5, 5);
    bias_and_clamp(odd);
    CHECK(sweep_direct(rng, odd) == 75);
    for (Texture* t : {&cube, &odd}) {
        t->sampler = SamplerState{};
        const float texel = 2.0f / float(t->levels(0)[0].width);
        for (TextureWrap s : {TextureWrap::ClampToEdge, TextureWrap::Repeat, TextureWrap::MirroredRepeat})
            for (auto [min, mag] : kSameFilters) {
                t->sampler.wrap_s = s;
                t->sampler.wrap_t = TextureWrap::ClampToEdge;
                t->sampler.min_filter = min;
                t->sampler.mag_filter = mag;
                REQUIRE(rt::gpu_direct_samples(*t));
                for (float scale : {0.05f, 0.3f, 0.9f, 1.7f, 4.0f})
                    for (int batch = 0; batch < 6; ++batch) check_close_cube(rng, *t, scale * texel);
            }
    }
}
