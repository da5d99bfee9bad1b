// The fused fragment pipeline (raster/fused/pipeline.h) against the
// interpreter's per-fragment path, the oracle: colour and depth buffers
// bit-identical, the same fragment counts, and every fragment of the JIT's
// draws through the fused pipeline (DrawStats::fragments_fused). Scenes with
// many overlapping small triangles (quads of one batch on the same pixel),
// perspective (w != 1), every depth function with and without depth
// writes, discard, gl_FragDepth (clamped, NaN), colours out of [0, 1] and
// NaN, gl_FragCoord, gl_FrontFacing, gl_PointCoord, points and lines, into
// RGBA8 and float framebuffers, sizes that are and are not multiples of 8.
// Built at 8 and 64 lanes too (tools/setup.sh test).
#include <string>
#include <string_view>

#include "harness.h"

using namespace glslrun;
using namespace fused_test;

TEST_CASE("the fused pipeline draws the interpreter's bits: triangles, every depth state", "[fused]") {
    // Small triangles: several quads of one batch cover the same pixel.
    Geometry small = random_geometry(11, 900, 0.08f);
    Geometry large = random_geometry(12, 30, 0.9f);
    for (const Shader& shader : kShaders) {
        Programs p(shader.fs);
        for (int state = 0; state < 2 * 8 + 1; ++state) {
            GLState gl;
            gl.depth_test = state < 16;
            gl.depth_func = kFuncs[state % 8];
            gl.depth_mask = state / 8 == 0;
            // Float storage on a few states (the colour conversion differs, not the tests).
            for (bool float_color : {false, true}) {
                if (float_color && state % 5 != 0) continue;
                INFO(shader.name << ", " << (float_color ? "float" : "RGBA8") << ", depth test " << gl.depth_test
                                 << " func " << int(gl.depth_func) << " mask " << gl.depth_mask);
                check_fused_matches(p, Primitive::Triangles, small, gl, float_color);
                check_fused_matches(p, Primitive::Triangles, large, gl, float_color);
                // A size that cuts 8x8 squares at the right and top edges
                // (the early depth test takes a square's pixels at once).
                if (!float_color && state % 3 == 0) check_fused_matches(p, Primitive::Triangles, small, gl, false, {93, 61});
            }
        }
    }
}

TEST_CASE("the fused pipeline draws the interpreter's bits: points and lines", "[fused]") {
    Geometry g = random_geometry(13, 240, 0.5f);
    for (const Shader& shader : kShaders) {
        Programs p(shader.fs);
        for (Primitive prim : {Primitive::Points, Primitive::Lines, Primitive::LineStrip}) {
            for (GLState::DepthFunc func : {GLState::DepthFunc::Less, GLState::DepthFunc::Always}) {
                // Sprites of a fractional size: gl_PointCoord steps by 1/6.3.
                for (bool sprite : {false, true}) {
                    GLState gl;
                    gl.depth_test = true;
                    gl.depth_func = func;
                    gl.point_size = sprite ? 6.3f : 7.0f;
                    gl.point_sprite = sprite;
                    INFO(shader.name << ", primitive " << int(prim) << ", depth func " << int(func) << ", sprite " << sprite);
                    check_fused_matches(p, prim, g, gl, false);
                    if (prim != Primitive::Points) break;
                }
            }
        }
    }
}

