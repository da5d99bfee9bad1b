// Shared by the reference tests: render one scene with glslrun and with Mesa
// in this process, compare, and on failure (or with
// GLSLRUN_SAVE_REFERENCE_IMAGES set) leave both images and the diff under
// <build>/reference-failures/.
#pragma once
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tools/glref/gl_render.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

namespace reference {

using namespace glslrun;

// A shader file as a source named by its path.
inline Result<ShaderSource> read_shader(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error("cannot read '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return ShaderSource{path, text.str()};
}

// Mesa reads GALLIUM_DRIVER once per process; every test here uses llvmpipe.
inline constexpr const char* kDriver = "llvmpipe";
// Issue #3's rule: <= 1/255 per channel on >= 99.9% of the covered pixels.
inline constexpr int kTolerance = 1;
inline constexpr double kMinFractionWithin = 0.999;

struct Inputs {
    std::vector<ShaderSource> vertex, fragment;
    scene::Scene scene;
};

// A vertex shader for texture scenes: gl_TexCoord[0] through the texture matrix.
inline constexpr const char* kTextureMatrixVertex = R"(
void main() {
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
)";

// A scene given as text with its program's two sources, named after `name`.
inline Inputs scene_inputs(const std::string& name, const std::string& toml, const char* vertex,
                           const char* fragment) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    return {{{name + ".vert", vertex}}, {{name + ".frag", fragment}}, std::move(*scene)};
}

// DIR/NAME.toml with its program DIR/NAME.vert and DIR/NAME.frag (the
// scene's passes may name their own).
inline Inputs scene_files(const std::string& dir, const std::string& name) {
    auto scene = scene::load_scene(dir + name + ".toml");
    if (!scene) FAIL(scene.error().str());
    auto vs = read_shader(dir + name + ".vert");
    auto fs = read_shader(dir + name + ".frag");
    if (!vs) FAIL(vs.error().str());
    if (!fs) FAIL(fs.error().str());
    return {{*vs}, {*fs}, std::move(*scene)};
}

// One image per colour buffer (draw_buffers).
inline Result<std::vector<scene::Image>> render_glslrun(const Inputs& in) {
    auto program = Program::compile(in.vertex, in.fragment);
    if (!program) return program.error();
    Framebuffer fb(in.scene.width, in.scene.height, false, scene::color_buffers(in.scene));
    auto stats = scene::render_scene(*program, in.scene, fb);
    if (!stats) return stats.error();
    std::vector<scene::Image> images;
    for (int i = 0; i < fb.color_buffers(); ++i) images.push_back(scene::read_framebuffer(fb, i));
    return images;
}

// Both images and their diff, for a person to look at; returns the paths.
inline std::string save_failure(const std::string& name, const scene::Image& mesa, const scene::Image& ours) {
    std::string dir = std::string(GLSLRUN_BINARY_DIR) + "/reference-failures";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::string stem = dir + "/" + name, written;
    auto save = [&](const scene::Image& img, const std::string& path) {
        Status st = scene::write_png(img, path);
        written += st ? " " + path : " (" + st.error().str() + ")";
    };
    save(mesa, stem + ".mesa.png");
    save(ours, stem + ".glslrun.png");
    if (auto diff = scene::diff_image(mesa, ours, kTolerance)) save(*diff, stem + ".diff.png");
    return written;
}

// Issue #3's rule on one pair of images; prints the statistics.
inline void compare_images(const std::string& name, const Inputs& in, const scene::Image& mesa,
                           const scene::Image& ours) {
    scene::CompareOptions options;
    options.tolerance = kTolerance;
    options.min_fraction_within = kMinFractionWithin;
    options.clear_color = scene::to_rgba8(in.scene.clear_color);
    auto stats = scene::compare_images(mesa, ours, options);
    REQUIRE(stats);
    std::printf("reference %-34s %s\n", name.c_str(), stats->summary().c_str());
    INFO(stats->summary());
    // A blank pair of images would pass vacuously.
    CHECK(stats->covered >= stats->pixels / 100);
    // GLSLRUN_SAVE_REFERENCE_IMAGES=1 keeps the images of passing cases too, to look at.
    bool keep = stats->passed && std::getenv("GLSLRUN_SAVE_REFERENCE_IMAGES");
    std::string saved = stats->passed && !keep ? std::string() : save_failure(name, mesa, ours);
    INFO("images:" << saved);
    CHECK(stats->passed);
}

// Renders `in` both ways and checks issue #3's rule on every colour buffer.
inline void compare(const std::string& name, const Inputs& in) {
    auto mesa = glref::render_with_mesa(kDriver, in.vertex, in.fragment, in.scene);
    if (!mesa) {
        FAIL_CHECK("Mesa (" << kDriver << ") could not render: " << mesa.error().str());
        return;
    }
    auto ours = render_glslrun(in);
    if (!ours) {
        FAIL_CHECK("glslrun could not render: " << ours.error().str());
        return;
    }
    REQUIRE(ours->size() == 1 + mesa->more_images.size());
    compare_images(name, in, mesa->image, (*ours)[0]);
    for (size_t i = 1; i < ours->size(); ++i)
        compare_images(name + "." + std::to_string(i), in, mesa->more_images[i - 1], (*ours)[i]);
}

// Colour buffer 0 of `in` rendered by glslrun in one precision mode, on one
// backend, with `threads` worker threads.
inline Result<scene::Image> render_with(const Inputs& in, Precision precision, Backend backend, unsigned threads) {
    auto program = Program::compile(in.vertex, in.fragment);
    if (!program) return program.error();
    program->exec.precision = precision;
    program->exec.backend = backend;
    program->exec.threads = threads;
    Framebuffer fb(in.scene.width, in.scene.height, false, scene::color_buffers(in.scene));
    auto stats = scene::render_scene(*program, in.scene, fb);
    if (!stats) return stats.error();
    return scene::read_framebuffer(fb, 0);
}

// The interpreter at 1 thread against the JIT and 2 threads, in `precision`:
// bit for bit. Returns the interpreter's image; a render error fails the test.
inline scene::Image check_same_everywhere(const Inputs& in, Precision precision = Precision::Precise) {
    auto base = render_with(in, precision, Backend::Interp, 1);
    if (!base) FAIL("glslrun could not render: " << base.error().str());
    for (Backend backend : {Backend::Interp, Backend::Jit})
        for (unsigned threads : {1u, 2u}) {
            if (backend == Backend::Jit && !jit_available()) continue;
            INFO((precision == Precision::Fast ? "fast, " : "precise, ")
                 << (backend == Backend::Jit ? "jit" : "interp") << ", " << threads << " threads");
            auto other = render_with(in, precision, backend, threads);
            REQUIRE(other);
            CHECK(other->rgba == base->rgba);
        }
    return *base;
}

// Issue #3's rule against Mesa in Precise and in Fast, and each mode's image
// the same bit for bit on the interpreter and the JIT, at 1 and 2 threads.
inline void compare_in_every_mode(const std::string& name, const Inputs& in) {
    auto mesa = glref::render_with_mesa(kDriver, in.vertex, in.fragment, in.scene);
    if (!mesa) {
        FAIL_CHECK("Mesa (" << kDriver << ") could not render: " << mesa.error().str());
        return;
    }
    for (Precision precision : {Precision::Precise, Precision::Fast}) {
        INFO(name);
        const scene::Image base = check_same_everywhere(in, precision);
        compare_images(name + (precision == Precision::Fast ? "-fast" : "-precise"), in, mesa->image, base);
    }
}

}  // namespace reference
