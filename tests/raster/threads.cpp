// The tiled, multi-threaded draw: images (colour and depth) and fragment
// counts are bit-identical whatever Program::exec.threads is, on scenes that
// span many tiles, with overlapping primitives, order effects at equal
// depth, discard, gl_FragDepth, lines and points across tile borders; the
// first shader error is the same too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

using namespace glslrun;

namespace {

const unsigned kThreadCounts[] = {2, 3, 7, 64};

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Program compile_files(const std::string& stem) {
    std::string dir = std::string(GLSLRUN_SOURCE_DIR) + "/shaders/";
    auto p = Program::compile({{stem + ".vert", read_text(dir + stem + ".vert")}},
                              {{stem + ".frag", read_text(dir + stem + ".frag")}});
    REQUIRE(p.ok());
    return std::move(*p);
}

Program compile(const char* vs, const char* fs) {
    auto p = Program::compile({{"vs", vs}}, {{"fs", fs}});
    if (!p) FAIL(p.error().str());
    return std::move(*p);
}

struct Frame {
    Framebuffer fb;
    DrawStats stats;
};

// Values that differ (bitwise equal values: same colour, same depth).
template <class T>
size_t differences(std::span<const T> a, std::span<const T> b) {
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
    return n;
}

// Colour buffer 0's channels that differ, in either format.
size_t color_differences(const Framebuffer& a, const Framebuffer& b) {
    if (a.float_color() != b.float_color()) return SIZE_MAX;
    if (a.float_color()) return differences<float>(a.color_data<float>(), b.color_data<float>());
    return differences<uint8_t>(a.color_data<uint8_t>(), b.color_data<uint8_t>());
}

void check_same(const Frame& a, const Frame& b) {
    CHECK(a.stats.fragments_shaded == b.stats.fragments_shaded);
    CHECK(a.stats.fragments_written == b.stats.fragments_written);
    CHECK(color_differences(a.fb, b.fb) == 0u);
    CHECK(differences<float>(a.fb.depth, b.fb.depth) == 0u);
}

// Distinct colours in the image: guards against comparing two blank frames.
size_t distinct_colors(const Framebuffer& fb) {
    std::vector<glm::vec4> seen;
    for (int y = 0; y < fb.height && seen.size() < 64; ++y)
        for (int x = 0; x < fb.width && seen.size() < 64; ++x)
            if (std::find(seen.begin(), seen.end(), fb.pixel(x, y)) == seen.end()) seen.push_back(fb.pixel(x, y));
    return seen.size();
}

Frame render_scene_file(const std::string& scene_name, const std::string& program, unsigned threads) {
    auto scene = scene::load_scene(std::string(GLSLRUN_SOURCE_DIR) + "/scenes/" + scene_name);
    REQUIRE(scene.ok());
    Program p = compile_files(program);
    p.exec.threads = threads;
    Frame f{Framebuffer(scene->width, scene->height), {}};
    auto stats = scene::render_scene(p, *scene, f.fb);
    REQUIRE(stats.ok());
    f.stats = *stats;
    return f;
}

// Random overlapping primitives over a 300x200 target (5x4 tiles): a few
// depths only, so that many fragments tie and GL_LEQUAL order decides.
struct Geometry {
    VertexAttrib pos{"gl_Vertex", 4, {}};
    VertexAttrib color{"gl_Color", 4, {}};
    uint32_t count = 0;
};

Geometry random_geometry(unsigned seed, uint32_t vertices) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xy(-1.2f, 1.2f), unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> level(0, 3);
    Geometry g;
    for (uint32_t v = 0; v < vertices; ++v) {
        // Triangles take one of four depth levels, so ties are common.
        float z = v % 3 == 0 ? float(level(rng)) * 0.25f - 0.4f : g.pos.data[g.pos.data.size() - 2];
        g.pos.data.insert(g.pos.data.end(), {xy(rng), xy(rng), z, 1.0f});
        g.color.data.insert(g.color.data.end(), {unit(rng), unit(rng), unit(rng), 1.0f});
    }
    g.count = vertices;
    return g;
}

