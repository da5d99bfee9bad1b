// The scene parser: defaults, camera, lights and the GL state, checked against
// values computed by hand from the GL/GLU definitions.
#include <cmath>

#include "parse_helpers.h"

using namespace scene_test;
using glslrun::GLState;
using glslrun::scene::Camera;
using glslrun::scene::resize_scene;

namespace {

const char* kLectureCamera = R"(
[camera]
look_at = { eye = [0, 0, 5], center = [0, 0, 0], up = [0, 1, 0] }
perspective = { fovy = 45, near = 1, far = 100 }
)";

}  // namespace

TEST_CASE("an empty scene is OpenGL's default state", "[scene][parse]") {
    Scene s = parse_ok("");
    CHECK(s.path == "scene.toml");
    CHECK(s.width == 512);
    CHECK(s.height == 512);
    check_vec(s.clear_color, {0, 0, 0, 0});
    CHECK(s.clear_depth == 1.0f);
    CHECK(s.view == glm::mat4(1.0f));
    CHECK(s.projection == glm::mat4(1.0f));
    CHECK(s.camera.kind == Camera::Kind::Matrix);
    CHECK(s.gl.modelview == glm::mat4(1.0f));
    CHECK(s.gl.projection == glm::mat4(1.0f));
    CHECK_FALSE(s.gl.depth_test);
    CHECK(s.gl.depth_func == GLState::DepthFunc::Less);
    CHECK_FALSE(s.gl.cull_face);
    CHECK(s.gl.front_ccw);
    CHECK_FALSE(s.gl.flat_shading);
    CHECK(s.gl.clip_plane_enabled == 0);
    check_vec(s.gl.light_model_ambient, {0.2, 0.2, 0.2, 1});
    check_vec(s.gl.front_material.diffuse, {0.8, 0.8, 0.8, 1});
    // GL_LIGHT0 is white, the others black; every position is (0,0,1,0) in eye space.
    check_vec(s.gl.lights[0].diffuse, {1, 1, 1, 1});
    check_vec(s.gl.lights[1].diffuse, {0, 0, 0, 1});
    for (const auto& l : s.gl.lights) check_vec(l.position, {0, 0, 1, 0});
    for (const auto& l : s.lights) CHECK_FALSE(l.enabled);
    CHECK(s.objects.empty());
    CHECK(s.uniforms.empty());
}

TEST_CASE("the lecture's camera: gluLookAt and gluPerspective", "[scene][parse]") {
    Scene s = parse_ok(kLectureCamera);
    // gluLookAt(0,0,5, 0,0,0, 0,1,0) is translate(0, 0, -5), exactly.
    CHECK(s.view == glm::mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1));
    // The notes' gl_ProjectionMatrix at 512x512: cot(22.5 deg), -(101/99), -(200/99).
    check_matrix(s.projection,
                 {2.414214, 0, 0, 0, 0, 2.414214, 0, 0, 0, 0, -1.020202, -1, 0, 0, -2.020202, 0});
    CHECK(s.projection[0][0] == Approx(1.0 / std::tan(M_PI / 8)).epsilon(1e-7));
    CHECK(s.gl.projection == s.projection);
    CHECK(s.gl.modelview == s.view);
    CHECK(s.camera.kind == Camera::Kind::Perspective);
    CHECK(s.camera.fovy == 45);
    CHECK(s.camera.aspect == 0);  // follows the size
    CHECK(s.camera.near == 1);
    CHECK(s.camera.far == 100);
}

