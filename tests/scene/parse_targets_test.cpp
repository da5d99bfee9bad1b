// [render_targets.NAME], the passes that draw into them (target, clear,
// camera), the textures that sample them, [state] viewport, and the
// projection entries of transform lists; and their mistakes.
#include <limits>

#include "glslrun/scene/render.h"
#include "parse_helpers.h"

using namespace scene_test;

namespace {

const char* kTarget = R"([render_targets.shadow]
size = [64, 32]
color_buffers = 2
[textures.3]
render_target = "shadow"
attachment = "depth"
min_filter = "linear"
compare_mode = "compare_r_to_texture"
[textures.4]
render_target = "shadow"
attachment = "color1"
min_filter = "nearest"
[[objects]]
mesh = "quad"
)";

}  // namespace

TEST_CASE("render targets, the textures that sample them and the passes that draw into them", "[scene][parse]") {
    Scene s = parse_ok(std::string(kTarget) + R"(
[[passes]]
target = "shadow"
clear = { depth = 0.5, stencil = 3 }
camera = { look_at = { eye = [0, 0, 2] }, ortho = { left = -2, right = 2, bottom = -1, top = 1, near = 1, far = 3 } }
state = { viewport = [1, 2, 30, 20] }
[[passes]]
clear = { color = [1, 0, 0] }
)");
    REQUIRE(s.targets.size() == 1);
    CHECK(s.targets[0].name == "shadow");
    CHECK(s.targets[0].width == 64);
    CHECK(s.targets[0].height == 32);
    CHECK(s.targets[0].color_buffers == 2);
    REQUIRE(s.textures.size() == 2);
    CHECK(s.textures[0].render_target == 0);
    CHECK(s.textures[0].attachment == -1);
    CHECK(s.textures[0].texture->depth());
    CHECK(s.textures[0].texture->sampler.compare);
    CHECK(s.textures[0].texture->levels(0)[0].width == 64);
    CHECK(s.textures[0].texture->levels(0)[0].texels[0].r == 1.0f);  // cleared depth until drawn
    CHECK(s.textures[1].attachment == 1);
    CHECK_FALSE(s.textures[1].texture->depth());
    const auto& p = s.passes[0];
    CHECK(p.target == 0);
    CHECK(p.clear.depth == 0.5f);
    CHECK(p.clear.stencil == 3);
    CHECK_FALSE(p.clear.color);
    REQUIRE(p.view);
    CHECK((*p.view)[3][2] == -2.0f);                 // gluLookAt from z = 2
    CHECK(p.state.projection[0][0] == 0.5f);          // glOrtho's 2 / (right - left)
    CHECK(s.gl.projection[0][0] == 1.0f);             // the scene's camera is untouched
    CHECK(p.state.viewport == std::array<int, 4>{1, 2, 30, 20});
    CHECK(s.passes[1].target == -1);
    check_vec(*s.passes[1].clear.color, {1, 0, 0, 1});
    // A pass into a target does not add colour buffers to the output.
    CHECK(glslrun::scene::color_buffers(s) == 1);
}

TEST_CASE("float render targets: rgba16f and rgba32f attachments, sampled in their format", "[scene][parse]") {
    Scene s = parse_ok(R"([render_targets.hdr]
size = [8, 4]
internal_format = "rgba16f"
color_buffers = 2
[render_targets.wide]
size = [4, 4]
internal_format = "rgba32f"
[render_targets.plain]
size = [4, 4]
[textures.0]
render_target = "hdr"
attachment = "color1"
min_filter = "linear"
[textures.1]
render_target = "wide"
min_filter = "nearest"
[textures.2]
render_target = "plain"
min_filter = "nearest"
[textures.3]
internal_format = "rgba16f"
solid = { size = [2, 2], color = [1.0001, 70000, -2.5, 0.5] }
min_filter = "nearest"
)");
    REQUIRE(s.targets.size() == 3);
    auto format_of = [&](const std::string& name) {
        for (const auto& t : s.targets)
            if (t.name == name) return t.format;
        FAIL("no target " << name);
        return glslrun::TextureFormat::Depth;
    };
    CHECK(format_of("hdr") == glslrun::TextureFormat::RGBA16F);
    CHECK(format_of("wide") == glslrun::TextureFormat::RGBA32F);
    CHECK(format_of("plain") == glslrun::TextureFormat::RGBA8);
    CHECK(s.textures[0].texture->format() == glslrun::TextureFormat::RGBA16F);
    CHECK(s.textures[1].texture->format() == glslrun::TextureFormat::RGBA32F);
    CHECK(s.textures[2].texture->format() == glslrun::TextureFormat::RGBA8);
    // Texels from data are stored as halves: 1.0001 to 1, 70000 to infinity.
    const glm::vec4 t = s.textures[3].texture->levels(0)[0].texels[0];
    CHECK(t == glm::vec4(1.0f, std::numeric_limits<float>::infinity(), -2.5f, 0.5f));
}

