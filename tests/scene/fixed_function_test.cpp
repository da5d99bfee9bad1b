// The programs of draws with a generated fixed-function stage: one per
// distinct state, holding the pass program's uniforms; and what a shader
// cannot see of the fixed-function state is refused rather than wrong.
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

TEST_CASE("a shader that reads fixed-function state the scene sets is refused, not drawn wrong",
          "[scene][render][fixed]") {
    auto program = Program::compile({}, {{"env.frag", "void main() { gl_FragColor = gl_TextureEnvColor[0]; }\n"}});
    REQUIRE(program);
    Scene plain = parse_ok("[[objects]]\nmesh = \"quad\"\n");
    CHECK(scene::render_image(*program, plain));  // GL's default, which glslrun gives
    Scene sets = parse_ok("[texture_env.0]\ncolor = [1, 0, 0, 1]\n[[objects]]\nmesh = \"quad\"\n");
    auto refused = scene::render_image(*program, sets);
    REQUIRE_FALSE(refused);
    CHECK_THAT(refused.error().str(), Catch::Contains("gl_TextureEnvColor"));
}
