// The scene parser: objects (meshes, materials, colours, attributes) and
// user uniforms flattened into glUniform names.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "parse_helpers.h"

using namespace scene_test;
using glslrun::scene::UniformSetting;

namespace {

const UniformSetting& find_uniform(const std::vector<UniformSetting>& us, const std::string& name) {
    for (const UniformSetting& u : us)
        if (u.name == name) return u;
    FAIL("no uniform " << name);
    return us.front();
}

void check_uniform(const std::vector<UniformSetting>& us, const std::string& name,
                   const std::vector<double>& values, bool integral, int line) {
    INFO("uniform " << name);
    const UniformSetting& u = find_uniform(us, name);
    CHECK(u.values == values);
    CHECK(u.integral == integral);
    CHECK(u.where.file == "scene.toml");
    CHECK(u.where.line == line);
}

}  // namespace

TEST_CASE("uniforms of every kind flatten to GL names", "[scene][parse]") {
    Scene s = parse_ok(R"([uniforms]
f = 0.5
i = 3
b = true
v = [1, 0.5, 0, 1]
iv = [1, 2, 3]
bv = [true, false]
m = [[1, 0, 0], [0, 2, 0], [0, 0, 3]]
flat = [1, 0, 0, 1]
arr = [1.0, 2.0, 3.0]
"arr[2]" = 5.0
vecs = [[1, 2], [3, 4], [5, 6]]
mats = [[[1, 0], [0, 1]], [[2, 0], [0, 2]]]
light = { pos = [0, 1, 0], color = [1, 1, 1], inner = { k = 2 } }
lights = [ { pos = [0, 1, 0] }, { pos = [1, 0, 0], on = false } ]
neg = -7
[uniforms.s]
a = 1
[[uniforms.t]]
x = 1.5
[[uniforms.t]]
x = 2.5
)");
    const auto& u = s.uniforms;
    check_uniform(u, "f", {0.5}, false, 2);
    check_uniform(u, "i", {3}, true, 3);
    check_uniform(u, "b", {1}, true, 4);
    check_uniform(u, "v", {1, 0.5, 0, 1}, false, 5);
    check_uniform(u, "iv", {1, 2, 3}, true, 6);
    check_uniform(u, "bv", {1, 0}, true, 7);
    check_uniform(u, "m", {1, 0, 0, 0, 2, 0, 0, 0, 3}, true, 8);
    check_uniform(u, "flat", {1, 0, 0, 1}, true, 9);
    check_uniform(u, "arr", {1, 2, 3}, false, 10);
    check_uniform(u, "arr[2]", {5}, false, 11);
    check_uniform(u, "vecs", {1, 2, 3, 4, 5, 6}, true, 12);
    check_uniform(u, "mats", {1, 0, 0, 1, 2, 0, 0, 2}, true, 13);
    check_uniform(u, "light.pos", {0, 1, 0}, true, 14);
    check_uniform(u, "light.color", {1, 1, 1}, true, 14);
    check_uniform(u, "light.inner.k", {2}, true, 14);
    check_uniform(u, "lights[0].pos", {0, 1, 0}, true, 15);
    check_uniform(u, "lights[1].pos", {1, 0, 0}, true, 15);
    check_uniform(u, "lights[1].on", {0}, true, 15);
    check_uniform(u, "neg", {-7}, true, 16);
    check_uniform(u, "s.a", {1}, true, 18);
    check_uniform(u, "t[0].x", {1.5}, false, 20);
    check_uniform(u, "t[1].x", {2.5}, false, 22);
    CHECK(u.size() == 22);
    // File order, as the glUniform calls would be made: "arr[2]" after "arr".
    for (size_t i = 1; i < u.size(); ++i) CHECK(u[i - 1].where.line <= u[i].where.line);
}

TEST_CASE("built-in meshes with their parameters", "[scene][parse]") {
    Scene s = parse_ok(R"(
[[objects]]
mesh = "teapot"
[[objects]]
name = "the quad"
mesh = "quad"
[[objects]]
mesh = "cube"
size = 2
[[objects]]
mesh = "sphere"
radius = 0.5
slices = 8
stacks = 4
[[objects]]
mesh = "torus"
inner_radius = 0.1
outer_radius = 0.5
sides = 6
rings = 12
[[objects]]
mesh = "plane"
size = 3
subdivisions = 4
[[objects]]
mesh = "teapot"
size = 0.5
subdivisions = 2
)");
    REQUIRE(s.objects.size() == 7);
    CHECK(s.objects[0].name == "objects[0]");
    CHECK(s.objects[0].mesh.vertex_count == 3872);  // the notes: 32 patches of 11x11
    CHECK(s.objects[0].where.line == 2);
    CHECK(s.objects[0].model == glm::mat4(1.0f));
    CHECK_FALSE(s.objects[0].color);
    CHECK_FALSE(s.objects[0].front_material);
    CHECK(s.objects[1].name == "the quad");
    CHECK(s.objects[1].mesh.vertex_count == 4);
    CHECK(s.objects[2].mesh.vertex_count == 24);
    CHECK(s.objects[6].mesh.vertex_count == 32 * 9);
    for (const auto& o : s.objects) {
        INFO(o.name);
        CHECK(o.mesh.vertex_count > 0);
        CHECK(o.mesh.find("gl_Vertex"));
        CHECK(o.mesh.find("gl_Normal"));
        CHECK(bool(o.mesh.find("gl_Color")) == (o.name == "the quad"));  // the lecture's colours
    }
}

