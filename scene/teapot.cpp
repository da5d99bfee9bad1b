// The lecture's teapot (mesh = "teapot", docs/scene-format.md): freeglut 3.x's
// glutSolidTeapot geometry at any density. Every detail below (patch order,
// the (u, v) roles, the vertex numbering, the normal's cross product, the
// triangle split) is fixed, because the reference images were made from
// these exact arrays (tests/scene/meshes_test.cpp checks them).
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include <glm/glm.hpp>

#include "glslrun/scene/meshes.h"

namespace glslrun::scene {

namespace teapot_data {
extern const double kControlPoints[306][3];
extern const int kPatches[32][16];
}  // namespace teapot_data

namespace {

constexpr int kPatchCount = 32;

// Control points of one patch, [row * 4 + column]; u runs over rows, v over columns.
using Patch = std::array<glm::dvec3, 16>;

// freeglut bakes classic GLUT's glRotated(270,1,0,0), glScaled(s/2) and
// glTranslated(0,0,-1.575) into the control points: y becomes up and the
// teapot is centred on y = 0. Doing it here (not on the evaluated points)
// follows freeglut, so rounding happens in the same order.
Patch transformed_patch(int p, double size) {
    Patch cp;
    for (int k = 0; k < 16; ++k) {
        const double* c = teapot_data::kControlPoints[teapot_data::kPatches[p][k]];
        cp[k] = glm::dvec3(c[0], c[2] - 1.575, -c[1]) * (size / 2);
    }
    return cp;
}

// Cubic Bernstein polynomials and their derivatives at t.
struct Bernstein {
    std::array<double, 4> b, d;
};

Bernstein bernstein(double t) {
    const double s = 1 - t;
    return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t},
            {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t}};
}

struct Sample {
    glm::dvec3 pos{0.0}, du{0.0}, dv{0.0};  // P, dP/du, dP/dv
};

Sample evaluate(const Patch& cp, const Bernstein& bu, const Bernstein& bv) {
    Sample s;
    for (int i = 0; i < 4; ++i) {
        glm::dvec3 row(0.0), row_dv(0.0);
        for (int j = 0; j < 4; ++j) {
            row += bv.b[j] * cp[i * 4 + j];
            row_dv += bv.d[j] * cp[i * 4 + j];
        }
        s.pos += bu.b[i] * row;
        s.dv += bu.b[i] * row_dv;
        s.du += bu.d[i] * row;
    }
    return s;
}

// A collapsed control row (lid-knob tip, bottom centre) makes one tangent
// vanish, so the cross product is zero up to rounding; relative to the other
// tangent that is unmistakable.
bool degenerate(const glm::dvec3& n, const Sample& s) {
    const double scale = std::max(glm::length(s.du), glm::length(s.dv));
    return glm::length(n) <= 1e-9 * scale * scale;
}

// normalize(dP/dv x dP/du), outward for this data. At a degenerate point the
// surface there is horizontal (a pole of the teapot's axis), so the normal is
// (0, +-1, 0), with the sign of the normal just inside the patch.
glm::dvec3 patch_normal(const Patch& cp, double u, double v, const Sample& s) {
    glm::dvec3 n = glm::cross(s.dv, s.du);
    if (!degenerate(n, s)) return glm::normalize(n);
    const double nudge = 1e-4;
    const double ui = u < 0.5 ? u + nudge : u - nudge;
    const double vi = v < 0.5 ? v + nudge : v - nudge;
    const Sample inside = evaluate(cp, bernstein(ui), bernstein(vi));
    const double y = glm::cross(inside.dv, inside.du).y;
    return glm::dvec3(0, y < 0 ? -1 : 1, 0);
}

void push3(std::vector<float>& out, const glm::dvec3& v) {
    out.push_back(float(v.x));
    out.push_back(float(v.y));
    out.push_back(float(v.z));
}

// Triangles of one patch's (n+1) x (n+1) grid starting at vertex `base`:
// per cell A=(i-1,j-1), B=(i-1,j), C=(i,j), D=(i,j-1) -> (A,B,C), (A,C,D),
// counter-clockwise seen from the side the normals point to.
void push_patch_triangles(std::vector<uint32_t>& out, uint32_t base, int n) {
    const uint32_t row = uint32_t(n) + 1;
    for (int i = 1; i <= n; ++i) {
        for (int j = 1; j <= n; ++j) {
            const uint32_t a = base + uint32_t(i - 1) * row + uint32_t(j - 1);
            const uint32_t b = a + 1, c = a + row + 1, d = a + row;
            out.insert(out.end(), {a, b, c, a, c, d});
        }
    }
}

}  // namespace

Mesh make_teapot(double size, int subdivisions) {
    assert(subdivisions >= 1 && subdivisions <= kMaxTeapotSubdivisions);
    const int n = subdivisions;
    const size_t per_patch = size_t(n + 1) * size_t(n + 1);
    const size_t vertices = per_patch * kPatchCount;

    // Bernstein values per grid line, shared by all patches (u and v use the same steps).
    std::vector<Bernstein> basis;
    for (int k = 0; k <= n; ++k) basis.push_back(bernstein(double(k) / n));

    std::vector<float> pos, nrm, tex;
    pos.reserve(vertices * 3);
    nrm.reserve(vertices * 3);
    tex.reserve(vertices * 2);
    std::vector<uint32_t> indices;
    indices.reserve(size_t(kPatchCount) * size_t(n) * size_t(n) * 6);

    for (int p = 0; p < kPatchCount; ++p) {
        const Patch cp = transformed_patch(p, size);
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                const double u = double(i) / n, v = double(j) / n;
                const Sample s = evaluate(cp, basis[i], basis[j]);
                push3(pos, s.pos);
                push3(nrm, patch_normal(cp, u, v, s));
                // freeglut 3.x's textured teapot: (s, t) = (u, v) of the patch.
                tex.push_back(float(u));
                tex.push_back(float(v));
            }
        }
        push_patch_triangles(indices, uint32_t(p * per_patch), n);
    }

    Mesh mesh;
    mesh.primitive = Primitive::Triangles;
    mesh.vertex_count = uint32_t(vertices);
    mesh.attribs = {{"gl_Vertex", 3, std::move(pos)},
                    {"gl_Normal", 3, std::move(nrm)},
                    {"gl_MultiTexCoord0", 2, std::move(tex)}};
    mesh.indices = std::move(indices);
    return mesh;
}

}  // namespace glslrun::scene
