// draw(): coverage, perspective-correct interpolation, clipping, depth,
// facing, flat shading, points and lines, through real shaders.
#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "helpers.h"

using namespace glslrun;
using api_test::compile;

namespace {

const char* kClipVs = R"(
attribute float t;
varying float vt;
void main() { vt = t; gl_Position = gl_Vertex; gl_FrontColor = gl_Color; gl_BackColor = gl_SecondaryColor; }
)";

const char* kShowFs = R"(
varying float vt;
void main() { gl_FragColor = vec4(vt, gl_FragCoord.z, gl_FragCoord.w, 1.0); }
)";

VertexAttrib positions(std::initializer_list<float> xyzw) { return {"gl_Vertex", 4, xyzw}; }

int count_written(const Framebuffer& fb, glm::vec4 clear) {
    int n = 0;
    for (int y = 0; y < fb.height; ++y)
        for (int x = 0; x < fb.width; ++x) n += fb.pixel(x, y) != clear;
    return n;
}

}  // namespace

TEST_CASE("perspective-correct interpolation matches the analytic value", "[api][draw]") {
    Program p = compile(kClipVs, kShowFs);
    Framebuffer fb(32, 32, true);
    fb.clear_color({-1, -1, -1, -1});
    GLState gl;
    // Clip coordinates with different w. The window positions (xy/w + 1) * 16
    // lie on the 1/256 subpixel grid, so snapping does not move them.
    const glm::vec4 clip[3] = {{3.25f / 16 - 1, 2.5f / 16 - 1, 0.0f, 1.0f},
                               {(29.75f / 16 - 1) * 2, (5.0f / 16 - 1) * 2, 1.0f, 2.0f},
                               {(6.0f / 16 - 1) * 4, (28.5f / 16 - 1) * 4, -2.0f, 4.0f}};
    const float t[3] = {0.0f, 10.0f, 100.0f};
    VertexAttrib pos{"gl_Vertex", 4, {}}, attr{"t", 1, {t[0], t[1], t[2]}};
    for (const auto& c : clip) pos.data.insert(pos.data.end(), {c.x, c.y, c.z, c.w});
    auto stats = draw(p, gl, fb, Primitive::Triangles, {pos, attr}, 3);
    REQUIRE(stats.ok());
    glm::dvec2 win[3];
    double zw[3];
    for (int i = 0; i < 3; ++i) {
        win[i] = (glm::dvec2(clip[i]) / double(clip[i].w) + 1.0) * 16.0;
        zw[i] = (clip[i].z / clip[i].w + 1.0) * 0.5;
    }
    int checked = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            glm::vec4 got = fb.pixel(x, y);
            if (got.a < 0) continue;
            glm::dvec2 pc(x + 0.5, y + 0.5);
            auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
            double area = cross(win[1] - win[0], win[2] - win[0]);
            double b1 = cross(pc - win[0], win[2] - win[0]) / area;  // weight of vertex 1
            double b2 = cross(win[1] - win[0], pc - win[0]) / area;  // weight of vertex 2
            double b0 = 1.0 - b1 - b2;
            REQUIRE(b0 >= -1e-6);
            REQUIRE(b1 >= -1e-6);
            REQUIRE(b2 >= -1e-6);
            double inv_w = b0 / clip[0].w + b1 / clip[1].w + b2 / clip[2].w;
            double expected_t = (b0 * t[0] / clip[0].w + b1 * t[1] / clip[1].w + b2 * t[2] / clip[2].w) / inv_w;
            INFO("pixel " << x << "," << y);
            CHECK(got.r == Approx(expected_t).margin(2e-3));
            CHECK(got.g == Approx(b0 * zw[0] + b1 * zw[1] + b2 * zw[2]).margin(1e-5));
            CHECK(got.b == Approx(inv_w).margin(1e-5));
            ++checked;
        }
    CHECK(checked > 100);
    CHECK(stats->fragments_written == uint64_t(checked));
}