// Many small triangles, some crossing the near or far plane (clipped).
Geometry small_triangles(unsigned seed, uint32_t triangles) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> centre(-1.1f, 1.1f), offset(-0.06f, 0.06f), depth(-1.3f, 1.3f),
        unit(0.0f, 1.0f);
    Geometry g;
    for (uint32_t t = 0; t < triangles; ++t) {
        float cx = centre(rng), cy = centre(rng), cz = depth(rng);
        for (int v = 0; v < 3; ++v) {
            g.pos.data.insert(g.pos.data.end(), {cx + offset(rng), cy + offset(rng), cz + 4 * offset(rng), 1.0f});
            g.color.data.insert(g.color.data.end(), {unit(rng), unit(rng), unit(rng), 1.0f});
        }
    }
    g.count = triangles * 3;
    return g;
}

// Draws g once per pass (program and state) into one frame.
struct Pass {
    Program* program;
    GLState gl;
};

Frame draw_passes(const std::vector<Pass>& passes, const Geometry& g, Primitive prim, unsigned threads) {
    Frame f{Framebuffer(300, 200), {}};
    f.fb.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
    f.fb.clear_depth(1.0f);
    for (const Pass& pass : passes) {
        pass.program->exec.threads = threads;
        auto stats = draw(*pass.program, pass.gl, f.fb, prim, {g.pos, g.color}, g.count);
        REQUIRE(stats.ok());
        f.stats += *stats;
    }
    return f;
}

Frame draw_geometry(Program& p, const Geometry& g, Primitive prim, unsigned threads, GLState gl) {
    return draw_passes({{&p, gl}}, g, prim, threads);
}

const char* kColorVs = "void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; gl_PointSize = 9.0; }";

}  // namespace

TEST_CASE("the spot-light teapot is identical with any thread count", "[raster][threads]") {
    Frame one = render_scene_file("spot.toml", "spot_pix_fixed", 1);
    CHECK(one.stats.fragments_written > 10000u);
    CHECK(distinct_colors(one.fb) > 20u);
    for (unsigned threads : kThreadCounts) {
        INFO("threads " << threads);
        check_same(one, render_scene_file("spot.toml", "spot_pix_fixed", threads));
    }
}

TEST_CASE("the textured teapot is identical with any thread count", "[raster][threads]") {
    Frame one = render_scene_file("textured.toml", "textured_pix", 1);
    CHECK(distinct_colors(one.fb) > 20u);
    for (unsigned threads : kThreadCounts) {
        INFO("threads " << threads);
        check_same(one, render_scene_file("textured.toml", "textured_pix", threads));
    }
}

TEST_CASE("overlapping triangles keep submission order at equal depth", "[raster][threads]") {
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    Program second = compile(kColorVs, "void main() { gl_FragColor = gl_Color.gbra; }");
    Geometry g = random_geometry(7, 600);
    GLState gl;
    gl.depth_test = true;
    for (auto func : {GLState::DepthFunc::Lequal, GLState::DepthFunc::Less, GLState::DepthFunc::Equal}) {
        // A second pass over the same geometry: GL_EQUAL and GL_LEQUAL redraw
        // exactly the surfaces the first pass left (multipass rendering).
        GLState then = gl;
        then.depth_func = func;
        std::vector<Pass> passes{{&p, gl}, {&second, then}};
        Frame one = draw_passes(passes, g, Primitive::Triangles, 1);
        CHECK(distinct_colors(one.fb) > 20u);
        for (unsigned threads : kThreadCounts) {
            INFO("depth func " << int(func) << ", threads " << threads);
            check_same(one, draw_passes(passes, g, Primitive::Triangles, threads));
        }
    }
}

TEST_CASE("a later triangle at equal depth wins with GL_LEQUAL, on every tile", "[raster][threads]") {
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    // Two full-screen quads at the same depth: red, then green.
    auto quad = [](float r, float gr) {
        Geometry q;
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            q.pos.data.insert(q.pos.data.end(), {c[0], c[1], 0.3f, 1.0f});
            q.color.data.insert(q.color.data.end(), {r, gr, 0.0f, 1.0f});
        }
        q.count = 4;
        return q;
    };
    GLState gl;
    gl.depth_test = true;
    gl.depth_func = GLState::DepthFunc::Lequal;
    for (unsigned threads : {1u, 2u, 3u, 7u, 64u}) {
        p.exec.threads = threads;
        Framebuffer fb(300, 200);
        fb.clear_depth(1.0f);
        Geometry red = quad(1, 0), green = quad(0, 1);
        REQUIRE(draw(p, gl, fb, Primitive::Quads, {red.pos, red.color}, 4).ok());
        REQUIRE(draw(p, gl, fb, Primitive::Quads, {green.pos, green.color}, 4).ok());
        for (int y = 0; y < fb.height; y += 7)
            for (int x = 0; x < fb.width; x += 5) {
                INFO("threads " << threads << " pixel " << x << "," << y);
                REQUIRE(fb.pixel(x, y) == glm::vec4(0, 1, 0, 1));
            }
    }
}

