// Point and line rasterization (GL 2.1 §3.4, §3.5, non-antialiased), feeding
// the fragment stage in 2x2 quads.
#pragma once
#include "raster/fragments.h"

namespace glslrun::raster {

// Point size as GL rasterizes it: rounded to an integer, at least 1.
int point_pixels(float size);
// Line width as GL rasterizes non-antialiased lines: rounded, at least 1 (at most 255).
int line_pixels(float width);

// The pixels a point covers, before the scissor: a size x size square.
Rect point_rect(const FsPrimitive& prim);

// A point covers the size x size square whose lower-left pixel is
// floor(centre - size/2 + 0.5); prim.count must be 1 and prim.point_size
// already whole (point_pixels). prim must outlive the stage's next flush.
void rasterize_point(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor);

// A line covers one pixel per column (x-major) or row (y-major) whose centre
// lies on [start, end), and a line of width w a column (row) of w pixels
// whose lowest is that of the line moved by -(w-1)/2 across (GL 2.1
// §3.5.2); prim.count must be 2. prim must outlive the stage's next flush.
void rasterize_line(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor);

// The pixels rasterize_line visits, in order (for tests).
template <class Visit>
void for_each_line_pixel(glm::vec2 a, glm::vec2 b, const Rect& scissor, Visit&& visit, int width = 1);

}  // namespace glslrun::raster

#include <algorithm>
#include <cmath>

namespace glslrun::raster {

template <class Visit>
void for_each_line_pixel(glm::vec2 a, glm::vec2 b, const Rect& scissor, Visit&& visit, int width) {
    glm::vec2 d = b - a;
    bool x_major = std::fabs(d.x) >= std::fabs(d.y);
    int major = x_major ? 0 : 1;
    float start = a[major], end = b[major], delta = d[major];
    if (delta == 0.0f || !std::isfinite(delta)) return;
    // Pixel centres c = i + 0.5 with c in [start, end) (or (end, start] going backwards).
    int step = delta > 0 ? 1 : -1;
    int first = step > 0 ? int(std::ceil(start - 0.5f)) : int(std::floor(start - 0.5f));
    int lo = x_major ? scissor.x0 : scissor.y0, hi = x_major ? scissor.x1 : scissor.y1;
    first = step > 0 ? std::max(first, lo) : std::min(first, hi - 1);
    for (int i = first;; i += step) {
        float c = float(i) + 0.5f;
        if (step > 0 ? c >= end : c <= end) break;
        if (step > 0 ? i >= hi : i < lo) break;
        float t = (c - start) / delta;
        float minor = a[1 - major] + t * d[1 - major] - float(width - 1) * 0.5f;
        int lowest = int(std::floor(minor));
        for (int j = lowest; j < lowest + width; ++j) {
            int x = x_major ? i : j, y = x_major ? j : i;
            if (x < scissor.x0 || x >= scissor.x1 || y < scissor.y0 || y >= scissor.y1) continue;
            visit(x, y);
        }
    }
}

}  // namespace glslrun::raster
