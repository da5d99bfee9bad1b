// ExecOptions::precision: Reference evaluates the IR in double (results only
// rounded to float at the outputs), Fast uses the approximations of
// ir/fast_math.h. Each test runs a real shader over many lanes with different
// inputs and checks every lane against a value computed here in C++ (double
// and libm's double functions for Reference, float for Precise).
#include "harness.h"

#include <cmath>
#include <span>

using namespace lang;
using glslrun::Precision;

namespace {

Outputs run_vs_in(glslrun::Program& program, Precision precision,
                  const std::vector<glslrun::VertexAttrib>& attribs, uint32_t count) {
    program.exec.precision = precision;
    return run_vs(program, attribs, count);
}

void set_floats(glslrun::Program& p, const char* name, std::vector<float> values) {
    auto status = p.set_uniform(name, std::span<const float>(values));
    INFO("set_uniform " << name << ": " << (status ? "" : status.error().str()));
    REQUIRE(status.ok());
}

// x = 1e8 + 8 * lane (exact in float), so x + 1 rounds back to x in float.
std::vector<glslrun::VertexAttrib> big_attribs(uint32_t count) {
    return {make_attrib("a", 4, count,
                        [](uint32_t l, uint32_t c) { return c == 0 ? 1e8f + 8.0f * float(l) : in_a(l)[c]; }),
            make_attrib("b", 4, count, [](uint32_t l, uint32_t c) { return in_b(l)[c]; }),
            make_attrib("c", 4, count, [](uint32_t l, uint32_t c) { return in_c(l)[c]; })};
}

}  // namespace

TEST_CASE("Reference keeps double precision where float loses it", "[precision]") {
    glslrun::Program p = compile_vs(R"(
        attribute vec4 a;
        attribute vec4 b;
        varying float cancel, thirds, sum;
        void main() {
            cancel = (a.x + 1.0) - a.x;           // 1 in double, 0 in float
            thirds = b.x / 3.0 * 3.0 - b.x;       // 0 in double (rounded), ~1 ULP in float
            sum = (a.x * b.y + 0.3) - a.x * b.y;  // the product is exact in double, not in float
            gl_Position = vec4(0.0);
        })");
    const auto attribs = big_attribs(kVerts);
    Outputs ref = run_vs_in(p, Precision::Reference, attribs, kVerts);
    Outputs pre = run_vs_in(p, Precision::Precise, attribs, kVerts);
    auto x = [](uint32_t l) { return double(1e8f + 8.0f * float(l)); };
    check_output(ref, "cancel", 1, [](uint32_t) { return glm::vec4(1.0f); });
    check_output(pre, "cancel", 1, [](uint32_t) { return glm::vec4(0.0f); });
    check_output(ref, "thirds", 1, [](uint32_t l) {
        double bx = in_b(l).x;
        return glm::vec4(float(bx / double(3.0f) * double(3.0f) - bx));
    });
    check_output(pre, "thirds", 1, [](uint32_t l) {
        float bx = in_b(l).x;
        return glm::vec4(bx / 3.0f * 3.0f - bx);
    });
    check_output(ref, "sum", 1, [&](uint32_t l) {
        double prod = x(l) * double(in_b(l).y);
        return glm::vec4(float((prod + double(0.3f)) - prod));
    });
    // In float, 0.3 is lost against the product (spacing 8 or more): 0.
    check_output(pre, "sum", 1, [](uint32_t) { return glm::vec4(0.0f); });
}

TEST_CASE("Reference accumulates in double across a long loop", "[precision]") {
    // 2^20 additions per lane of a lane-dependent step: float's sum drifts
    // far off, double's stays within its rounding of float(step) * n.
    glslrun::Program p = compile_vs(R"(
        attribute vec4 b;
        uniform int n;
        varying float total;
        void main() {
            float s = 0.0;
            float step = b.w;
            for (int i = 0; i < n; ++i) s += step;
            total = s;
            gl_Position = vec4(0.0);
        })");
    const int n = 1 << 20;
    REQUIRE(p.set_uniform("n", std::span<const int32_t>(&n, 1)).ok());
    const uint32_t count = 20;  // a full batch and a partial one
    const auto attribs = std_attribs(count);
    Outputs ref = run_vs_in(p, Precision::Reference, attribs, count);
    Outputs pre = run_vs_in(p, Precision::Precise, attribs, count);
    check_output(ref, "total", 1, [&](uint32_t l) {
        double s = 0.0, step = in_b(l).w;
        for (int i = 0; i < n; ++i) s += step;
        return glm::vec4(float(s));
    });
    check_output(pre, "total", 1, [&](uint32_t l) {
        float s = 0.0f, step = in_b(l).w;
        for (int i = 0; i < n; ++i) s += step;
        return glm::vec4(s);
    });
    for (uint32_t l = 0; l < count; ++l) {
        INFO("lane " << l);
        CHECK(std::fabs(pre.at("total", l) - ref.at("total", l)) > 1e-5f * ref.at("total", l));  // ~100 float ULPs
    }
}

