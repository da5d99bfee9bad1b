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
};

// Quads split 0-1-2 / 0-2-3 as llvmpipe does; polygons become fans around
// vertex 0. Incomplete trailing primitives are dropped.
std::vector<AssembledPrim> assemble(Primitive prim, uint32_t n);
// The same into `out`, whose storage is reused.
void assemble(Primitive prim, uint32_t n, std::vector<AssembledPrim>& out);

}  // namespace glslrun::raster
