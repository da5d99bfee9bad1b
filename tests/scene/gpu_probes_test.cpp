// Precision::Fast's texture filtering against NVIDIA's driver: the probes of
// tools/gpu_probes rendered by glslrun in Fast equal the GPU's images of them
// (tests/scene/data/gpu/, NVIDIA 580.159 on an H200, tools/gpu_probes/run_gpu.sh)
// byte for byte, on both backends and two threads. What the probes showed
// and Fast does not model is left out by name: lod.frag's band 2 (rho for a
// derivative with both s and t along one screen axis at 45 degrees, where the
// GPU's length differs from max + 11/32 min in the last table step), the
// quads of lodrand.frag's right half that differ in that step too, and the
// 1x1 levels of mipgen.frag (their pixel's derivatives cross levels). The
// last case holds Fast's whole image of the lecture's textured teapot to the
// GPU's (scenes/textured.toml).
#include <algorithm>
#include <cstdlib>
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

struct Job {
    std::string vert, frag, scene, gpu_image;  // paths
};

Job probe_job(const std::string& probe) {
    return {kProbes + "probe.vert", kProbes + probe + ".frag", kProbes + probe + ".toml",
            kRoot + "/tests/scene/data/gpu/" + probe + ".png"};
}

// Pixels (x, y from the top) where the render differs from the GPU's image,
// with their largest channel difference.
struct Differing {
    int x, y, max;
};

std::vector<Differing> differing_pixels(const Job& job, Backend backend, Precision precision) {
    auto p = Program::compile({shader(job.vert)}, {shader(job.frag)});
    REQUIRE(p);
    p->exec.backend = backend;
    p->exec.precision = precision;
    p->exec.threads = 2;
    auto scene = scene::load_scene(job.scene);
    REQUIRE(scene);
    auto programs = scene::ScenePrograms::compile(*p, *scene);
    REQUIRE(programs);
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    REQUIRE(scene::render_scene(*programs, *scene, fb));
    auto gpu = scene::read_png(job.gpu_image);
    REQUIRE(gpu);
    REQUIRE(gpu->width == fb.width);
    REQUIRE(gpu->height == fb.height);
    std::vector<Differing> out;
    for (int y = 0; y < fb.height; ++y)
        for (int x = 0; x < fb.width; ++x) {
            const glm::vec4 c = fb.pixel(x, fb.height - 1 - y);
            const uint8_t* g = gpu->pixel(x, y);
            int max = 0;
            for (int k = 0; k < 4; ++k) max = std::max(max, std::abs(int(c[k] * 255.0f + 0.5f) - int(g[k])));
            if (max) out.push_back({x, y, max});
        }
    return out;
}

std::vector<std::pair<int, int>> differing(const std::string& probe, Backend backend, Precision precision) {
    std::vector<std::pair<int, int>> out;
    for (const Differing& d : differing_pixels(probe_job(probe), backend, precision)) out.emplace_back(d.x, d.y);
    return out;
}

}  // namespace

