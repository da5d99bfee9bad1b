// Issue #17's reproducers through the library: every misuse comes back as an
// Error value, never as a throw, a crash or a hang.
#include <climits>
#include <thread>

#include "helpers.h"

using namespace glslrun;
using namespace api_test;

namespace {

const char* kVs = "void main() { gl_Position = gl_Vertex; }\n";

VertexAttrib big_triangle() { return {"gl_Vertex", 2, {-1, -1, 3, -1, -1, 3}}; }

}  // namespace

TEST_CASE("hardening: a framebuffer beyond the limits is an Error, not bad_alloc", "[api][hardening]") {
    auto huge = Framebuffer::create(100000, 100000);
    REQUIRE_FALSE(huge.ok());
    CHECK_THAT(huge.error().str(), Catch::Contains("100000x100000 framebuffer is not allowed"));
    CHECK_FALSE(Framebuffer::create(16384, 16384).ok());  // each side allowed, 256M pixels not
    CHECK_FALSE(Framebuffer::create(0, 4).ok());
    CHECK(Framebuffer::create(16384, 4).ok());
    Framebuffer refused(100000, 100000);  // the constructor allocates nothing; draw() refuses it
    CHECK(refused.width == 0);
    CHECK(refused.color_data<uint8_t>().empty());
    Program p = compile(kVs, kPassFs);
    auto st = draw(p, GLState{}, refused, Primitive::Triangles, {big_triangle()}, 3);
    REQUIRE_FALSE(st.ok());
    CHECK_THAT(st.error().str(), Catch::Contains("framebuffer is empty"));
}

