// Rectangle textures (ARB_texture_rectangle) on small hand-made textures:
// unnormalized coordinates, the three clamping wraps, NEAREST and LINEAR,
// the magnification switch, depth comparison, and what GL refuses for a
// rectangle. Every expected value is worked out by hand from the extension's
// rules (u = s, not s * width), not by a second sampler.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "runtime/sampling.h"

using namespace glslrun;

namespace {

// A 4x2 rectangle whose texel (i, j) is (i, j, i + 10 j, 1).
Texture ramp(TextureFilter filter, TextureWrap wrap) {
    TextureImage img{4, 2, 1, {}};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) img.texels.push_back({float(i), float(j), float(i + 10 * j), 1.0f});
    auto t = Texture::create(TextureTarget::Rect, {img}, TextureFormat::RGBA32F);
    if (!t) FAIL(t.error().str());
    t->sampler.min_filter = t->sampler.mag_filter = filter;
    t->sampler.wrap_s = t->sampler.wrap_t = wrap;
    t->sampler.border_color = {0.5f, 0.5f, 0.5f, 0.5f};
    return std::move(*t);
}

glm::vec4 at(const Texture& t, float s, float tt) { return rt::sample_texture(t, {s, tt, 0.0f}, 0.0f, 0.0f); }

void check_vec(const glm::vec4& got, const glm::vec4& want) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ", " << got.w << "), want (" << want.x << ", "
                 << want.y << ", " << want.z << ", " << want.w << ")");
    for (int c = 0; c < 4; ++c) CHECK(got[c] == want[c]);
}

}  // namespace

TEST_CASE("A rectangle starts with GL's state for rectangles and refuses mipmaps", "[sampling][rectangle]") {
    Texture t = ramp(TextureFilter::Linear, TextureWrap::ClampToEdge);
    auto fresh = Texture::create(TextureTarget::Rect, {TextureImage{2, 2, 1, std::vector<glm::vec4>(4)}});
    REQUIRE(fresh);
    CHECK(fresh->sampler.min_filter == TextureFilter::Linear);
    CHECK(fresh->sampler.wrap_s == TextureWrap::ClampToEdge);
    CHECK(fresh->sampler.wrap_t == TextureWrap::ClampToEdge);
    CHECK(fresh->complete());
    Status level = t.set_level(0, 1, TextureImage{2, 1, 1, std::vector<glm::vec4>(2)});
    REQUIRE_FALSE(level);
    CHECK(level.error().str().find("rectangles have level 0 only") != std::string::npos);
    t.generate_mipmaps();
    CHECK(t.levels(0).size() == 1);
    CHECK_FALSE(Texture::create(TextureTarget::Rect, {TextureImage{2, 2, 2, std::vector<glm::vec4>(8)}}));
    // Depth rectangles exist (shadow2DRect); 3D and cube depth textures do not.
    CHECK(Texture::create(TextureTarget::Rect, {TextureImage{2, 2, 1, std::vector<glm::vec4>(4)}},
                          TextureFormat::Depth));
}

TEST_CASE("A rectangle with a state GL refuses is incomplete and samples (0, 0, 0, 1)", "[sampling][rectangle]") {
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::MirroredRepeat}) {
        Texture t = ramp(TextureFilter::Nearest, TextureWrap::ClampToEdge);
        t.sampler.wrap_t = wrap;
        CHECK_FALSE(t.complete());
        check_vec(at(t, 1.5f, 0.5f), {0, 0, 0, 1});
    }
    Texture mip = ramp(TextureFilter::Nearest, TextureWrap::ClampToEdge);
    mip.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    CHECK_FALSE(mip.complete());
    Texture base = ramp(TextureFilter::Nearest, TextureWrap::ClampToEdge);
    base.sampler.base_level = 1;
    CHECK_FALSE(base.complete());
}

