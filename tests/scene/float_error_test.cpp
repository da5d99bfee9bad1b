// The error report's statistics (scene/float_error.h) on crafted
// values and buffers: the ULP distance at its edges (zeros, denormals, Inf,
// NaN, sign changes), the 8-bit differences, coverage and the worst pixel.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <limits>

#include "glslrun/scene/float_error.h"

using namespace glslrun;
using namespace glslrun::scene;

namespace {

using Lim = std::numeric_limits<float>;

float from_bits(uint32_t bits) { return std::bit_cast<float>(bits); }

}  // namespace

TEST_CASE("ULP distance: steps between neighbours, symmetric", "[scene][error]") {
    CHECK(ulp_distance(1.0f, 1.0f) == 0);
    CHECK(ulp_distance(1.0f, std::nextafter(1.0f, 2.0f)) == 1);
    CHECK(ulp_distance(std::nextafter(1.0f, 2.0f), 1.0f) == 1);
    CHECK(ulp_distance(1.0f, std::nextafter(1.0f, 0.0f)) == 1);  // across a binade
    CHECK(ulp_distance(1.0f, 2.0f) == (1u << 23));
    CHECK(ulp_distance(-1.0f, -2.0f) == (1u << 23));
    CHECK(ulp_distance(-3.5f, -3.5f) == 0);
}

TEST_CASE("ULP distance: zeros, denormals and sign changes", "[scene][error]") {
    CHECK(ulp_distance(0.0f, -0.0f) == 0);
    CHECK(ulp_distance(0.0f, Lim::denorm_min()) == 1);
    CHECK(ulp_distance(-0.0f, Lim::denorm_min()) == 1);
    CHECK(ulp_distance(-Lim::denorm_min(), Lim::denorm_min()) == 2);
    CHECK(ulp_distance(from_bits(0x007fffffu), Lim::min()) == 1);  // the largest denormal, then FLT_MIN
    CHECK(ulp_distance(-1.0f, 1.0f) == 2u * 0x3f800000u);
    CHECK(ulp_distance(-1e-30f, 1e-30f) == 2u * std::bit_cast<uint32_t>(1e-30f));
}

TEST_CASE("ULP distance: infinities and NaN", "[scene][error]") {
    float inf = Lim::infinity();
    CHECK(ulp_distance(Lim::max(), inf) == 1);
    CHECK(ulp_distance(inf, inf) == 0);
    CHECK(ulp_distance(-inf, -inf) == 0);
    CHECK(ulp_distance(-inf, inf) == 0xff000000u);
    float nan = Lim::quiet_NaN(), other_nan = from_bits(0xffc01234u);
    CHECK(ulp_distance(nan, other_nan) == 0);  // payload and sign do not matter
    CHECK(ulp_distance(nan, 1.0f) == kNanUlp);
    CHECK(ulp_distance(0.0f, other_nan) == kNanUlp);
    CHECK(ulp_distance(nan, inf) == kNanUlp);
    CHECK(kNanUlp > ulp_distance(-inf, inf));
}

TEST_CASE("8-bit values follow the RGBA8 buffer's rounding", "[scene][error]") {
    CHECK(to_unorm8(0.0f) == 0);
    CHECK(to_unorm8(1.0f) == 255);
    CHECK(to_unorm8(-3.0f) == 0);
    CHECK(to_unorm8(7.0f) == 255);
    CHECK(to_unorm8(Lim::quiet_NaN()) == 0);
    CHECK(to_unorm8(Lim::infinity()) == 255);
    CHECK(to_unorm8(0.5f) == 128);  // 127.5 rounds to even: 128
    CHECK(to_unorm8(1.5f / 255.0f) == 2);
    CHECK(to_unorm8(std::nextafter(0.5f / 255.0f, 0.0f)) == 0);
    // Every value the framebuffer's PNG writer can meet agrees with read_framebuffer().
    Framebuffer fb(256, 1, /*float_color=*/true);
    std::span<float> color = fb.color_data<float>();
    for (size_t i = 0; i < color.size(); ++i) color[i] = float(int(i) - 100) / 700.0f;
    Image image = read_framebuffer(fb);
    for (size_t i = 0; i < color.size(); ++i) {
        INFO("value " << color[i]);
        CHECK(to_unorm8(color[i]) == image.rgba[i]);
    }
}