TEST_CASE("gluLookAt from an oblique eye", "[scene][parse]") {
    Scene s = parse_ok(R"(
[camera]
look_at = { eye = [3, 4, 5], center = [0, 1, 0], up = [0, 1, 0] }
)");
    // f = (-3,-3,-5)/sqrt(43); s = f x up = (5,0,-3)/sqrt(34); u = s x f = (-9,34,-15)/sqrt(1462).
    // Rows: s, u, -f; translation (-s.eye, -u.eye, f.eye).
    double a = std::sqrt(34.0), b = std::sqrt(1462.0), c = std::sqrt(43.0);
    check_matrix(s.view, {5 / a, -9 / b, 3 / c, 0,
                          0, 34 / b, 3 / c, 0,
                          -3 / a, -15 / b, 5 / c, 0,
                          0, -34 / b, -46 / c, 1});
    check_vec(s.view * glm::vec4(3, 4, 5, 1), {0, 0, 0, 1}, 1e-5);
    check_vec(s.view * glm::vec4(0, 1, 0, 1), {0, 0, -c, 1}, 1e-5);
}

TEST_CASE("look_at keys default to the identity view", "[scene][parse]") {
    Scene s = parse_ok("[camera]\nlook_at = { eye = [0, 0, 2] }\n");
    CHECK(s.view == glm::mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -2, 1));
}

TEST_CASE("glOrtho, glFrustum and explicit matrices", "[scene][parse]") {
    SECTION("ortho") {
        Scene s = parse_ok("[camera]\northo = { left = -2, right = 2, bottom = -1, top = 1, near = 0.5, far = 10 }\n");
        CHECK(s.camera.kind == Camera::Kind::Ortho);
        check_matrix(s.projection, {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2 / 9.5, 0, 0, 0, -10.5 / 9.5, 1});
    }
    SECTION("frustum, asymmetric") {
        Scene s = parse_ok("[camera]\nfrustum = { left = 0, right = 2, bottom = -1, top = 1, near = 1, far = 100 }\n");
        CHECK(s.camera.kind == Camera::Kind::Frustum);
        check_matrix(s.projection, {1, 0, 0, 0, 0, 1, 0, 0, 1, 0, -101.0 / 99, -1, 0, 0, -200.0 / 99, 0});
    }
    SECTION("projection_matrix flat, view_matrix as columns") {
        Scene s = parse_ok(R"(
[camera]
projection_matrix = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]
view_matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [7, 8, 9, 1]]
)");
        CHECK(s.camera.kind == Camera::Kind::Matrix);
        check_matrix(s.projection, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
        check_matrix(s.view, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1});
        CHECK(s.gl.modelview == s.view);
    }
    SECTION("perspective with an explicit aspect") {
        Scene s = parse_ok("[camera]\nperspective = { fovy = 90, aspect = 2, near = 1, far = 3 }\n");
        check_matrix(s.projection, {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -3, 0});
    }
}

TEST_CASE("resize_scene keeps the perspective aspect equal to width/height", "[scene][parse]") {
    Scene s = parse_ok(kLectureCamera);
    REQUIRE(resize_scene(s, 1920, 1080));
    CHECK(s.width == 1920);
    CHECK(s.height == 1080);
    CHECK(s.projection[0][0] == Approx(1.357995).margin(1e-6));  // the notes' value
    CHECK(s.projection[1][1] == Approx(2.414214).margin(1e-6));
    CHECK(s.gl.projection == s.projection);

    SECTION("an explicit aspect stays") {
        Scene e = parse_ok("[camera]\nperspective = { fovy = 90, aspect = 2, near = 1, far = 3 }\n");
        glm::mat4 before = e.projection;
        REQUIRE(resize_scene(e, 100, 300));
        CHECK(e.projection == before);
    }
    SECTION("bad sizes are refused and change nothing") {
        for (auto [w, h] : std::vector<std::pair<int, int>>{{0, 512}, {512, -1}, {100000, 100000}, {16385, 1}}) {
            auto st = resize_scene(s, w, h);
            REQUIRE_FALSE(st);
            CHECK_THAT(st.error().str(), Catch::Contains("width and height must each be 1..16384"));
        }
        CHECK(s.width == 1920);
        REQUIRE(resize_scene(s, 16384, 1));
    }
}