TEST_CASE("NEAREST on a rectangle takes texel floor(u) of the unnormalized coordinate", "[sampling][rectangle]") {
    Texture edge = ramp(TextureFilter::Nearest, TextureWrap::ClampToEdge);
    check_vec(at(edge, 0.5f, 0.5f), {0, 0, 0, 1});
    check_vec(at(edge, 2.99f, 1.0f), {2, 1, 12, 1});
    check_vec(at(edge, 3.0f, 1.99f), {3, 1, 13, 1});  // a 2D texture would read s = 3 as past its end
    check_vec(at(edge, 9.0f, -4.0f), {3, 0, 3, 1});   // clamped to the last and first texel
    Texture clamp = ramp(TextureFilter::Nearest, TextureWrap::Clamp);
    check_vec(at(clamp, 4.0f, 2.0f), {3, 1, 13, 1});  // u = w reads the last texel, never the border
    check_vec(at(clamp, -1.0f, 0.5f), {0, 0, 0, 1});
    Texture border = ramp(TextureFilter::Nearest, TextureWrap::ClampToBorder);
    check_vec(at(border, 3.5f, 1.5f), {3, 1, 13, 1});
    check_vec(at(border, 4.0f, 1.5f), {0.5f, 0.5f, 0.5f, 0.5f});
    check_vec(at(border, -0.01f, 0.5f), {0.5f, 0.5f, 0.5f, 0.5f});
    float nan = std::numeric_limits<float>::quiet_NaN();
    check_vec(at(edge, nan, 0.5f), {0, 0, 0, 1});  // NaN reads some texel of the image
}

TEST_CASE("LINEAR on a rectangle blends around u - 1/2 with each clamp", "[sampling][rectangle]") {
    Texture edge = ramp(TextureFilter::Linear, TextureWrap::ClampToEdge);
    check_vec(at(edge, 1.5f, 0.5f), {1, 0, 1, 1});           // a texel centre
    check_vec(at(edge, 1.75f, 0.5f), {1.25f, 0, 1.25f, 1});  // a quarter towards texel 2
    check_vec(at(edge, 2.0f, 1.0f), {1.5f, 0.5f, 6.5f, 1});  // between four texels
    check_vec(at(edge, 0.1f, 3.0f), {0, 1, 10, 1});          // clamped to [1/2, w - 1/2]
    Texture clamp = ramp(TextureFilter::Linear, TextureWrap::Clamp);
    // u = 0: half texel 0, half the border (GL's CLAMP lets the border blend in).
    check_vec(at(clamp, -3.0f, 0.5f), {0.25f, 0.25f, 0.25f, 0.75f});
    Texture border = ramp(TextureFilter::Linear, TextureWrap::ClampToBorder);
    // u = 4.25: a quarter of texel 3, three quarters of the border.
    check_vec(at(border, 4.25f, 0.5f), {1.125f, 0.375f, 1.125f, 0.625f});
    check_vec(at(border, 9.0f, 0.5f), {0.5f, 0.5f, 0.5f, 0.5f});  // wholly outside: the border
}

TEST_CASE("A rectangle magnifies or minifies by rho over its own texels", "[sampling][rectangle]") {
    // One texel per pixel is lambda = 0: magnification; two per pixel, lambda = 1, the min filter.
    Texture t = ramp(TextureFilter::Linear, TextureWrap::ClampToEdge);
    t.sampler.min_filter = TextureFilter::Nearest;
    rt::LaneLookup lk;
    lk.coord = {1.75f, 0.5f, 0.0f};
    lk.ddx = {1.0f, 0.0f, 0.0f};
    lk.ddy = {0.0f, 1.0f, 0.0f};
    float rgba[4];
    rt::sample_rect_lane(t, lk, rgba);
    CHECK(rgba[0] == 1.25f);  // LINEAR (mag)
    lk.ddx = {2.0f, 0.0f, 0.0f};
    rt::sample_rect_lane(t, lk, rgba);
    CHECK(rgba[0] == 1.0f);  // NEAREST (min)
    lk.bias = true;
    lk.lod = -1.0f;  // the shader's bias brings lambda back to 0
    rt::sample_rect_lane(t, lk, rgba);
    CHECK(rgba[0] == 1.25f);
}

TEST_CASE("shadow2DRect compares each texel, then filters", "[sampling][rectangle]") {
    TextureImage img{2, 1, 1, {{0.25f, 0, 0, 1}, {0.75f, 0, 0, 1}}};
    auto t = Texture::create(TextureTarget::Rect, {img}, TextureFormat::Depth);
    REQUIRE(t);
    t->sampler.compare = true;
    t->sampler.compare_func = CompareFunc::Lequal;
    t->sampler.depth_mode = DepthTextureMode::Intensity;
    check_vec(rt::sample_texture(*t, {0.5f, 0.5f, 0}, 0.5f, 0.0f), {0, 0, 0, 0});  // 0.5 <= 0.25 fails
    check_vec(rt::sample_texture(*t, {1.5f, 0.5f, 0}, 0.5f, 0.0f), {1, 1, 1, 1});
    check_vec(rt::sample_texture(*t, {1.0f, 0.5f, 0}, 0.5f, 0.0f), {0.5f, 0.5f, 0.5f, 0.5f});
}
