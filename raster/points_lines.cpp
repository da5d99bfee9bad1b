#include "raster/points_lines.h"

#include <algorithm>
#include <cmath>

namespace glslrun::raster {

int point_pixels(float size) {
    if (!(size > 0.0f)) return 1;
    return std::clamp(int(std::floor(std::min(size, 4096.0f) + 0.5f)), 1, 4096);
}

void rasterize_point(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor) {
    int s = point_pixels(prim.point_size);
    FsPrimitive p = prim;
    p.point_size = float(s);
    int x0 = int(std::floor(prim.point_center.x - float(s) * 0.5f + 0.5f));
    int y0 = int(std::floor(prim.point_center.y - float(s) * 0.5f + 0.5f));
    int bx0 = std::max(x0, scissor.x0), by0 = std::max(y0, scissor.y0);
    int bx1 = std::min(x0 + s, scissor.x1), by1 = std::min(y0 + s, scissor.y1);
    if (bx0 >= bx1 || by0 >= by1) return;
    const std::array<glm::dvec3, 4> weights{glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0),
                                            glm::dvec3(1, 0, 0)};
    for (int y = by0 & ~1; y < by1; y += 2)
        for (int x = bx0 & ~1; x < bx1; x += 2) {
            unsigned mask = 0;
            for (int i = 0; i < 4; ++i) {
                int px = x + kQuadDx[i], py = y + kQuadDy[i];
                if (px >= bx0 && px < bx1 && py >= by0 && py < by1) mask |= 1u << i;
            }
            if (mask) stage.add_quad(p, x, y, mask, weights);
        }
}

namespace {

// Weights of a pixel centre projected onto the line's major axis.
glm::dvec3 line_weights(const FsPrimitive& prim, int x, int y) {
    glm::dvec2 a = prim.v[0].win, b = prim.v[1].win;
    glm::dvec2 d = b - a;
    int major = std::fabs(d.x) >= std::fabs(d.y) ? 0 : 1;
    glm::dvec2 c(x + 0.5, y + 0.5);
    double t = (c[major] - a[major]) / d[major];
    return {1.0 - t, t, 0.0};
}

}  // namespace

void rasterize_line(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor) {
    int qx = 0, qy = 0;
    unsigned mask = 0;
    auto emit = [&] {
        if (!mask) return;
        std::array<glm::dvec3, 4> weights;
        for (int i = 0; i < 4; ++i) weights[i] = line_weights(prim, qx + kQuadDx[i], qy + kQuadDy[i]);
        stage.add_quad(prim, qx, qy, mask, weights);
        mask = 0;
    };
    for_each_line_pixel(prim.v[0].win, prim.v[1].win, scissor, [&](int x, int y) {
        int nx = x & ~1, ny = y & ~1;
        if (mask && (nx != qx || ny != qy)) emit();
        qx = nx;
        qy = ny;
        mask |= 1u << ((x - nx) + 2 * (y - ny));
    });
    emit();
}

}  // namespace glslrun::raster