TEST_CASE("Fast filters textures as NVIDIA's driver: the GPU probes' images", "[scene][gpu]") {
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << int(backend));
        // Bilinear weights, 16-bit blends, NEAREST ties, wraps: every pixel.
        CHECK(differing("texfilter", backend, Precision::Fast).empty());
        // The mipmap blend of 1D and cube-map textures at explicit lambdas: every pixel
        // (blending each level's 16-bit result, 13% and 25% of them).
        CHECK(differing("trilod", backend, Precision::Fast).empty());
        // Biased implicit lookups, with and without the texture object's bias: every pixel
        // (the biases truncated toward -infinity, 84% and 78% of them).
        CHECK(differing("tribias", backend, Precision::Fast).empty());
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
        // A 3D texture's rho (max + 11/32 mid + 1/4 min lengths, the screen's diagonals):
        // every pixel (the exact lengths' rho, 519,508 of 524,288 pixels differ).
        CHECK(differing("lod3d", backend, Precision::Fast).empty());
        // 3D LINEAR's eight weights (two planes split as two mipmap levels): every pixel.
        CHECK(differing("tex3dw", backend, Precision::Fast).empty());
        // RGBA8 blending, SRC_ALPHA over ONE_MINUS_SRC_ALPHA: every pixel (storing the
        // result by the GPU's truncating rule, not to nearest, 3% of the channels one low).
        CHECK(differing("blendover", backend, Precision::Fast).empty());
        // Mipmap generation: every texel of the levels down to 2x2.
        for (auto [x, y] : differing("mipgen", backend, Precision::Fast)) {
            INFO("mipgen.frag pixel " << x << ", " << y << " from the top");
            CHECK(((x == 126 && y == 127) || (x == 62 && y == 63)));
        }
    }
    // Precise keeps exact weights: the GPU's probe is not its image.
    CHECK(differing("texfilter", Backend::Interp, Precision::Precise).size() > 100000);
}

// The lecture's textured teapot (scenes/textured.toml, 44,712 covered
// pixels) against the GPU's image of it: Fast interpolates over the triangle
// snapped to the subpixel grid, as NVIDIA's driver does (from the unsnapped
// positions, as llvmpipe, 1,078 pixels differ), and blends two mipmap levels
// as one sum of eight weighted texels (blending each level's 16-bit result,
// 690 differ); what differs is lambda where the GPU's varies within a quad
// (docs/precision.md), never by more than 1/255.
TEST_CASE("Fast interpolates and filters as NVIDIA's driver: the textured teapot", "[scene][gpu]") {
    const Job job{kRoot + "/shaders/textured_pix.vert", kRoot + "/shaders/textured_pix.frag",
                  kRoot + "/scenes/textured.toml", kRoot + "/tests/scene/data/gpu/textured_pix.png"};
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << int(backend));
        const std::vector<Differing> fast = differing_pixels(job, backend, Precision::Fast);
        CHECK(fast.size() <= 271);
        for (const Differing& d : fast) CHECK(d.max == 1);
    }
    CHECK(differing_pixels(job, Backend::Interp, Precision::Precise).size() > 8000);
}

// Multiply-add contraction (ir/contract.cpp) against the GPU's images of
// tools/gpu_probes/fma.frag, fma2.frag (bands of 32 rows, each one shape of
// multiply-add) and mandel.frag (mandelbrot's loop on exact points). The
// bands left out are the GPU compiler's algebra that Fast does not model
// (docs/precision.md, "The GPU's multiply-add contraction"): fma.frag's band
// 3 and fma2.frag's band 2 ((p - 1) - m reassociated), fma2.frag's bands 3
// ((p*0.5)*2 folded), 6 to 9 (the common factor 2 or 1/2 taken out) and 13
// (-(a*b) + P).
TEST_CASE("Fast contracts multiply-adds as NVIDIA's compiler: the GPU probes' images", "[scene][gpu]") {
    auto band = [](int y) { return (511 - y) / 32; };
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << int(backend));
        for (auto [x, y] : differing("fma", backend, Precision::Fast)) {
            INFO("fma.frag pixel " << x << ", " << y << " from the top");
            CHECK(band(y) == 3);
        }
        for (auto [x, y] : differing("fma2", backend, Precision::Fast)) {
            INFO("fma2.frag pixel " << x << ", " << y << " from the top");
            CHECK((band(y) == 2 || band(y) == 3 || (band(y) >= 6 && band(y) <= 9) || band(y) == 13));
        }
        CHECK(differing("mandel", backend, Precision::Fast).empty());  // 19,542 of 131,072 pixels unfused
    }
    // Precise rounds every product: most bands of fma.frag are not its image.
    CHECK(differing("fma", Backend::Interp, Precision::Precise).size() > 40000);
}
