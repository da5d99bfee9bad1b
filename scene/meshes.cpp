// The simple built-in meshes (the teapot is in teapot.cpp, OBJ files in
// obj.cpp). Each is computed in double and stored as float, front faces
// counter-clockwise seen from outside (GL's default GL_CCW), with the
// parameterisation documented at each builder so texture coordinates are
// predictable.
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "glslrun/scene/meshes.h"
#include "scene/trig.h"

namespace glslrun::scene {

namespace {

// Collects vertices and triangles, then becomes a Mesh with gl_Vertex,
// gl_Normal and gl_MultiTexCoord0.
struct MeshBuilder {
    std::vector<float> pos, nrm, tex;
    std::vector<uint32_t> indices;

    // Room for the mesh's vertices and triangles, known from its parameters
    // (a plane of 1024 subdivisions has a million vertices: no regrowing).
    MeshBuilder(size_t vertices, size_t triangles) {
        pos.reserve(3 * vertices);
        nrm.reserve(3 * vertices);
        tex.reserve(2 * vertices);
        indices.reserve(3 * triangles);
    }

    uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec2& st) {
        const uint32_t index = uint32_t(pos.size() / 3);
        pos.insert(pos.end(), {float(p.x), float(p.y), float(p.z)});
        nrm.insert(nrm.end(), {float(n.x), float(n.y), float(n.z)});
        tex.insert(tex.end(), {float(st.x), float(st.y)});
        return index;
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }

    Mesh finish() {
        Mesh mesh;
        mesh.primitive = Primitive::Triangles;
        mesh.vertex_count = uint32_t(pos.size() / 3);
        mesh.attribs = {{"gl_Vertex", 3, std::move(pos)},
                        {"gl_Normal", 3, std::move(nrm)},
                        {"gl_MultiTexCoord0", 2, std::move(tex)}};
        mesh.indices = std::move(indices);
        return mesh;
    }
};

// cos/sin of 2*pi*k/count, exact at the quarter turns and identical for k = 0
// and k = count, so the duplicated seam vertices of a closed surface coincide.
glm::dvec2 unit_circle(int k, int count) {
    k %= count;
    if (4 * k % count == 0) {
        constexpr std::array<glm::dvec2, 4> quarter{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
        return quarter[size_t(4 * k / count)];
    }
    const double angle = 2 * std::numbers::pi * k / count;
    const auto [sin, cos] = sin_cos(angle);
    return {cos, sin};
}

// Two triangles per grid cell of `columns` x `rows` cells laid out row-major
// with (columns + 1) vertices per row: (a, b, c), (a, c, d) with a = (r, k),
// b = (r, k+1), c = (r+1, k+1), d = (r+1, k). They are counter-clockwise seen
// from outside when d(column) x d(row) points outwards. With `poles`, the
// first and the last row of vertices are each a single point (a sphere's
// poles), and the zero-area triangle of each cell there is left out.
size_t grid_vertices(int columns, int rows) { return (size_t(columns) + 1) * (size_t(rows) + 1); }

void grid_triangles(MeshBuilder& m, int columns, int rows, bool poles = false) {
    const uint32_t stride = uint32_t(columns) + 1;
    for (int r = 0; r < rows; ++r) {
        for (int k = 0; k < columns; ++k) {
            const uint32_t a = uint32_t(r) * stride + uint32_t(k);
            const uint32_t b = a + 1, c = a + stride + 1, d = a + stride;
            if (!(poles && r == 0)) m.triangle(a, b, c);         // a == b at the first pole
            if (!(poles && r == rows - 1)) m.triangle(a, c, d);  // c == d at the last pole
        }
    }
}

}  // namespace

Mesh make_lecture_quad() {
    // The lecture's glBegin(GL_QUADS) with glColor3f per vertex; drawn as
    // GL_QUADS so the pipeline makes the split (0-1-2 / 0-2-3, as llvmpipe).
    Mesh mesh;
    mesh.primitive = Primitive::Quads;
    mesh.vertex_count = 4;
    mesh.attribs = {
        {"gl_Vertex", 3, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}},
        {"gl_Normal", 3, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}},
        {"gl_Color", 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0}},
        {"gl_MultiTexCoord0", 2, {0, 0, 1, 0, 1, 1, 0, 1}},
    };
    return mesh;
}

Mesh make_cube(double size) {
    // Six faces of four vertices (flat normals need their own vertices), in
    // the order +x, -x, +y, -y, +z, -z. On each face s runs along `right`
    // and t along normal x right, i.e. "up" when the face is seen from outside.
    struct Face {
        glm::dvec3 normal, right;
    };
    constexpr std::array<Face, 6> faces{{{{1, 0, 0}, {0, 0, -1}},
                                         {{-1, 0, 0}, {0, 0, 1}},
                                         {{0, 1, 0}, {1, 0, 0}},
                                         {{0, -1, 0}, {1, 0, 0}},
                                         {{0, 0, 1}, {1, 0, 0}},
                                         {{0, 0, -1}, {-1, 0, 0}}}};
    constexpr std::array<glm::dvec2, 4> corners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    const double h = size / 2;
    MeshBuilder m(24, 12);
    for (const Face& f : faces) {
        const glm::dvec3 up = glm::cross(f.normal, f.right);
        uint32_t first = 0;
        for (size_t k = 0; k < corners.size(); ++k) {
            const glm::dvec2 st = corners[k];
            const glm::dvec3 p = h * (f.normal + (2 * st.x - 1) * f.right + (2 * st.y - 1) * up);
            const uint32_t index = m.vertex(p, f.normal, st);
            if (k == 0) first = index;
        }
        m.triangle(first, first + 1, first + 2);
        m.triangle(first, first + 2, first + 3);
    }
    return m.finish();
}

