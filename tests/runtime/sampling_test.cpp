// Texture objects and sampling (GL 2.1 §3.8) on small hand-made textures:
// every expected value below is worked out by hand from the specification
// (texel indices, linear weights, mipmap levels), not by a second sampler.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "runtime/sampling.h"

using namespace glslrun;
using rt::implicit_lod;
using rt::sample_texture;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const glm::vec3 kZero(0.0f);

void check_vec(const glm::vec4& got, const glm::vec4& want, float margin = 1e-5f) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << ", " << got.w << "), want (" << want.x << ", "
                 << want.y << ", " << want.z << ", " << want.w << ")");
    for (int c = 0; c < 4; ++c) CHECK(got[c] == Approx(want[c]).margin(margin));
}

Texture make(TextureTarget target, std::vector<TextureImage> faces, TextureFormat format = TextureFormat::RGBA32F) {
    auto t = Texture::create(target, std::move(faces), format);
    if (!t) FAIL(t.error().str());
    return std::move(*t);
}

// width x height x depth, texel (i, j, k) = f(i, j, k).
template <class F>
TextureImage image(int w, int h, int d, F f) {
    TextureImage img{w, h, d, {}};
    for (int k = 0; k < d; ++k)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) img.texels.push_back(f(i, j, k));
    return img;
}
TextureImage solid(int w, int h, glm::vec4 c) { return {w, h, 1, std::vector<glm::vec4>(size_t(w * h), c)}; }

void set_filters(Texture& t, TextureFilter min, TextureFilter mag) {
    t.sampler.min_filter = min;
    t.sampler.mag_filter = mag;
}

std::string create_error(TextureTarget target, std::vector<TextureImage> faces,
                         TextureFormat format = TextureFormat::RGBA32F) {
    auto t = Texture::create(target, std::move(faces), format);
    REQUIRE_FALSE(t.ok());
    REQUIRE_FALSE(t.error().diagnostics.empty());
    return t.error().diagnostics[0].message;
}

// ------------------------------------------------------------------ wraps ---
// A 1D texture of 4 texels, texel i = (i + 1, -(i + 1), 0.5, 1), and a border
// (0, 0.5, 0.75, 1) that no texel has.
const glm::vec4 kBorder{0, 0.5f, 0.75f, 1};
glm::vec4 texel4(int i) { return i < 0 ? kBorder : glm::vec4(float(i + 1), -float(i + 1), 0.5f, 1); }

Texture wrap_texture(TextureWrap wrap, TextureFilter filter) {
    Texture t = make(TextureTarget::Tex1D, {image(4, 1, 1, [](int i, int, int) { return texel4(i); })});
    set_filters(t, filter, filter);
    t.sampler.wrap_s = wrap;
    t.sampler.border_color = kBorder;
    return t;
}

struct NearestCase { float s; int i; };  // i = -1: the border
struct LinearCase { float s; int i0, i1; float a; };

void check_nearest(TextureWrap wrap, const std::vector<NearestCase>& cases) {
    const Texture t = wrap_texture(wrap, TextureFilter::Nearest);
    for (const NearestCase& c : cases) {
        INFO("wrap " << int(wrap) << " s = " << c.s);
        check_vec(sample_texture(t, {c.s, 0, 0}, 0, 0), texel4(c.i));
    }
}

void check_linear(TextureWrap wrap, const std::vector<LinearCase>& cases) {
    const Texture t = wrap_texture(wrap, TextureFilter::Linear);
    for (const LinearCase& c : cases) {
        INFO("wrap " << int(wrap) << " s = " << c.s);
        check_vec(sample_texture(t, {c.s, 0, 0}, 0, 0), texel4(c.i0) * (1 - c.a) + texel4(c.i1) * c.a);
    }
}

}  // namespace

TEST_CASE("NEAREST under every wrap mode, inside and outside [0, 1]", "[sampling][wrap]") {
    check_nearest(TextureWrap::Repeat, {{0.1f, 0}, {0.3f, 1}, {0.99f, 3}, {1.0f, 0}, {1.3f, 1}, {-0.1f, 3},
                                        {-1.6f, 1}, {2.9f, 3}});
    check_nearest(TextureWrap::ClampToEdge, {{-0.5f, 0}, {0.1f, 0}, {0.6f, 2}, {1.0f, 3}, {1.7f, 3}});
    // CLAMP reaches the border only by linear filtering.
    check_nearest(TextureWrap::Clamp, {{-0.5f, 0}, {0.0f, 0}, {0.6f, 2}, {1.0f, 3}, {1.5f, 3}});
    check_nearest(TextureWrap::ClampToBorder, {{-0.01f, -1}, {0.01f, 0}, {0.5f, 2}, {0.99f, 3}, {1.0f, -1},
                                               {1.2f, -1}, {-3.0f, -1}});
    // mirror(f): frac(f) for even floor(f), 1 - frac(f) for odd; then clamped to the edge.
    check_nearest(TextureWrap::MirroredRepeat, {{0.1f, 0}, {1.1f, 3}, {1.6f, 1}, {-0.1f, 0}, {-0.6f, 2},
                                                {2.3f, 1}, {-1.3f, 2}, {1.0f, 3}, {2.0f, 0}});
}

TEST_CASE("LINEAR under every wrap mode: indices, weights and the border", "[sampling][wrap]") {
    // u = s * 4; i0 = floor(u - 1/2), i1 = i0 + 1, alpha = frac(u - 1/2).
    check_linear(TextureWrap::Repeat, {{0.5f, 1, 2, 0.5f}, {0.375f, 1, 2, 0.0f}, {0.0f, 3, 0, 0.5f},
                                       {1.0f, 3, 0, 0.5f}, {-0.125f, 3, 0, 0.0f}, {0.9375f, 3, 0, 0.25f},
                                       {2.25f, 0, 1, 0.5f}});
    check_linear(TextureWrap::ClampToEdge, {{0.0f, 0, 1, 0.0f}, {-1.0f, 0, 1, 0.0f}, {0.0625f, 0, 1, 0.0f},
                                            {0.25f, 0, 1, 0.5f}, {1.0f, 3, 3, 0.0f}, {0.9375f, 3, 3, 0.0f},
                                            {0.8125f, 2, 3, 0.75f}});
    // CLAMP: s in [0, 1], so at the ends half of the border blends in.
    check_linear(TextureWrap::Clamp, {{0.0f, -1, 0, 0.5f}, {-5.0f, -1, 0, 0.5f}, {1.0f, 3, -1, 0.5f},
                                      {2.0f, 3, -1, 0.5f}, {0.5f, 1, 2, 0.5f}, {0.0625f, -1, 0, 0.75f}});
    // CLAMP_TO_BORDER: s in [-1/8, 9/8], so far outside only the border is left.
    check_linear(TextureWrap::ClampToBorder, {{-1.0f, -1, 0, 0.0f}, {-0.125f, -1, 0, 0.0f}, {0.0f, -1, 0, 0.5f},
                                              {1.0f, 3, -1, 0.5f}, {1.125f, -1, -1, 0.0f}, {0.5f, 1, 2, 0.5f}});
    check_linear(TextureWrap::MirroredRepeat, {{1.0625f, 3, 3, 0.0f}, {-0.25f, 0, 1, 0.5f}, {1.25f, 2, 3, 0.5f},
                                               {2.25f, 0, 1, 0.5f}, {-1.125f, 3, 3, 0.0f}});
}

