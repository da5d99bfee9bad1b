// Rules glslang 12 does not enforce that our own checks add (unit_checks.cpp)
// and the preprocessor compatibility rewrites (source_rewrite.cpp): each
// rejected shader gets a `file:line: error:` at the offending line, and the
// closest legal shader still compiles.
#include "helpers.h"
#include "lanes.h"

#include "frontend/source_rewrite.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

std::string check(Stage stage, const std::string& src, int version = 110) {
    Status st = check_shader(stage, ShaderSource{"u.glsl", src}, version);
    return st.ok() ? std::string() : st.error().str();
}

bool has_error_at(const std::string& errors, int line, const std::string& text) {
    std::string head = "u.glsl:" + std::to_string(line) + ": error: ";
    size_t at = errors.find(head);
    return at != std::string::npos && errors.find(text, at) != std::string::npos;
}

}  // namespace

TEST_CASE("GLSL 1.10: no out or inout array parameters; 1.20 allows them") {
    const char* src = "void f(out float x[2]) {}\nvoid g(in float y[2]) {}\n\nvoid h(inout float z[2]) {}\n";
    std::string e = check(Stage::Vertex, src);
    CHECK(has_error_at(e, 1, "'x' : array parameters cannot be out or inout"));
    CHECK(has_error_at(e, 4, "'z' : array parameters"));
    CHECK(e.find("'y'") == std::string::npos);
    CHECK(check(Stage::Vertex, src, 120) == "");
}

TEST_CASE("a struct holding a sampler is not an out/inout parameter or return type") {
    const char* decl = "struct S { float x; sampler2D t; };\nuniform S u;\n";
    CHECK(has_error_at(check(Stage::Fragment, std::string(decl) + "void f(inout S p) {}\n"), 3, "'p' : a sampler"));
    CHECK(has_error_at(check(Stage::Fragment, std::string(decl) + "\nvoid f(out S p) {}\n"), 4, "'p'"));
    CHECK(has_error_at(check(Stage::Fragment, std::string(decl) + "S f() { return u; }\n"), 3, "'f' : function cannot return"));
    CHECK(check(Stage::Fragment, std::string(decl) + "float f(in S p) { return p.x; }\n") == "");
}

TEST_CASE("constant indices past an array's final size, gl_TexCoord past gl_MaxTextureCoords") {
    CHECK(has_error_at(check(Stage::Vertex, "void main() {\n gl_TexCoord[gl_MaxTextureCoords] = vec4(1.0);\n}\n"), 2,
                       "array index 8 out of range: 'gl_TexCoord'"));
    CHECK(check(Stage::Vertex, "void main() { gl_TexCoord[gl_MaxTextureCoords - 1] = vec4(1.0); }\n") == "");
    const char* resized =
        "float x[];\n"
        "void foo() { x[3] = 2.; }\n"
        "float x[] = float[2](1., 2.);\n";
    CHECK(has_error_at(check(Stage::Vertex, resized, 120), 2, "array index 3 out of range: 'x' has 2 elements"));
    const char* redeclared = "void main() {\n float[] a;\n a[2] = 0.0;\n float[2] a;\n}\n";
    CHECK(has_error_at(check(Stage::Vertex, redeclared, 120), 3, "array index 2 out of range"));
    CHECK(check(Stage::Vertex, "void main() {\n float[] a;\n a[2] = 0.0;\n float[3] a;\n}\n", 120) == "");
}

TEST_CASE("gl_FragColor and gl_FragData are not both written, even in dead code") {
    std::string e = check(Stage::Fragment,
                          "void main() {\n gl_FragColor = vec4(1.0);\n if (false)\n  gl_FragData[0] = vec4(1.0);\n}\n");
    CHECK(has_error_at(e, 4, "writes to both 'gl_FragColor' and 'gl_FragData'"));
    CHECK(check(Stage::Fragment, "void main() { gl_FragData[0] = vec4(1.0); gl_FragData[1] = vec4(0.0); }\n") == "");
    CHECK(check(Stage::Fragment, "void main() { gl_FragColor = vec4(1.0); gl_FragColor.x += 1.0; }\n") == "");
    CHECK(check(Stage::Vertex, "void main() { gl_Position = vec4(1.0); }\n") == "");
}

TEST_CASE("__VERSION__, __LINE__, __FILE__ count as defined") {
    const char* src =
        "#if !defined __VERSION__ || !defined(__LINE__) || ! defined ( __FILE__ )\n"
        "#error not defined\n"
        "#endif\n"
        "#ifndef __VERSION__\n"
        "#error ifndef\n"
        "#endif\n"
        "#ifdef __VERSION__\n"
        "#if __VERSION__ != 110\n"
        "#error wrong version\n"
        "#endif\n"
        "#else\n"
        "#error ifdef\n"
        "#endif\n"
        "void main() { gl_Position = vec4(__LINE__); }\n";
    CHECK(check(Stage::Vertex, src) == "");
    CHECK(has_error_at(check(Stage::Vertex, "#if defined __VERSION__\n#error yes\n#endif\n"), 2, "yes"));
    CHECK(frontend::define_predefined_macros("#ifdef __LINE__ // c\nx defined __LINE__\n") ==
          "#if 1           // c\nx defined __LINE__\n");
}

