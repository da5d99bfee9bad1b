// glslrun against Mesa on float render targets and textures (ARB_texture_float,
// ARB_color_buffer_float as Mesa exposes them in a compatibility context):
// scenes/app/half_float.toml reads back, as bytes, what a half-float target
// stores from draws, blends and clears (truncated toward zero, finite
// overflow to 65504), what glTexImage stores in a half-float texture
// (nearest even, overflow to infinity), and colours kept past [0, 1] in the
// target while the vertex colour is still clamped; scenes/programs/hdr_bloom
// draws an HDR bloom through half- and single-float targets tone-mapped onto
// the RGBA8 output. Both against Mesa in Precise and Fast, each mode's image
// the same on both backends at 1 and 2 threads.
#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const std::string kScenes = std::string(GLSLRUN_SOURCE_DIR) + "/scenes/";

}  // namespace

TEST_CASE("glslrun matches Mesa on half-float targets' stores, clears, blends and texel uploads", "[reference][float]") {
    reference::compare_in_every_mode("float-half-stores", reference::scene_files(kScenes + "app/", "half_float"));
}

TEST_CASE("glslrun matches Mesa on an HDR bloom through float render targets", "[reference][float]") {
    // The command line's program is the scene pass's; every pass names its own.
    auto scene = scene::load_scene(kScenes + "programs/hdr_bloom.toml");
    if (!scene) FAIL(scene.error().str());
    auto vs = reference::read_shader(kScenes + "programs/bloom.vert");
    auto fs = reference::read_shader(kScenes + "programs/hdr_bloom.frag");
    REQUIRE(vs);
    REQUIRE(fs);
    reference::compare_in_every_mode("float-hdr-bloom", {{*vs}, {*fs}, std::move(*scene)});
}
