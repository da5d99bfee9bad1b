// The .shader_test parser: sections, [require], implicit #version, vertex data.
#include <catch2/catch.hpp>

#include "tools/glslrun/piglit_parse.h"

using namespace glslrun::piglit;

namespace {

ShaderTest parse_ok(std::string_view text) {
    auto p = parse_shader_test(text);
    if (!parsed_ok(p)) FAIL("parse error: " << std::get<ParseError>(p).str());
    return std::get<ShaderTest>(p);
}

ParseError parse_err(std::string_view text) {
    auto p = parse_shader_test(text);
    REQUIRE_FALSE(parsed_ok(p));
    return std::get<ParseError>(p);
}

constexpr const char* kBasic = R"(# leading comment
[require]
GLSL >= 1.20
GL >= 2.1
GL_MAX_VARYING_COMPONENTS >= 52

[vertex shader]
void main() { gl_Position = gl_Vertex; }

[fragment shader]
uniform vec4 color;
void main() { gl_FragColor = color; }

[fragment shader]
#version 110
void helper() {}

[test]
clear color 0.0 0.0 1.0 0.5
clear
uniform vec4 color 0 1 0 1
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
)";

}  // namespace

TEST_CASE("sections and their line numbers", "[piglit][parse]") {
    ShaderTest t = parse_ok(kBasic);
    REQUIRE(t.has_require);
    CHECK(t.require.glsl_version == 120);
    CHECK(t.require.gl_version == 21);
    CHECK_FALSE(t.require.glsl_es);
    REQUIRE(t.require.limits.size() == 1);
    CHECK(t.require.limits[0].name == "GL_MAX_VARYING_COMPONENTS");
    CHECK(t.require.limits[0].op == ">=");
    CHECK(t.require.limits[0].value == 52);
    CHECK(t.require.width == 250);
    CHECK(t.require.height == 250);

    REQUIRE(t.shaders.size() == 3);  // two fragment shaders are allowed
    CHECK(t.shaders[0].stage == ShaderStage::Vertex);
    CHECK(t.shaders[0].first_line == 8);
    CHECK(t.shaders[0].text == "void main() { gl_Position = gl_Vertex; }\n\n");
    CHECK(t.shaders[1].stage == ShaderStage::Fragment);
    CHECK(t.shaders[1].label == "[fragment shader]");
    CHECK(t.shaders[2].stage == ShaderStage::Fragment);

    REQUIRE(t.has_test_section);
    REQUIRE(t.commands.size() == 5);  // blank and comment lines dropped
    CHECK(t.commands[0].line == 19);
    CHECK(std::holds_alternative<ClearColor>(t.commands[0].data));
    CHECK(std::get<ClearColor>(t.commands[0].data).rgba == std::array<float, 4>{0, 0, 1, 0.5f});
    CHECK(std::holds_alternative<Clear>(t.commands[1].data));
    CHECK(t.commands[4].line == 23);
    CHECK_FALSE(skip_reason(t).has_value());
}

TEST_CASE("implicit #version from the GLSL requirement", "[piglit][parse]") {
    ShaderTest t = parse_ok(kBasic);
    CHECK(effective_source(t.shaders[0].text, t.require) ==
          "#version 120\nvoid main() { gl_Position = gl_Vertex; }\n\n");
    // A shader that has its own #version is left alone.
    CHECK(effective_source(t.shaders[2].text, t.require) == t.shaders[2].text);
    Requirements r110;
    r110.glsl_version = 110;
    CHECK(effective_source("void main(){}\n", r110) == "#version 110\nvoid main(){}\n");
    // "#version" without the space (inside a comment word) does not count, as in piglit.
    CHECK(effective_source("// #versionless\nvoid main(){}\n", r110).rfind("#version 110\n", 0) == 0);
}

