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
#include <iterator>

#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const std::string kScenes = std::string(GLSLRUN_SOURCE_DIR) + "/scenes/";

// One program for both passes, picked by a pass uniform: colours past
// [0, 1] into an RGBA32F target under an alpha test that compares the
// unclamped alpha (1.5 fails EQUAL 1.0, which its clamped value would pass),
// then read back onto the output.
const char* kAlphaVertex = R"(
void main() {
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_Position = gl_Vertex;
}
)";
const char* kAlphaFragment = R"(
uniform float mode;
uniform sampler2D image;
void main() {
    if (mode < 0.5) {
        float a = gl_FragCoord.x < 16.0 ? 1.5 : 1.0;
        gl_FragColor = vec4(gl_FragCoord.y < 16.0 ? 3.0 : -2.0, 0.5, 0.5, a);
    } else {
        vec4 t = texture2D(image, gl_TexCoord[0].st);
        gl_FragColor = vec4(t.r * 0.25 + 0.5, t.a, 0.0, 1.0);
    }
}
)";
const char* kAlphaScene = R"(
[output]
size = [32, 32]
clear_color = [0, 0, 0, 1]
[render_targets.wide]
size = [32, 32]
internal_format = "rgba32f"
[textures.0]
render_target = "wide"
min_filter = "nearest"
mag_filter = "nearest"
[[objects]]
name = "screen"
mesh = "quad"
[[passes]]
target = "wide"
objects = ["screen"]
clear = { color = [0.25, 0.25, 0.25, 0.25] }
uniforms = { mode = 0.0, image = 1 }
state = { alpha_test = true, alpha_test_func = "equal", alpha_test_ref = 1.0 }
[[passes]]
objects = ["screen"]
uniforms = { mode = 1.0, image = 0 }
)";

// Every float format of fewer channels, one 8-pixel column each, sampled
// from a 2x2 texture of (2.5, 0.6, 0.9, 0.45): what each keeps and what GL
// returns for the rest (glref uploads each in its real format).
const char* const kChannelFormats[] = {"rgb16f", "rgb32f", "rg16f", "rg32f", "r16f", "r32f", "luminance16f",
                                       "luminance32f", "luminance_alpha16f", "luminance_alpha32f", "intensity16f",
                                       "intensity32f", "alpha16f", "alpha32f"};

reference::Inputs channel_formats_inputs() {
    const size_t n = std::size(kChannelFormats);
    std::string scene = fmt::format("[output]\nsize = [{}, 16]\nclear_color = [0, 0, 0, 0]\n[[objects]]\n"
                                    "mesh = \"quad\"\n[uniforms]\n", 8 * n);
    std::string fragment = "uniform sampler2D t0";
    std::string lookups;
    for (size_t i = 0; i < n; ++i) {
        scene += fmt::format("t{} = {}\n", i, i);
        if (i) fragment += fmt::format(", t{}", i);
        lookups += fmt::format("    {}if (k < {}.5) t = texture2D(t{}, vec2(0.5));\n", i ? "else " : "", i, i);
    }
    for (size_t i = 0; i < n; ++i)
        scene += fmt::format("[textures.{}]\ninternal_format = \"{}\"\nmin_filter = \"nearest\"\n"
                             "solid = {{ size = [2, 2], color = [2.5, 0.6, 0.9, 0.45] }}\n", i, kChannelFormats[i]);
    fragment += ";\nvoid main() {\n    float k = floor(gl_FragCoord.x / 8.0);\n    vec4 t = vec4(0.0);\n" + lookups +
                "    gl_FragColor = t * 0.3;\n}\n";
    return reference::scene_inputs("float-channel-formats", scene, "void main() { gl_Position = gl_Vertex; }\n",
                                   fragment.c_str());
}

}  // namespace

TEST_CASE("glslrun matches Mesa on float textures of one, two and three channels", "[reference][float]") {
    reference::compare_in_every_mode("float-channel-formats", channel_formats_inputs());
}

TEST_CASE("glslrun matches Mesa on unclamped colours and the alpha test in a float target", "[reference][float]") {
    reference::compare_in_every_mode("float-alpha-test",
                                     reference::scene_inputs("float-alpha-test", kAlphaScene, kAlphaVertex, kAlphaFragment));
}

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
