// mesh = "arrays": inline vertex arrays into Mesh attributes, primitive
// types and indices, and errors with file:line for arrays that do not fit.
#include "parse_helpers.h"

using namespace scene_test;
using namespace glslrun;

TEST_CASE("inline arrays become the mesh's attributes", "[scene][arrays]") {
    Scene s = parse_ok(R"(
[[objects]]
mesh = "arrays"
primitive = "quad_strip"
vertices = [[0, 0], [1, 0], [0, 1], [1, 1]]
normals = [[0, 0, 1], [0, 0, 1], [0, 1, 0], [1, 0, 0]]
colors = [[1, 0, 0, 0.5], [0, 1, 0, 1], [0, 0, 1, 1], [1, 1, 1, 1]]
secondary_colors = [[0.1, 0.2, 0.3], [0, 0, 0], [0, 0, 0], [0, 0, 0]]
tex_coords = { 0 = [[0, 0], [1, 0], [0, 1], [1, 1]], 7 = [0.5, 0.25, 0, 1] }
fog_coords = [0, 0.5, 1, 2]
indices = [3, 2, 1, 0]
attributes = { weight = [1, 2, 3, 4] }
)");
    REQUIRE(s.objects.size() == 1);
    const scene::Mesh& m = s.objects[0].mesh;
    CHECK(m.primitive == Primitive::QuadStrip);
    CHECK(m.vertex_count == 4);
    CHECK(m.indices == std::vector<uint32_t>{3, 2, 1, 0});
    auto find = [&](const char* name) {
        const VertexAttrib* a = m.find(name);
        INFO(name);
        REQUIRE(a);
        return *a;
    };
    CHECK(find("gl_Vertex").components == 2);
    CHECK(find("gl_Vertex").data == std::vector<float>{0, 0, 1, 0, 0, 1, 1, 1});
    CHECK(find("gl_Normal").data[5] == 1.0f);
    CHECK(find("gl_Color").components == 4);
    CHECK(find("gl_Color").data[3] == 0.5f);
    CHECK(find("gl_SecondaryColor").data[1] == 0.2f);
    CHECK(find("gl_MultiTexCoord0").components == 2);
    CHECK(find("gl_MultiTexCoord7").components == 1);
    CHECK(find("gl_MultiTexCoord7").data[1] == 0.25f);
    CHECK(find("gl_FogCoord").data[3] == 2.0f);
    CHECK(find("weight").data[2] == 3.0f);
}

TEST_CASE("every GL 2.1 primitive type has its name", "[scene][arrays]") {
    const char* names[] = {"points", "lines", "line_strip", "line_loop", "triangles", "triangle_strip",
                           "triangle_fan", "quads", "quad_strip", "polygon"};
    for (int i = 0; i < 10; ++i) {
        Scene s = parse_ok(std::string("[[objects]]\nmesh = \"arrays\"\nprimitive = \"") + names[i] +
                           "\"\nvertices = [[0, 0]]\n");
        CHECK(s.objects[0].mesh.primitive == Primitive(i));
    }
    // Triangles by default, as glDrawArrays(GL_TRIANGLES) is the common call.
    CHECK(parse_ok("[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0]]\n").objects[0].mesh.primitive ==
          Primitive::Triangles);
}

TEST_CASE("arrays that do not fit are errors citing their line", "[scene][arrays][errors]") {
    check_cases({
        {"[[objects]]\nmesh = \"arrays\"\nprimitive = \"triangle\"\nvertices = [[0, 0]]\n", 3,
         "did you mean 'triangles'?"},
        {"[[objects]]\nmesh = \"arrays\"\nprimitive = \"points\"\n", 1, "vertices"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = []\n", 3, "has 0 vertices; arrays hold 1.."},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0], [1, 0]]\ncolors = [[1, 0, 0]]\n", 4,
         "attribute 'gl_Color' has 1 values; the mesh has 2 vertices"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0], [1, 0]]\nattributes = { w = [1] }\n", 4,
         "attribute 'w' has 1 values; the mesh has 2 vertices"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0], [1, 0]]\nindices = [0, 1,\n 2]\n", 5,
         "'objects[0].indices[2]' = 2 is out of range: the arrays have 2 vertices (0..1)"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0]]\nindices = [-1]\n", 4, "is out of range"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0]]\nindices = [0.5]\n", 4, "must be an integer"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [0, 1]\n", 3, "needs 2 to 4 components per vertex (glVertexPointer)"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0]]\nnormals = [[0, 1]]\n", 4,
         "needs 3 components per vertex (glNormalPointer)"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0]]\ntex_coords = { 8 = [0] }\n", 4,
         "texture coordinate sets are 0..7"},
        {"[[objects]]\nmesh = \"arrays\"\nvertices = [[0, 0], [1, 0, 0]]\n", 3, "has 3 components; element 0 has 2"},
        {"[[objects]]\nmesh = \"quad\"\nvertices = [[0, 0]]\n", 3, "vertices"},
    });
}
