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
        {"[[passes]]\nvertex = \"a.vert\"\n", 1, "give both 'vertex' and 'fragment'"},
        {"[[passes]]\nstate = { blend_func = [\"one\", \"sideways\"] }\n", 2, "sideways"},
        {"[[passes]]\nstate = { point_size = -1 }\n", 2, "point_size"},
        {"[[passes]]\nvertex = 3\nfragment = \"a.frag\"\n", 2, "must be a shader file name"},
        {"passes = 3\n", 1, "'passes' must be an array of tables"},
    });
    check_error(objects + "[[passes]]\nobjects = [\"a\", 3]\n", 11, "must list object names");
}

TEST_CASE("a scene uniform that no pass's program declares is an error at its line", "[scene][render]") {
    Scene s = parse_ok(R"([uniforms]
tint = [1, 1, 1, 1]
nothing = 1.0
[[objects]]
mesh = "quad"
[[passes]]
[[passes]]
)");
    auto program = glslrun::Program::compile(
        {{"v.vert", "void main() { gl_Position = ftransform(); }"}},
        {{"f.frag", "uniform vec4 tint; void main() { gl_FragColor = tint; }"}});
    REQUIRE(program);
    glslrun::Framebuffer fb(8, 8);
    auto r = glslrun::scene::render_scene(*program, s, fb);
    REQUIRE_FALSE(r);
    CHECK(r.error().diagnostics[0].line == 3);
    CHECK_THAT(r.error().str(), Catch::Contains("no pass's program has an active uniform 'nothing'"));
}
