// The API's arguments as an attacker passes them: enums cast from ints past
// their last value, counts past every limit, objects moved from. Each comes
// back as an Error value (never a throw, a crash or memory written out of
// bounds).
#include <cstring>

#include "helpers.h"

using namespace glslrun;
using namespace api_test;

namespace {

const char* kVs = "void main() { gl_Position = gl_Vertex; }\n";

VertexAttrib big_triangle() { return {"gl_Vertex", 2, {-1, -1, 3, -1, -1, 3}}; }

TextureImage texel() { return TextureImage{1, 1, 1, {glm::vec4(1)}}; }

template <class E>
E bad(int value) {
    E e;
    std::memcpy(&e, &value, sizeof e);  // what a cast from an int gives, without UBSan's enum check
    return e;
}

}  // namespace

TEST_CASE("arguments: texture targets and formats outside their enums are errors", "[api][arguments]") {
    auto target = Texture::create(bad<TextureTarget>(200), {texel()});
    REQUIRE_FALSE(target.ok());
    CHECK_THAT(target.error().str(), Catch::Contains("texture target 200"));
    auto format = Texture::create(TextureTarget::Tex2D, {texel()}, bad<TextureFormat>(7));
    REQUIRE_FALSE(format.ok());
    CHECK_THAT(format.error().str(), Catch::Contains("texture format 7"));
}

TEST_CASE("arguments: ExecOptions' precision and backend outside their enums are errors", "[api][arguments]") {
    Program p = compile(kVs, kPassFs);
    Framebuffer fb(4, 4);
    p.exec.precision = bad<Precision>(9);
    CHECK_THAT(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).error().str(),
               Catch::Contains("precision 9"));
    CHECK_FALSE(run_vertices(p, {big_triangle()}, 3).ok());
    CHECK_FALSE(run_fragments(p, {}, 4).ok());
    p.exec.precision = Precision::Precise;
    p.exec.backend = bad<Backend>(-1);
    CHECK_THAT(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).error().str(),
               Catch::Contains("backend -1"));
    CHECK_FALSE(run_vertices(p, {big_triangle()}, 3).ok());
    p.exec.backend = Backend::Auto;
    CHECK(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
}

TEST_CASE("arguments: every enum of the GL state is checked before a draw", "[api][arguments]") {
    Program p = compile(kVs, kPassFs);
    Framebuffer fb(4, 4);
    auto refused = [&](const GLState& gl) {
        auto st = draw(p, gl, fb, Primitive::Triangles, {big_triangle()}, 3);
        return !st.ok() && st.error().str().find("GL_INVALID_ENUM") != std::string::npos;
    };
    GLState gl;
    gl.alpha_func = bad<CompareFunc>(8);
    CHECK(refused(gl));
    gl = GLState{};
    gl.stencil[1].depth_pass = bad<StencilOp>(8);
    CHECK(refused(gl));
    gl = GLState{};
    gl.stencil[0].func = bad<CompareFunc>(255);
    CHECK(refused(gl));
    gl = GLState{};
    gl.blend_state.dst_alpha = bad<BlendFactor>(15);  // indexed a table of 15 functions
    CHECK(refused(gl));
    gl = GLState{};
    gl.blend_state.equation_rgb = bad<BlendEquation>(5);
    CHECK(refused(gl));
    gl = GLState{};
    gl.logic_op = bad<LogicOp>(16);
    CHECK(refused(gl));
    CHECK_FALSE(run_vertices(p, {big_triangle()}, 3, &gl).ok());
    CHECK_FALSE(run_fragments(p, {}, 4, &gl).ok());
    CHECK_FALSE(refused(GLState{}));
}

TEST_CASE("arguments: the colour-buffer count outside 1..kMaxDrawBuffers is refused", "[api][arguments]") {
    for (int count : {0, -3, kMaxDrawBuffers + 1, 1 << 30}) {
        INFO(count);
        auto created = Framebuffer::create(4, 4, false, count);
        REQUIRE_FALSE(created.ok());
        CHECK_THAT(created.error().str(), Catch::Contains("colour buffers is not allowed"));
        Framebuffer constructed(4, 4, true, count);  // the constructor gives an empty framebuffer, which draw() refuses
        CHECK(constructed.width == 0);
        CHECK(constructed.color_buffers() == 0);
    }
    auto eight = Framebuffer::create(2, 2, false, kMaxDrawBuffers);
    REQUIRE(eight.ok());
    CHECK(eight->color_buffers() == kMaxDrawBuffers);
}

TEST_CASE("arguments: a moved-from Program answers every member function", "[api][arguments]") {
    Program p = compile(kVs, kPassFs);
    Program q = std::move(p);
    CHECK_FALSE(p.valid());  // NOLINT(bugprone-use-after-move): the case under test
    CHECK(p.jit_compile_seconds() == 0);
    CHECK(p.dump_ir().empty());
    CHECK(p.uniforms().empty());
    CHECK_FALSE(p.has_uniform("gl_ModelViewMatrix"));
    CHECK_FALSE(p.set_uniform("u", 1.0f).ok());
    CHECK_FALSE(p.set_uniform("u", 1).ok());
    CHECK_FALSE(p.set_uniform("u", glm::mat4(1.0f)).ok());
    Framebuffer fb(4, 4);
    CHECK_FALSE(draw(p, GLState{}, fb, ClearValues{glm::vec4(0), 1.0f, 0}, Primitive::Triangles, {big_triangle()}, 3)
                    .ok());
    Program r = std::move(q);  // a moved-from Program takes a valid one back
    q = std::move(r);
    CHECK(q.valid());
    CHECK(draw(q, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
}

TEST_CASE("arguments: counts past the batch limits are errors, not bad_alloc", "[api][arguments]") {
    Program p = compile(kVs, kPassFs);
    for (uint32_t count : {UINT32_MAX, (1u << 26) + 1}) {
        INFO(count);
        auto vertices = run_vertices(p, {}, count);
        REQUIRE_FALSE(vertices.ok());
        CHECK_THAT(vertices.error().str(), Catch::Contains("vertices are too many"));
        auto fragments = run_fragments(p, {}, count);
        REQUIRE_FALSE(fragments.ok());
        CHECK_THAT(fragments.error().str(), Catch::Contains("fragments are too many"));
        Framebuffer fb(4, 4);
        auto drawn = draw(p, GLState{}, fb, Primitive::Points, {}, count);
        REQUIRE_FALSE(drawn.ok());
        CHECK_THAT(drawn.error().str(), Catch::Contains("vertices are too many"));
    }
    // Within the count, the outputs' bytes: 2^26 vertices of gl_Position (and its copy) pass 1 GiB.
    auto bytes = run_vertices(p, {}, 1u << 26);
    REQUIRE_FALSE(bytes.ok());
    CHECK_THAT(bytes.error().str(), Catch::Contains("MiB of outputs"));
}
