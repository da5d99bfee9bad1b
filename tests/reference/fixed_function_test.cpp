// glslrun's generated fixed-function stages against Mesa's own fixed function
// (glref draws with no program, or a program of one shader): lighting with
// all 8 lights, each texture environment mode and combiners, each texgen
// mode, the colour sum, fog, programs of one shader, and a fixed-function
// object beside a shaded one. Each image is also the same on both backends
// and at 1 and 2 threads.
#include "tests/reference/helpers.h"

#include <fmt/format.h>

using namespace glslrun;

namespace {

// The command line's program, for scenes whose passes are all "fixed".
const char* kUnusedVertex = "void main() { gl_Position = ftransform(); }\n";
const char* kUnusedFragment = "void main() { gl_FragColor = vec4(1.0); }\n";

// A scene drawn by the given shaders; nullptr leaves that stage to fixed function.
void compare_fixed(const std::string& name, const std::string& toml, const char* vertex, const char* fragment) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    reference::Inputs in;
    if (vertex) in.vertex = {{name + ".vert", vertex}};
    if (fragment) in.fragment = {{name + ".frag", fragment}};
    in.scene = std::move(*scene);
    reference::compare(name, in);
    reference::check_same_everywhere(in);
}

// Every object in fixed function: one pass with no program.
void compare_all_fixed(const std::string& name, const std::string& toml) {
    compare_fixed(name, toml + "\n[[passes]]\nprogram = \"fixed\"\n", kUnusedVertex, kUnusedFragment);
}

const char* kCamera = R"(
[output]
size = [72, 72]
clear_color = [0.05, 0.05, 0.1, 1]
[camera]
look_at = { eye = [0, 0, 4], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 40, near = 1, far = 10 }
)";

// Directional, positional with attenuation, spots with and without it, an
// eye-space headlight: every term of GL 2.1's lighting equation.
const char* kEightLights = R"(
[state]
depth_test = true
[fixed_function]
lighting = true
[light_model]
ambient = [0.1, 0.1, 0.1]
[material]
ambient = [0.3, 0.2, 0.2]
diffuse = [0.6, 0.5, 0.4, 0.8]
specular = [0.5, 0.5, 0.5]
emission = [0.02, 0.0, 0.04]
shininess = 24
[lights.0]
position = [1, 1, 1, 0]
diffuse = [0.3, 0.3, 0.3]
specular = [0.3, 0.3, 0.3]
[lights.1]
position = [-2, 1, 2, 1]
ambient = [0.05, 0, 0]
diffuse = [0.4, 0.1, 0.1]
specular = [0.4, 0.2, 0.2]
constant_attenuation = 0.5
linear_attenuation = 0.2
quadratic_attenuation = 0.05
[lights.2]
position = [0, 2.5, 1.5, 1]
spot_direction = [0, -2.5, -1.5]
spot_cutoff = 30
spot_exponent = 8
diffuse = [0.1, 0.5, 0.1]
specular = [0.1, 0.5, 0.1]
[lights.3]
position = [2, -1, 2, 1]
spot_direction = [-1, 0.5, -1]
spot_cutoff = 45
spot_exponent = 2
linear_attenuation = 0.1
diffuse = [0.1, 0.1, 0.5]
[lights.4]
position = [0, -1, 0.3, 0]
ambient = [0.02, 0.02, 0]
diffuse = [0.2, 0.2, 0]
[lights.5]
space = "eye"
position = [0, 0, 0, 1]
diffuse = [0.1, 0.1, 0.1]
specular = [0.2, 0.2, 0.2]
quadratic_attenuation = 0.02
[lights.6]
position = [-1, -1, 3, 1]
diffuse = [0.15, 0, 0.15]
specular = [0.1, 0.1, 0.1]
[lights.7]
position = [0.5, 2, -1, 0]
diffuse = [0.1, 0.2, 0.2]
[[objects]]
mesh = "sphere"
slices = 32
stacks = 16
)";

