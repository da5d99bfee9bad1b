// Precision::Fast's texture filtering against NVIDIA's driver: the probes of
// tools/gpu_probes rendered by glslrun in Fast equal the GPU's images of them
// (tests/scene/data/gpu/, NVIDIA 580.159 on an H200, tools/gpu_probes/run_gpu.sh)
// byte for byte, on both backends and two threads. What the probes showed
// and Fast does not model is left out by name: lod.frag's band 2 (rho for a
// derivative with both s and t along one screen axis at 45 degrees, where the
// GPU's length differs from max + 11/32 min in the last table step), the
// quads of lodrand.frag's right half that differ in that step too, and the
// 1x1 levels of mipgen.frag (their pixel's derivatives cross levels).
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

using namespace glslrun;

namespace {

const std::string kRoot = GLSLRUN_SOURCE_DIR;
const std::string kProbes = kRoot + "/tools/gpu_probes/";

ShaderSource shader(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return {path, s.str()};
}

// Pixels (x, y from the top) where the Fast render differs from the GPU's image.
std::vector<std::pair<int, int>> differing(const std::string& probe, Backend backend, Precision precision) {
    auto p = Program::compile({shader(kProbes + "probe.vert")}, {shader(kProbes + probe + ".frag")});
    REQUIRE(p);
    p->exec.backend = backend;
    p->exec.precision = precision;
    p->exec.threads = 2;
    auto scene = scene::load_scene(kProbes + probe + ".toml");
    REQUIRE(scene);
    auto programs = scene::ScenePrograms::compile(*p, *scene);
    REQUIRE(programs);
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    REQUIRE(scene::render_scene(*programs, *scene, fb));
    auto gpu = scene::read_png(kRoot + "/tests/scene/data/gpu/" + probe + ".png");
    REQUIRE(gpu);
    REQUIRE(gpu->width == fb.width);
    REQUIRE(gpu->height == fb.height);
    std::vector<std::pair<int, int>> out;
    for (int y = 0; y < fb.height; ++y)
        for (int x = 0; x < fb.width; ++x) {
            const glm::vec4 c = fb.pixel(x, fb.height - 1 - y);
            const uint8_t* g = gpu->pixel(x, y);
            for (int k = 0; k < 4; ++k)
                if (int(c[k] * 255.0f + 0.5f) != g[k]) {
                    out.emplace_back(x, y);
                    break;
                }
        }
    return out;
}

}  // namespace

TEST_CASE("Fast filters textures as NVIDIA's driver: the GPU probes' images", "[scene][gpu]") {
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << int(backend));
        // Bilinear weights, 16-bit blends, NEAREST ties, wraps: every pixel.
        CHECK(differing("texfilter", backend, Precision::Fast).empty());
        // The level of detail: all bands but band 2 (gl_FragCoord.y in [128, 192)).
        for (auto [x, y] : differing("lod", backend, Precision::Fast)) {
            INFO("lod.frag pixel " << x << ", " << y << " from the top");
            CHECK((511 - y) / 64 == 2);
        }
        // rho for every sign and ratio of the four derivatives: every pixel of
        // lodrand.frag's left half (derivatives in half texels); the right
        // half's (steps of 11/16 texel) differ in the last table step at
        // some quads, and the ratchet keeps them from growing.
        size_t right = 0;
        for (auto [x, y] : differing("lodrand", backend, Precision::Fast)) {
            INFO("lodrand.frag pixel " << x << ", " << y << " from the top");
            CHECK(x >= 512);
            right += x >= 512;
        }
        CHECK(right <= 17056);
        // Mipmap generation: every texel of the levels down to 2x2.
        for (auto [x, y] : differing("mipgen", backend, Precision::Fast)) {
            INFO("mipgen.frag pixel " << x << ", " << y << " from the top");
            CHECK(((x == 126 && y == 127) || (x == 62 && y == 63)));
        }
    }
    // Precise keeps exact weights: the GPU's probe is not its image.
    CHECK(differing("texfilter", Backend::Interp, Precision::Precise).size() > 100000);
}
