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
