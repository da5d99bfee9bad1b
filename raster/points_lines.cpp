#include "raster/points_lines.h"

#include <algorithm>
#include <cmath>

namespace glslrun::raster {

int point_pixels(float size) {
    if (!(size > 0.0f)) return 1;
    return std::clamp(int(std::floor(std::min(size, 4096.0f) + 0.5f)), 1, 4096);
}

int line_pixels(float width) {
    if (!(width > 0.0f)) return 1;
    return std::clamp(int(std::floor(std::min(width, 255.0f) + 0.5f)), 1, 255);
}

Rect point_rect(const FsPrimitive& prim) {
    int s = point_pixels(prim.point_size);
    int x0 = pixel_floor(prim.point_center.x - float(s) * 0.5f + 0.5f);
    int y0 = pixel_floor(prim.point_center.y - float(s) * 0.5f + 0.5f);
    return {x0, y0, x0 + s, y0 + s};
}

void rasterize_point(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor) {
    Rect r = point_rect(prim);
    int bx0 = std::max(r.x0, scissor.x0), by0 = std::max(r.y0, scissor.y0);
    int bx1 = std::min(r.x1, scissor.x1), by1 = std::min(r.y1, scissor.y1);
    if (bx0 >= bx1 || by0 >= by1) return;
    for (int y = by0 & ~1; y < by1; y += 2)
        for (int x = bx0 & ~1; x < bx1; x += 2) {
            unsigned mask = 0;
            for (int i = 0; i < 4; ++i) {
                int px = x + kQuadDx[i], py = y + kQuadDy[i];
                if (px >= bx0 && px < bx1 && py >= by0 && py < by1) mask |= 1u << i;
            }
            if (mask) stage.add_quad(prim, x, y, mask);
        }
}

void rasterize_line(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor) {
    int qx = 0, qy = 0;
    unsigned mask = 0;
    auto emit = [&] {
        if (!mask) return;
        stage.add_quad(prim, qx, qy, mask);
        mask = 0;
    };
    for_each_line_pixel(
        prim.v[0].win, prim.v[1].win, scissor,
        [&](int x, int y) {
            int nx = x & ~1, ny = y & ~1;
            if (mask && (nx != qx || ny != qy)) emit();
            qx = nx;
            qy = ny;
            mask |= 1u << ((x - nx) + 2 * (y - ny));
        },
        prim.line_width);
    emit();
}

}  // namespace glslrun::raster
