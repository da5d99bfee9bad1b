// Issue #16's conformance work: the refusal of other GLSL versions, the
// constant folding glslang 12 lacks (frontend/glslang_fold.cpp), calls in
// code that folding removes, and min/max/clamp on ints before GLSL 1.30.
#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

const char* kMinimalFs = "void main() { gl_FragColor = vec4(1.0); }\n";

}  // namespace

TEST_CASE("other GLSL versions and profiles are refused with file:line, through the library") {
    for (std::string version : {"130", "140", "150", "330", "450", "100 es", "100", "300 es", "150 compatibility"}) {
        INFO(version);
        std::string vs = "// header comment\n#version " + version + "\nvoid main() { gl_Position = vec4(1.0); }\n";
        auto r = Program::compile({{"v.vert", vs}}, {{"f.frag", kMinimalFs}});
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().unsupported_version);
        REQUIRE(r.error().diagnostics.size() == 1);
        const Diagnostic& d = r.error().diagnostics[0];
        CHECK(d.file == "v.vert");
        CHECK(d.line == 2);
        CHECK(d.message.find("'#version " + version + "'") != std::string::npos);
        CHECK(d.message.find("glslrun runs GLSL 1.10 and 1.20 only") != std::string::npos);
        Status st = check_shader(Stage::Vertex, ShaderSource{"v.vert", vs});
        REQUIRE_FALSE(st.ok());
        CHECK(st.error().unsupported_version);
    }
    // An ES shader names its language.
    auto es = check_shader(Stage::Fragment, ShaderSource{"e.frag", "#version 100\nvoid main() {}\n"});
    REQUIRE_FALSE(es.ok());
    CHECK(es.error().str() == "e.frag:1: error: '#version 100' : GLSL ES 1.00 is not supported: glslrun runs GLSL "
                              "1.10 and 1.20 only\n");
}

TEST_CASE("a #version that is no GLSL version is an error, not an unsupported language") {
    for (std::string version : {"999", "0", "110 es", "120 core", "115"}) {
        INFO(version);
        Status st = check_shader(Stage::Vertex, ShaderSource{"v.vert", "#version " + version + "\nvoid main() {}\n"});
        REQUIRE_FALSE(st.ok());
        CHECK_FALSE(st.error().unsupported_version);
        CHECK(st.error().str().find("v.vert:1: error:") == 0);
    }
    CHECK(check_shader(Stage::Vertex, ShaderSource{"v.vert", "#version 120\nvoid main() { gl_Position = vec4(1.0); }\n"}));
}

TEST_CASE("a default version other than 110/120 is refused") {
    CompileOptions options;
    options.default_version = 130;
    auto r = Program::compile({{"v.vert", "void main() { gl_Position = vec4(1.0); }\n"}}, {}, options);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().unsupported_version);
    CHECK(r.error().str().find("GLSL 1.30 (the default version for sources without #version) is not supported") !=
          std::string::npos);
}

TEST_CASE("transpose and matrixCompMult of constants are constant expressions (GLSL 1.20)") {
    const char* fs =
        "#version 120\n"
        "const mat3x2 m = mat3x2(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);\n"
        "const mat2x3 t = transpose(m);\n"  // columns (1,3,5), (2,4,6)
        "const mat2 c = matrixCompMult(mat2(1.0, 2.0, 3.0, 4.0), mat2(5.0, 6.0, 7.0, 8.0));\n"
        "float sized[int(t[1][2])];\n"   // 6 elements
        "float sized2[int(c[1][0])];\n"  // 21 elements
        "void main() { gl_FragColor = vec4(t[0][1], float(sized.length()), float(sized2.length()), c[0][1]); }\n";
    CHECK(eval_fs(fs, {}, 120) == std::vector<float>{3.0f, 6.0f, 21.0f, 12.0f});
    // Non-constant arguments still work at run time.
    const char* dynamic =
        "#version 120\n"
        "uniform mat2 u;\n"
        "void main() { mat2 t = transpose(u); mat2 p = matrixCompMult(u, t); gl_FragColor = vec4(t[0][1], p[1][0], p[0][0], 1.0); }\n";
    CHECK(eval_fs(dynamic, {{"u", {1.0f, 2.0f, 3.0f, 4.0f}}}, 120) == std::vector<float>{3.0f, 6.0f, 1.0f, 1.0f});
}

