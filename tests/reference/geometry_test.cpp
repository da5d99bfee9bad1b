// glslrun against Mesa on inline vertex arrays (mesh = "arrays"): every GL
// 2.1 primitive type, drawn with and without indices, with per-vertex
// colours, secondary colours, texture coordinates of two units, fog
// coordinates and a generic attribute. Points and line ends sit off pixel
// boundaries: on one, which pixel a point or a line's end takes is the
// implementation's rounding (glslrun and llvmpipe then differ by a pixel).
#include "tests/reference/helpers.h"

#include <fmt/format.h>

using namespace glslrun;

namespace {

const char* kVertex = R"(
attribute float weight;
void main() {
    gl_FrontColor = vec4(gl_Color.rgb * weight, 1.0) + gl_SecondaryColor * 0.25;
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_TexCoord[3] = gl_MultiTexCoord3;
    gl_FogFragCoord = gl_FogCoord;
    gl_Position = ftransform();
}
)";

const char* kFragment = R"(
void main() { gl_FragColor = gl_Color + vec4(gl_TexCoord[0].xy * 0.2, gl_TexCoord[3].x * 0.2, 0.0) + gl_FogFragCoord * 0.1; }
)";

const char* kScene = R"(
[output]
size = [160, 120]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 16, bottom = 0, top = 12, near = -1, far = 1 }

[[objects]]
name = "points"
mesh = "arrays"
primitive = "points"
vertices = [[1.23, 1.37], [2.43, 1.63], [3.36, 2.25]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
attributes = { weight = [1, 1, 1] }

[[objects]]
name = "lines"
mesh = "arrays"
primitive = "lines"
vertices = [[4.113, 1.213], [7.313, 2.913], [4.213, 3.113], [6.813, 0.413]]
colors = [[1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 1, 1]]
attributes = { weight = [1, 0.5, 1, 0.5] }

[[objects]]
name = "strip"
mesh = "arrays"
primitive = "line_strip"
vertices = [[8.213, 1.113], [9.713, 3.313], [11.113, 1.413], [12.613, 3.213]]
colors = [[1, 0.5, 0], [0, 1, 0.5], [0.5, 0, 1], [1, 1, 1]]
attributes = { weight = [1, 1, 1, 1] }

[[objects]]
name = "loop"
mesh = "arrays"
primitive = "line_loop"
vertices = [[13.213, 0.613], [15.313, 1.113], [14.113, 3.413]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
attributes = { weight = [1, 1, 1] }

[[objects]]
name = "triangles"
mesh = "arrays"
primitive = "triangles"
vertices = [[0.5, 4.5, 0], [3.5, 4.2, 0], [2, 7.5, 0], [3.1, 5.5, 0.5], [4.9, 7.8, 0.5], [3.0, 7.9, 0.5]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]]
secondary_colors = [[0.2, 0, 0], [0, 0.2, 0], [0, 0, 0.2], [0, 0, 0], [0, 0, 0], [0, 0, 0]]
tex_coords = [[0, 0], [1, 0], [0, 1], [1, 1], [0.5, 0.5], [0, 0]]
attributes = { weight = [1, 0.8, 0.6, 0.4, 0.2, 1] }

[[objects]]
name = "strip"
mesh = "arrays"
primitive = "triangle_strip"
vertices = [[5.5, 4.5], [6, 7.5], [7, 4.4], [7.8, 7.2], [8.9, 4.1]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
tex_coords = { 3 = [0, 0.5, 1, 0.5, 0] }
attributes = { weight = [1, 1, 1, 1, 1] }

[[objects]]
name = "fan"
mesh = "arrays"
primitive = "triangle_fan"
vertices = [[11, 6], [9.5, 4.5], [12.5, 4.3], [13, 7], [10.5, 7.8]]
colors = [[1, 1, 1], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]]
fog_coords = [0, 1, 0.5, 0.2, 0.8]
indices = [0, 1, 2, 3, 4]
attributes = { weight = [1, 1, 1, 1, 1] }

[[objects]]
name = "quads"
mesh = "arrays"
primitive = "quads"
vertices = [[0.5, 8.5], [3.5, 8.5], [3.5, 11.5], [0.5, 11.5]]
colors = [[1, 0, 0], [1, 0, 0], [0, 0, 1], [0, 0, 1]]
attributes = { weight = [1, 1, 1, 1] }

[[objects]]
name = "quad strip"
mesh = "arrays"
primitive = "quad_strip"
vertices = [[4.5, 8.5], [4.5, 11.5], [6.5, 8.5], [6.5, 11.5], [8.5, 8.5], [8.5, 11.5]]
colors = [[1, 0, 0], [1, 0, 0], [0, 1, 0], [0, 1, 0], [0, 0, 1], [0, 0, 1]]
attributes = { weight = [1, 1, 1, 1, 1, 1] }

[[objects]]
name = "polygon"
mesh = "arrays"
primitive = "polygon"
vertices = [[11, 8.2], [13, 8.6], [13.8, 10.3], [12, 11.6], [10, 10.4]]
colors = [[0.5, 0.5, 0.5], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5]]
indices = [4, 3, 2, 1, 0]
attributes = { weight = [1, 1, 1, 1, 1] }
)";

}  // namespace

