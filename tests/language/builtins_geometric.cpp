// GLSL 1.10 §8.4-8.6, 8.10: geometric, matrix and vector relational
// functions, ftransform and noise; 1.20's outerProduct and transpose.
#include "harness.h"

#include <cmath>
#include <functional>

using namespace lang;

namespace {
template <int N>
glm::vec<N, float> head(glm::vec4 v) { return glm::vec<N, float>(v); }
}  // namespace

TEST_CASE("length, distance, dot on float and vec2-4", "[builtins][geometric]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 len, dist, dt;
void main() {
    len = vec4(length(a.x), length(a.xy), length(a.xyz), length(a));
    dist = vec4(distance(a.x, b.x), distance(a.xy, b.xy), distance(a.xyz, b.xyz), distance(a, b));
    dt = vec4(dot(a.x, b.x), dot(a.xy, b.xy), dot(a.xyz, b.xyz), dot(a, b));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "len", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(std::fabs(a.x), glm::length(head<2>(a)), glm::length(head<3>(a)), glm::length(a));
    }, kLoose);
    check_output(outs, "dist", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(std::fabs(a.x - b.x), glm::distance(head<2>(a), head<2>(b)),
                         glm::distance(head<3>(a), head<3>(b)), glm::distance(a, b));
    }, kLoose);
    check_output(outs, "dt", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x * b.x, glm::dot(head<2>(a), head<2>(b)), glm::dot(head<3>(a), head<3>(b)),
                         glm::dot(a, b));
    }, kLoose);
}

TEST_CASE("cross and normalize", "[builtins][geometric]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 cr, n2, n3, n4;
void main() {
    cr = vec4(cross(a.xyz, b.xyz), normalize(a.x));
    n2 = vec4(normalize(a.xy), normalize(b.x), 0.0);
    n3 = vec4(normalize(a.xyz), 0.0);
    n4 = normalize(a);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "cr", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(glm::cross(head<3>(a), head<3>(in_b(l))), a.x > 0 ? 1.0f : -1.0f);
    }, kLoose);
    check_output(outs, "n2", 3, [](uint32_t l) {
        return glm::vec4(glm::normalize(head<2>(in_a(l))), 1.0f, 0.0f);
    }, kLoose);
    check_output(outs, "n3", 3, [](uint32_t l) {
        return glm::vec4(glm::normalize(head<3>(in_a(l))), 0.0f);
    }, kLoose);
    check_output(outs, "n4", 4, [](uint32_t l) { return glm::normalize(in_a(l)); }, kLoose);
}

TEST_CASE("faceforward and reflect on float and vec2-4", "[builtins][geometric]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 ff, rf;
varying vec3 ff3, rf3;
void main() {
    ff = faceforward(b, a, a.wzyx);
    ff3 = faceforward(b.xyz, a.xyz, a.wzy);
    rf = vec4(reflect(a.x, b.x), reflect(a.xy, normalize(b.xy)), 0.0);
    rf3 = reflect(a.xyz, normalize(b.zyx));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "ff", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::faceforward(b, a, glm::vec4(a.w, a.z, a.y, a.x));
    }, kTight);
    check_output(outs, "ff3", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(glm::faceforward(head<3>(b), head<3>(a), glm::vec3(a.w, a.z, a.y)), 0);
    }, kTight);
    check_output(outs, "rf", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        float r1 = a.x - 2.0f * b.x * a.x * b.x;
        return glm::vec4(r1, glm::reflect(head<2>(a), glm::normalize(head<2>(b))), 0);
    }, kLoose);
    check_output(outs, "rf3", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(glm::reflect(head<3>(a), glm::normalize(glm::vec3(b.z, b.y, b.x))), 0);
    }, kLoose);
}

TEST_CASE("refract, including total internal reflection", "[builtins][geometric]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 r3;
varying vec2 r2;
varying float r1;
void main() {
    float eta = b.w * 3.0;          // 0.3 .. 2.8: some lanes reflect totally
    vec3 i = normalize(a.xyz);
    vec3 n = normalize(b.xyz);
    r3 = vec4(refract(i, n, eta), dot(n, i));
    r2 = refract(normalize(a.xy), normalize(b.yx), eta);
    r1 = refract(-1.0, 1.0, eta);
    gl_Position = vec4(0.0);
})");
    int tir = 0;
    for (uint32_t l = 0; l < kVerts; ++l) {
        glm::vec3 i = glm::normalize(head<3>(in_a(l))), n = glm::normalize(head<3>(in_b(l)));
        float eta = in_b(l).w * 3.0f, d = glm::dot(n, i);
        tir += 1.0f - eta * eta * (1.0f - d * d) < 0.0f;
    }
    REQUIRE(tir > 0);                   // the inputs exercise both outcomes
    REQUIRE(tir < int(kVerts));
    check_output(outs, "r3", 4, [](uint32_t l) {
        glm::vec3 i = glm::normalize(head<3>(in_a(l))), n = glm::normalize(head<3>(in_b(l)));
        return glm::vec4(glm::refract(i, n, in_b(l).w * 3.0f), glm::dot(n, i));
    }, 1e-4f);
    check_output(outs, "r2", 2, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        glm::vec2 r = glm::refract(glm::normalize(head<2>(a)), glm::normalize(glm::vec2(b.y, b.x)), b.w * 3.0f);
        return glm::vec4(r, 0, 0);
    }, 1e-4f);
    check_output(outs, "r1", 1, [](uint32_t l) {
        float eta = in_b(l).w * 3.0f;  // head-on: k = 1, result = eta*I - (eta*(-1) + 1)*N = -1
        (void)eta;
        return glm::vec4(-1.0f);
    }, 1e-5f);
}