TEST_CASE("passthrough vertex shader section", "[piglit][parse]") {
    ShaderTest t = parse_ok("[require]\nGLSL >= 1.10\n[vertex shader passthrough]\n"
                            "[fragment shader]\nvoid main(){}\n[test]\ndraw rect -1 -1 2 2\n");
    REQUIRE(t.shaders.size() == 2);
    CHECK(t.shaders[0].stage == ShaderStage::Vertex);
    CHECK(t.shaders[0].text.find("attribute vec4 piglit_vertex;") != std::string::npos);
    std::string src = effective_source(t.shaders[0].text, t.require);
    CHECK(src.rfind("#version 110\n#if __VERSION__ >= 130\n", 0) == 0);
}

TEST_CASE("requirements decide skips", "[piglit][parse]") {
    auto reason = [](const std::string& require) {
        ShaderTest t = parse_ok("[require]\n" + require + "\n[test]\n");
        return skip_reason(t);
    };
    CHECK_FALSE(reason("GLSL >= 1.10").has_value());
    CHECK_FALSE(reason("GLSL >= 1.20\nGL >= 2.0").has_value());
    CHECK(reason("GLSL >= 1.30").value() == "requires GLSL 1.30");
    CHECK(reason("GLSL >= 1.10\nGL >= 3.0").value() == "requires GL 3.0");
    CHECK(reason("GLSL ES >= 1.00").has_value());
    CHECK(reason("GLSL >= 1.10\nGL_ARB_DRAW_BUFFERS").value() ==
          "extension GL_ARB_DRAW_BUFFERS is not supported");
    // Extensions glslrun enables (ARB_draw_buffers) run; tests that need them absent skip.
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_ARB_draw_buffers").has_value());
    CHECK(reason("GLSL >= 1.10\n!GL_ARB_draw_buffers").value() == "requires GL_ARB_draw_buffers to be absent");
    // ARB_texture_rectangle is on in every shader too (glslang knows it; the preamble enables it).
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_ARB_draw_buffers\nGL_ARB_texture_rectangle").has_value());
    CHECK(reason("GLSL >= 1.10\n!GL_ARB_texture_rectangle").value() ==
          "requires GL_ARB_texture_rectangle to be absent");
    CHECK(reason("GLSL >= 1.10\nGL_ARB_texture_multisample").value() ==
          "extension GL_ARB_texture_multisample is not supported");
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_EXT_texture_array").has_value());  // EXT_texture_array is supported
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_MAX_VARYING_COMPONENTS >= 64").has_value());
    CHECK(reason("GLSL >= 1.10\nGL_MAX_VARYING_COMPONENTS >= 65").has_value());
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_MAX_FRAGMENT_UNIFORM_COMPONENTS >= 4097").has_value());
    CHECK_FALSE(reason("GLSL >= 1.10\nGL_MAX_VERTEX_UNIFORM_COMPONENTS >= 516").has_value());
    CHECK_FALSE(reason("GLSL >= 1.10\nrlimit 268435456\ndepthbuffer\n*/").has_value());
    CHECK(reason("GLSL >= 1.10\nGL_MAX_FOO >= 1").value() == "unknown limit GL_MAX_FOO");
}

TEST_CASE("SIZE changes the window", "[piglit][parse]") {
    ShaderTest t = parse_ok("[require]\nGLSL >= 1.10\nSIZE 20 30\n[test]\n");
    CHECK(t.require.width == 20);
    CHECK(t.require.height == 30);
}

TEST_CASE("GL 3 texture commands and unsupported sections skip", "[piglit][parse]") {
    ShaderTest t = parse_ok("[require]\nGLSL >= 1.10\n[test]\ntexture rgbw 0 (8, 8)\n"
                            "texparameter 2D compare_func greater\ndraw rect -1 -1 2 2\n");
    CHECK_FALSE(skip_reason(t).has_value());
    ShaderTest a = parse_ok("[require]\nGLSL >= 1.10\n[test]\ntexparameter CubeArray min nearest\n");
    CHECK(skip_reason(a).value() == "texparameter CubeArray needs GL 4 or extensions");
    // EXT_texture_array's textures are supported.
    CHECK_FALSE(skip_reason(parse_ok("[require]\nGLSL >= 1.10\n[test]\ntexture rgbw 2DArray 0 (8, 8, 2)\n"
                                     "texparameter 2DArray min linear\n")).has_value());
    ShaderTest g = parse_ok("[require]\nGLSL >= 1.10\n[geometry shader]\nvoid main(){}\n[test]\n");
    CHECK(skip_reason(g).value() == "unsupported section [geometry shader]");
    ShaderTest u = parse_ok("[require]\nGLSL >= 1.10\n[test]\nuniform dvec2 x 3 4\n");
    CHECK(skip_reason(u).value() == "uniform type dvec2 needs GL 4");
}

