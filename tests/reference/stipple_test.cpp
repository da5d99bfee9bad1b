// glslrun against Mesa on line and polygon stipple (GL 2.1 §3.5.2,
// §3.6.2): the counter restarted per line of GL_LINES and per strip, carried
// along strips and around a loop's closing line, repeat factors above 1,
// wide and diagonal lines, lines in perspective, the edges of
// glPolygonMode(GL_LINE); the window-aligned polygon pattern on small and
// large triangles, quads and polygons, with the depth test, and not on
// points, lines or unfilled polygons. Every case in Precise and Fast, and
// the same images on both backends and at 1 and 2 threads.
#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* kColorVertex = "void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }\n";
const char* kColorFragment = "void main() { gl_FragColor = gl_Color; }\n";

reference::Inputs inputs(const std::string& name, const std::string& toml) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    return {{{name + ".vert", kColorVertex}}, {{name + ".frag", kColorFragment}}, std::move(*scene)};
}

// Lines, strips and a loop at fractional positions, x- and y-major, with
// colours that change along them (the runs' ends are interpolated).
const char* kLines = R"(
[output]
size = [160, 120]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 40, bottom = 0, top = 30, near = -1, far = 1 }
[[objects]]
name = "lines"
mesh = "arrays"
primitive = "lines"
vertices = [[1.13, 1.27], [17.61, 2.39], [17.61, 2.39], [38.2, 1.6], [2.3, 4.1], [9.6, 13.7], [36.4, 28.1], [30.2, 5.35]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 1, 1], [1, 0.5, 0]]
[[objects]]
name = "strip"
mesh = "arrays"
primitive = "line_strip"
vertices = [[1.4, 16.3], [7.77, 17.1], [11.2, 26.9], [19.63, 27.4], [23.1, 18.2], [28.9, 19.9]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]]
[[objects]]
name = "loop"
mesh = "arrays"
primitive = "line_loop"
vertices = [[12.3, 6.2], [26.7, 7.9], [25.1, 14.6], [14.2, 13.3]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0]]
)";

std::string lines(const std::string& state) { return std::string(kLines) + "[state]\nline_stipple = true\n" + state; }

}  // namespace

TEST_CASE("glslrun matches Mesa on line stipple", "[reference][stipple]") {
    reference::compare_in_every_mode("stipple-lines", inputs("lines", lines("line_stipple_pattern = 0x0F0F\n")));
    reference::compare_in_every_mode("stipple-lines-odd",
                                     inputs("odd", lines("line_stipple_pattern = 0b0110111010110001\n")));
    reference::compare_in_every_mode(
        "stipple-lines-repeat", inputs("repeat", lines("line_stipple_pattern = 0x3C0F\nline_stipple_repeat = 3\n")));
    reference::compare_in_every_mode(
        "stipple-lines-wide",
        inputs("wide", lines("line_stipple_pattern = 0x00FF\nline_stipple_repeat = 2\nline_width = 3\n")));
    reference::compare_in_every_mode("stipple-lines-wide-even",
                                     inputs("wide-even", lines("line_stipple_pattern = 0xF0F0\nline_width = 4.4\n")));
    // The pattern of all ones draws the lines whole, as without the stipple.
    reference::compare_in_every_mode("stipple-lines-ones", inputs("ones", lines("line_stipple_pattern = 0xFFFF\n")));
}