TEST_CASE("channel statistics: max, mean, NaN mismatches, absolute error", "[scene][error]") {
    ChannelError e;
    CHECK(e.mean_ulp() == 0);
    CHECK(e.add(1.0f, 1.0f) == 0);
    CHECK(e.add(1.0f, std::nextafter(std::nextafter(1.0f, 2.0f), 2.0f)) == 2);
    CHECK(e.add(0.0f, -0.0f) == 0);
    CHECK(e.add(Lim::quiet_NaN(), 0.25f) == kNanUlp);
    CHECK(e.compared == 4);
    CHECK(e.nan_mismatches == 1);
    CHECK(e.max_ulp == kNanUlp);
    CHECK(e.mean_ulp() == Approx(2.0 / 3.0));  // the NaN pair is not in the mean
    CHECK(e.max_abs == Approx(2.0 * std::ldexp(1.0, -23)));
    e.add(Lim::infinity(), Lim::infinity());
    CHECK(std::isfinite(e.max_abs));  // equal infinities are no error
    e.add(Lim::infinity(), Lim::max());
    CHECK(std::isinf(e.max_abs));

    ChannelError q;
    CHECK(q.add_8bit(0.0f, 2.0f / 255.0f) == 2);
    CHECK(q.add_8bit(1.0f, 1.5f) == 0);  // both saturate
    CHECK(q.add_8bit(0.2f, 0.2f) == 0);
    CHECK(q.max_8bit == 2);
    CHECK(q.mean_8bit() == Approx(2.0 / 3.0));
    CHECK(q.compared == 0);  // 8-bit pairs are counted apart

    ChannelError merged = e;
    merged.merge(q);
    CHECK(merged.max_ulp == kNanUlp);
    CHECK(merged.max_8bit == 2);
    CHECK(merged.compared == e.compared);
    CHECK(merged.compared_8bit == 3);
}

namespace {

// 3x2 RGBA images, row 0 at the bottom as a framebuffer stores them.
FloatImage image3x2(float fill) {
    FloatImage f{3, 2, 4, std::vector<float>(24, fill), std::vector<uint8_t>(6, 1)};
    return f;
}

void set_pixel(FloatImage& f, int x, int y, std::array<float, 4> v) {
    for (int k = 0; k < 4; ++k) f.values[size_t((y * f.width + x) * 4 + k)] = v[size_t(k)];
}

}  // namespace

TEST_CASE("image comparison: coverage, per-channel errors and the worst pixels", "[scene][error]") {
    FloatImage ref = image3x2(0.5f), act = image3x2(0.5f);
    float up3 = from_bits(std::bit_cast<uint32_t>(0.5f) + 3);
    set_pixel(act, 0, 0, {up3, 0.5f, 0.5f, 0.5f});                          // bottom left: 3 ULP in r
    set_pixel(act, 2, 1, {0.5f, 0.5f + 2.0f / 255.0f, 0.5f, 0.5f});          // top right: 2 in 8 bits, g
    set_pixel(act, 1, 0, {0.5f, 0.5f, Lim::quiet_NaN(), 0.5f});              // bottom middle: NaN in b
    ref.covered[size_t(1 * 3 + 0)] = 0;                                      // top left: in `act` only
    set_pixel(act, 0, 1, {1.0f, 1.0f, 1.0f, 1.0f});
    ref.covered[size_t(1 * 3 + 1)] = 0;                                      // top middle: in neither
    act.covered[size_t(1 * 3 + 1)] = 0;
    set_pixel(act, 1, 1, {0.0f, 0.0f, 0.0f, 0.0f});                          // ignored: not covered

    auto r = compare_float_images("gl_FragColor", ref, act, true);
    REQUIRE(r);
    const ImageError& e = *r;
    CHECK(e.covered_both == 4);
    CHECK(e.covered_one == 1);
    CHECK(e.channel[0].max_ulp == 3);
    CHECK(e.channel[0].compared == 4);
    CHECK(e.channel[0].mean_ulp() == Approx(0.75));
    CHECK(e.channel[1].max_ulp == ulp_distance(0.5f, 0.5f + 2.0f / 255.0f));
    CHECK(e.channel[2].max_ulp == kNanUlp);
    CHECK(e.channel[2].nan_mismatches == 1);
    CHECK(e.channel[3].max_ulp == 0);
    // 8 bits: the NaN pixel (NaN stores 0: 128 off in b), the top-left one covered once (0.5 -> 1.0), the g one.
    CHECK(e.channel[2].max_8bit == 128);
    CHECK(e.channel[1].max_8bit == 127);
    CHECK(e.channel[1].compared_8bit == 5);
    CHECK(e.differing_8bit == 3);
    // Top-left origin: framebuffer row 0 is image row 1.
    CHECK(e.worst_ulp.found);
    CHECK(e.worst_ulp.x == 1);
    CHECK(e.worst_ulp.y == 1);
    CHECK(e.worst_ulp.ulp == kNanUlp);
    CHECK(e.worst_8bit.x == 1);  // the NaN pixel's 128 beats the covered-once pixel's 127
    CHECK(e.worst_8bit.y == 1);
    CHECK(e.worst_8bit.diff_8bit == 128);
    CHECK(e.worst_8bit.actual[2] != e.worst_8bit.actual[2]);  // the values come along: NaN
    REQUIRE(e.pixel_ulp.size() == 6);
    CHECK(e.pixel_ulp[0] == kCoverageMismatch);  // image row 0 = framebuffer row 1
    CHECK(e.pixel_ulp[1] == kBackground);
    CHECK(e.pixel_ulp[2] == ulp_distance(0.5f, 0.5f + 2.0f / 255.0f));
    CHECK(e.pixel_ulp[3] == 3);
    CHECK(e.pixel_ulp[4] == kNanUlp);
    CHECK(e.pixel_ulp[5] == 0);
    CHECK(e.total().max_ulp == kNanUlp);
    CHECK(e.total().compared == 16);
}

