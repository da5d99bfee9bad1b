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
};

// Triangle i of GL_TRIANGLES: draw() makes these on the fly instead of an
// array (for a 262k-triangle draw the array cost 2.4% of the frame: perf).
inline AssembledPrim triangle_at(uint32_t i) { return {{3 * i, 3 * i + 1, 3 * i + 2}, 3 * i + 2, 3, 7}; }

// Quads split 0-1-2 / 0-2-3 as llvmpipe does; polygons become fans around
// vertex 0. Incomplete trailing primitives are dropped.
// `unfilled` (glPolygonMode other than GL_FILL on a face): quads, quad strips
// and polygons split as Mesa's draw pipeline splits them for its unfilled
// stage (quads 0-1-3 / 1-2-3, polygons (i+1, i+2, 0)), so that both draw
// the same edges in the same order and fill the other face alike.
std::vector<AssembledPrim> assemble(Primitive prim, uint32_t n, bool unfilled = false);
// The same into `out`, whose storage is reused.
void assemble(Primitive prim, uint32_t n, std::vector<AssembledPrim>& out, bool unfilled = false);

}  // namespace glslrun::raster