TEST_CASE("glslrun matches Mesa on stippled lines in perspective and on polygon edges", "[reference][stipple]") {
    reference::compare_in_every_mode("stipple-lines-perspective", inputs("perspective", R"(
[output]
size = [160, 120]
clear_color = [0, 0, 0, 1]
[camera]
look_at = { eye = [0, 2, 6], center = [0, 0, -4], up = [0, 1, 0] }
perspective = { fovy = 50, near = 1, far = 40 }
[state]
line_stipple = true
line_stipple_pattern = 0x33FF
line_width = 3
depth_test = true
[[objects]]
mesh = "arrays"
primitive = "line_strip"
vertices = [[-4, -1, 2], [-2, 0.5, -8], [1.5, -0.7, -16], [3.3, 1.2, -3], [4.1, -1.6, 1.5]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
)"));
    // The counter restarts per polygon and runs along its edges in the order they are drawn.
    reference::compare_in_every_mode("stipple-polygon-edges", inputs("edges", R"(
[output]
size = [160, 96]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 20, bottom = 0, top = 12, near = -1, far = 1 }
[state]
polygon_mode = "line"
line_stipple = true
line_stipple_pattern = 0x1F1F
[[objects]]
mesh = "arrays"
primitive = "quads"
vertices = [[1.135, 1.26], [8.385, 1.385], [8.135, 5.26], [1.26, 4.885], [10.26, 1.135], [18.385, 1.385], [18.135, 5.635], [10.385, 4.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 1, 1], [1, 0.5, 0]]
[[objects]]
mesh = "arrays"
primitive = "triangle_strip"
vertices = [[1.26, 6.635], [2.135, 10.76], [6.385, 6.885], [7.26, 10.385], [11.635, 6.76], [12.385, 10.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]]
[[objects]]
mesh = "arrays"
primitive = "polygon"
vertices = [[16.135, 6.26], [13.385, 7.76], [14.26, 11.135], [17.635, 11.385], [18.76, 8.885]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
)"));
}

namespace {

// Triangles small (one 8x8 square) and large (the block walk), a quad and a
// polygon, overlapping under the depth test; a point, a line and an
// unfilled quad, which the polygon stipple leaves alone.
const char* kPolygons = R"(
[output]
size = [200, 150]
clear_color = [0, 0, 0, 1]
[camera]
ortho = { left = 0, right = 40, bottom = 0, top = 30, near = -1, far = 1 }
[state]
depth_test = true
polygon_stipple = true
point_size = 5
line_width = 2
%s
[[objects]]
mesh = "arrays"
primitive = "triangles"
vertices = [[1.1, 1.3, 0], [38.7, 2.2, 0.5], [20.3, 28.6, -0.5], [2.2, 20.1, 0.2], [3.1, 21.4, 0.2], [2.4, 22.2, 0.2]]
colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1], [1, 1, 1], [1, 1, 1]]
[[objects]]
mesh = "arrays"
primitive = "quads"
vertices = [[5.3, 5.1, -0.3], [25.7, 6.2, -0.3], [24.4, 18.3, 0.6], [6.1, 17.7, 0.6]]
colors = [[1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 1, 1]]
[[objects]]
mesh = "arrays"
primitive = "polygon"
vertices = [[30.1, 16.2], [38.4, 18.3], [37.9, 27.2], [31.3, 28.8], [27.7, 23.1]]
colors = [[0.5, 1, 0], [0, 0.5, 1], [1, 0, 0.5], [1, 1, 1], [0.5, 0.5, 0.5]]
[[objects]]
mesh = "arrays"
primitive = "points"
vertices = [[34.3, 9.6]]
colors = [[1, 1, 1]]
[[objects]]
mesh = "arrays"
primitive = "lines"
vertices = [[27.2, 12.1], [39.1, 14.6]]
colors = [[1, 1, 1], [0, 1, 0]]
[[objects]]
mesh = "arrays"
primitive = "quads"
vertices = [[1.5, 24.1], [9.2, 24.3], [9.4, 28.8], [1.6, 28.5]]
colors = [[1, 1, 1], [1, 1, 1], [1, 1, 1], [1, 1, 1]]
[objects.state]
polygon_mode = "line"
)";

std::string polygons(const std::string& pattern) {
    std::string text = kPolygons;
    text.replace(text.find("%s"), 2, pattern);
    return text;
}

// 32 rows of a pattern with no symmetry: each row's bits differ from its neighbours'.
std::string irregular_pattern() {
    std::string rows;
    uint32_t v = 0x9E3779B9u;
    for (int i = 0; i < 32; ++i) {
        v ^= v << 13, v ^= v >> 17, v ^= v << 5;
        rows += fmt::format("{}{:#010x}", i ? ", " : "", v);
    }
    return "polygon_stipple_pattern = [" + rows + "]";
}

}  // namespace

TEST_CASE("glslrun matches Mesa on polygon stipple", "[reference][stipple]") {
    reference::compare_in_every_mode("stipple-polygon-checker",
                                     inputs("checker", polygons("polygon_stipple_pattern = [0xAAAAAAAA, 0x55555555]")));
    reference::compare_in_every_mode("stipple-polygon-irregular", inputs("irregular", polygons(irregular_pattern())));
    // GL's default pattern, all ones, draws every pixel.
    reference::compare_in_every_mode("stipple-polygon-ones", inputs("ones", polygons("")));
}
