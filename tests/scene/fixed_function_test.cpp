// The programs of draws with a generated fixed-function stage: one per
// distinct state, holding the pass program's uniforms; and the
// fixed-function state that shaders read as built-in uniforms.
#include <catch2/catch.hpp>

#include "glslrun/scene/render.h"
#include "parse_helpers.h"

using namespace scene_test;
using namespace glslrun;

namespace {

// Two quads, the second with a texture of its own on unit 0: its
// fixed-function fragment stage samples a 2D texture, the first's none.
const char* kTwoQuads = R"([output]
size = [16, 8]
[texture_env.0]
mode = "replace"
[uniforms]
tint = [1, 0, 0, 1]
[[objects]]
mesh = "quad"
transform = [ { translate = [-0.5, 0, 0] }, { scale = [0.4, 0.8, 1] } ]
[[objects]]
mesh = "quad"
transform = [ { translate = [0.5, 0, 0] }, { scale = [0.4, 0.8, 1] } ]
uniforms = { tint = [0, 0, 1, 1] }
[objects.textures.0]
solid = { size = [1, 1], color = [0, 1, 0] }
min_filter = "nearest"
)";

std::array<uint8_t, 4> pixel(const scene::Image& img, int x, int y) {
    size_t i = (size_t(y) * size_t(img.width) + size_t(x)) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2], img.rgba[i + 3]};
}

}  // namespace

TEST_CASE("a vertex shader alone gets a fixed-function fragment stage per draw state, with its uniforms",
          "[scene][render][fixed]") {
    Scene s = parse_ok(kTwoQuads);
    auto program = Program::compile({{"tint.vert", "uniform vec4 tint;\n"
                                                   "void main() { gl_FrontColor = tint; gl_TexCoord[0] = "
                                                   "gl_MultiTexCoord0; gl_Position = ftransform(); }\n"}},
                                    {});
    REQUIRE(program);
    auto image = scene::render_image(*program, s);
    INFO((image ? std::string() : image.error().str()));
    REQUIRE(image);
    // Left: no texture bound, the unit is off: the vertex colour, red (the scene's tint).
    CHECK(pixel(*image, 4, 4) == std::array<uint8_t, 4>{255, 0, 0, 255});
    // Right: REPLACE with the green texture (the object's blue tint is replaced).
    CHECK(pixel(*image, 12, 4) == std::array<uint8_t, 4>{0, 255, 0, 255});

    auto programs = scene::ScenePrograms::compile(*program, s);
    REQUIRE(programs);
    auto bound = scene::bind_scene_textures(s);
    REQUIRE(bound);
    GLState first = scene::object_gl_state(s, *bound, s.objects[0]);
    auto a = programs->for_draw(0, s, first);
    auto b = programs->for_draw(0, s, first);
    REQUIRE((a && b));
    CHECK(*a == *b);  // compiled once per state
    CHECK(*a != &programs->of_pass(0));
    REQUIRE(bound->bind_texture(0, s.objects[1].textures[0].texture));
    GLState second = scene::object_gl_state(s, *bound, s.objects[1]);
    auto c = programs->for_draw(0, s, second);
    REQUIRE(c);
    CHECK(*c != *a);  // another texture state, another fragment stage
}

// GL's built-in uniforms of glTexEnv and glTexGen state: a shader reads the
// scene's values, the eye plane as glTexGen stores it (in eye space: the
// world-space plane times the inverse view).
TEST_CASE("a shader reads the scene's texture environment colour and texgen planes", "[scene][render][fixed]") {
    auto program = Program::compile(
        {}, {{"planes.frag", "void main() { gl_FragColor = vec4(gl_TextureEnvColor[2].rg, gl_ObjectPlaneR[1].z,"
                             " gl_EyePlaneS[0].w + 0.5); }\n"}});
    REQUIRE(program);
    auto at_centre = [&](const std::string& toml) {
        auto image = scene::render_image(*program, parse_ok(toml + "[[objects]]\nmesh = \"quad\"\n"));
        REQUIRE(image);
        return pixel(*image, image->width / 2, image->height / 2);
    };
    // GL's defaults: colour zero, r planes zero, s = (1, 0, 0, 0).
    CHECK(at_centre("[output]\nsize = [4, 4]\n") == std::array<uint8_t, 4>{0, 0, 0, 128});
    // The camera looks from z = 4 (view = translate(0, 0, -4)): the world-space plane (0, 0, 1, -3.75) is
    // (0, 0, 1, -3.75) * inverse(view) = (0, 0, 1, 0.25) in eye space. With space = "eye" it is stored as given.
    const std::string sets = R"([output]
size = [4, 4]
[camera]
look_at = { eye = [0, 0, 4], center = [0, 0, 0], up = [0, 1, 0] }
ortho = { left = -1, right = 1, bottom = -1, top = 1, near = 1, far = 10 }
[texture_env.2]
color = [0.2, 0.6, 0, 0]
[texture_gen.1]
r = { mode = "object_linear", object_plane = [0, 0, 0.4, 0] }
)";
    CHECK(at_centre(sets + "[texture_gen.0]\ns = { mode = \"eye_linear\", eye_plane = [0, 0, 1, -3.75] }\n") ==
          std::array<uint8_t, 4>{51, 153, 102, 191});
    CHECK(at_centre(sets + "[texture_gen.0]\nspace = \"eye\"\ns = { mode = \"eye_linear\", eye_plane = [0, 0, 1, "
                           "-0.25] }\n") == std::array<uint8_t, 4>{51, 153, 102, 64});
}
