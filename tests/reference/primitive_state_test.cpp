// glslrun against Mesa on primitive state: glPolygonMode (per face, quads
// and polygons drawing only their own edges), glPolygonOffset (fill and
// line: coplanar decals and hidden-line outlines), wide lines, point sprites
// (gl_PointCoord, GL_COORD_REPLACE), and glCullFace / glFrontFace, with
// GL_FRONT_AND_BACK. Vertices sit off pixel boundaries (on one, the pixel a
// point or a line's end takes is the implementation's rounding).
#include <fmt/format.h>

#include <array>
#include <glm/glm.hpp>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* kColorVertex = R"(
void main() { gl_FrontColor = gl_Color; gl_BackColor = vec4(1.0) - gl_Color; gl_Position = ftransform(); }
)";
const char* kColorFragment = "void main() { gl_FragColor = gl_Color; }\n";

void compare_colors(const std::string& name, const char* toml, const char* vertex = kColorVertex) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    reference::compare(name, {{{"color.vert", vertex}}, {{"color.frag", kColorFragment}}, std::move(*scene)});
}

// Counter-clockwise shapes are front faces, clockwise ones back faces.
const char* kShapes = R"(
[output]
size = [128, 96]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 16, bottom = 0, top = 12, near = -1, far = 1 }
[state]
point_size = 3
vertex_program_two_side = true
%s
[[objects]]
name = "quads, front"
mesh = "arrays"
primitive = "quads"
vertices = [[1.135, 1.26], [5.385, 1.385], [5.135, 5.26], [1.26, 4.885], [6.26, 1.135], [9.385, 1.385], [9.135, 4.635], [6.385, 4.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 1, 1], [1, 0.5, 0]]
[[objects]]
name = "polygon, back"
mesh = "arrays"
primitive = "polygon"
vertices = [[12.135, 1.26], [10.385, 2.76], [11.26, 5.135], [13.635, 5.385], [14.76, 2.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
[[objects]]
name = "strip, both faces"
mesh = "arrays"
primitive = "triangle_strip"
vertices = [[1.26, 6.635], [2.135, 10.76], [4.385, 6.885], [5.26, 10.385], [7.635, 6.76], [8.385, 10.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]]
[[objects]]
name = "quad strip"
mesh = "arrays"
primitive = "quad_strip"
vertices = [[9.76, 6.76], [9.885, 10.635], [12.135, 6.635], [12.26, 10.885], [14.635, 6.885], [14.51, 10.385]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]]
)";

// `scene` with its "%s" replaced by `state`.
std::string with_state(const std::string& scene, const std::string& state) {
    std::string text = scene;
    text.replace(text.find("%s"), 2, state);
    return text;
}

std::string shapes(const std::string& state) { return with_state(kShapes, state); }

}  // namespace

TEST_CASE("glslrun matches Mesa on glPolygonMode", "[reference]") {
    compare_colors("primitive-polygon-mode-line", shapes("polygon_mode = \"line\"").c_str());
    compare_colors("primitive-polygon-mode-point", shapes("polygon_mode = \"point\"").c_str());
    compare_colors("primitive-polygon-mode-line-fill", shapes("polygon_mode = [\"line\", \"fill\"]").c_str());
    compare_colors("primitive-polygon-mode-fill-point", shapes("polygon_mode = [\"fill\", \"point\"]\nshade_model = \"flat\"").c_str());
}

TEST_CASE("glslrun matches Mesa on wide lines and polygon edges", "[reference]") {
    compare_colors("primitive-line-width-3", shapes("polygon_mode = \"line\"\nline_width = 3").c_str());
    compare_colors("primitive-line-width-2", shapes("polygon_mode = \"line\"\nline_width = 2").c_str());
    compare_colors("primitive-line-strip-width-5", R"(
[output]
size = [96, 96]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 12, bottom = 0, top = 12, near = -1, far = 1 }
[state]
line_width = 5
[[objects]]
mesh = "arrays"
primitive = "line_loop"
vertices = [[1.135, 1.385], [10.76, 2.26], [9.385, 10.635], [2.26, 8.385]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]]
[[objects]]
mesh = "arrays"
primitive = "lines"
vertices = [[3.135, 4.135], [7.885, 6.26], [5.135, 3.26], [6.385, 8.885]]
colors = [[1, 0, 1], [0, 1, 1], [1, 1, 1], [0.5, 0.5, 1]]
state = { line_width = 2.4 }
)");
}

