// Fast's 3D lookups (the GPU's rule, runtime/sampling_gpu.h's linear_sum()):
// each texel's weight at coordinates whose weights NVIDIA's driver gave in
// tools/gpu_probes/tex3dw.frag, and the batched kernel
// (runtime/sampling_gpu3d.h) against the per-lane sampler bit for bit over
// random textures, coordinates (NaN, infinities and huge ones among them),
// filters and wraps, lanes partly masked.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <vector>

#include "runtime/interp_kernels.h"
#include "runtime/sampling_gpu3d.h"
#include "runtime/sampling_rules.h"
#include "tests/runtime/sampling_inputs.h"

using namespace glslrun;

namespace {

Texture texture3d(int w, int h, int d, std::vector<glm::vec4> texels) {
    std::vector<TextureImage> images{TextureImage{w, h, d, std::move(texels)}};
    auto t = Texture::create(TextureTarget::Tex3D, std::move(images), TextureFormat::RGBA8);
    if (!t) FAIL(t.error().str());
    t->sampler.min_filter = TextureFilter::Linear;
    return std::move(*t);
}

// A 2x2x2 texture whose channel c is 1 at texel (x, y, z) = v, index
// v = 4x + 2y + z in [first, first + 4), else 0.
Texture impulses(int first) {
    std::vector<glm::vec4> texels(8, glm::vec4(0.0f));
    for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y)
            for (int z = 0; z < 2; ++z) {
                const int v = 4 * x + 2 * y + z, c = v - first;
                if (c >= 0 && c < 4) texels[size_t(x + 2 * (y + 2 * z))][c] = 1.0f;
            }
    return texture3d(2, 2, 2, std::move(texels));
}

struct Measured {
    int fx, fy, fz;            // the fractions (of 65536) from texel 0 towards texel 1 on each axis
    std::array<int, 8> w;      // the GPU's weight (of 256) of texel 4x + 2y + z
};

}  // namespace

// The 8-bit weights wx, wy, wz (fractions rounded, ties up); the planes z0
// and z1 take 256 - wz and wz; each plane's columns round(wx share / 256)
// and the rest, each column's second row round(column wy / 256), ties up in
// the second column and down in the first, as a mipmap level's share is
// split. The first three rows differ from the 2D weights split along z
// (w11 = round(wx wy / 256), then each by wz), the next two from splitting
// a plane with ties the other way; wx = 256 starts the footprint at the
// second column, which then rounds as a first one.
TEST_CASE("Fast weighs a 3D lookup's eight texels as NVIDIA's driver", "[sampling][gpu]") {
    const Texture low = impulses(0), high = impulses(4);
    for (const Measured& m : {Measured{586, 17472, 864, {184, 2, 67, 1, 1, 0, 1, 0}},       // w8 2 68 3
                              Measured{972, 20890, 922, {169, 3, 79, 1, 3, 0, 1, 0}},       // w8 4 82 4
                              Measured{1358, 24308, 980, {155, 3, 92, 1, 3, 0, 2, 0}},      // w8 5 95 4
                              Measured{2323, 32853, 1125, {122, 2, 121, 2, 4, 0, 5, 0}},    // w8 9 128 4
                              Measured{26834, 53288, 4808, {26, 2, 114, 9, 18, 1, 79, 7}},  // w8 105 208 19
                              Measured{65434, 1872, 10608, {0, 0, 0, 0, 209, 40, 6, 1}}}) { // w8 256 7 41
        // s = (1/2 + f) / 2 on two texels: u - 1/2 = f, exact in float.
        const glm::vec3 coord((0.5f + float(m.fx) / 65536.0f) / 2.0f, (0.5f + float(m.fy) / 65536.0f) / 2.0f,
                              (0.5f + float(m.fz) / 65536.0f) / 2.0f);
        const glm::vec4 a = rt::sample_texture(low, coord, 0.0f, 0.0f, rt::SamplingRules::Gpu);
        const glm::vec4 b = rt::sample_texture(high, coord, 0.0f, 0.0f, rt::SamplingRules::Gpu);
        for (int v = 0; v < 8; ++v) {
            INFO("fractions " << m.fx << ", " << m.fy << ", " << m.fz << " texel " << v);
            // An impulse's 16-bit result: (65535 w + 128) >> 8, exactly r / 65535.
            const float want = float((65535 * m.w[size_t(v)] + 128) >> 8) / 65535.0f;
            CHECK(std::bit_cast<uint32_t>(v < 4 ? a[v] : b[v - 4]) == std::bit_cast<uint32_t>(want));
        }
    }
}