TEST_CASE("vertex data", "[piglit][parse]") {
    ShaderTest t = parse_ok(
        "[require]\nGLSL >= 1.10\n[vertex data]\n"
        "vertex/float/3  input_data/float/4\n"
        "-1.0 -1.0 -1.0  1.0 0.0 0.0 1.0 # comment\n"
        "\n"
        " 0.0  2.0 -2.0  0.0 1.0 0.0 1.0\n"
        " 3.0 -3.0 -3.0  0.0 0.0 1.0 1.0\n"
        "[test]\ndraw arrays GL_TRIANGLES 0 3\n");
    REQUIRE(t.vertex_data.has_value());
    const VertexData& vd = *t.vertex_data;
    REQUIRE(vd.columns.size() == 2);
    CHECK(vd.columns[0].name == "vertex");
    CHECK(vd.columns[0].components == 3);
    CHECK(vd.columns[1].name == "input_data");
    CHECK(vd.columns[1].components == 4);
    CHECK(vd.rows == 3);
    CHECK(vd.per_column[0] == std::vector<float>{-1, -1, -1, 0, 2, -2, 3, -3, -3});
    CHECK(vd.per_column[1] == std::vector<float>{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1});
    auto& d = std::get<DrawArrays>(t.commands.at(0).data);
    CHECK(d.mode == "GL_TRIANGLES");
    CHECK(d.first == 0);
    CHECK(d.count == 3);
}

TEST_CASE("malformed files give line-numbered errors", "[piglit][parse][malformed]") {
    CHECK(parse_err("[vertex shader]\nvoid main(){}\n").message == "[require] section missing");
    ParseError e = parse_err("[require]\nGLSL >= 1.10\n[test]\ndraw rect -1 -1\n");
    CHECK(e.line == 4);
    CHECK(e.str() == "line 4: bad draw command \"draw rect -1 -1\"");
    e = parse_err("[require]\nGLSL >= 1.10\n[test]\nclear\nfrobnicate 3\n");
    CHECK(e.line == 5);
    CHECK(e.message == "unknown command \"frobnicate 3\"");
    e = parse_err("[require]\nGLSL < 1.10\n");
    CHECK(e.line == 2);
    e = parse_err("[require]\nGLSL >= one\n");
    CHECK(e.line == 2);
    e = parse_err("[require]\nGLSL >= 1.10\n[bogus section]\n");
    CHECK(e.message == "unknown section [bogus section]");
    e = parse_err("[require]\nGLSL >= 1.10\n[vertex data]\nvertex/float/3\n1 2\n");
    CHECK(e.line == 5);
    e = parse_err("[require]\nGLSL >= 1.10\n[vertex data]\nvertex/float\n");
    CHECK(e.line == 4);
    e = parse_err("[require]\nGLSL >= 1.10\n[vertex data]\nvertex/float/9\n");
    CHECK(e.line == 4);
    e = parse_err("[require]\nGLSL >= 1.10\n[test]\nuniform vec4 c\n");
    CHECK(e.message == "uniform vec4 c needs 4 values, found none");
    e = parse_err("[require]\nGLSL >= 1.10\n[test]\nuniform vec5 c 1 2 3 4 5\n");
    CHECK(e.message == "unknown uniform type \"vec5\"");
    e = parse_err("[require]\nSIZE 0 0\n");
    CHECK(e.line == 2);
}

