// glslrun against Mesa on texture sampling state: wrap modes and the border,
// nearest and linear filters, mipmap level selection (min/max LOD, LOD bias,
// base and max level, the shader's bias), depth comparison with every depth
// texture mode, an incomplete texture, 1D and 3D textures.
//
// Every scene draws screen-aligned squares under a pixel-exact orthographic
// camera, so texel footprints are exact binary fractions: no pixel centre
// falls on a texel edge, and the level of detail is an exact integer or
// integer + 1/4 before any bias. That matters because llvmpipe computes
// log2(rho) with a piecewise-linear approximation (exact at powers of two,
// up to 0.043 low elsewhere) and one LOD per 2x2 quad; at any other scale a
// trilinear blend of two unlike levels would differ from glslrun's exact one
// by more than the 1/255 tolerance without either being wrong.
#include <string>

#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* k2DFragment = R"(
uniform sampler2D tex;
uniform float bias;
void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].st, bias); }
)";

// An orthographic camera in pixels, and a `size`-pixel square at (x, y).
std::string pixel_camera(int width, int height) {
    return fmt::format("[output]\nsize = [{0}, {1}]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
                       "ortho = {{ left = 0, right = {0}, bottom = 0, top = {1}, near = -1, far = 1 }}\n",
                       width, height);
}

std::string square(int x, int y, int size, const std::string& uniforms) {
    return fmt::format("[[objects]]\nmesh = \"plane\"\n"
                       "transform = [ {{ translate = [{}, {}, 0] }}, {{ scale = [{}, {}, 1] }} ]\n"
                       "uniforms = {{ {} }}\n",
                       x + size / 2.0, y + size / 2.0, size, size, uniforms);
}

// ------------------------------------------------- wraps and filters ---
// rgbw 4x4 seen over s, t in [-1, 2] (the texture matrix), 4 pixels a texel.
std::string wrap_scene() {
    std::string toml = pixel_camera(256, 128);
    toml += "[texture_matrix.0]\ntransform = [ { translate = [-1, -1, 0] }, { scale = [3, 3, 1] } ]\n";
    const char* units[] = {
        R"(wrap_s = "repeat"
wrap_t = "repeat"
mag_filter = "nearest")",
        R"(wrap_s = "mirrored_repeat"
wrap_t = "mirrored_repeat"
mag_filter = "nearest")",
        R"(wrap_s = "clamp_to_edge"
wrap_t = "mirrored_repeat"
mag_filter = "nearest")",
        R"(wrap_s = "clamp_to_border"
wrap_t = "clamp_to_border"
mag_filter = "nearest"
border_color = [0.2, 0.4, 0.6, 1])",
        R"(wrap_s = "clamp"
wrap_t = "clamp"
mag_filter = "linear"
border_color = [1, 0, 1, 1])",
        R"(wrap_s = "clamp_to_edge"
wrap_t = "repeat"
mag_filter = "linear")",
        R"(wrap_s = "clamp_to_border"
wrap_t = "clamp_to_edge"
mag_filter = "linear"
border_color = [0, 0, 0, 0])",
    };
    for (int u = 0; u < 7; ++u) {
        toml += fmt::format("[textures.{}]\nrgbw = {{ size = [4, 4], alpha = true }}\nmin_filter = \"nearest\"\n{}\n",
                            u, units[u]);
        toml += square(8 + 64 * (u % 4), 8 + 64 * (u / 4), 48, fmt::format("tex = {}", u));
    }
    // GL's default min filter on a texture without mipmaps: incomplete, so (0, 0, 0, 1).
    toml += "[textures.7]\nrgbw = { size = [4, 4] }\n";
    toml += square(8 + 64 * 3, 8 + 64, 48, "tex = 7");
    return toml;
}

// ------------------------------------------------------------ mipmaps ---
// 64x64 with levels of one colour each, so the picture names the level.
std::string mip_levels() {
    const char* colors[] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]", "[1, 1, 1]", "[1, 1, 0]", "[0, 1, 1]", "[1, 0, 1]"};
    std::string levels = "levels = [\n";
    for (int level = 0; level < 7; ++level)
        levels += fmt::format("  {{ solid = {{ size = [{0}, {0}], color = {1} }} }},\n", 64 >> level, colors[level]);
    return levels + "]\n";
}

struct MipCase {
    const char* sampler;  // glTexParameter keys
    int size;             // pixels: lambda = log2(64 / size)
    float bias;           // the shader's texture2D bias
};

std::string mip_scene() {
    const MipCase cases[] = {
        {R"(min_filter = "nearest_mipmap_nearest")", 32, 0},                          // level 1
        {R"(min_filter = "linear_mipmap_linear"
lod_bias = 0.25)", 32, 0},                                                            // 3/4 level 1 + 1/4 level 2
        {R"(min_filter = "linear_mipmap_nearest")", 16, 0},                           // level 2
        {R"(min_filter = "linear_mipmap_linear"
min_lod = 2.5)", 32, 0},                                                              // half level 2, half level 3
        {R"(min_filter = "nearest_mipmap_nearest"
base_level = 1)", 16, 0},                                                             // level 2: lambda from level 1
        {R"(min_filter = "linear_mipmap_linear"
max_level = 1)", 8, 0},                                                               // level 1 at most
        {R"(min_filter = "nearest_mipmap_linear"
max_lod = 1.75)", 8, 0},                                                              // 1/4 level 1 + 3/4 level 2
        {R"(min_filter = "nearest_mipmap_nearest")", 32, 1.0f},                       // the shader's bias: level 2
        {R"(min_filter = "linear_mipmap_linear")", 64, -0.75f},                       // magnification (lambda < 0)
    };
    std::string toml = pixel_camera(288, 216);
    for (int u = 0; u < 9; ++u) {
        const MipCase& c = cases[u];
        toml += fmt::format("[textures.{}]\n{}\n{}", u, c.sampler, mip_levels());
        toml += square(4 + 72 * (u % 4), 4 + 72 * (u / 4), c.size,
                       fmt::format("tex = {}, bias = {:.2f}", u, c.bias));
    }
    return toml;
}

