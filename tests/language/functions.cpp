// User functions: in/out/inout parameters with copy-in/copy-out semantics,
// aliasing, l-value arguments, return values, early returns, overloads.
#include "harness.h"

#include <cmath>

using namespace lang;

TEST_CASE("in parameters are copies", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
float scale(float x, vec3 v) {
    x *= 2.0;          // changes the copy only
    v.y = 0.0;
    return x + v.x + v.y + v.z;
}
void main() {
    float x = a.x;
    vec3 v = a.yzw;
    float r = scale(x, v);
    o = vec4(r, x, v.yz);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.x * 2.0f + a.y + a.w, a.x, a.z, a.w);
    }, kTight);
}

TEST_CASE("out and inout parameters", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
void split(vec2 v, out float lo, out float hi) {
    lo = min(v.x, v.y);
    hi = max(v.x, v.y);
}
void accumulate(inout float acc, float x) { acc = acc * 2.0 + x; }
void main() {
    float lo, hi;
    split(a.xy, lo, hi);
    float acc = b.x;
    accumulate(acc, a.z);
    accumulate(acc, 1.0);
    o = vec4(lo, hi, acc, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        float acc = (in_b(l).x * 2.0f + a.z) * 2.0f + 1.0f;
        return glm::vec4(std::min(a.x, a.y), std::max(a.x, a.y), acc, 0.0f);
    }, kTight);
}

TEST_CASE("out parameter is a copy, not a reference to the argument", "[functions]") {
    // While the callee runs, the global passed as the out argument keeps its
    // own value; the copy-out at return overwrites the callee's direct write.
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
float g;
void writer(out float r) { r = 3.0; o.y = g; g = 7.0; }
void main() {
    g = a.x;
    o = vec4(0.0);
    writer(g);      // g = 7.0 inside, then copy-out sets g = 3.0
    o.x = g;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 2, [](uint32_t l) { return glm::vec4(3.0f, in_a(l).x, 0, 0); }, kExact);
}

TEST_CASE("inout of a global: copy-out overwrites the callee's direct write", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
float g;
void f(inout float p) {
    p += 1.0;
    g = 100.0;        // the parameter is a copy: this does not change p
    o.y = p;
}
void main() {
    g = a.x;
    f(g);
    o.x = g;          // copy-out happened after the callee's write
    o.zw = vec2(0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 2, [](uint32_t l) {
        return glm::vec4(in_a(l).x + 1.0f, in_a(l).x + 1.0f, 0, 0);
    }, kTight);
}

TEST_CASE("aliasing: same variable as in and inout argument", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
void g(inout float p, float q) {
    p = p * 3.0;
    p = p + q;        // q is the value at call time, not the updated p
}
void main() {
    float x = a.x;
    g(x, x);
    o = vec4(x, 0.0, 0.0, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 1, [](uint32_t l) {
        float x = in_a(l).x;
        return glm::vec4(x * 3.0f + x);
    }, kTight);
}

TEST_CASE("aliasing: f(x, x) with two out parameters copies out left to right", "[functions]") {
    // GLSL leaves the copy-out order unspecified; glslrun copies out left to
    // right like Mesa, so the last parameter wins.
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
void two(out float p, out float q) { q = a.y; p = a.x; }
void main() {
    float x = 0.0;
    two(x, x);
    vec2 v = vec2(0.0);
    two(v.y, v.x);
    o = vec4(x, v, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.y, a.y, a.x, 0.0f);
    }, kExact);
}

TEST_CASE("out argument l-value (index) is evaluated at call time", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o;
int gi;
void bump_and_set(out float r) { gi = gi + 1; r = 5.0; }
void main() {
    float arr[5];
    for (int k = 0; k < 5; ++k) arr[k] = 0.0;
    gi = int(c.z);
    bump_and_set(arr[gi]);   // writes arr[old gi]
    o = vec4(arr[0], arr[1], arr[2], arr[3]) + vec4(float(gi) * 10.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        int i = int(in_c(l).z);
        glm::vec4 r(0.0f);
        r[i] = 5.0f;
        return r + glm::vec4(float(i + 1) * 10.0f);
    }, kExact);
}

TEST_CASE("indexed and struct-member l-values as out arguments", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
struct S { vec3 v; float f; };
void put(out vec3 r, vec3 x) { r = x * 2.0; }
void inc(inout float f) { f += 1.0; }
void main() {
    vec3 arr[3];
    for (int k = 0; k < 3; ++k) arr[k] = vec3(float(k));
    int i = int(c.z);
    if (i == 3) i = 2;
    put(arr[i], a.xyz);
    S s = S(vec3(0.0), a.w);
    put(s.v, a.zyx);
    inc(s.f);
    mat2 m = mat2(1.0);
    inc(m[1][0]);
    o1 = vec4(arr[0].x, arr[1].y, arr[2].z, s.f);
    o2 = vec4(s.v, m[1][0]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        int i = int(in_c(l).z);
        if (i == 3) i = 2;
        glm::vec4 r(0.0f, 1.0f, 2.0f, a.w + 1.0f);
        r[i] = 2.0f * a[i];
        return r;
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.z * 2, a.y * 2, a.x * 2, 1.0f);
    }, kTight);
}