TEST_CASE("line continuation is spliced in every version, line numbers kept") {
    CHECK(frontend::splice_line_continuations("#define A 1 \\\n + 2\nb\n") == "#define A 1  + 2\n\nb\n");
    CHECK(frontend::splice_line_continuations("a \\\r\nb") == "a b\n");
    const char* skipped = "#ifdef NOT_DEFINED\n#define M(x) \\\n  if (x)\n#endif\nvoid main() { gl_Position = vec4(0.0); }\n";
    CHECK(check(Stage::Vertex, skipped) == "");
    // The error after a continued #define still reports its own line.
    std::string e = check(Stage::Vertex, "#define TWO \\\n  2.0\nvoid main() {\n  gl_Position = vec4(TWO);\n  undeclared = 1;\n}\n");
    CHECK(has_error_at(e, 5, "undeclared"));
    std::vector<float> got = front_color_lanes(
        "attribute float a;\n#define SCALE(x) \\\n  ((x) * 3.0)\nvoid main() { gl_Position = gl_Vertex; gl_FrontColor = vec4(SCALE(a)); }\n",
        [](uint32_t lane) { return float(lane); });
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) CHECK(got[lane * 4] == 3.0f * float(lane));
}

TEST_CASE("unary + on void, an array or a struct is rejected; on values it is the identity") {
    const char* src =
        "struct S { float x; };\n"
        "void f(void) {}\n"
        "float a[2];\n"
        "void main() {\n"
        "  +f();\n"
        "  a[0] = +a[1] + +a[0];\n"
        "  +a;\n"
        "  S s; s.x = 1.0; +s;\n"
        "}\n";
    std::string e = check(Stage::Vertex, src);
    CHECK(has_error_at(e, 5, "unary '+' takes a scalar, vector or matrix, not void"));
    CHECK(has_error_at(e, 7, "not an array"));
    CHECK(has_error_at(e, 8, "not a structure"));
    CHECK(e.find("u.glsl:6:") == std::string::npos);
    std::vector<float> got = front_color_lanes(
        "attribute float a;\n"
        "float g(float x) { return x * 2.0; }\n"
        "void main() { float b[2]; b[0] = a; b[1] = +g(a); float c = a;\n"
        "  gl_Position = gl_Vertex; gl_FrontColor = vec4(+a, +b[1], + -a, c++ + +c); }\n",
        [](uint32_t lane) { return float(lane) - 10.0f; });
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) {
        float a = float(lane) - 10.0f;
        CHECK(got[lane * 4 + 0] == a);
        CHECK(got[lane * 4 + 1] == 2 * a);
        CHECK(got[lane * 4 + 2] == -a);
        CHECK(got[lane * 4 + 3] == a + (a + 1));
    }
}

TEST_CASE("an array size given as a vector constructor is rejected") {
    CHECK(has_error_at(check(Stage::Vertex, "#version 120\n\nuniform float [ivec2(2.3, 2.3)] a;\nvoid main() { gl_Position = vec4(a[0]); }\n"),
                       3, "array size or index must be a scalar integer"));
    CHECK(has_error_at(check(Stage::Vertex, "uniform float a[ivec4(1, 1, 1, 1)];\n"), 1, "scalar integer"));
    CHECK(check(Stage::Vertex, "uniform float a[ivec2(2, 3).y];\nvoid main() { gl_Position = vec4(a[2]); }\n") == "");
}

TEST_CASE("Mesa compatibility: float suffix f in GLSL 1.10") {
    using frontend::drop_float_suffixes;
    CHECK(drop_float_suffixes("x = 1.0f + .5F + 2e3f; y = 0x1f; z1f = 3; // 4.0f\n") ==
          "x = 1.0  + .5  + 2e3 ; y = 0x1f; z1f = 3; // 4.0f\n");
    std::vector<float> got = front_color_lanes(
        "attribute float a;\nvoid main() { int k = 0x1f; gl_Position = gl_Vertex; gl_FrontColor = vec4(a * 2.5f, 1e1f, float(k), 0.0); }\n",
        [](uint32_t lane) { return float(lane); });
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) {
        CHECK(got[lane * 4 + 0] == 2.5f * float(lane));
        CHECK(got[lane * 4 + 1] == 10.0f);
        CHECK(got[lane * 4 + 2] == 31.0f);
    }
    CHECK(check(Stage::Vertex, "void main() { gl_Position = vec4(1f); }\n") != "");  // no fraction: still invalid
}

TEST_CASE("# stringification in a macro is rejected, except in a skipped region") {
    CHECK(has_error_at(check(Stage::Fragment, "\n#define S(a, b) vec4(#a, b)\nvoid main() { }\n"), 2, "stringification"));
    CHECK(check(Stage::Fragment, "#ifdef NOPE\n#define S(a, b) vec4(#a, b)\n#endif\nvoid main() { }\n") == "");
    CHECK(check(Stage::Fragment, "#define S(a, b) ((a) * (b))\nvoid main() { gl_FragColor = vec4(S(1.0, 2.0)); }\n") == "");
}