Mesh make_sphere(double radius, int slices, int stacks) {
    // gluSphere's parameterisation: stack i (0..stacks) at polar angle
    // phi = pi*i/stacks from +z, slice j (0..slices) at theta = 2*pi*j/slices
    // from +y towards +x: P = r (sin(theta) sin(phi), cos(theta) sin(phi), cos(phi)),
    // normal P/r, (s, t) = (j/slices, 1 - i/stacks). The seam column and the
    // poles are repeated per slice (so each keeps its own s); the pole cells'
    // zero-area triangles are left out: (stacks+1)(slices+1) vertices, vertex
    // i*(slices+1) + j, and 2 * slices * (stacks - 1) triangles.
    assert(slices >= 3 && stacks >= 2 && slices <= kMaxSubdivisions && stacks <= kMaxSubdivisions);
    MeshBuilder m(grid_vertices(slices, stacks), 2 * size_t(slices) * size_t(stacks - 1));
    for (int i = 0; i <= stacks; ++i) {
        // Polar angle as a half turn of a full circle of 2*stacks steps.
        const glm::dvec2 polar = unit_circle(i, 2 * stacks);  // (cos phi, sin phi)
        for (int j = 0; j <= slices; ++j) {
            const glm::dvec2 az = unit_circle(j, slices);  // (cos theta, sin theta)
            const glm::dvec3 n(az.y * polar.y, az.x * polar.y, polar.x);
            m.vertex(radius * n, n, {double(j) / slices, 1 - double(i) / stacks});
        }
    }
    grid_triangles(m, slices, stacks, /*poles=*/true);
    return m.finish();
}

Mesh make_torus(double inner_radius, double outer_radius, int sides, int rings) {
    // glutSolidTorus: a tube of radius `inner_radius` whose centre circle has
    // radius `outer_radius` around z. Ring i (0..rings) at phi = 2*pi*i/rings
    // around z, side j (0..sides) at theta = 2*pi*j/sides around the tube:
    // P = ((R + r cos theta) cos phi, (R + r cos theta) sin phi, r sin theta),
    // normal (cos theta cos phi, cos theta sin phi, sin theta),
    // (s, t) = (i/rings, j/sides). Seams repeated: (rings+1)(sides+1) vertices,
    // vertex j*(rings+1) + i; 2 * rings * sides triangles.
    assert(sides >= 3 && rings >= 3 && sides <= kMaxSubdivisions && rings <= kMaxSubdivisions);
    // Rows are sides and columns rings, so that d(ring) x d(side) points out.
    MeshBuilder m(grid_vertices(rings, sides), 2 * size_t(rings) * size_t(sides));
    for (int j = 0; j <= sides; ++j) {
        const glm::dvec2 side = unit_circle(j, sides);
        for (int i = 0; i <= rings; ++i) {
            const glm::dvec2 ring = unit_circle(i, rings);
            const glm::dvec3 n(side.x * ring.x, side.x * ring.y, side.y);
            const glm::dvec3 centre(outer_radius * ring.x, outer_radius * ring.y, 0);
            m.vertex(centre + inner_radius * n, n, {double(i) / rings, double(j) / sides});
        }
    }
    grid_triangles(m, rings, sides);
    return m.finish();
}

Mesh make_plane(double size, int subdivisions) {
    // Row i (0..n) at y = size*(i/n - 1/2), column j at x = size*(j/n - 1/2);
    // normal +z; (s, t) = (j/n, i/n), so the texture sits upright seen from +z.
    assert(subdivisions >= 1 && subdivisions <= kMaxSubdivisions);
    const int n = subdivisions;
    MeshBuilder m(grid_vertices(n, n), 2 * size_t(n) * size_t(n));
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            const glm::dvec2 st(double(j) / n, double(i) / n);
            m.vertex({size * (st.x - 0.5), size * (st.y - 0.5), 0}, {0, 0, 1}, st);
        }
    }
    grid_triangles(m, n, n);
    return m.finish();
}

void add_normal_colors(Mesh& mesh) {
    // The lecture's `colors` teapot: glColorPointer with 0.5 + 0.5 * normal.
    const VertexAttrib* normal = mesh.find("gl_Normal");
    assert(normal && normal->components == 3);
    if (!normal || normal->components != 3) return;  // every mesh here has one
    VertexAttrib color{"gl_Color", 4, {}};
    color.data.reserve(size_t(mesh.vertex_count) * 4);
    for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
        for (uint32_t c = 0; c < 3; ++c) color.data.push_back(0.5f + 0.5f * normal->data[v * 3 + c]);
        color.data.push_back(1.0f);
    }
    std::erase_if(mesh.attribs, [](const VertexAttrib& a) { return a.name == "gl_Color"; });
    mesh.attribs.push_back(std::move(color));
}

}  // namespace glslrun::scene