TEST_CASE("object colour, vertex colours, materials, uniforms and attributes", "[scene][parse]") {
    Scene s = parse_ok(R"(
[material]
diffuse = [0.5, 0.5, 0.5, 1]
shininess = 10

[[objects]]
mesh = "quad"
color = [1, 0, 0]
vertex_colors = "normal"
[objects.material]
specular = [1, 1, 1, 1]
[objects.back_material]
shininess = 100
[objects.uniforms]
tint = [0, 1, 0, 1]
[objects.attributes]
weight = [0.1, 0.2, 0.3, 0.4]
offset = [[1, 2, 3], [4, 5, 6], [7, 8, 9], [10, 11, 12]]

[[objects]]
mesh = "quad"
[objects.front_material]
emission = [0, 0, 1]
)");
    REQUIRE(s.objects.size() == 2);
    const auto& a = s.objects[0];
    REQUIRE(a.color);
    check_vec(*a.color, {1, 0, 0, 1});
    REQUIRE(a.mesh.find("gl_Color"));
    REQUIRE(a.front_material);
    REQUIRE(a.back_material);
    check_vec(a.front_material->diffuse, {0.5, 0.5, 0.5, 1});  // from the scene's [material]
    check_vec(a.front_material->specular, {1, 1, 1, 1});
    CHECK(a.front_material->shininess == 10);
    check_vec(a.back_material->specular, {1, 1, 1, 1});
    CHECK(a.back_material->shininess == 100);
    REQUIRE(a.uniforms.size() == 1);
    CHECK(a.uniforms[0].name == "tint");
    CHECK(a.uniforms[0].where.line == 15);
    const glslrun::VertexAttrib* w = a.mesh.find("weight");
    REQUIRE(w);
    CHECK(w->components == 1);
    CHECK(w->data == std::vector<float>{0.1f, 0.2f, 0.3f, 0.4f});
    const glslrun::VertexAttrib* off = a.mesh.find("offset");
    REQUIRE(off);
    CHECK(off->components == 3);
    CHECK(off->data.size() == 12);
    CHECK(off->data[11] == 12);
    const auto& b = s.objects[1];
    REQUIRE(b.front_material);
    check_vec(b.front_material->emission, {0, 0, 1, 1});
    CHECK_FALSE(b.back_material);  // only the front was overridden
    CHECK(s.uniforms.empty());
}

TEST_CASE("OBJ files are found relative to the scene file", "[scene][parse]") {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("glslrun_scene_parse_" + std::to_string(::getpid()));
    fs::create_directories(dir / "models");
    std::ofstream(dir / "models" / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(dir / "scene.toml") << "[[objects]]\nmesh = \"obj\"\nfile = \"models/tri.obj\"\n"
                                         "[objects.attributes]\nw = [1, 2, 3]\n";
    std::ofstream(dir / "missing.toml") << "# a comment\n[[objects]]\nmesh = \"obj\"\nfile = \"models/none.obj\"\n";
    auto r = glslrun::scene::load_scene((dir / "scene.toml").string());
    INFO((r ? std::string() : r.error().str()));
    REQUIRE(r);
    REQUIRE(r->objects.size() == 1);
    CHECK(r->objects[0].mesh.vertex_count == 3);
    CHECK(r->objects[0].mesh.find("w"));

    auto missing = glslrun::scene::load_scene((dir / "missing.toml").string());
    REQUIRE_FALSE(missing);
    const auto& ds = missing.error().diagnostics;
    REQUIRE(ds.size() >= 2);
    CHECK(ds[0].file == (dir / "missing.toml").string());
    CHECK(ds[0].line == 4);
    CHECK_THAT(ds[0].message, Catch::Contains("models/none.obj"));
    CHECK_THAT(ds[1].str(), Catch::Contains("none.obj"));  // the loader's own diagnostic
    fs::remove_all(dir);
}

TEST_CASE("load_scene reports a missing scene file", "[scene][parse]") {
    auto r = glslrun::scene::load_scene("/nonexistent/scene.toml");
    REQUIRE_FALSE(r);
    CHECK_THAT(r.error().str(), Catch::StartsWith("/nonexistent/scene.toml: error: cannot open scene file"));
}
