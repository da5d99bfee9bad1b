// glslrun against Mesa on the per-fragment operations (GL 2.1 §4.1): every
// blend factor and equation with the blend colour, stencil functions and
// operations with separate back-face state and masks, scissor, alpha test,
// depth and colour write masks, logic ops, and several draw buffers written
// through gl_FragData. Each object carries its own [objects.state], so one
// scene shows many states side by side. Colours are affine in the vertex
// position, so that how Mesa splits a quad does not matter.
#include "tests/reference/helpers.h"
#include "tests/raster/alpha_boundaries.h"

using namespace glslrun;

namespace {

const char* kVertex = R"(
void main() {
    vec4 c = vec4(gl_Vertex.xy * 0.5 + 0.5, 0.8 - 0.3 * gl_Vertex.x, 1.0);
    gl_FrontColor = c;
    gl_BackColor = c.bgra;
    gl_Position = ftransform();
}
)";

// alpha < 0: stripes of alpha 0.8 and 0.3, eight pixels wide (for the alpha
// test: no fragment lies near its reference value).
const char* kFragment = R"(
uniform float alpha;
void main() {
    float stripes = mod(floor(gl_FragCoord.x / 8.0), 2.0) == 0.0 ? 0.8 : 0.3;
    gl_FragColor = vec4(gl_Color.rgb, alpha < 0.0 ? stripes : alpha);
}
)";

// A background quad, drawn without blending (alpha 0.7 where it covers,
// the clear's 0.5 around it), then a 3x2 grid of blended quads.
const char* kBlendScene = R"(
[output]
size = [192, 128]
clear_color = [0.2, 0.4, 0.6, 0.5]

[uniforms]
alpha = 0.7

[[objects]]
name = "background"
mesh = "quad"
transform = [ { translate = [-0.2, 0, 0] }, { scale = [0.75, 0.9, 1] } ]

[[objects]]
mesh = "quad"
transform = [ { translate = [-0.66, 0.45, 0] }, { rotate = [20, 0, 0, 1] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.6 }
state = { blend = true, blend_func = ["src_alpha", "one_minus_src_alpha"] }

[[objects]]
mesh = "quad"
transform = [ { translate = [0, 0.45, 0] }, { rotate = [-15, 0, 0, 1] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.4 }
state = { blend = true, blend_func = ["src_color", "one_minus_src_color", "dst_alpha", "one_minus_dst_alpha"], blend_equation = ["func_subtract", "func_add"] }

[[objects]]
mesh = "quad"
transform = [ { translate = [0.66, 0.45, 0] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.9 }
state = { blend = true, blend_func = ["dst_color", "one_minus_dst_color", "constant_alpha", "one_minus_constant_alpha"], blend_color = [0.1, 0.5, 0.9, 0.35] }

[[objects]]
mesh = "quad"
transform = [ { translate = [-0.66, -0.45, 0] }, { rotate = [10, 0, 0, 1] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.5 }
state = { blend = true, blend_func = ["constant_color", "one_minus_constant_color", "one", "zero"], blend_equation = ["func_reverse_subtract", "func_add"], blend_color = [0.25, 0.3, 0.1, 0.5] }

[[objects]]
mesh = "quad"
transform = [ { translate = [0, -0.45, 0] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.3 }
state = { blend = true, blend_func = ["src_alpha_saturate", "one", "one_minus_dst_color", "src_alpha"] }

[[objects]]
mesh = "quad"
transform = [ { translate = [0.66, -0.45, 0] }, { rotate = [-25, 0, 0, 1] }, { scale = [0.3, 0.4, 1] } ]
uniforms = { alpha = 0.2 }
state = { blend = true, blend_equation = ["min", "max"] }
)";

// Stencil: a square marks 3, a rotated quad tests it through a value mask and
// inverts the low bits it passes, a back-facing quad takes the back-face
// state, a depth test that always fails counts up, and full-screen quads show
// the stencil values at the end.
const char* kStencilScene = R"(
[output]
size = [128, 128]
clear_color = [0, 0, 0, 1]
clear_stencil = 1

[uniforms]
alpha = 1.0

[[objects]]
name = "mark"
mesh = "quad"
transform = [ { scale = [0.6, 0.6, 1] } ]
state = { stencil_test = true, stencil_ref = 3, stencil_pass_depth_pass = "replace", color_writemask = [false, false, false, false] }

[[objects]]
name = "masked"
mesh = "quad"
transform = [ { rotate = [45, 0, 0, 1] }, { scale = [0.7, 0.7, 1] } ]
state = { stencil_test = true, stencil_func = "equal", stencil_ref = 7, stencil_value_mask = 3, stencil_fail = "incr", stencil_pass_depth_pass = "invert", stencil_writemask = 15 }

[[objects]]
name = "back"
mesh = "quad"
transform = [ { translate = [0.3, -0.3, 0] }, { rotate = [180, 0, 1, 0] }, { scale = [0.5, 0.5, 1] } ]
state = { stencil_test = true, stencil_func = "never", stencil_back_func = "less", stencil_back_ref = 1, stencil_back_fail = "zero", stencil_back_pass_depth_pass = "decr_wrap" }

[[objects]]
name = "depth fails"
mesh = "quad"
transform = [ { translate = [-0.4, 0.4, 0] }, { scale = [0.4, 0.4, 1] } ]
state = { depth_test = true, depth_func = "never", stencil_test = true, stencil_pass_depth_fail = "incr_wrap", stencil_pass_depth_pass = "zero" }

[[objects]]
name = "show 1"
mesh = "quad"
uniforms = { alpha = 0.5 }
state = { stencil_test = true, stencil_func = "equal", stencil_ref = 1, blend = true, blend_func = ["one", "one"] }

[[objects]]
name = "show > 3"
mesh = "quad"
transform = [ { rotate = [90, 0, 0, 1] } ]
state = { stencil_test = true, stencil_func = "less", stencil_ref = 3 }

[[objects]]
name = "show 2"
mesh = "quad"
transform = [ { rotate = [180, 0, 0, 1] } ]
uniforms = { alpha = 0.5 }
state = { stencil_test = true, stencil_func = "equal", stencil_ref = 2, blend = true, blend_func = ["src_alpha", "one"] }
)";

// Scissor, alpha test, colour and depth write masks, logic ops.
const char* kMaskScene = R"(
[output]
size = [160, 128]
clear_color = [0.1, 0.2, 0.3, 1]

[uniforms]
alpha = -1.0

[[objects]]
name = "scissored, alpha tested"
mesh = "quad"
transform = [ { translate = [-0.5, 0.5, 0] }, { scale = [0.45, 0.45, 1] } ]
state = { scissor_test = true, scissor_box = [10, 70, 50, 40], alpha_test = true, alpha_test_func = "greater", alpha_test_ref = 0.5 }

[[objects]]
name = "red and blue only"
mesh = "quad"
transform = [ { translate = [0.5, 0.5, 0] }, { scale = [0.45, 0.45, 1] } ]
state = { color_writemask = [true, false, true, false] }

[[objects]]
name = "depth without writes"
mesh = "quad"
transform = [ { translate = [-0.5, -0.5, 0.5] }, { scale = [0.45, 0.45, 1] } ]
state = { depth_test = true, depth_writemask = false }

[[objects]]
name = "behind it"
mesh = "quad"
transform = [ { translate = [-0.4, -0.4, 0.2] }, { rotate = [30, 0, 0, 1] }, { scale = [0.4, 0.4, 1] } ]
uniforms = { alpha = 1.0 }
state = { depth_test = true }

[[objects]]
name = "xor"
mesh = "quad"
transform = [ { translate = [0.5, -0.5, 0] }, { scale = [0.45, 0.45, 1] } ]
state = { color_logic_op = true, logic_op_mode = "xor" }

[[objects]]
name = "or_inverted"
mesh = "quad"
transform = [ { translate = [0.3, -0.3, 0] }, { rotate = [40, 0, 0, 1] }, { scale = [0.25, 0.25, 1] } ]
state = { color_logic_op = true, logic_op_mode = "or_inverted" }
)";

const char* kDrawBuffersFragment = R"(
void main() {
    gl_FragData[0] = gl_Color;
    gl_FragData[1] = vec4(1.0 - gl_Color.rgb, 0.5);
    gl_FragData[2] = vec4(gl_Color.bgr * 0.5, 1.0);
}
)";

const char* kDrawBuffersScene = R"(
[output]
size = [96, 96]
clear_color = [0.2, 0.2, 0.2, 1]

[state]
draw_buffers = 3

[[objects]]
mesh = "quad"
transform = [ { scale = [0.8, 0.8, 1] } ]

[[objects]]
mesh = "quad"
transform = [ { translate = [0.3, 0.3, 0] }, { rotate = [30, 0, 0, 1] }, { scale = [0.5, 0.5, 1] } ]
state = { draw_buffers = 3, blend = true, blend_func = ["src_alpha", "one_minus_src_alpha"] }
)";

