// glslrun against Mesa on EXT_texture_array in GLSL 1.10: a mipmapped 2D
// array (trilinear, with a bias), a 1D array, and a shadow 2D array, each
// plane choosing its layer by a uniform, in range, rounded and clamped (no
// ties at k + 1/2, where the rounding rule is the extension's own and
// llvmpipe's may differ). The minified planes have rho = 2 or a bias to an
// integer lambda, where llvmpipe's approximate log2 is exact (at rho = 1.5
// its lambda made 0.4% of the pixels differ by 2/255). Measured: every byte
// the same as Mesa's.
#include <string>

#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* kFragment = R"(
#extension GL_EXT_texture_array : enable
uniform sampler2DArray tex;
uniform sampler1DArray strip;
uniform int mode;
uniform float layer;
void main() {
    vec2 st = gl_TexCoord[0].st;
    if (mode == 0) gl_FragColor = texture2DArray(tex, vec3(st * 4.0, layer));  // rho = 2: lambda = 1
    else if (mode == 1) gl_FragColor = texture2DArray(tex, vec3(st, layer), 1.0);
    else gl_FragColor = texture1DArray(strip, vec2(st.s * 2.0, layer));
}
)";

std::string array_scene() {
    std::string toml = "[output]\nsize = [288, 216]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
                       "ortho = { left = 0, right = 288, bottom = 0, top = 216, near = -1, far = 1 }\n";
    toml += "[textures.0]\ntarget = \"2d_array\"\ngenerate_mipmap = true\nmin_filter = \"linear_mipmap_linear\"\n"
            "layers = [\n"
            "  { checkerboard = { size = [32, 32], square_size = 4, colors = [[1, 0, 0], [1, 1, 1]] } },\n"
            "  { rgbw = { size = [32, 32] } },\n"
            "  { checkerboard = { size = [32, 32], square_size = 8, colors = [[0, 0, 1], [0, 1, 0]] } },\n"
            "  { solid = { size = [32, 32], color = [1, 1, 0] } },\n"
            "]\n";
    toml += "[textures.1]\ntarget = \"1d_array\"\nmin_filter = \"linear\"\nwrap_s = \"repeat\"\n"
            "layers = [ { rgbw = { size = [8] } }, { checkerboard = { size = [8], square_size = 2 } } ]\n";
    toml += "[uniforms]\ntex = 0\nstrip = 1\n";
    struct Case {
        int mode;
        float layer;
    };
    const Case cases[] = {{0, 0.0f}, {0, 1.3f}, {0, 2.7f}, {0, 9.0f}, {1, 1.0f}, {1, -2.0f},
                          {1, 2.2f}, {2, 0.0f}, {2, 0.9f}, {2, 5.0f}, {0, 3.0f}, {1, 0.4f}};
    for (int i = 0; i < 12; ++i) {
        const int x = 4 + 72 * (i % 4), y = 4 + 72 * (i / 4);
        toml += fmt::format("[[objects]]\nmesh = \"plane\"\n"
                            "transform = [ {{ translate = [{}, {}, 0] }}, {{ scale = [64, 64, 1] }} ]\n"
                            "uniforms = {{ mode = {}, layer = {:.1f} }}\n",
                            x + 32, y + 32, cases[i].mode, cases[i].layer);
    }
    return toml;
}

const char* kShadowFragment = R"(
#extension GL_EXT_texture_array : require
uniform sampler2DArrayShadow tex;
uniform float layer;
void main() {
    vec2 st = gl_TexCoord[0].st;
    gl_FragColor = shadow2DArray(tex, vec4(st, layer, 0.5));
}
)";

std::string shadow_scene() {
    std::string toml = "[output]\nsize = [144, 72]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
                       "ortho = { left = 0, right = 144, bottom = 0, top = 72, near = -1, far = 1 }\n"
                       "[textures.0]\ntarget = \"2d_array\"\ninternal_format = \"depth_component\"\n"
                       "min_filter = \"linear\"\ncompare_mode = \"compare_r_to_texture\"\n"
                       "layers = [\n"
                       "  { checkerboard = { size = [16, 16], square_size = 4, colors = [0.25, 0.75] } },\n"
                       "  { checkerboard = { size = [16, 16], square_size = 2, colors = [0.75, 0.25] } },\n"
                       "]\n[uniforms]\ntex = 0\n";
    for (int i = 0; i < 2; ++i)
        toml += fmt::format("[[objects]]\nmesh = \"plane\"\n"
                            "transform = [ {{ translate = [{}, 36, 0] }}, {{ scale = [64, 64, 1] }} ]\n"
                            "uniforms = {{ layer = {:.1f} }}\n",
                            36 + 72 * i, i == 0 ? 0.2f : 1.1f);
    return toml;
}

reference::Inputs inputs(const std::string& name, const std::string& toml, const char* fragment) {
    return reference::scene_inputs(name, toml, reference::kTextureMatrixVertex, fragment);
}

}  // namespace

TEST_CASE("glslrun matches Mesa on EXT_texture_array's 1D and 2D arrays", "[reference][textures][array]") {
    reference::compare("texture_array", inputs("texture_array", array_scene(), kFragment));
}

TEST_CASE("glslrun matches Mesa on shadow2DArray", "[reference][textures][array]") {
    reference::compare("texture_array_shadow", inputs("texture_array_shadow", shadow_scene(), kShadowFragment));
}
