// Line and polygon stipple (GL 2.1 §3.5.2, §3.6.2), as Mesa's llvmpipe (the
// reference, tools/glref) draws them.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "glslrun/glslrun.h"

namespace glslrun::raster {

// A stippled line is drawn as the runs of its pattern's set bits, each a
// line of its own from t0 to t1 of the way (llvmpipe cuts lines so, in its
// draw module): the counter steps once per whole pixel of the line's major
// length (rounded up), and carries on along a strip or loop. Each run then
// gets the diamond-exit rule at its own ends. Calls run(t0, t1) for each run
// in order, and advances `counter`.
template <class Run>
void for_each_stipple_run(glm::vec2 a, glm::vec2 b, uint16_t pattern, int repeat, uint32_t& counter, Run&& run) {
    const float dx = std::fabs(b.x - a.x), dy = std::fabs(b.y - a.y);
    const float length = std::max(dx, dy);
    const uint32_t steps = std::isfinite(length) ? uint32_t(std::ceil(length)) : 0;
    const uint32_t factor = uint32_t(std::clamp(repeat, 1, 256));  // glLineStipple clamps it so
    bool on = false;
    uint32_t start = 0;
    for (uint32_t i = 0; i < steps; ++i) {
        const bool bit = (pattern >> (((counter + i) / factor) & 15u)) & 1u;
        if (bit == on) continue;
        if (on) run(float(start) / length, float(i) / length);
        else start = i;
        on = bit;
    }
    if (on && float(start) < length) run(float(start) / length, 1.0f);
    counter += steps;
}

// glPolygonStipple's pattern as 8x8 pixel masks (raster/triangle.h's
// squares: bit j * 8 + i is pixel (ox + i, oy + j)), window-aligned.
class PolygonStipple {
public:
    explicit PolygonStipple(const std::array<uint32_t, 32>& pattern) {
        for (size_t y = 0; y < 32; ++y) {
            uint64_t row = 0;
            for (int x = 0; x < 32; ++x) row |= uint64_t((pattern[y] >> (31 - x)) & 1u) << x;
            rows_[y] = row | row << 32;
        }
    }
    uint64_t square(int ox, int oy) const {
        uint64_t mask = 0;
        const int shift = ox & 31;
        for (int j = 0; j < 8; ++j) mask |= ((rows_[size_t((oy + j) & 31)] >> shift) & 0xFFu) << (8 * j);
        return mask;
    }

private:
    // Per row: bit x is column x's, columns 0..31 twice over, so that eight
    // columns from any start are one shift away.
    std::array<uint64_t, 32> rows_{};
};

}  // namespace glslrun::raster