// ------------------------------------------------------------- depth ---
// A depth checkerboard (0.25, 0.75) compared with 0.5: each square is 0 or 1.
const char* kShadowFragment = R"(
uniform sampler2DShadow tex;
uniform float ref;
void main() { gl_FragColor = shadow2D(tex, vec3(gl_TexCoord[0].st, ref)); }
)";

std::string shadow_scene() {
    const char* units[] = {
        R"(compare_func = "lequal")",
        R"(compare_func = "greater"
depth_texture_mode = "intensity")",
        R"(compare_func = "lequal"
depth_texture_mode = "alpha")",
        R"(compare_func = "always")",
    };
    std::string toml = pixel_camera(256, 64);
    for (int u = 0; u < 4; ++u) {
        toml += fmt::format("[textures.{}]\ninternal_format = \"depth_component\"\n"
                            "checkerboard = {{ size = [8, 8], square_size = 2, colors = [0.25, 0.75] }}\n"
                            "min_filter = \"nearest\"\nmag_filter = \"nearest\"\n"
                            "compare_mode = \"compare_r_to_texture\"\n{}\n", u, units[u]);
        toml += square(8 + 64 * u, 8, 48, fmt::format("tex = {}, ref = {}", u, u == 3 ? 0.9 : 0.5));
    }
    return toml;
}

// A depth texture without comparison reads its depth as a luminance.
std::string depth_scene() {
    return pixel_camera(64, 64) +
           "[textures.0]\ninternal_format = \"depth_component\"\n"
           "checkerboard = { size = [8, 8], square_size = 2, colors = [0.25, 0.75] }\n"
           "min_filter = \"nearest\"\nmag_filter = \"linear\"\n" +
           square(8, 8, 48, "tex = 0, bias = 0.0");
}

// ------------------------------------------------------------ 1D, 3D ---
const char* k1D3DFragment = R"(
uniform sampler1D strip;
uniform sampler3D volume;
void main() {
    vec4 a = texture1D(strip, gl_TexCoord[0].s);
    vec4 b = texture3D(volume, gl_TexCoord[0].stp);
    gl_FragColor = mix(a, b, step(0.5, gl_TexCoord[0].t));
}
)";

std::string dims_scene() {
    std::string toml = pixel_camera(128, 64);
    toml += "[texture_matrix.0]\nmatrix = [1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0.75, 1]   # r = 0.75\n";
    toml += "[textures.0]\ntarget = \"1d\"\nrgbw = { size = [8] }\nmin_filter = \"nearest\"\nmag_filter = \"nearest\"\n";
    toml += "[textures.1]\ntarget = \"3d\"\nrgbw = { size = [2, 2, 2] }\nmin_filter = \"nearest\"\n"
            "mag_filter = \"nearest\"\n";
    toml += "[textures.2]\ntarget = \"1d\"\nrgbw = { size = [8] }\nmin_filter = \"linear\"\nwrap_s = \"clamp_to_edge\"\n";
    toml += "[textures.3]\ntarget = \"3d\"\ncheckerboard = { size = [4, 4, 4], square_size = 1 }\n"
            "min_filter = \"linear\"\nwrap_r = \"mirrored_repeat\"\n";
    toml += square(4, 4, 56, "strip = 0, volume = 1");
    toml += square(68, 4, 56, "strip = 2, volume = 3");
    return toml;
}

reference::Inputs inputs(const std::string& name, const std::string& toml, const char* fragment) {
    return reference::scene_inputs(name, toml, reference::kTextureMatrixVertex, fragment);
}

}  // namespace

TEST_CASE("glslrun matches Mesa on wrap modes, the border, filters and an incomplete texture", "[reference][textures]") {
    reference::compare("textures-wrap", inputs("wrap", wrap_scene(), k2DFragment));
}

TEST_CASE("glslrun matches Mesa on mipmap level selection", "[reference][textures]") {
    reference::compare("textures-mipmaps", inputs("mipmaps", mip_scene(), k2DFragment));
}

TEST_CASE("glslrun matches Mesa on depth comparison and depth texture modes", "[reference][textures]") {
    reference::compare("textures-shadow", inputs("shadow", shadow_scene(), kShadowFragment));
    reference::compare("textures-depth", inputs("depth", depth_scene(), k2DFragment));
}

TEST_CASE("glslrun matches Mesa on 1D and 3D textures", "[reference][textures]") {
    reference::compare("textures-1d-3d", inputs("dims", dims_scene(), k1D3DFragment));
}