TEST_CASE("REPEAT on a size that is not a power of two", "[sampling][wrap]") {
    Texture t = make(TextureTarget::Tex1D, {image(3, 1, 1, [](int i, int, int) { return glm::vec4(float(i)); })});
    set_filters(t, TextureFilter::Linear, TextureFilter::Linear);
    // s = 0: u - 1/2 = -1/2, texels 2 and 0 half each; s = 0.5: u - 1/2 = 1, texel 1.
    check_vec(sample_texture(t, {0.0f, 0, 0}, 0, 0), glm::vec4(1.0f));
    check_vec(sample_texture(t, {0.5f, 0, 0}, 0, 0), glm::vec4(1.0f));
    check_vec(sample_texture(t, {-2.0f / 3.0f, 0, 0}, 0, 0), glm::vec4(0.5f));  // frac = 1/3: u - 1/2 = 0.5
    t.sampler.mag_filter = TextureFilter::Nearest;
    check_vec(sample_texture(t, {-0.1f, 0, 0}, 0, 0), glm::vec4(2.0f));
    check_vec(sample_texture(t, {5.5f, 0, 0}, 0, 0), glm::vec4(1.0f));
}

TEST_CASE("bilinear and trilinear weights", "[sampling][filter]") {
    // 2x2: each texel is one unit vector, so the result is the weights.
    Texture t2 = make(TextureTarget::Tex2D, {image(2, 2, 1, [](int i, int j, int) {
                          glm::vec4 v(0.0f);
                          v[i + 2 * j] = 1.0f;
                          return v;
                      })});
    set_filters(t2, TextureFilter::Linear, TextureFilter::Linear);
    t2.sampler.wrap_s = t2.sampler.wrap_t = TextureWrap::ClampToEdge;
    check_vec(sample_texture(t2, {0.5f, 0.5f, 0}, 0, 0), {0.25f, 0.25f, 0.25f, 0.25f});
    // alpha = 0.25, beta = 0.75: (1-a)(1-b), a(1-b), (1-a)b, ab.
    check_vec(sample_texture(t2, {0.375f, 0.625f, 0}, 0, 0), {0.1875f, 0.0625f, 0.5625f, 0.1875f});
    // t clamped to the edge: row 1 only; alpha = 0.1.
    check_vec(sample_texture(t2, {0.3f, 0.9f, 0}, 0, 0), {0, 0, 0.9f, 0.1f});
    // (s, t) = (1, 0) under REPEAT: u - 1/2 = 1.5, v - 1/2 = -0.5: all four texels, 1/4 each.
    t2.sampler.wrap_s = t2.sampler.wrap_t = TextureWrap::Repeat;
    check_vec(sample_texture(t2, {1.0f, 0.0f, 0}, 0, 0), {0.25f, 0.25f, 0.25f, 0.25f});

    // 2x2x2 with texel value i + 2j + 4k: trilinear of a linear function is a + 2b + 4c.
    Texture t3 = make(TextureTarget::Tex3D, {image(2, 2, 2, [](int i, int j, int k) {
                          return glm::vec4(float(i + 2 * j + 4 * k), 0, 0, 1);
                      })});
    set_filters(t3, TextureFilter::Linear, TextureFilter::Linear);
    t3.sampler.wrap_s = t3.sampler.wrap_t = t3.sampler.wrap_r = TextureWrap::ClampToEdge;
    check_vec(sample_texture(t3, {0.5f, 0.5f, 0.5f}, 0, 0), {3.5f, 0, 0, 1});
    check_vec(sample_texture(t3, {0.375f, 0.5f, 0.625f}, 0, 0), {0.25f + 1.0f + 3.0f, 0, 0, 1});
    check_vec(sample_texture(t3, {0.0f, 1.0f, 0.875f}, 0, 0), {0 + 2 + 4, 0, 0, 1});
    // NEAREST in 3D: texel (1, 0, 1) = 5.
    set_filters(t3, TextureFilter::Nearest, TextureFilter::Nearest);
    check_vec(sample_texture(t3, {0.6f, 0.4f, 0.9f}, 0, 0), {5, 0, 0, 1});
}

