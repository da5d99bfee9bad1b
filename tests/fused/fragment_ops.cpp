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
    const auto& kEquations = kAllEquations;
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
            check_fused_matches(p, Primitive::Triangles, small, gl, true);
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
    Geometry small = random_geometry(25, 900, 0.08f);
    for (const Shader* shader : {&early_shader(), &discard_shader()}) {
        Programs p(shader->fs);
        for (int state = 0; state < 16; ++state) {
            INFO(shader->name << ", stencil state " << state);
            check_passes_match(p, small, stencil_passes(state),
                               state % 3 == 1 ? ColorRounding::Gpu : ColorRounding::Nearest);
        }
    }
}

TEST_CASE("the fused stencil comparison is not vacuous", "[fused]") {
    // Late (discard): the fragments the stencil rejects are shaded, not written.
    Geometry g = random_geometry(25, 900, 0.08f);
    Programs p(discard_shader().fs);
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
    CHECK(nonzero > 400u);  // of 900 small triangles, some fragments discarded
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

TEST_CASE("the fused pipeline writes several draw buffers as the interpreter does", "[fused]") {
    // gl_FragData[i] to buffer i (one left unwritten), and gl_FragColor to all.
    const char* kData = R"(
void main() {
    gl_FragData[0] = gl_Color * 1.4 - 0.2;
    gl_FragData[2] = vec4(fract(gl_FragCoord.xy * 0.031), gl_Color.a, 1.0 - gl_Color.r);
    if (gl_Color.g < 0.1) discard;
})";
    Geometry small = random_geometry(27, 900, 0.08f);
    for (const char* fs : {kData, kShaders[0].fs}) {
        Programs p(fs);
        for (int state = 0; state < 8; ++state) {
            GLState gl;
            gl.draw_buffers = 3;
            gl.depth_test = state % 4 != 3;
            gl.depth_func = GLState::DepthFunc::Lequal;
            gl.blend = state % 2 == 1;
            gl.blend_state.src_rgb = BlendFactor::SrcAlpha, gl.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
            gl.color_mask = {true, state != 2, true, state % 3 != 0};
            gl.alpha_test = state == 4;
            gl.alpha_func = CompareFunc::Gequal;
            gl.alpha_ref = 0.3f;
            gl.color_logic_op = state == 6;
            gl.logic_op = LogicOp::Xor;
            for (bool float_color : {false, true}) {
                const ColorRounding rounding = state % 3 == 1 ? ColorRounding::Gpu : ColorRounding::Nearest;
                Frame frames[2] = {{Framebuffer(93, 61, float_color, 3), {}}, {Framebuffer(93, 61, float_color, 3), {}}};
                for (int i = 0; i < 2; ++i) {
                    frames[i].fb.rounding = rounding;
                    frames[i].fb.clear_color({0.1f, 0.2f, 0.3f, 0.6f});
                    auto stats = draw(i == 0 ? p.oracle : p.fused, gl, frames[i].fb, Primitive::Triangles,
                                      {small.pos, small.color}, small.count);
                    REQUIRE(stats);
                    frames[i].stats = *stats;
                }
                INFO((fs == kData ? "gl_FragData" : "gl_FragColor") << ", state " << state << ", "
                                                                     << (float_color ? "float" : "RGBA8"));
                const Frame &oracle = frames[0], &fused = frames[1];
                if (jit_available()) CHECK(fused.stats.fragments_fused == fused.stats.fragments_shaded);
                CHECK(fused.stats.fragments_written == oracle.stats.fragments_written);
                for (int b = 0; b < 3; ++b) {
                    INFO("buffer " << b);
                    if (float_color) CHECK(same_bits<float>(fused.fb.color_data<float>(b), oracle.fb.color_data<float>(b)));
                    else CHECK(same_bits<uint8_t>(fused.fb.color_data<uint8_t>(b), oracle.fb.color_data<uint8_t>(b)));
                }
                CHECK(same_bits(std::span<const float>(fused.fb.depth), std::span<const float>(oracle.fb.depth)));
            }
        }
    }
}

TEST_CASE("the fused blending into float storage draws the interpreter's bits, NaNs included", "[fused]") {
    const auto& kFactors = kAllFactors;
    const auto& kEquations = kAllEquations;
    Geometry small = random_geometry(28, 900, 0.08f);
    // Colours out of [0, 1], NaNs of both signs (two NaN operands: the first one's), late depth.
    for (const Shader* shader : {&early_shader(), &kShaders[5], &depth_shader()}) {
        Programs p(shader->fs);
        const size_t n = std::size(kFactors);
        for (size_t i = 0; i < n; ++i) {
            GLState gl;
            gl.depth_test = i % 3 != 0;
            gl.depth_func = GLState::DepthFunc::Lequal;
            gl.blend = true;
            BlendState& b = gl.blend_state;
            b.src_rgb = kFactors[i];
            b.dst_rgb = kFactors[(i * 7 + 3) % n];
            b.src_alpha = kFactors[(i * 4 + 1) % n];
            b.dst_alpha = kFactors[n - 1 - i];
            b.equation_rgb = kEquations[i % 5];
            b.equation_alpha = kEquations[(i + 2) % 5];
            b.color = {0.2f, 1.3f, 0.55f, 0.7f - 0.05f * float(i)};
            gl.color_mask = {true, i % 4 != 1, true, i % 3 != 2};
            INFO(shader->name << ", blend " << i);
            check_fused_matches(p, Primitive::Triangles, small, gl, true, {93, 61});
        }
    }
}
