// Every operator of GLSL 1.10 on every operand combination it accepts.
#include "harness.h"

#include <utility>

using namespace lang;

TEST_CASE("arithmetic: vector with scalar, both orders", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2, o3, o4;
void main() {
    o1 = a * b.x + b.y;
    o2 = b.x * a - 2.0;
    o3 = 3.0 / b + a / b.z;
    o4 = 1.0 - a.zyxw;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) { return in_a(l) * in_b(l).x + in_b(l).y; }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) { return in_b(l).x * in_a(l) - 2.0f; }, kTight);
    check_output(outs, "o3", 4, [](uint32_t l) { return 3.0f / in_b(l) + in_a(l) / in_b(l).z; }, kTight);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return 1.0f - glm::vec4(a.z, a.y, a.x, a.w);
    }, kTight);
}

TEST_CASE("arithmetic: integer vectors with integer scalars", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o1, o2;
void main() {
    ivec4 v = ivec4(c);
    int k = int(c.z) + 1;               // 1..4
    ivec4 p = ivec4(c + 5.0);           // all positive: division is well defined
    o1 = vec4(v * k + 2 - v);
    o2 = vec4(p / k) + vec4(10 / ivec4(1, 2, 3, 4));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::ivec4 v(in_c(l));
        int k = v.z + 1;
        return glm::vec4(v * k + 2 - v);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::ivec4 v(in_c(l));
        glm::ivec4 p = v + 5;
        int k = v.z + 1;
        return glm::vec4(p / k) + glm::vec4(10, 5, 3, 2);
    }, kExact);
}

TEST_CASE("arithmetic: matrices (linear algebra and component-wise)", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2, o3, o4, o5, o6;
void main() {
    mat3 m = mat3(a.xyz, b.xyz, c.xyz + vec3(0.5));
    mat3 n = mat3(b.wzy, a.wzy, vec3(1.0, -2.0, 0.25));
    mat3 prod = m * n;
    vec3 mv = m * a.xyz;
    vec3 vm = a.xyz * m;
    mat3 sum = m + n - 2.0 * n;
    mat3 quo = m / b.x;
    mat3 cw = (m + 1.0) / (n * 0.5 + 3.0);   // component-wise / and scalar +
    o1 = vec4(prod[0], prod[2].y);
    o2 = vec4(prod[1], prod[2].z);
    o3 = vec4(mv, vm.x);
    o4 = vec4(vm.yz, sum[1].xz);
    o5 = vec4(quo[2], -m[0].y);
    o6 = vec4(cw[0], cw[2].z);
    gl_Position = vec4(0.0);
})");
    auto mats = [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l), c = in_c(l);
        glm::mat3 m{glm::vec3(a), glm::vec3(b), glm::vec3(c) + 0.5f};
        glm::mat3 n{glm::vec3(b.w, b.z, b.y), glm::vec3(a.w, a.z, a.y), glm::vec3(1, -2, 0.25f)};
        return std::pair{m, n};
    };
    check_output(outs, "o1", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::mat3 p = m * n;
        return glm::vec4(p[0], p[2].y);
    }, 1e-5f);
    check_output(outs, "o2", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::mat3 p = m * n;
        return glm::vec4(p[1], p[2].z);
    }, 1e-5f);
    check_output(outs, "o3", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::vec3 a(in_a(l));
        return glm::vec4(m * a, (a * m).x);
    }, 1e-5f);
    check_output(outs, "o4", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::vec3 vm = glm::vec3(in_a(l)) * m;
        glm::mat3 s = m + n - 2.0f * n;
        return glm::vec4(vm.y, vm.z, s[1].x, s[1].z);
    }, 1e-5f);
    check_output(outs, "o5", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::mat3 q = m / in_b(l).x;
        return glm::vec4(q[2], -m[0].y);
    }, 1e-5f);
    check_output(outs, "o6", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::mat3 cw;
        for (int i = 0; i < 3; ++i) cw[i] = (m[i] + 1.0f) / (n[i] * 0.5f + 3.0f);
        return glm::vec4(cw[0], cw[2].z);
    }, 1e-5f);
}

TEST_CASE("unary minus and logical not", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
void main() {
    ivec2 iv = ivec2(c.xy);
    bool p = a.x > 0.0;
    o1 = vec4(-a.xy, vec2(-iv));
    o2 = vec4(float(!p), float(!!p), -(-a.z), float(!(a.y < 0.0)));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        return glm::vec4(-in_a(l).x, -in_a(l).y, -in_c(l).x, -in_c(l).y);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(b2f(!(a.x > 0)), b2f(a.x > 0), a.z, b2f(!(a.y < 0)));
    }, kExact);
}

