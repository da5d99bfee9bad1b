// The fixed-function keys: [fixed_function], [light_model] color_control,
// [fog] mode and coord_src, [texture_env.N], [texture_gen.N], a pass's
// program = "fixed", and their mistakes at their lines.
#include "parse_helpers.h"

using namespace scene_test;
using namespace glslrun::scene;

TEST_CASE("fixed-function keys keep GL's defaults when left out", "[scene][parse]") {
    Scene s = parse_ok("");
    const FixedFunction& f = s.fixed;
    CHECK_FALSE(f.lighting);
    CHECK_FALSE(f.color_material);
    CHECK(f.color_material_mode == ColorMaterialMode::AmbientAndDiffuse);
    CHECK_FALSE(f.fog);
    CHECK(f.fog_mode == FogMode::Exp);
    CHECK_FALSE(f.texture_env[0].enabled);
    CHECK(f.texture_env[0].mode == TexEnvMode::Modulate);
    CHECK(f.texture_gen[3][0].mode == TexGenMode::Off);
    check_vec(f.texture_gen[3][0].eye_plane, {1, 0, 0, 0});
    check_vec(f.texture_gen[3][1].object_plane, {0, 1, 0, 0});
    check_vec(f.texture_gen[3][2].object_plane, {0, 0, 0, 0});
}

TEST_CASE("fixed-function keys are read as GL's calls set them", "[scene][parse]") {
    Scene s = parse_ok(R"([camera]
view_matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, -5, 1]]
[fixed_function]
lighting = true
color_material = "specular"
color_material_face = "back"
normalize = true
rescale_normal = true
color_sum = true
fog = true
[light_model]
color_control = "separate_specular_color"
[fog]
mode = "exp2"
coord_src = "fog_coord"
[texture_env.2]
mode = "combine"
color = [0.1, 0.2, 0.3, 0.4]
combine_rgb = "dot3_rgb"
combine_alpha = "subtract"
source0_rgb = "texture5"
source2_alpha = "primary_color"
operand1_rgb = "one_minus_src_alpha"
operand0_alpha = "one_minus_src_alpha"
rgb_scale = 4
[texture_gen.1]
s = "sphere_map"
t = { mode = "eye_linear", eye_plane = [0, 1, 0, 2] }
r = { mode = "object_linear", object_plane = [1, 2, 3, 4] }
[texture_gen.4]
space = "eye"
q = { mode = "eye_linear", eye_plane = [0, 0, 1, 2] }
)");
    const FixedFunction& f = s.fixed;
    CHECK(f.lighting);
    CHECK(f.color_material);
    CHECK(f.color_material_mode == ColorMaterialMode::Specular);
    CHECK_FALSE(f.color_material_front);
    CHECK(f.color_material_back);
    CHECK((f.normalize && f.rescale_normal && f.color_sum && f.fog && f.separate_specular && f.fog_coord_from_array));
    CHECK(f.fog_mode == FogMode::Exp2);
    const TextureEnv& e = f.texture_env[2];
    CHECK(e.enabled);
    CHECK(e.mode == TexEnvMode::Combine);
    check_vec(e.color, {0.1, 0.2, 0.3, 0.4});
    CHECK(e.combine_rgb == CombineFunction::Dot3Rgb);
    CHECK(e.combine_alpha == CombineFunction::Subtract);
    CHECK(e.source_rgb[0] == kCombineTexture0 + 5);
    CHECK(e.source_alpha[2] == uint8_t(CombineSource::PrimaryColor));
    CHECK(e.operand_rgb[1] == CombineOperand::OneMinusSrcAlpha);
    CHECK(e.operand_alpha[0] == CombineOperand::OneMinusSrcAlpha);
    CHECK(e.rgb_scale == 4);
    CHECK(e.alpha_scale == 1);
    CHECK_FALSE(f.texture_env[1].enabled);
    CHECK(f.texture_gen[1][0].mode == TexGenMode::SphereMap);
    CHECK(f.texture_gen[1][1].mode == TexGenMode::EyeLinear);
    // World-space plane p, stored as p * inverse(view): the view moves z by -5, so w gains 5 * z... here t's z is 0.
    check_vec(f.texture_gen[1][1].eye_plane, {0, 1, 0, 2});
    check_vec(f.texture_gen[1][2].object_plane, {1, 2, 3, 4});
    CHECK(f.texture_gen[1][3].mode == TexGenMode::Off);
    // An eye-space plane is kept as given; a world one with z moves by the view's translation.
    check_vec(f.texture_gen[4][3].eye_plane, {0, 0, 1, 2});
    Scene world = parse_ok(R"([camera]
view_matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, -5, 1]]
[texture_gen.0]
s = { mode = "eye_linear", eye_plane = [0, 0, 1, 2] }
)");
    check_vec(world.fixed.texture_gen[0][0].eye_plane, {0, 0, 1, 7});
}

TEST_CASE("a pass may give one shader, or program = \"fixed\"", "[scene][parse]") {
    Scene s = parse_ok(R"([[objects]]
mesh = "quad"
[[passes]]
program = "fixed"
[[passes]]
)");
    REQUIRE(s.passes.size() == 2);
    CHECK(s.passes[0].fixed_function);
    CHECK_FALSE(s.passes[1].fixed_function);
}

TEST_CASE("mistakes in fixed-function keys cite their line", "[scene][parse]") {
    check_cases({
        {"[fixed_function]\nlightning = true\n", 2, "did you mean 'lighting'"},
        {"[fixed_function]\ncolor_material = \"shininess\"\n", 2, "color_material"},
        {"[light_model]\ncolor_control = \"separate\"\n", 2, "separate_specular_color"},
        {"[fog]\nmode = \"exp3\"\n", 2, "is not allowed"},
        {"[texture_env.8]\nmode = \"add\"\n", 1, "texture units are 0..7"},
        {"[texture_env.0]\nmode = \"decal\"\ncombine_rgb = \"add\"\n", 1, "only mode = \"combine\""},
        {"[texture_env.0]\nmode = \"combine\"\nrgb_scale = 3\n", 3, "must be 1, 2 or 4"},
        {"[texture_env.0]\nmode = \"combine\"\ncombine_alpha = \"dot3_rgba\"\n", 3, "combine_alpha"},
        {"[texture_env.0]\nmode = \"combine\"\noperand0_alpha = \"src_color\"\n", 3, "src_alpha"},
        {"[texture_env.0]\ncolor = [2, 0, 0]\n", 2, "must be in [0, 1]"},
        {"[texture_gen.0]\nr = \"sphere_map\"\n", 2, "GL refuses sphere_map for r"},
        {"[texture_gen.0]\ns = { object_plane = [1, 0, 0, 0] }\n", 2, "mode"},
        {"[texture_gen.0]\nu = \"normal_map\"\n", 2, "u"},
    });
}
