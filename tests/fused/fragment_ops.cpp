// The per-fragment operations the fused pipeline generates beyond the depth
// test, against the interpreter's C++ path (raster/fragment_ops.cpp), bit
// for bit, with Nearest and ColorRounding::Gpu (Fast's) storage: the alpha
// test, the logic op, blending and colour masks with a late depth test
// (discard, gl_FragDepth), colour masks into float storage.
#include <string>

#include "harness.h"

using namespace glslrun;
using namespace fused_test;

namespace {

const CompareFunc kCompares[] = {CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,
                                 CompareFunc::Lequal,  CompareFunc::Greater,  CompareFunc::Notequal,
                                 CompareFunc::Gequal,  CompareFunc::Always};

// The shaders with an early depth test, and those that make it late.
const Shader& early_shader() { return kShaders[0]; }  // colour out of range
const Shader& discard_shader() { return kShaders[3]; }
const Shader& depth_shader() { return kShaders[4]; }  // gl_FragDepth, NaN

}  // namespace

TEST_CASE("the fused alpha test draws the interpreter's bits", "[fused]") {
    Geometry small = random_geometry(21, 900, 0.08f);
    // References on and between byte steps: 0.5 is no byte (127.5), 128/255 is one.
    const float kRefs[] = {0.0f, 0.5f, 128.0f / 255.0f, 0.1005f, 1.0f};
    for (const Shader* shader : {&early_shader(), &discard_shader(), &depth_shader(), &kShaders[2]}) {
        Programs p(shader->fs);
        for (size_t f = 0; f < std::size(kCompares); ++f) {
            GLState gl;
            gl.alpha_test = true;
            gl.alpha_func = kCompares[f];
            gl.alpha_ref = kRefs[f % std::size(kRefs)];
            gl.depth_test = f % 3 != 0;
            gl.depth_func = f % 2 ? GLState::DepthFunc::Lequal : GLState::DepthFunc::Less;
            gl.depth_mask = f != 4;
            const ColorRounding rounding = f % 2 ? ColorRounding::Gpu : ColorRounding::Nearest;
            for (bool float_color : {false, true}) {
                INFO(shader->name << ", alpha func " << int(gl.alpha_func) << " ref " << gl.alpha_ref << ", "
                                  << (float_color ? "float" : "RGBA8") << ", depth " << gl.depth_test);
                check_fused_matches(p, Primitive::Triangles, small, gl, float_color, {93, 61}, rounding);
            }
        }
    }
}

TEST_CASE("the fused logic op draws the interpreter's bits", "[fused]") {
    Geometry small = random_geometry(22, 900, 0.08f);
    for (const Shader* shader : {&early_shader(), &discard_shader()}) {
        Programs p(shader->fs);
        for (int op = 0; op < 16; ++op) {
            GLState gl;
            gl.color_logic_op = true;
            gl.logic_op = LogicOp(op);
            gl.blend = op % 4 == 1;  // the logic op wins (§4.1.10)
            gl.depth_test = op % 3 != 2;
            gl.depth_func = GLState::DepthFunc::Lequal;
            gl.color_mask = {true, op % 5 != 0, true, op % 2 == 0};
            for (ColorRounding rounding : {ColorRounding::Nearest, ColorRounding::Gpu}) {
                INFO(shader->name << ", logic op " << op << ", rounding " << int(rounding));
                check_fused_matches(p, Primitive::Triangles, small, gl, false, {93, 61}, rounding);
            }
            // Float storage has no logic op (GL ignores it there).
            if (op % 4 == 0) check_fused_matches(p, Primitive::Triangles, small, gl, true);
        }
    }
}

