// Array textures (EXT_texture_array) on small hand-made textures: the layer
// rounding clamp(floor(r + 1/2), 0, d - 1), filtering within one layer only,
// mipmaps that keep the layer count, depth comparison, and the size checks.
// Every expected value is worked out by hand from the extension's rules.
#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "runtime/sampling.h"

using namespace glslrun;

namespace {

// w x h x layers (a 1D array: w x layers x 1); texel (i, j, layer) = (i, j, layer, 1).
Texture ramp(TextureTarget target, int w, int h, int layers) {
    const bool one_d = target == TextureTarget::Tex1DArray;
    TextureImage img{w, one_d ? layers : h, one_d ? 1 : layers, {}};
    for (int l = 0; l < layers; ++l)
        for (int j = 0; j < (one_d ? 1 : h); ++j)
            for (int i = 0; i < w; ++i) img.texels.push_back({float(i), float(j), float(l), 1.0f});
    auto t = Texture::create(target, {img}, TextureFormat::RGBA32F);
    if (!t) FAIL(t.error().str());
    t->sampler.min_filter = t->sampler.mag_filter = TextureFilter::Nearest;
    t->sampler.wrap_s = t->sampler.wrap_t = TextureWrap::ClampToEdge;
    return std::move(*t);
}

void check_vec(const glm::vec4& got, const glm::vec4& want) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ", " << got.w << "), want (" << want.x << ", "
                 << want.y << ", " << want.z << ", " << want.w << ")");
    for (int c = 0; c < 4; ++c) CHECK(got[c] == want[c]);
}

}  // namespace

TEST_CASE("An array lookup takes layer clamp(floor(r + 1/2), 0, d - 1)", "[sampling][array]") {
    const Texture t = ramp(TextureTarget::Tex2DArray, 2, 2, 3);
    auto layer_of = [&](float r) { return rt::sample_texture(t, {0.25f, 0.25f, r}, 0.0f, 0.0f).z; };
    CHECK(layer_of(0.0f) == 0.0f);
    CHECK(layer_of(0.49f) == 0.0f);
    CHECK(layer_of(0.5f) == 1.0f);  // floor(1.0): ties go up
    CHECK(layer_of(1.49f) == 1.0f);
    CHECK(layer_of(1.5f) == 2.0f);
    CHECK(layer_of(7.0f) == 2.0f);   // clamped to the last layer
    CHECK(layer_of(-0.5f) == 0.0f);  // floor(0) = 0
    CHECK(layer_of(-0.51f) == 0.0f);  // clamped to the first
    CHECK(layer_of(std::numeric_limits<float>::quiet_NaN()) == 0.0f);
    const Texture one = ramp(TextureTarget::Tex1DArray, 4, 1, 3);
    check_vec(rt::sample_texture(one, {0.8f, 1.6f, 0.0f}, 0.0f, 0.0f), {3, 0, 2, 1});  // texel 3 of row (layer) 2
}

TEST_CASE("LINEAR filters within the layer, never across layers", "[sampling][array]") {
    Texture t = ramp(TextureTarget::Tex2DArray, 4, 2, 2);
    t.sampler.min_filter = t.sampler.mag_filter = TextureFilter::Linear;
    // s = 0.5: u = 2, between texels 1 and 2; t = 0.5: between rows 0 and 1; layer 1 only.
    check_vec(rt::sample_texture(t, {0.5f, 0.5f, 0.9f}, 0.0f, 0.0f), {1.5f, 0.5f, 1.0f, 1.0f});
    Texture one = ramp(TextureTarget::Tex1DArray, 4, 1, 2);
    one.sampler.min_filter = one.sampler.mag_filter = TextureFilter::Linear;
    // The layer is the row: t = 0.6 is row 1 alone, no blend with row 0.
    check_vec(rt::sample_texture(one, {0.5f, 0.6f, 0.0f}, 0.0f, 0.0f), {1.5f, 0.0f, 1.0f, 1.0f});
}

