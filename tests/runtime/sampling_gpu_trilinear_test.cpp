// Fast's mipmap blend (runtime/sampling_gpu.h, level_weights() and
// filter16()) against values NVIDIA's driver returned (580.159 on an H200,
// tools/gpu_probes/trimp.frag and trilin.frag, decode.py trimp / trilin):
// each texel's integer weight of a two-level lookup, and 16-bit results of
// textureLod on a texture with random levels. Rounding each level to 16 bits
// and blending the two (Fast's rule before) gives none of those results.
#include <catch2/catch.hpp>

#include <array>
#include <vector>

#include "runtime/interp_kernels.h"
#include "runtime/sampling.h"
#include "runtime/sampling_gpu.h"
#include "runtime/sampling_gpu_batch.h"

using namespace glslrun;

namespace {

// trimp.frag mode 0 (textureLod; one impulse texel per channel, so each
// channel read back is one texel's weight): the level's share of the
// lookup, its 8-bit weights wx, wy, and the four weights the GPU gave
// (t00, t01, t10, t11). The last rows are the ties, and wx = 256.
struct WeightRow {
    int share, wx, wy;
    std::array<int, 4> gpu;
};
constexpr WeightRow kWeightRows[] = {
    {174, 192, 31, {38, 115, 5, 16}},   // pixel (0, 0), level 0
    {82, 160, 79, {21, 35, 10, 16}},    // pixel (0, 0), level 1
    {213, 179, 110, {37, 85, 27, 64}},  // the first column's tie (27.5) goes down
    {227, 148, 164, {35, 47, 61, 84}},
    {73, 4, 240, {5, 0, 67, 1}},
    {193, 132, 128, {47, 50, 46, 50}},  // the second column's (99.5) up
    {173, 239, 128, {6, 81, 5, 81}},
    {64, 256, 118, {0, 35, 0, 29}},     // wx = 256: the second column rounds as a first
    {187, 256, 128, {0, 94, 0, 93}},
    {224, 256, 252, {0, 4, 0, 220}},
    {192, 256, 2, {0, 191, 0, 1}},
};

// rand_l8.png .. rand_l1.png's red channel (tools/gpu_probes, seed 25), rows from t = 0.
const std::vector<int> kLevels[] = {
    {158, 159, 136, 48,  153, 112, 193, 25,  52, 120, 76,  241, 220, 123, 222, 210, 145, 253, 23,  66, 46, 146,
     150, 84,  128, 158, 146, 34,  188, 221, 162, 195, 72, 83,  39,  14,  92,  217, 255, 3,   217, 171, 225, 31,
     151, 178, 7,   20,  72,  33,  152, 48,  68,  205, 167, 108, 84, 216, 188, 20,  23,  57,  225, 2},
    {232, 152, 173, 0, 48, 220, 146, 70, 43, 178, 16, 142, 4, 103, 177, 120},
    {255, 242, 208, 215},
    {149},
};

// trilin.frag mode 1 (textureLod at s, t in 1/65536 and lambda in 1/1024 on
// those levels, LINEAR_MIPMAP_LINEAR, REPEAT): the red channel in 16 bits.
struct LookupRow {
    int s, t, lambda, gpu;
};
constexpr LookupRow kLookupRows[] = {
    {15682, 11305, 35, 28180},   {30105, 18303, 1943, 61728}, {42360, 61965, 1998, 57315},
    {16925, 7112, 3056, 38671},  {23011, 37244, 402, 23416},  {42025, 28006, 685, 37001},
    {46877, 11457, 2173, 58574}, {25326, 32250, 520, 32463},  {63618, 28252, 2695, 46488},
    {50374, 40786, 1377, 34516}, {30128, 53001, 2675, 44977}, {9460, 16597, 349, 39572},
    {38506, 29394, -172, 48251},  // magnified
    {45696, 56781, 3279, 38293},  // the last level
};

Texture random_levels() {
    std::vector<TextureImage> levels;
    for (const std::vector<int>& level : kLevels) {
        const int n = level.size() == 64 ? 8 : level.size() == 16 ? 4 : level.size() == 4 ? 2 : 1;
        TextureImage image{n, n, 1, {}};
        for (int v : level) image.texels.push_back({v / 255.0f, 0.0f, 0.0f, 1.0f});
        levels.push_back(std::move(image));
    }
    auto t = Texture::create(TextureTarget::Tex2D, {levels[0]}, TextureFormat::RGBA8);
    if (!t) FAIL(t.error().str());
    for (int level = 1; level < int(levels.size()); ++level) REQUIRE(t->set_level(0, level, levels[size_t(level)]));
    t->sampler.min_filter = TextureFilter::LinearMipmapLinear;
    t->sampler.mag_filter = TextureFilter::Linear;
    REQUIRE(t->complete());
    return std::move(*t);
}

}  // namespace