TEST_CASE("adjacent triangles of an indexed grid write every pixel exactly once", "[api][draw]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; }", api_test::kPassFs);
    Framebuffer fb(40, 30);
    GLState gl;
    const int n = 7;
    VertexAttrib pos{"gl_Vertex", 2, {}};
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            float jx = (i > 0 && i < n) ? 0.037f * float((i * 7 + j * 3) % 5 - 2) : 0.0f;
            float jy = (j > 0 && j < n) ? 0.041f * float((i * 3 + j * 5) % 5 - 2) : 0.0f;
            pos.data.insert(pos.data.end(), {-1.0f + 2.0f * i / n + jx, -1.0f + 2.0f * j / n + jy});
        }
    std::vector<uint32_t> idx;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            idx.insert(idx.end(), {a, b, d, a, d, c});
        }
    auto stats = draw(p, gl, fb, Primitive::Triangles, {pos}, uint32_t((n + 1) * (n + 1)), idx);
    REQUIRE(stats.ok());
    CHECK(stats->triangles == uint64_t(2 * n * n));
    CHECK(stats->fragments_written == 40u * 30u);
    CHECK(count_written(fb, glm::vec4(0.0f)) == 40 * 30);
    auto bad = draw(p, gl, fb, Primitive::Triangles, {pos}, 3, idx);
    CHECK_FALSE(bad.ok());  // indices beyond the vertex count
}

TEST_CASE("a floor crossing the near plane is clipped and interpolated correctly", "[api][draw]") {
    Program p = compile(R"(
varying float depth;
void main() { depth = -(gl_ModelViewMatrix * gl_Vertex).z; gl_Position = ftransform(); }
)", "varying float depth; void main() { gl_FragColor = vec4(depth, 0.0, 0.0, 1.0); }");
    GLState gl;
    gl.projection = glm::perspective(glm::radians(90.0f), 1.0f, 1.0f, 50.0f);
    Framebuffer fb(32, 32, true);
    fb.clear_color({-1, -1, -1, -1});
    // The floor y = -1 from behind the eye (z = +3) to z = -40.
    VertexAttrib pos = positions({-30, -1, 3, 1, 30, -1, 3, 1, 30, -1, -40, 1, -30, -1, -40, 1});
    auto stats = draw(p, gl, fb, Primitive::Quads, {pos}, 4);
    REQUIRE(stats.ok());
    // Eye-space depth of the floor seen through a pixel row: y_ndc = -1 / d (90 degree fov).
    for (int y = 0; y < 32; ++y) {
        double y_ndc = (y + 0.5) / 16.0 - 1.0;
        glm::vec4 got = fb.pixel(16, y);
        INFO("row " << y);
        if (y_ndc < -1.0 / 40.0 + 1e-3) {  // floor visible, nearer than z = -40
            REQUIRE(got.a == 1.0f);
            // Near the horizon depth changes by d^2/16 per pixel, so the
            // 1/256-pixel vertex snapping allows a relative error of about d/4096.
            double d = -1.0 / y_ndc;
            CHECK(got.r == Approx(d).epsilon(1e-3 + d / 2048));
        } else if (y_ndc > 0) {
            CHECK(got.a == -1.0f);  // above the horizon: nothing
        }
    }
}

TEST_CASE("depth test functions and gl_FragDepth", "[api][draw]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; }",
                        "void main() { gl_FragColor = gl_Color; }");
    GLState gl;
    gl.depth_test = true;
    auto quad = [](float z) { return positions({-1, -1, z, 1, 1, -1, z, 1, 1, 1, z, 1, -1, 1, z, 1}); };
    VertexAttrib red{"gl_Color", 3, {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0}};
    VertexAttrib green{"gl_Color", 3, {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}};
    for (bool near_first : {false, true}) {
        Framebuffer fb(8, 8);
        fb.clear_depth(1.0f);
        auto first = near_first ? quad(-0.5f) : quad(0.5f);
        auto second = near_first ? quad(0.5f) : quad(-0.5f);
        REQUIRE(draw(p, gl, fb, Primitive::Quads, {first, near_first ? green : red}, 4).ok());
        auto stats = draw(p, gl, fb, Primitive::Quads, {second, near_first ? red : green}, 4);
        REQUIRE(stats.ok());
        CHECK(stats->fragments_written == (near_first ? 0u : 64u));
        CHECK(fb.pixel(3, 3) == glm::vec4(0, 1, 0, 1));
        CHECK(fb.depth[27] == Approx(0.25f));
    }
    Framebuffer fb(8, 8);
    fb.clear_depth(0.5f);
    gl.depth_func = GLState::DepthFunc::Greater;
    REQUIRE(draw(p, gl, fb, Primitive::Quads, {quad(-0.5f), green}, 4).ok());  // 0.25: fails
    CHECK(fb.pixel(1, 1) == glm::vec4(0.0f));
    REQUIRE(draw(p, gl, fb, Primitive::Quads, {quad(0.5f), red}, 4).ok());  // 0.75: passes
    CHECK(fb.pixel(1, 1) == glm::vec4(1, 0, 0, 1));
    CHECK(fb.depth[9] == Approx(0.75f));
    Program writes_depth = compile("void main() { gl_Position = gl_Vertex; }",
                                   "void main() { gl_FragDepth = 0.9; gl_FragColor = vec4(0.0, 0.0, 1.0, 1.0); }");
    REQUIRE(draw(writes_depth, gl, fb, Primitive::Quads, {quad(-0.9f)}, 4).ok());
    CHECK(fb.pixel(1, 1) == glm::vec4(0, 0, 1, 1));
    CHECK(fb.depth[9] == Approx(0.9f));
}

