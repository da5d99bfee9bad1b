// The fused pipeline tests' scenes and comparisons: random primitives drawn
// by a program on the interpreter (the oracle) and the same program on the
// JIT, warmed up so that its draws take the fused pipeline.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <cstring>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "raster/fused/pipeline.h"

namespace fused_test {

using namespace glslrun;


inline const char* kVs = R"(
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

inline const Shader kShaders[] = {
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

inline Geometry random_geometry(unsigned seed, uint32_t vertices, float spread) {
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

inline Program compile(Backend backend, const char* fs, const char* vs = kVs) {
    auto p = Program::compile({{"vs", vs}}, {{"fs", fs}});
    if (!p) FAIL(p.error().str());
    p->exec.backend = backend;
    // Pipelines compiled when due (warm_up), never an earlier run's taken
    // at the first draw (tests/fused/code_cache.cpp tests that).
    p->exec.code_cache = false;
    return std::move(*p);
}

// A program compiles its pipelines once it has shaded
// raster::fused::kPipelineAfterFragments fragments: a full-screen quad of that many.
inline void warm_up(Program& p) {
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
    explicit Programs(const char* fs, const char* vs = kVs)
        : oracle(compile(Backend::Interp, fs, vs)), fused(compile(Backend::Jit, fs, vs)) {
        warm_up(fused);
    }
};

// Two passes over the geometry: one that lays down depth (GL_LEQUAL), then
// the state under test.
inline Frame render(Program& p, Primitive prim, const Geometry& g, const GLState& second, bool float_color,
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
    first.coord_replace = second.coord_replace;
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

inline bool same_colors(const Framebuffer& a, const Framebuffer& b) {
    return a.float_color() == b.float_color() && same_bits<float>(a.color_data<float>(), b.color_data<float>()) &&
           same_bits<uint8_t>(a.color_data<uint8_t>(), b.color_data<uint8_t>());
}

inline size_t distinct_colors(const Framebuffer& fb) {
    std::set<std::array<float, 4>> seen;
    for (int y = 0; y < fb.height && seen.size() < 16; ++y)
        for (int x = 0; x < fb.width; ++x) {
            glm::vec4 c = fb.pixel(x, y);
            seen.insert({c.r, c.g, c.b, c.a});
        }
    return seen.size();
}

inline void check_fused_matches(Programs& p, Primitive prim, const Geometry& g, const GLState& gl, bool float_color,
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
    CHECK(fused.fb.stencil == oracle.fb.stencil);
}

// Every blend factor and equation.
inline const BlendFactor kAllFactors[] = {
    BlendFactor::Zero,          BlendFactor::One,              BlendFactor::SrcColor,
    BlendFactor::OneMinusSrcColor, BlendFactor::DstColor,      BlendFactor::OneMinusDstColor,
    BlendFactor::SrcAlpha,      BlendFactor::OneMinusSrcAlpha, BlendFactor::DstAlpha,
    BlendFactor::OneMinusDstAlpha, BlendFactor::ConstantColor, BlendFactor::OneMinusConstantColor,
    BlendFactor::ConstantAlpha, BlendFactor::OneMinusConstantAlpha, BlendFactor::SrcAlphaSaturate};
inline const BlendEquation kAllEquations[] = {BlendEquation::Add, BlendEquation::Subtract,
                                              BlendEquation::ReverseSubtract, BlendEquation::Min, BlendEquation::Max};

inline const GLState::DepthFunc kFuncs[] = {GLState::DepthFunc::Never,   GLState::DepthFunc::Less,
                                     GLState::DepthFunc::Equal,   GLState::DepthFunc::Lequal,
                                     GLState::DepthFunc::Greater, GLState::DepthFunc::Notequal,
                                     GLState::DepthFunc::Gequal,  GLState::DepthFunc::Always};


inline const CompareFunc kCompares[] = {CompareFunc::Never,   CompareFunc::Less,     CompareFunc::Equal,
                                        CompareFunc::Lequal,  CompareFunc::Greater,  CompareFunc::Notequal,
                                        CompareFunc::Gequal,  CompareFunc::Always};

// Two passes of stencil state `state` (0 to 15): one that writes stencil
// values (overlapping triangles count up and wrap), then one that tests them
// with every function and operation over the states, two-sided, and updates
// them again.
inline std::vector<GLState> stencil_passes(int state) {
    const StencilOp kOps[] = {StencilOp::Keep, StencilOp::Zero,     StencilOp::Replace,  StencilOp::Incr,
                              StencilOp::Decr, StencilOp::Invert,   StencilOp::IncrWrap, StencilOp::DecrWrap};
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
    return {mark, test};
}

// The passes `states` in order over one cleared framebuffer, by `p`.
inline Frame render_passes(Program& p, const Geometry& g, const std::vector<GLState>& states,
                           ColorRounding rounding = ColorRounding::Nearest, glm::ivec2 size = {93, 61}) {
    Frame f{Framebuffer(size.x, size.y), {}};
    f.fb.rounding = rounding;
    f.fb.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
    f.fb.clear_depth(0.8f);
    for (const GLState& gl : states) {
        auto stats = draw(p, gl, f.fb, Primitive::Triangles, {g.pos, g.color}, g.count);
        if (!stats) FAIL(stats.error().str());
        f.stats += *stats;
    }
    return f;
}

// The passes `states` in order over one framebuffer, on both programs:
// colour, depth and stencil bit-identical, every fragment of the JIT's
// draws fused.
inline void check_passes_match(Programs& p, const Geometry& g, const std::vector<GLState>& states,
                               ColorRounding rounding = ColorRounding::Nearest, glm::ivec2 size = {93, 61}) {
    const Frame oracle = render_passes(p.oracle, g, states, rounding, size);
    const Frame fused = render_passes(p.fused, g, states, rounding, size);
    if (jit_available()) CHECK(fused.stats.fragments_fused == fused.stats.fragments_shaded);
    CHECK(oracle.stats.fragments_shaded > 200u);
    CHECK(fused.stats.fragments_written == oracle.stats.fragments_written);
    CHECK(same_colors(fused.fb, oracle.fb));
    CHECK(same_bits(std::span<const float>(fused.fb.depth), std::span<const float>(oracle.fb.depth)));
    CHECK(fused.fb.stencil == oracle.fb.stencil);
}

}  // namespace fused_test
