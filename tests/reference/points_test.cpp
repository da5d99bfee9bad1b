// glslrun against Mesa on points at their exact sizes (GL 2.1 §3.3): point
// sprites of fractional and distance-attenuated sizes, whose square and
// gl_PointCoord follow the size itself, and non-sprite points, whose size is
// rounded (n + 1/2 down, as Mesa). Centres on and off pixel boundaries. Each
// image must be identical to Mesa's, not only within the usual tolerance: a
// one-pixel rim or a gl_PointCoord a step off is what these tests are about.
#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

// The size from the attribute `size`; gl_PointCoord and a blue of 1 show
// coverage and the coordinate's steps.
const char* kVertex = R"(#version 120
attribute float size;
void main() { gl_FrontColor = gl_Color; gl_PointSize = size; gl_Position = ftransform(); }
)";
const char* kFragment = R"(#version 120
void main() { gl_FragColor = vec4(gl_PointCoord, 1.0, 1.0); }
)";

// Twelve points, 8 pixels per unit: sizes with fractions (n + 1/2 among
// them), centres at pixel corners, edges and centres and in between.
const char* kFractionalObjects = R"(
[camera]
ortho = { left = 0, right = 12, bottom = 0, top = 8, near = -1, far = 1 }
[state]
vertex_program_point_size = true
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[1, 1], [3.0625, 1], [5.03, 1.1], [7.5, 1.0625], [9.71, 1.33], [11, 1.5],
            [1.5, 4], [4, 4.0625], [6.77, 3.81], [9.25, 4.4], [2, 6.6], [7.3, 6.5]]
attributes = { size = [2.5, 3.5, 4.25, 5.5, 6.3, 7.75, 9.5, 10.5, 13.1, 15.5, 11.2, 16.8] }
)";

inline scene::Scene parse(const std::string& text, const std::string& name) {
    auto scene = scene::parse_scene(text, name);
    if (!scene) FAIL(scene.error().str());
    return std::move(*scene);
}

// Renders both ways; the images must be byte for byte the same.
void compare_exactly(const std::string& name, const char* vertex, const std::string& scene_text) {
    reference::Inputs in{{{name + ".vert", vertex}}, {{name + ".frag", kFragment}}, parse(scene_text, name + ".toml")};
    auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
    REQUIRE(mesa);
    auto ours = reference::render_glslrun(in);
    REQUIRE(ours);
    reference::compare_images(name, in, mesa->image, (*ours)[0]);
    size_t differing = 0;
    for (size_t i = 0; i < mesa->image.rgba.size(); ++i) differing += mesa->image.rgba[i] != (*ours)[0].rgba[i];
    CHECK(differing == 0);
}

}  // namespace

TEST_CASE("glslrun matches Mesa exactly on point sprites of fractional sizes", "[reference]") {
    compare_exactly("points-sprite-fractional", kVertex,
                    std::string("[output]\nsize = [96, 64]\nclear_color = [0, 0, 0, 1]\n") + kFractionalObjects +
                        "\n[objects.state]\npoint_sprite = true\nvertex_program_point_size = true\n");
}

TEST_CASE("glslrun matches Mesa exactly on non-sprite points of fractional sizes", "[reference]") {
    compare_exactly("points-rounded", kVertex,
                    std::string("[output]\nsize = [96, 64]\nclear_color = [0, 0, 0, 1]\n") + kFractionalObjects);
}

TEST_CASE("glslrun matches Mesa exactly on distance-attenuated point sprites", "[reference]") {
    // A particle system's size: 60 / distance, in perspective.
    const char* vertex = R"(#version 120
void main() {
    gl_FrontColor = gl_Color;
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    gl_PointSize = 60.0 / -eye.z;
    gl_Position = ftransform();
}
)";
    compare_exactly("points-attenuated", vertex, R"(
[output]
size = [128, 96]
clear_color = [0, 0, 0, 1]
[camera]
look_at = { eye = [0, 1.5, 6], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 50, near = 1, far = 40 }
[state]
point_sprite = true
vertex_program_point_size = true
depth_test = true
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[-2.3, 0, 2.1], [-1.1, 0.2, 1.3], [0.3, -0.1, 0.7], [1.7, 0.4, -0.6], [2.9, 0, -2.2],
            [-3.1, 1.2, -4.5], [-0.7, 1.9, -7.3], [1.3, 2.3, -10.1], [3.4, 1.1, -13.7], [0.1, -1.2, 3.3],
            [-1.9, -0.8, -1.7], [2.2, -1.4, 1.9]]
)");
}