TEST_CASE("facing, culling, two-sided colour, flat shading, colour clamping", "[api][draw]") {
    Program p = compile(kClipVs, R"(
void main() { gl_FragColor = vec4(gl_Color.rgb, gl_FrontFacing ? 1.0 : 0.5); }
)");
    // Clockwise in window space: a back face.
    VertexAttrib pos = positions({-1, -1, 0, 1, -1, 1, 0, 1, 1, -1, 0, 1});
    VertexAttrib front{"gl_Color", 4, {2, -1, 0.5f, 1, 2, -1, 0.5f, 1, 2, -1, 0.5f, 1}};
    VertexAttrib back{"gl_SecondaryColor", 4, {0, 0, 1, 1, 0, 1, 0, 1, 0, 0.25f, 1, 1}};
    GLState gl;
    Framebuffer fb(8, 8, true);
    REQUIRE(draw(p, gl, fb, Primitive::Triangles, {pos, front, back}, 3).ok());
    CHECK(fb.pixel(0, 0) == glm::vec4(1, 0, 0.5f, 0.5f));  // front colour, clamped; back facing
    gl.vertex_program_two_side = true;
    gl.flat_shading = true;  // provoking vertex: the last one
    REQUIRE(draw(p, gl, fb, Primitive::Triangles, {pos, front, back}, 3).ok());
    CHECK(fb.pixel(0, 0) == glm::vec4(0, 0.25f, 1, 0.5f));
    CHECK(fb.pixel(2, 1) == glm::vec4(0, 0.25f, 1, 0.5f));
    gl.cull_face = true;
    Framebuffer culled(8, 8, true);
    auto stats = draw(p, gl, culled, Primitive::Triangles, {pos, front, back}, 3);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_shaded == 0u);
    gl.front_ccw = false;  // now it is the front face
    stats = draw(p, gl, culled, Primitive::Triangles, {pos, front, back}, 3);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written > 20u);
    CHECK(culled.pixel(0, 0) == glm::vec4(1, 0, 0.5f, 1));
}

TEST_CASE("user clip planes clip with gl_ClipVertex", "[api][draw]") {
    Program p = compile("void main() { gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex; gl_Position = ftransform(); }",
                        api_test::kPassFs);
    GLState gl;
    gl.clip_planes[3] = {0, 1, 0, -0.5f};  // keep y >= 0.5
    gl.clip_plane_enabled = 1u << 3;
    Framebuffer fb(16, 16);
    auto stats = draw(p, gl, fb, Primitive::Quads, {positions({-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1})}, 4);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 16u * 4u);  // rows 12..15
    CHECK(fb.pixel(5, 12) == glm::vec4(1.0f));
    CHECK(fb.pixel(5, 11) == glm::vec4(0.0f));
}