TEST_CASE("Array mipmaps halve width and height and keep every layer", "[sampling][array]") {
    // 4x4 with 3 layers: levels 2x2x3 and 1x1x3; each level's texels read (level, 0, layer, 1).
    auto level_image = [](int size, int layers, int level) {
        TextureImage img{size, size, layers, {}};
        for (int l = 0; l < layers; ++l)
            for (int k = 0; k < size * size; ++k) img.texels.push_back({float(level), 0.0f, float(l), 1.0f});
        return img;
    };
    auto t = Texture::create(TextureTarget::Tex2DArray, {level_image(4, 3, 0)}, TextureFormat::RGBA32F);
    REQUIRE(t);
    t->sampler.min_filter = TextureFilter::NearestMipmapNearest;
    t->sampler.mag_filter = TextureFilter::Nearest;
    CHECK_FALSE(t->complete());
    REQUIRE(t->set_level(0, 1, level_image(2, 3, 1)));
    REQUIRE(t->set_level(0, 2, level_image(1, 3, 2)));
    CHECK(t->complete());
    check_vec(rt::sample_texture(*t, {0.5f, 0.5f, 2.0f}, 0.0f, 1.0f), {1, 0, 2, 1});
    check_vec(rt::sample_texture(*t, {0.5f, 0.5f, 1.0f}, 0.0f, 5.0f), {2, 0, 1, 1});  // q = 2: log2(4)
    // A level that halves the layer count too is not the next level.
    auto wrong = Texture::create(TextureTarget::Tex2DArray, {level_image(4, 3, 0)}, TextureFormat::RGBA32F);
    REQUIRE(wrong);
    wrong->sampler.min_filter = TextureFilter::NearestMipmapNearest;
    REQUIRE(wrong->set_level(0, 1, level_image(2, 1, 1)));
    REQUIRE(wrong->set_level(0, 2, level_image(1, 1, 2)));
    CHECK_FALSE(wrong->complete());
    // Generated mipmaps average within each layer (layer 2 stays 2) and stop at 1x1.
    Texture gen = ramp(TextureTarget::Tex2DArray, 4, 4, 3);
    gen.sampler.min_filter = TextureFilter::NearestMipmapNearest;
    gen.generate_mipmaps();
    REQUIRE(gen.levels(0).size() == 3);
    CHECK(gen.levels(0)[2].width == 1);
    CHECK(gen.levels(0)[2].depth == 3);
    check_vec(rt::sample_texture(gen, {0.5f, 0.5f, 2.0f}, 0.0f, 2.0f), {1.5f, 1.5f, 2.0f, 1.0f});
    // A 1D array's levels: 8x2 -> 4x2 -> 2x2 -> 1x2 (the layers are its height).
    Texture one = ramp(TextureTarget::Tex1DArray, 8, 1, 2);
    one.generate_mipmaps();
    REQUIRE(one.levels(0).size() == 4);
    CHECK(one.levels(0)[3].width == 1);
    CHECK(one.levels(0)[3].height == 2);
    // The implicit LOD counts only s (and t): two texels per pixel along s is lambda = 1.
    rt::LaneLookup lk;
    lk.coord = {0.5f, 1.0f, 0.0f};
    lk.ddx = {2.0f / 8.0f, 0.0f, 0.0f};
    lk.ddy = {0.0f, 5.0f, 0.0f};  // a derivative of the layer does not count
    CHECK(rt::implicit_lod(one, lk.coord, lk.ddx, lk.ddy) == 1.0f);
}

TEST_CASE("Depth arrays compare per layer; size checks", "[sampling][array]") {
    TextureImage img{2, 1, 2, {{0.25f, 0, 0, 1}, {0.75f, 0, 0, 1}, {0.9f, 0, 0, 1}, {0.9f, 0, 0, 1}}};
    auto t = Texture::create(TextureTarget::Tex2DArray, {img}, TextureFormat::Depth);
    REQUIRE(t);
    t->sampler.min_filter = t->sampler.mag_filter = TextureFilter::Nearest;
    t->sampler.compare = true;
    t->sampler.compare_func = CompareFunc::Lequal;
    CHECK(rt::sample_texture(*t, {0.25f, 0.5f, 0.0f}, 0.5f, 0.0f).x == 0.0f);  // 0.5 <= 0.25: no
    CHECK(rt::sample_texture(*t, {0.75f, 0.5f, 0.0f}, 0.5f, 0.0f).x == 1.0f);
    CHECK(rt::sample_texture(*t, {0.25f, 0.5f, 1.0f}, 0.5f, 0.0f).x == 1.0f);  // layer 1: 0.9
    CHECK_FALSE(Texture::create(TextureTarget::Tex1DArray, {TextureImage{2, 2, 2, std::vector<glm::vec4>(8)}}));
    auto many = Texture::create(TextureTarget::Tex2DArray,
                                {TextureImage{1, 1, kMaxArrayTextureLayers + 1,
                                              std::vector<glm::vec4>(size_t(kMaxArrayTextureLayers) + 1)}});
    REQUIRE_FALSE(many);
    CHECK_THAT(many.error().str(), Catch::Contains("GL_MAX_ARRAY_TEXTURE_LAYERS_EXT"));
    // 2048 layers of a 16x16 image: the layer count is not held to the 2D size limit at level 4.
    auto t2 = Texture::create(TextureTarget::Tex2DArray, {TextureImage{16, 16, 4, std::vector<glm::vec4>(1024)}});
    REQUIRE(t2);
    CHECK(t2->set_level(0, 4, TextureImage{1, 1, 4, std::vector<glm::vec4>(4)}));
}
