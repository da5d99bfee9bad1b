// Regression tests for glslang AST shapes the lowering must not take
// literally, and for checks glslang does not make. Shaders run over many
// lanes with lane-dependent inputs.
#include "helpers.h"
#include "lanes.h"

#include "frontend/source_rewrite.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("converted out argument: its l-value index is evaluated before the call") {
    // glslang writes value[i] back after the call, where f has changed i.
    const char* vs =
        "#version 120\n"
        "attribute float a;\n"
        "void f(inout int i, out int x, out ivec2 y) { x = 10 + i; y = ivec2(20 + i, 30); i = 3 - i; }\n"
        "float g(inout int i, out int x) { x = 50; i = 0; return 7.0; }\n"
        "void main() {\n"
        "  gl_Position = gl_Vertex;\n"
        "  vec4 value = vec4(0.0);\n"
        "  vec4 w[4];\n"
        "  for (int k = 0; k < 4; ++k) w[k] = vec4(0.0);\n"
        "  int i = int(a);\n"
        "  f(i, value[i], w[i].yz);\n"
        "  int j = int(a);\n"
        "  float r = g(j, value[3 - int(a) + j]) + 1.0;\n"  // j == int(a) before the call
        "  gl_FrontColor = vec4(value[int(a)], w[int(a)].y, value[3], r) + vec4(0.0, w[int(a)].z, 0.0, 0.0);\n"
        "}\n";
    auto lane_a = [](uint32_t lane) { return float(lane % 3); };  // keeps 3 - a + a == 3 distinct from a
    std::vector<float> got = front_color_lanes(vs, lane_a);
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) {
        float a = lane_a(lane);
        INFO("lane " << lane);
        CHECK(got[lane * 4 + 0] == 10 + a);
        CHECK(got[lane * 4 + 1] == 20 + a + 30);
        CHECK(got[lane * 4 + 2] == 50);
        CHECK(got[lane * 4 + 3] == 8);
    }
}

TEST_CASE("do-while: the test does not see a declaration of a non-compound body") {
    // The piglit case and a nested one; `i` in each test is the outer one.
    const char* vs =
        "attribute float a;\n"
        "void main() {\n"
        "  gl_Position = gl_Vertex;\n"
        "  int i = 17;\n"
        "  int j = int(a);\n"
        "  do int i = (j++, 0); while (i <= 0 && j < 3);\n"
        "  int k = 0, n = 0;\n"
        "  do do int n = (k++, 1); while (n < 0 && k < 10); while (n < 1 && k < int(a) + 5);\n"
        "  gl_FrontColor = vec4(float(i), float(j), float(k), float(n));\n"
        "}\n";
    auto lane_a = [](uint32_t lane) { return float(lane % 7) - 3.0f; };
    std::vector<float> got = front_color_lanes(vs, lane_a);
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) {
        float a = lane_a(lane);
        INFO("lane " << lane);
        CHECK(got[lane * 4 + 0] == 17);
        CHECK(got[lane * 4 + 1] == a + 1);  // one iteration: 17 <= 0 is false
        CHECK(got[lane * 4 + 2] == std::max(1.0f, a + 5));
        CHECK(got[lane * 4 + 3] == 0);
    }
}

TEST_CASE("do-while body rewrite keeps lines and leaves other shapes alone") {
    using frontend::brace_do_while_bodies;
    CHECK(brace_do_while_bodies("do x++; while (x < 3);") == "do {x++; }while (x < 3);");
    CHECK(brace_do_while_bodies("do\n  int i = 0;\nwhile (i < 1);") == "do\n  {int i = 0;\n}while (i < 1);");
    CHECK(brace_do_while_bodies("do { x++; } while (x < 3);") == "do { x++; } while (x < 3);");
    CHECK(brace_do_while_bodies("do if (a) x; else y; while (b);") == "do {if (a) x; else y; }while (b);");
    CHECK(brace_do_while_bodies("do do x; while (a); while (b);") == "do {do {x; }while (a); }while (b);");
    CHECK(brace_do_while_bodies("do /* c */ for (;;) x; while (b);") == "do /* c */ {for (;;) x; }while (b);");
    // A body made by a macro, or broken by a directive: untouched.
    CHECK(brace_do_while_bodies("do BODY while (b);") == "do BODY while (b);");
    CHECK(brace_do_while_bodies("do\n#if 1\n x;\n#endif\nwhile (b);") == "do\n#if 1\n x;\n#endif\nwhile (b);");
    CHECK(brace_do_while_bodies("// do x; while (b);\nundo = 1;") == "// do x; while (b);\nundo = 1;");
}