TEST_CASE("large draws set up primitives on the workers, with identical results", "[raster][threads]") {
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    // 40,000 triangles: many setup jobs; 5,000: a few (a teapot's size, set
    // up on the workers too), with 15,000 vertices' clip vertices in jobs.
    for (uint32_t count : {40000u, 5000u}) {
        Geometry g = small_triangles(13, count);
        GLState gl;
        gl.depth_test = true;
        for (bool flat : {false, true}) {
            gl.flat_shading = flat;  // attribute vectors made per primitive
            Frame one = draw_geometry(p, g, Primitive::Triangles, 1, gl);
            CHECK(one.stats.triangles == count);
            CHECK(distinct_colors(one.fb) > 20u);
            for (unsigned threads : kThreadCounts) {
                INFO("triangles " << count << ", flat " << flat << ", threads " << threads);
                check_same(one, draw_geometry(p, g, Primitive::Triangles, threads, gl));
            }
        }
    }
}

TEST_CASE("many small overlapping draws across tile borders keep draw order", "[raster][threads]") {
    // 150 draws of one opaque rectangle each, without a depth test, over a
    // 300x200 target (5x4 tiles of 64): the last draw that covers a pixel
    // decides its colour, whatever the threads. Rectangles have whole-pixel
    // edges, so which pixel centres they cover is known exactly; most are
    // small (one thread per draw), some large enough for the workers.
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    constexpr int kWidth = 300, kHeight = 200, kDraws = 150;
    struct Box {
        int x0, y0, x1, y1;
        glm::u8vec4 color;
    };
    std::mt19937 rng(29);
    std::vector<Box> boxes;
    for (int i = 0; i < kDraws; ++i) {
        std::uniform_int_distribution<int> size(4, i % 10 == 0 ? 190 : 40);
        int w = size(rng), h = size(rng);
        int x0 = std::uniform_int_distribution<int>(0, kWidth - std::min(w, kWidth))(rng);
        int y0 = std::uniform_int_distribution<int>(0, kHeight - std::min(h, kHeight))(rng);
        auto channel = [&] { return uint8_t(std::uniform_int_distribution<int>(0, 255)(rng)); };
        boxes.push_back({x0, y0, std::min(x0 + w, kWidth), std::min(y0 + h, kHeight),
                         {channel(), channel(), uint8_t(i), 255}});
    }
    // The expected image: each pixel the colour of the last box over its centre.
    std::vector<glm::u8vec4> expected(size_t(kWidth * kHeight), glm::u8vec4(0, 0, 0, 255));
    for (const Box& b : boxes)
        for (int y = b.y0; y < b.y1; ++y)
            for (int x = b.x0; x < b.x1; ++x) expected[size_t(y * kWidth + x)] = b.color;
    // The order matters: drawn in reverse, thousands of pixels would differ.
    std::vector<glm::u8vec4> reversed(expected.size(), glm::u8vec4(0, 0, 0, 255));
    for (auto b = boxes.rbegin(); b != boxes.rend(); ++b)
        for (int y = b->y0; y < b->y1; ++y)
            for (int x = b->x0; x < b->x1; ++x) reversed[size_t(y * kWidth + x)] = b->color;
    size_t order_sensitive = 0;
    for (size_t i = 0; i < expected.size(); ++i) order_sensitive += expected[i] != reversed[i];
    CHECK(order_sensitive > 5000u);
    GLState gl;
    gl.flat_shading = true;  // the provoking vertex's colour, exactly k / 255
    for (unsigned threads : {1u, 2u, 3u, 7u}) {
        p.exec.threads = threads;
        Framebuffer fb(kWidth, kHeight);
        fb.clear_color({0, 0, 0, 1});
        for (const Box& b : boxes) {
            Geometry q;
            auto ndc = [](int pixel, int size) { return 2.0f * float(pixel) / float(size) - 1.0f; };
            const int corners[4][2] = {{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}};
            for (const auto& c : corners) {
                q.pos.data.insert(q.pos.data.end(), {ndc(c[0], kWidth), ndc(c[1], kHeight), 0.0f, 1.0f});
                q.color.data.insert(q.color.data.end(), {b.color.r / 255.0f, b.color.g / 255.0f, b.color.b / 255.0f, 1.0f});
            }
            REQUIRE(draw(p, gl, fb, Primitive::Quads, {q.pos, q.color}, 4).ok());
        }
        std::span<const uint8_t> bytes = fb.color_data<uint8_t>();
        size_t wrong = 0;
        for (size_t i = 0; i < expected.size(); ++i)
            wrong += std::memcmp(&bytes[4 * i], &expected[i], 4) != 0;
        INFO("threads " << threads);
        CHECK(wrong == 0u);
    }
}