// Two-sided lighting of a plane seen from the front and one seen from the
// back, a local viewer, the separate specular colour, colour material on the
// front only, and GL_NORMALIZE under a non-uniform scale.
const char* kTwoSided = R"(
[fixed_function]
lighting = true
color_material = "ambient_and_diffuse"
color_material_face = "front"
normalize = true
[light_model]
two_side = true
local_viewer = true
color_control = "separate_specular_color"
[front_material]
specular = [0.6, 0.6, 0.6]
shininess = 40
[back_material]
ambient_and_diffuse = [0.2, 0.7, 0.4]
specular = [0.3, 0.3, 0.9]
shininess = 10
[lights.0]
position = [1, 2, 3, 1]
[lights.1]
position = [-1, 0, 1, 0]
diffuse = [0.3, 0.3, 0.5]
specular = [0.5, 0.5, 0.5]
[state]
depth_test = true
[[objects]]
mesh = "plane"
subdivisions = 6
color = [0.9, 0.5, 0.2]
transform = [ { translate = [-0.75, 0, 0] }, { rotate = [35, 0, 1, 0] }, { scale = [0.7, 1.2, 1.0] } ]
[[objects]]
mesh = "plane"
subdivisions = 6
color = [0.9, 0.5, 0.2]
transform = [ { translate = [0.75, 0, 0] }, { rotate = [145, 0, 1, 0] }, { scale = [0.7, 1.2, 1.0] } ]
)";

// The quad's vertex colours under piglit's rgbw texture with four alphas.
std::string texenv_scene(const std::string& env) {
    return fmt::format(R"(
[output]
size = [48, 48]
clear_color = [0.1, 0.1, 0.1, 1]
[textures.0]
rgbw = {{ size = [8, 8], alpha = true }}
min_filter = "nearest"
mag_filter = "nearest"
[texture_env.0]
{}
[[objects]]
mesh = "quad"
transform = [ {{ scale = [0.9, 0.9, 1] }} ]
)", env);
}

// Unit 1: a checkerboard whose coordinates come from object-linear texgen.
const char* kSecondUnit = R"(
[textures.1]
checkerboard = { size = [8, 8], colors = [[0.9, 0.3, 0.1], [0.2, 0.4, 0.8]] }
min_filter = "nearest"
mag_filter = "nearest"
[texture_gen.1]
s = { mode = "object_linear", object_plane = [0.5, 0, 0, 0.5] }
t = { mode = "object_linear", object_plane = [0, 0.5, 0, 0.5] }
)";

const char* kCubeFaces = R"(
[state]
depth_test = true
[textures.0]
faces = [ { solid = { size = [4, 4], color = [1, 0, 0] } }, { solid = { size = [4, 4], color = [0, 1, 1] } },
          { solid = { size = [4, 4], color = [0, 1, 0] } }, { solid = { size = [4, 4], color = [1, 0, 1] } },
          { solid = { size = [4, 4], color = [0, 0, 1] } }, { solid = { size = [4, 4], color = [1, 1, 0] } } ]
min_filter = "linear"
wrap_s = "clamp_to_edge"
wrap_t = "clamp_to_edge"
[texture_env.0]
mode = "replace"
[[objects]]
mesh = "sphere"
slices = 32
stacks = 16
transform = [ { rotate = [30, 1, 1, 0] } ]
)";

const char* kChecker2D = R"(
[state]
depth_test = true
[textures.0]
checkerboard = { size = [16, 16], colors = [[0.9, 0.9, 0.2], [0.1, 0.3, 0.7]] }
min_filter = "linear"
mag_filter = "linear"
[texture_env.0]
mode = "modulate"
[[objects]]
mesh = "sphere"
slices = 32
stacks = 16
color = [0.9, 0.8, 0.7]
)";