// gl_PointSize counts only with vertex_program_point_size; the other object
// takes point_size (glPointSize). Centres off pixel boundaries.
const char* kPointVertex = R"(
void main() { gl_FrontColor = gl_Color; gl_PointSize = 7.0; gl_Position = ftransform(); }
)";

const char* kPointScene = R"(
[output]
size = [64, 64]
clear_color = [0, 0, 0, 1]
[state]
point_size = 3
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[-0.52, -0.47], [0.33, 0.61]]
colors = [[1, 0, 0], [0, 1, 0]]
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[0.41, -0.36], [-0.58, 0.44]]
colors = [[0, 0, 1], [1, 1, 0]]
state = { vertex_program_point_size = true }
)";

TEST_CASE("glslrun matches Mesa on glPointSize and gl_PointSize with GL_VERTEX_PROGRAM_POINT_SIZE", "[reference]") {
    auto scene = scene::parse_scene(kPointScene, "points.toml");
    if (!scene) FAIL(scene.error().str());
    reference::compare("geometry-point-size", {{{"points.vert", kPointVertex}},
                                               {{"points.frag", "void main() { gl_FragColor = gl_Color; }\n"}},
                                               std::move(*scene)});
}

TEST_CASE("glslrun matches Mesa on inline arrays of every primitive type", "[reference]") {
    auto scene = scene::parse_scene(kScene, "arrays.toml");
    if (!scene) FAIL(scene.error().str());
    reference::compare("geometry-arrays", {{{"arrays.vert", kVertex}}, {{"arrays.frag", kFragment}}, std::move(*scene)});
}

// Clipping where the spec leaves the precision open: llvmpipe clips x and y
// at the viewport (no guard band) and snaps the new vertex, which lies on
// the window's edge, to 1/256 pixel; glslrun clips x and y against a guard
// band 2^19 pixels wide, so an edge that crosses the window's side is the
// line between its own two snapped vertices. The transparency scene's ground
// (scenes/app/transparency.toml, its left edge seen crossing the window's
// left side at y = 44.3) is such a triangle, in clip coordinates here: the
// exact edge passes 0.002 pixel right of pixel (0, 44)'s centre, so GL's
// point-sampling rule leaves that pixel out; llvmpipe's snapped clip vertex
// moves the edge 0.003 pixel left of it and covers it. glslrun keeps the
// exact answer (docs/semantics.md, "clipping"); every other pixel is the same.
TEST_CASE("a triangle clipped at the window's side covers the pixels of its exact edge", "[reference]") {
    const double a[4] = {-5.01050968, 0.57151669, 5.9878302, 7.32232256};
    const double b[4] = {-5.82302476, -2.25369453, -0.49745329, 1.45468512};
    const double d[4] = {5.82302476, 0.35962584, 5.50143393, 6.88224975};
    const reference::Inputs in = reference::scene_inputs("clipped_edge", fmt::format(R"(
[output]
size = [128, 96]
clear_color = [0, 0, 0, 1]
[[objects]]
mesh = "arrays"
primitive = "triangles"
vertices = [[{}, {}, {}, {}], [{}, {}, {}, {}], [{}, {}, {}, {}]]
)", a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], d[0], d[1], d[2], d[3]),
        "void main() { gl_Position = gl_Vertex; }", "void main() { gl_FragColor = vec4(1.0); }");
    // The exact edge a-b in window coordinates, at pixel row 44's centre.
    auto window = [](const double* p) { return std::pair{(p[0] / p[3] + 1) * 64, (p[1] / p[3] + 1) * 48}; };
    auto [ax, ay] = window(a);
    auto [bx, by] = window(b);
    const double edge_x = ax + (44.5 - ay) / (by - ay) * (bx - ax);
    CHECK(edge_x > 0.5);
    CHECK(edge_x < 0.5 + 1.0 / 256);  // within the snap: the two clippings may differ here
    const scene::Image ours = reference::check_same_everywhere(in);
    auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
    REQUIRE(mesa);
    const int row = 95 - 44;  // top-left origin
    CHECK(ours.pixel(0, row)[0] == 0);
    CHECK(mesa->image.pixel(0, row)[0] == 255);
    int differ = 0;
    for (size_t i = 0; i < ours.rgba.size(); ++i) differ += ours.rgba[i] != mesa->image.rgba[i];
    CHECK(differ == 3);  // that pixel's R, G and B
}
