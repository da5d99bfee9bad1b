// Structs and arrays: nesting, constant and dynamic indexing (reads and
// writes), dynamic indices into vectors and matrices, whole-struct
// assignment and comparison.
#include "harness.h"

#include <algorithm>
#include <array>
#include <tuple>

using namespace lang;

namespace {
int wrap3(float cz) { int i = int(cz); return i == 3 ? 0 : i; }
}  // namespace

TEST_CASE("nested structs and arrays of structs", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2;
struct Light { vec3 pos; float power; };
struct Scene { Light lights[3]; int count; vec2 extra; };
void main() {
    Scene s;
    for (int k = 0; k < 3; ++k) {
        s.lights[k].pos = a.xyz * float(k + 1);
        s.lights[k].power = b.x + float(k);
    }
    s.count = int(c.z);
    s.extra = b.zw;
    s.lights[1].pos.y = -1.0;        // constant indices all the way down
    int i = int(c.z);
    if (i == 3) i = 0;
    o1 = vec4(s.lights[i].pos, s.lights[2 - i].power);
    o2 = vec4(s.lights[1].pos.y, float(s.count), s.extra);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        int i = wrap3(in_c(l).z);
        glm::vec3 pos = glm::vec3(a) * float(i + 1);
        if (i == 1) pos.y = -1.0f;
        return glm::vec4(pos, in_b(l).x + float(2 - i));
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        return glm::vec4(-1.0f, in_c(l).z, b.z, b.w);
    }, kExact);
}

TEST_CASE("arrays: writes and reads through dynamic indices", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2;
void main() {
    float arr[5];
    for (int k = 0; k < 5; k++) arr[k] = float(k) * 10.0;
    int i = int(c.z);            // 0..3
    int j = int(c.x) + 3;        // 0..6 -> clamp to 0..4 below
    if (j > 4) j = 4;
    arr[i] = a.x;                // dynamic write
    arr[j] += 1.0;               // dynamic read-modify-write
    arr[i + 1] = arr[j] * 2.0;   // index expressions
    o1 = vec4(arr[0], arr[1], arr[2], arr[3]);
    o2 = vec4(arr[4], arr[i], arr[j], float(i + j));
    gl_Position = vec4(0.0);
})");
    auto simulate = [](uint32_t l) {
        std::array<float, 5> arr{0, 10, 20, 30, 40};
        int i = int(in_c(l).z), j = std::min(int(in_c(l).x) + 3, 4);
        arr[i] = in_a(l).x;
        arr[j] += 1.0f;
        arr[i + 1] = arr[j] * 2.0f;
        return std::tuple{arr, i, j};
    };
    check_output(outs, "o1", 4, [&](uint32_t l) {
        auto [arr, i, j] = simulate(l);
        return glm::vec4(arr[0], arr[1], arr[2], arr[3]);
    }, kTight);
    check_output(outs, "o2", 4, [&](uint32_t l) {
        auto [arr, i, j] = simulate(l);
        return glm::vec4(arr[4], arr[i], arr[j], float(i + j));
    }, kTight);
}

TEST_CASE("dynamic index into vectors, read and write", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2;
void main() {
    int i = int(c.z);
    vec4 v = a;
    float picked = b[i];
    v[i] = 100.0 + picked;
    ivec3 iv = ivec3(7, 8, 9);
    iv[i == 3 ? 2 : i] = -1;
    o1 = v;
    o2 = vec4(vec3(iv), picked);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 v = in_a(l);
        int i = int(in_c(l).z);
        v[i] = 100.0f + in_b(l)[i];
        return v;
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        int i = int(in_c(l).z);
        glm::vec3 iv(7, 8, 9);
        iv[i == 3 ? 2 : i] = -1.0f;
        return glm::vec4(iv, in_b(l)[i]);
    }, kExact);
}

TEST_CASE("dynamic index into matrix columns and elements", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2, o3;
void main() {
    mat4 m = mat4(a, b, c, a * b);
    int i = int(c.z);
    int j = 3 - i;
    vec4 col = m[i];
    float e = m[j][i];
    m[j] = vec4(-1.0, -2.0, -3.0, -4.0);   // dynamic column write
    m[i][j] = 50.0;                         // dynamic element write
    o1 = col;
    o2 = vec4(e, m[0][0], m[1][1], m[2][2]);
    o3 = m[3];
    gl_Position = vec4(0.0);
})");
    auto matrix = [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::mat4(a, b, c, a * b);
    };
    check_output(outs, "o1", 4, [&](uint32_t l) { return matrix(l)[int(in_c(l).z)]; }, kExact);
    auto modified = [&](uint32_t l) {
        glm::mat4 m = matrix(l);
        int i = int(in_c(l).z), j = 3 - i;
        m[j] = glm::vec4(-1, -2, -3, -4);
        m[i][j] = 50.0f;
        return m;
    };
    check_output(outs, "o2", 4, [&](uint32_t l) {
        int i = int(in_c(l).z);
        glm::mat4 m = modified(l);
        return glm::vec4(matrix(l)[3 - i][i], m[0][0], m[1][1], m[2][2]);
    }, kTight);
    check_output(outs, "o3", 4, [&](uint32_t l) { return modified(l)[3]; }, kTight);
}

