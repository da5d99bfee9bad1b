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
