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
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <set>
#include <span>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "glslrun/glslrun.h"
#include "raster/fused/pipeline.h"

using namespace glslrun;

namespace {

const char* kVs = R"(
varying vec3 position;
varying float signed_nan;
void main() {
    float nan = sqrt(-1.0 - gl_Color.g);
    signed_nan = gl_Color.r > 0.5 ? nan : -nan;
    gl_Position = gl_Vertex;
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color.bgra;
    position = gl_Vertex.xyz * 0.5 + 0.5;
    gl_PointSize = 7.0;
}
)";

struct Shader {
    const char* name;
    const char* fs;
};

const Shader kShaders[] = {
    {"colour out of range", "void main() { gl_FragColor = gl_Color * 1.6 - 0.3; }"},
    {"varying, perspective", R"(
varying vec3 position;
void main() { gl_FragColor = vec4(fract(position * 3.7), gl_Color.a); })"},
    {"built-ins", R"(
void main() {
    vec4 c = vec4(fract(gl_FragCoord.xy * 0.013), gl_FragCoord.z, gl_FragCoord.w * 0.3);
    gl_FragColor = gl_FrontFacing ? c : c.wzyx;
})"},
    {"discard", R"(
void main() {
    if (fract(gl_FragCoord.x * 0.37 + gl_Color.g * 3.0) < 0.3) discard;
    gl_FragColor = gl_Color;
})"},
    {"gl_FragDepth, NaN", R"(
void main() {
    // Out of [0, 1] and NaN depths: clamped, NaN to 0; NaN colours to 0.
    float nan = sqrt(gl_Color.b - 0.9);
    gl_FragDepth = gl_Color.r < 0.1 ? nan : gl_Color.r * 1.4 - 0.2;
    gl_FragColor = vec4(gl_Color.gb, nan, 1.0);
})"},
    {"NaNs of both signs", R"(
varying float signed_nan;
void main() { gl_FragColor = vec4(signed_nan, -signed_nan, 0.5, 1.0); })"},
    {"depth only", "void main() { if (gl_Color.r < 0.4) discard; gl_FragDepth = gl_Color.g; }"},
    {"gl_PointCoord", "#version 120\nvoid main() { gl_FragColor = vec4(gl_PointCoord, gl_Color.b, 1.0); }"},
};

// Random primitives over a 96x64 target, with w in [0.5, 2] and a few depth
// levels, so that fragments tie and the depth function decides.
struct Geometry {
    VertexAttrib pos{"gl_Vertex", 4, {}};
    VertexAttrib color{"gl_Color", 4, {}};
    uint32_t count = 0;
};

Geometry random_geometry(unsigned seed, uint32_t vertices, float spread) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> centre(-1.1f, 1.1f), offset(-spread, spread), unit(0.0f, 1.0f), w(0.5f, 2.0f);
    std::uniform_int_distribution<int> level(0, 3);
    Geometry g;
    float cx = 0, cy = 0, z = 0;
    for (uint32_t v = 0; v < vertices; ++v) {
        if (v % 3 == 0) cx = centre(rng), cy = centre(rng), z = float(level(rng)) * 0.25f - 0.4f;
        float wv = w(rng);
        g.pos.data.insert(g.pos.data.end(), {(cx + offset(rng)) * wv, (cy + offset(rng)) * wv, z * wv, wv});
        g.color.data.insert(g.color.data.end(), {unit(rng), unit(rng), unit(rng), unit(rng)});
    }
    g.count = vertices;
    return g;
}

struct Frame {
    Framebuffer fb;
    DrawStats stats;
};

Program compile(Backend backend, const char* fs) {
    auto p = Program::compile({{"vs", kVs}}, {{"fs", fs}});
    if (!p) FAIL(p.error().str());
    p->exec.backend = backend;
    return std::move(*p);
}

// A program compiles its pipelines once it has shaded
// raster::fused::kPipelineAfterFragments fragments: a full-screen quad of that many.
void warm_up(Program& p) {
    static_assert(raster::fused::kPipelineAfterFragments == 1024 * 1024);
    Framebuffer fb(1024, 1024);
    VertexAttrib pos{"gl_Vertex", 4, {-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1}};
    auto stats = draw(p, GLState{}, fb, Primitive::Triangles, {pos}, 6);
    if (!stats) FAIL(stats.error().str());
    CHECK(stats->fragments_fused == 0u);
}

