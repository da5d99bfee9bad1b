// Golden IR tests: every tests/ir/golden/<case>.vert|.frag is compiled (with
// a trivial other stage) and its printed IR compared with <case>.ir; the
// cases of tests/ir/golden_optimized/ go through the pass pipeline first.
// GLSLRUN_UPDATE_GOLDEN=1 rewrites the expectations instead.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/compile.h"
#include "ir/passes.h"
#include "tests/ir/pass_helpers.h"

namespace fs = std::filesystem;
using namespace glslrun;
using glslrun::test::read_file;

namespace {

// The printed IR of `shader` (with its sibling of the other stage, or a
// trivial one), after the pass pipeline when `optimized`.
std::string golden_ir(const fs::path& shader, bool optimized) {
    bool vertex = shader.extension() == ".vert";
    ShaderSource src{shader.filename().string(), read_file(shader)};
    ShaderSource vs{"pass.vert", "void main() { gl_Position = ftransform(); }\n"};
    ShaderSource fsrc{"pass.frag", "void main() { gl_FragColor = vec4(1.0); }\n"};
    fs::path sibling = fs::path(shader).replace_extension(vertex ? ".frag" : ".vert");
    if (fs::exists(sibling)) (vertex ? fsrc : vs) = ShaderSource{sibling.filename().string(), read_file(sibling)};
    auto r = frontend::compile_program({vertex ? src : vs}, {vertex ? fsrc : src}, CompileOptions{});
    if (!r) return "compile error:\n" + r.error().str();
    ir::Shader s = vertex ? r->vertex : r->fragment;
    if (optimized) {
        std::string error = ir::optimize(s, {});
        if (!error.empty()) return "verify: " + error + "\n";
    }
    std::string v = ir::verify(s);
    return (v.empty() ? "" : "verify: " + v + "\n") + ir::print(s);
}

// Compares every <case>.vert|.frag of `dir` with <case>.ir; `min_cases` guards
// against a directory that lost its files.
void check_goldens(const char* dir_name, bool optimized, int min_cases) {
    fs::path dir = fs::path(GLSLRUN_SOURCE_DIR) / dir_name;
    const char* update_env = std::getenv("GLSLRUN_UPDATE_GOLDEN");
    bool update = update_env && std::string(update_env) == "1";
    int cases = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        fs::path p = entry.path();
        if (p.extension() != ".vert" && p.extension() != ".frag") continue;
        ++cases;
        fs::path expected = p;
        expected += ".ir";
        std::string actual = golden_ir(p, optimized);
        SECTION(p.filename().string()) {
            if (update) {
                std::ofstream(expected) << actual;
            } else {
                INFO("expectation: " << expected.string() << " (GLSLRUN_UPDATE_GOLDEN=1 rewrites it)");
                REQUIRE(fs::exists(expected));
                CHECK(actual == read_file(expected));
                CHECK_THAT(actual, !Catch::StartsWith("compile error") && !Catch::StartsWith("verify:"));
            }
        }
    }
    CHECK(cases >= min_cases);
}

}  // namespace

TEST_CASE("golden IR of the frontend") { check_goldens("tests/ir/golden", false, 9); }

// The pass pipeline's output (fuse_mad, hoist, dead_stores, regalloc): a
// change in what the passes do shows up as a diff here.
TEST_CASE("golden IR after the pass pipeline") { check_goldens("tests/ir/golden_optimized", true, 5); }