TEST_CASE("Reference built-ins are libm's double functions", "[precision]") {
    glslrun::Program p = compile_vs(R"(
        attribute vec4 a;
        attribute vec4 b;
        varying vec4 r0, r1, r2;
        void main() {
            r0 = vec4(exp(a.x), exp2(a.y), log(b.x), log2(b.y));
            r1 = vec4(sin(a.x * 3.0), cos(a.z), pow(b.x, a.y), inversesqrt(b.z));
            r2 = vec4(sqrt(b.w), atan(a.x, b.y), tan(a.w), asin(b.w - 0.5));
            gl_Position = vec4(0.0);
        })");
    Outputs out = run_vs_in(p, Precision::Reference, std_attribs(kVerts), kVerts);
    auto A = [](uint32_t l) { return glm::dvec4(in_a(l)); };
    auto B = [](uint32_t l) { return glm::dvec4(in_b(l)); };
    check_output(out, "r0", 4, [&](uint32_t l) {
        return glm::vec4(std::exp(A(l).x), std::exp2(A(l).y), std::log(B(l).x), std::log2(B(l).y));
    });
    check_output(out, "r1", 4, [&](uint32_t l) {
        return glm::vec4(std::sin(A(l).x * 3.0), std::cos(A(l).z), std::pow(B(l).x, A(l).y),
                         1.0 / std::sqrt(B(l).z));
    });
    check_output(out, "r2", 4, [&](uint32_t l) {
        return glm::vec4(std::sqrt(B(l).w), std::atan2(A(l).x, B(l).y), std::tan(A(l).w),
                         std::asin(B(l).w - 0.5));
    });
}

TEST_CASE("Reference integers stay 32-bit: wrapping, division by zero", "[precision]") {
    glslrun::Program p = compile_vs(R"(
        attribute vec4 c;
        varying vec4 r;
        void main() {
            int i = int(c.x) * 536870912 + int(c.y);  // c.x * 2^29: i * 8 wraps
            int big = 2147483647 + int(c.z);           // wraps past INT_MAX for c.z > 0
            r = vec4(float(i * 8), float(big), float(int(c.y) / (int(c.z) - int(c.z))), float(big / -1));
            gl_Position = vec4(0.0);
        })");
    auto wrap = [](int64_t v) { return int32_t(uint32_t(uint64_t(v))); };
    auto want = [&](uint32_t l) {
        glm::vec4 c = in_c(l);
        int32_t i = wrap(int64_t(int32_t(c.x)) * 536870912 + int32_t(c.y));
        int32_t big = wrap(2147483647ll + int32_t(c.z));
        return glm::vec4(float(wrap(int64_t(i) * 8)), float(big), 0.0f, float(wrap(-int64_t(big))));
    };
    for (Precision mode : {Precision::Reference, Precision::Precise, Precision::Fast}) {
        INFO("precision " << glslrun::precision_name(mode));
        check_output(run_vs_in(p, mode, std_attribs(kVerts), kVerts), "r", 4, want, kExact);
    }
}

TEST_CASE("Reference: the prologue and uniform arrays keep double precision", "[precision]") {
    // big = u[0] * 1e8 depends on uniforms only: ir/hoist.cpp moves it to the
    // per-draw prologue, whose results must stay double. u[k] by a per-lane
    // index is uniform_ind.
    glslrun::Program p = compile_vs(R"(
        attribute vec4 b;
        attribute vec4 c;
        uniform float u[4];
        varying float hoisted, indexed;
        void main() {
            float big = u[0] * 1e8;
            hoisted = ((big + 1.0) - big) * b.x;
            float v = u[int(c.z)] * 1e8;
            indexed = (v + 1.0) - v;
            gl_Position = vec4(0.0);
        })");
    set_floats(p, "u", {1.0f, 3.0f, 5.0f, 7.0f});
    Outputs ref = run_vs_in(p, Precision::Reference, std_attribs(kVerts), kVerts);
    check_output(ref, "hoisted", 1, [](uint32_t l) { return glm::vec4(in_b(l).x); });
    check_output(ref, "indexed", 1, [](uint32_t) { return glm::vec4(1.0f); });
    Outputs pre = run_vs_in(p, Precision::Precise, std_attribs(kVerts), kVerts);
    check_output(pre, "hoisted", 1, [](uint32_t) { return glm::vec4(0.0f); });
    check_output(pre, "indexed", 1, [](uint32_t) { return glm::vec4(0.0f); });
}