// The programs of one shader, on the interpreter (the oracle) and the JIT
// (warmed up: its draws take the fused pipeline).
struct Programs {
    Program oracle, fused;
    explicit Programs(const char* fs) : oracle(compile(Backend::Interp, fs)), fused(compile(Backend::Jit, fs)) {
        warm_up(fused);
    }
};

// Two passes over the geometry: one that lays down depth (GL_LEQUAL), then
// the state under test.
Frame render(Program& p, Primitive prim, const Geometry& g, const GLState& second, bool float_color,
             glm::ivec2 size = {96, 64}, ColorRounding rounding = ColorRounding::Nearest) {
    Frame f{Framebuffer(size.x, size.y, float_color), {}};
    f.fb.rounding = rounding;
    f.fb.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
    f.fb.clear_depth(0.8f);
    GLState first;
    first.depth_test = true;
    first.depth_func = GLState::DepthFunc::Lequal;
    first.point_size = second.point_size;
    first.point_sprite = second.point_sprite;
    for (const GLState& gl : {first, second}) {
        auto stats = draw(p, gl, f.fb, prim, {g.pos, g.color}, g.count);
        if (!stats) FAIL(stats.error().str());
        f.stats += *stats;
    }
    return f;
}

template <class T>
bool same_bits(std::span<const T> a, std::span<const T> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

bool same_colors(const Framebuffer& a, const Framebuffer& b) {
    return a.float_color() == b.float_color() && same_bits<float>(a.color_data<float>(), b.color_data<float>()) &&
           same_bits<uint8_t>(a.color_data<uint8_t>(), b.color_data<uint8_t>());
}

size_t distinct_colors(const Framebuffer& fb) {
    std::set<std::array<float, 4>> seen;
    for (int y = 0; y < fb.height && seen.size() < 16; ++y)
        for (int x = 0; x < fb.width; ++x) {
            glm::vec4 c = fb.pixel(x, y);
            seen.insert({c.r, c.g, c.b, c.a});
        }
    return seen.size();
}

void check_fused_matches(Programs& p, Primitive prim, const Geometry& g, const GLState& gl, bool float_color,
                         glm::ivec2 size = {96, 64}, ColorRounding rounding = ColorRounding::Nearest) {
    Frame oracle = render(p.oracle, prim, g, gl, float_color, size, rounding);
    Frame fused = render(p.fused, prim, g, gl, float_color, size, rounding);
    CHECK(oracle.stats.fragments_fused == 0u);
    if (jit_available()) {
        // Every fragment of the JIT's draws took the fused pipeline.
        CHECK(fused.stats.fragments_fused == fused.stats.fragments_shaded);
    }
    CHECK(oracle.stats.fragments_shaded > 200u);
    CHECK(fused.stats.fragments_shaded == oracle.stats.fragments_shaded);
    CHECK(fused.stats.fragments_written == oracle.stats.fragments_written);
    CHECK(same_colors(fused.fb, oracle.fb));
    CHECK(same_bits(std::span<const float>(fused.fb.depth), std::span<const float>(oracle.fb.depth)));
}

const GLState::DepthFunc kFuncs[] = {GLState::DepthFunc::Never,   GLState::DepthFunc::Less,
                                     GLState::DepthFunc::Equal,   GLState::DepthFunc::Lequal,
                                     GLState::DepthFunc::Greater, GLState::DepthFunc::Notequal,
                                     GLState::DepthFunc::Gequal,  GLState::DepthFunc::Always};

}  // namespace

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
            // Blending and masks with a late depth test (discard, gl_FragDepth) keep the C++ path.
            const bool late_depth = std::string_view(shader.fs).find("discard") != std::string_view::npos ||
                                    std::string_view(shader.fs).find("gl_FragDepth") != std::string_view::npos;
            if (late_depth && gl.depth_test && (gl.blend || state == 1)) continue;
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

TEST_CASE("blending with a late depth test or float storage keeps the C++ path", "[fused]") {
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
            const bool second_fused = !float_color && shader.fs == kShaders[0].fs;
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