namespace {

using namespace sampling_inputs;

Texture random3d(std::mt19937& rng, int w, int h, int d) {
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<glm::vec4> texels;
    for (int i = 0; i < w * h * d; ++i)
        texels.push_back({byte(rng) / 255.0f, byte(rng) / 255.0f, byte(rng) / 255.0f, byte(rng) / 255.0f});
    return texture3d(w, h, d, std::move(texels));
}

void check_batch(std::mt19937& rng, const Texture& texture) {
    alignas(32) float coord[3][rt::kLanes];
    for (auto& axis : coord)
        for (float& c : axis) c = coordinate(rng);
    rt::BatchLookup lk;
    lk.implicit = true;
    for (int c = 0; c < 3; ++c) lk.coord[c] = coord[c];
    const rt::LaneMask lanes = std::uniform_int_distribution<rt::LaneMask>(0, rt::kAllLanes)(rng) | 1;
    alignas(64) float out[4][rt::kLanes];
    for (auto& channel : out)
        for (float& v : channel) v = -7.0f;  // what lanes outside the mask must keep
    rt::sample_gpu3d(texture, lk, lanes, out);
    for (int i = 0; i < rt::kLanes; ++i) {
        float want[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
        if ((lanes >> i) & 1) {
            rt::LaneLookup lane;
            lane.rules = rt::SamplingRules::Gpu;
            lane.coord = {coord[0][i], coord[1][i], coord[2][i]};
            lane.implicit = true;
            rt::sample_complete_lane(texture, lane, want);
        }
        for (int c = 0; c < 4; ++c) {
            INFO("lane " << i << " channel " << c << " coord (" << coord[0][i] << ", " << coord[1][i] << ", "
                         << coord[2][i] << ") got " << out[c][i] << " want " << want[c]);
            REQUIRE(std::bit_cast<uint32_t>(out[c][i]) == std::bit_cast<uint32_t>(want[c]));
        }
    }
}

}  // namespace

TEST_CASE("Fast's batched 3D lookups equal its per-lane ones", "[sampling][batch][gpu]") {
    if (!rt::cpu_has_avx2()) return;  // the kernel is for AVX2 machines; the others take the per-lane path
    std::mt19937 rng(3);
    constexpr TextureWrap kInner[] = {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge};
    for (auto [w, h, d] : {std::array{2, 2, 2}, std::array{5, 3, 4}, std::array{1, 7, 3}, std::array{32, 32, 32}}) {
        Texture texture = random3d(rng, w, h, d);
        for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear})
            for (TextureWrap s : kInner)
                for (TextureWrap t : kInner)
                    for (TextureWrap r : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge,
                                          TextureWrap::Clamp}) {
                        texture.sampler.min_filter = texture.sampler.mag_filter = filter;
                        texture.sampler.wrap_s = s;
                        texture.sampler.wrap_t = t;
                        texture.sampler.wrap_r = r;
                        // LINEAR's CLAMP can read the border: the per-lane path's.
                        const bool taken = filter == TextureFilter::Nearest || r != TextureWrap::Clamp;
                        REQUIRE(rt::gpu3d_samples(texture) == taken);
                        if (!taken) continue;
                        for (int batch = 0; batch < 4; ++batch) check_batch(rng, texture);
                    }
    }
}

TEST_CASE("Fast's batched 3D kernel takes one-image RGBA8 3D textures only", "[sampling][batch][gpu]") {
    std::mt19937 rng(5);
    Texture texture = random3d(rng, 4, 4, 4);
    CHECK(rt::gpu3d_samples(texture));
    texture.sampler.wrap_s = TextureWrap::ClampToBorder;
    CHECK_FALSE(rt::gpu3d_samples(texture));
    texture.sampler.wrap_s = TextureWrap::Repeat;
    texture.sampler.mag_filter = TextureFilter::Nearest;  // the level of detail picks the filter
    CHECK_FALSE(rt::gpu3d_samples(texture));
    texture.generate_mipmaps();
    texture.sampler.mag_filter = TextureFilter::Linear;
    texture.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    CHECK_FALSE(rt::gpu3d_samples(texture));
    std::vector<TextureImage> images{TextureImage{2, 2, 2, std::vector<glm::vec4>(8, glm::vec4(0.5f))}};
    auto f = Texture::create(TextureTarget::Tex3D, std::move(images), TextureFormat::RGBA32F);
    REQUIRE(f);
    CHECK_FALSE(rt::gpu3d_samples(*f));
}

// The GPU's LINEAR sum reads the lookup's layer of an array texture (it read
// layer 0 whatever the coordinate before the 3D planes shared its code).
TEST_CASE("Fast's LINEAR lookups of array textures read the lookup's layer", "[sampling][gpu]") {
    for (TextureTarget target : {TextureTarget::Tex1DArray, TextureTarget::Tex2DArray}) {
        const bool one = target == TextureTarget::Tex1DArray;
        // Two layers of 2 (x 2) texels: layer 0 black, layer 1 white.
        std::vector<glm::vec4> texels;
        for (int layer = 0; layer < 2; ++layer)
            for (int i = 0; i < (one ? 2 : 4); ++i) texels.push_back(glm::vec4(float(layer)));
        std::vector<TextureImage> images{one ? TextureImage{2, 2, 1, texels} : TextureImage{2, 2, 2, texels}};
        auto t = Texture::create(target, std::move(images), TextureFormat::RGBA8);
        REQUIRE(t);
        t->sampler.min_filter = t->sampler.mag_filter = TextureFilter::Linear;
        const glm::vec3 coord = one ? glm::vec3(0.3f, 1.0f, 0.0f) : glm::vec3(0.3f, 0.6f, 1.0f);
        INFO("target " << int(target));
        CHECK(rt::sample_texture(*t, coord, 0.0f, 0.0f, rt::SamplingRules::Gpu) == glm::vec4(1.0f));
        CHECK(rt::sample_texture(*t, coord, 0.0f, 0.0f, rt::SamplingRules::Common) == glm::vec4(1.0f));
    }
}