// -------------------------------------------------------------- mipmaps ---
TEST_CASE("generate_mipmaps: box filter down to 1x1 for every target", "[sampling][mipmap]") {
    SECTION("2D, even sizes") {
        Texture t = make(TextureTarget::Tex2D, {image(4, 4, 1, [](int i, int j, int) {
                             return glm::vec4(float(i), float(j), float(i * j), 1);
                         })});
        t.generate_mipmaps();
        REQUIRE(t.levels(0).size() == 3);
        const TextureImage& l1 = t.levels(0)[1];
        REQUIRE((l1.width == 2 && l1.height == 2 && l1.depth == 1));
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const float mi = 2.0f * float(i) + 0.5f, mj = 2.0f * float(j) + 0.5f;
                check_vec(l1.texels[size_t(i + 2 * j)], {mi, mj, mi * mj, 1});
            }
        REQUIRE((t.levels(0)[2].width == 1 && t.levels(0)[2].height == 1));
        check_vec(t.levels(0)[2].texels[0], {1.5f, 1.5f, 2.25f, 1});
        t.sampler.min_filter = TextureFilter::NearestMipmapNearest;
        CHECK(t.complete());
    }
    SECTION("2D, odd sizes keep every source texel") {
        Texture t = make(TextureTarget::Tex2D, {image(5, 3, 1, [](int i, int j, int) {
                             return glm::vec4(float(i), float(j), 0, 1);
                         })});
        t.generate_mipmaps();
        REQUIRE(t.levels(0).size() == 3);
        const TextureImage& l1 = t.levels(0)[1];
        REQUIRE((l1.width == 2 && l1.height == 1));
        // 5 -> 2: weights 0.4, 0.4, 0.2 | 0.2, 0.4, 0.4; 3 -> 1: a third each.
        check_vec(l1.texels[0], {0.8f, 1, 0, 1});
        check_vec(l1.texels[1], {3.2f, 1, 0, 1});
        check_vec(t.levels(0)[2].texels[0], {2.0f, 1, 0, 1});
        Texture three = make(TextureTarget::Tex2D, {image(3, 1, 1, [](int i, int, int) { return glm::vec4(3.0f * float(i)); })});
        three.generate_mipmaps();
        REQUIRE(three.levels(0).size() == 2);
        check_vec(three.levels(0)[1].texels[0], glm::vec4(3.0f));
    }
    SECTION("1D and 3D") {
        Texture t1 = make(TextureTarget::Tex1D, {image(8, 1, 1, [](int i, int, int) { return glm::vec4(float(i)); })});
        t1.generate_mipmaps();
        REQUIRE(t1.levels(0).size() == 4);
        CHECK(t1.levels(0)[1].width == 4);
        check_vec(t1.levels(0)[1].texels[3], glm::vec4(6.5f));
        check_vec(t1.levels(0)[3].texels[0], glm::vec4(3.5f));
        Texture t3 = make(TextureTarget::Tex3D, {image(4, 2, 2, [](int i, int j, int k) {
                              return glm::vec4(float(i + 10 * j + 100 * k), 0, 0, 1);
                          })});
        t3.generate_mipmaps();
        REQUIRE(t3.levels(0).size() == 3);
        const TextureImage& l1 = t3.levels(0)[1];
        REQUIRE((l1.width == 2 && l1.height == 1 && l1.depth == 1));
        check_vec(l1.texels[0], {0.5f + 5 + 50, 0, 0, 1});
        check_vec(l1.texels[1], {2.5f + 5 + 50, 0, 0, 1});
        check_vec(t3.levels(0)[2].texels[0], {1.5f + 5 + 50, 0, 0, 1});
    }
    SECTION("cube maps: every face") {
        std::vector<TextureImage> faces;
        for (int f = 0; f < 6; ++f) faces.push_back(solid(2, 2, {float(f), 1, 0, 1}));
        faces[5] = image(2, 2, 1, [](int i, int j, int) { return glm::vec4(float(i), float(j), float(i * j), 1); });
        Texture t = make(TextureTarget::Cube, faces);
        t.generate_mipmaps();
        for (int f = 0; f < 5; ++f) {
            REQUIRE(t.levels(f).size() == 2);
            check_vec(t.levels(f)[1].texels[0], {float(f), 1, 0, 1});
        }
        check_vec(t.levels(5)[1].texels[0], {0.5f, 0.5f, 0.25f, 1});
        t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
        CHECK(t.complete());
    }
    SECTION("RGBA8 levels are rounded to k/255") {
        Texture t = make(TextureTarget::Tex2D,
                         {image(2, 2, 1, [](int i, int j, int) {
                             return i + j == 2 ? glm::vec4(1, 0.2f, 0, 1) : glm::vec4(0, 1, 0, 1);
                         })},
                         TextureFormat::RGBA8);
        t.generate_mipmaps();
        // r: 0.25 -> 63.75 -> 64; g: 0.8 -> 204.
        const glm::vec4 got = t.levels(0)[1].texels[0];
        CHECK(got.r == 64.0f / 255.0f);
        CHECK(got.g == 204.0f / 255.0f);
        CHECK(got.b == 0.0f);
        CHECK(got.a == 1.0f);
    }
    SECTION("from level_base up to max_level") {
        Texture t = make(TextureTarget::Tex2D, {solid(8, 8, {0, 0, 0, 1})});
        REQUIRE(t.set_level(0, 1, solid(4, 4, {1, 0, 0, 1})).ok());
        t.sampler.base_level = 1;
        t.sampler.max_level = 2;
        t.generate_mipmaps();
        REQUIRE(t.levels(0).size() == 3);
        check_vec(t.levels(0)[0].texels[0], {0, 0, 0, 1});  // below level_base: untouched
        CHECK(t.levels(0)[2].width == 2);
        check_vec(t.levels(0)[2].texels[0], {1, 0, 0, 1});
        t.sampler.base_level = 5;  // no image there: nothing happens
        t.generate_mipmaps();
        CHECK(t.levels(0).size() == 3);
    }
}

namespace {

// 8x8 with levels 0..3; level L has texel (i, j) = (L, i, 0, 1): .r names the
// level, .g the column, so the nearest and linear filters within a level
// differ at s = 1/4: level 0 nearest 2, linear 1.5; level 1: 1, 0.5; levels 2, 3: 0.
Texture level_texture() {
    auto level = [](int l) {
        const int size = 8 >> l;
        return image(size, size, 1, [l](int i, int, int) { return glm::vec4(float(l), float(i), 0, 1); });
    };
    Texture t = make(TextureTarget::Tex2D, {level(0)});
    for (int l = 1; l <= 3; ++l) REQUIRE(t.set_level(0, l, level(l)).ok());
    t.sampler.wrap_s = t.sampler.wrap_t = TextureWrap::ClampToEdge;
    return t;
}
glm::vec4 at_level(float level, bool linear) {
    const float g_nearest[4] = {2, 1, 0, 0}, g_linear[4] = {1.5f, 0.5f, 0, 0};
    const int l = int(level);
    const float g = linear ? g_linear[l] : g_nearest[l];
    return {level, g, 0, 1};
}
// Mipmap-linear: levels d1 and d1 + 1 blended by f.
glm::vec4 between(int d1, float f, bool linear) {
    return at_level(float(d1), linear) * (1 - f) + at_level(float(d1 + 1), linear) * f;
}

struct LodCase { float lod; glm::vec4 want; };
void check_lods(const Texture& t, const std::vector<LodCase>& cases,
                rt::SamplingRules rules = rt::SamplingRules::Common) {
    for (const LodCase& c : cases) {
        INFO("min " << int(t.sampler.min_filter) << " mag " << int(t.sampler.mag_filter) << " lod " << c.lod);
        check_vec(sample_texture(t, {0.25f, 0.5f, 0}, 0, c.lod, rules), c.want);
    }
}

}  // namespace

