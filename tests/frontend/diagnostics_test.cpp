// Compile and link diagnostics: the lecture's typos, and the GL link rules
// that glslang 12 does not check.
#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

const char* kLectureVs =
    "void main()\n"
    "{\n"
    "    vec3 normal, lightDir;\n"
    "    vec4 diffuse, ambient;\n"
    "    float intensity;\n"
    "    normal = normalize(gl_NormalMatrix * gl_Normal);\n"
    "    lightDir = normalize(vec3(gl_LightSource[0].position));\n"
    "    intensity = max(dot(lightDir, normal), 0.0);\n"
    "    diffuse = gl_FrontMaterial.diffuse * gl_LightSource[0].diffuse;\n"
    "    ambient = gl_FrontMaterial.ambient * gl_LightSource[0].ambient;\n"
    "    gl_FrontColor = intensity * diffuse + ambient + gl_FrontMaterial.emission;\n"
    "    gl_Position = ftransform();\n"
    "}\n";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
}

const char* kColorFs = "void main() { gl_FragColor = gl_Color; }\n";

}  // namespace

TEST_CASE("Diagnostic and Error formatting") {
    CHECK(Diagnostic{"a.frag", 3, "boom", false}.str() == "a.frag:3: error: boom");
    CHECK(Diagnostic{"a.frag", 0, "boom", false}.str() == "a.frag: error: boom");
    CHECK(Diagnostic{"", 0, "boom", true}.str() == "warning: boom");
    Error e("bad", "x.vert", 7);
    REQUIRE(e.diagnostics.size() == 1);
    CHECK(e.str() == "x.vert:7: error: bad\n");
}

TEST_CASE("the corrected lecture shader compiles") { compile_ok(kLectureVs, kColorFs); }