TEST_CASE("discard and gl_FragDepth give identical images with any thread count", "[raster][threads]") {
    Program discards = compile(kColorVs, R"(
void main() {
    if (fract(gl_FragCoord.x * 0.13 + gl_Color.r * 3.0) < 0.3) discard;
    gl_FragColor = gl_Color;
})");
    Program writes_depth = compile(kColorVs, R"(
void main() {
    gl_FragDepth = fract(gl_Color.g * 7.0 + gl_FragCoord.y * 0.01);
    gl_FragColor = gl_Color.bgra;
})");
    Geometry g = random_geometry(11, 450);
    GLState gl;
    gl.depth_test = true;
    gl.depth_func = GLState::DepthFunc::Lequal;
    for (Program* p : {&discards, &writes_depth}) {
        Frame one = draw_geometry(*p, g, Primitive::Triangles, 1, gl);
        CHECK(distinct_colors(one.fb) > 20u);
        for (unsigned threads : kThreadCounts) {
            INFO("threads " << threads);
            check_same(one, draw_geometry(*p, g, Primitive::Triangles, threads, gl));
        }
    }
}

TEST_CASE("lines and points across tile borders are identical with any thread count", "[raster][threads]") {
    Program p = compile(kColorVs, "#version 120\nvoid main() { gl_FragColor = vec4(gl_Color.rgb, gl_PointCoord.x); }");
    // Over 4096 vertices: the vertices are shaded on the workers too.
    Geometry g = random_geometry(5, 6000);
    GLState gl;
    gl.depth_test = true;
    gl.depth_func = GLState::DepthFunc::Lequal;
    gl.vertex_program_point_size = true;  // gl_PointSize = 9: points across tile borders
    for (Primitive prim : {Primitive::Lines, Primitive::LineStrip, Primitive::Points}) {
        Frame one = draw_geometry(p, g, prim, 1, gl);
        CHECK(distinct_colors(one.fb) > 20u);
        for (unsigned threads : kThreadCounts) {
            INFO("primitive " << int(prim) << ", threads " << threads);
            check_same(one, draw_geometry(p, g, prim, threads, gl));
        }
    }
}

TEST_CASE("polygon modes, polygon offset, wide lines and point sprites are identical with any thread count",
          "[raster][threads]") {
    Program p = compile(kColorVs, "#version 120\nvoid main() { gl_FragColor = vec4(gl_Color.rgb, gl_TexCoord[0].x); }");
    Geometry g = random_geometry(7, 6000);
    GLState gl;
    gl.depth_test = true;
    gl.polygon_mode = {PolygonMode::Line, PolygonMode::Point};
    gl.polygon_offset_line = gl.polygon_offset_point = true;
    gl.polygon_offset_factor = 1;
    gl.polygon_offset_units = 3;
    gl.line_width = 5;
    gl.point_sprite = true;
    gl.coord_replace = 1;
    gl.vertex_program_point_size = true;
    for (Primitive prim : {Primitive::Triangles, Primitive::Quads, Primitive::Lines, Primitive::Points}) {
        Frame one = draw_geometry(p, g, prim, 1, gl);
        CHECK(distinct_colors(one.fb) > 20u);
        for (unsigned threads : kThreadCounts) {
            INFO("primitive " << int(prim) << ", threads " << threads);
            check_same(one, draw_geometry(p, g, prim, threads, gl));
        }
    }
}

