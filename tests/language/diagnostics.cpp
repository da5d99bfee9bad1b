// Bad input: the lecture's typo'd lines must come back from Program::compile
// as `file:line: error: ...` diagnostics naming the right file and line.
#include "harness.h"

#include <fstream>
#include <sstream>

using namespace lang;

namespace {

const char* const kGoodVs = "void main() { gl_FrontColor = gl_Color; gl_Position = ftransform(); }\n";
const char* const kGoodFs = "void main() { gl_FragColor = gl_Color; }\n";

const char* const kPixVs = R"(varying vec3 normal, ecPos;
void main()
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    ecPos = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_Position = ftransform();
}
)";

// Finds an error (not a warning) reported at file:line.
const glslrun::Diagnostic* find_error(const glslrun::Error& error, const std::string& file, int line) {
    for (const auto& d : error.diagnostics)
        if (!d.warning && d.file == file && d.line == line) return &d;
    return nullptr;
}

// Compiles, expects failure with an error at one of `lines` of `file`, and
// returns that diagnostic's message.
std::string expect_error_at(const glslrun::Result<glslrun::Program>& result, const std::string& file,
                            std::initializer_list<int> lines) {
    REQUIRE_FALSE(result.ok());
    const auto& error = result.error();
    INFO("diagnostics:\n" << error.str());
    REQUIRE_FALSE(error.diagnostics.empty());
    const glslrun::Diagnostic* found = nullptr;
    int line = 0;
    for (int l : lines)
        if (!found && (found = find_error(error, file, l))) line = l;
    REQUIRE(found != nullptr);
    std::string prefix = file + ":" + std::to_string(line) + ": error: ";
    CHECK(found->str().rfind(prefix, 0) == 0);
    CHECK(error.str().find(prefix) != std::string::npos);
    CHECK_FALSE(found->message.empty());
    return found->message;
}

}  // namespace

TEST_CASE("undeclared glColor (the colors example)", "[diagnostics]") {
    const char* vs = "void main(void) {\n    glColor = gl_Color;\n    gl_Position = ftransform();\n}\n";
    auto result = glslrun::Program::compile({{"colors.vert", vs}}, {{"colors.frag", kGoodFs}});
    std::string message = expect_error_at(result, "colors.vert", {2});
    CHECK(message.find("glColor") != std::string::npos);
}

TEST_CASE("gl_FrontMaterial.emissive (no such field)", "[diagnostics]") {
    const char* vs = R"(void main() {
    vec3 normal, lightDir;
    vec4 diffuse, ambient, globalAmbient;
    float NdotL;
    normal = normalize(gl_NormalMatrix * gl_Normal);
    lightDir = normalize(vec3(gl_LightSource[0].position));
    NdotL = max(dot(normal, lightDir), 0.0);
    diffuse = gl_FrontMaterial.diffuse * gl_LightSource[0].diffuse;
    ambient = gl_FrontMaterial.ambient * gl_LightSource[0].ambient;
    globalAmbient = gl_LightModel.ambient * gl_FrontMaterial.ambient;
    gl_FrontColor = NdotL * diffuse + globalAmbient + ambient
        + gl_FrontMaterial.emissive;
    gl_Position = ftransform();
}
)";
    auto result = glslrun::Program::compile({{"dir_vert_global.vert", vs}}, {{"colors.frag", kGoodFs}});
    std::string message = expect_error_at(result, "dir_vert_global.vert", {12});
    CHECK(message.find("emissive") != std::string::npos);
}

TEST_CASE("FrontMaterial.diffuse (undeclared struct name) in a fragment shader", "[diagnostics]") {
    const char* fs = R"(varying vec3 normal, ecPos;
void main()
{
    vec3 n = normalize(normal);
    vec3 lightDir = normalize(vec3(gl_LightSource[0].position) - ecPos);
    float intensity = max(dot(lightDir, n), 0.0);
    vec4 diffuse = gl_LightSource[0].diffuse * FrontMaterial.diffuse;
    gl_FragColor = diffuse * intensity;
}
)";
    auto result = glslrun::Program::compile({{"pos_pix.vert", kPixVs}}, {{"pos_pix.frag", fs}});
    std::string message = expect_error_at(result, "pos_pix.frag", {7});
    CHECK(message.find("FrontMaterial") != std::string::npos);
}

