// Point and line rasterization (GL 2.1 §3.4, §3.5, non-antialiased), feeding
// the fragment stage in 2x2 quads.
#pragma once
#include <cstdint>

#include "raster/fragments.h"

namespace glslrun::raster {

// A point's square, as llvmpipe (the reference, tools/glref) rasterizes GL
// 2.1 §3.3 in 1/256-pixel fixed point: the size, clamped to [1, 255] (Mesa's
// GL_ALIASED_POINT_SIZE_RANGE), and the centre snapped to 1/256 (nearest,
// ties to even).
//  - Point sprites: a square of the exact size, centred on the point; a
//    pixel is in when its centre is, the left and bottom edges included.
//    gl_PointCoord steps by 1/size per pixel, t from the top down, or from
//    the bottom up with `lower_left` (GL_POINT_SPRITE_COORD_ORIGIN).
//  - Other points (§3.3.1): the size rounded to a whole n (n + 1/2 rounds
//    down, as Mesa), the n x n pixels around floor(centre) (n odd) or
//    floor(centre + 1/2) (n even). gl_PointCoord is undefined; it steps by
//    1/n, t upwards, as Mesa leaves it.
// Sets prim.point_box, point_coord_origin and point_coord_step.
void set_point_square(FsPrimitive& prim, glm::vec2 centre, float size, bool sprite, bool lower_left = false);
// The largest point size: larger sizes draw at this one (as llvmpipe).
inline constexpr float kMaxPointSize = 255.0f;
// Line width as GL rasterizes non-antialiased lines: rounded, at least 1 (at most 255).
int line_pixels(float width);

// A point covers prim.point_box (set_point_square); prim.count must be 1.
// prim must outlive the stage's next flush.
void rasterize_point(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor);

// A non-antialiased line covers the pixels GL 2.1 §3.4.1's diamond-exit rule
// gives, in the form llvmpipe (the reference, tools/glref) rasterizes it: a
// parallelogram `width` pixels across the minor axis, whose ends along the
// major axis are moved to a pixel boundary wherever the half-open span of
// centres would disagree with the diamond rule about the first or last pixel
// (the end point inside a pixel's diamond is not drawn, the start point's
// pixel is). prim.count must be 2. prim must outlive the stage's next flush.
void rasterize_line(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor);

// The corners of that parallelogram in 1/256 pixel with pixel centres on
// whole numbers, clockwise; false for a line of zero length or not finite.
struct LineCorners {
    int64_t x[4], y[4];
};
bool line_corners(glm::vec2 a, glm::vec2 b, int width, LineCorners& out);

// Whether the pixel (x, y) lies in the parallelogram: its centre inside
// every edge, or on a left or top edge (llvmpipe's rule for lines in a
// framebuffer object).
struct LineEdges {
    int64_t c[4], dcdx[4], dcdy[4];
    explicit LineEdges(const LineCorners& q);
    bool covers(int x, int y) const;
};

// The pixels rasterize_line visits, column by column (row by row for a
// y-major line), each once.
template <class Visit>
void for_each_line_pixel(glm::vec2 a, glm::vec2 b, const Rect& scissor, Visit&& visit, int width = 1);

}  // namespace glslrun::raster

#include <algorithm>
#include <cmath>

namespace glslrun::raster {

template <class Visit>
void for_each_line_pixel(glm::vec2 a, glm::vec2 b, const Rect& scissor, Visit&& visit, int width) {
    LineCorners q;
    if (!line_corners(a, b, width, q)) return;
    LineEdges edges(q);
    glm::vec2 d = b - a;
    bool x_major = std::fabs(d.x) >= std::fabs(d.y);
    int major = x_major ? 0 : 1;
    const int64_t* qmajor = x_major ? q.x : q.y;
    // Whole pixels between the corners, widened by one for the fill rule.
    int first = int(std::min({qmajor[0], qmajor[1], qmajor[2], qmajor[3]}) >> 8) - 1;
    int last = int(std::max({qmajor[0], qmajor[1], qmajor[2], qmajor[3]}) >> 8) + 1;
    int lo = x_major ? scissor.x0 : scissor.y0, hi = x_major ? scissor.x1 : scissor.y1;
    first = std::max(first, lo);
    last = std::min(last, hi - 1);
    float slope = d[1 - major] / d[major];
    for (int i = first; i <= last; ++i) {
        // The minor coordinate of the line at this centre, and the pixels
        // within half the width (and the moved ends' reach) of it.
        float minor = a[1 - major] + (float(i) + 0.5f - a[major]) * slope;
        if (!std::isfinite(minor)) continue;
        int j0 = int(std::floor(minor - float(width) * 0.5f)) - 2, j1 = j0 + width + 4;
        for (int j = j0; j <= j1; ++j) {
            int x = x_major ? i : j, y = x_major ? j : i;
            if (x < scissor.x0 || x >= scissor.x1 || y < scissor.y0 || y >= scissor.y1) continue;
            if (edges.covers(x, y)) visit(x, y);
        }
    }
}

}  // namespace glslrun::raster