TEST_CASE("points and lines", "[api][draw]") {
    Program sized = compile("void main() { gl_Position = gl_Vertex; gl_PointSize = 3.0; }",
                            "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }");
    GLState gl;
    gl.vertex_program_point_size = true;
    Framebuffer fb(16, 16, true);
    // Window centres (4.5, 4.5) and (10, 10) (a pixel corner).
    VertexAttrib pos = positions({4.5f / 8 - 1, 4.5f / 8 - 1, 0, 1, 10.0f / 8 - 1, 10.0f / 8 - 1, 0, 1});
    auto stats = draw(sized, gl, fb, Primitive::Points, {pos}, 2);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 18u);
    CHECK(fb.pixel(3, 3).a == 1.0f);
    CHECK(fb.pixel(5, 5).a == 1.0f);
    CHECK(fb.pixel(6, 5).a == 0.0f);
    // gl_PointCoord without point sprites is undefined: Mesa's s right, t up.
    CHECK(fb.pixel(3, 3).r == Approx(1.0f / 6.0f));
    CHECK(fb.pixel(3, 3).g == Approx(1.0f / 6.0f));
    CHECK(fb.pixel(9, 9).a == 1.0f);  // centre 10: pixels floor(10 - 1.5 + 0.5) = 9 .. 11
    CHECK(fb.pixel(11, 11).a == 1.0f);
    CHECK(fb.pixel(8, 8).a == 0.0f);
    Program plain = compile("void main() { gl_Position = gl_Vertex; }", api_test::kPassFs);
    Framebuffer lines(16, 16);
    stats = draw(plain, gl, lines, Primitive::Lines,
                 {positions({2.5f / 8 - 1, 3.5f / 8 - 1, 0, 1, 10.5f / 8 - 1, 3.5f / 8 - 1, 0, 1})}, 2);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 8u);
    for (int x = 0; x < 16; ++x) CHECK(lines.pixel(x, 3).a == ((x >= 2 && x < 10) ? 1.0f : 0.0f));
    Framebuffer loop(16, 16);
    stats = draw(plain, gl, loop, Primitive::LineLoop,
                 {positions({-0.5f, -0.5f, 0, 1, 0.5f, -0.5f, 0, 1, 0.5f, 0.5f, 0, 1, -0.5f, 0.5f, 0, 1})}, 4);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 32u);  // four sides of 8 pixels (the corner (4,4) twice)
}

TEST_CASE("discarded fragments are not written", "[api][draw]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; }",
                        "void main() { if (gl_FragCoord.x < 4.0) discard; gl_FragColor = vec4(1.0); }");
    GLState gl;
    gl.depth_test = true;
    Framebuffer fb(8, 8);
    auto stats = draw(p, gl, fb, Primitive::TriangleStrip,
                      {positions({-1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1})}, 4);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_shaded == 64u);
    CHECK(stats->fragments_written == 32u);
    CHECK(fb.pixel(3, 0) == glm::vec4(0.0f));
    CHECK(fb.depth[3] == 1.0f);
    CHECK(fb.pixel(4, 0) == glm::vec4(1.0f));
}

TEST_CASE("the lecture's quad covers as many pixels as llvmpipe", "[api][draw][lecture]") {
    // scenes/quad.toml: gluPerspective(45, 1, 1, 100), gluLookAt(0,0,5, 0,0,0, 0,1,0),
    // the quad (-1,-1)..(1,1) at z = 0 covers 61504 pixels at 512x512.
    Program p = compile("void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }",
                        "void main() { gl_FragColor = gl_Color; }");
    GLState gl;
    gl.projection = glm::perspective(glm::radians(45.0f), 1.0f, 1.0f, 100.0f);
    gl.modelview = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    gl.depth_test = true;
    Framebuffer fb(512, 512);
    fb.clear_color({0, 0, 0, 1});
    VertexAttrib pos{"gl_Vertex", 3, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}};
    VertexAttrib col{"gl_Color", 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0}};
    auto stats = draw(p, gl, fb, Primitive::Quads, {pos, col}, 4);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 61504u);
    // The 0-2 diagonal (red to blue) is magenta-ish in the middle.
    glm::vec4 mid = fb.pixel(256, 256);
    CHECK(mid.r == Approx(0.5f).margin(0.02f));
    CHECK(mid.g == Approx(0.0f).margin(0.02f));
    CHECK(mid.b == Approx(0.5f).margin(0.02f));
}

