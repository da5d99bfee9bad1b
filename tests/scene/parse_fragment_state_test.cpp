// [state]'s per-fragment operations and [objects.state]: GL's defaults, every
// key into GLState, and errors with file:line for bad values.
#include "parse_helpers.h"

using namespace scene_test;
using namespace glslrun;

TEST_CASE("per-fragment state defaults are GL's", "[scene][fragment]") {
    Scene s = parse_ok("");
    const GLState& gl = s.gl;
    CHECK_FALSE(gl.scissor_test);
    CHECK_FALSE(gl.alpha_test);
    CHECK(gl.alpha_func == CompareFunc::Always);
    CHECK_FALSE(gl.stencil_test);
    for (const StencilFace& f : gl.stencil) {
        CHECK(f.func == CompareFunc::Always);
        CHECK(f.ref == 0);
        CHECK(f.value_mask == 0xFF);
        CHECK(f.write_mask == 0xFF);
        CHECK(f.fail == StencilOp::Keep);
        CHECK(f.depth_pass == StencilOp::Keep);
    }
    CHECK(gl.depth_mask);
    CHECK_FALSE(gl.blend);
    CHECK(gl.blend_state.src_rgb == BlendFactor::One);
    CHECK(gl.blend_state.dst_alpha == BlendFactor::Zero);
    CHECK(gl.blend_state.equation_rgb == BlendEquation::Add);
    CHECK(gl.logic_op == LogicOp::Copy);
    CHECK(gl.color_mask == std::array<bool, 4>{true, true, true, true});
    CHECK(gl.draw_buffers == 1);
    CHECK(s.clear_stencil == 0);
}

TEST_CASE("per-fragment state keys set GLState", "[scene][fragment]") {
    Scene s = parse_ok(R"(
[output]
clear_stencil = 7
[state]
scissor_test = true
scissor_box = [1, 2, 30, 40]
alpha_test = true
alpha_test_func = "gequal"
alpha_test_ref = 0.25
stencil_test = true
stencil_func = "notequal"
stencil_ref = 5
stencil_value_mask = 15
stencil_writemask = 240
stencil_fail = "incr_wrap"
stencil_pass_depth_fail = "invert"
stencil_pass_depth_pass = "replace"
stencil_back_func = "less"
stencil_back_pass_depth_pass = "decr"
depth_writemask = false
blend = true
blend_func = ["src_alpha", "one_minus_src_alpha", "one", "zero"]
blend_equation = ["func_reverse_subtract", "max"]
blend_color = [0.1, 0.2, 0.3]
color_logic_op = true
logic_op_mode = "nand"
color_writemask = [true, false, true, false]
draw_buffers = 4
[[objects]]
mesh = "quad"
[[objects]]
mesh = "quad"
state = { blend = false, stencil_back_ref = 9, draw_buffers = 2 }
)");
    const GLState& gl = s.gl;
    CHECK(s.clear_stencil == 7);
    CHECK(gl.scissor_test);
    CHECK(gl.scissor_box == std::array<int, 4>{1, 2, 30, 40});
    CHECK(gl.alpha_test);
    CHECK(gl.alpha_func == CompareFunc::Gequal);
    CHECK(gl.alpha_ref == 0.25f);
    CHECK(gl.stencil_test);
    const StencilFace& front = gl.stencil[0];
    const StencilFace& back = gl.stencil[1];
    CHECK(front.func == CompareFunc::Notequal);
    CHECK(front.ref == 5);
    CHECK(front.value_mask == 15);
    CHECK(front.write_mask == 240);
    CHECK(front.fail == StencilOp::IncrWrap);
    CHECK(front.depth_fail == StencilOp::Invert);
    CHECK(front.depth_pass == StencilOp::Replace);
    // stencil_* sets both faces (glStencilFunc), stencil_back_* then the back alone.
    CHECK(back.func == CompareFunc::Less);
    CHECK(back.ref == 5);
    CHECK(back.depth_fail == StencilOp::Invert);
    CHECK(back.depth_pass == StencilOp::Decr);
    CHECK_FALSE(gl.depth_mask);
    CHECK(gl.blend);
    CHECK(gl.blend_state.src_rgb == BlendFactor::SrcAlpha);
    CHECK(gl.blend_state.dst_rgb == BlendFactor::OneMinusSrcAlpha);
    CHECK(gl.blend_state.src_alpha == BlendFactor::One);
    CHECK(gl.blend_state.dst_alpha == BlendFactor::Zero);
    CHECK(gl.blend_state.equation_rgb == BlendEquation::ReverseSubtract);
    CHECK(gl.blend_state.equation_alpha == BlendEquation::Max);
    check_vec(gl.blend_state.color, {0.1, 0.2, 0.3, 1});
    CHECK(gl.color_logic_op);
    CHECK(gl.logic_op == LogicOp::Nand);
    CHECK(gl.color_mask == std::array<bool, 4>{true, false, true, false});
    CHECK(gl.draw_buffers == 4);
    // An object's state is the scene's with its own keys on top.
    REQUIRE(s.objects.size() == 2);
    CHECK_FALSE(s.objects[0].state);
    REQUIRE(s.objects[1].state);
    const GLState& o = *s.objects[1].state;
    CHECK_FALSE(o.blend);
    CHECK(o.stencil[1].ref == 9);
    CHECK(o.stencil[0].ref == 5);
    CHECK(o.draw_buffers == 2);
    CHECK(o.logic_op == LogicOp::Nand);
}

