// Clipping against near/far, w = 0 and user planes; depth functions; the
// framebuffer's quantisation; primitive assembly; line pixels.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "raster/assemble.h"
#include "raster/clip.h"
#include "raster/framebuffer.h"
#include "raster/points_lines.h"

using namespace glslrun;
using namespace glslrun::raster;

namespace {

ClipVertex vertex(glm::vec4 pos, const float* attrs) {
    ClipVertex v;
    v.pos = pos;
    v.attrs = attrs;
    return v;
}

// Checks that `attr` (attribute 0) still equals the linear function
// f(pos) = pos.x + 2 pos.y + 3 pos.z + 4 pos.w the inputs were built with.
void check_linear_attrs(const ClipPolygon& poly) {
    for (const ClipVertex& v : poly) {
        float f = v.pos.x + 2 * v.pos.y + 3 * v.pos.z + 4 * v.pos.w;
        CHECK(v.attrs[0] == Approx(f).margin(1e-4));
    }
}

float linear(glm::vec4 p) { return p.x + 2 * p.y + 3 * p.z + 4 * p.w; }

}  // namespace

TEST_CASE("triangles crossing the near and far planes are clipped", "[raster][clip]") {
    ClipParams params{1.0f, 0, 1};
    glm::vec4 p[3] = {{0, 0, -3, 1}, {0.5f, 0, 0, 1}, {0, 0.5f, 3, 1}};
    float a[3] = {linear(p[0]), linear(p[1]), linear(p[2])};
    CHECK(outcode(vertex(p[0], a), params) == 1u);       // behind near
    CHECK(outcode(vertex(p[1], a + 1), params) == 0u);
    CHECK(outcode(vertex(p[2], a + 2), params) == 2u);   // beyond far
    ClipPolygon poly{vertex(p[0], a), vertex(p[1], a + 1), vertex(p[2], a + 2)};
    AttrArena arena;
    clip_polygon(poly, params, arena);
    // Near cuts off one corner (a quadrilateral), far then another: a pentagon.
    REQUIRE(poly.size() == 5);
    for (const ClipVertex& v : poly) {
        CHECK(v.pos.z >= -v.pos.w - 1e-6f);
        CHECK(v.pos.z <= v.pos.w + 1e-6f);
    }
    check_linear_attrs(poly);
}

TEST_CASE("a triangle crossing w = 0 keeps only the w > 0 part", "[raster][clip]") {
    ClipParams params{4.0f, 0, 1};
    glm::vec4 p[3] = {{0, 0, 0.5f, 1}, {1, 0, 0.5f, -1}, {0, 1, 0.5f, -0.5f}};
    float a[3] = {linear(p[0]), linear(p[1]), linear(p[2])};
    ClipPolygon poly{vertex(p[0], a), vertex(p[1], a + 1), vertex(p[2], a + 2)};
    AttrArena arena;
    clip_polygon(poly, params, arena);
    REQUIRE(poly.size() >= 3);
    for (const ClipVertex& v : poly) {
        CHECK(v.pos.w > 0.0f);
        CHECK(std::abs(v.pos.x) <= params.guard * v.pos.w + 1e-5f);
        CHECK(std::abs(v.pos.z) <= v.pos.w + 1e-5f);
    }
    check_linear_attrs(poly);
    // Entirely behind the eye: nothing left.
    glm::vec4 q[3] = {{0, 0, 0, -1}, {1, 0, 0, -1}, {0, 1, 0, -2}};
    ClipPolygon gone{vertex(q[0], a), vertex(q[1], a), vertex(q[2], a)};
    clip_polygon(gone, params, arena);
    CHECK(gone.size() < 3);
}

TEST_CASE("the guard band leaves x/y alone unless coordinates would overflow", "[raster][clip]") {
    ClipParams params{100.0f, 0, 1};
    float a[3] = {0, 0, 0};
    CHECK(outcode(vertex({50, -90, 0, 1}, a), params) == 0u);
    CHECK(outcode(vertex({150, 0, 0, 1}, a), params) == (1u << 2));
    CHECK(outcode(vertex({0, -150, 0, 1}, a), params) == (1u << 5));
}