TEST_CASE("transform lists take gluLookAt, glOrtho, glFrustum, gluPerspective and inverses", "[scene][parse]") {
    Scene s = parse_ok(R"(
[texture_matrix.1]
transform = [ { ortho = { left = -2, right = 2, bottom = -2, top = 2, near = -1, far = 1 } },
              { look_at = { eye = [0, 0, 3] } }, { inverse = [ { look_at = { eye = [0, 0, 3] } } ] } ]
[texture_matrix.2]
transform = [ { perspective = { fovy = 90, aspect = 2, near = 1, far = 3 } }, { frustum = { left = -1, right = 1, bottom = -1, top = 1, near = 1, far = 3 } } ]
)");
    const glm::mat4& m = s.gl.texture_matrix[1];
    CHECK(m[0][0] == 0.5f);  // the look_at and its inverse cancel
    CHECK(m[3][2] == Approx(0.0f).margin(1e-6));
    CHECK(s.gl.texture_matrix[2][1][1] == Approx(1.0f));  // cot(45) of the perspective, times frustum's 1
}

TEST_CASE("render target mistakes cite their line", "[scene][parse]") {
    check_cases({
        {"[render_targets.a]\ncolor_buffers = 1\n", 1, "needs its size"},
        {"[render_targets.a]\nsize = [0, 4]\n", 2, "size 0x4 is not allowed"},
        {"[render_targets.a]\nsize = [4, 4]\ncolor_buffers = 9\n", 3, "must be"},
        {"[render_targets.a]\nsize = [4, 4]\ninternal_format = \"rgb16f\"\n", 3, "rgba16f"},
        {"[render_targets.a]\nsize = [4096, 4096]\ninternal_format = \"rgba32f\"\n", 1, "float ones counted 4 times"},
        {"[render_targets.a]\nsize = [8192, 4096]\n[render_targets.b]\nsize = [16, 16]\n", 3, "hold 67109376 pixels"},
        {"[textures.0]\nrender_target = \"nope\"\nmin_filter = \"linear\"\n", 2, "no [render_targets.nope]"},
        {"[render_targets.a]\nsize = [4, 4]\n[textures.0]\nrender_target = \"a\"\n", 4, "min_filter must be"},
        {"[render_targets.a]\nsize = [4, 4]\n[textures.0]\nrender_target = \"a\"\nattachment = \"color1\"\n"
         "min_filter = \"linear\"\n", 5, "has 1 colour buffer"},
        {"[render_targets.a]\nsize = [4, 4]\n[textures.0]\nrender_target = \"a\"\nmin_filter = \"linear\"\n"
         "[textures.1]\nrender_target = \"a\"\nmin_filter = \"linear\"\n", 7, "already samples"},
        {"[render_targets.a]\nsize = [4, 4]\n[textures.0]\nrender_target = \"a\"\nmin_filter = \"linear\"\n"
         "compare_mode = \"compare_r_to_texture\"\n", 6, "depth textures only"},
        {"[render_targets.a]\nsize = [4, 4]\n[textures.0]\nrender_target = \"a\"\nmin_filter = \"linear\"\n"
         "image = \"x.png\"\n", 6, "unknown key"},
        {"[textures.0]\nattachment = \"depth\"\nsolid = [1, 1, 1]\n", 2, "needs render_target"},
        {"[[objects]]\nmesh = \"quad\"\n[[passes]]\ntarget = \"x\"\n", 4, "the scene declares no render target"},
        {"[[objects]]\nmesh = \"quad\"\n[[passes]]\nclear = { depth = 2 }\n", 4, "glClearDepth"},
        {"[[objects]]\nmesh = \"quad\"\n[[passes]]\nclear = { colour = [1, 1, 1] }\n", 4, "unknown key"},
        {"[[objects]]\nmesh = \"quad\"\n[[passes]]\ncamera = { look_at = {}, view_matrix = [] }\n", 4, "give only one"},
        {"[state]\nviewport = [0, 0, 0, 4]\n", 2, "viewport[2]"},
        {"[state]\nviewport = [0, 0, 4]\n", 2, "[x, y, width, height]"},
        {"[texture_matrix.0]\ntransform = [ { perspective = { fovy = 45, near = 1, far = 2 } } ]\n", 2, "needs its aspect"},
        {"[texture_matrix.0]\ntransform = [ { inverse = [ { scale = [0, 1, 1] } ] } ]\n", 2, "singular"},
    });
}

