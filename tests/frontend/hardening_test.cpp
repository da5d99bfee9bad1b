// Issue #17's reproducers: hostile or huge input must end in an Error value,
// quickly and without recursion as deep as the input is long.
#include "frontend/source_rewrite.h"
#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

TEST_CASE("hardening: #error with a 2500-byte line of 0xFF is a diagnostic, not a stack overflow") {
    std::string fs = "#error " + std::string(2500, '\xff') + "\nvoid main() { gl_FragColor = vec4(1.0); }\n";
    std::string e = compile_error(kPassVs, fs);
    CHECK(e.find("t.frag:1: error:") != std::string::npos);
}

TEST_CASE("hardening: #ifdef followed by 30000 blanks is rewritten without a regex") {
    std::string fs = "#ifdef" + std::string(30000, ' ') + "__LINE__\n#endif\n"
                     "#if defined" + std::string(30000, ' ') + "__FILE__\n#endif\n"
                     "#define F(x)" + std::string(30000, ' ') + "x\n"
                     "void main() { gl_FragColor = vec4(1.0); }\n";
    compile_ok(kPassVs, fs);
    CHECK(frontend::define_predefined_macros("#ifdef" + std::string(30000, ' ')).size() == 30006);
}

TEST_CASE("hardening: the predefined-macro rewrite keeps its shapes") {
    using frontend::define_predefined_macros;
    CHECK(define_predefined_macros("  # ifndef  __FILE__ x\n") == "  # if 0             x\n");
    CHECK(define_predefined_macros("#if defined ( __VERSION__ ) && defined __LINE__\n") ==
          "#if 1                       && 1               \n");
    CHECK(define_predefined_macros("#if defined(__LINE__X) || xdefined __LINE__ || defined__LINE__\n") ==
          "#if defined(__LINE__X) || xdefined __LINE__ || defined__LINE__\n");
    CHECK(define_predefined_macros("#ifdef __LINE__X\n") == "#ifdef __LINE__X\n");
}

TEST_CASE("hardening: #line with a negative number gives the file without a line") {
    std::string fs = "#line -5\nvoid main() { gl_FragColor = vec4(1.0) + undefined_name; }\n";
    std::string e = compile_error(kPassVs, fs);
    INFO(e);
    CHECK(e.find("t.frag: error:") != std::string::npos);
    CHECK(e.find(":-") == std::string::npos);
}

TEST_CASE("hardening: #line past INT_MAX gives the file without a line") {
    // glslang's line counter wraps to -2147483648; its location was printed raw.
    for (const char* line : {"#line 2147483647\n", "#line 2147483646\n\n\n"}) {
        std::string fs = std::string(line) + "void main() { gl_FragColor = vec4(1.0) + undefined_name; }\n";
        std::string e = compile_error(kPassVs, fs);
        INFO(e);
        CHECK(e.find("t.frag: error: 'undefined_name' : undeclared identifier") != std::string::npos);
        CHECK(e.find(":-") == std::string::npos);
    }
}

TEST_CASE("hardening: x+x+...+x nested 100000 deep compiles on the compile thread's deep stack") {
    // glslang's traversals recurse once per `+`: 8 MB of stack overflowed at ~50000.
    std::string sum = "x";
    for (int i = 0; i < 100000; ++i) sum += "+x";
    compile_ok(kPassVs, "uniform float x; void main() { gl_FragColor = vec4(" + sum + "); }\n");
}

TEST_CASE("hardening: the parser's depth limit and the source size limit are clear errors") {
    std::string deep = "void main() { float x = 1.0; x = " + std::string(20000, '(') + "x" + std::string(20000, ')') +
                       "; gl_FragColor = vec4(x); }\n";
    CHECK_THAT(compile_error(kPassVs, deep), Catch::Contains("nest too deeply for the parser"));
    std::string huge = "void main() { gl_FragColor = vec4(1.0); }\n" + std::string(2 << 20, ' ');
    CHECK_THAT(compile_error(kPassVs, huge), Catch::Contains("glslrun's limit is 1024 KiB per stage"));
    CHECK_FALSE(check_shader(Stage::Fragment, {"t.frag", huge}).ok());
}

// Each macro doubles the one before: a few hundred bytes that expand to 2^n
// tokens. A20 overflowed the compile thread's 512 MiB stack under ASan (found
// by a long fuzz_compile run's author, not by the fuzzer).
std::string doubling_macros(int n, const std::string& use) {
    std::string s = "#define A1 x+x\n";
    for (int i = 2; i <= n; ++i) s += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" +
                                      std::to_string(i - 1) + "\n";
    return s + "uniform float x;\n" + use + "void main() { gl_FragColor = vec4(A" + std::to_string(n) + "); }\n";
}

TEST_CASE("hardening: macros that expand exponentially stop at the token budget with a clear error") {
    compile_ok(kPassVs, doubling_macros(14, ""));  // 16384 terms: within the budget
    for (int n : {20, 40}) {
        INFO(n);
        CHECK_THAT(compile_error(kPassVs, doubling_macros(n, "")), Catch::Contains("t.frag: error: the source's macros "
                                                                                  "expand past glslrun's limit"));
    }
    // Expansions that never reach the parser: an argument expanded before it
    // is substituted (2^40 tokens), and an #if.
    std::string args = "#define F(a) a+a\n#define X ";
    for (int i = 0; i < 40; ++i) args += "F(";
    args += "x" + std::string(40, ')') + "\n";
    for (const std::string& fs : {args + "uniform float x;\nvoid main() { gl_FragColor = vec4(X); }\n",
                                  doubling_macros(40, "#if A40\n#endif\n")}) {
        CHECK_THAT(compile_error(kPassVs, fs), Catch::Contains("expand past glslrun's limit"));
        CHECK_FALSE(check_shader(Stage::Fragment, {"t.frag", fs}).ok());
    }
}