TEST_CASE("each min filter picks its level(s) from lambda", "[sampling][lod]") {
    Texture t = level_texture();
    SECTION("NEAREST and LINEAR read level_base only") {
        set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
        check_lods(t, {{-1, at_level(0, false)}, {0.3f, at_level(0, false)}, {2, at_level(0, false)}, {5, at_level(0, false)}});
        set_filters(t, TextureFilter::Linear, TextureFilter::Nearest);
        check_lods(t, {{-1, at_level(0, false)}, {0.3f, at_level(0, true)}, {2, at_level(0, true)}});
    }
    SECTION("*_MIPMAP_NEAREST: level_base + ceil(lambda + 1/2) - 1, at most q") {
        for (bool linear : {false, true}) {
            set_filters(t, linear ? TextureFilter::LinearMipmapNearest : TextureFilter::NearestMipmapNearest,
                        TextureFilter::Nearest);
            check_lods(t, {{-1, at_level(0, false)}, {0.3f, at_level(0, linear)}, {0.5f, at_level(0, linear)},
                           {0.51f, at_level(1, linear)}, {1.5f, at_level(1, linear)}, {1.6f, at_level(2, linear)},
                           {2.4f, at_level(2, linear)}, {3.4f, at_level(3, linear)}, {3.6f, at_level(3, linear)},
                           {10, at_level(3, linear)}});
        }
    }
    SECTION("*_MIPMAP_LINEAR: floor(lambda) and the next level, blended by frac(lambda)") {
        for (bool linear : {false, true}) {
            set_filters(t, linear ? TextureFilter::LinearMipmapLinear : TextureFilter::NearestMipmapLinear,
                        TextureFilter::Nearest);
            check_lods(t, {{-1, at_level(0, false)}, {0.0f, at_level(0, false)}, {0.25f, between(0, 0.25f, linear)},
                           {1.5f, between(1, 0.5f, linear)}, {2.75f, between(2, 0.75f, linear)},
                           {3.0f, at_level(3, linear)}, {5, at_level(3, linear)}});
        }
    }
}

TEST_CASE("magnification below c: c = 0.5 for LINEAR mag with NEAREST_MIPMAP_* in Reference alone",
          "[sampling][lod]") {
    Texture t = level_texture();
    const auto spec = rt::SamplingRules::Spec;
    set_filters(t, TextureFilter::NearestMipmapLinear, TextureFilter::Linear);
    check_lods(t, {{0.25f, at_level(0, true)}, {0.5f, at_level(0, true)}, {0.75f, between(0, 0.75f, false)}}, spec);
    // Precise (and Fast) switch at c = 0, as llvmpipe and NVIDIA's driver: lambda 0.25 minifies.
    check_lods(t, {{0.0f, at_level(0, true)}, {0.25f, between(0, 0.25f, false)}, {0.5f, between(0, 0.5f, false)}});
    set_filters(t, TextureFilter::NearestMipmapNearest, TextureFilter::Linear);
    check_lods(t, {{0.3f, at_level(0, true)}, {0.5f, at_level(0, true)}, {0.51f, at_level(1, false)}}, spec);
    check_lods(t, {{0.0f, at_level(0, true)}, {0.3f, at_level(0, false)}, {0.5f, at_level(0, false)},
                   {0.51f, at_level(1, false)}});
    // Otherwise c = 0 in every mode: lambda 0.25 is minification already.
    set_filters(t, TextureFilter::LinearMipmapNearest, TextureFilter::Linear);
    check_lods(t, {{0.0f, at_level(0, true)}, {0.3f, at_level(0, true)}, {0.51f, at_level(1, true)}});
    set_filters(t, TextureFilter::NearestMipmapLinear, TextureFilter::Nearest);
    check_lods(t, {{0.0f, at_level(0, false)}, {0.25f, between(0, 0.25f, false)}});
    set_filters(t, TextureFilter::Nearest, TextureFilter::Linear);
    check_lods(t, {{0.0f, at_level(0, true)}, {0.01f, at_level(0, false)}});
}

TEST_CASE("level_base, level_max, min/max LOD and the LOD bias", "[sampling][lod]") {
    Texture t = level_texture();
    set_filters(t, TextureFilter::NearestMipmapLinear, TextureFilter::Nearest);
    SECTION("level_base and level_max") {
        t.sampler.base_level = 1;
        // q = min(floor(log2(4)) + 1, 1000) = 3; lambda counts from level_base.
        check_lods(t, {{-1, at_level(1, false)}, {0.5f, between(1, 0.5f, false)}, {1.25f, between(2, 0.25f, false)},
                       {2, at_level(3, false)}, {9, at_level(3, false)}});
        t.sampler.max_level = 2;
        check_lods(t, {{0.5f, between(1, 0.5f, false)}, {1.0f, at_level(2, false)}, {2.5f, at_level(2, false)}});
        t.sampler.min_filter = TextureFilter::NearestMipmapNearest;
        check_lods(t, {{0.4f, at_level(1, false)}, {1.0f, at_level(2, false)}, {5, at_level(2, false)}});
        t.sampler.base_level = t.sampler.max_level = 2;
        check_lods(t, {{0.7f, at_level(2, false)}, {-3, at_level(2, false)}});
    }
    SECTION("min_lod and max_lod clamp lambda") {
        t.sampler.min_lod = 1.0f;
        check_lods(t, {{-5, at_level(1, false)}, {0, at_level(1, false)}, {2.5f, between(2, 0.5f, false)}});
        t.sampler.min_lod = -1000;
        t.sampler.max_lod = 1.5f;
        check_lods(t, {{10, between(1, 0.5f, false)}, {0.5f, between(0, 0.5f, false)}});
    }
    SECTION("the texture's lod_bias adds to the LOD before the clamp") {
        t.sampler.lod_bias = 1.0f;
        check_lods(t, {{0.5f, between(1, 0.5f, false)}, {-1.0f, at_level(0, false)}, {-0.75f, between(0, 0.25f, false)}});
        t.sampler.lod_bias = -2.0f;
        check_lods(t, {{2.5f, between(0, 0.5f, false)}, {1.0f, at_level(0, false)}});
        t.sampler.lod_bias = 5.0f;
        t.sampler.max_lod = 2.0f;
        check_lods(t, {{0, at_level(2, false)}});
    }
}