TEST_CASE("the fused pipeline blends and masks the interpreter's bits", "[fused]") {
    // Every factor on both sides, every equation, separate alpha, a
    // constant colour, colour masks; colours out of [0, 1], varied alpha,
    // and overlapping small triangles (a batch's quads blend in order).
    const BlendFactor kFactors[] = {
        BlendFactor::Zero,          BlendFactor::One,           BlendFactor::SrcColor,
        BlendFactor::OneMinusSrcColor, BlendFactor::DstColor,   BlendFactor::OneMinusDstColor,
        BlendFactor::SrcAlpha,      BlendFactor::OneMinusSrcAlpha, BlendFactor::DstAlpha,
        BlendFactor::OneMinusDstAlpha, BlendFactor::ConstantColor, BlendFactor::OneMinusConstantColor,
        BlendFactor::ConstantAlpha, BlendFactor::OneMinusConstantAlpha, BlendFactor::SrcAlphaSaturate};
    const BlendEquation kEquations[] = {BlendEquation::Add, BlendEquation::Subtract, BlendEquation::ReverseSubtract,
                                        BlendEquation::Min, BlendEquation::Max};
    Geometry small = random_geometry(14, 900, 0.08f);
    Geometry large = random_geometry(15, 30, 0.9f);
    Programs p(kShaders[0].fs);  // colour out of range
    const size_t n = std::size(kFactors);
    for (size_t i = 0; i < n; ++i) {
        GLState gl;
        // Early depth tests that pass the second pass's fragments where the
        // first left their depth (as multi-pass lighting draws), or none.
        const GLState::DepthFunc kPassing[] = {GLState::DepthFunc::Equal, GLState::DepthFunc::Lequal,
                                               GLState::DepthFunc::Gequal, GLState::DepthFunc::Always};
        gl.depth_test = i % 3 != 0;
        gl.depth_func = kPassing[i % 4];
        gl.depth_mask = i % 2 == 0;
        gl.blend = true;
        BlendState& b = gl.blend_state;
        b.src_rgb = kFactors[i];
        b.dst_rgb = kFactors[(i * 7 + 3) % n];
        b.src_alpha = kFactors[(i * 4 + 1) % n];
        b.dst_alpha = kFactors[(n - 1 - i)];
        b.equation_rgb = kEquations[i % 5];
        b.equation_alpha = kEquations[(i + 2) % 5];
        b.color = {0.2f, 1.3f, 0.55f, 0.7f - 0.05f * float(i)};  // clamped by GL
        INFO("blend " << i << ": factors " << int(b.src_rgb) << " " << int(b.dst_rgb) << " " << int(b.src_alpha)
                      << " " << int(b.dst_alpha) << ", equations " << int(b.equation_rgb) << " "
                      << int(b.equation_alpha));
        check_fused_matches(p, Primitive::Triangles, small, gl, false);
        check_fused_matches(p, Primitive::Triangles, large, gl, false);
        // Quads cut by the right and top edges (masked reads and writes there).
        check_fused_matches(p, Primitive::Triangles, small, gl, false, {93, 61});
        // glBlendFunc(S, D): the same factors for alpha, and the common pairs.
        b.src_alpha = b.src_rgb, b.dst_alpha = b.dst_rgb, b.equation_alpha = BlendEquation::Add;
        b.equation_rgb = BlendEquation::Add;
        check_fused_matches(p, Primitive::Triangles, small, gl, false);
    }
    for (int mask = 0; mask < 16; ++mask) {
        GLState gl;
        gl.depth_test = true;
        gl.depth_func = GLState::DepthFunc::Lequal;
        gl.color_mask = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0};
        gl.blend = mask % 3 == 0;
        gl.blend_state.src_rgb = BlendFactor::SrcAlpha;
        gl.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
        INFO("colour mask " << mask << ", blend " << gl.blend);
        check_fused_matches(p, Primitive::Triangles, small, gl, false);
    }
}

TEST_CASE("the fused pipeline rounds colours as the C++ path does: ColorRounding::Gpu", "[fused]") {
    Geometry small = random_geometry(17, 900, 0.08f);
    Geometry large = random_geometry(18, 30, 0.9f);
    for (const Shader& shader : kShaders) {
        Programs p(shader.fs);
        const BlendEquation kEquations[] = {BlendEquation::Add, BlendEquation::Subtract,
                                            BlendEquation::ReverseSubtract, BlendEquation::Min, BlendEquation::Max};
        for (int state = 0; state < 8; ++state) {
            GLState gl;
            gl.depth_test = state != 3;
            gl.depth_func = state == 0 ? GLState::DepthFunc::Less : GLState::DepthFunc::Lequal;
            gl.blend = state >= 2;
            BlendState& b = gl.blend_state;
            b.src_rgb = state % 2 ? BlendFactor::ConstantColor : BlendFactor::SrcAlpha;
            b.dst_rgb = state % 3 ? BlendFactor::OneMinusSrcAlpha : BlendFactor::DstColor;
            b.src_alpha = BlendFactor::One, b.dst_alpha = BlendFactor::OneMinusDstAlpha;
            b.equation_rgb = kEquations[state % 5], b.equation_alpha = kEquations[(state + 1) % 5];
            gl.blend_state.color = {0.1f, 0.502f, 0.7f, 0.35f};  // bytes that the two roundings store differently
            gl.color_mask = {true, state != 1, true, true};
            INFO(shader.name << ", state " << state);
            check_fused_matches(p, Primitive::Triangles, small, gl, false, {96, 64}, ColorRounding::Gpu);
            check_fused_matches(p, Primitive::Triangles, large, gl, false, {93, 61}, ColorRounding::Gpu);
        }
    }
    // The rule reaches the stored bytes (so the comparison above is not of two Nearest images).
    Programs p(kShaders[0].fs);
    Geometry g = random_geometry(19, 30, 0.9f);
    Frame nearest = render(p.fused, Primitive::Triangles, g, GLState{}, false, {96, 64}, ColorRounding::Nearest);
    Frame gpu = render(p.fused, Primitive::Triangles, g, GLState{}, false, {96, 64}, ColorRounding::Gpu);
    CHECK_FALSE(same_colors(nearest.fb, gpu.fb));
}

