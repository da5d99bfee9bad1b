// Swizzles read and written: every name set, repeats, swizzle of swizzle,
// swizzled l-values (assignment, op-assign, out arguments).
#include "harness.h"

#include <array>
#include <tuple>

using namespace lang;

namespace {
glm::vec4 wzyx(glm::vec4 v) { return {v.w, v.z, v.y, v.x}; }
}  // namespace

TEST_CASE("swizzle reads with xyzw rgba stpq", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2, o3, o4;
void main() {
    o1 = a.wzyx;
    o2 = vec4(a.rg, b.ba);
    o3 = vec4(b.stp, a.q);
    o4 = a.xxyy + b.yyy.xxxx;   // repeats and swizzle of swizzle
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) { return wzyx(in_a(l)); }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(in_a(l).x, in_a(l).y, in_b(l).z, in_b(l).w);
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        return glm::vec4(in_b(l).x, in_b(l).y, in_b(l).z, in_a(l).w);
    }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        float by = in_b(l).y;
        return glm::vec4(a.x + by, a.x + by, a.y + by, a.y + by);
    }, kTight);
}

TEST_CASE("swizzle of swizzle chains", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
varying float f;
void main() {
    o = a.zwxy.yxwz.wzyx;   // zwxy -> wzyx(of zwxy)= ... computed in C++
    f = a.wzyx.yx.y;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        glm::vec4 s1(a.z, a.w, a.x, a.y);
        glm::vec4 s2(s1.y, s1.x, s1.w, s1.z);
        return wzyx(s2);
    }, kExact);
    check_output(outs, "f", 1, [](uint32_t l) { return glm::vec4(in_a(l).w); }, kExact);
}

TEST_CASE("swizzle writes", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2, o3;
void main() {
    vec4 v = a;
    v.zx = b.xy;          // v.z = b.x, v.x = b.y
    o1 = v;
    vec4 w = vec4(0.0);
    w.wzyx = a;           // reversal
    o2 = w;
    vec4 u = b;
    u.gr = u.rg;          // swap through a swizzle
    u.q = 7.0;
    u.xy += vec2(1.0, 2.0);
    u.ba *= 2.0;
    o3 = u;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(b.y, a.y, b.x, a.w);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) { return wzyx(in_a(l)); }, kExact);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        return glm::vec4(b.y + 1.0f, b.x + 2.0f, b.z * 2.0f, 14.0f);
    }, kTight);
}

TEST_CASE("swizzle writes of vectors inside arrays and matrices", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2;
void main() {
    vec3 arr[2];
    arr[0] = vec3(0.0);
    arr[1] = a.xyz;
    arr[1].zy = b.xy;
    int i = int(c.z) / 2;   // 0 or 1
    arr[i].x = 9.0;         // dynamic index then component
    mat2 m = mat2(1.0);
    m[1].yx = a.zw;
    o1 = vec4(arr[0], arr[1].x);
    o2 = vec4(arr[1].yz, m[1]);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        int i = int(in_c(l).z) / 2;
        return glm::vec4(i == 0 ? 9.0f : 0.0f, 0.0f, 0.0f, i == 1 ? 9.0f : a.x);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(b.y, b.x, a.w, a.z);
    }, kExact);
}

TEST_CASE("swizzle as out and inout argument", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o1, o2;
void set2(out vec2 r, float x, float y) { r = vec2(x, y); }
void twice(inout vec3 r) { r = r * 2.0 + vec3(0.0, 0.5, 1.0); }
void main() {
    vec4 v = a;
    set2(v.wy, b.x, b.z);   // v.w = b.x, v.y = b.z
    o1 = v;
    vec4 w = b;
    twice(w.zxy);            // w.z, w.x, w.y in that order
    o2 = w;
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x, b.z, a.z, b.x);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        // r = (b.z, b.x, b.y) * 2 + (0, .5, 1) written back to z, x, y
        return glm::vec4(b.x * 2.0f + 0.5f, b.y * 2.0f + 1.0f, b.z * 2.0f, b.w);
    }, kTight);
}

TEST_CASE("swizzle of scalar-producing expressions and constructors", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b;
varying vec4 o;
void main() {
    o = vec4((a + b).yx, vec3(a.x, b.x, 3.0).zz);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 s = in_a(l) + in_b(l);
        return glm::vec4(s.y, s.x, 3.0f, 3.0f);
    }, kTight);
}

TEST_CASE("compound l-values: dynamic index, member, swizzle, op-assign, increment", "[swizzle]") {
    auto outs = eval_vs(R"(
attribute vec4 a, b, c;
varying vec4 o1, o2, o3;
struct S { vec3 v; float arr[3]; };
void main() {
    S s[2];
    for (int k = 0; k < 2; ++k) {
        s[k].v = vec3(float(k));
        s[k].arr[0] = 0.0; s[k].arr[1] = 1.0; s[k].arr[2] = 2.0;
    }
    int i = int(c.z) / 2;          // 0 or 1
    int j = int(c.z) == 3 ? 2 : int(c.z);
    s[i].v.zx = a.xy;              // dynamic element, then swizzle write
    s[1 - i].v.y += b.x;           // op-assign through dynamic index and component
    s[i].arr[j]++;                 // increment through two dynamic indices
    mat3 m = mat3(1.0);
    m[j].yx += vec2(b.z, b.w);     // dynamic column, swizzle, op-assign
    o1 = vec4(s[0].v, s[0].arr[j]);
    o2 = vec4(s[1].v, s[1].arr[j]);
    o3 = vec4(m[0].xy, m[2].xy);
    gl_Position = vec4(0.0);
})");
    struct S { glm::vec3 v; float arr[3]; };
    auto simulate = [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        std::array<S, 2> s{S{glm::vec3(0.0f), {0, 1, 2}}, S{glm::vec3(1.0f), {0, 1, 2}}};
        int cz = int(in_c(l).z), i = cz / 2, j = cz == 3 ? 2 : cz;
        s[i].v.z = a.x;
        s[i].v.x = a.y;
        s[1 - i].v.y += b.x;
        s[i].arr[j] += 1.0f;
        glm::mat3 m(1.0f);
        m[j].y += b.z;
        m[j].x += b.w;
        return std::tuple{s, m, j};
    };
    check_output(outs, "o1", 4, [&](uint32_t l) {
        auto [s, m, j] = simulate(l);
        return glm::vec4(s[0].v, s[0].arr[j]);
    }, kTight);
    check_output(outs, "o2", 4, [&](uint32_t l) {
        auto [s, m, j] = simulate(l);
        return glm::vec4(s[1].v, s[1].arr[j]);
    }, kTight);
    check_output(outs, "o3", 4, [&](uint32_t l) {
        auto [s, m, j] = simulate(l);
        return glm::vec4(m[0].x, m[0].y, m[2].x, m[2].y);
    }, kTight);
}
