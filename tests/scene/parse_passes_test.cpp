// [[passes]]: their objects, state on top of the scene's (and objects' on
// top of the pass's), shader files, uniforms, and their mistakes.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "glslrun/scene/render.h"
#include "parse_helpers.h"

using namespace scene_test;

namespace {

const char* kTwoObjects = R"([state]
depth_test = true
[[objects]]
name = "a"
mesh = "quad"
state = { cull_face = "back" }
[[objects]]
name = "b"
mesh = "cube"
)";

}  // namespace

TEST_CASE("passes draw the objects they name with their state on the scene's", "[scene][parse]") {
    Scene s = parse_ok(std::string(kTwoObjects) + R"(
[[passes]]
name = "first"
state = { depth_func = "equal", blend = true }
[[passes]]
objects = ["b"]
uniforms = { k = 2 }
)");
    REQUIRE(s.passes.size() == 2);
    const auto& first = s.passes[0];
    CHECK(first.name == "first");
    CHECK(first.where.line == 11);
    CHECK(first.vertex.empty());
    CHECK(first.objects == std::vector<size_t>{0, 1});
    CHECK(first.state.depth_test);  // the scene's
    CHECK(first.state.blend);
    CHECK(first.state.depth_func == glslrun::CompareFunc::Equal);
    // Object a's own state goes on top of the pass's.
    REQUIRE(first.object_states.size() == 2);
    REQUIRE(first.object_states[0]);
    CHECK(first.object_states[0]->cull_face);
    CHECK(first.object_states[0]->blend);
    CHECK_FALSE(first.object_states[1]);
    const auto& second = s.passes[1];
    CHECK(second.name == "passes[1]");
    CHECK(second.objects == std::vector<size_t>{1});
    REQUIRE(second.uniforms.size() == 1);
    CHECK(second.uniforms[0].name == "k");
    CHECK_FALSE(second.state.blend);
}

