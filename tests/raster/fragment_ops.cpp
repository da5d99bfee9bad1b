// The per-fragment operations (raster/fragment_ops.h): GL 2.1's tables for
// stencil ops, logic ops and blending on chosen values, and images with all
// of them on (blending, stencil, alpha test, masks, draw buffers) that are
// bit-identical whatever the thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstring>

#include "raster/fragment_ops.h"
#include "raster/quad_lanes.h"
#include "raster/framebuffer.h"
#include "tests/raster/alpha_boundaries.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

using namespace glslrun;
using namespace glslrun::raster;

// NVIDIA's RGBA8 blend (tools/gpu_probes/blendover.frag, every channel of
// 1,048,576 pixels): the source and its alpha stored as bytes by the GPU's
// rule, the products of bytes exact, the result rounded to the nearest byte.
// Storing the result by the GPU's truncating rule instead gave one less on
// 3% of the channels; these five are among them, as the GPU drew them.
TEST_CASE("ColorRounding::Gpu blends as NVIDIA's driver: exact products, the result to nearest", "[raster][fragment]") {
    BlendState over;
    over.src_rgb = over.src_alpha = BlendFactor::SrcAlpha;
    over.dst_rgb = over.dst_alpha = BlendFactor::OneMinusSrcAlpha;
    struct Measured {
        uint8_t s, a, d, gpu;  // the source byte and alpha, the destination, the GPU's result
    };
    // (s a + d (255 - a)) / 255: 3.510, 148.525, 145.514, 91.510, 215.529
    for (const Measured m : {Measured{68, 2, 3, 4}, Measured{115, 172, 218, 149}, Measured{7, 46, 176, 146},
                             Measured{167, 5, 90, 92}, Measured{229, 26, 214, 216}}) {
        INFO(int(m.s) << " over " << int(m.d) << " at alpha " << int(m.a));
        const Unorm8 out = blend_unorm8(over, {m.s, m.s, m.s, m.a}, {m.d, m.d, m.d, m.d}, ColorRounding::Gpu);
        CHECK(int(out[0]) == int(m.gpu));
    }
    // Every source, alpha and destination byte: the exact value's nearest byte (255 is odd: no ties).
    for (uint32_t s = 0; s < 256; s += 3)
        for (uint32_t a = 0; a < 256; a += 5)
            for (uint32_t d = 0; d < 256; d += 7) {
                const Unorm8 out = blend_unorm8(over, {uint8_t(s), 0, 0, uint8_t(a)}, {uint8_t(d), 0, 0, 0},
                                                ColorRounding::Gpu);
                REQUIRE(int(out[0]) == int(std::lround((s * a + d * (255 - a)) / 255.0)));
            }
}

TEST_CASE("ColorRounding::Gpu stores NVIDIA's byte: 12 fraction bits, then nearest, ties down", "[raster][fragment]") {
    // The driver's rule as measured (docs/precision.md), in double: every
    // step of 2^-20 over [0, 1] and just past the ends, scalar and four lanes.
    auto measured = [](float v) {
        double c = std::clamp(double(v), 0.0, 1.0);
        return int(std::ceil(std::floor(c * 4096.0) * 255.0 / 4096.0 - 0.5));
    };
    int differ_from_nearest = 0;
    for (int k = -64; k <= (1 << 20) + 64; k += 1) {
        const float v = float(k) / float(1 << 20);
        REQUIRE(int(to_unorm8(v, ColorRounding::Gpu)) == measured(v));
        differ_from_nearest += to_unorm8(v, ColorRounding::Gpu) != to_unorm8(v);
        if (k % 4 == 0) {
            QuadF q{v, v + 0x1p-20f, v + 0x2p-20f, v + 0x3p-20f};
            QuadI bytes = pack_unorm8(q, q, q, q, ColorRounding::Gpu);
            for (int lane = 0; lane < 4; ++lane) REQUIRE((bytes[lane] & 255) == measured(q[lane]));
        }
    }
    CHECK(differ_from_nearest > 1000);  // the two rules are not the same
    CHECK(to_unorm8(0.1f, ColorRounding::Gpu) == 25);  // multi_pass's clear: 25 on the GPU, 26 in Mesa
    CHECK(to_unorm8(0.1f) == 26);
    CHECK(to_unorm8(0.5f, ColorRounding::Gpu) == 127);  // 127.5 ties down
    CHECK(to_unorm8(std::numeric_limits<float>::quiet_NaN(), ColorRounding::Gpu) == 0);
    CHECK(to_unorm8(std::numeric_limits<float>::infinity(), ColorRounding::Gpu) == 255);
    CHECK(to_unorm8(-1.0f, ColorRounding::Gpu) == 0);
}

