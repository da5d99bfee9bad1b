// Every scalar, vector and matrix type of GLSL 1.10, and 1.20's non-square
// matrices: declared, computed with per lane, and read back.
#include "harness.h"

using namespace lang;

TEST_CASE("float scalars", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
void main() {
    float x = a.x;
    float y = b.y;
    float z;
    z = x * y + 1.5;
    o = vec4(x + y, x - y, z, x / y);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        float x = in_a(l).x, y = in_b(l).y;
        return glm::vec4(x + y, x - y, x * y + 1.5f, x / y);
    }, kTight);
}

TEST_CASE("int scalars", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o;
void main() {
    int i = int(c.x);
    int j = int(c.y);
    int k = int(c.z);
    int q = (i + 4) / (k + 1);   // both operands positive
    o = vec4(float(i + j), float(i * j - 3), float(q), float(-i));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        int i = int(in_c(l).x), j = int(in_c(l).y), k = int(in_c(l).z);
        return glm::vec4(float(i + j), float(i * j - 3), float((i + 4) / (k + 1)), float(-i));
    }, kExact);
}

TEST_CASE("bool scalars", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
void main() {
    bool p = a.x > 0.0;
    bool q = c.z > 1.0;
    bool r = p == q;
    o = vec4(float(p), float(q), float(r), float(p != q));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        bool p = in_a(l).x > 0.0f, q = in_c(l).z > 1.0f;
        return glm::vec4(b2f(p), b2f(q), b2f(p == q), b2f(p != q));
    }, kExact);
}

TEST_CASE("vec2 vec3 vec4", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec2 o2;
varying vec3 o3;
varying vec4 o4;
void main() {
    vec2 u = a.xy;
    vec3 v = b.xyz;
    vec4 w = a;
    o2 = u * b.zw + vec2(1.0, -1.0);
    o3 = v - a.zyx;
    o4 = w / b;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o2", 2, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(glm::vec2(a.x, a.y) * glm::vec2(b.z, b.w) + glm::vec2(1, -1), 0, 0);
    }, kTight);
    check_output(outs, "o3", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(b.x - a.z, b.y - a.y, b.z - a.x, 0);
    }, kTight);
    check_output(outs, "o4", 4, [](uint32_t l) { return in_a(l) / in_b(l); }, kTight);
}

TEST_CASE("ivec2 ivec3 ivec4", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o2, o3, o4;
void main() {
    ivec2 u = ivec2(c.xy);
    ivec3 v = ivec3(c.xyz);
    ivec4 w = ivec4(c);
    u = u * 3 + ivec2(1, 2);
    v = v - ivec3(c.zyx) * 2;
    w = -w + w * w;
    o2 = vec4(vec2(u), 0.0, 0.0);
    o3 = vec4(vec3(v), 0.0);
    o4 = vec4(w);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o2", 2, [](uint32_t l) {
        glm::ivec4 c(in_c(l));
        return glm::vec4(c.x * 3 + 1, c.y * 3 + 2, 0, 0);
    }, kExact);
    check_output(outs, "o3", 3, [](uint32_t l) {
        glm::ivec4 c(in_c(l));
        return glm::vec4(c.x - 2 * c.z, c.y - 2 * c.y, c.z - 2 * c.x, 0);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::ivec4 c(in_c(l));
        return glm::vec4(-c + c * c);
    }, kExact);
}

TEST_CASE("bvec2 bvec3 bvec4", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o2, o3, o4;
void main() {
    bvec2 u = bvec2(a.x > 0.0, a.y > 0.0);
    bvec3 v = bvec3(c.x > 0.0, c.y < 0.0, c.z == 2.0);
    bvec4 w = bvec4(u, v.yz);
    w.x = !w.x;
    o2 = vec4(vec2(u), 0.0, 0.0);
    o3 = vec4(vec3(v), 0.0);
    o4 = vec4(w);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o2", 2, [](uint32_t l) {
        return glm::vec4(b2f(in_a(l).x > 0), b2f(in_a(l).y > 0), 0, 0);
    }, kExact);
    check_output(outs, "o3", 3, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(b2f(c.x > 0), b2f(c.y < 0), b2f(c.z == 2), 0);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        return glm::vec4(b2f(!(a.x > 0)), b2f(a.y > 0), b2f(c.y < 0), b2f(c.z == 2));
    }, kExact);
}