TEST_CASE("hardening: out-of-range enums and a negative viewport are errors; x + width past INT_MAX is clipped",
          "[api][hardening]") {
    Program p = compile(kVs, kPassFs);
    Framebuffer fb(8, 8);
    GLState gl;
    CHECK_FALSE(draw(p, gl, fb, Primitive(77), {big_triangle()}, 3).ok());
    gl.depth_func = CompareFunc(200);
    CHECK_FALSE(draw(p, gl, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
    gl = GLState{};
    gl.viewport = {0, 0, -8, 8};
    CHECK_THAT(draw(p, gl, fb, Primitive::Triangles, {big_triangle()}, 3).error().str(),
               Catch::Contains("must not be negative"));
    gl.viewport = {INT_MAX - 4, INT_MAX - 4, INT_MAX, INT_MAX};  // UBSan: signed overflow before the fix
    auto st = draw(p, gl, fb, Primitive::Triangles, {big_triangle()}, 3);
    REQUIRE(st.ok());
    CHECK(st->fragments_written == 0);
    auto tex = Texture::create(TextureTarget::Tex2D, {TextureImage{1, 1, 1, {glm::vec4(1)}}});
    REQUIRE(tex.ok());
    tex->sampler.wrap_s = TextureWrap(9);
    gl = GLState{};
    REQUIRE(gl.bind_texture(0, std::make_shared<Texture>(std::move(*tex))).ok());
    CHECK_THAT(draw(p, gl, fb, Primitive::Triangles, {big_triangle()}, 3).error().str(),
               Catch::Contains("GL_INVALID_ENUM"));
}

TEST_CASE("hardening: a moved-from Program returns errors", "[api][hardening]") {
    Program p = compile(kVs, kPassFs);
    Program q = std::move(p);
    CHECK_FALSE(p.valid());  // NOLINT(bugprone-use-after-move): the case under test
    CHECK(q.valid());
    Framebuffer fb(8, 8);
    CHECK_THAT(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).error().str(),
               Catch::Contains("moved from"));
    CHECK_FALSE(p.set_uniform("u", std::array{1.0f}).ok());
    CHECK_FALSE(run_vertices(p, {big_triangle()}, 3).ok());
    CHECK_FALSE(run_fragments(p, {}, 4).ok());
    CHECK_FALSE(apply_builtin_uniforms(p, GLState{}).ok());
    CHECK_FALSE(p.has_uniform("u"));
    CHECK(p.uniforms().empty());
    CHECK(p.dump_ir().empty());
    CHECK(draw(q, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
}

TEST_CASE("hardening: a Program in use on another thread gives an Error", "[api][hardening]") {
    // The draw runs until it is cancelled, so the other thread surely meets it.
    Program p = compile(kVs, "uniform int n; void main() { float s = 0.0;"
                             " for (int i = 0; i < n; ++i) s += sin(float(i)); gl_FragColor = vec4(s); }\n");
    const std::array n{1 << 30};
    REQUIRE(p.set_uniform("n", n).ok());
    std::atomic<bool> cancel{false};
    p.exec.max_loop_iterations = p.exec.max_instructions = UINT64_MAX;
    p.exec.cancel = &cancel;
    p.exec.threads = 1;
    Framebuffer a(4, 4), b(4, 4);
    Result<DrawStats> drawn = Error("not run");
    // The draw may itself meet the main thread's set_uniform below (the program is in use then too):
    // it tries again until it runs.
    std::thread t([&] {
        do drawn = draw(p, GLState{}, a, Primitive::Triangles, {big_triangle()}, 3);
        while (!drawn.ok() && drawn.error().str().find("in use on another thread") != std::string::npos);
    });
    Status busy = Ok{};
    auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (busy.ok() && std::chrono::steady_clock::now() < give_up) {
        busy = p.set_uniform("n", n);
        std::this_thread::yield();
    }
    auto second = draw(p, GLState{}, b, Primitive::Triangles, {big_triangle()}, 3);
    cancel = true;
    t.join();
    REQUIRE_FALSE(busy.ok());
    CHECK_THAT(busy.error().str(), Catch::Contains("in use on another thread"));
    REQUIRE_FALSE(second.ok());
    CHECK_THAT(second.error().str(), Catch::Contains("in use on another thread"));
    REQUIRE_FALSE(drawn.ok());
    CHECK_THAT(drawn.error().str(), Catch::Contains("cancelled"));
    CHECK(p.set_uniform("n", std::array{1}).ok());  // free again afterwards
}

TEST_CASE("hardening: calls that multiply stop at the instruction budget, and the cancel flag stops a draw",
          "[api][hardening]") {
    std::string fs = "float f0(float x) { return x * 1.0001 + 0.5; }\n";
    for (int i = 1; i < 30; ++i)
        fs += "float f" + std::to_string(i) + "(float x) { return f" + std::to_string(i - 1) + "(x) + f" +
              std::to_string(i - 1) + "(x * 0.5); }\n";
    fs += "void main() { gl_FragColor = vec4(f29(gl_FragCoord.x)); }\n";
    Program p = compile(kVs, fs);
    p.exec.max_instructions = 1u << 20;
    Framebuffer fb(4, 4);
    auto st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
    REQUIRE_FALSE(st.ok());
    CHECK_THAT(st.error().str(), Catch::Contains("more than 1048576 instructions"));
    std::atomic<bool> cancel{true};
    p.exec.max_instructions = ExecOptions{}.max_instructions;
    p.exec.cancel = &cancel;
    st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
    REQUIRE_FALSE(st.ok());
    CHECK_THAT(st.error().str(), Catch::Contains("cancelled"));
}

// LLVM's compile time grows faster than linearly with a function's control
// flow (1000 loops in a row: 21 s of CPU): the JIT leaves shaders with more
// than 200 Ifs and Loops to the interpreter, which gives the same bits. Both
// stages loop, so that jit_compile_seconds() says whether the JIT took them.
TEST_CASE("hardening: the JIT leaves a shader of hundreds of loops to the interpreter", "[api][hardening]") {
    if (!jit_available()) return;
    auto loops = [](int count) {
        std::string sum = "uniform int n;\nfloat sum() {\n    float s = 0.0;\n";
        for (int i = 0; i < count; ++i) sum += "    for (int i = 0; i < n; ++i) s += 1.0;\n";
        return sum + "    return s / 1024.0;\n}\n";
    };
    for (int count : {20, 400}) {
        INFO(count << " loops");
        Program p = compile(loops(count) + "void main() { gl_Position = gl_Vertex * (1.0 + sum()); }\n",
                            loops(count) + "void main() { gl_FragColor = vec4(sum()); }\n");
        p.exec.backend = Backend::Jit;
        REQUIRE(p.set_uniform("n", std::array{1}).ok());
        Framebuffer fb(4, 4, true);
        REQUIRE(draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3).ok());
        CHECK(fb.pixel(2, 2).r == float(count) / 1024.0f);
        CHECK((p.jit_compile_seconds() > 0) == (count == 20));
    }
}

TEST_CASE("hardening: both backends stop a long loop at the instruction budget and at the cancel flag",
          "[api][hardening]") {
    Program p = compile(kVs, "uniform int n; void main() { float s = 0.0;"
                             " for (int i = 0; i < n; ++i) s += float(i) * 0.5; gl_FragColor = vec4(s); }\n");
    REQUIRE(p.set_uniform("n", std::array{1 << 30}).ok());
    p.exec.max_loop_iterations = UINT64_MAX;
    p.exec.threads = 1;
    Framebuffer fb(4, 4);
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO(backend_name(backend));
        p.exec.backend = backend;
        p.exec.max_instructions = 1u << 20;
        p.exec.cancel = nullptr;
        auto st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
        REQUIRE_FALSE(st.ok());
        CHECK_THAT(st.error().str(), Catch::Contains("more than 1048576 instructions"));
        std::atomic<bool> cancel{true};
        p.exec.max_instructions = UINT64_MAX;
        p.exec.cancel = &cancel;
        st = draw(p, GLState{}, fb, Primitive::Triangles, {big_triangle()}, 3);
        REQUIRE_FALSE(st.ok());
        CHECK_THAT(st.error().str(), Catch::Contains("cancelled"));
    }
    CHECK((p.jit_compile_seconds() > 0) == jit_available());  // the JIT's code ran, not the interpreter's
}
