// The API's arguments as an attacker passes them: enums cast from ints past
// their last value, counts past every limit, objects moved from. Each comes
// back as an Error value (never a throw, a crash or memory written out of
// bounds).
#include <array>
#include <chrono>
#include <cstring>
#include <filesystem>

#include <unistd.h>

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

// The budgets of a draw as a whole: a loop just under the per-batch caps,
// over many batches, used to run for tens of minutes.
TEST_CASE("arguments: the instruction budget of a draw counts all its batches and threads together",
          "[api][arguments][budget]") {
    Program p = compile(kVs, "uniform int n; void main() { float s = 0.0;"
                             " for (int i = 0; i < n; ++i) s += float(i) * 0.5; gl_FragColor = vec4(s); }\n");
    REQUIRE(p.set_uniform("n", std::array{1000}).ok());
    Framebuffer fb(64, 64);
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        p.exec.backend = backend;
        std::vector<uint64_t> totals;
        for (unsigned threads : {1u, 2u, 5u}) {
            INFO(backend_name(backend) << ", " << threads << " threads");
            p.exec.threads = threads;
            p.exec.max_draw_instructions = ExecOptions{}.max_draw_instructions;
            auto st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
            REQUIRE(st.ok());
            CHECK(st->instructions > 100u * 1000);  // every batch's iterations, well past one batch's
            totals.push_back(st->instructions);
            // One instruction short of the total fails, exactly the total passes: whatever the threads.
            p.exec.max_draw_instructions = st->instructions - 1;
            auto over = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
            REQUIRE_FALSE(over.ok());
            CHECK_THAT(over.error().str(), Catch::Contains("the draw executed more than"));
            p.exec.max_draw_instructions = st->instructions;
            CHECK(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
        }
        CHECK(totals[0] == totals[1]);
        CHECK(totals[0] == totals[2]);
        p.exec.max_draw_instructions = 100000;
        CHECK_THAT(run_fragments(p, {}, 64 * 64).error().str(), Catch::Contains("the draw executed more than"));
    }
}

TEST_CASE("arguments: a deadline stops a long draw with an error, on both backends", "[api][arguments][budget]") {
    Program p = compile(kVs, "uniform int n; void main() { float s = 0.0;"
                             " for (int i = 0; i < n; ++i) s += sin(float(i)); gl_FragColor = vec4(s); }\n");
    REQUIRE(p.set_uniform("n", std::array{4000000}).ok());  // under the loop cap: minutes at 512x512
    Framebuffer fb(512, 512);
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO(backend_name(backend));
        p.exec.backend = backend;
        p.exec.max_draw_instructions = UINT64_MAX;
        p.exec.set_time_limit(0.3);
        auto start = std::chrono::steady_clock::now();
        auto st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        REQUIRE_FALSE(st.ok());
        CHECK_THAT(st.error().str(), Catch::Contains("the time limit ran out"));
        CHECK(seconds < 5);  // 0.3 s and the polls' latency, with room for a loaded machine
        // The default budget alone ends it too, in about a minute rather than hours; not run here.
    }
    ExecOptions none;
    none.set_time_limit(0);
    CHECK(none.deadline == std::chrono::steady_clock::time_point::max());
    none.set_time_limit(1e300);
    CHECK(none.deadline == std::chrono::steady_clock::time_point::max());
}

TEST_CASE("arguments: a path with a NUL byte is an error, never a shorter path", "[api][arguments]") {
    Framebuffer fb(2, 2);
    const std::string dir = std::filesystem::temp_directory_path() / ("glslrun_nul_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string cut = dir + "/a";
    auto written = write_png(fb, cut + std::string("\0.png", 5));
    REQUIRE_FALSE(written.ok());
    CHECK_THAT(written.error().str(), Catch::Contains("holds a NUL byte"));
    CHECK_FALSE(std::filesystem::exists(cut));  // fopen stopped at the NUL and wrote `a`
    std::filesystem::remove_all(dir);
}