TEST_CASE("completeness (GL 2.1 section 3.8.10)", "[sampling][complete]") {
    const glm::vec4 black{0, 0, 0, 1}, red{1, 0, 0, 1};
    Texture t = make(TextureTarget::Tex2D, {solid(4, 4, red)});
    SECTION("GL's default min filter needs mipmaps") {
        CHECK_FALSE(t.complete());
        check_vec(sample_texture(t, {0.5f, 0.5f, 0}, 0, 2), black);
        t.sampler.min_filter = TextureFilter::Linear;
        CHECK(t.complete());
        check_vec(sample_texture(t, {0.5f, 0.5f, 0}, 0, 2), red);
    }
    SECTION("a missing level") {
        REQUIRE(t.set_level(0, 1, solid(2, 2, red)).ok());
        t.sampler.min_filter = TextureFilter::NearestMipmapNearest;
        CHECK_FALSE(t.complete());
        check_vec(sample_texture(t, {0.5f, 0.5f, 0}, 0, 0), black);
        t.sampler.max_level = 1;  // q = 1: levels 0 and 1 suffice
        CHECK(t.complete());
        check_vec(sample_texture(t, {0.5f, 0.5f, 0}, 0, 0), red);
    }
    SECTION("a hole in the chain and a level of the wrong size") {
        REQUIRE(t.set_level(0, 2, solid(1, 1, red)).ok());
        REQUIRE(t.levels(0).size() == 3);
        t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
        CHECK_FALSE(t.complete());
        REQUIRE(t.set_level(0, 1, solid(3, 3, red)).ok());
        CHECK_FALSE(t.complete());
        REQUIRE(t.set_level(0, 1, solid(2, 2, red)).ok());
        CHECK(t.complete());
        t.sampler.min_filter = TextureFilter::Nearest;
        REQUIRE(t.set_level(0, 1, solid(3, 3, red)).ok());
        CHECK(t.complete());  // NEAREST reads level_base only
    }
    SECTION("level_base must exist; level_base > level_max breaks mipmapping only") {
        t.sampler.min_filter = TextureFilter::Nearest;
        t.sampler.base_level = 1;
        CHECK_FALSE(t.complete());
        check_vec(sample_texture(t, {0.5f, 0.5f, 0}, 0, 0), black);
        t.generate_mipmaps();  // no level 1 to derive from: nothing changes
        CHECK_FALSE(t.complete());
        t.sampler.base_level = 0;
        t.generate_mipmaps();
        t.sampler.base_level = 2;
        t.sampler.max_level = 1;
        CHECK(t.complete());
        t.sampler.min_filter = TextureFilter::NearestMipmapNearest;
        CHECK_FALSE(t.complete());
    }
    SECTION("a 1x1 texture is its own mipmap") {
        Texture one = make(TextureTarget::Tex2D, {solid(1, 1, red)});
        CHECK(one.complete());
        check_vec(sample_texture(one, {0.3f, 0.3f, 0}, 0, 4), red);
    }
    SECTION("cube maps: cube complete and cube mipmap complete") {
        std::vector<TextureImage> faces(6, solid(4, 4, red));
        Texture cube = make(TextureTarget::Cube, faces);
        cube.sampler.min_filter = TextureFilter::Linear;
        CHECK(cube.complete());
        REQUIRE(cube.set_level(3, 0, solid(2, 2, red)).ok());  // -Y smaller than the others
        CHECK_FALSE(cube.complete());
        check_vec(sample_texture(cube, {0, 1, 0}, 0, 0), black);
        REQUIRE(cube.set_level(3, 0, solid(4, 4, red)).ok());
        cube.generate_mipmaps();
        cube.sampler.min_filter = TextureFilter::LinearMipmapLinear;
        CHECK(cube.complete());
        REQUIRE(cube.set_level(4, 1, solid(1, 1, red)).ok());  // +Z level 1 of the wrong size
        CHECK_FALSE(cube.complete());
        cube.sampler.min_filter = TextureFilter::Linear;
        CHECK(cube.complete());
    }
}

// --------------------------------------------------------------- cubes ---
namespace {
// Six 2x2 faces; texel (i, j) of face f = (f, i, j, 1).
Texture cube_texture() {
    std::vector<TextureImage> faces;
    for (int f = 0; f < 6; ++f)
        faces.push_back(image(2, 2, 1, [f](int i, int j, int) { return glm::vec4(float(f), float(i), float(j), 1); }));
    Texture t = make(TextureTarget::Cube, faces);
    set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
    t.sampler.wrap_s = t.sampler.wrap_t = TextureWrap::ClampToEdge;
    return t;
}
}  // namespace

TEST_CASE("cube maps: the face of the major axis and the texel on it", "[sampling][cube]") {
    const Texture t = cube_texture();
    struct Case { glm::vec3 dir; int face, i, j; };
    // s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 with sc, tc from the table of section 3.8.6;
    // minor components of +-1 over |ma| = 2 land on s, t = 0.25 (texel 0) or 0.75 (texel 1).
    const Case cases[] = {
        {{2, 1, 1}, 0, 0, 0},    {{2, -1, -1}, 0, 1, 1},  {{2, 1, -1}, 0, 1, 0},     // +X: sc = -rz, tc = -ry
        {{-2, 1, 1}, 1, 1, 0},   {{-2, -1, -1}, 1, 0, 1}, {{-2, -1, 1}, 1, 1, 1},    // -X: sc = +rz, tc = -ry
        {{1, 2, 1}, 2, 1, 1},    {{-1, 2, 1}, 2, 0, 1},   {{1, 2, -1}, 2, 1, 0},     // +Y: sc = +rx, tc = +rz
        {{1, -2, 1}, 3, 1, 0},   {{-1, -2, -1}, 3, 0, 1}, {{1, -2, -1}, 3, 1, 1},    // -Y: sc = +rx, tc = -rz
        {{1, 1, 2}, 4, 1, 0},    {{-1, -1, 2}, 4, 0, 1},  {{-1, 1, 2}, 4, 0, 0},     // +Z: sc = +rx, tc = -ry
        {{1, 1, -2}, 5, 0, 0},   {{-1, -1, -2}, 5, 1, 1}, {{-1, 1, -2}, 5, 1, 0},    // -Z: sc = -rx, tc = -ry
    };
    for (const Case& c : cases) {
        INFO("direction " << c.dir.x << " " << c.dir.y << " " << c.dir.z);
        check_vec(sample_texture(t, c.dir, 0, 0), {float(c.face), float(c.i), float(c.j), 1});
    }
    // Ties: X over Y and Z, Y over Z (Mesa's order); the sign picks the face.
    const std::pair<glm::vec3, int> ties[] = {{{1, 1, 0}, 0}, {{0, 1, 1}, 2}, {{1, 1, 1}, 0}, {{-1, 1, 1}, 1},
                                              {{0, -1, 1}, 3}, {{0.5f, 0, -0.5f}, 0}, {{0, 0, -3}, 5}};
    for (const auto& [dir, face] : ties) {
        INFO("direction " << dir.x << " " << dir.y << " " << dir.z);
        CHECK(sample_texture(t, dir, 0, 0).r == float(face));
    }
    // A zero or NaN direction still reads some texel.
    for (glm::vec3 dir : {glm::vec3(0.0f), glm::vec3(kNaN), glm::vec3(kInf, 1, 0)}) {
        const glm::vec4 v = sample_texture(t, dir, 0, 0);
        CHECK((v.r >= 0 && v.r <= 5 && v.w == 1));
    }
}