TEST_CASE("stencil operations follow GL 2.1 section 4.1.5", "[raster][fragment]") {
    CHECK(stencil_op(StencilOp::Keep, 7, 3) == 7);
    CHECK(stencil_op(StencilOp::Zero, 7, 3) == 0);
    CHECK(stencil_op(StencilOp::Replace, 7, 3) == 3);
    CHECK(stencil_op(StencilOp::Replace, 7, 300) == 255);  // the reference clamped to the buffer's bits
    CHECK(stencil_op(StencilOp::Incr, 255, 0) == 255);     // saturates
    CHECK(stencil_op(StencilOp::Decr, 0, 0) == 0);
    CHECK(stencil_op(StencilOp::IncrWrap, 255, 0) == 0);   // wraps
    CHECK(stencil_op(StencilOp::DecrWrap, 0, 0) == 255);
    CHECK(stencil_op(StencilOp::Invert, 0x0F, 0) == 0xF0);
}

TEST_CASE("logic ops follow GL 2.1 Table 4.3", "[raster][fragment]") {
    const uint32_t s = 0xCA, d = 0x5C;
    const uint32_t want[16] = {0x00,          s & d,          s & ~d & 0xFF, s,
                               ~s & d & 0xFF, d,              s ^ d,         s | d,
                               ~(s | d) & 0xFF, ~(s ^ d) & 0xFF, ~d & 0xFF,  (s | ~d) & 0xFF,
                               ~s & 0xFF,     (~s | d) & 0xFF, ~(s & d) & 0xFF, 0xFF};
    for (int op = 0; op < 16; ++op) {
        INFO("logic op " << op);
        CHECK(logic_op(LogicOp(op), s, d) == want[op]);
    }
}

TEST_CASE("blending follows GL 2.1 Table 4.1 and the equations", "[raster][fragment]") {
    const glm::vec4 src{0.5f, 0.25f, 1.0f, 0.75f}, dst{0.25f, 0.5f, 0.0f, 0.5f};
    BlendState b;
    b.src_rgb = b.src_alpha = BlendFactor::SrcAlpha;
    b.dst_rgb = b.dst_alpha = BlendFactor::OneMinusSrcAlpha;
    glm::vec4 over = blend(b, src, dst);
    CHECK(over.r == Approx(0.5 * 0.75 + 0.25 * 0.25));
    CHECK(over.a == Approx(0.75 * 0.75 + 0.5 * 0.25));
    b.src_rgb = BlendFactor::SrcAlphaSaturate;  // f = min(As, 1 - Ad) = 0.5; alpha factor 1
    b.src_alpha = BlendFactor::SrcAlphaSaturate;
    b.dst_rgb = b.dst_alpha = BlendFactor::Zero;
    glm::vec4 sat = blend(b, src, dst);
    CHECK(sat.g == Approx(0.25 * 0.5));
    CHECK(sat.a == Approx(0.75));
    b.src_rgb = b.dst_rgb = BlendFactor::ConstantColor;
    b.color = {0.5f, 0.5f, 0.5f, 0.5f};
    b.equation_rgb = BlendEquation::ReverseSubtract;
    CHECK(blend(b, src, dst).g == Approx(0.5 * 0.5 - 0.25 * 0.5));
    b.equation_rgb = BlendEquation::Min;
    b.equation_alpha = BlendEquation::Max;
    glm::vec4 mm = blend(b, src, dst);
    CHECK(mm.b == 0.0f);
    CHECK(mm.a == 0.75f);
    // Fixed point: products rounded to n/255, saturating sums.
    BlendState add;
    add.dst_rgb = add.dst_alpha = BlendFactor::One;
    const Unorm8 light{204, 204, 204, 204}, mid{153, 153, 153, 153}, dark{102, 102, 102, 102}, darker{51, 51, 51, 51};
    CHECK(blend_unorm8(add, light, mid)[0] == 255);
    CHECK(blend_unorm8(b, dark, darker)[0] == 51);  // min(102, 51)
}