TEST_CASE("Reference: control flow, discard and derivatives per lane", "[precision]") {
    const auto inputs = std::vector{make_attrib("v", 4, kFrags, [](uint32_t l, uint32_t c) {
        glm::vec2 xy = frag_xy(l);
        return c == 0 ? 1e8f + 8.0f * xy.x : c == 1 ? xy.y : c == 2 ? in_a(l).x : 0.0f;
    })};
    glslrun::Program p = compile_fs(R"(
        varying vec4 v;
        void main() {
            float dx = dFdx(v.x * 3.0 + 1.0);  // 24 in double; float rounds 3e8 + 1 to 32s
            float dy = dFdy(v.y * v.y);
            if (v.z < -2.0) discard;
            float acc = 0.0;
            for (int i = 0; i < 4; ++i) {
                if (float(i) > v.y) break;
                acc += (v.x + 1.0) - v.x;
            }
            gl_FragColor = vec4(acc, dx, dy, 1.0);
        })",
                                    inputs);
    p.exec.precision = Precision::Reference;
    Outputs out = run_fs(p, inputs);
    int discarded = 0;
    for (uint32_t l = 0; l < kFrags; ++l) {
        INFO("lane " << l);
        const bool discards = in_a(l).x < -2.0f;
        discarded += discards;
        CHECK(out.at("discarded", l) == (discards ? 1.0f : 0.0f));
        if (discards) continue;  // its outputs are never written
        glm::vec2 xy = frag_xy(l);
        float acc = float(std::min(4, int(xy.y) + 1));  // (x + 1) - x is 1 in double
        float top = float(uint32_t(xy.y) & ~1u), dy = (top + 1.0f) * (top + 1.0f) - top * top;
        CHECK(out.vec("gl_FragColor", l) == glm::vec4(acc, 24.0f, dy, 1.0f));
    }
    CHECK(discarded > 0);
    CHECK(discarded < int(kFrags));
}

TEST_CASE("Fast is within the fast functions' tolerance of Precise on every lane", "[precision]") {
    const uint32_t count = 301;
    auto attribs = std::vector{make_attrib("a", 4, count, [](uint32_t l, uint32_t c) {
        const float t = float(l) / float(count);
        return c == 0 ? -6.0f + 12.0f * t : c == 1 ? 0.01f + 40.0f * t * t : c == 2 ? std::sin(float(l)) * 3.0f
                                                                                : 0.2f + 3.0f * t;
    })};
    glslrun::Program p = compile_vs(R"(
        attribute vec4 a;
        varying vec4 r0, r1, r2;
        void main() {
            r0 = vec4(inversesqrt(a.w), inversesqrt(a.y), exp(a.x), exp2(a.x));
            r1 = vec4(log(a.y), log2(a.y), pow(a.w, a.z), sin(a.x * 10.0));
            r2 = vec4(cos(a.x * 10.0), exp2(-a.y), log2(a.w), a.z / a.y);
            gl_Position = vec4(0.0);
        })");
    Outputs pre = run_vs_in(p, Precision::Precise, attribs, count);
    Outputs fast = run_vs_in(p, Precision::Fast, attribs, count);
    int differing = 0;
    for (const char* name : {"r0", "r1", "r2"}) {
        // ir/fast_math.h: 2^-21 relative for rcp, rsqrt, exp2 and log2; exp,
        // log and pow add their argument's rounding (|y log2 x| <= ~12 here:
        // 12 * 2^-21); sin and cos 2^-22 absolute. 1e-5 covers them all.
        check_output(fast, name, 4, [&](uint32_t l) { return pre.vec(name, l); }, 1e-5f);
        for (uint32_t l = 0; l < count; ++l) differing += fast.vec(name, l) != pre.vec(name, l);
    }
    CHECK(differing > int(count));  // the approximations do run
    // Division is the CPU's exact one in Fast too (runtime/fast_kernels.h).
    for (uint32_t l = 0; l < count; ++l) CHECK(fast.at("r2", l, 3) == pre.at("r2", l, 3));
}

// normalize and x / sqrt(y) (ir/sqrt_divisor.cpp): Precise keeps the square
// root and the divisions, bit for bit; Fast multiplies by its rsqrt.
TEST_CASE("Fast computes normalize with rsqrt; Precise keeps its bits", "[precision]") {
    const uint32_t count = 301;
    auto value = [](uint32_t l, uint32_t c) {
        return std::sin(float(l * 4 + c) * 0.7f) * (c == 3 ? 50.0f : 3.0f) + (c == 3 ? 60.0f : 0.0f);
    };
    auto attribs = std::vector{make_attrib("a", 4, count, value)};
    glslrun::Program p = compile_vs(R"(
        attribute vec4 a;
        varying vec4 r0;
        void main() {
            r0 = vec4(normalize(a.xyz), a.x / sqrt(a.w));
            gl_Position = vec4(0.0);
        })");
    Outputs pre = run_vs_in(p, Precision::Precise, attribs, count);
    Outputs fast = run_vs_in(p, Precision::Fast, attribs, count);
    int differing = 0;
    for (uint32_t l = 0; l < count; ++l) {
        const float x = value(l, 0), y = value(l, 1), z = value(l, 2);
        const float len = std::sqrt(x * x + y * y + z * z);
        INFO("lane " << l);
        CHECK(pre.vec("r0", l) == glm::vec4(x / len, y / len, z / len, x / std::sqrt(value(l, 3))));
        for (int c = 0; c < 4; ++c) differing += fast.at("r0", l, c) != pre.at("r0", l, c);
    }
    // rsqrt's 2^-23 relative and a multiply's rounding.
    check_output(fast, "r0", 4, [&](uint32_t l) { return pre.vec("r0", l); }, 1e-6f);
    CHECK(differing > int(count) / 4);
}