TEST_CASE("cube maps: linear filtering on a face and the wrap modes at its edge", "[sampling][cube]") {
    Texture t = cube_texture();
    set_filters(t, TextureFilter::Linear, TextureFilter::Linear);
    check_vec(sample_texture(t, {3, 0, 0}, 0, 0), {0, 0.5f, 0.5f, 1});  // the centre of +X: all four texels
    // -Z: sc = -rx = -1/4, so s = 3/8 and u - 1/2 = 0.25; t = 1/2 blends both rows.
    check_vec(sample_texture(t, {0.25f, 0, -1}, 0, 0), {5, 0.25f, 0.5f, 1});
    // GL 2.1 applies the texture's wraps to the face's (s, t) (no seamless
    // filtering). At s = 1 on +X (rz = -rx): CLAMP_TO_EDGE stays on column 1,
    // REPEAT wraps to column 0 under NEAREST.
    set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
    CHECK(sample_texture(t, {1, 0.5f, -1}, 0, 0).g == 1.0f);
    t.sampler.wrap_s = TextureWrap::Repeat;
    CHECK(sample_texture(t, {1, 0.5f, -1}, 0, 0).g == 0.0f);
}

// ------------------------------------------------------------ implicit LOD ---
TEST_CASE("implicit_lod: log2 of the longest scaled derivative", "[sampling][lod]") {
    Texture t2 = make(TextureTarget::Tex2D, {solid(64, 64, {1, 1, 1, 1})});
    const float px = 1.0f / 64.0f;
    CHECK(implicit_lod(t2, {0.5f, 0.5f, 0}, {px, 0, 0}, {0, px, 0}) == Approx(0.0f).margin(1e-6));
    CHECK(implicit_lod(t2, {0.5f, 0.5f, 0}, {2 * px, 0, 0}, {0, 2 * px, 0}) == Approx(1.0f));
    CHECK(implicit_lod(t2, {0.5f, 0.5f, 0}, {px, 0, 0}, {0, 4 * px, 0}) == Approx(2.0f));
    CHECK(implicit_lod(t2, {0.5f, 0.5f, 0}, {3 * px, 4 * px, 0}, {0, 0, 0}) == Approx(std::log2(5.0f)));
    CHECK(implicit_lod(t2, {0.5f, 0.5f, 0}, {px / 4, 0, 9}, {0, 0, 0}) == Approx(-2.0f));  // r ignored in 2D
    const float none = implicit_lod(t2, {0.5f, 0.5f, 0}, {0, 0, 0}, {0, 0, 0});
    CHECK(none <= -100.0f);
    CHECK_FALSE(std::isnan(implicit_lod(t2, {0.5f, 0.5f, 0}, {kNaN, 0, 0}, {0, kNaN, 0})));
    CHECK_FALSE(std::isnan(implicit_lod(t2, {0.5f, 0.5f, 0}, {kInf, 0, 0}, {0, 0, 0})));

    Texture wide = make(TextureTarget::Tex2D, {solid(64, 16, {1, 1, 1, 1})});
    CHECK(implicit_lod(wide, kZero, {0, 1.0f / 16, 0}, kZero) == Approx(0.0f).margin(1e-6));
    CHECK(implicit_lod(wide, kZero, {1.0f / 16, 0, 0}, kZero) == Approx(2.0f));

    Texture t1 = make(TextureTarget::Tex1D, {image(64, 1, 1, [](int, int, int) { return glm::vec4(1); })});
    CHECK(implicit_lod(t1, kZero, {px, 100, 100}, {0, 100, 0}) == Approx(0.0f).margin(1e-6));
    Texture t3 = make(TextureTarget::Tex3D, {image(16, 16, 16, [](int, int, int) { return glm::vec4(1); })});
    CHECK(implicit_lod(t3, kZero, {0, 0, 2.0f / 16}, kZero) == Approx(1.0f));

    // The sizes of level_base count.
    t2.generate_mipmaps();
    t2.sampler.base_level = 1;
    CHECK(implicit_lod(t2, kZero, {1.0f / 32, 0, 0}, kZero) == Approx(0.0f).margin(1e-6));
}

TEST_CASE("implicit_lod on cube maps: derivatives projected onto the face", "[sampling][lod][cube]") {
    std::vector<TextureImage> faces(6, solid(16, 16, {1, 1, 1, 1}));
    const Texture t = make(TextureTarget::Cube, faces);
    // +X at (1, 0, 0): ds = d(-rz)/2, dt = d(-ry)/2 (|ma| = 1).
    CHECK(implicit_lod(t, {1, 0, 0}, {0, 0, 2.0f / 16}, kZero) == Approx(0.0f).margin(1e-6));
    CHECK(implicit_lod(t, {1, 0, 0}, {0, 4.0f / 16, 0}, kZero) == Approx(1.0f));
    // Along the major axis at the face centre nothing moves on the face.
    CHECK(implicit_lod(t, {1, 0, 0}, {1, 0, 0}, kZero) <= -100.0f);
    // Off centre it does: sc = -0.5, d|ma| = 0.5: ds = (0 - (-0.5)(0.5)) / 2 = 1/8, 2 texels.
    CHECK(implicit_lod(t, {1, 0, 0.5f}, {0.5f, 0, 0}, kZero) == Approx(1.0f));
    // -Z at (0, 0, -2): sc = -rx, so ds = 0.5 * (-0.5 * 2) / 4 = -1/8: 2 texels.
    CHECK(implicit_lod(t, {0, 0, -2}, {0.5f, 0, 0}, {0, 0, 0}) == Approx(1.0f));
    CHECK_FALSE(std::isnan(implicit_lod(t, {0, 0, 0}, {1, 1, 1}, {1, 1, 1})));
}

// -------------------------------------------------------------- depth ---
TEST_CASE("depth textures: every compare function and DEPTH_TEXTURE_MODE", "[sampling][depth]") {
    Texture t = make(TextureTarget::Tex2D, {image(2, 1, 1, [](int i, int, int) {
                         return glm::vec4(i == 0 ? 0.25f : 0.75f, 0.9f, 0.9f, 0.9f);
                     })},
                     TextureFormat::Depth);
    set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
    const CompareFunc funcs[] = {CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,
                                 CompareFunc::Lequal,  CompareFunc::Greater,  CompareFunc::Notequal,
                                 CompareFunc::Gequal,  CompareFunc::Always};
    // Against D = 0.25 (texel 0), in the order of `funcs`.
    const struct { float ref; float want[8]; } refs[] = {
        {0.1f, {0, 1, 0, 1, 0, 1, 0, 1}},
        {0.25f, {0, 0, 1, 1, 0, 0, 1, 1}},
        {0.5f, {0, 0, 0, 0, 1, 1, 1, 1}},
    };
    t.sampler.compare = true;
    for (const auto& r : refs)
        for (int f = 0; f < 8; ++f) {
            t.sampler.compare_func = funcs[f];
            const float w = r.want[f];
            INFO("func " << f << " ref " << r.ref);
            t.sampler.depth_mode = DepthTextureMode::Luminance;
            check_vec(sample_texture(t, {0.25f, 0.5f, 0}, r.ref, 0), {w, w, w, 1});
            t.sampler.depth_mode = DepthTextureMode::Intensity;
            check_vec(sample_texture(t, {0.25f, 0.5f, 0}, r.ref, 0), {w, w, w, w});
            t.sampler.depth_mode = DepthTextureMode::Alpha;
            check_vec(sample_texture(t, {0.25f, 0.5f, 0}, r.ref, 0), {0, 0, 0, w});
        }
    // Compare off: the depth itself, through DEPTH_TEXTURE_MODE.
    t.sampler.compare = false;
    t.sampler.depth_mode = DepthTextureMode::Luminance;
    check_vec(sample_texture(t, {0.75f, 0.5f, 0}, 0.1f, 0), {0.75f, 0.75f, 0.75f, 1});
    t.sampler.depth_mode = DepthTextureMode::Intensity;
    check_vec(sample_texture(t, {0.25f, 0.5f, 0}, 0.9f, 0), glm::vec4(0.25f));
    t.sampler.depth_mode = DepthTextureMode::Alpha;
    check_vec(sample_texture(t, {0.75f, 0.5f, 0}, 0, 0), {0, 0, 0, 0.75f});
}