// Never ends where red > 0.5; the loop cap stops it.
constexpr const char* kRunawayFs = R"(
void main() {
    float x = 0.0;
    while (x < 1.0) { x += gl_Color.r > 0.5 ? 0.0 : 0.25; }
    gl_FragColor = gl_Color * x;
})";

// Draws `g` with every thread count and requires the same loop-cap error,
// naming `where` (the runaway loop's "stage:line").
static void check_loop_cap_error(Program& p, const Geometry& g, Primitive prim, const char* where) {
    p.exec.max_loop_iterations = 1000;
    std::string first;
    for (unsigned threads : {1u, 2u, 3u, 7u, 64u}) {
        INFO("threads " << threads);
        p.exec.threads = threads;
        Framebuffer fb(300, 200);
        auto stats = draw(p, GLState{}, fb, prim, {g.pos, g.color}, g.count);
        REQUIRE_FALSE(stats.ok());
        if (threads == 1) first = stats.error().str();
        CHECK(stats.error().str() == first);
        CHECK(first.find(where) != std::string::npos);
    }
}

TEST_CASE("a loop-cap error is reported the same way with any thread count", "[raster][threads]") {
    Program p = compile(kColorVs, kRunawayFs);
    check_loop_cap_error(p, random_geometry(3, 300), Primitive::Triangles, "fs:4");
}

TEST_CASE("a vertex shader's loop-cap error is the same with any thread count", "[raster][threads]") {
    Program p = compile(R"(
void main() {
    float x = 0.0;
    while (x < 1.0) { x += gl_Vertex.x > 0.9 ? 0.0 : 0.5; }
    gl_Position = gl_Vertex * x;
})", "void main() { gl_FragColor = vec4(1.0); }");
    check_loop_cap_error(p, random_geometry(9, 9000), Primitive::Points, "vs:4");
}

// draw() with ClearValues clears in its tile jobs (every tile of the
// framebuffer, tiles without primitives and outside the viewport too).
namespace {

// What a clear must overwrite: every colour channel is kDirty (or its byte), every depth 0.33.
constexpr float kDirty = 0.77f;
constexpr uint8_t kDirtyByte = 196;
Framebuffer dirty_framebuffer(int w, int h, bool float_color) {
    Framebuffer fb(w, h, float_color);
    std::ranges::fill(fb.color_data<float>(), kDirty);
    std::ranges::fill(fb.color_data<uint8_t>(), kDirtyByte);
    std::fill(fb.depth.begin(), fb.depth.end(), 0.33f);
    return fb;
}

// draw() with `clear` against the same clear made eagerly, then the draw:
// both from a dirty framebuffer; returns the former.
Framebuffer check_clear_then_draw(Program& p, const GLState& gl, const Geometry& g, const ClearValues& clear, int w,
                                  int h, bool float_color) {
    Framebuffer eager = dirty_framebuffer(w, h, float_color);
    if (clear.color) eager.clear_color(*clear.color);
    if (clear.depth) eager.clear_depth(*clear.depth);
    REQUIRE(draw(p, gl, eager, Primitive::Triangles, {g.pos, g.color}, g.count).ok());
    Framebuffer fused = dirty_framebuffer(w, h, float_color);
    REQUIRE(draw(p, gl, fused, clear, Primitive::Triangles, {g.pos, g.color}, g.count).ok());
    CHECK(color_differences(eager, fused) == 0u);
    CHECK(differences<float>(eager.depth, fused.depth) == 0u);
    return fused;
}

// No pixel of fb is left dirty: the clear is 51, the shader writes alpha 255.
void check_no_dirty_pixel(const Framebuffer& fb) {
    int dirty = 0;
    for (int y = 0; y < fb.height; ++y)
        for (int x = 0; x < fb.width; ++x) dirty += fb.pixel(x, y) == glm::vec4(kDirtyByte / 255.0f);
    CHECK(dirty == 0);
    CHECK(std::count(fb.depth.begin(), fb.depth.end(), 0.33f) == 0);
}

}  // namespace

