// The instruction budget of a render as a whole (ExecOptions::
// max_render_instructions): every draw of every pass counts toward it, so a
// scene of many draws, each within its own budget, still ends.
#include <array>
#include <atomic>

#include <catch2/catch.hpp>

#include "glslrun/scene/render.h"
#include "parse_helpers.h"

using namespace glslrun;
using namespace scene_test;

namespace {

// Eight full-screen quads in two passes: eight draws of one loop each.
const char* kEightDraws = R"([output]
size = [32, 32]
[[objects]]
name = "a"
mesh = "quad"
[[objects]]
name = "b"
mesh = "quad"
[[passes]]
objects = ["a", "b", "a", "b"]
[[passes]]
objects = ["b", "a", "b", "a"]
)";

Program looping_program() {
    auto p = Program::compile({{"vs", "void main() { gl_Position = gl_Vertex; }\n"}},
                              {{"fs", "uniform int n; void main() { float s = 0.0;"
                                      " for (int i = 0; i < n; ++i) s += float(i); gl_FragColor = vec4(s); }\n"}});
    REQUIRE(p);
    REQUIRE(p->set_uniform("n", std::array{200}).ok());
    return std::move(*p);
}

}  // namespace

TEST_CASE("a render's draws together stop at its instruction budget, whatever the threads and backend",
          "[scene][budget]") {
    Scene scene = parse_ok(kEightDraws);
    Program p = looping_program();
    auto fb = Framebuffer::create(32, 32);
    REQUIRE(fb);
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        p.exec.backend = backend;
        p.exec.max_render_instructions = ExecOptions{}.max_render_instructions;
        p.exec.threads = 1;
        auto whole = scene::render_scene(p, scene, *fb);
        REQUIRE(whole);
        const uint64_t total = whole->instructions;
        for (unsigned threads : {1u, 3u}) {
            INFO(backend_name(backend) << ", " << threads << " threads");
            p.exec.threads = threads;
            // One short of the total fails at the last draw, with the render's message; the total passes.
            p.exec.max_draw_instructions = total;  // each draw is well within its own budget
            p.exec.max_render_instructions = total - 1;
            auto over = scene::render_scene(p, scene, *fb);
            REQUIRE_FALSE(over);
            CHECK_THAT(over.error().str(), Catch::Contains("the render executed more than " + std::to_string(total - 1) +
                                                           " instructions, its draws together"));
            CHECK(p.exec.render_instructions == nullptr);  // the render's count is gone with it
            p.exec.max_render_instructions = total;
            auto exact = scene::render_scene(p, scene, *fb);
            REQUIRE(exact);
            CHECK(exact->instructions == total);
            // Each render counts afresh: a second render of the same budget passes too.
            CHECK(scene::render_scene(p, scene, *fb));
        }
        // The draw's own budget still names the draw.
        p.exec.max_render_instructions = ExecOptions{}.max_render_instructions;
        p.exec.max_draw_instructions = total / 8 - 1;
        auto draw_over = scene::render_scene(p, scene, *fb);
        REQUIRE_FALSE(draw_over);
        CHECK_THAT(draw_over.error().str(), Catch::Contains("the draw executed more than"));
        p.exec.max_draw_instructions = ExecOptions{}.max_draw_instructions;
    }
}

TEST_CASE("a caller's render count spans several renders, as glslrun --frames counts its frames", "[scene][budget]") {
    Scene scene = parse_ok(kEightDraws);
    Program p = looping_program();
    auto fb = Framebuffer::create(32, 32);
    REQUIRE(fb);
    auto one = scene::render_scene(p, scene, *fb);
    REQUIRE(one);
    std::atomic<uint64_t> count{0};
    p.exec.render_instructions = &count;
    p.exec.max_render_instructions = 3 * one->instructions;
    for (int frame = 0; frame < 3; ++frame) REQUIRE(scene::render_scene(p, scene, *fb));
    CHECK(count.load() == 3 * one->instructions);
    auto fourth = scene::render_scene(p, scene, *fb);
    REQUIRE_FALSE(fourth);
    CHECK_THAT(fourth.error().str(), Catch::Contains("ExecOptions::max_render_instructions"));
    // The first draw of the fourth frame found nothing left and stopped at its first share.
    CHECK(count.load() < 3 * one->instructions + one->instructions / 8 + 70000);
    p.exec.render_instructions = nullptr;
}
