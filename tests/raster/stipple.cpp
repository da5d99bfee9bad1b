// Line stipple runs, the polygon stipple's masks, where primitive assembly
// restarts the stipple counter, the point square's largest size and sprite
// origin. Whole draws against Mesa: tests/reference/stipple_test.cpp and
// point_parameters_test.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "raster/assemble.h"
#include "raster/points_lines.h"
#include "raster/stipple.h"

using namespace glslrun;
using namespace glslrun::raster;

namespace {

std::vector<std::pair<float, float>> runs(glm::vec2 a, glm::vec2 b, uint16_t pattern, int repeat, uint32_t& counter) {
    std::vector<std::pair<float, float>> out;
    for_each_stipple_run(a, b, pattern, repeat, counter, [&](float t0, float t1) { out.emplace_back(t0, t1); });
    return out;
}

}  // namespace

TEST_CASE("line stipple runs: the counter per whole pixel, carried on", "[raster][stipple]") {
    uint32_t counter = 0;
    // 10 pixels long: bits 0-3 on, 4-7 off, 8-9 on.
    auto r = runs({0.5f, 2.5f}, {10.5f, 2.5f}, 0x0F0F, 1, counter);
    REQUIRE(r.size() == 2);
    CHECK(r[0] == std::pair{0.0f, 0.4f});
    CHECK(r[1] == std::pair{0.8f, 1.0f});
    CHECK(counter == 10);
    // 9.8 long steps 10 (rounded up), and the next line goes on from there.
    counter = 0;
    runs({0.5f, 2.5f}, {10.3f, 2.5f}, 0x0F0F, 1, counter);
    CHECK(counter == 10);
    r = runs({10.3f, 2.5f}, {25.7f, 2.5f}, 0x0F0F, 1, counter);  // counter 10, 11 on, then off
    REQUIRE(!r.empty());
    CHECK(r[0].first == 0.0f);
    CHECK(r[0].second == 2.0f / 15.4f);
    CHECK(counter == 26);
    // The repeat stretches every bit; y-major lines count along y.
    counter = 0;
    r = runs({1.0f, 1.0f}, {2.0f, 13.0f}, 0x0001, 3, counter);
    REQUIRE(r.size() == 1);
    CHECK(r[0] == std::pair{0.0f, 3.0f / 12.0f});
    // All ones: one run, the whole line; all zeros: none. Lengths that are not
    // finite count nothing.
    counter = 0;
    CHECK(runs({0, 0}, {7.25f, 1}, 0xFFFF, 1, counter) == std::vector<std::pair<float, float>>{{0.0f, 1.0f}});
    CHECK(runs({0, 0}, {7.25f, 1}, 0x0000, 1, counter).empty());
    counter = 5;
    CHECK(runs({0, 0}, {INFINITY, 1}, 0xFFFF, 1, counter).empty());
    CHECK(counter == 5);
}

TEST_CASE("polygon stipple masks are aligned to the window", "[raster][stipple]") {
    std::array<uint32_t, 32> pattern{};
    for (size_t y = 0; y < 32; ++y) pattern[y] = 0x80000001u >> (y % 2);  // x = 0 and 31 on even rows, 1 on odd
    PolygonStipple stipple(pattern);
    auto on = [&](int x, int y) {
        int ox = x & ~7, oy = y & ~7;
        return (stipple.square(ox, oy) >> ((y - oy) * 8 + (x - ox))) & 1u;
    };
    for (int y = 0; y < 70; ++y)
        for (int x = 0; x < 70; ++x) {
            INFO(x << ", " << y);
            bool want = y % 2 == 0 ? (x % 32 == 0 || x % 32 == 31) : x % 32 == 1;
            CHECK(bool(on(x, y)) == want);
        }
    // A square at any even origin (small triangles' squares start on a quad).
    CHECK(((stipple.square(30, 2) >> 1) & 1u) == 1);    // (31, 2)
    CHECK(((stipple.square(30, 2) >> 2) & 1u) == 1);    // (32, 2)
    CHECK(((stipple.square(30, 2) >> 11) & 1u) == 1);   // (33, 3)
    CHECK(stipple.square(2, 0) == 0);
    PolygonStipple ones(GLState::filled_stipple());
    CHECK(ones.square(13, 7) == ~uint64_t(0));
}

TEST_CASE("primitive assembly says where the stipple counter restarts", "[raster][stipple]") {
    auto restarts = [](Primitive p, uint32_t n, bool unfilled = false) {
        std::vector<bool> out;
        for (const AssembledPrim& a : assemble(p, n, unfilled)) out.push_back(a.restarts_stipple);
        return out;
    };
    using V = std::vector<bool>;
    CHECK(restarts(Primitive::Lines, 6) == V{true, true, true});
    CHECK(restarts(Primitive::LineStrip, 4) == V{true, false, false});
    CHECK(restarts(Primitive::LineLoop, 4) == V{true, false, false, false});  // the closing line carries on
    CHECK(restarts(Primitive::TriangleStrip, 5) == V{true, true, true});
    CHECK(restarts(Primitive::TriangleFan, 5) == V{true, true, true});
    CHECK(restarts(Primitive::Quads, 8) == V{true, false, true, false});
    CHECK(restarts(Primitive::Quads, 8, true) == V{true, false, true, false});
    CHECK(restarts(Primitive::QuadStrip, 6) == V{true, false, true, false});
    CHECK(restarts(Primitive::Polygon, 5) == V{true, false, false});
    CHECK(restarts(Primitive::Polygon, 5, true) == V{true, false, false});
    CHECK(triangle_at(7).restarts_stipple);
}

TEST_CASE("point squares: at most 255 pixels, and the sprite's origin", "[raster][points]") {
    FsPrimitive p;
    set_point_square(p, {500.0f, 500.0f}, 300.0f, true);
    CHECK(p.point_box.x1 - p.point_box.x0 == 255);
    set_point_square(p, {500.0f, 500.0f}, 300.0f, false);
    CHECK(p.point_box.x1 - p.point_box.x0 == 255);
    // t runs down from the top by default, up from the bottom with GL_LOWER_LEFT.
    set_point_square(p, {10.5f, 10.5f}, 2.5f, true, true);
    CHECK(p.point_coord_step == glm::vec2(0.4f, 0.4f));
    CHECK(std::fma(p.point_coord_step.y, 11.0f, p.point_coord_origin.y) == Approx(0.9f).margin(1e-6));
    set_point_square(p, {10.5f, 10.5f}, 2.5f, true, false);
    CHECK(std::fma(p.point_coord_step.y, 11.0f, p.point_coord_origin.y) == Approx(0.1f).margin(1e-6));
    // Without sprites the origin changes nothing (Mesa's values: t upwards).
    set_point_square(p, {10.5f, 10.5f}, 3.0f, false, false);
    glm::vec2 upper = p.point_coord_step;
    set_point_square(p, {10.5f, 10.5f}, 3.0f, false, true);
    CHECK(p.point_coord_step == upper);
}
