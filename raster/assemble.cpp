#include "raster/assemble.h"

namespace glslrun::raster {

namespace {

void add_tri(std::vector<AssembledPrim>& out, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking,
             uint8_t edges = 7, bool restarts = true) {
    out.push_back({{a, b, c}, provoking, 3, edges, restarts});
}

void add_line(std::vector<AssembledPrim>& out, uint32_t a, uint32_t b, uint32_t provoking, bool restarts) {
    out.push_back({{a, b, b}, provoking, 2, 7, restarts});
}

// Quad a-b-c-d: edges a-b, b-c, c-d and d-a.
void add_quad(std::vector<AssembledPrim>& out, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
              uint32_t provoking, bool unfilled) {
    if (unfilled) {
        add_tri(out, a, b, d, provoking, 0b101);  // a-b, d-a
        add_tri(out, b, c, d, provoking, 0b011, false);  // b-c, c-d
        return;
    }
    add_tri(out, a, b, c, provoking, 0b011);  // a-b, b-c
    add_tri(out, a, c, d, provoking, 0b110, false);  // c-d, d-a
}

// Polygon 0..n-1 as triangles (i+1, i+2, 0): edge 0-1 in the first, i+1 -> i+2 in each, n-1 -> 0 in the last.
void add_unfilled_polygon(std::vector<AssembledPrim>& out, uint32_t n) {
    for (uint32_t i = 0; i + 2 < n; ++i)
        add_tri(out, i + 1, i + 2, 0, 0, uint8_t(1 | (i == 0 ? 4 : 0) | (i + 3 == n ? 2 : 0)), i == 0);
}

}  // namespace

std::vector<AssembledPrim> assemble(Primitive prim, uint32_t n, bool unfilled) {
    std::vector<AssembledPrim> out;
    assemble(prim, n, out, unfilled);
    return out;
}

void assemble(Primitive prim, uint32_t n, std::vector<AssembledPrim>& out, bool unfilled) {
    out.clear();
    out.reserve(n);  // no mode makes more primitives than vertices
    switch (prim) {
    case Primitive::Points:
        for (uint32_t i = 0; i < n; ++i) out.push_back({{i, i, i}, i, 1});
        break;
    case Primitive::Lines:
        for (uint32_t i = 0; i + 1 < n; i += 2) add_line(out, i, i + 1, i + 1, true);
        break;
    case Primitive::LineStrip:
        for (uint32_t i = 0; i + 1 < n; ++i) add_line(out, i, i + 1, i + 1, i == 0);
        break;
    case Primitive::LineLoop:
        for (uint32_t i = 0; i + 1 < n; ++i) add_line(out, i, i + 1, i + 1, i == 0);
        if (n >= 2) add_line(out, n - 1, 0, 0, false);  // the loop's counter carries on
        break;
    case Primitive::Triangles:
        for (uint32_t i = 0; 3 * i + 2 < n; ++i) out.push_back(triangle_at(i));
        break;
    case Primitive::TriangleStrip:
        for (uint32_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0) add_tri(out, i, i + 1, i + 2, i + 2);
            else add_tri(out, i + 1, i, i + 2, i + 2);
        }
        break;
    case Primitive::TriangleFan:
        for (uint32_t i = 1; i + 1 < n; ++i) add_tri(out, 0, i, i + 1, i + 1);
        break;
    case Primitive::Quads:
        for (uint32_t i = 0; i + 3 < n; i += 4) add_quad(out, i, i + 1, i + 2, i + 3, i + 3, unfilled);
        break;
    case Primitive::QuadStrip:
        for (uint32_t i = 0; i + 3 < n; i += 2) add_quad(out, unfilled ? i + 2 : i, unfilled ? i : i + 1, unfilled ? i + 1 : i + 3, unfilled ? i + 3 : i + 2,
                     i + 3, unfilled);
        break;
    case Primitive::Polygon:
        if (unfilled) {
            add_unfilled_polygon(out, n);
            break;
        }
        for (uint32_t i = 1; i + 1 < n; ++i)
            add_tri(out, 0, i, i + 1, 0, uint8_t((i == 1 ? 1 : 0) | 2 | (i + 2 == n ? 4 : 0)), i == 1);
        break;
    }
}

}  // namespace glslrun::raster
