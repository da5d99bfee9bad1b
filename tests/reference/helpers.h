// Shared by the reference tests: render one scene with glslrun and with Mesa
// in this process, compare, and on failure (or with
// GLSLRUN_SAVE_REFERENCE_IMAGES set) leave both images and the diff under
// <build>/reference-failures/.
#pragma once
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/glref/gl_render.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

namespace reference {

using namespace glslrun;

// Mesa reads GALLIUM_DRIVER once per process; every test here uses llvmpipe.
inline constexpr const char* kDriver = "llvmpipe";
// Issue #3's rule: <= 1/255 per channel on >= 99.9% of the covered pixels.
inline constexpr int kTolerance = 1;
inline constexpr double kMinFractionWithin = 0.999;

struct Inputs {
    std::vector<ShaderSource> vertex, fragment;
    scene::Scene scene;
};

inline Result<scene::Image> render_glslrun(const Inputs& in) {
    auto program = Program::compile(in.vertex, in.fragment);
    if (!program) return program.error();
    Framebuffer fb(in.scene.width, in.scene.height);
    auto stats = scene::render_scene(*program, in.scene, fb);
    if (!stats) return stats.error();
    return scene::read_framebuffer(fb);
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

// Renders `in` both ways and checks issue #3's rule; prints the statistics.
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
    scene::CompareOptions options;
    options.tolerance = kTolerance;
    options.min_fraction_within = kMinFractionWithin;
    options.clear_color = scene::to_rgba8(in.scene.clear_color);
    auto stats = scene::compare_images(mesa->image, *ours, options);
    REQUIRE(stats);
    std::printf("reference %-34s %s\n", name.c_str(), stats->summary().c_str());
    INFO(stats->summary());
    // A blank pair of images would pass vacuously.
    CHECK(stats->covered >= stats->pixels / 100);
    // GLSLRUN_SAVE_REFERENCE_IMAGES=1 keeps the images of passing cases too, to look at.
    bool keep = stats->passed && std::getenv("GLSLRUN_SAVE_REFERENCE_IMAGES");
    std::string saved = stats->passed && !keep ? std::string() : save_failure(name, mesa->image, *ours);
    INFO("images:" << saved);
    CHECK(stats->passed);
}

}  // namespace reference
