// shader_runner semantics end to end, through the real library.
#include <catch2/catch.hpp>

#include "tools/glslrun/piglit_exec.h"

using namespace glslrun::piglit;

namespace {

TestResult run(const std::string& text) { return run_shader_test(text, ".", RunOptions{}); }

const std::string kHeader = "[require]\nGLSL >= 1.10\n\n";

// A VS that passes gl_Vertex through the fixed-function matrices, and a FS
// that paints a uniform colour.
const std::string kUniformColor = kHeader + R"([vertex shader]
void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }

[fragment shader]
uniform vec4 color;
void main() { gl_FragColor = color; }
)";

}  // namespace

TEST_CASE("draw rect, uniforms and probes", "[piglit][exec]") {
    TestResult r = run(kUniformColor + R"([test]
clear color 0.0 0.0 1.0 1.0
clear
uniform vec4 color 0.0 1.0 0.0 1.0
draw rect -1 -1 1 2
probe rect rgba (0, 0, 125, 250) (0.0, 1.0, 0.0, 1.0)
probe rect rgba (125, 0, 125, 250) (0.0, 0.0, 1.0, 1.0)
relative probe rgb (0.25, 0.5) (0, 1, 0)
relative probe rgb (0.75, 0.5) (0, 0, 1)
probe rgba 124 10 0 1 0 1
probe rgba 125 10 0 0 1 1
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("a failing probe names its line, pixel and colours", "[piglit][exec]") {
    TestResult r = run(kUniformColor + R"([test]
uniform vec4 color 1.0 0.0 0.0 1.0
draw rect -1 -1 2 2
probe all rgb 1 0 0
probe rgb 3 4 0 1 0
)");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "line 14: probe rgb at (3, 4): expected (0, 1, 0), observed (1, 0, 0)");
}

TEST_CASE("probe tolerance is piglit's 3/256, after 8-bit quantisation", "[piglit][exec]") {
    // 0.5 is stored as 128/255 = 0.50196; expected values within 3/256 pass.
    std::string body = kUniformColor + "[test]\nuniform vec4 color 0.5 0.5 0.5 0.5\ndraw rect -1 -1 2 2\n";
    CHECK(run(body + "probe all rgba 0.5 0.5 0.5 0.5\n").outcome == Outcome::Pass);
    CHECK(run(body + "probe all rgba 0.491 0.5 0.5 0.5\n").outcome == Outcome::Pass);
    CHECK(run(body + "probe all rgba 0.5 0.5 0.5 0.485\n").outcome == Outcome::Fail);
    CHECK(run(body + "tolerance 0.1 0.1 0.1 0.1\nprobe all rgba 0.45 0.5 0.5 0.5\n").outcome == Outcome::Pass);
    TestResult warn = run(body + "probe warn all rgba 0 0 0 0\n");
    CHECK(warn.outcome == Outcome::Pass);
    CHECK(warn.message.rfind("warn: line 13: probe rgba at (0, 0)", 0) == 0);
}

TEST_CASE("ortho, draw rect ortho and the passthrough VS", "[piglit][exec]") {
    TestResult r = run(kUniformColor + R"([test]
ortho
uniform vec4 color 1 1 0 1
draw rect 10 20 30 40
probe rect rgb (10, 20, 30, 40) (1, 1, 0)
probe rgb 9 20 0 0 0
probe rgb 40 20 0 0 0
probe rgb 10 60 0 0 0
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
    r = run(kHeader + R"([vertex shader passthrough]
[fragment shader]
void main() { gl_FragColor = vec4(gl_FragCoord.x < 50.0 ? 1.0 : 0.0, 0.0, 0.0, 1.0); }
[test]
draw rect ortho 0 0 100 250
probe rect rgb (0, 0, 50, 250) (1, 0, 0)
probe rect rgb (50, 0, 50, 250) (0, 0, 0)
probe rect rgb (100, 0, 150, 250) (0, 0, 0)
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("implicit #version 1.20 makes 1.20 features compile", "[piglit][exec]") {
    std::string test = R"([require]
GLSL >= 1.20
[vertex shader passthrough]
[fragment shader]
void main() {
    float a[2] = float[](0.25, 0.75);  // array constructors need 1.20
    mat2x3 m = mat2x3(1.0);
    gl_FragColor = vec4(a[0], a[1], m[1][1], 1.0);
}
[test]
draw rect -1 -1 2 2
probe all rgba 0.25 0.75 1.0 1.0
)";
    TestResult r = run(test);
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("link error expectations", "[piglit][exec]") {
    std::string unresolved = kHeader + R"([vertex shader passthrough]
[fragment shader]
void helper();
void main() { helper(); gl_FragColor = vec4(1.0); }
)";
    CHECK(run(unresolved + "[test]\nlink error\n").outcome == Outcome::Pass);
    TestResult r = run(unresolved + "[test]\ndraw rect -1 -1 2 2\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.rfind("line 9: failed to link", 0) == 0);
    r = run(kUniformColor + "[test]\nlink error\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "line 11: shader link error expected, but it was successful");
    // A compile error fails the test even when a link error is expected.
    r = run(kHeader + "[fragment shader]\nvoid main() { gl_FragColor = undeclared; }\n[test]\nlink error\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.rfind("failed to compile [fragment shader]", 0) == 0);
}

TEST_CASE("vertex data, draw arrays, flat shading", "[piglit][exec]") {
    TestResult r = run(kHeader + R"([vertex shader]
attribute vec4 vertex;
attribute vec4 c;
void main() { gl_Position = vertex; gl_FrontColor = c; }
[fragment shader]
void main() { gl_FragColor = gl_Color; }
[vertex data]
vertex/float/2  c/float/3
-1 -1   1 0 0
 1 -1   0 1 0
 1  1   0 0 1
-1  1   1 1 0
[test]
shade model flat
draw arrays GL_TRIANGLE_FAN 0 4
probe rgb 200 50 0 0 1
probe rgb 50 200 1 1 0
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
    r = run(kHeader + "[vertex shader passthrough]\n[fragment shader]\nvoid main(){gl_FragColor=vec4(1.0);}\n"
                      "[vertex data]\npiglit_vertex/float/2\n0 0\n[test]\ndraw arrays GL_TRIANGLES 0 3\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "line 11: draw arrays cannot draw beyond 1");
}

TEST_CASE("runner problems are failures or skips, never crashes", "[piglit][exec]") {
    CHECK(run("garbage").outcome == Outcome::Fail);
    CHECK(run(kUniformColor + "[test]\nuniform vec4 nosuch 1 2 3 4\n").message.rfind("line 11: uniform nosuch", 0) == 0);
    CHECK(run(kUniformColor + "[test]\nprobe rgb 300 0 0 0 0\n").message ==
          "line 11: probe region (300, 0) is outside the 250x250 window");
    // Past int's range: cast to int, the width wrapped negative and no pixel was probed (a pass).
    CHECK(run(kUniformColor + "[test]\nprobe rect rgb (0, 0, 3e9, 10) (9, 9, 9)\n").message ==
          "line 11: probe region (0, 0, 3000000000, 10) is outside the 250x250 window");
    CHECK(run(kUniformColor + "[test]\nrelative probe rect rgb (0, 0, 1e30, 0.5) (9, 9, 9)\n").outcome ==
          Outcome::Fail);
    CHECK(run(kUniformColor + "[test]\nenable GL_FOG\n").message == "line 11: bad enable/disable enum \"GL_FOG\"");
    CHECK(run(kUniformColor + "[test]\ntexparameter 2D swizzle_r green\n").outcome == Outcome::Skip);
    CHECK(run("[require]\nGLSL >= 1.30\n[test]\n").outcome == Outcome::Skip);
    // No [test] section: compiling (and even failing to link) passes, as in shader_runner.
    CHECK(run(kUniformColor).outcome == Outcome::Pass);
    TestResult missing = run_test_file("/nonexistent/x.shader_test", RunOptions{});
    CHECK(missing.outcome == Outcome::Fail);
    CHECK(missing.message == "cannot open test file: no such file");
}

TEST_CASE("glslparsertest files", "[piglit][exec]") {
    RunOptions o;
    auto parser = [&](const std::string& ext, const std::string& expect, const std::string& version,
                      const std::string& body) {
        return run_parser_test("// [config]\n// expect_result: " + expect + "\n// glsl_version: " + version +
                                   "\n// [end config]\n" + body,
                               ext, "t" + ext, o);
    };
    CHECK(parser(".frag", "pass", "1.10", "void main() { gl_FragColor = vec4(1.0); }\n").outcome == Outcome::Pass);
    CHECK(parser(".vert", "fail", "1.10", "void main() { gl_Position = nope; }\n").outcome == Outcome::Pass);
    TestResult r = parser(".vert", "pass", "1.10", "void main() { gl_Position = nope; }\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.rfind("failed to compile: t.vert:5: error:", 0) == 0);
    r = parser(".frag", "fail", "1.10", "void main() { gl_FragColor = vec4(1.0); }\n");
    CHECK(r.message == "compiled, but failure was expected");
    CHECK(parser(".frag", "pass", "1.30", "void main() {}\n").outcome == Outcome::Skip);
    CHECK(parser(".geom", "pass", "1.50", "void main() {}\n").outcome == Outcome::Skip);
}

TEST_CASE("depthfunc changes the depth test of later draws", "[piglit][exec]") {
    // Every rect lands at window depth 0.5; the depth buffer starts at 0.
    std::string test = kUniformColor + R"([test]
clear color 0.0 0.0 0.0 1.0
clear depth 0.0
clear
enable GL_DEPTH_TEST
uniform vec4 color 1.0 0.0 0.0 1.0
draw rect -1 -1 2 2
probe all rgba 0.0 0.0 0.0 1.0
depthfunc GL_GREATER
uniform vec4 color 0.0 1.0 0.0 1.0
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
depthfunc GL_LESS
uniform vec4 color 0.0 0.0 1.0 1.0
draw rect -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
depthfunc GL_EQUAL
draw rect -1 -1 2 2
probe all rgba 0.0 0.0 1.0 1.0
depthfunc GL_NEVER
uniform vec4 color 1.0 0.0 0.0 1.0
draw rect -1 -1 2 2
probe all rgba 0.0 0.0 1.0 1.0
)";
    TestResult r = run(test);
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}
