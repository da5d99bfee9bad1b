// Source positions (ir::SourceLoc) through the frontend and the passes: an
// inlined call keeps its callee's lines, a hoisted instruction its own, a
// second source of a stage its source index; ir::Shader::variables names the
// variables' registers until regalloc.
#include <catch2/catch.hpp>

#include <set>

#include "frontend/compile.h"
#include "ir/flow.h"
#include "ir/passes.h"

using namespace glslrun;

namespace {

const ShaderSource kVertex{"pass.vert", "void main() { gl_Position = ftransform(); }\n"};

ir::Shader fragment(const std::vector<ShaderSource>& sources) {
    auto r = frontend::compile_program({kVertex}, sources, CompileOptions{});
    REQUIRE(r);
    return r->fragment;
}

// The lines of every instruction writing an `op` result.
std::set<int> lines_of(const ir::Block& block, ir::Op op) {
    std::set<int> lines;
    ir::flow::walk(block, [&](const ir::Node& n) {
        if (n.kind == ir::NodeKind::Instr && n.instr.op == op) lines.insert(n.loc.line);
    });
    return lines;
}

}  // namespace

TEST_CASE("inlined calls keep the callee's lines, hoisted code its own", "[ir][loc]") {
    ir::Shader s = fragment({{"f.frag",
                              "uniform float k;\n"                                     // 1
                              "// the multiply below is twice's\n"                     // 2
                              "float twice(float x) {\n"                               // 3
                              "    return x * 2.0;\n"                                  // 4
                              "}\n"                                                    // 5
                              "void main() {\n"                                        // 6
                              "    float u = k + 1.0;\n"                               // 7
                              "    gl_FragColor = vec4(twice(gl_FragCoord.x) / u);\n"  // 8
                              "}\n"}});
    REQUIRE(s.sources == std::vector<std::string>{"f.frag"});
    REQUIRE_FALSE(s.variables.empty());
    bool named_u = false;
    for (const ir::Variable& v : s.variables)
        named_u = named_u || (v.name == "u" && v.function == "main" && v.count == 1);
    CHECK(named_u);
    REQUIRE(ir::optimize(s, {}).empty());
    CHECK(lines_of(s.body, ir::Op::fmul) == std::set<int>{4});      // twice's multiply, inlined into main
    CHECK(lines_of(s.prologue, ir::Op::fadd) == std::set<int>{7});  // k + 1.0, hoisted
    CHECK(lines_of(s.body, ir::Op::fdiv) == std::set<int>{8});
    CHECK(s.variables.empty());  // regalloc renumbered the registers
}

TEST_CASE("a stage's second source has its own index and columns are kept", "[ir][loc]") {
    ir::Shader s = fragment({{"main.frag",
                              "vec4 colour();\n"
                              "void main() { gl_FragColor = colour(); }\n"},
                             {"lib.frag",
                              "uniform vec4 c;\n"
                              "vec4 colour() {\n"
                              "    return c * 0.5;\n"
                              "}\n"}});
    REQUIRE(s.sources == std::vector<std::string>{"main.frag", "lib.frag"});
    bool found = false;
    for (const ir::Function& f : s.functions)
        ir::flow::walk(f.body, [&](const ir::Node& n) {
            if (n.kind != ir::NodeKind::Instr || n.instr.op != ir::Op::fmul) return;
            found = true;
            CHECK(n.loc.source == 1);
            CHECK(n.loc.line == 3);
            CHECK(n.loc.column > 0);
        });
    CHECK(found);
    std::string printed = ir::print(s);
    CHECK(printed.find("source s1 lib.frag") != std::string::npos);
    CHECK(printed.find("; s1:3:") != std::string::npos);
}