TEST_CASE("mat2 mat3 mat4 times vectors", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o2, o3, o4;
void main() {
    mat2 m2 = mat2(a.xy, b.xy);
    mat3 m3 = mat3(a.xyz, b.xyz, c.xyz);
    mat4 m4 = mat4(a, b, c, a.wzyx);
    o2 = vec4(m2 * c.xy, c.zw * m2);
    o3 = vec4(m3 * a.wzy, 0.0);
    o4 = m4 * b;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat2 m{glm::vec2(a), glm::vec2(b)};
        glm::vec2 r1 = m * glm::vec2(c.x, c.y), r2 = glm::vec2(c.z, c.w) * m;
        return glm::vec4(r1, r2);
    }, kTight);
    check_output(outs, "o3", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat3 m{glm::vec3(a), glm::vec3(b), glm::vec3(c)};
        return glm::vec4(m * glm::vec3(a.w, a.z, a.y), 0);
    }, kTight);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat4 m(a, b, c, glm::vec4(a.w, a.z, a.y, a.x));
        return m * b;
    }, kTight);
}

TEST_CASE("matrix columns and elements read and written", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o, p;
void main() {
    mat3 m = mat3(0.0);
    m[0] = a.xyz;
    m[1].y = b.x;
    m[2][2] = b.y;
    m[1][0] = m[0][2] + 1.0;
    o = vec4(m[0], m[1][0]);
    p = vec4(m[1], m[2][2]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.x, a.y, a.z, a.z + 1.0f);
    }, kTight);
    check_output(outs, "p", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.z + 1.0f, b.x, 0.0f, b.y);
    }, kTight);
}

TEST_CASE("1.20 non-square matrices", "[types][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, b, c;
varying vec4 o23, o32, o24, o42, o34, o43;
void main() {
    mat2x3 m23 = mat2x3(a.xyz, b.xyz);           // 2 columns, 3 rows
    mat3x2 m32 = mat3x2(a.xy, b.xy, c.xy);
    mat2x4 m24 = mat2x4(a, b);
    mat4x2 m42 = mat4x2(a.xy, a.zw, b.xy, b.zw);
    mat3x4 m34 = mat3x4(a, b, c);
    mat4x3 m43 = mat4x3(a.xyz, b.xyz, c.xyz, a.wzy);
    o23 = vec4(m23 * c.xy, 0.0);
    o32 = vec4(m32 * c.xyz, c.xy * m32);          // vec2 * mat3x2 is a vec3: take .xy
    o24 = m24 * b.zw;
    o42 = vec4(m42 * c, 0.0, 0.0);
    o34 = m34 * a.xyz;
    o43 = vec4(m43 * c, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o23", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat2x3 m{glm::vec3(a), glm::vec3(b)};
        return glm::vec4(m * glm::vec2(c), 0);
    }, kTight);
    check_output(outs, "o32", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat3x2 m{glm::vec2(a), glm::vec2(b), glm::vec2(c)};
        glm::vec2 r = m * glm::vec3(c);
        glm::vec3 s = glm::vec2(c) * m;
        return glm::vec4(r, s.x, s.y);
    }, kTight);
    check_output(outs, "o24", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::mat2x4(a, b) * glm::vec2(b.z, b.w);
    }, kTight);
    check_output(outs, "o42", 2, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat4x2 m{glm::vec2(a.x, a.y), glm::vec2(a.z, a.w), glm::vec2(b.x, b.y), glm::vec2(b.z, b.w)};
        return glm::vec4(m * c, 0, 0);
    }, kTight);
    check_output(outs, "o34", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::mat3x4(a, b, c) * glm::vec3(a);
    }, kTight);
    check_output(outs, "o43", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat4x3 m{glm::vec3(a), glm::vec3(b), glm::vec3(c), glm::vec3(a.w, a.z, a.y)};
        return glm::vec4(m * c, 0);
    }, kTight);
}

TEST_CASE("1.20 implicit int to float conversion", "[types][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, c;
varying vec4 o;
void main() {
    int i = int(c.x);
    float f = i;             // implicit conversion
    vec3 v = ivec3(c.xyz);   // ivec3 -> vec3
    o = vec4(f + a.x, v.yz * 2, a.y > 0 ? 1 : 2);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        return glm::vec4(c.x + a.x, c.y * 2, c.z * 2, a.y > 0 ? 1.0f : 2.0f);
    }, kTight);
}

TEST_CASE("global variables with initializers and const", "[types]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
const float K = 2.5;
const vec3 KV = vec3(1.0, 2.0, 3.0);
float g = 4.0;
vec3 gv = KV * K;
void bump() { g += 1.0; }
void main() {
    bump();
    o = vec4(g * a.x, gv + a.yzw);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(5.0f * a.x, 2.5f + a.y, 5.0f + a.z, 7.5f + a.w);
    }, kTight);
}
