// Shared helpers of the frontend tests: compile, verify, evaluate one lane.
#pragma once
#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "frontend/compile.h"
#include "ir/passes.h"
#include "mini_eval.h"

namespace glslrun::test {

inline const char* kPassVs = "void main() { gl_Position = ftransform(); }\n";

inline Result<ir::Program> compile(const std::string& vs, const std::string& fs, int version = 110) {
    CompileOptions opt;
    opt.default_version = version;
    std::vector<ShaderSource> v, f;
    if (!vs.empty()) v.push_back({"t.vert", vs});
    if (!fs.empty()) f.push_back({"t.frag", fs});
    return frontend::compile_program(v, f, opt);
}

inline ir::Program compile_ok(const std::string& vs, const std::string& fs, int version = 110) {
    auto r = compile(vs, fs, version);
    INFO((r ? std::string() : r.error().str()));
    REQUIRE(r.ok());
    CHECK(ir::verify(r->vertex) == "");
    CHECK(ir::verify(r->fragment) == "");
    return std::move(r.value());
}

inline std::string compile_error(const std::string& vs, const std::string& fs, int version = 110) {
    auto r = compile(vs, fs, version);
    REQUIRE_FALSE(r.ok());
    return r.error().str();
}

inline uint32_t bits(float f) {
    uint32_t b;
    std::memcpy(&b, &f, 4);
    return b;
}

// Uniform values by GL name ("u", "a[2]", "s.f"); ints for int/bool/sampler leaves.
inline std::vector<uint32_t> uniform_store(const ir::Program& p, const std::map<std::string, std::vector<float>>& values) {
    std::vector<uint32_t> store(p.uniform_words, 0);
    for (const auto& [name, v] : values) {
        uint32_t element = 0;
        const ir::Uniform* u = ir::find_uniform(p, name, &element);
        REQUIRE(u != nullptr);
        uint32_t slot = u->slot + element * u->type.components();
        for (size_t i = 0; i < v.size(); ++i)
            store.at(slot + i) = u->type.kind == ir::Kind::F32 ? bits(v[i]) : uint32_t(int32_t(v[i]));
    }
    return store;
}

// Runs the fragment shader once; returns gl_FragColor.
inline std::vector<float> run_fs(const ir::Program& p, const std::map<std::string, std::vector<float>>& uniforms = {},
                                 const std::map<std::string, std::vector<float>>& inputs = {}) {
    MiniEval ev(p.fragment, uniform_store(p, uniforms));
    for (const auto& [name, v] : inputs) ev.set_input(name, v);
    ev.run();
    return ev.output("gl_FragColor");
}

inline std::vector<float> eval_fs(const std::string& fs, const std::map<std::string, std::vector<float>>& uniforms = {},
                                  int version = 110) {
    ir::Program p = compile_ok(kPassVs, fs, version);
    return run_fs(p, uniforms);
}

inline bool near(const std::vector<float>& a, const std::vector<float>& b, float eps = 1e-5f) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!(std::abs(a[i] - b[i]) <= eps * std::max(1.0f, std::abs(b[i])))) return false;
    return true;
}

}  // namespace glslrun::test
