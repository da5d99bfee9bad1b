// glslrun against Mesa on GL 1.4's point parameters and GL 2.0's sprite
// origin: the fixed-function stage's distance attenuation clamped to
// [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX] (sprites at their exact sizes and
// rounded points), glPointSize clamped alike under a vertex shader that
// leaves the size to GL, gl_PointSize unclamped but for the largest point
// (255), the fade threshold (no fade without multisampling, in both), the
// gl_Point uniforms a shader reads, and GL_POINT_SPRITE_COORD_ORIGIN. Every
// case in Precise and Fast, and the same images on both backends and at 1
// and 2 threads.
#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

// The fixed-function vertex stage's colour, and the sprite's coordinate.
const char* kCoordFragment = R"(#version 120
void main() { gl_FragColor = vec4(gl_PointCoord, gl_Color.b, 1.0); }
)";
const char* kColorVertex = "void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }\n";
const char* kColorFragment = "void main() { gl_FragColor = gl_Color; }\n";

// 36 points in perspective, from 2 to 30 units away and off the axis (Mesa
// measures the distance as |z| in eye space, not the length).
std::string depth_grid() {
    std::string vertices, colors;
    for (int i = 0; i < 36; ++i) {
        float x = -5.3f + 2.1f * float(i % 6) + 0.137f * float(i), y = -2.9f + 1.13f * float(i / 6);
        float z = 3.7f - 0.83f * float(i);
        vertices += fmt::format("{}[{}, {}, {}]", i ? ", " : "", x, y, z);
        colors += fmt::format("{}[{}, {}, {}]", i ? ", " : "", float(i % 3) / 2.0f, float(i % 5) / 4.0f, 0.75f);
    }
    return fmt::format(R"(
[output]
size = [192, 128]
clear_color = [0, 0, 0, 1]
[camera]
look_at = {{ eye = [0, 1, 6], center = [0, 0, -6], up = [0, 1, 0] }}
perspective = {{ fovy = 55, near = 1, far = 60 }}
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [{}]
colors = [{}]
)",
                       vertices, colors);
}

reference::Inputs inputs(const std::string& name, const std::string& toml, const char* vertex, const char* fragment) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    std::vector<ShaderSource> vs;
    if (vertex) vs.push_back({name + ".vert", vertex});
    return {std::move(vs), {{name + ".frag", fragment}}, std::move(*scene)};
}

const char* kAttenuation = R"(
[state]
depth_test = true
point_size = 40
point_distance_attenuation = [0.6, 0.15, 0.012]
point_size_min = 3.5
point_size_max = 17.25
)";

}  // namespace

TEST_CASE("glslrun matches Mesa on fixed-function distance attenuation, clamped to the size range",
          "[reference][points]") {
    const std::string grid = depth_grid();
    // No vertex shader: GL's fixed-function stage sizes the points.
    reference::compare_in_every_mode("points-ff-attenuation-sprites",
                                     inputs("ff-sprites", grid + kAttenuation + "point_sprite = true\n", nullptr,
                                            kCoordFragment));
    reference::compare_in_every_mode("points-ff-attenuation-rounded",
                                     inputs("ff-rounded", grid + kAttenuation, nullptr, kCoordFragment));
    // A minimum above the maximum: Mesa's fixed-function stage ends with the maximum.
    reference::compare_in_every_mode(
        "points-ff-attenuation-crossed",
        inputs("ff-crossed", grid + kAttenuation + "point_sprite = true\n[objects.state]\npoint_size_min = 9\npoint_size_max = 6.5\n",
               nullptr, kCoordFragment));
}

TEST_CASE("glslrun matches Mesa on glPointSize clamped to the size range under a vertex shader",
          "[reference][points]") {
    // The attenuation does not apply to a shader's points; the range does,
    // to glPointSize, but not to the shader's gl_PointSize.
    std::string toml = R"(
[output]
size = [160, 64]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 20, bottom = 0, top = 8, near = -1, far = 1 }
[state]
point_sprite = true
point_distance_attenuation = [0, 0, 4]
point_size_min = 4.25
point_size_max = 12.5
)";
    auto object = [](float x, const std::string& state) {
        return fmt::format("[[objects]]\nmesh = \"arrays\"\nprimitive = \"points\"\nvertices = [[{}, 4.1]]\n"
                           "colors = [[1, 0.5, 1]]\n[objects.state]\n{}\n",
                           x, state);
    };
    toml += object(2.3f, "point_size = 1.5") + object(6.6f, "point_size = 9.3") + object(12.1f, "point_size = 30") +
            object(17.2f, "point_size = 30\npoint_size_min = 11\npoint_size_max = 7.5");
    reference::compare_in_every_mode("points-shader-size-range", inputs("range", toml, kColorVertex, kCoordFragment));

    const char* written = R"(#version 120
