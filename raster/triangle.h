// Triangle setup and coverage: fixed-point edge functions (8 subpixel bits),
// pixel centres at +0.5, a top-left fill rule so that adjacent triangles
// never leave cracks nor cover a pixel twice, and iteration over aligned 2x2
// quads (GL window coordinates: y up, row 0 at the bottom).
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

namespace glslrun::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int64_t kSubpixelOne = int64_t(1) << kSubpixelBits;
// Window coordinates must stay within this many pixels of the origin so that
// edge functions fit in 64 bits; clipping keeps them there (guard band).
inline constexpr float kMaxWindowCoord = float(1 << 20);

// Half-open pixel rectangle [x0, x1) x [y0, y1).
struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Quad coverage bits: bit 0 (x,y), 1 (x+1,y), 2 (x,y+1), 3 (x+1,y+1).
inline constexpr int kQuadDx[4] = {0, 1, 0, 1};
inline constexpr int kQuadDy[4] = {0, 0, 1, 1};

// setup_triangle() sets every field; there are no initializers, because
// zeroing this per triangle showed in profiles.
struct TriangleSetup {
    std::array<int64_t, 3> fx, fy;  // snapped vertex positions
    // Edge i is opposite vertex i: E_i(p) = a*px + b*py + c, with E_i(v_i) = area2.
    std::array<int64_t, 3> ea, eb, ec;
    std::array<int64_t, 3> bias;  // 0 if ties on the edge are inside (top-left), else -1
    // The same edges turned so that a pixel centre is covered where all
    // three are >= 0: times the orientation's sign, with the bias in c.
    std::array<int64_t, 3> ia, ib, ic;
    int64_t area2;                // twice the signed area in subpixel units (> 0: CCW)
    Rect bbox;  // covered pixels lie inside, already clipped to the scissor
};

int64_t snap(float window_coord);

// floor() as a pixel index, kept in the rasterizer's range; NaN gives 0.
inline int pixel_floor(float v) {
    if (!(v == v)) return 0;
    return int(std::clamp(std::floor(v), -kMaxWindowCoord, kMaxWindowCoord));
}

// Returns nothing for degenerate triangles or ones outside the scissor.
std::optional<TriangleSetup> setup_triangle(const std::array<glm::vec2, 3>& win, const Rect& scissor);
// The same into `t` (false: nothing to draw, `t` unspecified), without the
// optional's copy, for the per-triangle paths.
bool setup_triangle(const std::array<glm::vec2, 3>& win, const Rect& scissor, TriangleSetup& t);

// Edge function values at the centre of pixel (x, y).
inline std::array<int64_t, 3> edge_values(const TriangleSetup& t, int x, int y) {
    int64_t px = int64_t(x) * kSubpixelOne + kSubpixelOne / 2;
    int64_t py = int64_t(y) * kSubpixelOne + kSubpixelOne / 2;
    return {t.ea[0] * px + t.eb[0] * py + t.ec[0], t.ea[1] * px + t.eb[1] * py + t.ec[1],
            t.ea[2] * px + t.eb[2] * py + t.ec[2]};
}

inline bool covers(const TriangleSetup& t, const std::array<int64_t, 3>& e) {
    int64_t s = t.area2 > 0 ? 1 : -1;
    return s * e[0] + t.bias[0] >= 0 && s * e[1] + t.bias[1] >= 0 && s * e[2] + t.bias[2] >= 0;
}

enum class BlockCover { Outside, Partial, Inside };

// Edge functions are linear, so a rectangle is inside (outside) an edge when
// all four corner pixels are, that is when the corner where the edge
// function is least (greatest) is: one corner per test, picked by the signs
// of the edge's gradient.
inline BlockCover classify_block(const TriangleSetup& t, const Rect& b) {
    const int64_t x0 = int64_t(b.x0) * kSubpixelOne + kSubpixelOne / 2, x1 = int64_t(b.x1 - 1) * kSubpixelOne + kSubpixelOne / 2;
    const int64_t y0 = int64_t(b.y0) * kSubpixelOne + kSubpixelOne / 2, y1 = int64_t(b.y1 - 1) * kSubpixelOne + kSubpixelOne / 2;
    bool inside = true;
    for (size_t i = 0; i < 3; ++i) {
        const int64_t a = t.ia[i], bb = t.ib[i], c = t.ic[i];
        const int64_t greatest = a * (a > 0 ? x1 : x0) + bb * (bb > 0 ? y1 : y0) + c;
        if (greatest < 0) return BlockCover::Outside;
        const int64_t least = a * (a > 0 ? x0 : x1) + bb * (bb > 0 ? y0 : y1) + c;
        inside = inside && least >= 0;
    }
    return inside ? BlockCover::Inside : BlockCover::Partial;
}

inline constexpr int kBlockSize = 8;

// Pixel masks of an 8x8 square at (ox, oy): bit j * 8 + i is pixel
// (ox + i, oy + j). Blocks and small triangles' coverage use them.
inline constexpr int kSquareSize = kBlockSize;
static_assert(kSquareSize * kSquareSize == 64);

// Bits [lo, hi) of a 64-bit word.
inline uint64_t bit_range(int lo, int hi) {
    lo = std::clamp(lo, 0, 64), hi = std::clamp(hi, 0, 64);
    if (lo >= hi) return 0;
    uint64_t below_hi = hi == 64 ? ~uint64_t(0) : (uint64_t(1) << hi) - 1;
    return below_hi & ~((uint64_t(1) << lo) - 1);
}