TEST_CASE("glslrun matches Mesa on glPolygonOffset", "[reference]") {
    // A decal coplanar with a slanted quad, pulled forward by units and by
    // factor (the slope), and a hidden-line outline: the quad filled, then its
    // edges in line mode, pulled forward with GL_POLYGON_OFFSET_LINE.
    compare_colors("primitive-polygon-offset", R"(
[output]
size = [128, 64]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 16, bottom = 0, top = 8, near = -2, far = 2 }
[state]
depth_test = true
[[objects]]
name = "base"
mesh = "arrays"
primitive = "quads"
vertices = [[0.635, 0.76, -1.3], [7.385, 0.885, 0.7], [7.26, 7.135, 0.7], [0.76, 7.26, -1.3]]
color = [0.8, 0.1, 0.1]
[[objects]]
name = "decal: units only would fight the slope"
mesh = "arrays"
primitive = "quads"
vertices = [[0.635, 0.76, -1.3], [7.385, 0.885, 0.7], [7.26, 7.135, 0.7], [0.76, 7.26, -1.3]]
color = [0.1, 0.8, 0.1]
state = { polygon_offset_fill = true, polygon_offset = [-1, -2] }
[[objects]]
name = "base 2"
mesh = "arrays"
primitive = "triangles"
vertices = [[8.76, 0.635, 0.4], [15.26, 1.135, -0.9], [11.885, 7.26, 0.2]]
color = [0.2, 0.2, 0.9]
[[objects]]
name = "outline"
mesh = "arrays"
primitive = "triangles"
vertices = [[8.76, 0.635, 0.4], [15.26, 1.135, -0.9], [11.885, 7.26, 0.2]]
color = [1, 1, 0]
state = { polygon_mode = "line", polygon_offset_line = true, polygon_offset = [-1, -1], line_width = 2 }
)");
}

TEST_CASE("glslrun matches Mesa on point sprites", "[reference]") {
    // gl_PointCoord (GLSL 1.20) and gl_TexCoord[0] replaced by GL_COORD_REPLACE.
    auto scene = scene::parse_scene(R"(
[output]
size = [96, 64]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 12, bottom = 0, top = 8, near = -1, far = 1 }
[state]
point_sprite = true
coord_replace = [0]
point_size = 12
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[2.135, 2.26], [6.385, 5.135], [9.76, 2.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[3.385, 6.135]]
colors = [[1, 1, 1]]
state = { point_size = 7 }
)", "sprites.toml");
    if (!scene) FAIL(scene.error().str());
    reference::compare("primitive-point-sprite",
                       {{{"sprite.vert", "#version 120\nvoid main() { gl_FrontColor = gl_Color; gl_TexCoord[0] = "
                                         "vec4(0.5); gl_Position = ftransform(); }\n"}},
                        {{"sprite.frag", "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, "
                                         "gl_TexCoord[0].y, 1.0) * gl_Color.r + gl_Color * 0.25; }\n"}},
                        std::move(*scene)});
}

TEST_CASE("glslrun matches Mesa on glCullFace and glFrontFace", "[reference]") {
    compare_colors("primitive-cull-back", shapes("cull_face = \"back\"").c_str());
    compare_colors("primitive-cull-front", shapes("cull_face = \"front\"").c_str());
    compare_colors("primitive-cull-back-cw", shapes("cull_face = \"back\"\nfront_face = \"cw\"").c_str());
    compare_colors("primitive-cull-front-cw", shapes("cull_face = \"front\"\nfront_face = \"cw\"").c_str());
    // Every polygon culled; the points and lines of the last object stay.
    std::string both = shapes("cull_face = \"front_and_back\"") + R"(
[[objects]]
name = "lines stay"
mesh = "arrays"
primitive = "line_strip"
vertices = [[0.635, 5.76], [15.385, 6.135]]
colors = [[1, 1, 1], [1, 0, 1]]
state = { line_width = 4 }
)";
    compare_colors("primitive-cull-front-and-back", both.c_str());
}

namespace {

// Window coordinates that survive the transforms exactly (a 128-pixel
// viewport and an ortho of the same size, powers of two), so that an end
// point meant to lie on a diamond's edge or a pixel's centre does.
const char* kPixelGrid = R"(
[output]
size = [128, 128]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 128, bottom = 0, top = 128, near = -1, far = 1 }
)";

// Where in its pixel an end point lies: the centre, inside the diamond off
// the centre, on the diamond's edge, at the pixel's corner.
const std::array<glm::vec2, 4> kEndPlaces = {{{0.5f, 0.5f}, {0.75f, 0.625f}, {0.75f, 0.75f}, {0.0f, 0.0f}}};

// One line per 8x8 cell: 16 directions (every octant, both slopes of each,
// the axes and the diagonals) times every pair of end places.
std::string octant_lines() {
    const int directions[16][2] = {{5, 2},  {2, 5},  {-2, 5}, {-5, 2}, {-5, -2}, {-2, -5}, {2, -5}, {5, -2},
                                   {4, 0},  {0, 4},  {-4, 0}, {0, -4}, {3, 3},   {-3, 3},  {-3, -3}, {3, -3}};
    std::string vertices, colors;
    int cell = 0;
    for (const auto& dir : directions)
        for (glm::vec2 start : kEndPlaces)
            for (glm::vec2 end : kEndPlaces) {
                glm::vec2 base{float(cell % 16 * 8 + (dir[0] < 0 ? 6 : 1)), float(cell / 16 * 8 + (dir[1] < 0 ? 6 : 1))};
                glm::vec2 a = base + start, b = base + glm::vec2(dir[0], dir[1]) + end;
                vertices += fmt::format("[{}, {}], [{}, {}], ", a.x, a.y, b.x, b.y);
                colors += fmt::format("[1, {}, 0.5], [0.25, 1, {}], ", cell % 7 / 6.0, cell % 5 / 4.0);
                ++cell;
            }
    return fmt::format("{}[[objects]]\nmesh = \"arrays\"\nprimitive = \"lines\"\nvertices = [{}]\ncolors = [{}]\n",
                       kPixelGrid, vertices, colors);
}

}  // namespace