TEST_CASE("increment and decrement, pre and post", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2, o3;
void main() {
    float f = a.x;
    int i = int(c.x);
    float r1 = f++;        // old value
    float r2 = ++f;        // new value
    int r3 = i--;
    int r4 = --i;
    vec3 v = a.yzw;
    vec3 r5 = v++;
    ivec2 iv = ivec2(c.zw);
    ivec2 r6 = --iv;
    o1 = vec4(r1, r2, f, float(r3));
    o2 = vec4(float(r4), float(i), r5.x, v.y);
    o3 = vec4(vec2(r6), vec2(iv));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        float f = in_a(l).x;
        return glm::vec4(f, f + 2.0f, f + 2.0f, in_c(l).x);
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        float i = in_c(l).x;
        return glm::vec4(i - 2.0f, i - 2.0f, in_a(l).y, in_a(l).z + 1.0f);
    }, kTight);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(c.z - 1, c.w - 1, c.z - 1, c.w - 1);
    }, kExact);
}

TEST_CASE("assignment operators, including vec *= mat and mat *= mat", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2, o3, o4;
void main() {
    vec4 v = a;
    v += b;
    v -= vec4(0.5);
    v *= 2.0;
    v /= b;
    o1 = v;
    mat2 m = mat2(a.xy, b.xy);
    vec2 w = c.xy;
    w *= m;                  // w = w * m
    m *= mat2(b.zw, a.zw);   // m = m * other
    o2 = vec4(w, m[0]);
    o3 = vec4(m[1], 0.0, 0.0);
    ivec3 iv = ivec3(c.xyz);
    iv += 4;                 // all non-negative from here
    iv *= ivec3(2, 3, 4);
    iv /= 2;
    iv -= ivec3(1);
    o4 = vec4(vec3(iv), 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        return ((in_a(l) + in_b(l) - 0.5f) * 2.0f) / in_b(l);
    }, kTight);
    auto mats = [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        glm::mat2 m{glm::vec2(a), glm::vec2(b)};
        glm::mat2 n{glm::vec2(b.z, b.w), glm::vec2(a.z, a.w)};
        return std::pair{m, n};
    };
    check_output(outs, "o2", 4, [&](uint32_t l) {
        auto [m, n] = mats(l);
        glm::vec2 w = glm::vec2(in_c(l)) * m;
        return glm::vec4(w, (m * n)[0]);
    }, 1e-5f);
    check_output(outs, "o3", 2, [&](uint32_t l) {
        auto [m, n] = mats(l);
        return glm::vec4((m * n)[1], 0, 0);
    }, 1e-5f);
    check_output(outs, "o4", 3, [](uint32_t l) {
        glm::ivec3 iv(in_c(l));
        iv = (iv + 4) * glm::ivec3(2, 3, 4) / 2 - 1;
        return glm::vec4(glm::vec3(iv), 0);
    }, kExact);
}

TEST_CASE("relational operators on floats and ints", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
void main() {
    float x = a.x, y = a.z;
    int i = int(c.x), j = int(c.y);
    o1 = vec4(float(x < y), float(x <= y), float(x > y), float(x >= y));
    o2 = vec4(float(i < j), float(i <= j), float(i > j), float(i >= j));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        float x = in_a(l).x, y = in_a(l).z;
        return glm::vec4(b2f(x < y), b2f(x <= y), b2f(x > y), b2f(x >= y));
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        float i = in_c(l).x, j = in_c(l).y;
        return glm::vec4(b2f(i < j), b2f(i <= j), b2f(i > j), b2f(i >= j));
    }, kExact);
}

TEST_CASE("equality on scalars, vectors and matrices", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
void main() {
    int i = int(c.x), j = int(c.w);
    vec3 u = vec3(c.xyz);
    vec3 w = vec3(c.wyz);                 // equal to u where c.x == c.w
    bvec2 p = bvec2(c.x > 0.0, c.y > 0.0), q = bvec2(c.w > 0.0, c.y > 0.0);
    mat2 m = mat2(c.x), n = mat2(c.w);
    o1 = vec4(float(i == j), float(i != j), float(u == w), float(u != w));
    o2 = vec4(float(p == q), float(m == n), float(m != n), float(a.x == a.x));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        bool eq = in_c(l).x == in_c(l).w;
        return glm::vec4(b2f(eq), b2f(!eq), b2f(eq), b2f(!eq));
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        bool eq = c.x == c.w;
        return glm::vec4(b2f((c.x > 0) == (c.w > 0)), b2f(eq), b2f(!eq), 1.0f);
    }, kExact);
}