TEST_CASE("glBlendFunc's two factors set RGB and alpha alike; one equation sets both", "[scene][fragment]") {
    Scene s = parse_ok("[state]\nblend_func = [\"dst_color\", \"zero\"]\nblend_equation = \"min\"\n");
    CHECK(s.gl.blend_state.src_alpha == BlendFactor::DstColor);
    CHECK(s.gl.blend_state.dst_alpha == BlendFactor::Zero);
    CHECK(s.gl.blend_state.equation_alpha == BlendEquation::Min);
}

TEST_CASE("bad per-fragment values cite file:line", "[scene][fragment][errors]") {
    check_cases({
        {"[state]\nblend = true\nblend_func = [\"src_alpha\", \"one_minus_src_alhpa\"]\n", 3,
         "'state.blend_func[1]' = \"one_minus_src_alhpa\" is not allowed; did you mean 'one_minus_src_alpha'?"},
        {"[state]\nblend_func = [\"one\"]\n", 2, "must be [src, dst] or [src_rgb, dst_rgb, src_alpha, dst_alpha]"},
        {"[state]\nblend_func = [\"one\", \"src_alpha_saturate\"]\n", 2, "is a source factor only"},
        {"[state]\nblend_equation = \"add\"\n", 2, "valid values: func_add, func_subtract"},
        {"[state]\nblend_color = [0, 2, 0]\n", 2, "glBlendColor"},
        {"[state]\nstencil_writemask = 256\n", 2, "'state.stencil_writemask (stencil values are 8 bits)' must be in [0, 255]; got 256"},
        {"[state]\nstencil_back_value_mask = -1\n", 2, "must be in [0, 255]"},
        {"[state]\nstencil_ref = 1.5\n", 2, "must be an integer"},
        {"[state]\nstencil_fail = \"increment\"\n", 2, "is not allowed"},
        {"[state]\nalpha_test_ref = 1.5\n", 2, "glAlphaFunc"},
        {"[state]\nscissor_box = [0, 0, -1, 10]\n", 2, "'state.scissor_box.width' must be in [0,"},
        {"[state]\nscissor_box = [0, 0, 10]\n", 2, "must be [x, y, width, height]"},
        {"[state]\ncolor_writemask = [true, 1, true, true]\n", 2, "'state.color_writemask[1]' must be true or false"},
        {"[state]\nlogic_op_mode = \"xnor\"\n", 2, "is not allowed"},
        {"[state]\ndraw_buffers = 9\n", 2, "must be in [1, 8]"},
        {"[output]\nclear_stencil = 300\n", 2, "must be in [0, 255]"},
        {"[[objects]]\nmesh = \"quad\"\nstate = { blend_fnc = [\"one\", \"one\"] }\n", 3,
         "unknown key 'blend_fnc' in [objects[0].state]; did you mean 'blend_func'?"},
    });
}