TEST_CASE("object transforms multiply in GL's order", "[scene][parse]") {
    Scene s = parse_ok(R"(
[[objects]]
mesh = "quad"
transform = [ { translate = [1, 2, 3] }, { rotate = [90, 0, 0, 1] }, { scale = [2, 3, 4] } ]
[[objects]]
mesh = "quad"
transform = [ { rotate = [120, 1, 1, 1] } ]
[[objects]]
mesh = "quad"
transform = [ { rotate = [30, 0, 0, 2] }, { matrix = [1,0,0,0, 0,1,0,0, 0,0,1,0, 5,0,0,1] } ]
)");
    REQUIRE(s.objects.size() == 3);
    // T * Rz(90) * S: x -> 2y, y -> -3x, z -> 4z, then + (1,2,3); exact at 90 degrees.
    CHECK(s.objects[0].model == glm::mat4(0, 2, 0, 0, -3, 0, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1));
    // 120 degrees about (1,1,1) cycles the axes x -> y -> z -> x.
    check_matrix(s.objects[1].model, {0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1});
    // The axis is normalized; the matrix entry is post-multiplied (its translation is rotated).
    double c = std::cos(M_PI / 6), sn = std::sin(M_PI / 6);
    check_matrix(s.objects[2].model, {c, sn, 0, 0, -sn, c, 0, 0, 0, 0, 1, 0, 5 * c, 5 * sn, 0, 1});
}

TEST_CASE("world-space lights are transformed by the view, as glLightfv after gluLookAt", "[scene][parse]") {
    Scene s = parse_ok(std::string(kLectureCamera) + R"(
[lights.0]
ambient = [0.2, 0.2, 0.2]
position = [1, 1, 3, 1]
constant_attenuation = 1
linear_attenuation = 0.05
quadratic_attenuation = 0.02

[lights.1]
position = [0.4, 1.2, 2.4, 1]
spot_direction = [-0.4, -1.2, -2.4]
spot_cutoff = 20
spot_exponent = 12

[lights.2]
space = "eye"
position = [1, 2, 3, 1]
spot_direction = [0, 0, -3]
enabled = false
diffuse = [0.5, 0.25, 0.125, 0.5]
specular = [1, 0, 0]
)");
    const GLState& gl = s.gl;
    check_vec(gl.lights[0].position, {1, 1, -2, 1});
    check_vec(gl.lights[0].ambient, {0.2, 0.2, 0.2, 1});
    check_vec(gl.lights[0].diffuse, {1, 1, 1, 1});  // GL_LIGHT0's default kept
    CHECK(gl.lights[0].linear_attenuation == 0.05f);
    CHECK(gl.lights[0].quadratic_attenuation == 0.02f);
    check_vec(gl.lights[1].position, {0.4, 1.2, -2.6, 1});
    check_vec(gl.lights[1].spot_direction, {-0.4, -1.2, -2.4});  // not normalized
    CHECK(gl.lights[1].spot_cutoff == 20);
    CHECK(gl.lights[1].spot_exponent == 12);
    check_vec(gl.lights[1].diffuse, {0, 0, 0, 1});  // other lights default black
    check_vec(gl.lights[2].position, {1, 2, 3, 1});
    check_vec(gl.lights[2].spot_direction, {0, 0, -3});
    check_vec(gl.lights[2].diffuse, {0.5, 0.25, 0.125, 0.5});
    check_vec(gl.lights[2].specular, {1, 0, 0, 1});
    CHECK(s.lights[0].enabled);
    CHECK(s.lights[1].enabled);
    CHECK_FALSE(s.lights[2].enabled);
    CHECK_FALSE(s.lights[3].enabled);
    CHECK(s.lights[0].world_space);
    CHECK_FALSE(s.lights[2].world_space);
    check_vec(s.lights[0].as_given.position, {1, 1, 3, 1});
}