TEST_CASE("logical operators && || ^^ short-circuit", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o1, o2;
float calls;
bool counted(bool v) { calls += 1.0; return v; }
void main() {
    int n = 0;
    bool p = a.x > 0.0;
    bool q = a.y > 0.0;
    bool r1 = p && (++n > 0);          // increments only where p
    bool r2 = q || (n++ > 100);        // increments only where !q
    calls = 0.0;
    bool r3 = counted(p) ^^ counted(q);   // ^^ evaluates both sides
    bool r4 = (c.x > 0.0 && c.y > 0.0) || (c.z == 1.0 && !p);
    o1 = vec4(float(r1), float(r2), float(r3), float(r4));
    o2 = vec4(float(n), calls, 0.0, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        bool p = a.x > 0, q = a.y > 0;
        return glm::vec4(b2f(p), b2f(q), b2f(p != q), b2f((c.x > 0 && c.y > 0) || (c.z == 1 && !p)));
    }, kExact);
    check_output(outs, "o2", 2, [](uint32_t l) {
        bool p = in_a(l).x > 0, q = in_a(l).y > 0;
        return glm::vec4(float(int(p) + int(!q)), 2.0f, 0, 0);
    }, kExact);
}

TEST_CASE("conditional operator evaluates only the taken branch", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2;
void main() {
    float t = 0.0, f = 0.0;
    float r = a.x > 0.0 ? (t += 1.0) * b.x : (f += 2.0) + b.y;
    vec2 v = a.y > a.z ? a.yz : b.zw;
    float nested = a.x > 0.0 ? (a.y > 0.0 ? 1.0 : 2.0) : (a.z > 0.0 ? 3.0 : 4.0);
    o1 = vec4(r, t, f, nested);
    o2 = vec4(v, 0.0, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        bool p = a.x > 0;
        float nested = p ? (a.y > 0 ? 1.0f : 2.0f) : (a.z > 0 ? 3.0f : 4.0f);
        return glm::vec4(p ? b.x : 2.0f + b.y, b2f(p), p ? 0.0f : 2.0f, nested);
    }, kTight);
    check_output(outs, "o2", 2, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return a.y > a.z ? glm::vec4(a.y, a.z, 0, 0) : glm::vec4(b.z, b.w, 0, 0);
    }, kExact);
}

TEST_CASE("comma operator and chained assignment", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
void main() {
    float x = 0.0, y = 0.0, z;
    z = (x = a.x, y = x * 2.0, y + 1.0);   // value of the last operand
    float p, q;
    p = q = a.y;
    int i, j;
    for (i = 0, j = 10; i < 3; i++, j--) {}
    o = vec4(z, y, p + q, float(i * 100 + j));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(a.x * 2.0f + 1.0f, a.x * 2.0f, 2.0f * a.y, 307.0f);
    }, kTight);
}

TEST_CASE("unary operators and increments on matrices", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2;
void main() {
    mat2 m = mat2(a.xy, b.xy);
    mat2 n = -m;
    mat2 old = m++;
    --m;
    --m;
    o1 = vec4(n[0], n[1]);
    o2 = vec4(old[1], m[0]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        return -glm::vec4(in_a(l).x, in_a(l).y, in_b(l).x, in_b(l).y);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(in_b(l).x, in_b(l).y, in_a(l).x - 1.0f, in_a(l).y - 1.0f);
    }, kTight);
}

TEST_CASE("conditional operator on structs, arrays elements and matrices", "[operators]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
struct P { vec2 p; float w; };
void main() {
    P s1 = P(a.xy, 1.0), s2 = P(b.xy, 2.0);
    P r = a.z > 0.0 ? s1 : s2;
    mat2 m = a.w > 0.0 ? mat2(a.xy, b.xy) : mat2(2.0);
    o = vec4(r.p, r.w, m[1][0]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        bool p = a.z > 0;
        return glm::vec4(p ? a.x : b.x, p ? a.y : b.y, p ? 1.0f : 2.0f, a.w > 0 ? b.x : 0.0f);
    }, kExact);
}
