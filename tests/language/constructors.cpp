// Every constructor form of GLSL 1.10 (§5.4), plus 1.20's matrix-from-matrix
// and array constructors.
#include "harness.h"

#include <cmath>

using namespace lang;

TEST_CASE("vector constructors: broadcast, mixed components, truncation", "[constructors]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2, o3, o4;
void main() {
    o1 = vec4(a.x);                       // broadcast
    o2 = vec4(a.xy, b.z, 1.5);            // mixed components
    vec3 t = vec3(b);                     // truncating a vec4
    vec2 u = vec2(a.zwxy);
    o3 = vec4(t, u.y);
    o4 = vec4(vec2(a.w, b.w), vec3(b.x, a.z, 9.0));   // the last argument is partly used
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) { return glm::vec4(in_a(l).x); }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(in_a(l).x, in_a(l).y, in_b(l).z, 1.5f);
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        return glm::vec4(b.x, b.y, b.z, in_a(l).w);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.w, b.w, b.x, a.z);
    }, kExact);
}

TEST_CASE("scalar conversions: int(float) truncates, bool(float), float(bool), int(bool)",
          "[constructors]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
void main() {
    int i = int(a.x * 1.7);          // truncation toward zero, negative values included
    bool z = bool(c.x);              // 0.0 -> false, anything else -> true
    float f = float(a.y > 0.0);
    int j = int(c.y < 0.0);
    bool k = bool(int(c.w));
    o1 = vec4(float(i), float(z), f, float(j));
    o2 = vec4(float(k), float(int(-2.7)), float(int(a.z)), float(bool(0.0)));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        return glm::vec4(std::trunc(a.x * 1.7f), b2f(c.x != 0), b2f(a.y > 0), b2f(c.y < 0));
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(b2f(in_c(l).w != 0), -2.0f, std::trunc(in_a(l).z), 0.0f);
    }, kExact);
}

TEST_CASE("vector conversions: ivec(vec), vec(ivec), bvec(vec), vec(bvec)", "[constructors]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2, o3;
void main() {
    ivec4 iv = ivec4(a * 1.3);
    bvec3 bv = bvec3(c.xyz);
    ivec2 ib = ivec2(bvec2(c.x, c.z));
    o1 = vec4(iv);
    o2 = vec4(vec3(bv), float(ib.x + ib.y * 2));
    o3 = vec4(bvec4(a.x > 0.0, false, true, c.w));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) { return glm::trunc(in_a(l) * 1.3f); }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(b2f(c.x != 0), b2f(c.y != 0), b2f(c.z != 0),
                         b2f(c.x != 0) + 2.0f * b2f(c.z != 0));
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        return glm::vec4(b2f(in_a(l).x > 0), 0.0f, 1.0f, b2f(in_c(l).w != 0));
    }, kExact);
}

TEST_CASE("matrix constructors: diagonal, columns, components", "[constructors]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2, o3, o4;
void main() {
    mat3 d = mat3(a.x);                       // diagonal
    mat2 cols = mat2(a.xy, b.zw);             // from columns
    mat2 comps = mat2(a.x, a.y, b.x, b.y);    // from components, column-major
    mat4 mix4 = mat4(a, b.xyz, c.x, c.yzw, a.x, vec2(1.0), b.xy);
    o1 = vec4(d[0], d[1][1]) + vec4(0.0, 0.0, d[2][2], 0.0);
    o2 = vec4(cols[0], cols[1]);
    o3 = vec4(comps[0], comps[1]);
    o4 = mix4[2] + mix4[3] * 10.0 + vec4(mix4[1][3]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        float x = in_a(l).x;
        return glm::vec4(x, 0.0f, x, x);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, a.y, b.z, b.w);
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, a.y, b.x, b.y);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::vec4 col1(b.x, b.y, b.z, c.x), col2(c.y, c.z, c.w, a.x), col3(1.0f, 1.0f, b.x, b.y);
        return col2 + col3 * 10.0f + glm::vec4(col1.w);
    }, kTight);
}

TEST_CASE("1.20 matrix from matrix: bigger, smaller, identity fill", "[constructors][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, b, c;
varying vec4 o1, o2, o3, o4, o5;
void main() {
    mat4 big = mat4(a, b, c, a + b);
    mat2 small = mat2(big);                   // upper-left 2x2
    mat3 m3 = mat3(a.xyz, b.xyz, c.xyz);
    mat4 grown = mat4(m3);                    // identity fill
    mat3x2 ns = mat3x2(mat2(a.xy, b.xy));     // missing column from the identity: (0,0)
    o1 = vec4(small[0], small[1]);
    o2 = grown[0] + grown[3] * 2.0;
    o3 = grown[2];
    o4 = vec4(ns[1], ns[2]);
    o5 = vec4(mat2(a.xy, b.xy));              // vector from matrix, column-major
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, a.y, b.x, b.y);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.x, a.y, a.z, 0.0f) + glm::vec4(0, 0, 0, 2.0f);
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(c.x, c.y, c.z, 0.0f);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        return glm::vec4(b.x, b.y, 0.0f, 0.0f);
    }, kExact);
    check_output(outs, "o5", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, a.y, b.x, b.y);
    }, kExact);
}

TEST_CASE("struct constructors", "[constructors]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2;
struct Inner { float f; ivec2 i; };
struct Outer { vec3 v; Inner in1; bool flag; mat2 m; };
void main() {
    Inner inner = Inner(a.x, ivec2(c.xy));
    Outer s = Outer(b.xyz, inner, a.y > 0.0, mat2(a.zw, b.zw));
    Outer t = Outer(vec3(1.0), Inner(2.0, ivec2(3, 4)), false, mat2(5.0));
    o1 = vec4(s.v, s.in1.f + float(s.in1.i.x * 10 + s.in1.i.y));
    o2 = vec4(float(s.flag), s.m[1].x, t.in1.f + float(t.in1.i.y), t.m[1][1] + t.v.z);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::vec4(b.x, b.y, b.z, a.x + (c.x * 10 + c.y));
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(b2f(in_a(l).y > 0), in_b(l).z, 6.0f, 6.0f);
    }, kExact);
}

TEST_CASE("1.20 array constructors and length()", "[constructors][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, b, c;
varying vec4 o1, o2;
void main() {
    float f[3] = float[3](a.x, b.y, 2.5);
    vec2 v[4] = vec2[](a.xy, b.xy, c.xy, a.zw);  // size taken from the constructor
    int i = int(c.z);
    o1 = vec4(f[0], f[1], f[2], float(v.length()));
    o2 = vec4(v[i], v[3 - i]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        return glm::vec4(in_a(l).x, in_b(l).y, 2.5f, 4.0f);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::vec2 v[4] = {{a.x, a.y}, {b.x, b.y}, {c.x, c.y}, {a.z, a.w}};
        int i = int(c.z);
        return glm::vec4(v[i], v[3 - i]);
    }, kExact);
}