TEST_CASE("depth textures: clamps, compare-then-filter and the border", "[sampling][depth]") {
    Texture t = make(TextureTarget::Tex1D, {image(4, 1, 1, [](int i, int, int) {
                         const float d[4] = {-0.2f, 0.25f, 0.75f, 1.5f};  // stored clamped to [0, 1]
                         return glm::vec4(d[i], 0, 0, 1);
                     })},
                     TextureFormat::Depth);
    CHECK(t.levels(0)[0].texels[0].r == 0.0f);
    CHECK(t.levels(0)[0].texels[3].r == 1.0f);
    set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
    t.sampler.compare = true;
    t.sampler.compare_func = CompareFunc::Equal;
    // The reference is clamped to [0, 1] too.
    CHECK(sample_texture(t, {0.9f, 0, 0}, 1.5f, 0).r == 1.0f);
    CHECK(sample_texture(t, {0.1f, 0, 0}, -0.5f, 0).r == 1.0f);
    CHECK(sample_texture(t, {0.1f, 0, 0}, 0.5f, 0).r == 0.0f);
    // LINEAR compares each texel, then filters: at s = 0.5 texels 1 and 2 (0.25, 0.75)
    // half each; ref 0.5 LEQUAL gives 0 and 1, so 0.5 (filtering first would give 1).
    set_filters(t, TextureFilter::Linear, TextureFilter::Linear);
    t.sampler.wrap_s = TextureWrap::ClampToEdge;
    t.sampler.compare_func = CompareFunc::Lequal;
    check_vec(sample_texture(t, {0.5f, 0, 0}, 0.5f, 0), {0.5f, 0.5f, 0.5f, 1});
    check_vec(sample_texture(t, {0.4375f, 0, 0}, 0.5f, 0), {0.25f, 0.25f, 0.25f, 1});
    check_vec(sample_texture(t, {0.375f, 0, 0}, 0.5f, 0), {0, 0, 0, 1});
    // The border's depth is border_color.r, compared like a texel.
    set_filters(t, TextureFilter::Nearest, TextureFilter::Nearest);
    t.sampler.wrap_s = TextureWrap::ClampToBorder;
    t.sampler.border_color = {0.6f, 0, 0, 0};
    CHECK(sample_texture(t, {-1, 0, 0}, 0.5f, 0).r == 1.0f);
    CHECK(sample_texture(t, {-1, 0, 0}, 0.7f, 0).r == 0.0f);
    t.sampler.compare = false;
    check_vec(sample_texture(t, {2, 0, 0}, 0.7f, 0), {0.6f, 0.6f, 0.6f, 1});
    // Compare mode on a colour texture is ignored (section 3.8.14: depth textures only).
    Texture colour = make(TextureTarget::Tex2D, {solid(1, 1, {0.2f, 0.4f, 0.6f, 0.8f})});
    set_filters(colour, TextureFilter::Nearest, TextureFilter::Nearest);
    colour.sampler.compare = true;
    check_vec(sample_texture(colour, {0.5f, 0.5f, 0}, 0.5f, 0), {0.2f, 0.4f, 0.6f, 0.8f});
}

// ---------------------------------------------------------- formats ---
TEST_CASE("RGBA8 texels and the border colour", "[sampling][format]") {
    Texture t = make(TextureTarget::Tex2D, {image(2, 1, 1, [](int i, int, int) {
                         return i == 0 ? glm::vec4(0.5f, 0.123f, 1.2f, -0.3f) : glm::vec4(kNaN, 0.2f, 1, 0);
                     })},
                     TextureFormat::RGBA8);
    const glm::vec4 a = t.levels(0)[0].texels[0], b = t.levels(0)[0].texels[1];
    CHECK(a.r == 128.0f / 255.0f);  // 127.5 rounds to even
    CHECK(a.g == 31.0f / 255.0f);   // 31.365
    CHECK(a.b == 1.0f);
    CHECK(a.a == 0.0f);
    CHECK(b.r == 0.0f);  // NaN stores as 0
    CHECK(b.g == 51.0f / 255.0f);
    REQUIRE(t.set_level(0, 1, solid(1, 1, {0.95f, 0.01f, 0.5f, 2})).ok());
    const glm::vec4 l1 = t.levels(0)[1].texels[0];
    CHECK(l1.r == 242.0f / 255.0f);  // 242.25
    CHECK(l1.g == 3.0f / 255.0f);    // 2.55
    CHECK(l1.a == 1.0f);
    // Float textures keep any value; the border colour is clamped to [0, 1] (GL 2.1).
    Texture f = make(TextureTarget::Tex1D, {TextureImage{1, 1, 1, {{1.7f, -3, 0.5f, 100}}}});
    set_filters(f, TextureFilter::Nearest, TextureFilter::Nearest);
    check_vec(sample_texture(f, {0.5f, 0, 0}, 0, 0), {1.7f, -3, 0.5f, 100});
    f.sampler.wrap_s = TextureWrap::ClampToBorder;
    f.sampler.border_color = {2, -1, 0.25f, 1};
    check_vec(sample_texture(f, {1.5f, 0, 0}, 0, 0), {1, 0, 0.25f, 1});
}

