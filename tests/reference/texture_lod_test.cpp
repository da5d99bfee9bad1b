// glslrun against Mesa on ARB_shader_texture_lod in the fragment shader:
// texture2DLod, texture2DProjLod, textureCubeLod with explicit levels, and
// the Grad forms (texture2DGradARB, texture2DProjGradARB, shadow2DGradARB)
// whose gradients set lambda. Each level of the 64x64 texture has its own
// colour, so the picture names the level; the explicit levels and the
// gradients are powers of two or halfway between them, where llvmpipe's
// piecewise-linear log2 is exact.
#include <string>

#include <fmt/format.h>

#include "tests/reference/helpers.h"

using namespace glslrun;

namespace {

const char* kFragment = R"(
#extension GL_ARB_shader_texture_lod : require
uniform sampler2D tex;
uniform samplerCube cube;
uniform int mode;
uniform float lod;
void main() {
    vec2 st = gl_TexCoord[0].st;
    vec2 g = vec2(lod / 64.0, 0.0);  // |gradient| = lod texels of level 0
    if (mode == 0) gl_FragColor = texture2DLod(tex, st, lod);
    else if (mode == 1) gl_FragColor = texture2DProjLod(tex, vec3(st * 2.0, 2.0), lod);
    else if (mode == 2) gl_FragColor = texture2DGradARB(tex, st, g, g.yx);
    else if (mode == 3) gl_FragColor = texture2DProjGradARB(tex, vec4(st * 4.0, 0.0, 4.0), g.yx, g);
    else gl_FragColor = textureCubeLod(cube, vec3(1.0, st * 2.0 - 1.0), lod);
}
)";

std::string levels() {
    const char* colors[] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]", "[1, 1, 1]", "[1, 1, 0]", "[0, 1, 1]", "[1, 0, 1]"};
    std::string out = "levels = [\n";
    for (int level = 0; level < 7; ++level)
        out += fmt::format("  {{ solid = {{ size = [{0}, {0}], color = {1} }} }},\n", 64 >> level, colors[level]);
    return out + "]\n";
}

std::string lod_scene() {
    std::string toml = "[output]\nsize = [288, 144]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
                       "ortho = { left = 0, right = 288, bottom = 0, top = 144, near = -1, far = 1 }\n";
    toml += "[textures.0]\nmin_filter = \"linear_mipmap_linear\"\n" + levels();
    toml += "[textures.1]\ntarget = \"cube_map\"\ncheckerboard = { size = [16, 16], square_size = 4 }\n"
            "generate_mipmap = true\nmin_filter = \"nearest_mipmap_nearest\"\n";
    toml += "[uniforms]\ntex = 0\ncube = 1\n";
    struct Case {
        int mode;
        float lod;  // the level, or the gradient's length in texels
    };
    const Case cases[] = {{0, 0.0f}, {0, 2.0f}, {0, 1.5f}, {1, 3.0f}, {2, 4.0f},
                          {2, 1.0f}, {3, 8.0f}, {4, 2.0f}};
    for (int i = 0; i < 8; ++i) {
        const int x = 4 + 72 * (i % 4), y = 4 + 72 * (i / 4);
        toml += fmt::format("[[objects]]\nmesh = \"plane\"\n"
                            "transform = [ {{ translate = [{}, {}, 0] }}, {{ scale = [64, 64, 1] }} ]\n"
                            "uniforms = {{ mode = {}, lod = {:.1f} }}\n",
                            x + 32, y + 32, cases[i].mode, cases[i].lod);
    }
    return toml;
}

const char* kShadowFragment = R"(
#extension GL_ARB_shader_texture_lod : require
uniform sampler2DShadow tex;
void main() {
    vec2 st = gl_TexCoord[0].st;
    gl_FragColor = shadow2DGradARB(tex, vec3(st, 0.5), vec2(1.0 / 16.0, 0.0), vec2(0.0, 1.0 / 16.0));
}
)";

std::string shadow_scene() {
    return "[output]\nsize = [72, 72]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
           "ortho = { left = 0, right = 72, bottom = 0, top = 72, near = -1, far = 1 }\n"
           "[textures.0]\ninternal_format = \"depth_component\"\n"
           "checkerboard = { size = [32, 32], square_size = 4, colors = [0.25, 0.75] }\n"
           "generate_mipmap = true\nmin_filter = \"nearest_mipmap_nearest\"\nmag_filter = \"nearest\"\n"
           "compare_mode = \"compare_r_to_texture\"\n"
           "[uniforms]\ntex = 0\n"
           "[[objects]]\nmesh = \"plane\"\n"
           "transform = [ { translate = [36, 36, 0] }, { scale = [64, 64, 1] } ]\n";
}

// Gradients that differ between the columns of a quad: each fragment's own
// choose its level, as GL says and llvmpipe does (the screen's derivatives
// are shared by a quad, the program's are not).
const char* kGradPerFragment = R"(
#extension GL_ARB_shader_texture_lod : require
uniform sampler2D tex;
void main() {
    float texels = mod(floor(gl_FragCoord.x), 2.0) == 1.0 ? 8.0 : 1.0;  // level 3 or level 0
    vec2 g = vec2(texels / 64.0, 0.0);
    gl_FragColor = texture2DGradARB(tex, gl_TexCoord[0].st, g, g.yx);
}
)";

std::string grad_per_fragment_scene() {
    return "[output]\nsize = [24, 16]\nclear_color = [0.1, 0.1, 0.1, 1]\n[camera]\n"
           "ortho = { left = -1, right = 1, bottom = -1, top = 1, near = -1, far = 1 }\n"
           "[textures.0]\nmin_filter = \"nearest_mipmap_nearest\"\n" + levels() +
           "[uniforms]\ntex = 0\n[[objects]]\nmesh = \"plane\"\nsize = 2\n";
}

reference::Inputs inputs(const std::string& name, const std::string& toml, const char* fragment) {
    return reference::scene_inputs(name, toml, reference::kTextureMatrixVertex, fragment);
}

}  // namespace

TEST_CASE("glslrun matches Mesa on ARB_shader_texture_lod's Lod and Grad lookups", "[reference][textures][lod]") {
    reference::compare("texture_lod", inputs("texture_lod", lod_scene(), kFragment));
}

TEST_CASE("glslrun matches Mesa on shadow2DGradARB with a mipmapped depth texture", "[reference][textures][lod]") {
    reference::compare("shadow_grad", inputs("shadow_grad", shadow_scene(), kShadowFragment));
}

TEST_CASE("texture2DGradARB's gradients are each fragment's, in every mode", "[reference][textures][lod]") {
    reference::compare_in_every_mode("grad_per_fragment",
                                     inputs("grad_per_fragment", grad_per_fragment_scene(), kGradPerFragment));
}