// A floor going into the distance, fogged, with rescaled normals under a uniform scale.
std::string fog_scene(const std::string& fog) {
    return fmt::format(R"(
[output]
size = [64, 48]
clear_color = [0.5, 0.5, 0.6, 1]
[camera]
look_at = {{ eye = [0, 1, 4], center = [0, 0, -2], up = [0, 1, 0] }}
perspective = {{ fovy = 50, near = 0.5, far = 30 }}
[state]
depth_test = true
[fixed_function]
fog = true
lighting = true
rescale_normal = true
[lights.0]
position = [0, 1, 1, 0]
[fog]
color = [0.5, 0.5, 0.6]
{}
[[objects]]
mesh = "plane"
size = 8
subdivisions = 8
transform = [ {{ translate = [0, -0.5, -2] }}, {{ rotate = [-90, 1, 0, 0] }}, {{ scale = [1.5, 1.5, 1.5] }} ]
[[objects]]
mesh = "torus"
transform = [ {{ translate = [0, 0.2, -3] }}, {{ scale = [0.8, 0.8, 0.8] }} ]
)", fog);
}

}  // namespace

TEST_CASE("glslrun's fixed-function lighting matches Mesa's: 8 lights, attenuation, spots", "[reference][fixed]") {
    compare_all_fixed("ffp-eight-lights", std::string(kCamera) + kEightLights);
}

TEST_CASE("glslrun's fixed-function lighting matches Mesa's: two sides, local viewer, separate specular, "
          "colour material, normalize", "[reference][fixed]") {
    compare_all_fixed("ffp-two-sided", std::string(kCamera) + kTwoSided);
}

TEST_CASE("glslrun's texture environments match Mesa's: each glTexEnv mode", "[reference][fixed]") {
    for (const char* mode : {"modulate", "decal", "blend", "replace", "add"}) {
        INFO(mode);
        compare_all_fixed(fmt::format("ffp-texenv-{}", mode),
                          texenv_scene(fmt::format("mode = \"{}\"\ncolor = [0.2, 0.6, 0.9, 0.5]", mode)));
    }
}

