// The built-in meshes and OBJ loading (scene/meshes.h). The teapot must
// be exactly freeglut's geometry (scene/teapot.cpp), since images are compared with
// Mesa's pixel by pixel: counts, numbering, normals and winding are checked.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <glm/glm.hpp>
#include <unistd.h>

#include "glslrun/scene/meshes.h"

using namespace glslrun;
using namespace glslrun::scene;

namespace {

const VertexAttrib& attrib(const Mesh& mesh, const char* name, uint32_t components) {
    const VertexAttrib* a = mesh.find(name);
    REQUIRE(a != nullptr);
    REQUIRE(a->components == components);
    REQUIRE(a->data.size() == size_t(mesh.vertex_count) * components);
    return *a;
}

glm::dvec3 vec3_at(const VertexAttrib& a, uint32_t i) {
    return {a.data[size_t(i) * 3], a.data[size_t(i) * 3 + 1], a.data[size_t(i) * 3 + 2]};
}

struct Box {
    glm::dvec3 lo{1e30}, hi{-1e30};
};

Box bounds(const Mesh& mesh) {
    const VertexAttrib& pos = attrib(mesh, "gl_Vertex", 3);
    Box box;
    for (uint32_t i = 0; i < mesh.vertex_count; ++i) {
        box.lo = glm::min(box.lo, vec3_at(pos, i));
        box.hi = glm::max(box.hi, vec3_at(pos, i));
    }
    return box;
}

// What every mesh promises: the three attributes, indices in range, and unit
// normals (except an OBJ file's own normals, which are kept as given).
void check_basics(const Mesh& mesh, bool unit_normals = true) {
    attrib(mesh, "gl_Vertex", 3);
    attrib(mesh, "gl_MultiTexCoord0", 2);
    const VertexAttrib& nrm = attrib(mesh, "gl_Normal", 3);
    REQUIRE(mesh.primitive == Primitive::Triangles);
    REQUIRE(mesh.indices.size() % 3 == 0);
    REQUIRE(std::all_of(mesh.indices.begin(), mesh.indices.end(),
                        [&](uint32_t i) { return i < mesh.vertex_count; }));
    for (uint32_t i = 0; unit_normals && i < mesh.vertex_count; ++i)
        REQUIRE(glm::length(vec3_at(nrm, i)) == Approx(1.0).margin(1e-6));
}

// Counter-clockwise seen from outside: each triangle's geometric normal
// agrees with its vertex normals. Returns the triangles that disagree;
// zero-area triangles count as disagreeing.
int wrongly_wound(const Mesh& mesh) {
    const VertexAttrib& pos = attrib(mesh, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(mesh, "gl_Normal", 3);
    int wrong = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::dvec3 g = glm::cross(vec3_at(pos, b) - vec3_at(pos, a), vec3_at(pos, c) - vec3_at(pos, a));
        const glm::dvec3 n = vec3_at(nrm, a) + vec3_at(nrm, b) + vec3_at(nrm, c);
        if (!(glm::dot(g, n) > 0)) ++wrong;
    }
    return wrong;
}

// Möller-Trumbore: does the ray hit the triangle in front of its origin?
bool ray_hits(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
              const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-15) return false;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0 || u > 1) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0 || u + v > 1) return false;
    return glm::dot(e2, q) / det > 1e-9;
}

// Ray parity: a ray leaving vertex i along its normal crosses the surface an
// even number of times when the normal points outside.
bool normal_points_outside(const Mesh& mesh, uint32_t i, double sign = 1) {
    const VertexAttrib& pos = attrib(mesh, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(mesh, "gl_Normal", 3);
    // A slight tilt keeps the ray off the edges of symmetric meshes.
    const glm::dvec3 dir = glm::normalize(sign * vec3_at(nrm, i) + glm::dvec3(0.011, 0.017, 0.013));
    const glm::dvec3 origin = vec3_at(pos, i) + 1e-5 * dir;
    int crossings = 0;
    for (size_t t = 0; t < mesh.indices.size(); t += 3)
        crossings += ray_hits(origin, dir, vec3_at(pos, mesh.indices[t]), vec3_at(pos, mesh.indices[t + 1]),
                              vec3_at(pos, mesh.indices[t + 2]));
    return crossings % 2 == 0;
}

uint32_t teapot_vertex(int n, int patch, int i, int j) {
    return uint32_t(patch * (n + 1) * (n + 1) + i * (n + 1) + j);
}

}  // namespace

