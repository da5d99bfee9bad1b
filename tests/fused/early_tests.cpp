// The stencil and depth tests before the shader (FragmentStage's early
// tests: no discard, gl_FragDepth or alpha test) against the same tests
// after it, on the interpreter's C++ path and the fused pipeline: the same
// bits, fewer fragments shaded; a draw whose colours no buffer takes runs
// the tests and no shader.
#include "harness.h"

using namespace glslrun;
using namespace fused_test;

namespace {

// The same colours; the second has a discard that never happens (colour
// varyings are clamped to [0, 1]), which makes its tests late.
const char* kEarly = "void main() { gl_FragColor = gl_Color * 1.6 - 0.3; }";
const char* kLate = "void main() { if (gl_Color.a < -1.0) discard; gl_FragColor = gl_Color * 1.6 - 0.3; }";

void check_same_bits(const Frame& a, const Frame& b) {
    CHECK(a.stats.fragments_written == b.stats.fragments_written);
    CHECK(same_colors(a.fb, b.fb));
    CHECK(same_bits(std::span<const float>(a.fb.depth), std::span<const float>(b.fb.depth)));
    CHECK(a.fb.stencil == b.fb.stencil);
}

}  // namespace

TEST_CASE("the early stencil and depth tests draw the late tests' bits and shade less", "[fused]") {
    Geometry g = random_geometry(25, 900, 0.08f);
    Programs early(kEarly), late(kLate);
    uint64_t early_shaded = 0, late_shaded = 0;
    for (int state = 0; state < 16; ++state) {
        INFO("stencil state " << state);
        const std::vector<GLState> passes = stencil_passes(state);
        for (bool fused : {false, true}) {
            INFO((fused ? "fused pipeline" : "interpreter"));
            const Frame a = render_passes(fused ? early.fused : early.oracle, g, passes);
            const Frame b = render_passes(fused ? late.fused : late.oracle, g, passes);
            check_same_bits(a, b);
            CHECK(a.stats.fragments_shaded <= b.stats.fragments_shaded);
            if (fused && jit_available()) CHECK(a.stats.fragments_fused == a.stats.fragments_shaded);
            early_shaded += a.stats.fragments_shaded;
            late_shaded += b.stats.fragments_shaded;
        }
    }
    // The stencil rejected fragments before the shader.
    CHECK(early_shaded < late_shaded * 9 / 10);
    CHECK(early_shaded > 0u);
}

TEST_CASE("a draw whose colours no buffer takes runs its stencil and depth tests, no shader", "[fused]") {
    Geometry g = random_geometry(31, 900, 0.08f);
    Programs early(kEarly), late(kLate);
    for (int state = 0; state < 16; state += 3) {
        INFO("stencil state " << state);
        std::vector<GLState> passes = stencil_passes(state);
        // Both passes mask every channel, the second only where state is odd
        // (and then no colour output of a depth-only pass either).
        passes[0].color_mask = {false, false, false, false};
        if (state % 2) passes[1].color_mask = {false, false, false, false};
        for (bool fused : {false, true}) {
            INFO((fused ? "fused pipeline" : "interpreter"));
            const Frame a = render_passes(fused ? early.fused : early.oracle, g, passes);
            const Frame b = render_passes(fused ? late.fused : late.oracle, g, passes);
            check_same_bits(a, b);
            const Frame masked = render_passes(fused ? early.fused : early.oracle, g, {passes[0]});
            CHECK(masked.stats.fragments_shaded == 0u);
            CHECK(masked.stats.fragments_written > 200u);
        }
    }
    // A depth-only pre-pass, then the colours where the depth is equal.
    GLState depth_only;
    depth_only.depth_test = true;
    depth_only.color_mask = {false, false, false, false};
    GLState equal = depth_only;
    equal.depth_func = GLState::DepthFunc::Lequal;
    equal.color_mask = {true, true, true, true};
    for (bool fused : {false, true}) {
        const Frame a = render_passes(fused ? early.fused : early.oracle, g, {depth_only, equal});
        const Frame b = render_passes(fused ? late.fused : late.oracle, g, {depth_only, equal});
        check_same_bits(a, b);
        CHECK(a.stats.fragments_shaded < b.stats.fragments_shaded);
    }
}
