// Values computed by lowered shaders: l-values, operators, constructors,
// control flow, functions. Each case runs with uniform inputs so nothing can
// be folded away by glslang, and checks every output component.
#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

using V = std::vector<float>;

TEST_CASE("swizzle writes and reads") {
    const char* fs =
        "uniform vec4 u;\n"
        "void main() { vec4 v = u; v.zx = v.xz; v.w += 10.0; vec2 t = v.wy; gl_FragColor = vec4(t, v.x, v.z); }\n";
    CHECK(eval_fs(fs, {{"u", {1, 2, 3, 4}}}) == V{14, 2, 3, 1});
}

TEST_CASE("array of struct member writes with dynamic indices") {
    const char* fs =
        "struct S { vec3 f; float g; };\n"
        "uniform int i; uniform int j;\n"
        "void main() {\n"
        "  S a[3];\n"
        "  for (int k = 0; k < 3; ++k) { a[k].f = vec3(0.0); a[k].g = float(k); }\n"
        "  a[i].f.y = 5.0;\n"
        "  a[i].f[j] += 2.0;\n"
        "  gl_FragColor = vec4(a[1].f, a[i].g);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"i", {1}}, {"j", {2}}}) == V{0, 5, 2, 1});
    CHECK(eval_fs(fs, {{"i", {1}}, {"j", {1}}}) == V{0, 7, 0, 1});
    CHECK(eval_fs(fs, {{"i", {2}}, {"j", {0}}}) == V{0, 0, 0, 2});
}

TEST_CASE("matrix column and element writes, dynamic matrix indexing") {
    const char* fs =
        "uniform int i; uniform int j;\n"
        "void main() {\n"
        "  mat3 m = mat3(1.0);\n"
        "  m[1] = vec3(4.0, 5.0, 6.0);\n"
        "  m[2][0] = 7.0;\n"
        "  m[i][j] = 9.0;\n"
        "  gl_FragColor = vec4(m[1][1], m[2].x, m[i][j], m[0][0]);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"i", {0}}, {"j", {0}}}) == V{5, 7, 9, 9});
    CHECK(eval_fs(fs, {{"i", {1}}, {"j", {1}}}) == V{9, 7, 9, 1});
}

TEST_CASE("out and inout arguments of swizzles and array elements") {
    const char* fs =
        "uniform int i;\n"
        "void f(in float a, out vec2 b, inout float c) { b = vec2(a, a + 1.0); c = c * 2.0; }\n"
        "void main() {\n"
        "  vec4 v = vec4(1.0, 2.0, 3.0, 4.0);\n"
        "  float arr[3]; arr[0] = 10.0; arr[1] = 20.0; arr[2] = 30.0;\n"
        "  f(v.x, v.wz, arr[i]);\n"
        "  gl_FragColor = vec4(v.z, v.w, arr[1], arr[2]);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"i", {1}}}) == V{2, 1, 40, 30});
}

TEST_CASE("increments, decrements and op-assign") {
    const char* fs =
        "uniform float x;\n"
        "void main() {\n"
        "  float a = x; float b = a++; float c = ++a; int n = 3; n--; int m = --n;\n"
        "  vec2 v = vec2(x); v *= 3.0; v /= vec2(2.0, 4.0); v -= 1.0;\n"
        "  gl_FragColor = vec4(b, c, float(m), v.x + v.y);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"x", {2}}}) == V{2, 4, 1, 2 + 0.5f});
}

TEST_CASE("constructors") {
    const char* fs =
        "uniform vec4 u; uniform mat2 m2;\n"
        "void main() {\n"
        "  mat2 a = mat2(u.x);\n"
        "  mat3 b = mat3(m2);\n"
        "  vec3 c = vec3(u.yz, a[0][0]);\n"
        "  ivec2 d = ivec2(u.zw);\n"
        "  bvec2 e = bvec2(u.x, 0.0);\n"
        "  vec4 f = vec4(m2);\n"
        "  gl_FragColor = vec4(a[0][1] + a[1][1], b[2][2] + b[0][1], c.z + float(d.y), float(e.x) + float(e.y)) + f;\n"
        "}\n";
    CHECK(eval_fs(fs, {{"u", {2, 3, 4.5f, 5.7f}}, {"m2", {1, 2, 3, 4}}}, 120) == V{2 + 1, 1 + 2 + 2, 2 + 5 + 3, 1 + 4});
}

TEST_CASE("matrix products") {
    const char* fs =
        "uniform mat2 a; uniform mat2 b; uniform vec2 v;\n"
        "void main() {\n"
        "  vec2 mv = a * v; vec2 vm = v * a; mat2 ab = a * b;\n"
        "  gl_FragColor = vec4(mv.x + 10.0 * mv.y, vm.x + 10.0 * vm.y, ab[0][0] + 10.0 * ab[0][1], ab[1][0] + 10.0 * ab[1][1]);\n"
        "}\n";
    // a = [[1,3],[2,4]] (columns (1,2) and (3,4)), b columns (5,6), (7,8), v = (1,2)
    // a*v = (1*1+3*2, 2*1+4*2) = (7, 10); v*a = (dot(v,col0), dot(v,col1)) = (5, 11)
    // a*b col0 = a*(5,6) = (5+18, 10+24) = (23, 34); col1 = a*(7,8) = (31, 46)
    CHECK(eval_fs(fs, {{"a", {1, 2, 3, 4}}, {"b", {5, 6, 7, 8}}, {"v", {1, 2}}}) == V{107, 115, 363, 491});
}

