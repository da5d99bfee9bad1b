// Half-float colour buffers (GL_RGBA16F render targets): fused::fusable()
// declines them, so the JIT's draws take the C++ per-fragment path, with the
// interpreter's bits; the buffer holds halves only, and differs from a
// float buffer's.
#include "tests/fused/harness.h"

#include "runtime/half_float.h"

using namespace fused_test;

namespace {

Frame render_half(Program& p, const Geometry& g, const GLState& gl, bool half) {
    Frame f{Framebuffer(93, 61, true), {}};
    f.fb.half_float = half;
    f.fb.clear_color({0.1f, 2.7f, 0.3f, 1.0f});
    for (int pass = 0; pass < 2; ++pass) {
        auto stats = draw(p, gl, f.fb, Primitive::Triangles, {g.pos, g.color}, g.count);
        if (!stats) FAIL(stats.error().str());
        f.stats += *stats;
    }
    return f;
}

bool holds_halves(const Framebuffer& fb) {
    for (float v : fb.color_data<float>())
        if (std::bit_cast<uint32_t>(v) != std::bit_cast<uint32_t>(rt::round_to_half(v))) return false;
    return true;
}

}  // namespace

TEST_CASE("half-float storage draws on the C++ path with the interpreter's bits", "[fused][half]") {
    Geometry small = random_geometry(31, 900, 0.08f);
    Programs p(kShaders[0].fs);  // colours out of [0, 1]
    for (bool blend : {false, true}) {
        GLState gl;
        gl.depth_test = true;
        gl.depth_func = GLState::DepthFunc::Lequal;
        gl.blend = blend;
        gl.blend_state.src_rgb = gl.blend_state.dst_rgb = BlendFactor::One;
        gl.blend_state.dst_alpha = BlendFactor::ConstantColor;
        gl.blend_state.color = {0.3f, 1.7f, -0.2f, 1.3f};  // unclamped with float storage
        INFO("blend " << blend);
        Frame oracle = render_half(p.oracle, small, gl, true);
        Frame jit = render_half(p.fused, small, gl, true);
        Frame floats = render_half(p.oracle, small, gl, false);
        CHECK(oracle.stats.fragments_shaded > 200u);
        CHECK(jit.stats.fragments_shaded == oracle.stats.fragments_shaded);
        CHECK(jit.stats.fragments_fused == 0u);  // declined by fusable()
        CHECK(same_colors(jit.fb, oracle.fb));
        CHECK(holds_halves(oracle.fb));
        CHECK_FALSE(holds_halves(floats.fb));
        CHECK_FALSE(same_colors(floats.fb, oracle.fb));
    }
}