TEST_CASE("blending into float storage keeps the C++ path; with a late depth test it is fused", "[fused]") {
    Geometry small = random_geometry(16, 900, 0.08f);
    GLState gl;
    gl.blend = true;
    gl.blend_state.src_rgb = BlendFactor::One;
    gl.blend_state.dst_rgb = BlendFactor::One;
    gl.depth_test = true;
    gl.depth_func = GLState::DepthFunc::Lequal;
    for (const Shader& shader : {kShaders[0], kShaders[3]}) {  // early depth; discard (late)
        Programs p(shader.fs);
        for (bool float_color : {false, true}) {
            INFO(shader.name << ", " << (float_color ? "float" : "RGBA8"));
            Frame oracle = render(p.oracle, Primitive::Triangles, small, gl, float_color);
            Frame fused = render(p.fused, Primitive::Triangles, small, gl, float_color);
            CHECK(same_colors(fused.fb, oracle.fb));
            CHECK(same_bits(std::span<const float>(fused.fb.depth), std::span<const float>(oracle.fb.depth)));
            CHECK(fused.stats.fragments_written == oracle.stats.fragments_written);
            // The first pass (no blending) is fused; the second only where generated.
            const bool second_fused = !float_color;
            INFO("fused " << fused.stats.fragments_fused << " of " << fused.stats.fragments_shaded);
            CHECK(fused.stats.fragments_shaded > 671u + 600u);  // the first pass shades 671, the second most again
            if (jit_available()) CHECK((fused.stats.fragments_fused == fused.stats.fragments_shaded) == second_fused);
        }
    }
}

TEST_CASE("the fused blending's product is mul_unorm8's for every pair of bytes", "[fused]") {
    // raster/fused/gen/blend.cpp rounds a product to n/255 with shifts; raster/fragment_ops.cpp divides.
    int differ = 0;
    for (uint32_t x = 0; x < 256; ++x)
        for (uint32_t f = 0; f < 256; ++f) {
            const uint32_t t = x * f + 128;
            differ += ((t + (t >> 8)) >> 8) != (x * f * 2 + 255) / 510;
        }
    CHECK(differ == 0);
}

TEST_CASE("the fused blending comparisons are not vacuous", "[fused]") {
    Geometry g = random_geometry(14, 900, 0.08f);
    Programs p(kShaders[0].fs);
    GLState gl;
    gl.depth_test = true;
    gl.depth_func = GLState::DepthFunc::Lequal;
    Frame plain = render(p.fused, Primitive::Triangles, g, gl, false);
    gl.blend = true;
    gl.blend_state.src_rgb = BlendFactor::SrcAlpha;
    gl.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
    Frame blended = render(p.fused, Primitive::Triangles, g, gl, false);
    gl.color_mask = {true, false, true, false};
    Frame masked = render(p.fused, Primitive::Triangles, g, gl, false);
    CHECK(blended.stats.fragments_written == plain.stats.fragments_written);
    CHECK_FALSE(same_colors(plain.fb, blended.fb));
    CHECK_FALSE(same_colors(blended.fb, masked.fb));
}

TEST_CASE("the fused comparisons are not vacuous", "[fused]") {
    Geometry g = random_geometry(11, 900, 0.08f);
    GLState gl;
    gl.depth_test = true;
    for (const Shader& shader : kShaders) {
        // Nothing to see in RGBA8: the depth only shader's colour, NaN's (0).
        if (std::string(shader.name) == "depth only" || std::string(shader.name) == "NaNs of both signs") continue;
        INFO(shader.name);
        Programs p(shader.fs);
        CHECK(distinct_colors(render(p.fused, Primitive::Triangles, g, gl, false).fb) > 8u);
    }
}