TEST_CASE("early return under divergence", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
float classify(float x) {
    if (x < -1.0) return -10.0;
    if (x < 0.0) return -1.0;
    if (x == 0.0) return 0.0;
    float y = x * 2.0;
    if (y > 3.0) return 3.0;
    return y;
}
void count_up(inout float n, float limit) {
    if (limit < 0.0) return;
    n += limit;
}
void main() {
    float n = 1.0;
    count_up(n, c.x);
    o = vec4(classify(a.x), classify(a.y), classify(c.y), n);
    gl_Position = vec4(0.0);
})");
    auto classify = [](float x) {
        if (x < -1.0f) return -10.0f;
        if (x < 0.0f) return -1.0f;
        if (x == 0.0f) return 0.0f;
        float y = x * 2.0f;
        return y > 3.0f ? 3.0f : y;
    };
    check_output(outs, "o", 4, [&](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        return glm::vec4(classify(a.x), classify(a.y), classify(c.y), c.x < 0 ? 1.0f : 1.0f + c.x);
    }, kExact);
}

TEST_CASE("overloads, nested calls and prototypes", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
float twice(float x);                  // prototype before the definition
float f(float x) { return x + 1.0; }
float f(vec2 v) { return v.x * v.y; }
float f(int i) { return float(i) * 100.0; }
vec3 f(vec3 v, float s) { return v * s; }
void main() {
    o = vec4(f(a.x), f(a.yz), f(int(c.x)), twice(f(f(a.zw)))) + vec4(f(a.xyz, 2.0).z);
    gl_Position = vec4(0.0);
}
float twice(float x) { return 2.0 * x; })");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        float extra = a.z * 2.0f;
        return glm::vec4(a.x + 1.0f, a.y * a.z, c.x * 100.0f, 2.0f * (a.z * a.w + 1.0f)) +
               glm::vec4(extra);
    }, kTight);
}

TEST_CASE("function called from divergent branches keeps each lane's arguments", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
float g_calls;
vec2 poly(float x, float k) { g_calls += 1.0; return vec2(x * x * k, x + k); }
void main() {
    g_calls = 0.0;
    vec2 r;
    if (a.x > 0.0) r = poly(a.y, 2.0);
    else r = poly(b.y, -1.0);
    if (a.z > 0.0) r += poly(r.x, 0.5);
    o = vec4(r, g_calls, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        auto poly = [](float x, float k) { return glm::vec2(x * x * k, x + k); };
        glm::vec2 r = a.x > 0 ? poly(a.y, 2.0f) : poly(b.y, -1.0f);
        float calls = 1.0f;
        if (a.z > 0) { r += poly(r.x, 0.5f); calls += 1.0f; }
        return glm::vec4(r, calls, 0.0f);
    }, kTight);
}

TEST_CASE("const in parameters and functions in another unit of the stage", "[functions]") {
    const char* lib = "float scaled(const in float x, const float k) { return x * k; }\n";
    const char* main_vs = R"(
attribute vec4 a;
varying vec4 o;
float scaled(const in float x, const float k);
void main() {
    o = vec4(scaled(a.x, 3.0), scaled(a.y, a.z), 0.0, 0.0);
    gl_Position = vec4(0.0);
})";
    auto result = glslrun::Program::compile({{"lib.vert", lib}, {"main.vert", main_vs}},
                                            {{"f.frag", "void main() { gl_FragColor = vec4(1.0); }\n"}});
    if (!result) FAIL(result.error().str());
    auto outs = run_vs(*result, std_attribs());
    check_output(outs, "o", 2, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.x * 3.0f, a.y * a.z, 0, 0);
    }, kTight);
}

TEST_CASE("the same function nested in its own arguments", "[functions]") {
    // Functions have static frames: an inner call must finish with its frame
    // before the outer call copies its arguments in.
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
float add2(float x, float y) { float t = x + 2.0 * y; return t; }
void swap_into(inout vec2 v, out float first) { first = v.x; v = v.yx; }
void main() {
    float r = add2(add2(a.x, a.y), add2(a.z, add2(a.w, 1.0)));
    float s = add2(a.x, 1.0) * add2(a.y, -1.0);
    vec2 v = a.xy;
    float f1, f2;
    swap_into(v, f1);
    swap_into(v, f2);
    o = vec4(r, s, f1 - f2, v.x);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        auto add2 = [](float x, float y) { return x + 2.0f * y; };
        float r = add2(add2(a.x, a.y), add2(a.z, add2(a.w, 1.0f)));
        float s = add2(a.x, 1.0f) * add2(a.y, -1.0f);
        return glm::vec4(r, s, a.x - a.y, a.x);
    }, 1e-5f);
}

TEST_CASE("out parameters written in a loop with a lane-dependent trip count", "[functions]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
void step_it(inout float acc, out int parity, float x) {
    acc = acc * 0.5 + x;
    parity = int(acc > 1.0);
}
void main() {
    float acc = 0.0;
    int ones = 0;
    int n = int(c.x) + 4;            // 1..7
    for (int i = 0; i < n; ++i) {
        int p;
        step_it(acc, p, a.y + float(i));
        ones += p;
    }
    o = vec4(acc, float(ones), 0.0, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 2, [](uint32_t l) {
        float acc = 0.0f, y = in_a(l).y;
        int ones = 0, n = int(in_c(l).x) + 4;
        for (int i = 0; i < n; ++i) {
            acc = acc * 0.5f + y + float(i);
            ones += acc > 1.0f;
        }
        return glm::vec4(acc, float(ones), 0, 0);
    }, 1e-5f);
}