TEST_CASE("glslrun's texture combiners match Mesa's", "[reference][fixed]") {
    compare_all_fixed("ffp-combine-interpolate", texenv_scene(R"(mode = "combine"
combine_rgb = "interpolate"
source1_rgb = "primary_color"
operand2_rgb = "one_minus_src_alpha"
combine_alpha = "add_signed"
source1_alpha = "primary_color"
alpha_scale = 2
color = [0.8, 0.1, 0.3, 0.25])"));
    compare_all_fixed("ffp-combine-crossbar", texenv_scene(R"(mode = "modulate"
[texture_env.1]
mode = "combine"
combine_rgb = "subtract"
source0_rgb = "texture0"
source1_rgb = "texture"
operand1_rgb = "one_minus_src_color"
rgb_scale = 2
combine_alpha = "replace"
source0_alpha = "primary_color")") + kSecondUnit);
    compare_all_fixed("ffp-combine-dot3", texenv_scene(R"(mode = "add"
[texture_env.1]
mode = "combine"
combine_rgb = "dot3_rgba"
source0_rgb = "previous"
source1_rgb = "texture")") + kSecondUnit);
}

TEST_CASE("glslrun's texgen matches Mesa's: object and eye linear, sphere, reflection and normal maps",
          "[reference][fixed]") {
    compare_all_fixed("ffp-texgen-linear", std::string(kCamera) + kChecker2D + R"(
[texture_gen.0]
s = { mode = "object_linear", object_plane = [1, 0.5, 0, 0.5] }
t = { mode = "eye_linear", eye_plane = [0, 1, 0.5, 0.25] }
)");
    compare_all_fixed("ffp-texgen-sphere", std::string(kCamera) + kChecker2D + R"(
[texture_gen.0]
s = "sphere_map"
t = "sphere_map"
)");
    // A cube map's corners flip a few pixels between faces wherever two renderers differ by an ulp: the
    // normal map's seams are short enough at this size; the reflection map's are not, so it samples a
    // smooth 2D gradient of (s, t) through the texture matrix instead.
    std::string camera = kCamera;
    camera.replace(camera.find("[72, 72]"), 8, "[160, 160]");
    compare_all_fixed("ffp-texgen-normal_map", camera + kCubeFaces + R"([texture_gen.0]
s = "normal_map"
t = "normal_map"
r = "normal_map"
)");
    compare_all_fixed("ffp-texgen-reflection_map", std::string(kCamera) + R"(
[state]
depth_test = true
[textures.0]
rgbw = { size = [2, 2] }
min_filter = "linear"
wrap_s = "clamp_to_edge"
wrap_t = "clamp_to_edge"
[texture_matrix.0]
transform = [ { translate = [0.5, 0.5, 0] }, { scale = [0.3, 0.3, 1] } ]
[texture_env.0]
mode = "replace"
[texture_gen.0]
s = "reflection_map"
t = "reflection_map"
r = "reflection_map"
[[objects]]
mesh = "sphere"
slices = 32
stacks = 16
)");
}

TEST_CASE("glslrun's fixed-function fog matches Mesa's: linear, exp, exp2, the fog coordinate", "[reference][fixed]") {
    compare_all_fixed("ffp-fog-linear", fog_scene("mode = \"linear\"\nstart = 2\nend = 9"));
    compare_all_fixed("ffp-fog-exp", fog_scene("mode = \"exp\"\ndensity = 0.25"));
    compare_all_fixed("ffp-fog-exp2", fog_scene("mode = \"exp2\"\ndensity = 0.2"));
    compare_all_fixed("ffp-fog-coord", R"(
[output]
size = [48, 48]
[fixed_function]
fog = true
[fog]
mode = "linear"
coord_src = "fog_coord"
color = [0.9, 0.5, 0.1]
[[objects]]
mesh = "arrays"
primitive = "triangle_fan"
vertices = [[-0.9, -0.9], [0.9, -0.9], [0.9, 0.9], [-0.9, 0.9]]
colors = [[0.1, 0.2, 0.9], [0.1, 0.9, 0.2], [0.9, 0.9, 0.9], [0.3, 0.3, 0.3]]
fog_coords = [0, 0.4, 1, 0.7]
)");
}

TEST_CASE("glslrun's colour sum matches Mesa's", "[reference][fixed]") {
    compare_all_fixed("ffp-color-sum", texenv_scene("mode = \"modulate\"") + R"(
[fixed_function]
color_sum = true
[current]
secondary_color = [0.3, 0.1, 0.0]
)");
}

TEST_CASE("a vertex shader alone draws with Mesa's fixed-function fragment stage", "[reference][fixed]") {
    const char* vertex = R"(
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    gl_FrontColor = vec4(0.5 + 0.5 * gl_Normal, 1.0);
    gl_TexCoord[0] = gl_MultiTexCoord0 * vec4(2.0, 2.0, 1.0, 1.0);
    gl_FogFragCoord = -eye.z;
    gl_Position = ftransform();
}
)";
    compare_fixed("ffp-vertex-only", std::string(kCamera) + kChecker2D + R"(
[fixed_function]
fog = true
[fog]
mode = "linear"
start = 3
end = 5
color = [0.2, 0.2, 0.2]
)", vertex, nullptr);
}

TEST_CASE("a fragment shader alone draws with Mesa's fixed-function vertex stage", "[reference][fixed]") {
    const char* fragment = R"(
void main() {
    gl_FragColor = vec4(gl_Color.rgb * vec3(gl_TexCoord[0].st, 1.0) + gl_SecondaryColor.rgb, gl_Color.a);
}
)";
    std::string lights = kEightLights;
    lights.replace(lights.find("[light_model]\n"), 14, "[light_model]\ncolor_control = \"separate_specular_color\"\n");
    compare_fixed("ffp-fragment-only", std::string(kCamera) + lights + R"(
[texture_gen.0]
s = { mode = "eye_linear", eye_plane = [0.4, 0, 0, 0.5] }
t = { mode = "eye_linear", eye_plane = [0, 0.4, 0, 0.5] }
)", nullptr, fragment);
}