TEST_CASE("image comparison: equal images give zero everywhere", "[scene][error]") {
    FloatImage a = image3x2(0.25f);
    set_pixel(a, 2, 0, {Lim::quiet_NaN(), Lim::infinity(), -0.0f, Lim::denorm_min()});
    auto r = compare_float_images("depth", a, a, false);
    REQUIRE(r);
    CHECK(r->total().max_ulp == 0);
    CHECK(r->total().max_abs == 0);
    CHECK(r->total().compared_8bit == 0);  // depth is not quantized
    CHECK(r->differing_8bit == 0);
    CHECK(r->covered_both == 6);
    CHECK(r->worst_ulp.ulp == 0);
}

TEST_CASE("image comparison: mismatched or malformed images are errors", "[scene][error]") {
    FloatImage a = image3x2(0.0f), b = image3x2(0.0f);
    b.width = 2;
    b.height = 3;
    auto r = compare_float_images("gl_FragColor", a, b, true);
    REQUIRE_FALSE(r);
    CHECK_THAT(r.error().str(), Catch::Contains("gl_FragColor"));
    FloatImage c = image3x2(0.0f);
    c.covered.pop_back();
    CHECK_FALSE(compare_float_images("x", a, c, true));
    FloatImage d = image3x2(0.0f);
    d.channels = 5;
    CHECK_FALSE(compare_float_images("x", d, d, true));
}

TEST_CASE("heat map colours: markers and the log2 scale", "[scene][error]") {
    ImageError e;
    e.width = 8;
    e.height = 1;
    e.pixel_ulp = {kBackground, 0, 1, 64, 4096, uint64_t(1) << 30, kNanUlp, kCoverageMismatch};
    Image h = heat_map(e);
    REQUIRE(h.rgba.size() == 32);
    auto rgb = [&](int i) { return std::array<int, 3>{h.rgba[size_t(i) * 4], h.rgba[size_t(i) * 4 + 1], h.rgba[size_t(i) * 4 + 2]}; };
    CHECK(rgb(0) == std::array{48, 48, 48});
    CHECK(rgb(1) == std::array{0, 0, 0});
    CHECK(rgb(2) == std::array{0, 0, 255});
    CHECK(rgb(3) == std::array{0, 255, 255});
    CHECK(rgb(4) == std::array{0, 255, 0});
    CHECK(rgb(5) == std::array{255, 0, 0});  // beyond the top: red
    CHECK(rgb(6) == std::array{255, 0, 255});
    CHECK(rgb(7) == std::array{255, 255, 255});
    for (int i = 0; i < 8; ++i) CHECK(h.rgba[size_t(i) * 4 + 3] == 255);
    CHECK_THAT(heat_map_legend(), Catch::Contains("log2"));
}