TEST_CASE("glslrun matches Mesa on line ends in and on pixel diamonds", "[reference]") {
    // GL 2.1 §3.4.1's diamond-exit rule decides the first and last pixels.
    compare_colors("primitive-line-diamonds", octant_lines().c_str());
    // Strips and loops whose shared vertices lie at centres, inside diamonds
    // and on their edges, blended additively: a shared vertex's pixel drawn
    // twice (or dropped) shows. Wide, the same ends move whole rows.
    std::string strips = std::string(kPixelGrid) + R"(
[state]
blend = true
blend_func = ["one", "one"]
%s
[[objects]]
mesh = "arrays"
primitive = "line_strip"
vertices = [[4.5, 4.5], [20.75, 9.625], [30.75, 30.75], [9.0, 40.0], [12.5, 60.5], [40.75, 58.625], [44.5, 20.5]]
colors = [[0.25, 0.25, 0.25], [0.25, 0, 0.25], [0, 0.25, 0.25], [0.25, 0.25, 0], [0.25, 0, 0], [0, 0.25, 0], [0, 0, 0.25]]
[[objects]]
mesh = "arrays"
primitive = "line_loop"
vertices = [[70.5, 10.5], [110.75, 14.75], [118.5, 50.5], [90.0, 40.0], [100.75, 70.625], [66.5, 60.5]]
colors = [[0.25, 0.25, 0.25], [0.25, 0, 0.25], [0, 0.25, 0.25], [0.25, 0.25, 0], [0.25, 0, 0], [0, 0.25, 0]]
[[objects]]
mesh = "arrays"
primitive = "line_loop"
vertices = [[20.5, 80.5], [60.5, 80.5], [60.5, 120.5], [20.5, 120.5], [40.75, 100.75]]
colors = [[0.25, 0.25, 0.25], [0.25, 0, 0.25], [0, 0.25, 0.25], [0.25, 0.25, 0], [0.25, 0, 0]]
[[objects]]
mesh = "arrays"
primitive = "line_strip"
vertices = [[80.0, 80.0], [120.0, 84.0], [84.0, 124.0], [124.0, 120.0], [100.25, 100.5]]
colors = [[0.25, 0.25, 0.25], [0.25, 0, 0.25], [0, 0.25, 0.25], [0.25, 0.25, 0], [0.25, 0, 0]]
)";
    compare_colors("primitive-line-strip-diamonds", with_state(strips, "").c_str());
    compare_colors("primitive-line-strip-diamonds-width-3", with_state(strips, "line_width = 3").c_str());
    compare_colors("primitive-line-diamonds-width-2", (octant_lines() + "state = { line_width = 2 }\n").c_str());
}

TEST_CASE("glslrun matches Mesa on polygon edges made by clipping", "[reference]") {
    // Mesa draws a clipped polygon's edges along a user plane, and not those
    // along the view volume; points where an edge comes back into it.
    const char* clip_vertex = R"(
void main() {
    gl_FrontColor = gl_Color;
    gl_BackColor = vec4(1.0) - gl_Color;
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
    gl_Position = ftransform();
}
)";
    auto compare_clipped = [&](const std::string& name, const std::string& toml) {
        compare_colors(name, toml.c_str(), clip_vertex);
    };
    const std::string user_plane = "clip_planes = [[1, -0.35, 0, -4.6], [-0.2, -1, 0, 10.3]]\n";
    compare_clipped("primitive-clip-plane-line", shapes(user_plane + "polygon_mode = \"line\""));
    compare_clipped("primitive-clip-plane-point", shapes(user_plane + "polygon_mode = \"point\""));
    compare_clipped("primitive-clip-plane-line-width-3", shapes(user_plane + "polygon_mode = \"line\"\nline_width = 3"));
    // Through the near plane: a quad and a triangle reaching behind the eye.
    std::string near = R"(
[output]
size = [128, 96]
clear_color = [0, 0, 0, 1]
[camera]
look_at = { eye = [0, 0.5, 4], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 60, near = 1, far = 20 }
[state]
%s
[[objects]]
mesh = "arrays"
primitive = "quads"
vertices = [[-2.1, -1.3, 6.2], [-0.35, -1.1, 6.1], [-0.45, -0.9, -5.3], [-1.9, -1.15, -5.1]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]]
[[objects]]
mesh = "arrays"
primitive = "triangles"
vertices = [[0.35, -0.8, -4.3], [2.2, 0.9, -3.7], [1.1, -0.2, 7.4]]
colors = [[0, 1, 1], [1, 0, 1], [1, 1, 1]]
)";
    compare_clipped("primitive-near-plane-line", with_state(near, "polygon_mode = \"line\""));
    compare_clipped("primitive-near-plane-point", with_state(near, "polygon_mode = \"point\"\npoint_size = 6"));
}