// GL's built-in uniforms of glTexGen and glTexEnv state (GLSL 1.10 §7.5): a
// program computes texgen and an environment blend from them, as programs
// moving off the fixed function did. The camera turns and moves, so that the
// world-space eye planes differ from the eye-space ones Mesa stores.
TEST_CASE("shaders read the scene's texgen planes and texture environment colours as Mesa gives them",
          "[reference][fixed]") {
    const char* vertex = R"(
varying vec4 planes;
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    planes = vec4(dot(gl_Vertex, gl_ObjectPlaneS[0]), dot(gl_Vertex, gl_ObjectPlaneT[0]),
                  dot(eye, gl_EyePlaneR[1]), dot(eye, gl_EyePlaneQ[3]) + gl_ObjectPlaneQ[2].w);
    gl_Position = ftransform();
}
)";
    const char* fragment = R"(
varying vec4 planes;
void main() {
    vec4 env = gl_TextureEnvColor[0] + 0.5 * gl_TextureEnvColor[5];
    gl_FragColor = vec4(mix(env.rgb, planes.xyz, 0.6) + 0.1 * gl_EyePlaneS[2].xyz, planes.w);
}
)";
    compare_fixed("shader-texgen-env", R"(
[output]
size = [72, 72]
clear_color = [0.05, 0.05, 0.1, 1]
[camera]
look_at = { eye = [1.5, 1, 3.5], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 40, near = 1, far = 10 }
[state]
depth_test = true
[texture_env.0]
color = [0.8, 0.2, 0.1, 1]
[texture_env.5]
color = [0, 0.4, 0.6, 0.5]
[texture_gen.0]
s = { mode = "object_linear", object_plane = [0.5, 0, 0.25, 0.5] }
t = { mode = "object_linear", object_plane = [0, 0.5, 0, 0.5] }
[texture_gen.1]
r = { mode = "eye_linear", eye_plane = [0.1, 0.3, 0.4, 0.2] }
[texture_gen.2]
space = "eye"
s = { mode = "eye_linear", eye_plane = [1, 0.5, 0.25, 0] }
q = { mode = "object_linear", object_plane = [0, 0, 0, 0.75] }
[texture_gen.3]
q = { mode = "eye_linear", eye_plane = [0, 0, 0.2, 0.9] }
[[objects]]
mesh = "cube"
transform = [ { rotate = [25, 0, 1, 0] }, { scale = [0.8, 0.8, 0.8] } ]
)", vertex, fragment);
}

TEST_CASE("a fixed-function object beside a shaded one", "[reference][fixed]") {
    const char* vertex =
        "void main() { gl_FrontColor = vec4(1.0, 0.5, 0.25, 1.0) * gl_Color; gl_Position = ftransform(); }\n";
    const char* fragment = "void main() { gl_FragColor = gl_Color.bgra; }\n";
    compare_fixed("ffp-beside-shaded", std::string(kCamera) + R"(
[state]
depth_test = true
[fixed_function]
lighting = true
[lights.0]
position = [1, 1, 1, 0]
[[objects]]
name = "lit"
mesh = "torus"
transform = [ { translate = [-0.7, 0, 0] }, { scale = [0.6, 0.6, 0.6] } ]
[[objects]]
name = "shaded"
mesh = "cube"
vertex_colors = "normal"
transform = [ { translate = [0.8, 0, 0] }, { rotate = [30, 1, 1, 0] }, { scale = [0.8, 0.8, 0.8] } ]
[[passes]]
objects = ["lit"]
program = "fixed"
state = { cull_face = "back" }
[[passes]]
objects = ["shaded"]
state = { cull_face = "back" }
)", vertex, fragment);
}