TEST_CASE("array of structs containing arrays, dynamic at both levels", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o;
struct Item { float w[4]; vec2 p; };
void main() {
    Item items[3];
    for (int k = 0; k < 3; ++k) {
        for (int m = 0; m < 4; ++m) items[k].w[m] = float(k * 4 + m);
        items[k].p = vec2(float(k));
    }
    int i = int(c.z);
    if (i == 3) i = 0;
    int j = 3 - int(c.z);
    items[i].w[j] = a.y;
    items[2 - i].p.y = b.x;
    o = vec4(items[i].w[j], items[i].w[0], items[1].w[j], items[2 - i].p.y + items[i].p.x);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        float w[3][4];
        glm::vec2 p[3];
        for (int k = 0; k < 3; ++k) {
            for (int m = 0; m < 4; ++m) w[k][m] = float(k * 4 + m);
            p[k] = glm::vec2(float(k));
        }
        int i = wrap3(in_c(l).z), j = 3 - int(in_c(l).z);
        w[i][j] = in_a(l).y;
        p[2 - i].y = in_b(l).x;
        return glm::vec4(w[i][j], w[i][0], w[1][j], p[2 - i].y + p[i].x);
    }, kTight);
}

TEST_CASE("whole-struct assignment, == and !=", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
struct S { vec2 v; int n; mat2 m; };   // 1.10: no whole-struct ops with array members
void main() {
    S s;
    s.v = a.xy;
    s.n = int(c.x);
    s.m = mat2(a.z, a.w, a.x, a.y);
    S t = s;                  // copy
    t.n += 1;                 // does not touch s
    S u;
    u = s;
    if (c.y > 0.0) u.m[1][1] = 0.5;   // differs only deep in a member, on some lanes
    o = vec4(float(s == t), float(s == u), float(s != u), float(t.n - s.n));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        bool differs = in_c(l).y > 0.0f && in_a(l).y != 0.5f;
        return glm::vec4(0.0f, b2f(!differs), b2f(differs), 1.0f);
    }, kExact);
}

TEST_CASE("struct returned from and passed to functions", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
struct P { vec3 pos; float w; };
P make(vec4 v) { return P(v.xyz, v.w); }
float sum(P p) { p.w += 1.0; return p.pos.x + p.pos.y + p.pos.z + p.w; }
void main() {
    P p = make(a);
    float s = sum(p);        // the callee's change to its copy is not visible
    o = vec4(s, p.w, make(b).pos.yz);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x + a.y + a.z + (a.w + 1.0f), a.w, b.y, b.z);
    }, 1e-5f);
}

TEST_CASE("1.20 whole-array assignment and ==", "[aggregates][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, c;
varying vec4 o;
void main() {
    float x[3] = float[3](a.x, a.y, a.z);
    float y[3];
    y = x;
    y[1] += 0.0;
    float z[3] = x;
    if (c.x > 0.0) z[2] = 99.0;
    o = vec4(float(x == y), float(x == z), float(x != z), y[2]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        bool differs = in_c(l).x > 0.0f;
        return glm::vec4(1.0f, b2f(!differs), b2f(differs), in_a(l).z);
    }, kExact);
}

// GLSL 1.10 forbids whole arrays as l-values, so out arrays need 1.20.
TEST_CASE("1.20 arrays as in and out parameters", "[aggregates][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, c;
varying vec4 o;
void fill(out float dst[3], float base) {
    for (int k = 0; k < 3; ++k) dst[k] = base + float(k);
}
float pick(float src[3], int i) { src[0] = -5.0; return src[i]; }
void main() {
    float arr[3];
    fill(arr, a.x);
    int i = int(c.z);
    if (i == 3) i = 1;
    float p = pick(arr, i);
    o = vec4(arr[0], arr[1], arr[2], p);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        float x = in_a(l).x;
        int i = int(in_c(l).z);
        if (i == 3) i = 1;
        float arr[3] = {x, x + 1, x + 2};
        return glm::vec4(arr[0], arr[1], arr[2], i == 0 ? -5.0f : arr[i]);
    }, kTight);
}

// glslrun's documented choice (ir/opcodes.def, load_ind/store_ind): a
// dynamic index out of range is clamped to the nearest element, for reads
// and writes; it never touches another variable.
TEST_CASE("out-of-range dynamic indices clamp and touch nothing else", "[aggregates]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o1, o2;
void main() {
    float before = 1.0;
    float arr[3];
    float after = 2.0;
    arr[0] = 10.0; arr[1] = 20.0; arr[2] = 30.0;
    int i = int(c.y) * 3;          // -12 .. 12: mostly out of range
    float got = arr[i];
    arr[i] = -1.0;
    vec4 v = vec4(5.0, 6.0, 7.0, 8.0);
    float vg = v[i];
    o1 = vec4(got, vg, before, after);
    o2 = vec4(arr[0], arr[1], arr[2], 0.0);
    gl_Position = vec4(0.0);
})");
    auto clamped = [](uint32_t l, int n) { return std::clamp(int(in_c(l).y) * 3, 0, n - 1); };
    check_output(outs, "o1", 4, [&](uint32_t l) {
        return glm::vec4(10.0f * float(clamped(l, 3) + 1), 5.0f + float(clamped(l, 4)), 1.0f, 2.0f);
    }, kExact);
    check_output(outs, "o2", 4, [&](uint32_t l) {
        glm::vec4 r(10, 20, 30, 0);
        r[clamped(l, 3)] = -1.0f;
        return r;
    }, kExact);
}