namespace {

const char* kVertex = R"(
void main() {
    gl_FrontColor = vec4(gl_Vertex.xy * 0.5 + 0.5, 0.5, 1.0);
    gl_Position = ftransform();
}
)";

const char* kFragment = R"(
uniform float alpha;
void main() {
    float a = alpha < 0.0 ? fract(gl_FragCoord.x * 0.37) : alpha;
    gl_FragData[0] = vec4(gl_Color.rgb, a);
    gl_FragData[1] = vec4(gl_Color.bgr, 1.0 - a);
}
)";

// Many overlapping quads and a teapot across many tiles, each with its own state.
const char* kScene = R"(
[output]
size = [300, 200]
clear_color = [0.1, 0.2, 0.3, 0.4]
clear_stencil = 2
[state]
draw_buffers = 2
[uniforms]
alpha = 0.6
[[objects]]
mesh = "teapot"
subdivisions = 6
transform = [ { scale = [0.6, 0.6, 0.6] } ]
state = { depth_test = true, stencil_test = true, stencil_pass_depth_pass = "incr", blend = true, blend_func = ["src_alpha", "one_minus_src_alpha"] }
[[objects]]
mesh = "quad"
transform = [ { rotate = [20, 0, 0, 1] }, { scale = [0.8, 0.8, 1] } ]
uniforms = { alpha = -1.0 }
state = { stencil_test = true, stencil_func = "lequal", stencil_ref = 3, stencil_fail = "invert", alpha_test = true, alpha_test_func = "less", alpha_test_ref = 0.5, blend = true, blend_func = ["one", "one"], blend_equation = "func_subtract" }
[[objects]]
mesh = "quad"
transform = [ { rotate = [-30, 0, 0, 1] }, { scale = [0.9, 0.5, 1] } ]
state = { color_logic_op = true, logic_op_mode = "xor", color_writemask = [true, true, false, true], scissor_test = true, scissor_box = [40, 30, 200, 150] }
)";

}  // namespace

TEST_CASE("blending picked once per draw is bit-identical to blend_unorm8()", "[raster][fragment]") {
    // Every factor pair and equation for RGB, alpha with the same ones
    // (glBlendFunc: the whole-pixel functions) or others, over byte values
    // that include 0 and 255.
    const Unorm8 srcs[] = {{51, 178, 255, 102}, {255, 0, 128, 254}, {0, 0, 0, 0}, {1, 64, 200, 255}};
    const Unorm8 dsts[] = {{153, 25, 0, 255}, {255, 255, 255, 0}, {77, 217, 115, 51}};
    size_t checked = 0;
    for (int sf = 0; sf <= int(BlendFactor::SrcAlphaSaturate); ++sf)
        for (int df = 0; df <= int(BlendFactor::SrcAlphaSaturate); ++df)
            for (int eq = 0; eq <= int(BlendEquation::Max); ++eq)
                for (int alpha = 0; alpha < 2; ++alpha) {
                    BlendState st;
                    st.src_rgb = BlendFactor(sf);
                    st.dst_rgb = BlendFactor(df);
                    st.src_alpha = alpha ? BlendFactor((sf + 3) % 15) : st.src_rgb;
                    st.dst_alpha = alpha ? BlendFactor((df + 5) % 15) : st.dst_rgb;
                    st.equation_rgb = BlendEquation(eq);
                    st.equation_alpha = alpha ? BlendEquation((eq + 1) % 5) : st.equation_rgb;
                    st.color = {0.3f, 0.6f, 0.9f, 0.5f};
                    ResolvedBlend b = resolve_blend(st);
                    for (const Unorm8& src : srcs)
                        for (const Unorm8& dst : dsts) {
                            INFO("factors " << sf << " " << df << ", equation " << eq << ", alpha " << alpha);
                            CHECK(b.pixel8(b, src, dst) == blend_unorm8(st, src, dst));
                            ++checked;
                        }
                }
    CHECK(checked == 15u * 15u * 5u * 2u * 12u);
}