TEST_CASE("a draw that clears gives the pixels of a clear, then the draw", "[raster][threads][clear]") {
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    Geometry g = small_triangles(5, 400);
    const ClearValues both{glm::vec4(0.1f, 0.25f, 1.5f, -0.5f), 0.9f, std::nullopt};
    const ClearValues kinds[] = {both, {both.color, std::nullopt, std::nullopt}, {std::nullopt, 0.6f, std::nullopt}, {}};
    const std::array<int, 4> viewports[] = {{0, 0, 0, 0}, {20, 10, 150, 100}, {400, 400, 10, 10}};
    for (auto [w, h] : {std::pair{300, 200}, std::pair{130, 70}})
        for (bool float_color : {false, true})
            for (size_t kind = 0; kind < std::size(kinds); ++kind)
                for (const auto& viewport : viewports)
                    for (unsigned threads : {1u, 2u, 7u}) {
                        INFO(w << "x" << h << " float " << float_color << " clear " << kind << " viewport "
                               << viewport[0] << " threads " << threads);
                        const ClearValues& clear = kinds[kind];
                        GLState gl;
                        gl.depth_test = true;
                        gl.viewport = viewport;
                        p.exec.threads = threads;
                        check_clear_then_draw(p, gl, g, clear, w, h, float_color);
                    }
}

TEST_CASE("a draw that clears and fails leaves no pixel uncleared", "[raster][threads][clear]") {
    Program p = compile(kColorVs, kRunawayFs);
    p.exec.max_loop_iterations = 1000;
    Geometry g = random_geometry(3, 300);
    for (unsigned threads : {1u, 2u, 3u, 7u}) {
        INFO("threads " << threads);
        p.exec.threads = threads;
        Framebuffer fb = dirty_framebuffer(300, 200, false);
        auto stats = draw(p, GLState{}, fb, ClearValues{glm::vec4(0.2f), 1.0f, std::nullopt}, Primitive::Triangles,
                          {g.pos, g.color}, g.count);
        REQUIRE_FALSE(stats.ok());
        check_no_dirty_pixel(fb);
    }
}

TEST_CASE("a large draw clears on a thread of its own at 2 or 3 threads: the same pixels", "[raster][threads][clear]") {
    // 640x520 pixels and 9,000 vertices: over the sizes from which draw()
    // clears ahead, while the vertices and setup run (raster/draw.cpp).
    constexpr int kWidth = 640, kHeight = 520;
    Program p = compile(kColorVs, "void main() { gl_FragColor = gl_Color; }");
    Geometry g = small_triangles(21, 3000);
    const ClearValues both{glm::vec4(0.1f, 0.25f, 0.5f, 1.0f), 0.9f, std::nullopt};
    const ClearValues kinds[] = {both, {both.color, std::nullopt, std::nullopt}, {std::nullopt, 0.6f, std::nullopt}};
    for (size_t kind = 0; kind < std::size(kinds); ++kind)
        for (unsigned threads : {1u, 2u, 3u, 7u}) {
            INFO("clear " << kind << " threads " << threads);
            const ClearValues& clear = kinds[kind];
            GLState gl;
            gl.depth_test = true;
            p.exec.threads = threads;
            CHECK(distinct_colors(check_clear_then_draw(p, gl, g, clear, kWidth, kHeight, false)) > 20u);
        }
    // Failing draws, in the tiles (the fragment shader's loop cap) and before
    // them (the vertex shader's): every pixel is cleared all the same.
    Program fs_fails = compile(kColorVs, kRunawayFs);
    Program vs_fails = compile(R"(
void main() {
    float x = 0.0;
    while (x < 1.0) { x += gl_Vertex.x > 0.9 ? 0.0 : 0.5; }
    gl_Position = gl_Vertex * x;
    gl_FrontColor = gl_Color;
})", "void main() { gl_FragColor = gl_Color; }");
    for (Program* failing : {&fs_fails, &vs_fails})
        for (unsigned threads : {2u, 3u}) {
            INFO((failing == &fs_fails ? "fragment" : "vertex") << " shader fails, threads " << threads);
            failing->exec.max_loop_iterations = 1000;
            failing->exec.threads = threads;
            Framebuffer fb = dirty_framebuffer(kWidth, kHeight, false);
            auto stats = draw(*failing, GLState{}, fb, ClearValues{glm::vec4(0.2f), 1.0f, std::nullopt},
                              Primitive::Triangles, {g.pos, g.color}, g.count);
            REQUIRE_FALSE(stats.ok());
            check_no_dirty_pixel(fb);
        }
}
