// glslrun against Mesa on render targets: passes that draw into textures
// (framebuffer objects) which later passes sample. scenes/shadow_map.toml
// (a depth texture from the light, compared through sampler2DShadow with
// 2x2 PCF) and scenes/blur.toml (a two-pass blur of a rendered image). Each
// image is also the same on both backends and at 1 and 2 threads.
#include "tests/reference/helpers.h"

#include "glslrun/scene/meshes.h"

using namespace glslrun;

namespace {

const std::string kSourceDir = GLSLRUN_SOURCE_DIR;

// The command line's program: every pass of these scenes names its own.
const char* kUnusedVertex = "void main() { gl_Position = ftransform(); }\n";
const char* kUnusedFragment = "void main() { gl_FragColor = vec4(1.0); }\n";

// An inline scene with one program, compared and checked everywhere.
void compare_inline(const std::string& name, const char* text, const char* vertex, const char* fragment) {
    auto scene = scene::parse_scene(text, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    reference::Inputs in{{{name + ".vert", vertex}}, {{name + ".frag", fragment}}, std::move(*scene)};
    reference::compare(name, in);
    reference::check_same_everywhere(in);
}

void compare_scene_file(const std::string& name, const std::string& file) {
    auto scene = scene::load_scene(kSourceDir + "/scenes/" + file);
    if (!scene) FAIL(scene.error().str());
    reference::Inputs in{{{"unused.vert", kUnusedVertex}}, {{"unused.frag", kUnusedFragment}}, std::move(*scene)};
    reference::compare(name, in);
    reference::check_same_everywhere(in);
}

const char* kColorVertex = "void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }\n";
const char* kHalfFragment = "void main() { gl_FragColor = gl_Color * 0.45; }\n";

// Passes into parts of the output (glViewport), one from its own camera after
// a depth clear, and one that draws the cube twice, added.
const char* kViewportScene = R"(
[output]
size = [96, 64]
clear_color = [0.1, 0.1, 0.1, 1]
[camera]
look_at = { eye = [0, 0, 3], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 45, near = 1, far = 10 }
[state]
depth_test = true
[[objects]]
name = "cube"
mesh = "cube"
vertex_colors = "normal"
transform = [ { rotate = [30, 1, 1, 0] } ]
[[passes]]
state = { viewport = [0, 0, 48, 64] }
[[passes]]
clear = { depth = 1 }
camera = { look_at = { eye = [2, 2, 2], center = [0, 0, 0], up = [0, 1, 0] }, perspective = { fovy = 50, aspect = 1, near = 1, far = 10 } }
state = { viewport = [48, 8, 40, 40] }
[[passes]]
objects = ["cube", "cube"]
state = { viewport = [60, 40, 36, 24], depth_test = false, blend = true, blend_func = ["one", "one"] }
)";

// [current]: glMultiTexCoord on a unit the mesh has no array for (the
// quad's unit 0 array wins over its current value), glFogCoord, and
// constant generic attributes (glVertexAttrib).
const char* kCurrentVertex = R"(
attribute float weight;
attribute vec2 shift;
void main() {
    gl_FrontColor = vec4(gl_MultiTexCoord0.x, gl_MultiTexCoord2.y + 0.25 * gl_MultiTexCoord2.w, weight + gl_FogCoord, 1.0);
    gl_Position = ftransform() + vec4(shift, 0.0, 0.0);
}
)";
const char* kColorFragment = "void main() { gl_FragColor = gl_Color; }\n";
const char* kCurrentScene = R"(
[output]
size = [64, 64]
[current]
tex_coords = { 0 = [0.9, 0.9], 2 = [0.1, 0.3] }
fog_coord = 0.2
attributes = { weight = 0.5, shift = [0.25, -0.25] }
[[objects]]
mesh = "quad"
transform = [ { scale = [0.6, 0.6, 1] } ]
)";

const char* kTexVertex = "void main() { gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }\n";
const char* kTexFragment = R"(
uniform sampler2D tex;
uniform sampler2D other;
void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].st) * 0.7 + texture2D(other, gl_TexCoord[0].st) * 0.3; }
)";
// Textures bound per object: each of the first two quads binds its own to
// unit 0; the third binds none and samples the second's (GL's binding is
// context state); unit 1 keeps the scene's texture throughout.
const char* kObjectTexturesScene = R"(
[output]
size = [96, 32]
[textures.1]
checkerboard = { size = [8, 8], colors = [[0, 0, 1], [1, 1, 0]] }
min_filter = "nearest"
mag_filter = "nearest"
[uniforms]
tex = 0
other = 1
[[objects]]
mesh = "quad"
transform = [ { translate = [-0.66, 0, 0] }, { scale = [0.3, 0.9, 1] } ]
[objects.textures.0]
checkerboard = { size = [4, 4], colors = [[1, 0, 0], [1, 1, 1]] }
min_filter = "nearest"
mag_filter = "nearest"
[[objects]]
mesh = "quad"
transform = [ { scale = [0.3, 0.9, 1] } ]
[objects.textures.0]
rgbw = { size = [2, 2] }
min_filter = "linear"
[[objects]]
mesh = "quad"
transform = [ { translate = [0.66, 0, 0] }, { scale = [0.3, 0.9, 1] } ]
)";

}  // namespace

TEST_CASE("glslrun matches Mesa on textures bound per object", "[reference]") {
    compare_inline("object-textures", kObjectTexturesScene, kTexVertex, kTexFragment);
}

TEST_CASE("glslrun matches Mesa on current texture coordinates, fog coordinate and generic attributes", "[reference]") {
    compare_inline("current-attributes", kCurrentScene, kCurrentVertex, kColorFragment);
}

TEST_CASE("glslrun matches Mesa on viewports, per-pass cameras and clears, and an object drawn twice", "[reference]") {
    compare_inline("targets-viewports", kViewportScene, kColorVertex, kHalfFragment);
}

TEST_CASE("glslrun matches Mesa on shadow mapping through a depth render target (PCF)", "[reference]") {
    compare_scene_file("targets-shadow-map", "shadow_map.toml");
}

TEST_CASE("glslrun matches Mesa on a two-pass blur through colour render targets", "[reference]") {
    compare_scene_file("targets-blur", "blur.toml");
}