TEST_CASE("missing semicolon", "[diagnostics]") {
    const char* fs = R"(varying vec3 normal, ecPos;
void main()
{
    vec3 n, lightDir;
    float intensity;
    lightDir = vec3(gl_LightSource[0].position) - ecPos;
    n = normalize(normal);
    lightDir = normalize(lightDir)
    intensity = max(dot(lightDir, n), 0.0);
    gl_FragColor = gl_FrontMaterial.diffuse * intensity;
}
)";
    auto result = glslrun::Program::compile({{"pos_pix.vert", kPixVs}}, {{"pos_pix.frag", fs}});
    // The parser notices at the next token, on line 9; line 8 would be better.
    expect_error_at(result, "pos_pix.frag", {8, 9});
}

TEST_CASE("int literal divided by float: 1 / (...) in GLSL 1.10", "[diagnostics]") {
    const char* fs = R"(varying vec3 normal, ecPos;
void main()
{
    vec3 lightDir = vec3(gl_LightSource[0].position) - ecPos;
    float d = length(lightDir);
    float att = 1 / (gl_LightSource[0].constantAttenuation +
        gl_LightSource[0].linearAttenuation * d +
        gl_LightSource[0].quadraticAttenuation * d * d);
    gl_FragColor = gl_FrontMaterial.diffuse * att;
}
)";
    auto result = glslrun::Program::compile({{"pos_pix.vert", kPixVs}}, {{"spot_att.frag", fs}});
    // glslang reports the whole expression where it ends or where it starts.
    expect_error_at(result, "spot_att.frag", {6, 7, 8});
}

TEST_CASE("float compared with int literal: if (intensity > 0) in GLSL 1.10", "[diagnostics]") {
    const char* fs = R"(varying vec3 normal, ecPos;
void main()
{
    vec3 lightDir = normalize(vec3(gl_LightSource[0].position) - ecPos);
    float intensity = max(dot(lightDir, normalize(normal)), 0.0);
    vec4 color = gl_FrontMaterial.diffuse * intensity;
    if (intensity > 0) {
        color += gl_FrontMaterial.specular;
    }
    gl_FragColor = color;
}
)";
    auto result = glslrun::Program::compile({{"pos_pix.vert", kPixVs}}, {{"specular.frag", fs}});
    expect_error_at(result, "specular.frag", {7});

    SECTION("the same line is valid GLSL 1.20") {
        std::string fs120 = std::string("#version 120\n") + fs;
        auto ok = glslrun::Program::compile({{"pos_pix.vert", kPixVs}}, {{"specular.frag", fs120}});
        INFO((ok ? std::string() : ok.error().str()));
        CHECK(ok.ok());
    }
}

TEST_CASE("errors in several units of one stage name the right unit", "[diagnostics]") {
    const char* helper = "vec4 shade(vec4 c) {\n    return c * 2.0;\n}\n";
    const char* bad_main = "vec4 shade(vec4 c);\nvoid main() {\n    gl_FragColor = shade(gl_Color) + undefined_thing;\n}\n";
    auto result = glslrun::Program::compile({{"a.vert", kGoodVs}},
                                            {{"helper.frag", helper}, {"main.frag", bad_main}});
    std::string message = expect_error_at(result, "main.frag", {3});
    CHECK(message.find("undefined_thing") != std::string::npos);
}