TEST_CASE("degrees and radians fold in float: int(degrees(3.1415926535)) is 180") {
    const char* fs =
        "#version 120\n"
        "const int d = int(degrees(3.1415926535));\n"
        "const float r = radians(180.0);\n"
        "float sized[d];\n"
        "void main() { gl_FragColor = vec4(float(d), r, float(sized.length()), 0.0); }\n";
    std::vector<float> out = eval_fs(fs, {}, 120);
    CHECK(out[0] == 180.0f);
    CHECK(out[1] == 3.14159274f);  // pi rounded to float
    CHECK(out[2] == 180.0f);
}

TEST_CASE("a call in code that constant folding removes needs no definition") {
    const char* fs =
        "#version 120\n"
        "void missing();\n"
        "uniform float u;\n"
        "void main() {\n"
        "  gl_FragColor = vec4(u);\n"
        "  if (false) missing();\n"
        "  else if (sqrt(4.0) != 2.0) missing();\n"
        "  if (true) gl_FragColor.y = 2.0; else missing();\n"
        "}\n";
    CHECK(eval_fs(fs, {{"u", {0.5f}}}, 120) == std::vector<float>{0.5f, 2.0f, 0.5f, 0.5f});
    // A reachable call still needs a body.
    std::string e = compile_error(kPassVs, "void missing();\nuniform bool b;\nvoid main() { if (b) missing(); gl_FragColor = vec4(1.0); }\n");
    CHECK(e.find("No function definition (body) found") != std::string::npos);
}

TEST_CASE("min, max, clamp, abs and sign on int and ivec before GLSL 1.30, as Mesa (docs/semantics.md)") {
    for (int version : {110, 120}) {
        INFO(version);
        std::string fs = std::string(version == 120 ? "#version 120\n" : "") +
                         "uniform int n;\n"
                         "void main() {\n"
                         "  int a = min(n, 4);\n"
                         "  ivec2 b = max(ivec2(n, -n), 1);\n"
                         "  int c = clamp(n, -2, 3);\n"
                         "  ivec3 d = clamp(ivec3(n), ivec3(0, 1, 9), ivec3(5));\n"
                         "  float f = min(2.5, float(n));\n"  // float overloads on the same line still work
                         "  gl_FragColor = vec4(float(a), float(b.x + b.y), float(c * 10 + d.x + d.y + d.z), f);\n"
                         "}\n";
        CHECK(eval_fs(fs, {{"n", {7.0f}}}, version) == std::vector<float>{4.0f, 8.0f, 45.0f, 2.5f});
        CHECK(eval_fs(fs, {{"n", {-3.0f}}}, version) == std::vector<float>{-3.0f, 4.0f, -20.0f + 0.0f + 1.0f + 5.0f, -3.0f});
    }
    // abs and sign too.
    const char* abs_sign =
        "uniform int n;\n"
        "void main() { ivec2 s = sign(ivec2(n, -n)); gl_FragColor = vec4(float(abs(n)), float(s.x), float(s.y), abs(-1.5)); }\n";
    CHECK(eval_fs(abs_sign, {{"n", {-3.0f}}}) == std::vector<float>{3.0f, -1.0f, 1.0f, 1.5f});
    // The float built-ins stay constant expressions.
    CHECK(eval_fs("#version 120\nconst float c = min(1.0, 2.0);\nfloat s[int(max(c, 3.0))];\n"
                  "void main() { gl_FragColor = vec4(float(s.length())); }\n",
                  {}, 120)[0] == 3.0f);
    // When the retry fails too, glslang's first verdict is the one reported.
    std::string e = compile_error(kPassVs, "uniform int n;\nvoid main() { int a = min(n, 4) + undeclared; gl_FragColor = vec4(1.0); }\n");
    CHECK(e.find("t.frag:2: error: ") == 0);
    CHECK(e.find("glslrun_") == std::string::npos);
}

TEST_CASE("__FILE__ is the source string number; #line sets it") {
    const char* fs =
        "void main() {\n"
        "  float a = float(__FILE__);\n"
        "#line 40 5\n"
        "  gl_FragColor = vec4(a, float(__FILE__), float(__LINE__), 1.0);\n"
        "}\n";
    CHECK(eval_fs(fs) == std::vector<float>{0.0f, 5.0f, 41.0f, 1.0f});
}