TEST_CASE("aggregate equality produces one bool") {
    const char* fs =
        "struct S { vec2 a; int b; };\n"
        "uniform vec3 u; uniform int k;\n"
        "void main() {\n"
        "  S s1 = S(u.xy, k); S s2 = S(vec2(1.0, 2.0), 3);\n"
        "  float arr1[2]; arr1[0] = u.x; arr1[1] = u.y;\n"
        "  bool e = u == vec3(1.0, 2.0, 3.0);\n"
        "  gl_FragColor = vec4(float(e), float(s1 == s2), float(s1 != s2), float(u.xy != vec2(1.0, 2.0)));\n"
        "}\n";
    CHECK(eval_fs(fs, {{"u", {1, 2, 3}}, {"k", {3}}}) == V{1, 1, 0, 0});
    CHECK(eval_fs(fs, {{"u", {1, 2, 4}}, {"k", {4}}}) == V{0, 0, 1, 0});
}

TEST_CASE("short-circuit && and || evaluate the right operand only when needed") {
    const char* fs =
        "uniform float x;\n"
        "float count = 0.0;\n"
        "bool bump() { count += 1.0; return true; }\n"
        "void main() {\n"
        "  bool a = x > 0.0 && bump();\n"
        "  bool b = x > 0.0 || bump();\n"
        "  float t = x > 0.0 ? (count += 10.0) : (count += 100.0);\n"
        "  gl_FragColor = vec4(float(a), float(b), count, t);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"x", {1}}}) == V{1, 1, 11, 11});
    CHECK(eval_fs(fs, {{"x", {-1}}}) == V{0, 1, 101, 101});
}

TEST_CASE("loops: for, while, do-while, break, continue") {
    const char* fs =
        "uniform int n;\n"
        "void main() {\n"
        "  float s = 0.0;\n"
        "  for (int i = 0; i < n; i++) { if (i == 2) continue; if (i == 6) break; s += float(i); }\n"
        "  int j = 0; float w = 0.0;\n"
        "  while (j < n) { j++; w += 1.0; }\n"
        "  int k = 0; float d = 0.0;\n"
        "  do { k++; if (k == 2) continue; d += 1.0; } while (k < n);\n"
        "  int z = 0; do { z++; } while (false);\n"
        "  gl_FragColor = vec4(s, w, d, float(z));\n"
        "}\n";
    CHECK(eval_fs(fs, {{"n", {10}}}) == V{0 + 1 + 3 + 4 + 5, 10, 9, 1});
    CHECK(eval_fs(fs, {{"n", {0}}}) == V{0, 0, 1, 1});
}

TEST_CASE("return from main and from functions inside loops") {
    const char* fs =
        "uniform float x;\n"
        "float find(float lim) { for (int i = 0; i < 100; i++) { if (float(i) >= lim) return float(i) * 2.0; } return -1.0; }\n"
        "void main() {\n"
        "  gl_FragColor = vec4(find(x), find(1000.0), 0.0, 0.0);\n"
        "  if (x > 5.0) return;\n"
        "  gl_FragColor.w = 1.0;\n"
        "}\n";
    CHECK(eval_fs(fs, {{"x", {3}}}) == V{6, -1, 0, 1});
    CHECK(eval_fs(fs, {{"x", {7}}}) == V{14, -1, 0, 0});
}

TEST_CASE("discard sets uses_discard and stops the invocation") {
    ir::Program p = compile_ok(kPassVs, "uniform float x;\nvoid main() { gl_FragColor = vec4(1.0); if (x > 0.0) discard; }\n");
    CHECK(p.fragment.uses_discard);
    MiniEval ev(p.fragment, uniform_store(p, {{"x", {1}}}));
    CHECK_FALSE(ev.run());
    MiniEval ev2(p.fragment, uniform_store(p, {{"x", {-1}}}));
    CHECK(ev2.run());
}

TEST_CASE("nested calls reuse static frames safely") {
    const char* fs =
        "uniform float x;\n"
        "float sq(float a) { return a * a; }\n"
        "float g(float a) { return sq(a) + 1.0; }\n"
        "void main() { gl_FragColor = vec4(sq(sq(x)), sq(x) + sq(x + 1.0), g(sq(x)), g(x)); }\n";
    CHECK(eval_fs(fs, {{"x", {2}}}) == V{16, 4 + 9, 17, 5});
}

