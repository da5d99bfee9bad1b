// draw() keeps its working memory in the Program between draws
// (raster/scratch.h). Nothing of one draw may reach the next: a sequence of
// draws of different sizes, primitive types, index lists, viewports and
// thread counts on one Program gives, draw for draw, the images of the same
// draws on freshly compiled Programs.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

using namespace glslrun;

namespace {

Program color_program() {
    auto p = Program::compile(
        {{"vs", "void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; gl_PointSize = 5.0; }"}},
        {{"fs", "void main() { gl_FragColor = gl_Color; }"}});
    if (!p) FAIL(p.error().str());
    return std::move(*p);
}

struct Mesh {
    std::vector<VertexAttrib> attribs{{"gl_Vertex", 4, {}}, {"gl_Color", 4, {}}};
    uint32_t count = 0;
};

// `n` vertices: clusters of three close together (small triangles) spread
// over the view, some crossing the near plane, with random colours.
Mesh random_mesh(unsigned seed, uint32_t n, float size) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> centre(-1.1f, 1.1f), offset(-size, size), depth(-1.2f, 1.2f),
        unit(0.0f, 1.0f);
    Mesh m;
    float cx = 0, cy = 0, cz = 0;
    for (uint32_t v = 0; v < n; ++v) {
        if (v % 3 == 0) cx = centre(rng), cy = centre(rng), cz = depth(rng);
        m.attribs[0].data.insert(m.attribs[0].data.end(), {cx + offset(rng), cy + offset(rng), cz, 1.0f});
        m.attribs[1].data.insert(m.attribs[1].data.end(), {unit(rng), unit(rng), unit(rng), 1.0f});
    }
    m.count = n;
    return m;
}

struct Step {
    const Mesh* mesh;
    Primitive prim;
    std::vector<uint32_t> indices;
    unsigned threads;
    int viewport_width;  // 0: the whole framebuffer
};

Framebuffer run(Program& p, const Step& s) {
    Framebuffer fb(320, 200);
    fb.clear_color({0.0f, 0.0f, 0.2f, 1.0f});
    fb.clear_depth(1.0f);
    GLState gl;
    gl.depth_test = true;
    gl.vertex_program_point_size = true;  // the shader's gl_PointSize = 5
    if (s.viewport_width) gl.viewport = {10, 5, s.viewport_width, 150};
    p.exec.threads = s.threads;
    auto st = draw(p, gl, fb, s.prim, s.mesh->attribs, s.mesh->count, s.indices);
    REQUIRE(st.ok());
    return fb;
}

template <class T>
bool same_bits(std::span<const T> a, std::span<const T> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

}  // namespace

TEST_CASE("a Program's kept working memory does not change its later draws", "[raster][reuse]") {
    const Mesh big = random_mesh(3, 3 * 40000, 0.03f);  // 40,000 triangles: several setup jobs
    const Mesh small = random_mesh(4, 3 * 50, 0.3f);
    std::vector<uint32_t> some;  // every other triangle of `big`, backwards
    for (uint32_t t = 40000; t-- > 0;)
        if (t % 2 == 0) some.insert(some.end(), {3 * t + 2, 3 * t + 1, 3 * t});
    const std::vector<Step> steps{
        {&big, Primitive::Triangles, {}, 2, 0},   {&small, Primitive::Triangles, {}, 1, 0},
        {&small, Primitive::Points, {}, 1, 0},    {&big, Primitive::Lines, {}, 3, 0},
        {&big, Primitive::Triangles, some, 2, 200}, {&small, Primitive::TriangleStrip, {}, 1, 120},
        {&big, Primitive::Triangles, {}, 1, 0},
    };
    Program reused = color_program();
    for (size_t i = 0; i < steps.size(); ++i) {
        INFO("step " << i);
        Framebuffer after_others = run(reused, steps[i]);
        Program fresh = color_program();
        Framebuffer alone = run(fresh, steps[i]);
        CHECK(same_bits<uint8_t>(after_others.color_data<uint8_t>(), alone.color_data<uint8_t>()));
        CHECK(same_bits<float>(after_others.depth, alone.depth));
        // Something was drawn: the images are not both the clear colour.
        Framebuffer blank(320, 200);
        blank.clear_color({0.0f, 0.0f, 0.2f, 1.0f});
        CHECK_FALSE(same_bits<uint8_t>(alone.color_data<uint8_t>(), blank.color_data<uint8_t>()));
    }
}