TEST_CASE("spot directions use the view's upper 3x3; unset parameters stay in eye space", "[scene][parse]") {
    // Looking down -x from (5,0,0): world -x is eye -z, world +z is eye -x.
    Scene s = parse_ok(R"(
[camera]
look_at = { eye = [5, 0, 0], center = [0, 0, 0], up = [0, 1, 0] }
[lights.0]
position = [0, 0, 1, 0]
spot_direction = [-2, 0, 0]
[lights.1]
diffuse = [1, 1, 1]
)");
    check_vec(s.gl.lights[0].position, {-1, 0, 0, 0});
    check_vec(s.gl.lights[0].spot_direction, {0, 0, -2});
    // GL_LIGHT1's position and direction were never set: GL's eye-space defaults.
    check_vec(s.gl.lights[1].position, {0, 0, 1, 0});
    check_vec(s.gl.lights[1].spot_direction, {0, 0, -1});

    SECTION("derive_eye_space_lights follows a new view") {
        s.view = glm::mat4(1.0f);
        glslrun::scene::derive_eye_space_lights(s);
        check_vec(s.gl.lights[0].position, {0, 0, 1, 0});
        check_vec(s.gl.lights[0].spot_direction, {-2, 0, 0});
    }
}

TEST_CASE("light model, materials and current attributes", "[scene][parse]") {
    Scene s = parse_ok(R"(
[light_model]
ambient = [0.1, 0.2, 0.3, 0.4]
local_viewer = true
two_side = true

[material]
ambient = [0.25, 0.20, 0.07]
diffuse = [0.75, 0.61, 0.23, 1]
specular = [0.8, 0.8, 0.8, 1]
emission = [0, 0, 0.05, 1]
shininess = 64

[back_material]
diffuse = [0, 1, 0]
shininess = 8

[front_material]
ambient_and_diffuse = [1, 0, 0, 1]

[current]
color = [0.5, 0.5, 0.5]
secondary_color = [0.1, 0.2, 0.3, 0.4]
normal = [0, 1, 0]
)");
    const GLState& gl = s.gl;
    check_vec(gl.light_model_ambient, {0.1, 0.2, 0.3, 0.4});
    CHECK(gl.light_model_local_viewer);
    CHECK(gl.light_model_two_side);
    check_vec(gl.front_material.ambient, {1, 0, 0, 1});
    check_vec(gl.front_material.diffuse, {1, 0, 0, 1});
    check_vec(gl.front_material.specular, {0.8, 0.8, 0.8, 1});
    check_vec(gl.front_material.emission, {0, 0, 0.05, 1});
    CHECK(gl.front_material.shininess == 64);
    check_vec(gl.back_material.ambient, {0.25, 0.20, 0.07, 1});
    check_vec(gl.back_material.diffuse, {0, 1, 0, 1});
    CHECK(gl.back_material.shininess == 8);
    check_vec(gl.current_color, {0.5, 0.5, 0.5, 1});
    check_vec(gl.current_secondary_color, {0.1, 0.2, 0.3, 0.4});
    check_vec(gl.current_normal, {0, 1, 0});
}