TEST_CASE("global initializers run in order before main") {
    const char* fs =
        "uniform float x;\n"
        "float a = x * 2.0;\n"
        "float b = a + 1.0;\n"
        "const float c = 3.0;\n"
        "void main() { gl_FragColor = vec4(a, b, c, 0.0); }\n";
    CHECK(eval_fs(fs, {{"x", {5}}}) == V{10, 11, 3, 0});
}

TEST_CASE("dynamic indexing of local arrays, reads and writes") {
    const char* fs =
        "uniform int i;\n"
        "void main() {\n"
        "  vec2 a[4];\n"
        "  for (int k = 0; k < 4; k++) a[k] = vec2(float(k), float(k * 10));\n"
        "  a[i] = a[i] * 2.0;\n"
        "  vec4 v = vec4(1.0, 2.0, 3.0, 4.0); v[i] = 0.0;\n"
        "  gl_FragColor = vec4(a[i], a[3].y, v[0] + v[1] + v[2] + v[3]);\n"
        "}\n";
    CHECK(eval_fs(fs, {{"i", {2}}}) == V{4, 40, 30, 7});
    CHECK(eval_fs(fs, {{"i", {0}}}) == V{0, 0, 30, 9});
}

TEST_CASE("GLSL 1.20 array constructors, const arrays and implicit conversions") {
    const char* fs =
        "#version 120\n"
        "uniform int i;\n"
        "const float k[3] = float[3](1.0, 2.0, 4.0);\n"
        "void main() {\n"
        "  float a[] = float[](5.0, 6.0, 7.0);\n"
        "  float f = i;\n"
        "  gl_FragColor = vec4(a[i], k[i], f, a.length());\n"
        "}\n";
    CHECK(eval_fs(fs, {{"i", {2}}}) == V{7, 4, 2, 3});
}

TEST_CASE("vector relational built-ins and any/all/not") {
    const char* fs =
        "uniform vec3 u;\n"
        "void main() {\n"
        "  bvec3 lt = lessThan(u, vec3(2.0));\n"
        "  bvec3 eq = equal(u, vec3(1.0, 5.0, 3.0));\n"
        "  gl_FragColor = vec4(float(any(lt)), float(all(lt)), float(all(not(eq))), float(eq.z));\n"
        "}\n";
    CHECK(eval_fs(fs, {{"u", {1, 2, 3}}}) == V{1, 0, 0, 1});
    CHECK(eval_fs(fs, {{"u", {0, 1, 0}}}) == V{1, 1, 1, 0});
}

TEST_CASE("the (vec == vec) == true constant-fold miscompile") {
    const char* fs =
        "#version 120\n"
        "void main() {\n"
        "  bool c = (vec2(1.0) == vec2(1.0)) == true;\n"
        "  bool d = (ivec3(1) != ivec3(2)) == true;\n"
        "  bool e = (vec2(1.0) == vec2(2.0)) == false;\n"
        "  gl_FragColor = vec4(float(c), float(d), float(e), 1.0);\n"
        "}\n";
    CHECK(eval_fs(fs, {}, 120) == V{1, 1, 1, 1});
}

#include "frontend/fold_workaround.h"

TEST_CASE("fold workaround rewrites only parenthesized equality compared with a literal") {
    using frontend::rewrite_bool_literal_compares;
    CHECK(rewrite_bool_literal_compares("bool c = (a == b) == true;") == "bool c = (a == b)        ;");
    CHECK(rewrite_bool_literal_compares("bool c = (a != b) == false;") == "bool c = !(a != b)         ;");
    CHECK(rewrite_bool_literal_compares("x = true != (a == b);") == "x =         !(a == b);");
    CHECK(rewrite_bool_literal_compares("return (a == b) != false;") == "return (a == b)         ;");
    // Not touched: no equality inside, a call, or a tighter operator before.
    CHECK(rewrite_bool_literal_compares("c = (a) == true;") == "c = (a) == true;");
    CHECK(rewrite_bool_literal_compares("c = f(a == b) == true;") == "c = f(a == b) == true;");
    CHECK(rewrite_bool_literal_compares("c = x == (a == b) == false;") == "c = x == (a == b) == false;");
    CHECK(rewrite_bool_literal_compares("c = (a ==\n b) ==\n false;") == "c = !(a ==\n b)   \n      ;");
    CHECK(rewrite_bool_literal_compares("bool truex = (a == b) == trueish;") == "bool truex = (a == b) == trueish;");
}

TEST_CASE("dynamic index into a swizzle, read and written") {
    const char* fs =
        "uniform int zero;\n"
        "void main() {\n"
        "  gl_FragColor = vec4(1, 0, 0, 1);\n"
        "  gl_FragColor.wzyx[zero + 2] = 1.0;\n"
        "  gl_FragColor.wzyx[zero + 3] = 0.0;\n"
        "  gl_FragColor.w = gl_FragColor.zxy[zero + 2] + 0.5;\n"
        "}\n";
    CHECK(eval_fs(fs, {{"zero", {0}}}) == V{0, 1, 0, 1.5f});
}