// ------------------------------------------------------------------ teapot ---

TEST_CASE("teapot: counts of freeglut's teapot", "[mesh]") {
    const Mesh ten = make_teapot(1.0, 10);
    CHECK(ten.vertex_count == 3872);
    CHECK(ten.indices.size() == 6400 * 3);
    const Mesh dense = make_teapot(1.0, 64);
    CHECK(dense.vertex_count == 135200);
    CHECK(dense.indices.size() == 262144 * 3);
    const Mesh coarse = make_teapot(1.0, 1);
    CHECK(coarse.vertex_count == 32 * 4);
    CHECK(coarse.indices.size() == 32 * 2 * 3);
    check_basics(ten);
    check_basics(dense);
}

TEST_CASE("teapot: bounding box of glutSolidTeapot(1)", "[mesh]") {
    const Box box = bounds(make_teapot(1.0, 64));
    CHECK(box.lo.x == Approx(-1.5).margin(1e-3));
    CHECK(box.hi.x == Approx(1.7168).margin(1e-3));
    CHECK(box.lo.y == Approx(-0.7875).margin(1e-7));  // the bottom centre
    CHECK(box.hi.y == Approx(0.7875).margin(1e-7));   // the knob tip
    CHECK(box.lo.z == Approx(-1.0).margin(1e-7));     // the body's widest ring is a patch edge
    CHECK(box.hi.z == Approx(1.0).margin(1e-7));
    // Spout to +x, handle to -x, symmetric in z.
    const Box half = bounds(make_teapot(0.5, 8));
    CHECK(half.hi.y == Approx(0.7875 / 2).margin(1e-7));
}

TEST_CASE("teapot: size scales the control points", "[mesh]") {
    // A power-of-two size scales every double operation exactly.
    const Mesh one = make_teapot(1.0, 4), two = make_teapot(2.0, 4);
    const VertexAttrib &a = attrib(one, "gl_Vertex", 3), &b = attrib(two, "gl_Vertex", 3);
    for (size_t k = 0; k < a.data.size(); ++k) REQUIRE(b.data[k] == 2 * a.data[k]);
    CHECK(attrib(one, "gl_Normal", 3).data == attrib(two, "gl_Normal", 3).data);
}

TEST_CASE("teapot: numbering and texture coordinates", "[mesh]") {
    const int n = 6;
    const Mesh mesh = make_teapot(1.0, n);
    const VertexAttrib& tex = attrib(mesh, "gl_MultiTexCoord0", 2);
    for (int p : {0, 13, 31})
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const uint32_t v = teapot_vertex(n, p, i, j);
                REQUIRE(tex.data[v * 2] == float(double(i) / n));      // s = u, the outer loop
                REQUIRE(tex.data[v * 2 + 1] == float(double(j) / n));  // t = v, the inner loop
            }
    // The first cell of the first patch: (A,B,C), (A,C,D).
    const uint32_t a = teapot_vertex(n, 0, 0, 0), b = teapot_vertex(n, 0, 0, 1);
    const uint32_t c = teapot_vertex(n, 0, 1, 1), d = teapot_vertex(n, 0, 1, 0);
    CHECK(std::vector<uint32_t>(mesh.indices.begin(), mesh.indices.begin() + 6) ==
          std::vector<uint32_t>{a, b, c, a, c, d});
    // The last triangle ends the last patch.
    CHECK(mesh.indices.back() == teapot_vertex(n, 31, n, n - 1));
}