// The pixels of the square whose columns (rows) are in [lo, hi) of it.
inline uint64_t square_columns(int lo, int hi) {
    return bit_range(std::clamp(lo, 0, kSquareSize), std::clamp(hi, 0, kSquareSize)) * 0x0101010101010101u;
}
inline uint64_t square_rows(int lo, int hi) {
    return bit_range(kSquareSize * std::clamp(lo, 0, kSquareSize), kSquareSize * std::clamp(hi, 0, kSquareSize));
}
// The pixels of rectangle r in the square at (ox, oy).
inline uint64_t square_rect(int ox, int oy, const Rect& r) {
    return square_columns(r.x0 - ox, r.x1 - ox) & square_rows(r.y0 - oy, r.y1 - oy);
}

// The pixels of r (which must lie in the square at (ox, oy)) that t covers:
// covers() with the orientation and the fill rule's bias folded into each
// edge, a whole row of the square at a time (two pixels per SSE2 register),
// without branches (a test per pixel mispredicted often: perf).
uint64_t coverage_mask(const TriangleSetup& t, int ox, int oy, const Rect& r);

// Calls visit(x, y, mask) for each quad of `part` (pixels of the square at
// (ox, oy), ox and oy even) with a pixel in `pixels`, in bit order: rows
// bottom up, left to right.
template <class Visit>
void visit_quads(uint64_t pixels, uint64_t part, int ox, int oy, Visit&& visit) {
    // Bit j * 8 + i (i, j even): quad (i, j) has a pixel.
    uint64_t quads = (pixels | pixels >> 1 | pixels >> 8 | pixels >> 9) & 0x0055005500550055u & part;
    for (; quads; quads &= quads - 1) {
        int bit = std::countr_zero(quads);
        unsigned low = unsigned(pixels >> bit) & 3u, high = unsigned(pixels >> (bit + kSquareSize)) & 3u;
        visit(ox + (bit & 7), oy + (bit >> 3), low | high << 2);
    }
}

// Calls visit(pixels, part, ox, oy) for the aligned 8x8 blocks (as squares
// for visit_quads) with a covered pixel inside `clip`: rows of blocks bottom
// up, left to right. Blocks outside an edge are skipped, and pixels of
// blocks inside all edges are not tested one by one.
template <class Visit>
void for_each_block(const TriangleSetup& t, const Rect& clip, Visit&& visit) {
    Rect r{std::max(t.bbox.x0, clip.x0), std::max(t.bbox.y0, clip.y0), std::min(t.bbox.x1, clip.x1),
           std::min(t.bbox.y1, clip.y1)};
    for (int by = r.y0 & ~(kBlockSize - 1); by < r.y1; by += kBlockSize) {
        for (int bx = r.x0 & ~(kBlockSize - 1); bx < r.x1; bx += kBlockSize) {
            Rect b{std::max(bx, r.x0), std::max(by, r.y0), std::min(bx + kBlockSize, r.x1),
                   std::min(by + kBlockSize, r.y1)};
            BlockCover cover = classify_block(t, b);
            if (cover == BlockCover::Outside) continue;
            uint64_t pixels = cover == BlockCover::Inside ? square_rect(bx, by, b) : coverage_mask(t, bx, by, b);
            if (pixels) visit(pixels, ~uint64_t(0), bx, by);
        }
    }
}

// Calls visit(x, y, mask) for every 2x2 quad (x, y even) with at least one
// covered pixel inside `clip`, block by block (for_each_block).
template <class Visit>
void for_each_quad(const TriangleSetup& t, const Rect& clip, Visit&& visit) {
    for_each_block(t, clip, [&](uint64_t pixels, uint64_t part, int ox, int oy) { visit_quads(pixels, part, ox, oy, visit); });
}

// Coverage of a small triangle, one whose candidate pixels lie within the
// 8x8 square at (x, y) (x, y even, so the square holds whole quads, but not
// necessarily aligned to a block). Computed once at setup, so that tiles
// need neither the edge functions nor the block walk, and triangles that
// cover no pixel centre can be dropped before binning.
struct SmallCoverage {
    int x = 0, y = 0;
    uint64_t mask = 0;
};

// Nothing when the triangle's bounding box does not fit the square.
std::optional<SmallCoverage> small_coverage(const TriangleSetup& t);

// Calls visit(pixels, part, x, y) for the parts of `c`'s square that hold
// covered pixels inside `clip`, in the order for_each_block visits them, so
// that a tile's batches (and the loop cap's iteration count per batch) are
// the same either way. The parts' edges are even: they cut no quad.
template <class Visit>
void for_each_small_part(const SmallCoverage& c, const Rect& clip, Visit&& visit) {
    const uint64_t pixels = c.mask & square_rect(c.x, c.y, clip);
    if (!pixels) return;
    // Where the square crosses a block boundary, for_each_block finishes the
    // lower (left) block before it starts the next.
    const int sx = kBlockSize - (c.x & (kBlockSize - 1)), sy = kBlockSize - (c.y & (kBlockSize - 1));
    const uint64_t rows[2] = {square_rows(0, sy), square_rows(sy, kSquareSize)};
    const uint64_t columns[2] = {square_columns(0, sx), square_columns(sx, kSquareSize)};
    for (uint64_t row : rows)
        for (uint64_t column : columns)
            if (pixels & row & column) visit(pixels, row & column, c.x, c.y);
}

// Calls visit(x, y, mask) for the quads of `c` with a covered pixel inside
// `clip`, in the order for_each_quad visits them.
template <class Visit>
void for_each_small_quad(const SmallCoverage& c, const Rect& clip, Visit&& visit) {
    for_each_small_part(c, clip, [&](uint64_t pixels, uint64_t part, int ox, int oy) { visit_quads(pixels, part, ox, oy, visit); });
}

}  // namespace glslrun::raster