TEST_CASE("matrixCompMult on mat2, mat3, mat4", "[builtins][matrix]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 m2, m3a, m3b, m4;
void main() {
    mat2 x2 = matrixCompMult(mat2(a), mat2(b));
    mat3 x3 = matrixCompMult(mat3(a.xyz, b.xyz, c.xyz), mat3(b.zyx, c.zyx, a.zyx));
    mat4 x4 = matrixCompMult(mat4(a, b, c, a), mat4(c, a, b, b));
    m2 = vec4(x2[0], x2[1]);
    m3a = vec4(x3[0], x3[1].x);
    m3b = vec4(x3[1].yz, x3[2].xz);
    m4 = x4[0] + x4[1] * 2.0 + x4[2] * 3.0 + x4[3] * 4.0;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "m2", 4, [](uint32_t l) { return in_a(l) * in_b(l); }, kTight);
    check_output(outs, "m3a", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::vec4(a.x * b.z, a.y * b.y, a.z * b.x, b.x * c.z);
    }, kTight);
    check_output(outs, "m3b", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::vec4(b.y * c.y, b.z * c.x, c.x * a.z, c.z * a.x);
    }, kTight);
    check_output(outs, "m4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return a * c + b * a * 2.0f + c * b * 3.0f + a * b * 4.0f;
    }, 1e-5f);
}

TEST_CASE("1.20 outerProduct and transpose", "[builtins][matrix][120]") {
    auto outs = eval_vs(R"(#version 120
attribute vec4 a, b, c;
varying vec4 op0, op2, t3, t23, t32;
void main() {
    mat3 o = outerProduct(a.xyz, b.xyz);        // column j = a * b[j]
    mat2x4 o24 = outerProduct(a, b.xy);
    mat3 m = mat3(a.xyz, b.xyz, c.xyz);
    mat3 t = transpose(m);
    mat2x3 n = mat2x3(a.xyz, b.xyz);
    mat3x2 tn = transpose(n);
    op0 = vec4(o[0], o[2].y);
    op2 = o24[1];
    t3 = vec4(t[0], t[2].y);
    t23 = vec4(tn[0], tn[2]);
    t32 = vec4(tn[1], 0.0, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "op0", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(head<3>(a) * b.x, a.y * b.z);
    }, kTight);
    check_output(outs, "op2", 4, [](uint32_t l) { return in_a(l) * in_b(l).y; }, kTight);
    check_output(outs, "t3", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        return glm::vec4(a.x, b.x, c.x, b.z);
    }, kExact);
    check_output(outs, "t23", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, b.x, a.z, b.z);
    }, kExact);
    check_output(outs, "t32", 2, [](uint32_t l) {
        return glm::vec4(in_a(l).y, in_b(l).y, 0, 0);
    }, kExact);
}