TEST_CASE("a pass draws its objects in its list's order, a name listed twice twice", "[scene][parse]") {
    Scene s = parse_ok(R"(
[[objects]]
name = "a"
mesh = "quad"
[[objects]]
name = "b"
mesh = "cube"
[[objects]]
name = "a"
mesh = "sphere"
[[passes]]
objects = ["b", "a", "b"]
)");
    CHECK(s.passes[0].objects == std::vector<size_t>{1, 0, 2, 1});
}

TEST_CASE("[current] texture coordinates, fog coordinate and generic attributes", "[scene][parse]") {
    Scene s = parse_ok(R"(
[current]
tex_coords = { 3 = [0.5, 0.25] }
fog_coord = 2
attributes = { w = 0.5, v = [1, 2, 3] }
)");
    REQUIRE(s.current_attributes.size() == 4);
    CHECK(s.current_attributes[0].name == "gl_MultiTexCoord3");
    check_vec(s.current_attributes[0].value, {0.5, 0.25, 0, 1});
    CHECK(s.current_attributes[1].name == "gl_FogCoord");
    CHECK(s.current_attributes[1].value.x == 2.0f);
    CHECK(s.current_attributes[2].name == "v");  // toml++ keeps tables sorted by key
    check_vec(s.current_attributes[2].value, {1, 2, 3, 1});
    check_vec(s.current_attributes[3].value, {0.5, 0, 0, 1});
    check_cases({
        {"[current]\ntex_coords = { 8 = [1] }\n", 2, "0..7"},
        {"[current]\ntex_coords = { 0 = [1, 2, 3, 4, 5] }\n", 2, "tex_coords.0"},
        {"[current]\nattributes = { gl_Color = 1 }\n", 2, "keys of their own"},
        {"[current]\nfog_coord = \"x\"\n", 2, "fog_coord"},
    });
}

TEST_CASE("objects bind textures of their own", "[scene][parse]") {
    Scene s = parse_ok(R"(
[[objects]]
mesh = "quad"
[objects.textures.2]
solid = { size = [2, 2], color = [1, 0, 0] }
min_filter = "linear"
)");
    REQUIRE(s.objects[0].textures.size() == 1);
    CHECK(s.objects[0].textures[0].unit == 2);
    CHECK(s.textures.empty());
    check_cases({
        {"[render_targets.a]\nsize = [4, 4]\n[[objects]]\nmesh = \"quad\"\n[objects.textures.0]\n"
         "render_target = \"a\"\n", 6, "bound in [textures.N]"},
        {"[[objects]]\nmesh = \"quad\"\n[objects.textures.16]\nsolid = { size = [1, 1], color = [1, 1, 1] }\n", 3,
         "0..15"},
    });
}