TEST_CASE("garbage never crashes the parser", "[piglit][parse][malformed]") {
    const std::string pieces[] = {"[require]\n", "GLSL >= 1.10\n", "[test]\n", "[vertex data]\n",
                                  "probe rgba (\n", "uniform\n", "uniform mat4x\n", "draw arrays\n",
                                  "\x01\xff\n", "probe rect rgb (1,2,3\n", "relative probe rgba (1,\n",
                                  "clip plane\n", "light\n", "light 9 GL_POSITION float 1\n", "a/b/c\n",
                                  "[fragment shader file]\n", "SIZE 5\n", "ortho 1 2\n", "]\n", ""};
    // Every ordered pair and triple of the pieces: must return, error or not.
    int parsed = 0;
    for (const auto& a : pieces)
        for (const auto& b : pieces)
            for (const auto& c : pieces) {
                auto p = parse_shader_test(a + b + c);
                parsed += parsed_ok(p) ? 1 : 0;
            }
    CHECK(parsed > 0);
}

TEST_CASE("number lists follow strtod/strtol and piglit's hex floats", "[piglit][parse]") {
    CHECK(parse_float_list("1 -2.5 3e2") == std::vector<float>{1, -2.5f, 300});
    CHECK(parse_float_list("1;") == std::vector<float>{1});
    CHECK(parse_float_list("0x3f800000 0xbf800000") == std::vector<float>{1.0f, -1.0f});
    CHECK(parse_float_list("  ").empty());
    CHECK(parse_int_list("-3 0x10 7") == std::vector<int32_t>{-3, 16, 7});
    size_t used = 0;
    CHECK(parse_int_list("4 5 x 6", &used) == std::vector<int32_t>{4, 5});
    CHECK(used == 3);
}

TEST_CASE("glslparsertest config blocks", "[piglit][parse]") {
    auto ok = [](std::string_view text) {
        auto p = parse_parser_test(text);
        if (!parsed_ok(p)) FAIL(std::get<ParseError>(p).str());
        return std::get<ParserTest>(p);
    };
    ParserTest a = ok("// [config]\n// expect_result: fail\n// glsl_version: 1.20\n"
                      "// require_extensions: GL_ARB_foo !GL_ARB_bar\n// [end config]\nvoid main(){}\n");
    CHECK_FALSE(a.expect_pass);
    CHECK(a.glsl_version == 120);
    CHECK(a.extensions == std::vector<std::string>{"GL_ARB_foo", "!GL_ARB_bar"});
    CHECK_FALSE(a.check_link);
    ParserTest b = ok("/* [config]\n * expect_result: pass\n * glsl_version: 1.10\n"
                      " * check_link: true\n * [end config]\n */\n");
    CHECK(b.expect_pass);
    CHECK(b.glsl_version == 110);
    CHECK(b.check_link);
    ParserTest es = ok("// [config]\n// expect_result: pass\n// glsl_version: 1.00\n// [end config]\n");
    CHECK(es.glsl_es);
    CHECK_FALSE(parsed_ok(parse_parser_test("void main(){}\n")));
    CHECK_FALSE(parsed_ok(parse_parser_test("// [config]\n// glsl_version: 1.10\n// [end config]\n")));
    CHECK_FALSE(parsed_ok(parse_parser_test("// [config]\n// expect_result: maybe\n")));
    CHECK_FALSE(parsed_ok(parse_parser_test("// [config]\n// expect_result: pass\n// glsl_version: 1.10\n")));
}

TEST_CASE("a version number too large for an int is malformed, not an overflow (fuzz_piglit)", "[piglit][parse]") {
    // UBSan: signed integer overflow in parse_version_number before the fix.
    auto p = parse_parser_test("// [config]\n// expect_result: fail\n// glsl_version: 1214748364.0\n// [end config]\n");
    REQUIRE_FALSE(parsed_ok(p));
    CHECK_FALSE(parsed_ok(parse_shader_test("[require]\nGLSL >= 2147483647.99\n")));
}