TEST_CASE("teapot: the two degenerate normals", "[mesh]") {
    const int n = 10;
    const Mesh mesh = make_teapot(1.0, n);
    const VertexAttrib& pos = attrib(mesh, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(mesh, "gl_Normal", 3);
    // Patches 20-23 are the lid's top, 28-31 the bottom: their first control
    // row is one point, the knob tip resp. the bottom centre.
    for (int p = 20; p < 32; ++p) {
        if (p >= 24 && p < 28) continue;
        const double up = p < 24 ? 1 : -1;
        for (int j = 0; j <= n; ++j) {
            const uint32_t v = teapot_vertex(n, p, 0, j);
            REQUIRE(vec3_at(pos, v) == glm::dvec3(0, float(up * 0.7875), 0));
            REQUIRE(vec3_at(nrm, v) == glm::dvec3(0, up, 0));
        }
        // One step inside, the normal is ordinary and leans the same way.
        REQUIRE(vec3_at(nrm, teapot_vertex(n, p, 1, 3)).y * up > 0.5);
    }
}

TEST_CASE("teapot: counter-clockwise from outside", "[mesh]") {
    const Mesh mesh = make_teapot(1.0, 10);
    // Only the zero-area triangles at the two collapsed rows may disagree:
    // one per cell of the first row on each of those 8 patches.
    CHECK(wrongly_wound(mesh) == 8 * 10);
}

TEST_CASE("teapot: normals point outwards (ray parity)", "[mesh]") {
    const int n = 8;
    const Mesh mesh = make_teapot(1.0, n);
    // The teapot is not closed, so some rays legitimately see odd parity: from
    // the rim's inner lip (into the pot), the handle's and spout's ends (inside
    // the body), the spout's mouth, and the body where the spout or handle
    // covers it. That is 5% of the vertices at n = 8 (no patch above 12%); a
    // wrongly oriented patch would score near 0, flipped normals score ~5%.
    int outside = 0, flipped_outside = 0;
    const int per_patch = (n + 1) * (n + 1);
    for (int p = 0; p < 32; ++p) {
        int patch_outside = 0;
        for (int k = 0; k < per_patch; ++k) {
            const uint32_t v = uint32_t(p * per_patch + k);
            patch_outside += normal_points_outside(mesh, v);
            flipped_outside += normal_points_outside(mesh, v, -1);
        }
        INFO("patch " << p << ": " << patch_outside << " of " << per_patch);
        CHECK(patch_outside > per_patch * 3 / 4);
        outside += patch_outside;
    }
    const int total = 32 * per_patch;
    CHECK(outside > total * 93 / 100);
    CHECK(flipped_outside < total * 10 / 100);
}

TEST_CASE("teapot: neighbouring patches share their edges exactly", "[mesh]") {
    // Rim (patch 0) -> body (4) -> lower body (8) -> bottom (28..31 share the
    // body's last ring): the data's shared control rows evaluate identically.
    const int n = 5;
    const Mesh mesh = make_teapot(1.0, n);
    const VertexAttrib& pos = attrib(mesh, "gl_Vertex", 3);
    for (int j = 0; j <= n; ++j) {
        REQUIRE(vec3_at(pos, teapot_vertex(n, 0, n, j)) == vec3_at(pos, teapot_vertex(n, 4, 0, j)));
        REQUIRE(vec3_at(pos, teapot_vertex(n, 4, n, j)) == vec3_at(pos, teapot_vertex(n, 8, 0, j)));
        // Patch 1 starts where patch 0 ends, around the rim.
        REQUIRE(vec3_at(pos, teapot_vertex(n, 0, j, n)) == vec3_at(pos, teapot_vertex(n, 1, j, 0)));
    }
}

// ----------------------------------------------------------- simple meshes ---

TEST_CASE("lecture quad", "[mesh]") {
    const Mesh quad = make_lecture_quad();
    CHECK(quad.primitive == Primitive::Quads);
    CHECK(quad.vertex_count == 4);
    CHECK(quad.indices.empty());
    CHECK(attrib(quad, "gl_Vertex", 3).data == std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
    CHECK(attrib(quad, "gl_Color", 3).data == std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0});
    CHECK(attrib(quad, "gl_Normal", 3).data == std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    attrib(quad, "gl_MultiTexCoord0", 2);
}

TEST_CASE("cube", "[mesh]") {
    const Mesh cube = make_cube(3.0);
    check_basics(cube);
    CHECK(cube.vertex_count == 24);
    CHECK(cube.indices.size() == 36);
    CHECK(wrongly_wound(cube) == 0);
    const Box box = bounds(cube);
    CHECK(box.lo == glm::dvec3(-1.5));
    CHECK(box.hi == glm::dvec3(1.5));
    const VertexAttrib& pos = attrib(cube, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(cube, "gl_Normal", 3);
    for (uint32_t v = 0; v < cube.vertex_count; ++v) {
        // Flat, axis-aligned and outward: the face's coordinate is +-1.5 along it.
        CHECK(glm::dot(vec3_at(pos, v), vec3_at(nrm, v)) == 1.5);
        CHECK(normal_points_outside(cube, v));
    }
}

TEST_CASE("sphere", "[mesh]") {
    const int slices = 12, stacks = 8;
    const Mesh sphere = make_sphere(2.0, slices, stacks);
    check_basics(sphere);
    CHECK(sphere.vertex_count == uint32_t((slices + 1) * (stacks + 1)));
    CHECK(sphere.indices.size() == size_t(2 * slices * (stacks - 1) * 3));
    CHECK(wrongly_wound(sphere) == 0);
    const VertexAttrib& pos = attrib(sphere, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(sphere, "gl_Normal", 3);
    for (uint32_t v = 0; v < sphere.vertex_count; ++v) {
        CHECK(glm::length(vec3_at(pos, v)) == Approx(2.0));
        CHECK(glm::length(vec3_at(pos, v) / 2.0 - vec3_at(nrm, v)) < 1e-6);
    }
    // gluSphere's layout: +z pole first, s = 0 at +y.
    CHECK(vec3_at(pos, 0) == glm::dvec3(0, 0, 2));
    CHECK(vec3_at(pos, uint32_t(slices + 1)).y > 0);
    CHECK(vec3_at(pos, sphere.vertex_count - 1) == glm::dvec3(0, 0, -2));
    CHECK(bounds(sphere).hi.y == 2.0);
}

TEST_CASE("torus", "[mesh]") {
    const int sides = 8, rings = 16;
    const double r = 0.25, R = 1.0;
    const Mesh torus = make_torus(r, R, sides, rings);
    check_basics(torus);
    CHECK(torus.vertex_count == uint32_t((sides + 1) * (rings + 1)));
    CHECK(torus.indices.size() == size_t(2 * sides * rings * 3));
    CHECK(wrongly_wound(torus) == 0);
    const VertexAttrib& pos = attrib(torus, "gl_Vertex", 3);
    const VertexAttrib& nrm = attrib(torus, "gl_Normal", 3);
    for (uint32_t v = 0; v < torus.vertex_count; ++v) {
        const glm::dvec3 p = vec3_at(pos, v);
        const glm::dvec3 centre = R * glm::normalize(glm::dvec3(p.x, p.y, 0));
        CHECK(glm::length(p - centre) == Approx(r));
        CHECK(glm::length((p - centre) / r - vec3_at(nrm, v)) < 1e-6);  // outward from the tube
    }
    const Box box = bounds(torus);
    CHECK(box.hi.x == Approx(R + r));
    CHECK(box.hi.z == Approx(r));
}

TEST_CASE("plane", "[mesh]") {
    const Mesh plane = make_plane(4.0, 3);
    check_basics(plane);
    CHECK(plane.vertex_count == 16);
    CHECK(plane.indices.size() == 18 * 3);
    CHECK(wrongly_wound(plane) == 0);
    const Box box = bounds(plane);
    CHECK(box.lo == glm::dvec3(-2, -2, 0));
    CHECK(box.hi == glm::dvec3(2, 2, 0));
    const VertexAttrib& tex = attrib(plane, "gl_MultiTexCoord0", 2);
    CHECK(tex.data[0] == 0);
    CHECK(tex.data[2 * 15] == 1);
    CHECK(tex.data[2 * 15 + 1] == 1);
}

TEST_CASE("normal colours", "[mesh]") {
    Mesh mesh = make_teapot(1.0, 3);
    add_normal_colors(mesh);
    add_normal_colors(mesh);  // replaces, does not add a second array
    CHECK(std::count_if(mesh.attribs.begin(), mesh.attribs.end(),
                        [](const VertexAttrib& a) { return a.name == "gl_Color"; }) == 1);
    const VertexAttrib& color = attrib(mesh, "gl_Color", 4);
    const VertexAttrib& nrm = attrib(mesh, "gl_Normal", 3);
    for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
        for (uint32_t c = 0; c < 3; ++c) REQUIRE(color.data[v * 4 + c] == 0.5f + 0.5f * nrm.data[v * 3 + c]);
        REQUIRE(color.data[v * 4 + 3] == 1.0f);
    }
}

// --------------------------------------------------------------------- OBJ ---

namespace {

std::string data_path(const char* name) { return std::string(GLSLRUN_SOURCE_DIR) + "/tests/scene/data/" + name; }

// A file in the temporary directory, removed again at the end of the test.
class TempObj {
public:
    explicit TempObj(const std::string& text) {
        static int counter = 0;
        path_ = (std::filesystem::temp_directory_path() /
                 fmt::format("glslrun_mesh_test_{}_{}.obj", getpid(), counter++)).string();
        std::ofstream(path_, std::ios::binary) << text;
    }
    ~TempObj() { std::filesystem::remove(path_); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Loads `text` and expects an error at `line` (0: any) that names the file.
std::string obj_error(const std::string& text, int line = 0) {
    TempObj file(text);
    Result<Mesh> mesh = load_obj(file.path());
    REQUIRE(!mesh.ok());
    const Diagnostic& d = mesh.error().diagnostics.at(0);
    CHECK(d.file == file.path());
    if (line) CHECK(d.line == line);
    return d.message;
}

}  // namespace

TEST_CASE("OBJ: quads with normals and texture coordinates", "[mesh]") {
    Result<Mesh> cube = load_obj(data_path("mesh_cube.obj"));
    REQUIRE(cube.ok());
    check_basics(*cube);
    CHECK(cube->vertex_count == 24);  // each corner has its own (v, vt, vn)
    CHECK(cube->indices.size() == 12 * 3);
    CHECK(wrongly_wound(*cube) == 0);
    CHECK(bounds(*cube).hi == glm::dvec3(0.5));
    const VertexAttrib& tex = attrib(*cube, "gl_MultiTexCoord0", 2);
    CHECK(std::vector<float>(tex.data.begin(), tex.data.begin() + 8) == std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1});
}

TEST_CASE("OBJ: flat normals when the file has none", "[mesh]") {
    Result<Mesh> pyramid = load_obj(data_path("mesh_pyramid.obj"));
    REQUIRE(pyramid.ok());
    check_basics(*pyramid);
    CHECK(pyramid->vertex_count == 4 + 4 * 3);  // corners are per face
    CHECK(pyramid->indices.size() == 6 * 3);
    CHECK(wrongly_wound(*pyramid) == 0);
    const VertexAttrib& nrm = attrib(*pyramid, "gl_Normal", 3);
    CHECK(vec3_at(nrm, 0) == glm::dvec3(0, -1, 0));  // the base
    CHECK(vec3_at(nrm, 4).z > 0);                    // the first side faces +z
    CHECK(attrib(*pyramid, "gl_MultiTexCoord0", 2).data[0] == 0);
}

TEST_CASE("OBJ: line endings and shared corners", "[mesh]") {
    for (const char* eol : {"\n", "\r\n", "\r"}) {
        std::string text;
        for (const char* line : {"v 0 0 0", "v 1 0 0", "v 1 1 0", "v 0 1 0", "f 1 2 3", "f 1 3 4"})
            text += std::string(line) + eol;
        TempObj file(text);
        Result<Mesh> mesh = load_obj(file.path());
        REQUIRE(mesh.ok());
        // No normals: each face has its own corners, even where positions repeat.
        CHECK(mesh->vertex_count == 6);
        CHECK(mesh->indices.size() == 6);
    }
    TempObj shared("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n");
    Result<Mesh> mesh = load_obj(shared.path());
    REQUIRE(mesh.ok());
    CHECK(mesh->vertex_count == 4);
}

TEST_CASE("OBJ: missing and unreadable files", "[mesh]") {
    const std::string missing = data_path("no_such_mesh.obj");
    Result<Mesh> mesh = load_obj(missing);
    REQUIRE(!mesh.ok());
    CHECK(mesh.error().diagnostics.at(0).file == missing);
    CHECK_THAT(mesh.error().str(), Catch::Contains("no such file"));
    Result<Mesh> dir = load_obj(data_path(""));
    REQUIRE(!dir.ok());
    CHECK_THAT(dir.error().str(), Catch::Contains("directory"));
}

TEST_CASE("OBJ: malformed lines are cited", "[mesh]") {
    const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    CHECK_THAT(obj_error(""), Catch::Contains("no faces"));
    CHECK_THAT(obj_error(v3 + "l 1 2\n"), Catch::Contains("no faces"));
    CHECK_THAT(obj_error("v 1 2\n", 1), Catch::Contains("needs 3 to 7 numbers"));
    CHECK_THAT(obj_error(v3 + "f 1 2\n", 4), Catch::Contains("at least 3"));
    CHECK_THAT(obj_error(v3 + "f 1 2 3/\n", 4), Catch::Contains("missing texture coordinate index"));
    CHECK_THAT(obj_error(v3 + "f 1 2 3//\n", 4), Catch::Contains("missing normal index"));
    CHECK_THAT(obj_error(v3 + "f 1 2 3/1/1/1\n", 4), Catch::Contains("not a corner"));
    CHECK_THAT(obj_error(v3 + "f 1 2 4\n", 4), Catch::Contains("vertex index 4 is out of range: only 3"));
    CHECK_THAT(obj_error(v3 + "f 1 2 0\n", 4), Catch::Contains("index 0"));
    CHECK_THAT(obj_error(v3 + "f 1 2 -4\n", 4), Catch::Contains("out of range"));
    CHECK_THAT(obj_error(v3 + "f 1 2 99999999999999999999999999\n", 4), Catch::Contains("out of range"));
    CHECK_THAT(obj_error(v3 + "f 1/1 2/1 3/1\n", 4), Catch::Contains("texture coordinate index 1 is out of range"));
    CHECK_THAT(obj_error(v3 + "f 1//2 2//2 3//2\n", 4), Catch::Contains("normal index 2 is out of range"));
    CHECK_THAT(obj_error("f 1 2 3\n" + v3, 1), Catch::Contains("none defined before"));  // no forward refs
    CHECK_THAT(obj_error("v nan 0 0\n", 1), Catch::Contains("not a number"));
    CHECK_THAT(obj_error("v 1e39 0 0\n", 1), Catch::Contains("too large"));
    CHECK_THAT(obj_error("v 1 2 3 # trailing\n", 1), Catch::Contains("not a number"));
    CHECK_THAT(obj_error("vn 0 0\n", 1), Catch::Contains("needs 3 numbers"));
    CHECK_THAT(obj_error("# fine\n\n  3 4 5\n", 3), Catch::Contains("not an OBJ statement"));
    CHECK_THAT(obj_error(v3 + std::string("v 1 2 \0 3\n", 10), 4), Catch::Contains("byte 0x00 in column 7"));
    std::string big = v3 + "f";
    for (int i = 0; i < 300; ++i) big += " 1";
    CHECK_THAT(obj_error(big + "\n", 4), Catch::Contains("at most 255"));
    // Left to tinyobjloader (its own extension): its message and line number come through.
    CHECK_THAT(obj_error(v3 + "vw 0 -1 0.5\n", 4), Catch::Contains("OBJ file not understood"));
}

TEST_CASE("OBJ: garbage never crashes", "[mesh]") {
    std::mt19937 rng(12345);
    std::ifstream in(data_path("mesh_cube.obj"), std::ios::binary);
    const std::string valid((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(!valid.empty());
    const std::string alphabet = "0123456789 /-+.e\nfvtn#\r\t";
    for (int round = 0; round < 300; ++round) {
        std::string text;
        if (round < 50) {  // random bytes
            text.resize(rng() % 400);
            for (char& c : text) c = char(rng() % 256);
        } else if (round < 100) {  // truncated
            text = valid.substr(0, rng() % valid.size());
        } else {  // mutated: digits, slashes, signs and line breaks in random places
            text = valid;
            for (int k = 0, edits = 1 + int(rng() % 6); k < edits; ++k)
                text[rng() % text.size()] = alphabet[rng() % alphabet.size()];
        }
        TempObj file(text);
        Result<Mesh> mesh = load_obj(file.path());
        if (mesh.ok()) {
            check_basics(*mesh, /*unit_normals=*/false);
            CHECK(!mesh->indices.empty());
        } else {
            CHECK(mesh.error().diagnostics.at(0).file == file.path());
        }
    }
}
