#include "raster/points_lines.h"

#include <algorithm>
#include <cmath>

namespace glslrun::raster {

namespace {

// llvmpipe's subpixel_snap: 1/256 pixel, to nearest even (lrintf).
int64_t snap256(float v) { return std::llrint(v * 256.0f); }
// The first whole pixel at or after v/256.
int ceil256(int64_t v) { return int((v + 255) >> 8); }

}  // namespace

void set_point_square(FsPrimitive& prim, glm::vec2 centre, float size, bool sprite, bool lower_left) {
    const int64_t width = snap256(size > 1.0f ? std::min(size, kMaxPointSize) : 1.0f);  // NaN -> 1
    float step = 1.0f;
    if (sprite) {
        // Pixel x is in when x0 <= 256 x < x0 + width, the centres at whole
        // numbers (the half-pixel offset taken off first, as llvmpipe).
        const int64_t x0 = snap256(centre.x - 0.5f) - width / 2, y0 = snap256(centre.y - 0.5f) - width / 2;
        prim.point_box = {ceil256(x0), ceil256(y0), ceil256(x0 + width), ceil256(y0 + width)};
        step = 256.0f / float(width);
    } else {
        const int n = int((width + 127) >> 8);
        auto first = [n](float c) {
            int64_t fixed = snap256(c);
            return int(n & 1 ? (fixed >> 8) - (n - 1) / 2 : ((fixed + 128) >> 8) - n / 2);
        };
        const int x0 = first(centre.x), y0 = first(centre.y);
        prim.point_box = {x0, y0, x0 + n, y0 + n};
        step = 1.0f / float(n);
    }
    // llvmpipe's plane constants, 0.5 - d (centre - 1/2) in double rounded
    // once. With sprites t runs down from the top (GL's upper-left origin
    // in a framebuffer object) unless the origin is the lower left; without
    // them up, as Mesa leaves it.
    const float t_step = sprite && !lower_left ? -step : step;
    prim.point_coord_step = {step, t_step};
    prim.point_coord_origin = {float(0.5 - double(step * (centre.x - 0.5f))),
                               float(0.5 - double(t_step * (centre.y - 0.5f)))};
}

int line_pixels(float width) {
    if (!(width > 0.0f)) return 1;
    return std::clamp(int(std::floor(std::min(width, 255.0f) + 0.5f)), 1, 255);
}

void rasterize_point(FragmentStage& stage, const FsPrimitive& prim, const Rect& scissor) {
    const Rect& r = prim.point_box;
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

namespace {

// GL's pixel centres lie at +0.5; the corners are kept with centres on whole
// numbers, in 1/256 pixel rounded to nearest even, as llvmpipe snaps them.
int64_t snap_fixed(float v) { return std::llrint((v - 0.5f) * 256.0f); }
bool non_negative(float v) { return v >= 0.0f; }
float fraction(float v) { return v - std::floor(v); }

// Where an end point lies in its pixel, from the centre: (-0.5, -0.5) to (0.5, 0.5).
glm::vec2 from_centre(glm::vec2 p) { return p - glm::floor(p) - 0.5f; }

// The diamond-exit test for one end point: the start's pixel is drawn when
// the line leaves its diamond, the end's when the line leaves the diamond
// before reaching the end point. `along` and `across` are the major and
// minor components of the point's offset from its pixel's centre and of the
// line's delta; `meet` is where the line crosses the centre's column (row).
struct EndTest {
    float along_diff, across_diff, along_delta, across_delta, across_frac, slope;
};

bool draws_start(const EndTest& t) {
    if (std::fabs(t.along_diff) + std::fabs(t.across_diff) < 0.5f) return true;
    if (non_negative(t.along_diff) == non_negative(-t.along_delta)) return false;
    if (non_negative(-t.across_diff) != non_negative(t.across_delta)) return true;
    float meet = t.across_frac + t.along_diff * t.slope;
    return meet < 1.0f && meet > 0.0f;
}

bool draws_end(const EndTest& t, bool closed_at_zero) {
    if (std::fabs(t.along_diff) + std::fabs(t.across_diff) < 0.5f) return false;
    if (non_negative(t.along_diff) != non_negative(-t.along_delta)) return false;
    if (non_negative(-t.across_diff) == non_negative(t.across_delta)) return true;
    float meet = t.across_frac + t.along_diff * t.slope;
    return meet < 1.0f && (closed_at_zero ? meet >= 0.0f : meet > 0.0f);
}

}  // namespace

bool line_corners(glm::vec2 a, glm::vec2 b, int width, LineCorners& out) {
    // Deltas run from b to a, as in llvmpipe's setup, whose decisions
    // (including its asymmetries) this reproduces for the same pixels.
    glm::vec2 d = a - b;
    if (d.x * d.x + d.y * d.y == 0.0f || !std::isfinite(d.x) || !std::isfinite(d.y)) return false;
    glm::vec2 da = from_centre(a), db = from_centre(b);
    int64_t half = int64_t(width) * 256 / 2;
    glm::vec2 off_a{0.0f}, off_b{0.0f};  // moves of each end along the line
    bool x_major = std::fabs(d.x) >= std::fabs(d.y);
    int major = x_major ? 0 : 1, minor = 1 - major;
    if (db[minor] == -0.5f && d[minor] < 0.0f) db[minor] = 0.5f;
    float slope = d[minor] / d[major];
    // llvmpipe reads a y-major line's differences negated (its y runs down).
    float s = x_major ? 1.0f : -1.0f;
    EndTest at_a{s * da[major], s * da[minor], s * d[major], s * d[minor], fraction(a[minor]), s * slope};
    EndTest at_b{s * db[major], s * db[minor], s * d[major], s * d[minor], fraction(b[minor]), s * slope};
    bool draw_start = draws_start(at_a), draw_end = draws_end(at_b, !x_major);
    // Whether the span of centres between the ends (llvmpipe's reckoning,
    // not quite the half-open span) takes each end's pixel; where it
    // disagrees with the diamond rule, the end moves to a pixel boundary
    // along the major axis (llvmpipe moves both ends the same way).
    bool a_low = d[major] < 0.0f;
    bool span_takes_a = non_negative(-at_a.along_diff) != non_negative(at_a.along_delta);
    bool span_takes_b =
        non_negative(at_b.along_diff) == non_negative(-at_b.along_delta) || at_b.along_diff == 0.0f;
    auto move = [&](glm::vec2& off, float diff) {
        off[major] = -diff + (a_low ? -0.5f : 0.5f);
        off[minor] = off[major] * slope;
    };
    if (span_takes_a != draw_start) move(off_a, da[major]);
    if (span_takes_b != draw_end) move(off_b, db[major]);
    // Corners, clockwise: the right end (x-major) or the bottom end
    // (y-major) first, each end split across the minor axis.
    glm::vec2 end_a = a + off_a, end_b = b + off_b;
    bool a_first = x_major ? !a_low : a_low;
    glm::vec2 first = a_first ? end_a : end_b, second = a_first ? end_b : end_a;
    int64_t* qmajor = x_major ? out.x : out.y;
    int64_t* qminor = x_major ? out.y : out.x;
    qmajor[0] = qmajor[3] = snap_fixed(first[major]);
    qmajor[1] = qmajor[2] = snap_fixed(second[major]);
    qminor[0] = snap_fixed(first[minor]) - half;
    qminor[1] = snap_fixed(second[minor]) - half;
    qminor[2] = snap_fixed(second[minor]) + half;
    qminor[3] = snap_fixed(first[minor]) + half;
    return true;
}

LineEdges::LineEdges(const LineCorners& q) {
    for (int i = 0; i < 4; ++i) {
        int n = (i + 1) % 4;
        dcdy[i] = q.x[i] - q.x[n];
        dcdx[i] = q.y[i] - q.y[n];
        c[i] = dcdx[i] * q.x[i] - dcdy[i] * q.y[i];
        // Centres on the left or top edge are inside (GL's rule in a
        // framebuffer object, as llvmpipe applies it to lines).
        if (dcdx[i] < 0 || (dcdx[i] == 0 && dcdy[i] > 0)) ++c[i];
    }
}

bool LineEdges::covers(int x, int y) const {
    for (int i = 0; i < 4; ++i)
        if (c[i] + dcdy[i] * 256 * int64_t(y) - dcdx[i] * 256 * int64_t(x) <= 0) return false;
    return true;
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