TEST_CASE("results do not depend on how fragments are batched", "[api][draw]") {
    // The same mesh drawn in one call and triangle by triangle fills the
    // shader batches differently; the images must be identical.
    Program p = compile(R"(
varying vec2 uv;
void main() { uv = gl_Vertex.xy * 3.0; gl_Position = gl_Vertex; }
)", R"(
varying vec2 uv;
void main() {
    float d = dFdx(uv.x) + dFdy(uv.y);
    gl_FragColor = vec4(fract(uv), d * 10.0, 1.0);
}
)");
    GLState gl;
    VertexAttrib pos{"gl_Vertex", 2, {-0.9f, -0.8f, 0.7f, -0.95f, 0.1f, 0.9f, 0.95f, 0.6f, -0.7f, 0.3f, 0.2f, -0.1f}};
    std::vector<uint32_t> idx{0, 1, 5, 1, 3, 5, 3, 2, 5, 2, 4, 5, 4, 0, 5};
    Framebuffer all(48, 40, true), one_by_one(48, 40, true);
    REQUIRE(draw(p, gl, all, Primitive::Triangles, {pos}, 6, idx).ok());
    for (size_t t = 0; t < idx.size(); t += 3)
        REQUIRE(draw(p, gl, one_by_one, Primitive::Triangles, {pos}, 6, std::span(idx).subspan(t, 3)).ok());
    CHECK(std::ranges::equal(all.color_data<float>(), one_by_one.color_data<float>()));
    CHECK(count_written(all, glm::vec4(0.0f)) > 500);
}

TEST_CASE("a huge triangle is clipped to the guard band and covers the screen once", "[api][draw]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; }", api_test::kPassFs);
    GLState gl;
    Framebuffer fb(20, 20);
    auto stats = draw(p, gl, fb, Primitive::Triangles,
                      {positions({-1e7f, -1e7f, 0, 1, 3e7f, -1e7f, 0, 1, -1e7f, 3e7f, 0, 1})}, 3);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 400u);
    // NaN and infinite positions are dropped, not drawn or crashed on.
    stats = draw(p, gl, fb, Primitive::Triangles,
                 {positions({NAN, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, INFINITY, 0, 0, 1, 1, 1, 0, 1, 0, 1, 0, 0})}, 6);
    REQUIRE(stats.ok());
    CHECK(stats->fragments_written == 0u);
}

TEST_CASE("per-fragment state through the API: draw buffers, stencil, scissor", "[api][draw][fragment]") {
    const char* vs = "void main() { gl_Position = gl_Vertex; }\n";
    const char* fs = "void main() { gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0); gl_FragData[1] = vec4(0.0, 1.0, 0.0, 1.0); }\n";
    Program p = compile(vs, fs);
    VertexAttrib quad = positions({-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1});
    GLState gl;
    gl.draw_buffers = 2;
    Framebuffer one(8, 8);
    // More draw buffers than the framebuffer has: an error, not a write past it.
    auto refused = draw(p, gl, one, Primitive::Quads, {quad}, 4);
    REQUIRE_FALSE(refused);
    CHECK_THAT(refused.error().str(), Catch::Contains("glDrawBuffers names 2 colour buffers; the framebuffer has 1"));
    Framebuffer fb(8, 8, false, 2);
    gl.scissor_test = true;
    gl.scissor_box = {2, 2, 4, 3};
    gl.stencil_test = true;
    gl.stencil[0].depth_pass = StencilOp::Incr;
    REQUIRE(draw(p, gl, fb, ClearValues{glm::vec4(0.0f), 1.0f, 5}, Primitive::Quads, {quad}, 4));
    CHECK(fb.pixel(3, 3, 0) == glm::vec4(1, 0, 0, 1));
    CHECK(fb.pixel(3, 3, 1) == glm::vec4(0, 1, 0, 1));
    CHECK(fb.pixel(1, 3, 1) == glm::vec4(0.0f));  // outside the scissor box
    CHECK(fb.pixel(3, 5, 0) == glm::vec4(0.0f));  // y = 5 is past 2 + 3
    CHECK(fb.stencil[3 * 8 + 3] == 6);
    CHECK(fb.stencil[0] == 5);
    CHECK(count_written(fb, glm::vec4(0.0f)) == 12);
}
