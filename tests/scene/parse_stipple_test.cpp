// The scene parser on [state]'s point parameters, sprite origin and line
// and polygon stipples: values, defaults, per-object state and errors at
// file:line; draw() refuses what GL refuses.
#include "tests/scene/parse_helpers.h"

#include "glslrun/glslrun.h"
#include "glslrun/scene/render.h"

using namespace scene_test;

TEST_CASE("point parameter keys", "[scene][parse]") {
    Scene defaults = parse_ok("");
    const glslrun::GLState& d = defaults.gl;
    CHECK(d.point_size_min == 0.0f);
    CHECK(d.point_size_max == 255.0f);  // Mesa's GL_POINT_SIZE_MAX
    CHECK(d.point_distance_attenuation == glm::vec3(1, 0, 0));
    CHECK(d.point_fade_threshold_size == 1.0f);
    CHECK_FALSE(d.point_sprite_coord_lower_left);
    Scene s = parse_ok(R"([state]
point_size_min = 2.5
point_size_max = 40
point_distance_attenuation = [0.5, 0.25, 0.125]
point_fade_threshold_size = 3
point_sprite_coord_origin = "lower_left"
[[objects]]
mesh = "quad"
[objects.state]
point_sprite_coord_origin = "upper_left"
point_size_max = 9
)");
    const glslrun::GLState& g = s.gl;
    CHECK(g.point_size_min == 2.5f);
    CHECK(g.point_size_max == 40.0f);
    CHECK(g.point_distance_attenuation == glm::vec3(0.5f, 0.25f, 0.125f));
    CHECK(g.point_fade_threshold_size == 3.0f);
    CHECK(g.point_sprite_coord_lower_left);
    REQUIRE(s.objects.size() == 1);
    REQUIRE(s.objects[0].state);
    CHECK_FALSE(s.objects[0].state->point_sprite_coord_lower_left);
    CHECK(s.objects[0].state->point_size_max == 9.0f);
    CHECK(s.objects[0].state->point_size_min == 2.5f);  // the scene's, under the object's own keys
    check_cases({
        {"[state]\npoint_size_min = -1\n", 2, "GL_INVALID_VALUE"},
        {"[state]\n\npoint_size_max = -0.5\n", 3, "point_size_max"},
        {"[state]\npoint_fade_threshold_size = -2\n", 2, "glPointParameter"},
        {"[state]\npoint_distance_attenuation = [1, 0]\n", 2, "[constant, linear, quadratic]"},
        {"[state]\npoint_distance_attenuation = [1, 0, nan]\n", 2, "point_distance_attenuation"},
        {"[state]\npoint_sprite_coord_origin = \"upper_right\"\n", 2, "upper_right"},
        {"[state]\npoint_size_maximum = 3\n", 2, "did you mean 'point_size_max'?"},
    });
}

TEST_CASE("line and polygon stipple keys", "[scene][parse]") {
    Scene defaults = parse_ok("");
    CHECK_FALSE(defaults.gl.line_stipple);
    CHECK(defaults.gl.line_stipple_repeat == 1);
    CHECK(defaults.gl.line_stipple_pattern == 0xFFFF);
    CHECK_FALSE(defaults.gl.polygon_stipple);
    for (uint32_t row : defaults.gl.polygon_stipple_pattern) CHECK(row == 0xFFFFFFFFu);
    Scene s = parse_ok(R"([state]
line_stipple = true
line_stipple_pattern = 0x0F0F
line_stipple_repeat = 256
polygon_stipple = true
polygon_stipple_pattern = [0xAAAAAAAA, 0x55555555, 0, 4294967295]
)");
    const glslrun::GLState& g = s.gl;
    CHECK(g.line_stipple);
    CHECK(g.line_stipple_pattern == 0x0F0F);
    CHECK(g.line_stipple_repeat == 256);
    CHECK(g.polygon_stipple);
    for (size_t y = 0; y < 32; ++y) {
        INFO("row " << y);
        const uint32_t want[] = {0xAAAAAAAAu, 0x55555555u, 0u, 0xFFFFFFFFu};
        CHECK(g.polygon_stipple_pattern[y] == want[y % 4]);  // four rows repeat upwards
    }
    Scene binary = parse_ok("[state]\nline_stipple_pattern = 0b1000000000000001\n");
    CHECK(binary.gl.line_stipple_pattern == 0x8001);
    std::string rows32 = "[state]\npolygon_stipple_pattern = [";
    for (int i = 0; i < 32; ++i) rows32 += (i ? ", " : "") + std::to_string(i);
    Scene all = parse_ok(rows32 + "]\n");
    for (uint32_t y = 0; y < 32; ++y) CHECK(all.gl.polygon_stipple_pattern[y] == y);
    check_cases({
        {"[state]\nline_stipple = 1\n", 2, "true or false"},
        {"[state]\nline_stipple_pattern = 0x10000\n", 2, "16 bits"},
        {"[state]\nline_stipple_pattern = 3.5\n", 2, "must be an integer"},
        {"[state]\nline_stipple_repeat = 0\n", 2, "[1, 256]"},
        {"[state]\nline_stipple_repeat = 257\n", 2, "glLineStipple's factor"},
        {"[state]\npolygon_stipple_pattern = [1, 2, 3]\n", 2, "1, 2, 4, 8 or 16 rows"},
        {"[state]\npolygon_stipple_pattern = []\n", 2, "32 rows"},
        {"[state]\npolygon_stipple_pattern = [1, -1]\n", 2, "polygon_stipple_pattern[1]"},
        {"[state]\npolygon_stipple_pattern = [0x100000000]\n", 2, "a row of 32 bits"},
        {"[state]\npolygon_stipple_pattern = 7\n", 2, "must be an array"},
        {"[state]\nline_stiple = true\n", 2, "did you mean 'line_stipple'?"},
    });
}

TEST_CASE("draw refuses negative point parameters (GL_INVALID_VALUE)", "[scene][render]") {
    auto program = glslrun::Program::compile({{"v.vert", "void main() { gl_Position = ftransform(); }"}},
                                             {{"f.frag", "void main() { gl_FragColor = vec4(1.0); }"}});
    REQUIRE(program);
    glslrun::Framebuffer fb(8, 8);
    std::vector<glslrun::VertexAttrib> attribs = {{"gl_Vertex", 2, {0, 0}}};
    for (int which = 0; which < 3; ++which) {
        glslrun::GLState gl;
        (which == 0 ? gl.point_size_min : which == 1 ? gl.point_size_max : gl.point_fade_threshold_size) = -1;
        auto r = glslrun::draw(*program, gl, fb, glslrun::Primitive::Points, attribs, 1);
        REQUIRE_FALSE(r);
        CHECK_THAT(r.error().str(), Catch::Contains("GL_INVALID_VALUE"));
    }
}
