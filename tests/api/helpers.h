// Shared helpers for the API tests.
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace api_test {

inline glslrun::Program compile(const std::string& vs, const std::string& fs) {
    auto p = glslrun::Program::compile({{"t.vert", vs}}, {{"t.frag", fs}});
    if (!p) FAIL(p.error().str());
    return std::move(p.value());
}

inline const glslrun::ShaderOutput& output(const std::vector<glslrun::ShaderOutput>& outs, const std::string& name) {
    for (const auto& o : outs)
        if (o.name == name) return o;
    FAIL("no output " << name);
    return outs.front();
}

inline const char* kPassFs = "void main() { gl_FragColor = vec4(1.0); }\n";

}  // namespace api_test