TEST_CASE("user clip planes use the distances given per vertex", "[raster][clip]") {
    ClipParams params{1.0f, 1u << 1, 1};
    float a[2] = {0.0f, 10.0f};
    ClipVertex v0 = vertex({0, 0, 0, 1}, a), v1 = vertex({1, 0, 0, 1}, a + 1);
    v0.user[1] = 1.0f;
    v1.user[1] = -3.0f;
    CHECK(outcode(v1, params) == (1u << 7));
    AttrArena arena;
    REQUIRE(clip_segment(v0, v1, params, arena));
    CHECK(v1.pos.x == Approx(0.25f));
    CHECK(v1.attrs[0] == Approx(2.5f));
    CHECK(v1.user[1] == Approx(0.0f).margin(1e-6));
    // A disabled plane clips nothing.
    ClipParams off{1.0f, 0, 1};
    ClipVertex w1 = vertex({1, 0, 0, 1}, a + 1);
    w1.user[1] = -3.0f;
    CHECK(outcode(w1, off) == 0u);
}

TEST_CASE("depth functions", "[raster][depth]") {
    using F = GLState::DepthFunc;
    struct Row { F f; bool less, equal, greater; };
    const Row rows[] = {{F::Never, false, false, false},  {F::Less, true, false, false},
                        {F::Equal, false, true, false},   {F::Lequal, true, true, false},
                        {F::Greater, false, false, true}, {F::Notequal, true, false, true},
                        {F::Gequal, false, true, true},   {F::Always, true, true, true}};
    for (const Row& r : rows) {
        INFO("func " << int(r.f));
        CHECK(depth_passes(r.f, 0.25f, 0.5f) == r.less);
        CHECK(depth_passes(r.f, 0.5f, 0.5f) == r.equal);
        CHECK(depth_passes(r.f, 0.75f, 0.5f) == r.greater);
    }
}

TEST_CASE("RGBA8 writes clamp and round to n/255; float targets keep values", "[raster][framebuffer]") {
    CHECK(to_unorm8(-0.5f) == 0);
    CHECK(to_unorm8(NAN) == 0);
    CHECK(to_unorm8(2.0f) == 255);
    CHECK(to_unorm8(0.5f) == 128);
    CHECK(to_unorm8(0.1f) == 26);
    Framebuffer fb(4, 3), ffb(4, 3, true);
    write_color(fb, 3, 2, {1.5f, 0.5f, -1.0f, 0.2f});
    write_color(ffb, 3, 2, {1.5f, 0.5f, -1.0f, 0.2f});
    CHECK(fb.pixel(3, 2) == glm::vec4(1.0f, 128.0f / 255.0f, 0.0f, 51.0f / 255.0f));
    // Four bytes a pixel.
    REQUIRE(fb.color_data<uint8_t>().size() == 4 * 3 * 4);
    CHECK(fb.color_data<float>().empty());
    const uint8_t* stored = fb.color_row<uint8_t>(0, 2) + 3 * 4;
    CHECK(std::vector<uint8_t>(stored, stored + 4) == std::vector<uint8_t>{255, 128, 0, 51});
    CHECK(ffb.pixel(3, 2) == glm::vec4(1.5f, 0.5f, -1.0f, 0.2f));
    CHECK(fb.pixel(2, 2) == glm::vec4(0.0f));
    CHECK(fb.pixel(9, 9) == glm::vec4(0.0f));
    fb.clear_color({0.3f, 0.3f, 0.3f, 1});
    // 0.3 * 255 = 76.5 in float arithmetic: round half to even, as Mesa's float_to_unorm does.
    CHECK(fb.pixel(0, 0).r == Approx(76.0f / 255.0f));
    fb.clear_depth(0.25f);
    CHECK(fb.depth[5] == 0.25f);
}