attribute float size;
void main() { gl_FrontColor = gl_Color; gl_PointSize = size; gl_Position = ftransform(); }
)";
    // gl_PointSize of 30 passes the maximum of 7, 300 is drawn at 255.
    reference::compare_in_every_mode("points-shader-size-unclamped", inputs("unclamped", R"(
[output]
size = [320, 300]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 320, bottom = 0, top = 300, near = -1, far = 1 }
[state]
point_sprite = true
vertex_program_point_size = true
point_size_max = 7
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[30.3, 260.6], [160.4, 150.2]]
colors = [[1, 0.5, 1], [0.5, 1, 1]]
attributes = { size = [30, 300] }
)",
                                                                            written, kCoordFragment));
}

TEST_CASE("glslrun matches Mesa on the fade threshold: no fade without multisampling", "[reference][points]") {
    // Attenuated sizes from 2 to 17, a threshold of 20, blended: GL fades
    // only with multisampling, and neither Mesa nor glslrun fades here.
    const std::string grid = depth_grid();
    std::string state = std::string(kAttenuation) +
                        "point_fade_threshold_size = 20\nblend = true\nblend_func = [\"src_alpha\", \"one_minus_src_alpha\"]\n";
    reference::compare_in_every_mode("points-ff-fade-threshold",
                                     inputs("fade", grid + state + "[current]\ncolor = [1, 0.5, 0.25, 0.6]\n", nullptr,
                                            kColorFragment));
}

TEST_CASE("glslrun matches Mesa on the gl_Point uniforms a particle shader reads", "[reference][points]") {
    // The size from gl_Point as GL's own rule, with the eye distance; the
    // fade GL leaves to multisampling done in the shader from its threshold.
    const char* vertex = R"(#version 120
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    float d = length(eye.xyz);
    float size = gl_Point.size * inversesqrt(gl_Point.distanceConstantAttenuation
                 + d * (gl_Point.distanceLinearAttenuation + d * gl_Point.distanceQuadraticAttenuation));
    size = clamp(size, gl_Point.sizeMin, gl_Point.sizeMax);
    float fade = size >= gl_Point.fadeThresholdSize ? 1.0 : pow(size / gl_Point.fadeThresholdSize, 2.0);
    gl_PointSize = size;
    gl_FrontColor = vec4(gl_Color.rg, fade, 1.0);
    gl_Position = gl_ProjectionMatrix * eye;
}
)";
    // Opaque discs: what the test shows is the sizes and the fade, not blending.
    const char* fragment = R"(#version 120
void main() {
    vec2 p = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(p, p);
    if (r2 > 1.0) discard;
    gl_FragColor = vec4(gl_Color.rgb * (1.0 - 0.5 * r2), 1.0);
}
)";
    std::string state = std::string(kAttenuation) +
                        "point_sprite = true\nvertex_program_point_size = true\npoint_fade_threshold_size = 9.5\n";
    reference::compare_in_every_mode("points-gl-point-uniforms", inputs("gl-point", depth_grid() + state, vertex, fragment));
}

TEST_CASE("glslrun matches Mesa on GL_POINT_SPRITE_COORD_ORIGIN", "[reference][points]") {
    // gl_PointCoord and a GL_COORD_REPLACE unit's coordinates, t from the top
    // (GL's default) or from the bottom; without sprites the origin changes nothing.
    const char* vertex = R"(#version 120
attribute float size;
void main() { gl_FrontColor = gl_Color; gl_TexCoord[1] = vec4(0.5); gl_PointSize = size; gl_Position = ftransform(); }
)";
    const char* fragment = R"(#version 120
void main() { gl_FragColor = vec4(gl_PointCoord.x, gl_PointCoord.y, gl_TexCoord[1].t, 1.0); }
)";
    const std::string points = R"(
[output]
size = [128, 64]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 16, bottom = 0, top = 8, near = -1, far = 1 }
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[2.03, 2.1], [6.5, 2.5], [11.27, 3.3], [3.6, 6.2], [9.1, 5.9]]
attributes = { size = [13.5, 20, 31.3, 17.75, 22.5] }
[state]
vertex_program_point_size = true
coord_replace = [1]
)";
    for (const char* origin : {"upper_left", "lower_left"})
        for (bool sprite : {true, false}) {
            std::string name = fmt::format("points-origin-{}{}", origin, sprite ? "" : "-no-sprite");
            std::string toml = points + fmt::format("point_sprite_coord_origin = \"{}\"\npoint_sprite = {}\n", origin, sprite);
            reference::compare_in_every_mode(name, inputs(name, toml, vertex, fragment));
        }
}

TEST_CASE("glslrun matches Mesa on the particles scene", "[reference][points]") {
    // scenes/particles.toml: attenuated sprites, discs and a texture, blended over a floor.
    const std::string dir = GLSLRUN_SOURCE_DIR;
    auto vs = reference::read_shader(dir + "/shaders/particles.vert");
    auto fs = reference::read_shader(dir + "/shaders/particles.frag");
    auto sc = scene::load_scene(dir + "/scenes/particles.toml");
    if (!vs || !fs || !sc) FAIL((!vs ? vs.error().str() : !fs ? fs.error().str() : sc.error().str()));
    reference::compare_in_every_mode("particles", {{*vs}, {*fs}, std::move(*sc)});
}