// ------------------------------------------------------------ errors ---
TEST_CASE("create() refuses images GL would refuse", "[sampling][errors]") {
    auto contains = [](const std::string& s, const std::string& part) {
        INFO(s);
        CHECK(s.find(part) != std::string::npos);
    };
    contains(create_error(TextureTarget::Tex1D, {solid(4, 2, {})}), "height = depth = 1");
    contains(create_error(TextureTarget::Tex2D, {TextureImage{2, 2, 2, std::vector<glm::vec4>(8)}}), "depth = 1");
    contains(create_error(TextureTarget::Tex2D, {TextureImage{0, 1, 1, {}}}), "at least 1");
    contains(create_error(TextureTarget::Tex2D, {TextureImage{2, -1, 1, {}}}), "at least 1");
    contains(create_error(TextureTarget::Tex2D, {TextureImage{2, 2, 1, std::vector<glm::vec4>(3)}}), "got 3");
    contains(create_error(TextureTarget::Tex2D, {}), "1 image");
    contains(create_error(TextureTarget::Tex2D, {solid(1, 1, {}), solid(1, 1, {})}), "got 2");
    contains(create_error(TextureTarget::Cube, std::vector<TextureImage>(5, solid(2, 2, {}))), "6 images");
    std::vector<TextureImage> faces(6, solid(2, 2, {}));
    faces[2] = solid(4, 2, {});
    contains(create_error(TextureTarget::Cube, faces), "square");
    faces[2] = solid(4, 4, {});
    contains(create_error(TextureTarget::Cube, faces), "+Y");
    contains(create_error(TextureTarget::Tex2D, {TextureImage{kMaxTextureSize + 1, 1, 1, {}}}), "GL_MAX_TEXTURE_SIZE");
    contains(create_error(TextureTarget::Tex3D, {TextureImage{1, 1, kMax3DTextureSize + 1, {}}}),
             "GL_MAX_3D_TEXTURE_SIZE");
    contains(create_error(TextureTarget::Tex3D, {solid(1, 1, {})}, TextureFormat::Depth), "1D, 2D or a rectangle");
    contains(create_error(TextureTarget::Cube, std::vector<TextureImage>(6, solid(1, 1, {})), TextureFormat::Depth),
             "1D, 2D or a rectangle");
    // The largest sizes are fine.
    CHECK(Texture::create(TextureTarget::Tex1D, {TextureImage{kMaxTextureSize, 1, 1,
                                                              std::vector<glm::vec4>(size_t(kMaxTextureSize))}})
              .ok());
    CHECK(Texture::create(TextureTarget::Tex3D, {TextureImage{1, 1, kMax3DTextureSize,
                                                              std::vector<glm::vec4>(size_t(kMax3DTextureSize))}})
              .ok());
}

TEST_CASE("set_level() checks the face, the level and the image", "[sampling][errors]") {
    Texture t = make(TextureTarget::Tex2D, {solid(4, 4, {})});
    CHECK_FALSE(t.set_level(1, 1, solid(2, 2, {})).ok());
    CHECK_FALSE(t.set_level(-1, 1, solid(2, 2, {})).ok());
    CHECK_FALSE(t.set_level(0, -1, solid(2, 2, {})).ok());
    CHECK_FALSE(t.set_level(0, 15, solid(1, 1, {})).ok());
    CHECK(t.set_level(0, 14, solid(1, 1, {})).ok());
    CHECK_FALSE(t.set_level(0, 14, solid(2, 1, {})).ok());  // GL_MAX_TEXTURE_SIZE >> 14 = 1
    CHECK_FALSE(t.set_level(0, 1, TextureImage{2, 2, 2, std::vector<glm::vec4>(8)}).ok());
    CHECK_FALSE(t.set_level(0, 1, TextureImage{2, 2, 1, std::vector<glm::vec4>(5)}).ok());
    CHECK(t.set_level(0, 1, solid(7, 3, {})).ok());  // any size: the texture is just mipmap-incomplete
    CHECK(t.levels(0).size() == 15);
    Texture cube = make(TextureTarget::Cube, std::vector<TextureImage>(6, solid(2, 2, {})));
    CHECK(cube.set_level(5, 1, solid(1, 1, {})).ok());
    CHECK_FALSE(cube.set_level(6, 1, solid(1, 1, {})).ok());
    CHECK_FALSE(cube.set_level(0, 1, solid(2, 1, {})).ok());  // faces are square
}

TEST_CASE("bind_texture fills the slot of the texture's target", "[sampling][bind]") {
    GLState gl;
    auto t2 = std::make_shared<const Texture>(make(TextureTarget::Tex2D, {solid(1, 1, {})}));
    auto cube = std::make_shared<const Texture>(make(TextureTarget::Cube, std::vector<TextureImage>(6, solid(1, 1, {}))));
    REQUIRE(gl.bind_texture(3, t2).ok());
    REQUIRE(gl.bind_texture(3, cube).ok());
    CHECK(gl.texture_units[3].bound[size_t(TextureTarget::Tex2D)] == t2);
    CHECK(gl.texture_units[3].bound[size_t(TextureTarget::Cube)] == cube);
    CHECK(gl.texture_units[3].bound[size_t(TextureTarget::Tex1D)] == nullptr);
    CHECK(gl.texture_units[0].bound[size_t(TextureTarget::Tex2D)] == nullptr);
    CHECK_THAT(gl.bind_texture(-1, t2).error().str(), Catch::Contains("texture unit -1 does not exist"));
    CHECK_FALSE(gl.bind_texture(kMaxTextureUnits, t2).ok());
    for (const auto& unit : gl.texture_units)
        if (&unit != &gl.texture_units[3]) CHECK(unit.bound[size_t(TextureTarget::Tex2D)] == nullptr);
    CHECK(gl.bind_texture(3, nullptr).ok());  // unbinds every target of the unit
    for (const auto& slot : gl.texture_units[3].bound) CHECK(slot == nullptr);
}

TEST_CASE("NaN and infinite coordinates and LODs never index out of range", "[sampling][robust]") {
    Texture t = make(TextureTarget::Tex2D, {image(4, 4, 1, [](int i, int j, int) {
                         return glm::vec4(float(i), float(j), 0, 1);
                     })});
    t.generate_mipmaps();
    const float odd[] = {kNaN, kInf, -kInf, 1e30f, -1e30f, 3e9f};
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::Clamp,
                             TextureWrap::ClampToBorder, TextureWrap::MirroredRepeat})
        for (TextureFilter min : {TextureFilter::Nearest, TextureFilter::Linear, TextureFilter::NearestMipmapNearest,
                                  TextureFilter::LinearMipmapLinear}) {
            t.sampler.wrap_s = t.sampler.wrap_t = wrap;
            t.sampler.min_filter = min;
            for (float x : odd) {
                const glm::vec4 v = sample_texture(t, {x, 0.5f, 0}, 0, 1.0f);
                if (min == TextureFilter::Nearest || min == TextureFilter::NearestMipmapNearest)
                    CHECK((v.r >= 0 && v.r <= 3));  // some texel (or the border's 0)
                sample_texture(t, {0.5f, x, 0}, 0, x);
                sample_texture(t, {x, x, x}, x, x);
            }
        }
    t.sampler.min_lod = kNaN;
    const glm::vec4 v = sample_texture(t, {0.5f, 0.5f, 0}, 0, kNaN);
    CHECK((v.w == 1));
}
