// Primitive assembly: which vertices form each point, line or triangle, and
// which one is the provoking vertex for flat shading (GL 2.1 table 2.12).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::raster {

struct AssembledPrim {
    std::array<uint32_t, 3> v{};  // positions in the vertex stream
    uint32_t provoking = 0;
    int count = 3;  // 1, 2 or 3
    // Triangles: bit k set when edge v[k] -> v[k+1 mod 3] is an edge of the
    // primitive the program drew (GL's edge flags), not a diagonal that
    // splits a quad or polygon; glPolygonMode's line and point modes draw
    // those edges and their first vertices.
    uint8_t edges = 7;
    // Whether the line stipple counter restarts here (GL 2.1 §3.5.2): at
    // every line of GL_LINES, the first of a strip or loop, and, for the
    // edges of glPolygonMode(GL_LINE), every polygon (Mesa: each triangle of
    // a list, strip or fan, the first of each quad and of a polygon).
    bool restarts_stipple = true;
};

// Triangle i of GL_TRIANGLES: draw() makes these on the fly instead of an
// array (for a 262k-triangle draw the array cost 2.4% of the frame: perf).
inline AssembledPrim triangle_at(uint32_t i) { return {{3 * i, 3 * i + 1, 3 * i + 2}, 3 * i + 2, 3, 7, true}; }

// Quads split 0-1-2 / 0-2-3 as llvmpipe does; polygons become fans around
// vertex 0. Incomplete trailing primitives are dropped.
// `unfilled` (glPolygonMode other than GL_FILL on a face, or the polygon
// stipple: what sends Mesa's polygons through its draw pipeline): quads,
// quad strips and polygons split as that pipeline splits them (quads 0-1-3 /
// 1-2-3, polygons (i+1, i+2, 0)), so that both draw the same edges in the
// same order and interpolate across the same diagonals.
std::vector<AssembledPrim> assemble(Primitive prim, uint32_t n, bool unfilled = false);
// The same into `out`, whose storage is reused.
void assemble(Primitive prim, uint32_t n, std::vector<AssembledPrim>& out, bool unfilled = false);

}  // namespace glslrun::raster
