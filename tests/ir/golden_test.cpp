// Golden IR tests: every tests/ir/golden/<case>.vert|.frag is compiled (with
// a trivial other stage) and its printed IR compared with <case>.ir.
// GLSLRUN_UPDATE_GOLDEN=1 rewrites the expectations instead.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/compile.h"
#include "ir/passes.h"

namespace fs = std::filesystem;
using namespace glslrun;

namespace {

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string golden_ir(const fs::path& shader) {
    bool vertex = shader.extension() == ".vert";
    ShaderSource src{shader.filename().string(), slurp(shader)};
    ShaderSource vs{"pass.vert", "void main() { gl_Position = ftransform(); }\n"};
    ShaderSource fsrc{"pass.frag", "void main() { gl_FragColor = vec4(1.0); }\n"};
    auto r = frontend::compile_program({vertex ? src : vs}, {vertex ? fsrc : src}, CompileOptions{});
    if (!r) return "compile error:\n" + r.error().str();
    const ir::Shader& s = vertex ? r->vertex : r->fragment;
    std::string v = ir::verify(s);
    return (v.empty() ? "" : "verify: " + v + "\n") + ir::print(s);
}

}  // namespace

TEST_CASE("golden IR of the frontend") {
    fs::path dir = fs::path(GLSLRUN_SOURCE_DIR) / "tests/ir/golden";
    const char* update_env = std::getenv("GLSLRUN_UPDATE_GOLDEN");
    bool update = update_env && std::string(update_env) == "1";
    int cases = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        fs::path p = entry.path();
        if (p.extension() != ".vert" && p.extension() != ".frag") continue;
        ++cases;
        fs::path expected = p;
        expected += ".ir";
        std::string actual = golden_ir(p);
        SECTION(p.filename().string()) {
            if (update) {
                std::ofstream(expected) << actual;
            } else {
                INFO("expectation: " << expected.string() << " (GLSLRUN_UPDATE_GOLDEN=1 rewrites it)");
                REQUIRE(fs::exists(expected));
                CHECK(actual == slurp(expected));
                CHECK_THAT(actual, !Catch::StartsWith("compile error") && !Catch::StartsWith("verify:"));
            }
        }
    }
    CHECK(cases >= 5);
}