TEST_CASE("the fused blending and colour masks with a late depth test draw the interpreter's bits", "[fused]") {
    const BlendFactor kFactors[] = {BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendFactor::One,
                                    BlendFactor::DstColor, BlendFactor::ConstantAlpha,    BlendFactor::SrcAlphaSaturate};
    const BlendEquation kEquations[] = {BlendEquation::Add, BlendEquation::Subtract, BlendEquation::ReverseSubtract,
                                        BlendEquation::Min, BlendEquation::Max};
    Geometry small = random_geometry(23, 900, 0.08f);
    for (const Shader* shader : {&discard_shader(), &depth_shader()}) {
        Programs p(shader->fs);
        for (int state = 0; state < 12; ++state) {
            GLState gl;
            gl.depth_test = true;
            gl.depth_func = kCompares[state % 8];
            gl.depth_mask = state % 4 != 3;
            gl.blend = state % 6 != 5;
            BlendState& b = gl.blend_state;
            b.src_rgb = kFactors[state % 6], b.dst_rgb = kFactors[(state + 1) % 6];
            b.src_alpha = kFactors[(state + 2) % 6], b.dst_alpha = kFactors[(state * 5 + 1) % 6];
            b.equation_rgb = kEquations[state % 5], b.equation_alpha = kEquations[(state + 3) % 5];
            b.color = {0.3f, 0.502f, 0.9f, 0.45f};
            gl.color_mask = {state % 3 != 0, true, state % 5 != 1, state % 2 == 0};
            for (ColorRounding rounding : {ColorRounding::Nearest, ColorRounding::Gpu}) {
                INFO(shader->name << ", state " << state << ", rounding " << int(rounding));
                check_fused_matches(p, Primitive::Triangles, small, gl, false, {93, 61}, rounding);
            }
            // Float storage: the colour mask is generated, blending is not (the C++ path draws).
            if (!gl.blend) check_fused_matches(p, Primitive::Triangles, small, gl, true);
        }
    }
}

TEST_CASE("the fused colour mask into float storage draws the interpreter's bits", "[fused]") {
    Geometry small = random_geometry(24, 900, 0.08f);
    for (const Shader* shader : {&early_shader(), &discard_shader()}) {
        Programs p(shader->fs);
        for (int mask = 0; mask < 16; mask += 3) {
            GLState gl;
            gl.depth_test = mask % 2 == 0;
            gl.depth_func = GLState::DepthFunc::Lequal;
            gl.color_mask = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0};
            INFO(shader->name << ", mask " << mask);
            check_fused_matches(p, Primitive::Triangles, small, gl, true);
        }
    }
}

TEST_CASE("the fused alpha test and logic op comparisons are not vacuous", "[fused]") {
    Geometry g = random_geometry(21, 900, 0.08f);
    Programs p(early_shader().fs);
    GLState gl;
    Frame plain = render(p.fused, Primitive::Triangles, g, gl, false);
    gl.alpha_test = true;
    gl.alpha_func = CompareFunc::Greater;
    gl.alpha_ref = 0.5f;
    Frame tested = render(p.fused, Primitive::Triangles, g, gl, false);
    // Some fragments fail the test, and all went through the fused pipeline.
    CHECK(tested.stats.fragments_written < plain.stats.fragments_written);
    CHECK(tested.stats.fragments_written > plain.stats.fragments_written / 4);
    if (jit_available()) CHECK(tested.stats.fragments_fused == tested.stats.fragments_shaded);
    CHECK_FALSE(same_colors(plain.fb, tested.fb));
    GLState logic;
    logic.color_logic_op = true;
    logic.logic_op = LogicOp::Xor;
    Frame xored = render(p.fused, Primitive::Triangles, g, logic, false);
    CHECK_FALSE(same_colors(plain.fb, xored.fb));
    if (jit_available()) CHECK(xored.stats.fragments_fused == xored.stats.fragments_shaded);
}