TEST_CASE("a pass reads its shader files relative to the scene", "[scene][parse]") {
    auto dir = std::filesystem::temp_directory_path() / ("glslrun_passes_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir / "sub");
    std::ofstream(dir / "sub" / "p.vert") << "void main() { gl_Position = ftransform(); }\n";
    std::ofstream(dir / "sub" / "p.frag") << "void main() { gl_FragColor = vec4(1.0); }\n";
    std::ofstream(dir / "scene.toml") << "[[objects]]\nmesh = \"quad\"\n[[passes]]\nvertex = \"sub/p.vert\"\n"
                                         "fragment = [\"sub/p.frag\"]\n[[passes]]\nvertex = \"missing.vert\"\n"
                                         "fragment = \"sub/p.frag\"\n";
    auto r = glslrun::scene::load_scene((dir / "scene.toml").string());
    REQUIRE_FALSE(r);
    CHECK(r.error().diagnostics[0].line == 7);
    CHECK_THAT(r.error().str(), Catch::Contains("cannot read the shader") && Catch::Contains("missing.vert"));
    std::ofstream(dir / "scene.toml") << "[[objects]]\nmesh = \"quad\"\n[[passes]]\nvertex = \"sub/p.vert\"\n"
                                         "fragment = [\"sub/p.frag\"]\n";
    auto ok = glslrun::scene::load_scene((dir / "scene.toml").string());
    REQUIRE(ok);
    REQUIRE(ok->passes[0].vertex.size() == 1);
    CHECK_THAT(ok->passes[0].vertex[0].text, Catch::Contains("ftransform"));
    CHECK_THAT(ok->passes[0].fragment[0].name, Catch::EndsWith("p.frag"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("mistakes in passes cite their line", "[scene][parse]") {
    std::string objects = kTwoObjects;  // 9 lines
    check_cases({
        {"[[passes]]\nobject = [\"a\"]\n", 2, "did you mean 'objects'"},
        {"[[objects]]\nname = \"floor\"\nmesh = \"quad\"\n[[passes]]\nobjects = [\"flor\"]\n", 5,
         "no object named 'flor'"},
        {"[[passes]]\nprogram = \"fixed\"\nvertex = \"a.vert\"\n", 2, "leave out 'vertex'"},
        {"[[passes]]\nprogram = \"fixd\"\n", 2, "fixed"},
        {"[[passes]]\nstate = { blend_func = [\"one\", \"sideways\"] }\n", 2, "sideways"},
        {"[[passes]]\nstate = { point_size = -1 }\n", 2, "point_size"},
        {"[[passes]]\nvertex = 3\nfragment = \"a.frag\"\n", 2, "must be a shader file name"},
        {"passes = 3\n", 1, "'passes' must be an array of tables"},
    });
    check_error(objects + "[[passes]]\nobjects = [\"a\", 3]\n", 11, "must list object names");
}

// GL ignores glUniform at location -1: an entry no program uses is drawn
// past, with a warning at its line naming the nearest uniform there is; one
// typed for the render (--uniform, no line) is an error.
TEST_CASE("a scene uniform that no program uses is a warning at its line", "[scene][render]") {
    const std::string text = R"([uniforms]
tint = [1, 0, 0, 1]
tnit = 1.0
[[objects]]
mesh = "quad"
)";
    auto program = glslrun::Program::compile(
        {{"v.vert", "void main() { gl_Position = ftransform(); }"}},
        {{"f.frag", "uniform vec4 tint; void main() { gl_FragColor = tint; }"}});
    REQUIRE(program);
    for (const char* passes : {"", "[[passes]]\n[[passes]]\n"}) {
        INFO(passes);
        Scene s = parse_ok(text + passes);
        auto programs = glslrun::scene::ScenePrograms::compile(*program, s);
        REQUIRE(programs);
        REQUIRE(programs->warnings().size() == 1);
        const glslrun::Diagnostic& w = programs->warnings()[0];
        CHECK((w.warning && w.line == 3 && w.file == "scene.toml"));
        CHECK_THAT(w.message, Catch::Contains("active uniform 'tnit'") && Catch::Contains("did you mean 'tint'?") &&
                                  Catch::Contains("ignored"));
        glslrun::Framebuffer fb(8, 8);
        REQUIRE(glslrun::scene::render_scene(*programs, s, fb));
        CHECK(fb.pixel(4, 4) == glm::vec4(1, 0, 0, 1));  // the entries it has are set
        // The same name from the command line was typed for this render: an error.
        auto overrides = glslrun::scene::parse_uniform_override("tnit=1");
        REQUIRE(overrides);
        glslrun::scene::override_uniforms(s, *overrides);
        auto refused = glslrun::scene::ScenePrograms::compile(*program, s);
        REQUIRE_FALSE(refused);
        CHECK_THAT(refused.error().str(), Catch::StartsWith("--uniform tnit=1: error: ") &&
                                              Catch::Contains("did you mean 'tint'?"));
    }
}

TEST_CASE("primitive state keys: polygon mode and offset, line width, point sprites, culling", "[scene][parse]") {
    Scene s = parse_ok(R"([state]
polygon_mode = ["line", "point"]
polygon_offset = [1.5, -2]
polygon_offset_fill = true
polygon_offset_point = true
line_width = 3.5
point_sprite = true
coord_replace = [0, 3]
cull_face = "front_and_back"
)");
    const glslrun::GLState& g = s.gl;
    CHECK(g.polygon_mode[0] == glslrun::PolygonMode::Line);
    CHECK(g.polygon_mode[1] == glslrun::PolygonMode::Point);
    CHECK(g.polygon_offset_factor == 1.5f);
    CHECK(g.polygon_offset_units == -2.0f);
    CHECK(g.polygon_offset_fill);
    CHECK_FALSE(g.polygon_offset_line);
    CHECK(g.polygon_offset_point);
    CHECK(g.line_width == 3.5f);
    CHECK(g.point_sprite);
    CHECK(g.coord_replace == 0b1001u);
    CHECK(g.cull_face);
    CHECK(g.cull_front_and_back);
    Scene one = parse_ok("[state]\npolygon_mode = \"point\"\ncull_face = \"front\"\n");
    CHECK(one.gl.polygon_mode[0] == glslrun::PolygonMode::Point);
    CHECK(one.gl.polygon_mode[1] == glslrun::PolygonMode::Point);
    CHECK_FALSE(one.gl.cull_back);
    CHECK_FALSE(one.gl.cull_front_and_back);
    check_cases({
        {"[state]\npolygon_mode = \"wireframe\"\n", 2, "wireframe"},
        {"[state]\npolygon_mode = [\"line\"]\n", 2, "[front, back]"},
        {"[state]\npolygon_mode = [\"line\", \"dots\"]\n", 2, "dots"},
        {"[state]\nline_width = -1\n", 2, "line_width"},
        {"[state]\nline_width = 0\n", 2, "glLineWidth"},
        {"[state]\npolygon_offset = [1]\n", 2, "polygon_offset"},
        {"[state]\ncoord_replace = [8]\n", 2, "texture units 0..7"},
        {"[state]\npoint_sprite = 1\n", 2, "point_sprite"},
        {"[state]\ncull_face = \"sideways\"\n", 2, "sideways"},
    });
}

TEST_CASE("draw refuses a line width <= 0 and a polygon mode outside GL's", "[scene][render]") {
    auto program = glslrun::Program::compile({{"v.vert", "void main() { gl_Position = ftransform(); }"}},
                                             {{"f.frag", "void main() { gl_FragColor = vec4(1.0); }"}});
    REQUIRE(program);
    glslrun::Framebuffer fb(8, 8);
    std::vector<glslrun::VertexAttrib> attribs = {{"gl_Vertex", 2, {0, 0, 1, 0}}};
    glslrun::GLState gl;
    gl.line_width = 0;
    auto r = glslrun::draw(*program, gl, fb, glslrun::Primitive::Lines, attribs, 2);
    REQUIRE_FALSE(r);
    CHECK_THAT(r.error().str(), Catch::Contains("line width"));
    gl.line_width = 1;
    gl.polygon_mode[1] = glslrun::PolygonMode(7);
    auto m = glslrun::draw(*program, gl, fb, glslrun::Primitive::Lines, attribs, 2);
    REQUIRE_FALSE(m);
    CHECK_THAT(m.error().str(), Catch::Contains("GL_INVALID_ENUM"));
}