TEST_CASE("check_shader reports the same diagnostics for one stage", "[diagnostics]") {
    auto status = glslrun::check_shader(glslrun::Stage::Vertex,
                                        {"colors.vert", "void main() {\n\n    glColor = gl_Color;\n}\n"});
    REQUIRE_FALSE(status.ok());
    INFO(status.error().str());
    CHECK(find_error(status.error(), "colors.vert", 3) != nullptr);
    auto good = glslrun::check_shader(glslrun::Stage::Fragment, {"ok.frag", kGoodFs});
    INFO((good ? std::string() : good.error().str()));
    CHECK(good.ok());
}

TEST_CASE("the corrected lecture shaders compile", "[diagnostics]") {
    auto read = [](const char* path) {
        std::ifstream in(std::string(GLSLRUN_SOURCE_DIR) + "/shaders/" + path);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    std::string vs = read("pos_pix.vert"), fs = read("spot_pix_fixed.frag");
    REQUIRE_FALSE(vs.empty());
    REQUIRE_FALSE(fs.empty());
    auto result = glslrun::Program::compile({{"pos_pix.vert", vs}}, {{"spot_pix_fixed.frag", fs}});
    INFO((result ? std::string() : result.error().str()));
    CHECK(result.ok());
}

TEST_CASE("other compile and link errors are reported, not crashed on", "[diagnostics]") {
    auto compile = [](const char* vs, const char* fs) {
        return glslrun::Program::compile({{"x.vert", vs}}, {{"x.frag", fs}});
    };
    auto expect_failure = [](const glslrun::Result<glslrun::Program>& result) {
        REQUIRE_FALSE(result.ok());
        INFO(result.error().str());
        CHECK_FALSE(result.error().diagnostics.empty());
        CHECK_FALSE(result.error().str().empty());
    };
    SECTION("discard in a vertex shader") {
        auto r = compile("void main() {\n    discard;\n}\n", kGoodFs);
        expect_error_at(r, "x.vert", {2});
    }
    SECTION("recursion") {
        expect_failure(compile("float f(float x);\nfloat g(float x) { return f(x); }\n"
                               "float f(float x) { return g(x) + 1.0; }\n"
                               "void main() { gl_Position = vec4(f(1.0)); }\n",
                               kGoodFs));
    }
    SECTION("no main") {
        expect_failure(compile("float f() { return 1.0; }\n", kGoodFs));
    }
    SECTION("fragment varying not declared in the vertex shader") {
        expect_failure(compile(kGoodVs, "varying vec3 missing;\nvoid main() { gl_FragColor = vec4(missing, 1.0); }\n"));
    }
    SECTION("varying types differ between the stages") {
        expect_failure(compile("varying vec3 n;\nvoid main() { n = vec3(1.0); gl_Position = vec4(0.0); }\n",
                               "varying vec4 n;\nvoid main() { gl_FragColor = n; }\n"));
    }
    SECTION("assigning to a uniform and to an attribute") {
        auto r = compile("uniform float u;\nattribute vec4 a;\nvoid main() {\n    u = 1.0;\n"
                         "    a = vec4(0.0);\n    gl_Position = vec4(u);\n}\n", kGoodFs);
        expect_error_at(r, "x.vert", {4});
        expect_error_at(r, "x.vert", {5});
    }
    SECTION("empty source") {
        expect_failure(compile("", kGoodFs));
    }
}

TEST_CASE("a runaway loop's error names the shader", "[diagnostics]") {
    auto program = compile_or_fail("attribute vec4 a;\nvoid main() {\n    float x = a.x;\n"
                                   "    while (x < 1e30 || x > -1e30) x += 1.0;\n"
                                   "    gl_Position = vec4(x);\n}\n",
                                   kGoodFs);
    program.exec.max_loop_iterations = 64;
    auto result = glslrun::run_vertices(program, std_attribs(), kVerts);
    REQUIRE_FALSE(result.ok());
    INFO(result.error().str());
    CHECK(result.error().str().find("loop") != std::string::npos);
    CHECK(result.error().str().find("test.vert:4:") != std::string::npos);
}