TEST_CASE("vector relational functions on vec, ivec and bvec", "[builtins][relational]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 lt, le, gt, ge, eq, ne, ieq, beq;
varying vec3 misc;
void main() {
    vec4 x = c, y = c.wzyx;                  // integer-valued: ties happen
    ivec3 ix = ivec3(c.xyz), iy = ivec3(c.wyx);
    bvec2 bx = bvec2(c.x > 0.0, c.y > 0.0), by = bvec2(c.w > 0.0, a.x > 0.0);
    lt = vec4(lessThan(x, y));
    le = vec4(lessThanEqual(x, y));
    gt = vec4(greaterThan(x.xy, y.xy), greaterThan(ix.yz, iy.yz));
    ge = vec4(greaterThanEqual(x.xyz, y.xyz), float(ix.x >= iy.x));
    eq = vec4(equal(x, y));
    ne = vec4(notEqual(x, y));
    ieq = vec4(vec3(equal(ix, iy)), float(notEqual(ix.xy, iy.xy).y));
    beq = vec4(equal(bx, by), notEqual(bx, by));
    misc = vec3(float(any(lessThan(x, y))), float(all(lessThanEqual(x, y))), float(not(bx).x));
    gl_Position = vec4(0.0);
})");
    auto cmp = [](uint32_t l, auto op) {
        glm::vec4 x = in_c(l), y(x.w, x.z, x.y, x.x), r;
        for (int k = 0; k < 4; ++k) r[k] = b2f(op(x[k], y[k]));
        return r;
    };
    check_output(outs, "lt", 4, [&](uint32_t l) { return cmp(l, std::less<float>()); }, kExact);
    check_output(outs, "le", 4, [&](uint32_t l) { return cmp(l, std::less_equal<float>()); }, kExact);
    check_output(outs, "eq", 4, [&](uint32_t l) { return cmp(l, std::equal_to<float>()); }, kExact);
    check_output(outs, "ne", 4, [&](uint32_t l) { return cmp(l, std::not_equal_to<float>()); }, kExact);
    check_output(outs, "gt", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(b2f(c.x > c.w), b2f(c.y > c.z), b2f(c.y > c.y), b2f(c.z > c.x));
    }, kExact);
    check_output(outs, "ge", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(b2f(c.x >= c.w), b2f(c.y >= c.z), b2f(c.z >= c.y), b2f(c.x >= c.w));
    }, kExact);
    check_output(outs, "ieq", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(b2f(c.x == c.w), 1.0f, b2f(c.z == c.x), 0.0f);
    }, kExact);
    check_output(outs, "beq", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        bool bx0 = c.x > 0, bx1 = c.y > 0, by0 = c.w > 0, by1 = in_a(l).x > 0;
        return glm::vec4(b2f(bx0 == by0), b2f(bx1 == by1), b2f(bx0 != by0), b2f(bx1 != by1));
    }, kExact);
    check_output(outs, "misc", 3, [](uint32_t l) {
        glm::vec4 x = in_c(l), y(x.w, x.z, x.y, x.x);
        bool any = false, all = true;
        for (int k = 0; k < 4; ++k) { any |= x[k] < y[k]; all &= x[k] <= y[k]; }
        return glm::vec4(b2f(any), b2f(all), b2f(!(x.x > 0)), 0);
    }, kExact);
}

TEST_CASE("ftransform and the matrix built-in uniforms", "[builtins][ftransform]") {
    auto program = compile_vs(R"(
varying vec4 ft, mvp, mv;
void main() {
    ft = ftransform();
    mvp = gl_ModelViewProjectionMatrix * gl_Vertex;
    mv = gl_ModelViewMatrix * gl_Vertex;
    gl_Position = ft;
})");
    glslrun::GLState gl;
    gl.modelview = glm::mat4(glm::vec4(0.8f, 0.1f, -0.2f, 0.0f), glm::vec4(-0.3f, 0.9f, 0.05f, 0.0f),
                             glm::vec4(0.25f, -0.1f, 0.7f, 0.0f), glm::vec4(0.5f, -1.0f, -6.0f, 1.0f));
    gl.projection = glm::mat4(glm::vec4(1.5f, 0, 0, 0), glm::vec4(0, 2.0f, 0, 0),
                              glm::vec4(0.1f, -0.2f, -1.2f, -1.0f), glm::vec4(0, 0, -2.2f, 0));
    auto status = glslrun::apply_builtin_uniforms(program, gl);
    INFO((status ? std::string() : status.error().str()));
    REQUIRE(status.ok());
    auto vertex = make_attrib("gl_Vertex", 4, kVerts, [](uint32_t l, uint32_t c) {
        return c == 3 ? 1.0f : in_a(l)[c];
    });
    auto outs = run_vs(program, {vertex});
    auto pos = [](uint32_t l) { glm::vec4 a = in_a(l); return glm::vec4(a.x, a.y, a.z, 1.0f); };
    glm::mat4 mvp = gl.projection * gl.modelview;
    check_output(outs, "ft", 4, [&](uint32_t l) { return mvp * pos(l); }, 1e-5f);
    check_output(outs, "mvp", 4, [&](uint32_t l) { return mvp * pos(l); }, 1e-5f);
    check_output(outs, "mv", 4, [&](uint32_t l) { return gl.modelview * pos(l); }, 1e-5f);
    check_output(outs, "gl_Position", 4, [&](uint32_t l) { return mvp * pos(l); }, 1e-5f);
}

TEST_CASE("noise1..noise4 return 0 (documented glslrun choice)", "[builtins][noise]") {
    // GLSL 1.10 allows any noise in [-1, 1]; glslrun returns 0, as Mesa does.
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 n1, n2, n3, n4;
void main() {
    n1 = vec4(noise1(a.x), noise1(a.xy), noise1(a.xyz), noise1(a));
    n2 = vec4(noise2(a.x), noise2(a));
    n3 = vec4(noise3(a.xy), 0.0);
    n4 = noise4(a.xyz);
    gl_Position = vec4(0.0);
})");
    for (const char* name : {"n1", "n2", "n3", "n4"})
        check_output(outs, name, 4, [](uint32_t) { return glm::vec4(0.0f); }, kExact);
}