TEST_CASE("per-fragment operations give the same image whatever the thread count", "[raster][fragment][threads]") {
    auto scene = scene::parse_scene(kScene, "ops.toml");
    REQUIRE(scene);
    auto render = [&](unsigned threads) {
        auto p = Program::compile({{"vs", kVertex}}, {{"fs", kFragment}});
        REQUIRE(p);
        p->exec.threads = threads;
        Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
        REQUIRE(scene::render_scene(*p, *scene, fb));
        return fb;
    };
    Framebuffer one = render(1);
    // Something of every buffer was written: not a vacuous comparison.
    CHECK(one.color_buffers() == 2);
    CHECK(std::count(one.stencil.begin(), one.stencil.end(), uint8_t(2)) < std::ptrdiff_t(one.stencil.size()));
    for (unsigned threads : {2u, 3u, 7u}) {
        INFO("threads " << threads);
        Framebuffer many = render(threads);
        for (int b = 0; b < 2; ++b) CHECK(std::ranges::equal(one.color_data<uint8_t>(b), many.color_data<uint8_t>(b)));
        CHECK(one.depth == many.depth);
        CHECK(one.stencil == many.stencil);
    }
}

TEST_CASE("scenes in Fast store colours by the GPU's rule, the other modes by Mesa's", "[raster][fragment]") {
    auto scene = scene::parse_scene("[output]\nsize = [8, 8]\nclear_color = [0.1, 0.5, 0.0, 1.0]\n", "clear.toml");
    if (!scene) FAIL(scene.error().str());
    auto cleared = [&](Precision precision) {
        auto p = Program::compile({{"vs", "void main() { gl_Position = ftransform(); }"}},
                                  {{"fs", "void main() { gl_FragColor = vec4(1.0); }"}});
        REQUIRE(p);
        p->exec.precision = precision;
        Framebuffer fb(scene->width, scene->height);
        REQUIRE(scene::render_scene(*p, *scene, fb));
        CHECK(fb.rounding == color_rounding_for(precision));
        return std::array<int, 2>{fb.color_data<uint8_t>()[0], fb.color_data<uint8_t>()[1]};
    };
    CHECK(cleared(Precision::Fast) == std::array<int, 2>{25, 127});
    CHECK(cleared(Precision::Precise) == std::array<int, 2>{26, 128});
    CHECK(cleared(Precision::Reference) == std::array<int, 2>{26, 128});
}

TEST_CASE("the alpha test compares the bytes of an RGBA8 buffer, floats of a float buffer", "[raster][fragment]") {
    using alpha_boundaries::kCases;
    auto scene = scene::parse_scene(alpha_boundaries::scene(), "alpha.toml");
    REQUIRE(scene);
    for (size_t i = 0; i < kCases.size(); ++i) {
        const auto& c = kCases[i];
        INFO("case " << i << ": alpha " << c.alpha << " " << c.func << " " << c.ref);
        REQUIRE(scene->objects[i].state);
        const GLState& gl = *scene->objects[i].state;
        REQUIRE(gl.alpha_test);
        Lanes alpha{};
        alpha.fill(c.alpha);
        CHECK(bool(alpha_test(FragmentOps(gl, Framebuffer(4, 4)), alpha, 1) & 1) == c.passes);
        // A float buffer compares the values themselves (clamped reference).
        float ref = std::clamp(c.ref, 0.0f, 1.0f);
        bool float_passes = depth_passes(gl.alpha_func, c.alpha, ref);
        CHECK(bool(alpha_test(FragmentOps(gl, Framebuffer(4, 4, true)), alpha, 1) & 1) == float_passes);
    }
    // Both backends draw it so: the JIT's fused pipeline leaves the alpha test to the C++ path.
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << backend_name(backend));
        auto p = Program::compile({{"vs", kVertex}}, {{"fs", "uniform float alpha;\n"
                                                               "void main() { gl_FragColor = vec4(gl_Color.rgb, alpha); }\n"}});
        REQUIRE(p);
        p->exec.backend = backend;
        Framebuffer fb(scene->width, scene->height);
        REQUIRE(scene::render_scene(*p, *scene, fb));
        for (size_t i = 0; i < kCases.size(); ++i) {
            auto [x, y] = alpha_boundaries::centre(i);
            INFO("case " << i);
            // Drawn where it passes: the clear's black otherwise.
            CHECK((fb.pixel(x, y).b > 0.0f) == kCases[i].passes);
        }
    }
}
