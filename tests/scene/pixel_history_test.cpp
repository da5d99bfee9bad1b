// The pixel history (debug::pixel_history): on every scene in scenes/, the
// last fragment's "after" at 20 random covered pixels is the rendered pixel,
// bit for bit (colour, depth and stencil), on both backends (and Fast's GPU
// rounding on the JIT); the JIT's
// reference render takes the fused fragment pipeline where the draw's state
// allows it, while the history's render runs the C++ per-fragment path with
// the probe.
#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "debug/debugger.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"
#include "raster/fused/pipeline.h"
#include "runtime/program_state.h"

using namespace glslrun;

namespace {

const std::string kRoot = GLSLRUN_SOURCE_DIR;

ShaderSource shader(const std::string& name) {
    std::ifstream in(kRoot + "/" + name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return {name, s.str()};
}

// Each scene with a program that draws it (bench/precision.py's pairs; the
// scenes with passes name their own shaders).
struct Case {
    const char* program;
    const char* scene;
};
constexpr Case kCases[] = {
    {"back_material", "back_material"}, {"minimal", "blur"},       {"cube_reflect", "cube_map"},
    {"dir_pix", "directional"},         {"multi_light", "multi_light"}, {"minimal", "multi_pass"},
    {"dir_vert", "nonorthogonal"},      {"pos_pix", "positional"}, {"colors", "quad"},
    {"minimal", "shadow_map"},          {"spot_pix_fixed", "spot"}, {"matamb", "teapot"},
    {"textured_pix", "textured"},       {"two_side", "two_side"},
};

Program compile(const Case& c, Backend backend, Precision precision) {
    auto p = Program::compile({shader(fmt::format("shaders/{}.vert", c.program))},
                              {shader(fmt::format("shaders/{}.frag", c.program))});
    REQUIRE(p);
    p->exec.backend = backend;
    p->exec.precision = precision;
    return std::move(*p);
}

// The scene rendered as glslrun renders it, on two threads; on the JIT with
// the fused pipeline wherever the draw state allows it (its programs count
// as warmed up: raster::fused::kPipelineAfterFragments).
Framebuffer render(Program& program, const scene::Scene& scene, Backend backend, uint64_t& fused) {
    program.exec.threads = 2;
    auto programs = scene::ScenePrograms::compile(program, scene);
    REQUIRE(programs);
    if (backend == Backend::Jit)
        for (size_t i = 0; i < programs->size(); ++i)
            state_of(programs->of_pass(i)).pipelines->count_unfused(raster::fused::kPipelineAfterFragments);
    Framebuffer fb(scene.width, scene.height, false, scene::color_buffers(scene));
    auto stats = scene::render_scene(*programs, scene, fb);
    REQUIRE(stats);
    fused += stats->fragments_fused;
    return fb;
}

}  // namespace

TEST_CASE("the pixel history's last 'after' is the rendered pixel on every scene, both backends", "[debug][history]") {
    uint64_t fused = 0;
    // Fast stores RGBA8 with the GPU's rounding (ColorRounding::Gpu): on the JIT too.
    const std::pair<Backend, Precision> kRuns[] = {
        {Backend::Interp, Precision::Precise}, {Backend::Jit, Precision::Precise}, {Backend::Jit, Precision::Fast}};
    for (auto [backend, precision] : kRuns)
        for (const Case& c : kCases) {
            INFO(c.program << " on " << c.scene << ", backend " << backend_name(backend) << ", precision "
                           << int(precision));
            auto scene = scene::load_scene(kRoot + "/scenes/" + c.scene + ".toml");
            REQUIRE(scene);
            Program program = compile(c, backend, precision);
            const Framebuffer expected = render(program, *scene, backend, fused);
            // 400 random pixels, fixed seed; the first 20 covered ones count.
            std::mt19937 random(20261128);
            std::vector<std::pair<int, int>> pixels;
            for (int i = 0; i < 400; ++i)
                pixels.emplace_back(int(random() % uint32_t(scene->width)), int(random() % uint32_t(scene->height)));
            auto debug = debug::compile_for_debugging({shader(fmt::format("shaders/{}.vert", c.program))},
                                                      {shader(fmt::format("shaders/{}.frag", c.program))},
                                                      program.exec.precision);
            REQUIRE(debug);
            Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
            auto history = debug::pixel_history(program, *debug, *scene, fb, pixels);
            REQUIRE(history);
            int checked = 0;
            for (const debug::PixelHistory& h : *history) {
                if (h.fragments.empty() || checked == 20) continue;
                ++checked;
                INFO("pixel " << h.x << "," << h.y << ", " << h.fragments.size() << " fragments");
                const debug::PixelValues& after = h.fragments.back().after;
                const size_t wy = size_t(scene->height - 1 - h.y), at = wy * size_t(scene->width) + size_t(h.x);
                REQUIRE(after.bytes);
                REQUIRE(int(after.color.size()) == expected.color_buffers());
                for (int b = 0; b < expected.color_buffers(); ++b)
                    for (size_t k = 0; k < 4; ++k)
                        CHECK(after.color[size_t(b)][k] == float(expected.color_data<uint8_t>(b)[at * 4 + k]));
                CHECK(std::bit_cast<uint32_t>(after.depth) == std::bit_cast<uint32_t>(expected.depth[at]));
                CHECK(after.stencil == expected.stencil[at]);
                // A fragment starts from what the one before it left, within a draw.
                for (size_t i = 1; i < h.fragments.size(); ++i)
                    if (h.fragments[i].draw == h.fragments[i - 1].draw)
                        CHECK(h.fragments[i].before.color == h.fragments[i - 1].after.color);
            }
            CHECK(checked == 20);
            // The history's render is the plain render's image.
            CHECK(std::ranges::equal(fb.color_data<uint8_t>(), expected.color_data<uint8_t>()));
        }
    CHECK(fused > 0);  // the JIT's renders took the fused pipeline
}
