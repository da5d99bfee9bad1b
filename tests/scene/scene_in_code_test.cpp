// A Scene built in code rather than parsed: its defaults are GL's, the
// matrices and lights have one source each (view, projection, lights), and
// a copy in scene.gl that disagrees is refused, never silently ignored.
#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "glslrun/scene/meshes.h"
#include "glslrun/scene/render.h"
#include "parse_helpers.h"

using namespace scene_test;
namespace gs = glslrun::scene;

namespace {

const char* kVertex = "void main() { gl_FrontColor = gl_LightSource[0].diffuse; gl_Position = ftransform(); }";
const char* kFragment = "void main() { gl_FragColor = gl_Color; }";

glslrun::Program program() {
    auto p = glslrun::Program::compile({{"a.vert", kVertex}}, {{"a.frag", kFragment}});
    REQUIRE(p);
    return std::move(*p);
}

Scene quad_scene() {
    Scene s;
    gs::Object quad;
    quad.mesh = gs::make_plane(1.0, 1);
    s.objects.push_back(std::move(quad));
    REQUIRE(gs::resize_scene(s, 8, 8));
    return s;
}

}  // namespace

TEST_CASE("a Scene built in code starts with GL's lights", "[scene][code]") {
    Scene s;
    const glslrun::GLState defaults;
    std::array<glslrun::LightState, 8> eye = gs::eye_space_lights(s);
    check_vec(eye[0].diffuse, {1, 1, 1, 1});  // light 0's special default, not black
    check_vec(eye[1].diffuse, {0, 0, 0, 1});
    // A view moves only what was given: the default position stays GL's eye-space one.
    s.view = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5));
    check_vec(gs::eye_space_lights(s)[0].position, {0, 0, 1, 0});
    // A position set in code counts as given, even without has_position.
    s.lights[0].as_given.position = {1, 0, 0, 1};
    check_vec(gs::eye_space_lights(s)[0].position, {1, 0, -5, 1});
    s.lights[0].world_space = false;
    check_vec(gs::eye_space_lights(s)[0].position, {1, 0, 0, 1});
    CHECK(s.gl.lights[0].diffuse == defaults.lights[0].diffuse);
}

TEST_CASE("rendering takes the projection and the lights from their one source", "[scene][code]") {
    glslrun::Program p = program();
    Scene s = quad_scene();
    auto white = gs::render_image(p, s);
    REQUIRE(white);
    CHECK(white->rgba[4 * (4 * 8 + 4)] == 255);  // light 0's default white diffuse, not black

    s.lights[0].as_given.diffuse = {0, 1, 0, 1};  // no derive_eye_space_lights() needed
    auto green = gs::render_image(p, s);
    REQUIRE(green);
    CHECK(green->rgba[4 * (4 * 8 + 4)] == 0);
    CHECK(green->rgba[4 * (4 * 8 + 4) + 1] == 255);

    // A projection that pushes the plane out of the view: the image is cleared only.
    s.projection = glm::ortho(5.0f, 6.0f, 5.0f, 6.0f, -1.0f, 1.0f);
    auto away = gs::render_image(p, s);
    REQUIRE(away);
    CHECK(away->rgba[4 * (4 * 8 + 4) + 1] == 0);
}

TEST_CASE("a copy in scene.gl that disagrees with its source is an error", "[scene][code]") {
    glslrun::Program p = program();
    Scene s = quad_scene();
    SECTION("projection") {
        s.gl.projection = glm::ortho(5.0f, 6.0f, 5.0f, 6.0f, -1.0f, 1.0f);
        auto r = gs::render_image(p, s);
        REQUIRE_FALSE(r);
        CHECK_THAT(r.error().str(), Catch::Contains("scene.gl.projection differs from scene.projection"));
        s.projection = s.gl.projection;  // the source set too: fine
        CHECK(gs::render_image(p, s));
    }
    SECTION("lights") {
        s.gl.lights[0].diffuse = {1, 0, 0, 1};
        auto r = gs::render_image(p, s);
        REQUIRE_FALSE(r);
        CHECK_THAT(r.error().str(), Catch::Contains("scene.gl.lights[0] differs from scene.lights[0]"));
    }
    SECTION("modelview") {
        s.gl.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5));
        REQUIRE_FALSE(gs::render_image(p, s));
        s.view = s.gl.modelview;
        CHECK(gs::render_image(p, s));
    }
    SECTION("derive_eye_space_lights makes the copies agree") {
        s.view = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -1));
        s.lights[2].as_given.position = {0, 1, 0, 1};
        gs::derive_eye_space_lights(s);
        check_vec(s.gl.lights[2].position, {0, 1, -1, 1});
        CHECK(gs::render_image(p, s));
    }
}