TEST_CASE("Fast weighs a mipmap blend's eight texels as NVIDIA's driver", "[sampling][gpu]") {
    for (const WeightRow& row : kWeightRows) {
        const rt::sampling::gpu::TexelWeights w = rt::sampling::gpu::level_weights(row.wx, row.wy, row.share);
        INFO("share " << row.share << " wx " << row.wx << " wy " << row.wy);
        CHECK(std::array<int, 4>{w.w00, w.w01, w.w10, w.w11} == row.gpu);
    }
    // A whole lookup (share 256) weighs as the bilinear rule texfilter.frag measured.
    for (int wx = 0; wx <= 256; ++wx)
        for (int wy = 0; wy <= 256; ++wy) {
            const rt::sampling::gpu::TexelWeights w = rt::sampling::gpu::level_weights(wx, wy, 256);
            const int w11 = (wx * wy + 128) >> 8;
            REQUIRE(std::array<int, 4>{w.w00, w.w01, w.w10, w.w11} ==
                    std::array<int, 4>{256 - wx - wy + w11, wx - w11, wy - w11, w11});
        }
}

TEST_CASE("Fast's textureLod between two levels returns NVIDIA's 16-bit values", "[sampling][gpu]") {
    const Texture texture = random_levels();
    for (const LookupRow& row : kLookupRows) {
        const float s = float(row.s) / 65536.0f, t = float(row.t) / 65536.0f, lambda = float(row.lambda) / 1024.0f;
        INFO("s " << row.s << "/65536 t " << row.t << "/65536 lambda " << row.lambda << "/1024");
        rt::LaneLookup lane;
        lane.rules = rt::SamplingRules::Gpu;
        lane.coord = {s, t, 0.0f};
        lane.implicit = false;
        lane.lod = lambda;
        float rgba[4];
        rt::sample_complete_lane(texture, lane, rgba);
        CHECK(rgba[0] == float(row.gpu) / 65535.0f);
        // The batched sampler, every lane this lookup.
        alignas(32) float coord[3][rt::kLanes], lod[rt::kLanes], zero[3][rt::kLanes] = {};
        for (int i = 0; i < rt::kLanes; ++i) {
            coord[0][i] = s;
            coord[1][i] = t;
            coord[2][i] = 0.0f;
            lod[i] = lambda;
        }
        rt::BatchLookup lk;
        lk.implicit = false;
        lk.lod = lod;
        for (int c = 0; c < 3; ++c) {
            lk.coord[c] = coord[c];
            lk.ddx[c] = lk.ddy[c] = zero[c];
        }
        for (bool avx2 : {false, true}) {
            if (avx2 && !rt::cpu_has_avx2()) continue;
            alignas(64) float out[4][rt::kLanes];
            rt::sample_gpu_batch(texture, lk, rt::kAllLanes, out, avx2);
            INFO("avx2 " << avx2);
            CHECK(out[0][0] == float(row.gpu) / 65535.0f);
            CHECK(out[0][rt::kLanes - 1] == float(row.gpu) / 65535.0f);
        }
    }
}