TEST_CASE("lecture typo: glColor is an undeclared identifier") {
    std::string err = compile_error("void main() {\n glColor = gl_Color;\n gl_Position = ftransform();\n}\n", kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:2: error: 'glColor' : undeclared identifier ("));
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
}

TEST_CASE("lecture typo: gl_FrontMaterial.emissive") {
    std::string err = compile_error(replace(kLectureVs, "gl_FrontMaterial.emission", "gl_FrontMaterial.emissive"), kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:11: error: 'emissive' : no such field in structure"));
    CHECK_THAT(err, !Catch::Contains("compilation terminated"));
    CHECK_THAT(err, !Catch::Contains("compilation errors"));
}

TEST_CASE("lecture typo: FrontMaterial.diffuse") {
    std::string err = compile_error(replace(kLectureVs, "gl_FrontMaterial.diffuse", "FrontMaterial.diffuse"), kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:9: error: 'FrontMaterial' : undeclared identifier (did you mean 'gl_FrontMaterial'?)\n"));
}

TEST_CASE("lecture typo: a missing semicolon is reported on the line that lacks it") {
    std::string err = compile_error(replace(kLectureVs, "0.0);\n", "0.0)\n"), kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:8: error: missing ';' at the end of this line (line 9 continues with 'diffuse = "));
}

TEST_CASE("lecture typo: int literal in 1 / (...)") {
    std::string vs = replace(kLectureVs, "    gl_Position", "    float att = 1 / (gl_LightSource[0].constantAttenuation + 1.0);\n    gl_Position");
    std::string err = compile_error(vs, kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:12: error: '/' : no operator int / float exists (GLSL 1.10 never converts int to float implicitly"));
    // GLSL 1.20 converts the int implicitly.
    compile_ok(vs, kColorFs, 120);
}

TEST_CASE("lecture typo: intensity > 0") {
    std::string vs = replace(kLectureVs, "    gl_Position", "    if (intensity > 0) gl_FrontColor += vec4(1.0);\n    gl_Position");
    std::string err = compile_error(vs, kColorFs);
    CHECK_THAT(err, Catch::StartsWith("t.vert:12: error: '>' : no operator float > int exists"));
}

TEST_CASE("a constructor given too few or too many components names its type") {
    CHECK_THAT(compile_error(kPassVs, "void main() {\n gl_FragColor = vec4(1.0, 0.0, 0.0);\n}\n"),
               Catch::StartsWith("t.frag:2: error: 'constructor' : not enough data provided for construction (vec4 "
                                 "takes 4 components, or one scalar for all of them: the arguments give fewer)\n"));
    CHECK_THAT(compile_error(kPassVs, "void main() {\n vec2 v = vec2(1.0, 2.0, 3.0);\n gl_FragColor = vec4(v, v);\n}\n"),
               Catch::StartsWith("t.frag:2: error: 'constructor' : too many arguments (vec2 takes 2 components: "
                                 "the arguments give more)"));
}

TEST_CASE("diagnostics name the right unit when a stage has several") {
    CompileOptions opt;
    auto r = frontend::compile_program({{"a.vert", "void f() {}\n"}, {"b.vert", "void main() {\n\n x = 1.0; }\n"}},
                                       {{"c.frag", kColorFs}}, opt);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str() == "b.vert:3: error: 'x' : undeclared identifier\n");
}

TEST_CASE("link error: gl_Position not written") {
    std::string err = compile_error("void main() { gl_FrontColor = vec4(0.3); }\n", kColorFs);
    CHECK_THAT(err, Catch::Contains("gl_Position"));
}

TEST_CASE("GLSL 1.30+ syntax is named with the version it needs and the 1.10/1.20 way") {
    struct Case { const char* vs; const char* fs; const char* expected; };
    const Case cases[] = {
        {"uniform Light {\n vec4 pos;\n};\nvoid main() { gl_Position = pos; }\n", nullptr,
         "1: error: uniform blocks need GLSL 1.40"},
        {"layout(std140) uniform Light {\n vec4 pos;\n};\nvoid main() { gl_Position = pos; }\n", nullptr,
         "1: error: layout qualifiers need GLSL 1.40"},
        {"in vec3 position;\nvoid main() { gl_Position = vec4(position, 1.0); }\n", nullptr,
         "1: error: 'in' on a global variable needs GLSL 1.30: in GLSL 1.10/1.20 write 'attribute'"},
        {nullptr, "out vec4 color;\nvoid main() { color = vec4(1.0); }\n",
         "1: error: 'out' on a global variable needs GLSL 1.30"},
        {"\nflat varying vec4 c; // flat\nvoid main() { gl_Position = c; }\n", nullptr,
         "2: error: interpolation qualifiers ('flat') need GLSL 1.30"},
        {"void main() { int i = 3;\n switch (i) { default: break; } gl_Position = vec4(1.0); }\n", nullptr,
         "2: error: switch statements need GLSL 1.30"},
        {"void main() { int i = 7 % 2; gl_Position = vec4(float(i)); }\n", nullptr, "1: error: the '%' operator needs GLSL 1.30"},
        {"void main() { int i = 1 << 2; gl_Position = vec4(float(i)); }\n", nullptr, "1: error: bit shifts need GLSL 1.30"},
        {"void main() { uint u = 1u; gl_Position = vec4(1.0); }\n", nullptr, "1: error: unsigned integers ('uint') need GLSL 1.30"},
        {nullptr, "uniform sampler2D t;\nvoid main() { gl_FragColor = texture(t, vec2(0.5)); }\n",
         "2: error: texture() needs GLSL 1.30: in GLSL 1.10/1.20 write texture1D, texture2D"},
    };
    for (const Case& c : cases) {
        std::string err = compile_error(c.vs ? c.vs : kPassVs, c.fs ? c.fs : kColorFs);
        INFO(err);
        CHECK_THAT(err, Catch::Contains(c.expected));
    }
    // A syntax error that is not about a newer feature keeps glslang's message.
    CHECK_THAT(compile_error("void main() { gl_Position = vec4(1.0) vec4; }\n", kColorFs), Catch::Contains("syntax error"));
}

TEST_CASE("link error: a function without a body is named by its GLSL signature") {
    std::string err = compile_error(kPassVs, "float compute_dotprod(vec3 a);\n"
                                             "void main() { gl_FragColor = vec4(compute_dotprod(vec3(1.0))); }\n");
    CHECK_THAT(err, Catch::Contains("found: compute_dotprod(vec3)"));
    err = compile_error(kPassVs, "#version 120\nstruct S { vec3 p; float w[2]; };\nuniform sampler2DShadow t;\n"
                                 "float f(S s, mat3 m, mat2x4 n, sampler2DShadow t, float a[3], bvec2 b, ivec4 i, int k);\n"
                                 "void g();\n"
                                 "void main() { float a[3]; g(); gl_FragColor = vec4(f(S(vec3(1.0), float[2](1.0, 2.0)), "
                                 "mat3(1.0), mat2x4(1.0), t, a, bvec2(true), ivec4(0), 1)); }\n", 120);
    CHECK_THAT(err, Catch::Contains("f(S, mat3, mat2x4, sampler2DShadow, float[3], bvec2, ivec4, int)"));
    CHECK_THAT(err, Catch::Contains("g()"));
    CHECK_THAT(err, !Catch::Contains(";"));
}

TEST_CASE("link error: varying read but not written") {
    std::string err = compile_error("varying vec4 foo;\nvoid main() { gl_Position = ftransform(); }\n",
                                    "varying vec4 foo;\nvoid main() { gl_FragColor = foo; }\n");
    CHECK_THAT(err, Catch::Contains("'foo'"));
    compile_ok("varying vec4 foo;\nvoid main() { foo = vec4(1.0); gl_Position = ftransform(); }\n",
               "varying vec4 foo;\nvoid main() { gl_FragColor = foo; }\n");
    // Declared but unused in the FS: fine.
    compile_ok(kPassVs, "varying vec4 foo;\nvoid main() { gl_FragColor = vec4(1.0); }\n");
}

TEST_CASE("link error: varying type mismatch") {
    std::string err = compile_error("varying vec3 foo;\nvoid main() { foo = vec3(1.0); gl_Position = ftransform(); }\n",
                                    "varying vec4 foo;\nvoid main() { gl_FragColor = foo; }\n");
    CHECK_THAT(err, Catch::Contains("'foo'"));
}

TEST_CASE("link error: uniform type mismatch between stages") {
    std::string err = compile_error("uniform vec4 u;\nvoid main() { gl_Position = ftransform() + u; }\n",
                                    "uniform vec3 u;\nvoid main() { gl_FragColor = vec4(u, 1.0); }\n");
    CHECK_THAT(err, Catch::Contains("'u'"));
}

TEST_CASE("link error: global initialized in two units") {
    CompileOptions opt;
    auto r = frontend::compile_program(
        {{"a.vert", "float g = 1.0;\nvoid f() {}\n"}, {"b.vert", "float g = 2.0;\nvoid main() { gl_Position = gl_Vertex; }\n"}},
        {{"c.frag", kColorFs}}, opt);
    REQUIRE_FALSE(r.ok());
    CHECK_THAT(r.error().str(), Catch::Contains("'g'"));
    // The same non-constant expression twice is still an error; the same constant is not.
    const char* expr_init = "uniform float a;\nfloat g = sin(a);\n";
    auto r2 = frontend::compile_program({{"a.vert", std::string(expr_init) + "void f() {}\n"},
                                         {"b.vert", std::string(expr_init) + "void main() { gl_Position = gl_Vertex; }\n"}},
                                        {{"c.frag", kColorFs}}, opt);
    CHECK_FALSE(r2.ok());
    auto r3 = frontend::compile_program(
        {{"a.vert", "float g = 2.0;\nvoid f() {}\n"}, {"b.vert", "float g = 2.0;\nvoid main() { gl_Position = gl_Vertex; }\n"}},
        {{"c.frag", kColorFs}}, opt);
    CHECK(r3.ok());
    // Initialized once, declared in both: fine, and both units see it.
    auto ok = frontend::compile_program(
        {{"a.vert", "float g = 2.0;\nfloat getg() { return g; }\n"},
         {"b.vert", "float g;\nfloat getg();\nvoid main() { gl_Position = gl_Vertex * getg(); }\n"}},
        {{"c.frag", kColorFs}}, opt);
    INFO((ok ? std::string() : ok.error().str()));
    REQUIRE(ok.ok());
    MiniEval vs(ok->vertex, uniform_store(*ok, {}));
    vs.set_input("gl_Vertex", {1, 2, 3, 4});
    vs.run();
    CHECK(vs.output("gl_Position") == std::vector<float>{2, 4, 6, 8});
}

TEST_CASE("texture functions of later GLSL versions are refused with file and line") {
    std::string err = compile_error(kPassVs, "uniform sampler2D s;\nvoid main() {\n gl_FragColor = texture(s, vec2(0.5));\n}\n");
    CHECK_THAT(err, Catch::Contains("t.frag:3: error:"));
    CHECK_THAT(err, Catch::Contains("texture"));
}

TEST_CASE("check_shader compiles one unit without linking") {
    CHECK(check_shader(Stage::Fragment, {"x.frag", "void f() {}\n"}, 110).ok());
    auto st = check_shader(Stage::Vertex, {"x.vert", "void main() { int i = 1.0; }\n"}, 110);
    REQUIRE_FALSE(st.ok());
    CHECK_THAT(st.error().str(), Catch::StartsWith("x.vert:1: error:"));
}