TEST_CASE("write_png writes a PNG file, top row first", "[raster][png]") {
    Framebuffer fb(2, 2);
    write_color(fb, 0, 0, {1, 0, 0, 1});  // bottom left
    std::string path = "test_raster_out.png";
    REQUIRE(write_png(fb, path).ok());
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() > 8);
    CHECK(bytes.substr(1, 3) == "PNG");
    std::remove(path.c_str());
    CHECK_FALSE(write_png(fb, "/nonexistent-dir/x.png").ok());
}

TEST_CASE("primitive assembly and provoking vertices", "[raster][assemble]") {
    auto quads = assemble(Primitive::Quads, 9);  // one trailing vertex too many
    REQUIRE(quads.size() == 4);
    CHECK(quads[0].v == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(quads[1].v == std::array<uint32_t, 3>{0, 2, 3});
    CHECK(quads[2].v == std::array<uint32_t, 3>{4, 5, 6});
    CHECK(quads[3].provoking == 7);
    auto strip = assemble(Primitive::TriangleStrip, 5);
    REQUIRE(strip.size() == 3);
    CHECK(strip[1].v == std::array<uint32_t, 3>{2, 1, 3});  // odd triangles keep the winding
    CHECK(strip[2].provoking == 4);
    auto fan = assemble(Primitive::TriangleFan, 5);
    REQUIRE(fan.size() == 3);
    CHECK(fan[2].v == std::array<uint32_t, 3>{0, 3, 4});
    auto poly = assemble(Primitive::Polygon, 5);
    REQUIRE(poly.size() == 3);
    CHECK(poly[2].provoking == 0);
    auto qstrip = assemble(Primitive::QuadStrip, 6);
    REQUIRE(qstrip.size() == 4);
    CHECK(qstrip[0].v == std::array<uint32_t, 3>{0, 1, 3});
    CHECK(qstrip[1].v == std::array<uint32_t, 3>{0, 3, 2});
    auto loop = assemble(Primitive::LineLoop, 3);
    REQUIRE(loop.size() == 3);
    CHECK(loop[2].v[0] == 2);
    CHECK(loop[2].v[1] == 0);
    CHECK(assemble(Primitive::Lines, 5).size() == 2);
    CHECK(assemble(Primitive::Points, 3).size() == 3);
    CHECK(assemble(Primitive::Triangles, 2).empty());
}

TEST_CASE("line pixels: GL's diamond-exit rule, as llvmpipe draws it", "[raster][lines]") {
    Rect scissor{0, 0, 16, 16};
    std::set<std::pair<int, int>> px;
    auto collect = [&](int x, int y) { CHECK(px.insert({x, y}).second); };  // each pixel once
    using Pixels = std::set<std::pair<int, int>>;
    // From one centre to another: the start's diamond is left, the end's never.
    for_each_line_pixel({0.5f, 2.5f}, {4.5f, 2.5f}, scissor, collect);
    CHECK(px == Pixels{{0, 2}, {1, 2}, {2, 2}, {3, 2}});
    px.clear();
    for_each_line_pixel({4.5f, 2.5f}, {0.5f, 2.5f}, scissor, collect);  // backwards: 4..1
    CHECK(px == Pixels{{1, 2}, {2, 2}, {3, 2}, {4, 2}});
    px.clear();
    // Ends inside diamonds but off centre: the half-open span of centres
    // would take column 5 and drop column 1; the diamond rule the reverse.
    for_each_line_pixel({1.7f, 6.5f}, {5.6f, 6.5f}, scissor, collect);
    CHECK(px == Pixels{{1, 6}, {2, 6}, {3, 6}, {4, 6}});
    px.clear();
    // Ends outside every diamond (a pixel's corner): one pixel per centre passed.
    for_each_line_pixel({1.0f, 9.0f}, {5.0f, 9.0f}, scissor, collect);
    CHECK(px.size() == 4);
    px.clear();
    for_each_line_pixel({1.5f, 0.25f}, {1.5f, 8.25f}, scissor, collect);  // y-major
    CHECK(px.size() == 8);
    for (auto [x, y] : px) CHECK(x == 1);
    px.clear();
    for_each_line_pixel({0.0f, 0.0f}, {8.0f, 4.0f}, scissor, collect);  // diagonal, x-major
    REQUIRE(px.size() == 8);
    std::set<int> columns;
    for (auto [x, y] : px) {
        columns.insert(x);
        CHECK(y == int((x + 0.5f) * 0.5f));
    }
    CHECK(columns.size() == 8);
    px.clear();
    for_each_line_pixel({-100.0f, 3.5f}, {100.0f, 3.5f}, scissor, collect);  // clipped by the scissor
    CHECK(px.size() == 16);
    px.clear();
    for_each_line_pixel({1.25f, 3.5f}, {9.25f, 3.5f}, scissor, collect, 3);  // 3 wide: rows 2..4
    CHECK(px.size() == 24);
    for (auto [x, y] : px) CHECK((y >= 2 && y <= 4));
}

TEST_CASE("point squares: sprites at their exact size, other points rounded as Mesa", "[raster][points]") {
    auto square = [](glm::vec2 centre, float size, bool sprite) {
        FsPrimitive p;
        set_point_square(p, centre, size, sprite);
        return p;
    };
    auto box = [](const FsPrimitive& p) { return std::array{p.point_box.x0, p.point_box.y0, p.point_box.x1, p.point_box.y1}; };
    // Without sprites the size is rounded, n + 1/2 down (llvmpipe), at least 1.
    CHECK(box(square({10.3f, 20.0f}, 2.5f, false)) == std::array{9, 19, 11, 21});   // floor(c + 1/2) - 1
    CHECK(box(square({10.3f, 20.0f}, 3.5f, false)) == std::array{9, 19, 12, 22});   // floor(c) - 1
    CHECK(box(square({10.3f, 20.0f}, 2.6f, false)) == std::array{9, 19, 12, 22});
    CHECK(box(square({10.3f, 20.0f}, 0.2f, false)) == std::array{10, 20, 11, 21});
    CHECK(box(square({10.3f, 20.0f}, std::nanf(""), false)) == std::array{10, 20, 11, 21});
    // Sprites: the pixels whose centres lie in [c - s/2, c + s/2), left and
    // bottom edges in.
    CHECK(box(square({10.3f, 20.0f}, 2.5f, true)) == std::array{9, 19, 12, 21});     // [9.05, 11.55) x [18.75, 21.25)
    CHECK(box(square({10.5f, 10.5f}, 2.0f, true)) == std::array{9, 9, 11, 11});      // centres 9.5 in, 11.5 out
    CHECK(box(square({-3.25f, 5.0f}, 1.5f, true)) == std::array{-4, 4, -3, 6});      // [-4, -2.5) x [4.25, 5.75)
    // gl_PointCoord: 1/size per pixel, 0.5 at the centre; t from the top with sprites.
    FsPrimitive p = square({10.5f, 10.5f}, 2.5f, true);
    CHECK(p.point_coord_step == glm::vec2(0.4f, -0.4f));
    CHECK(std::fma(p.point_coord_step.x, 10.0f, p.point_coord_origin.x) == Approx(0.5f).margin(1e-6));
    CHECK(std::fma(p.point_coord_step.y, 10.0f, p.point_coord_origin.y) == Approx(0.5f).margin(1e-6));
    CHECK(std::fma(p.point_coord_step.x, 11.0f, p.point_coord_origin.x) == Approx(0.9f).margin(1e-6));
    CHECK(std::fma(p.point_coord_step.y, 11.0f, p.point_coord_origin.y) == Approx(0.1f).margin(1e-6));
    CHECK(square({10.5f, 10.5f}, 2.5f, false).point_coord_step == glm::vec2(0.5f, 0.5f));
}
