// Shared by the scene parser's tests: parse TOML text, compare GL values.
#pragma once
#include <array>
#include <string>
#include <string_view>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "glslrun/scene/scene.h"

namespace scene_test {

using glslrun::scene::Scene;

inline Scene parse_ok(std::string_view text) {
    auto r = glslrun::scene::parse_scene(text, "scene.toml");
    INFO((r ? std::string() : r.error().str()));
    REQUIRE(r);
    return std::move(*r);
}

// The first diagnostic of a scene that must not parse.
inline glslrun::Diagnostic parse_error(std::string_view text) {
    auto r = glslrun::scene::parse_scene(text, "scene.toml");
    REQUIRE_FALSE(r);
    REQUIRE_FALSE(r.error().diagnostics.empty());
    return r.error().diagnostics[0];
}

// The error names the file and the line, and says what is wrong.
inline void check_error(std::string_view text, int line, const std::string& message) {
    glslrun::Diagnostic d = parse_error(text);
    INFO(d.str());
    CHECK(d.file == "scene.toml");
    CHECK(d.line == line);
    CHECK_THAT(d.message, Catch::Contains(message));
}

inline void check_vec(const glm::vec4& v, const std::array<double, 4>& want, double eps = 1e-6) {
    for (int i = 0; i < 4; ++i) {
        INFO("component " << i);
        CHECK(v[i] == Approx(want[size_t(i)]).margin(eps));
    }
}

inline void check_vec(const glm::vec3& v, const std::array<double, 3>& want, double eps = 1e-6) {
    for (int i = 0; i < 3; ++i) {
        INFO("component " << i);
        CHECK(v[i] == Approx(want[size_t(i)]).margin(eps));
    }
}

// `want` is column-major, as glGetFloatv(GL_PROJECTION_MATRIX) returns it.
inline void check_matrix(const glm::mat4& m, const std::array<double, 16>& want, double eps = 1e-6) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            INFO("column " << c << " row " << r);
            CHECK(m[c][r] == Approx(want[size_t(c * 4 + r)]).margin(eps));
        }
}

}  // namespace scene_test