// Every texture target in one draw: 1D, 3D and rectangle textures through
// object-linear texgen, and a depth texture compared (shadow2DProj), each
// unit modulating the one before.
const char* kTargets = R"(
[output]
size = [64, 64]
clear_color = [0.1, 0.1, 0.1, 1]
[textures.0]
target = "1d"
rgbw = { size = [8] }
min_filter = "nearest"
mag_filter = "nearest"
[textures.1]
target = "3d"
checkerboard = { size = [8, 8, 8], square_size = 4, colors = [[1, 1, 1], [0.5, 0.7, 0.9]] }
min_filter = "nearest"
mag_filter = "nearest"
[textures.2]
target = "rectangle"
checkerboard = { size = [16, 16], square_size = 4, colors = [[1, 0.8, 0.6], [0.6, 0.8, 1]] }
min_filter = "nearest"
mag_filter = "nearest"
[textures.3]
internal_format = "depth_component"
checkerboard = { size = [8, 8], square_size = 2, colors = [0.3, 0.7] }
min_filter = "nearest"
mag_filter = "nearest"
compare_mode = "compare_r_to_texture"
depth_texture_mode = "intensity"
[texture_env.0]
[texture_env.1]
[texture_env.2]
[texture_env.3]
mode = "blend"
color = [0.2, 0.9, 0.4, 1]
[texture_gen.0]
s = { mode = "object_linear", object_plane = [0.5, 0, 0, 0.5] }
[texture_gen.1]
s = { mode = "object_linear", object_plane = [0.5, 0, 0, 0.5] }
t = { mode = "object_linear", object_plane = [0, 0.5, 0, 0.5] }
r = { mode = "object_linear", object_plane = [0.25, 0.25, 0, 0.5] }
[texture_gen.2]
s = { mode = "object_linear", object_plane = [8, 0, 0, 8] }
t = { mode = "object_linear", object_plane = [0, 8, 0, 8] }
[texture_gen.3]
s = { mode = "object_linear", object_plane = [0.5, 0, 0, 0.5] }
t = { mode = "object_linear", object_plane = [0, 0.5, 0, 0.5] }
r = { mode = "object_linear", object_plane = [0.3, 0.2, 0, 0.5] }
[[objects]]
mesh = "quad"
transform = [ { scale = [0.9, 0.9, 1] } ]
)";

TEST_CASE("fixed-function texturing of 1D, 3D, rectangle and compared depth textures matches Mesa's",
          "[reference][fixed]") {
    compare_all_fixed("ffp-targets", kTargets);
    // A depth texture's texture environment follows its depth_texture_mode's base format.
    for (const char* depth_mode : {"luminance", "alpha"})
        for (const char* env : {"replace", "decal", "add"}) {
            INFO(depth_mode << " " << env);
            std::string scene = texenv_scene(fmt::format("mode = \"{}\"\ncolor = [0.9, 0.2, 0.5, 0.5]", env));
            const std::string rgbw = "rgbw = { size = [8, 8], alpha = true }";
            scene.replace(scene.find(rgbw), rgbw.size(),
                          fmt::format("internal_format = \"depth_component\"\ncheckerboard = {{ size = [8, 8], "
                                      "colors = [0.2, 0.8] }}\ndepth_texture_mode = \"{}\"", depth_mode));
            compare_all_fixed(fmt::format("ffp-depth-{}-{}", depth_mode, env), scene);
        }
}

TEST_CASE("scenes/fixed_function.toml without shaders matches Mesa's fixed function", "[reference][fixed]") {
    auto scene = scene::load_scene(std::string(GLSLRUN_SOURCE_DIR) + "/scenes/fixed_function.toml");
    if (!scene) FAIL(scene.error().str());
    // What `glslrun scene.toml` does: every draw in fixed function, the command line's program unused.
    scene::use_fixed_function(*scene);
    REQUIRE(scene::resize_scene(*scene, 256, 192));
    reference::Inputs in{{{"unused.vert", kUnusedVertex}}, {{"unused.frag", kUnusedFragment}}, std::move(*scene)};
    reference::compare("ffp-scene-file", in);
    reference::check_same_everywhere(in);
}

TEST_CASE("the fixed-function vertex stage clips against user clip planes in eye space", "[reference][fixed]") {
    std::string lights = kEightLights;
    lights.replace(lights.find("[state]\ndepth_test = true\n"), 26,
                   "[state]\ndepth_test = true\nclip_planes = [[1, 0.3, 0, 0.2], [0, -1, 0.2, 0.6]]\n");
    compare_all_fixed("ffp-clip-planes", std::string(kCamera) + lights);
}
