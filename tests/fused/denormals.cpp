// Denormals in the fragment stage: a tile walk runs its batches, their
// inputs and per-fragment operations as well as the shader, with denormals
// flushed (raster::FragmentStage::Walk), so the C++ path and the fused
// pipeline must agree under that mode on denormal inputs, depths, colours
// and blends, and the mode must reach the interpolation (as llvmpipe's
// fragment threads run) but not Reference, which keeps denormals.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "harness.h"

using namespace glslrun;
using namespace fused_test;

namespace {

const char* kTinyVs = R"(
attribute vec4 tiny;
varying vec4 t;
void main() {
    gl_Position = gl_Vertex;
    gl_FrontColor = gl_Color;
    t = tiny;
}
)";

// The varying straight into the colour and the depth: moves, which keep a
// denormal's bits where no arithmetic flushes it.
const char* kTinyFs = R"(
varying vec4 t;
void main() {
    gl_FragColor = t;
    gl_FragDepth = gl_Color.r < 0.4 ? t.w : gl_Color.g;
}
)";

const char* kTinyColorFs = "varying vec4 t;\nvoid main() { gl_FragColor = t; }";

// Per vertex: values around the smallest normal float (denormals of both
// signs, the smallest normals, zeros of both signs), so that the interpolation's
// products and sums cross into the denormal range.
Geometry tiny_geometry(unsigned seed, uint32_t vertices, VertexAttrib& tiny) {
    Geometry g = random_geometry(seed, vertices, 0.3f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> scale(-4.0f, 4.0f);
    tiny = VertexAttrib{"tiny", 4, {}};
    for (uint32_t v = 0; v < vertices * 4; ++v) {
        const float min_normal = 1.17549435e-38f;
        const float value = v % 7 == 0 ? 0.0f : v % 11 == 0 ? -0.0f : v % 5 == 0 ? 0.5f : min_normal * scale(rng);
        tiny.data.push_back(value);
    }
    return g;
}

Frame draw_tiny(Program& p, const Geometry& g, const VertexAttrib& tiny, const GLState& gl, glm::ivec2 size) {
    Frame f{Framebuffer(size.x, size.y, true), {}};
    f.fb.clear_color({0.5f, 0.5f, 0.25f, 1.0f});
    f.fb.clear_depth(0.9f);
    auto stats = draw(p, gl, f.fb, Primitive::Triangles, {g.pos, g.color, tiny}, g.count);
    if (!stats) FAIL(stats.error().str());
    f.stats = *stats;
    return f;
}

}  // namespace

TEST_CASE("the fused pipeline and the C++ path agree on denormals: inputs, depths, float colours, blends",
          "[fused]") {
    VertexAttrib tiny;
    Geometry g = tiny_geometry(31, 600, tiny);
    Programs p(kTinyFs, kTinyVs);
    for (int state = 0; state < 4; ++state) {
        GLState gl;
        gl.depth_test = true;
        gl.depth_func = state % 2 ? GLState::DepthFunc::Lequal : GLState::DepthFunc::Greater;
        gl.blend = state >= 2;  // float blending: denormal products and sums
        gl.blend_state.src_rgb = BlendFactor::SrcAlpha;
        gl.blend_state.dst_rgb = state == 3 ? BlendFactor::One : BlendFactor::OneMinusSrcAlpha;
        INFO("state " << state);
        for (glm::ivec2 size : {glm::ivec2{96, 64}, glm::ivec2{93, 61}}) {
            Frame oracle = draw_tiny(p.oracle, g, tiny, gl, size);
            Frame fused = draw_tiny(p.fused, g, tiny, gl, size);
            if (jit_available()) CHECK(fused.stats.fragments_fused == fused.stats.fragments_shaded);
            CHECK(oracle.stats.fragments_shaded > 1000u);
            CHECK(fused.stats.fragments_written == oracle.stats.fragments_written);
            CHECK(same_colors(fused.fb, oracle.fb));
            CHECK(same_bits(std::span<const float>(fused.fb.depth), std::span<const float>(oracle.fb.depth)));
        }
    }
}

TEST_CASE("the fragment stage interpolates with denormals flushed, except in Reference", "[fused]") {
    // Every vertex carries the same denormal: interpolated without flushing,
    // a0 + p1 * 0 + p2 * 0 is a0 itself; flushed, +0.
    Geometry g = random_geometry(32, 90, 0.6f);
    VertexAttrib tiny{"tiny", 4, {}};
    for (uint32_t v = 0; v < g.count; ++v) tiny.data.insert(tiny.data.end(), {3e-39f, -3e-39f, 3e-39f, 1.0f});
    GLState gl;
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        for (Precision precision : {Precision::Precise, Precision::Fast, Precision::Reference}) {
            Program program = compile(backend, kTinyColorFs, kTinyVs);
            program.exec.precision = precision;
            if (backend == Backend::Jit) warm_up(program);
            Frame f = draw_tiny(program, g, tiny, gl, {96, 64});
            const bool flushed = precision != Precision::Reference;
            INFO("backend " << int(backend) << ", precision " << int(precision));
            size_t covered = 0, kept = 0, zeros = 0;
            std::span<const float> colors = f.fb.color_data<float>();
            for (size_t pixel = 0; pixel < colors.size() / 4; ++pixel) {
                const float* c = &colors[pixel * 4];
                if (c[2] == 0.25f) continue;  // the clear colour
                ++covered;
                kept += c[0] == 3e-39f && c[1] == -3e-39f;
                zeros += std::signbit(c[0]) == false && c[0] == 0.0f && c[1] == 0.0f;
            }
            CHECK(covered > 500u);
            CHECK(kept == (flushed ? 0u : covered));
            CHECK(zeros == (flushed ? covered : 0u));
        }
    }
}
