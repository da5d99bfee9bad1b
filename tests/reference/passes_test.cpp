// glslrun against Mesa on [[passes]]: passes with programs of their own
// (scenes/multi_pass.toml: depth and ambient, one additive pass per light
// where the depth is equal, a transparent object on top), and passes that
// share the scene's program with state and uniforms of their own.
#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const std::string kSourceDir = GLSLRUN_SOURCE_DIR;

const char* kTintVertex = R"(
void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }
)";

const char* kTintFragment = R"(
uniform vec4 tint;
void main() { gl_FragColor = gl_Color * tint; }
)";

// A depth pre-pass that writes no colour, then a blended pass drawn only
// where the depth equals the pre-pass's: the far quad never shows through
// the near one, and blending sees the clear colour below each pixel once.
const char* kPrePassScene = R"(
[output]
size = [96, 80]
clear_color = [0.2, 0.1, 0.3, 1]
[state]
depth_test = true
[uniforms]
tint = [1, 1, 1, 1]
[[objects]]
name = "far"
mesh = "arrays"
primitive = "triangle_fan"
vertices = [[-0.9, -0.9, 0.5], [0.5, -0.9, 0.5], [0.5, 0.6, 0.5], [-0.9, 0.6, 0.5]]
color = [0.9, 0.2, 0.1]
[[objects]]
name = "near"
mesh = "arrays"
primitive = "triangles"
vertices = [[-0.4, -0.7, -0.2], [0.9, -0.3, 0.1], [0.1, 0.9, -0.1]]
colors = [[0.1, 0.9, 0.2], [0.2, 0.3, 1.0], [1.0, 1.0, 0.1]]
[[passes]]
name = "depth"
state = { color_writemask = [false, false, false, false] }
[[passes]]
name = "colour"
uniforms = { tint = [1, 1, 1, 0.6] }
state = { depth_func = "equal", depth_writemask = false, blend = true, blend_func = ["src_alpha", "one_minus_src_alpha"] }
[[passes]]
name = "outline of the far quad"
objects = ["far"]
uniforms = { tint = [0.2, 0.2, 1, 1] }
state = { depth_func = "lequal", blend = true, blend_func = ["one", "one"] }
)";


}  // namespace

TEST_CASE("glslrun matches Mesa on passes with their own programs (multi-pass lighting)", "[reference]") {
    auto scene = scene::load_scene(kSourceDir + "/scenes/multi_pass.toml");
    if (!scene) FAIL(scene.error().str());
    REQUIRE(scene->passes.size() == 4);
    auto vs = reference::read_shader(kSourceDir + "/shaders/minimal.vert");
    auto fs = reference::read_shader(kSourceDir + "/shaders/minimal.frag");
    REQUIRE(vs);
    REQUIRE(fs);
    reference::compare("passes-multi-pass", {{*vs}, {*fs}, std::move(*scene)});
}

TEST_CASE("glslrun matches Mesa on a depth pre-pass and blended passes of one program", "[reference]") {
    auto scene = scene::parse_scene(kPrePassScene, "prepass.toml");
    if (!scene) FAIL(scene.error().str());
    reference::compare("passes-pre-pass", {{{"tint.vert", kTintVertex}}, {{"tint.frag", kTintFragment}},
                                            std::move(*scene)});
}
