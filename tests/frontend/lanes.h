// Running a compiled vertex shader over many lanes through the public API,
// with a per-lane float attribute `a`, for frontend tests whose result must
// differ from lane to lane (dynamic indices, loop trip counts).
#pragma once
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include <glslrun/glslrun.h>

namespace glslrun::test {

inline constexpr uint32_t kLaneCount = 37;  // full batches and a partial one

// gl_FrontColor of every lane (4 floats per lane) of `vs`, which reads
// `attribute float a;` = a_of(lane).
inline std::vector<float> front_color_lanes(const std::string& vs, const std::function<float(uint32_t)>& a_of,
                                            int version = 110) {
    CompileOptions opt;
    opt.default_version = version;
    auto prog = Program::compile({{"t.vert", vs}}, {}, opt);
    INFO((prog ? std::string() : prog.error().str()));
    REQUIRE(prog.ok());
    VertexAttrib a{"a", 1, {}};
    for (uint32_t lane = 0; lane < kLaneCount; ++lane) a.data.push_back(a_of(lane));
    auto outs = run_vertices(*prog, {a}, kLaneCount);
    INFO((outs ? std::string() : outs.error().str()));
    REQUIRE(outs.ok());
    for (const ShaderOutput& o : *outs)
        if (o.name == "gl_FrontColor") {
            REQUIRE(o.components == 4);
            return o.data;
        }
    FAIL("no gl_FrontColor output");
    return {};
}

}  // namespace glslrun::test
