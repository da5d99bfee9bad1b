// The whole pass pipeline against the frontend's unoptimized IR, on every
// shader of shaders/ and tests/ir/golden/: the optimized shader must verify
// and compute the same output bits on every lane, for varied inputs and
// uniforms (fusion, hoisting and register allocation included).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/compile.h"
#include "ir/passes.h"
#include "tests/ir/pass_helpers.h"

namespace fs = std::filesystem;
using namespace glslrun;
using namespace glslrun::test;

namespace {

std::vector<uint32_t> uniform_store(const ir::Program& p) {
    std::vector<uint32_t> words(std::max<uint32_t>(p.uniform_words, 1), 0);
    for (const ir::Uniform& u : p.uniforms)
        for (uint32_t w = 0; w < u.type.components() * u.array_size && u.slot + w < words.size(); ++w)
            words[u.slot + w] = input_value(u.type.kind, u.slot + w, 0);
    return words;
}

}  // namespace

TEST_CASE("optimized shaders compute the unoptimized shaders' bits", "[ir][pipeline]") {
    // Each shader with its sibling of the other stage, or a trivial one.
    const ShaderSource vs{"pass.vert", "void main() { gl_Position = ftransform(); }\n"};
    const ShaderSource fsrc{"pass.frag", "void main() { gl_FragColor = vec4(1.0); }\n"};
    int shaders = 0;
    for (const char* dir : {"shaders", "tests/ir/golden"}) {
        for (const auto& entry : fs::directory_iterator(fs::path(GLSLRUN_SOURCE_DIR) / dir)) {
            const fs::path p = entry.path();
            const bool vertex = p.extension() == ".vert";
            if (!vertex && p.extension() != ".frag") continue;
            ShaderSource src{p.filename().string(), read_file(p)}, other = vertex ? fsrc : vs;
            fs::path sibling = fs::path(p).replace_extension(vertex ? ".frag" : ".vert");
            if (fs::exists(sibling)) other = ShaderSource{sibling.filename().string(), read_file(sibling)};
            auto program = frontend::compile_program({vertex ? src : other}, {vertex ? other : src}, CompileOptions{});
            if (!program) continue;  // deliberately broken lecture shaders
            const ir::Shader& original = vertex ? program->vertex : program->fragment;
            ir::Shader optimized = original;
            INFO(p.filename().string() << "\n" << ir::print(optimized));
            REQUIRE(ir::optimize(optimized, {}) == "");
            REQUIRE(ir::verify(optimized) == "");
            std::vector<uint32_t> uniforms = uniform_store(*program);
            CHECK(run_outputs(original, uniforms) == run_outputs(optimized, uniforms));
            ++shaders;
        }
    }
    CHECK(shaders >= 25);
}