TEST_CASE("render state, fog, depth range and texture matrices", "[scene][parse]") {
    Scene s = parse_ok(R"(
[output]
size = [640, 480]
clear_color = [0.1, 0.2, 0.3]
clear_depth = 0.5

[state]
depth_test = true
depth_func = "gequal"
cull_face = "front"
front_face = "cw"
shade_model = "flat"
vertex_program_two_side = true
point_size = 4.5
depth_range = [0.25, 0.75]

[fog]
color = [1, 0.5, 0.25, 1]
density = 0.5
start = 2
end = 10

[texture_matrix.0]
transform = [ { scale = [2, 2, 1] } ]
[texture_matrix.3]
matrix = [1,0,0,0, 0,1,0,0, 0,0,1,0, 0.5,0.25,0,1]
)");
    CHECK(s.width == 640);
    CHECK(s.height == 480);
    check_vec(s.clear_color, {0.1, 0.2, 0.3, 1});
    CHECK(s.clear_depth == 0.5f);
    const GLState& gl = s.gl;
    CHECK(gl.depth_test);
    CHECK(gl.depth_func == GLState::DepthFunc::Gequal);
    CHECK(gl.cull_face);
    CHECK_FALSE(gl.cull_back);
    CHECK_FALSE(gl.front_ccw);
    CHECK(gl.flat_shading);
    CHECK(gl.vertex_program_two_side);
    CHECK(gl.point_size == 4.5f);
    CHECK(gl.depth_near == 0.25f);
    CHECK(gl.depth_far == 0.75f);
    check_vec(gl.fog.color, {1, 0.5, 0.25, 1});
    CHECK(gl.fog.density == 0.5f);
    CHECK(gl.fog.start == 2);
    CHECK(gl.fog.end == 10);
    CHECK(gl.texture_matrix[0] == glm::mat4(2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
    CHECK(gl.texture_matrix[1] == glm::mat4(1.0f));
    CHECK(gl.texture_matrix[3] == glm::mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0.25f, 0, 1));
}

TEST_CASE("every depth function and cull mode has its GL value", "[scene][parse]") {
    const char* funcs[] = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"};
    for (int i = 0; i < 8; ++i) {
        Scene s = parse_ok(std::string("[state]\ndepth_func = \"") + funcs[i] + "\"\n");
        CHECK(int(s.gl.depth_func) == i);
    }
    CHECK_FALSE(parse_ok("[state]\ncull_face = \"off\"\n").gl.cull_face);
    Scene back = parse_ok("[state]\ncull_face = \"back\"\nfront_face = \"ccw\"\nshade_model = \"smooth\"\n");
    CHECK(back.gl.cull_face);
    CHECK(back.gl.cull_back);
    CHECK(back.gl.front_ccw);
    CHECK_FALSE(back.gl.flat_shading);
}

TEST_CASE("clip planes: world planes go through the inverse of the view", "[scene][parse]") {
    Scene s = parse_ok(std::string(kLectureCamera) + R"(
[state]
clip_planes = [[0, 0, 1, 0], [1, 0, 0, -0.5]]
)");
    // p_eye = p_world * inverse(view), inverse(view) = translate(0, 0, 5).
    check_vec(s.gl.clip_planes[0], {0, 0, 1, 5});
    check_vec(s.gl.clip_planes[1], {1, 0, 0, -0.5});
    CHECK(s.gl.clip_plane_enabled == 0b11);
    // The world origin (eye (0,0,-5)) is on plane 0, as it was in world space.
    CHECK(glm::dot(s.gl.clip_planes[0], glm::vec4(0, 0, -5, 1)) == Approx(0).margin(1e-6));

    Scene e = parse_ok(std::string(kLectureCamera) + R"(
[state]
clip_planes_space = "eye"
clip_planes = [[0, 0, 1, 0], [0, 1, 0, 0], [1, 0, 0, 0], [0, 0, -1, 0], [0, -1, 0, 0], [-1, 0, 0, 1]]
)");
    check_vec(e.gl.clip_planes[0], {0, 0, 1, 0});
    check_vec(e.gl.clip_planes[5], {-1, 0, 0, 1});
    CHECK(e.gl.clip_plane_enabled == 0b111111);
}

TEST_CASE("the lecture's scene files parse to the notes' state", "[scene][parse]") {
    std::string dir = std::string(GLSLRUN_SOURCE_DIR) + "/scenes/";
    auto load = [&](const char* name) {
        auto r = glslrun::scene::load_scene(dir + name);
        INFO((r ? std::string() : r.error().str()));
        REQUIRE(r);
        return std::move(*r);
    };
    Scene dir_scene = load("directional.toml");
    check_vec(dir_scene.gl.lights[0].position, {1, 1, 1, 0});
    CHECK(dir_scene.gl.depth_test);
    check_vec(dir_scene.clear_color, {0, 0, 0, 1});
    CHECK(dir_scene.gl.front_material.shininess == 64);
    Scene pos = load("positional.toml");
    check_vec(pos.gl.lights[0].position, {1, 1, -2, 1});
    Scene spot = load("spot.toml");
    check_vec(spot.gl.lights[0].position, {0.4, 1.2, -2.6, 1});
    check_vec(spot.gl.lights[0].spot_direction, {-0.1474420, -0.4423259, -0.8846517});
    CHECK(spot.gl.lights[0].spot_cutoff == 20);
}