TEST_CASE("the fused stencil test draws the interpreter's bits: every function and operation, two-sided", "[fused]") {
    const StencilOp kOps[] = {StencilOp::Keep, StencilOp::Zero,     StencilOp::Replace,  StencilOp::Incr,
                              StencilOp::Decr, StencilOp::Invert,   StencilOp::IncrWrap, StencilOp::DecrWrap};
    Geometry small = random_geometry(25, 900, 0.08f);
    for (const Shader* shader : {&early_shader(), &discard_shader()}) {
        Programs p(shader->fs);
        for (int state = 0; state < 16; ++state) {
            // A pass that writes stencil values (overlapping triangles count
            // up and wrap), then one that tests them and updates them again.
            GLState mark;
            mark.stencil_test = true;
            mark.depth_test = state % 2 == 0;
            mark.depth_func = GLState::DepthFunc::Less;
            for (size_t face = 0; face < 2; ++face) {
                StencilFace& f = mark.stencil[face];
                f.func = CompareFunc::Always;
                f.ref = 3 + int(face) * 250;  // 253: IncrWrap wraps soon
                f.fail = StencilOp::Keep;
                f.depth_fail = kOps[size_t(state + 3) % 8];
                f.depth_pass = face == 0 ? StencilOp::IncrWrap : kOps[size_t(state) % 8];
            }
            GLState test = mark;
            test.depth_func = state % 3 == 0 ? GLState::DepthFunc::Lequal : GLState::DepthFunc::Greater;
            test.depth_mask = state % 4 != 1;
            for (size_t face = 0; face < 2; ++face) {
                StencilFace& f = test.stencil[face];
                f.func = kCompares[size_t(state + int(face) * 3) % 8];
                f.ref = state % 5 == 0 ? 300 : 2 + state % 3;  // 300: clamped to 255
                f.value_mask = face == 0 ? 0xFFu : 0x3u;
                f.write_mask = state % 2 ? 0xFFu : 0xF0u | uint32_t(state);
                f.fail = kOps[size_t(state + int(face)) % 8];
                f.depth_fail = kOps[size_t(state + 5) % 8];
                f.depth_pass = kOps[size_t(state * 3 + int(face)) % 8];
            }
            // One face's state for both sides on some: one code path.
            if (state % 4 == 2) test.stencil[1] = test.stencil[0];
            test.blend = state % 5 == 1;
            test.blend_state.src_rgb = BlendFactor::SrcAlpha, test.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
            INFO(shader->name << ", stencil state " << state);
            check_passes_match(p, small, {mark, test},
                               state % 3 == 1 ? ColorRounding::Gpu : ColorRounding::Nearest);
        }
    }
}

TEST_CASE("the fused stencil comparison is not vacuous", "[fused]") {
    Geometry g = random_geometry(25, 900, 0.08f);
    Programs p(early_shader().fs);
    GLState mark;
    mark.stencil_test = true;
    mark.stencil[0].depth_pass = mark.stencil[1].depth_pass = StencilOp::Incr;
    GLState test;
    test.stencil_test = true;
    test.stencil[0].func = test.stencil[1].func = CompareFunc::Less;
    test.stencil[0].ref = test.stencil[1].ref = 1;  // where two or more marked
    Framebuffer fb(96, 64);
    auto marked = draw(p.fused, mark, fb, Primitive::Triangles, {g.pos, g.color}, g.count);
    REQUIRE(marked);
    size_t nonzero = 0;
    for (uint8_t s : fb.stencil) nonzero += s != 0;
    CHECK(nonzero > 500u);
    auto tested = draw(p.fused, test, fb, Primitive::Triangles, {g.pos, g.color}, g.count);
    REQUIRE(tested);
    CHECK(tested->fragments_written < tested->fragments_shaded);
    CHECK(tested->fragments_written > 0u);
    if (jit_available()) CHECK(tested->fragments_fused == tested->fragments_shaded);
}

TEST_CASE("the fused point sprites' coordinates draw the interpreter's bits", "[fused]") {
    // gl_TexCoord[0] replaced on points (GL_COORD_REPLACE), fed by the
    // vertex shader or by nothing; kept on lines.
    const char* fs = "void main() { gl_FragColor = gl_TexCoord[0] * vec4(1.0, 1.0, 7.0, 0.5) + gl_TexCoord[1]; }";
    std::string vs = std::string(kVs);
    vs.insert(vs.rfind('}'), "    gl_TexCoord[0] = gl_Color.bgra * 1.3 - 0.1;\n    gl_TexCoord[1] = gl_Color * 0.25;\n");
    Geometry g = random_geometry(26, 240, 0.5f);
    for (const char* v : {vs.c_str(), kVs}) {
        Programs p(fs, v);
        for (Primitive prim : {Primitive::Points, Primitive::Lines}) {
            for (uint32_t replace : {1u, 3u, 2u}) {
                GLState gl;
                gl.depth_test = true;
                gl.point_size = 6.3f;
                gl.point_sprite = true;
                gl.coord_replace = replace;
                INFO("vertex shader " << (v == kVs ? "without" : "with") << " gl_TexCoord, primitive " << int(prim)
                                      << ", coord_replace " << replace);
                check_fused_matches(p, prim, g, gl, false);
                check_fused_matches(p, prim, g, gl, true);
            }
        }
    }
}