reference::Inputs inline_inputs(const std::string& name, const std::string& toml, const char* fs = kFragment) {
    auto scene = scene::parse_scene(toml, name + ".toml");
    if (!scene) FAIL(scene.error().str());
    return {{{name + ".vert", kVertex}}, {{name + ".frag", fs}}, std::move(*scene)};
}

}  // namespace

TEST_CASE("glslrun matches Mesa on every blend factor and equation", "[reference]") {
    reference::compare("fragment-blend", inline_inputs("blend", kBlendScene));
}

TEST_CASE("glslrun matches Mesa on stencil functions, operations, masks and back faces", "[reference]") {
    reference::compare("fragment-stencil", inline_inputs("stencil", kStencilScene));
}

TEST_CASE("glslrun matches Mesa on scissor, alpha test, write masks and logic ops", "[reference]") {
    reference::compare("fragment-masks", inline_inputs("masks", kMaskScene));
}

TEST_CASE("glslrun matches Mesa on several draw buffers through gl_FragData", "[reference]") {
    reference::compare("fragment-draw-buffers", inline_inputs("draw_buffers", kDrawBuffersScene, kDrawBuffersFragment));
}

// Each quad is one alpha-test case at a rounding boundary of the RGBA8
// buffer; one that goes the other way from Mesa is 4% of the image.
TEST_CASE("glslrun matches Mesa on the alpha test at the RGBA8 rounding boundaries", "[reference]") {
    const char* fragment = "uniform float alpha;\nvoid main() { gl_FragColor = vec4(gl_Color.rgb, alpha); }\n";
    auto in = inline_inputs("alpha_boundaries", alpha_boundaries::scene(), fragment);
    reference::compare("fragment-alpha-boundaries", in);
    // And each case as the table says GL draws it.
    auto mesa = glref::render_with_mesa(reference::kDriver, in.vertex, in.fragment, in.scene);
    REQUIRE(mesa);
    for (size_t i = 0; i < alpha_boundaries::kCases.size(); ++i) {
        auto [x, y] = alpha_boundaries::centre(i);
        INFO("case " << i);
        CHECK((mesa->image.pixel(x, mesa->image.height - 1 - y)[2] > 0) == alpha_boundaries::kCases[i].passes);
    }
}
