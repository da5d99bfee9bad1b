// glslrun against Mesa on rectangle textures (ARB_texture_rectangle):
// unnormalized coordinates with each wrap mode a rectangle allows (CLAMP,
// CLAMP_TO_EDGE, CLAMP_TO_BORDER), NEAREST and LINEAR, the projective forms,
// minification, and sampler2DRectShadow with its depth comparison.
//
// Every square is 64 pixels under a pixel-exact camera and shows texels
// [-2, 14] x [-2, 6] of a 12x4 texture: a pixel is 1/4 texel wide and 1/8
// high, so no pixel centre falls on a texel edge (NEAREST) or a texel centre
// (LINEAR) and the weights are exact binary fractions.
#include <string>

#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

// No #extension line: Mesa enables ARB_texture_rectangle in every shader.
const char* kRectFragment = R"(
uniform sampler2DRect tex;
uniform int mode;
void main() {
    vec4 c = gl_TexCoord[0];
    if (mode == 1) gl_FragColor = texture2DRectProj(tex, vec3(c.st * 2.0, 2.0));
    else if (mode == 2) gl_FragColor = texture2DRectProj(tex, vec4(c.st * 4.0, 0.5, 4.0));
    else gl_FragColor = texture2DRect(tex, c.st);
}
)";

const char* kShadowFragment = R"(
#extension GL_ARB_texture_rectangle : require
uniform sampler2DRectShadow tex;
uniform int mode;
void main() {
    vec4 c = gl_TexCoord[0];
    if (mode == 1) gl_FragColor = shadow2DRectProj(tex, vec4(c.st * 2.0, 1.0, 2.0));
    else gl_FragColor = shadow2DRect(tex, vec3(c.st, 0.5));
}
)";

// Where a rectangle is magnified (rho < 1 over its texels, as
// ARB_texture_rectangle computes it) and the two filters differ, llvmpipe
// applies the min filter: it scales rho by the texture's size as for a 2D
// texture (docs/semantics.md). So the NEAREST squares that magnify set both.

std::string camera(int width, int height) {
    return fmt::format("[output]\nsize = [{0}, {1}]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
                       "ortho = {{ left = 0, right = {0}, bottom = 0, top = {1}, near = -1, far = 1 }}\n"
                       "[texture_matrix.0]\ntransform = [ {{ translate = [-2, -2, 0] }}, {{ scale = [16, 8, 1] }} ]\n",
                       width, height);
}

// A square of `size` pixels in cell `cell`. The 8-pixel squares show 2 texels
// a pixel; a quarter-pixel shift keeps their pixel centres off texel edges.
std::string square(int cell, int size, const std::string& uniforms) {
    const double shift = size == 8 ? 0.25 : 0.0;
    const double x = 4 + 72 * (cell % 4) + shift, y = 4 + 72 * (cell / 4) + shift;
    return fmt::format("[[objects]]\nmesh = \"plane\"\n"
                       "transform = [ {{ translate = [{}, {}, 0] }}, {{ scale = [{}, {}, 1] }} ]\n"
                       "uniforms = {{ {} }}\n",
                       x + size / 2.0, y + size / 2.0, size, size, uniforms);
}

std::string rect_scene() {
    struct Case {
        const char* sampler;
        int size, mode;
    };
    const Case cases[] = {
        {"wrap_s = \"clamp_to_edge\"\nwrap_t = \"clamp_to_edge\"\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"", 64, 0},
        {"wrap_s = \"clamp\"\nwrap_t = \"clamp\"\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"", 64, 0},
        {"wrap_s = \"clamp_to_border\"\nwrap_t = \"clamp_to_border\"\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"\n"
         "border_color = [0.2, 0.4, 0.6, 1]", 64, 0},
        {"", 64, 0},  // GL's defaults for a rectangle: LINEAR, CLAMP_TO_EDGE
        {"wrap_s = \"clamp\"\nwrap_t = \"clamp\"\nborder_color = [1, 0, 1, 1]", 64, 0},
        {"wrap_s = \"clamp_to_border\"\nwrap_t = \"clamp_to_edge\"\nborder_color = [0, 1, 0, 0.5]", 64, 0},
        {"min_filter = \"nearest\"\nmag_filter = \"nearest\"", 64, 1},
        {"wrap_s = \"clamp_to_border\"\nwrap_t = \"clamp_to_border\"", 64, 2},
        // 16 pixels over 16 texels across, 8 up: rho = 1 exactly, lambda = 0.
        {"wrap_s = \"clamp\"\nwrap_t = \"clamp_to_border\"", 16, 0},
        // 8 pixels over 16 texels: lambda = 1, minified: the min filter.
        {"min_filter = \"nearest\"\nmag_filter = \"linear\"", 8, 0},
        {"min_filter = \"linear\"\nmag_filter = \"nearest\"", 8, 0},
    };
    std::string toml = camera(288, 216);
    for (int u = 0; u < 11; ++u) {
        toml += fmt::format("[textures.{}]\ntarget = \"rectangle\"\n"
                            "checkerboard = {{ size = [12, 4], square_size = [3, 1], "
                            "colors = [[1, 0.5, 0, 1], [0, 0.25, 1, 1]] }}\n{}\n",
                            u, cases[u].sampler);
        toml += square(u, cases[u].size, fmt::format("tex = {}, mode = {}", u, cases[u].mode));
    }
    return toml;
}

std::string shadow_scene() {
    const char* units[] = {
        "compare_func = \"lequal\"\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"",
        "compare_func = \"greater\"\ndepth_texture_mode = \"intensity\"",
        "compare_func = \"lequal\"\nwrap_s = \"clamp_to_border\"\nborder_color = [0.6, 0, 0, 0]",
        "compare_func = \"lequal\"\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"",
    };
    std::string toml = camera(288, 72);
    for (int u = 0; u < 4; ++u) {
        toml += fmt::format("[textures.{}]\ntarget = \"rectangle\"\ninternal_format = \"depth_component\"\n"
                            "checkerboard = {{ size = [12, 4], square_size = [3, 1], colors = [0.25, 0.75] }}\n"
                            "compare_mode = \"compare_r_to_texture\"\n{}\n",
                            u, units[u]);
        toml += square(u, 64, fmt::format("tex = {}, mode = {}", u, u == 3 ? 1 : 0));
    }
    return toml;
}

reference::Inputs inputs(const std::string& name, const std::string& toml, const char* fragment) {
    return reference::scene_inputs(name, toml, reference::kTextureMatrixVertex, fragment);
}

}  // namespace

TEST_CASE("glslrun matches Mesa on rectangle textures: wraps, filters, projection, minification",
          "[reference][textures][rectangle]") {
    reference::compare("rectangle", inputs("rectangle", rect_scene(), kRectFragment));
}

TEST_CASE("glslrun matches Mesa on sampler2DRectShadow", "[reference][textures][rectangle]") {
    reference::compare("rectangle_shadow", inputs("rectangle_shadow", shadow_scene(), kShadowFragment));
}
