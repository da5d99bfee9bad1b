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
#include <vector>

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

// What the block walk needs of a triangle. FsPrimitive keeps it for the
// triangles larger than a square, so that tiles do not set them up again.
struct TriangleEdges {
    // Edge i (opposite vertex i) turned so that a pixel centre is covered
    // where all three are >= 0: times the orientation's sign, with the fill
    // rule's bias in c.
    std::array<int64_t, 3> ia, ib, ic;
    Rect bbox;  // covered pixels lie inside, already clipped to the scissor
};

// setup_triangle() sets every field; there are no initializers, because
// zeroing this per triangle showed in profiles.
struct TriangleSetup : TriangleEdges {
    std::array<int64_t, 3> fx, fy;  // snapped vertex positions
    // Edge i is opposite vertex i: E_i(p) = a*px + b*py + c, with E_i(v_i) = area2.
    std::array<int64_t, 3> ea, eb, ec;
    std::array<int64_t, 3> bias;  // 0 if ties on the edge are inside (top-left), else -1
    int64_t area2;                // twice the signed area in subpixel units (> 0: CCW)
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
// edge, a whole row of the square at a time (four pixels per SSE2 register
// where the edge values fit in 32 bits, else two), without branches (a test
// per pixel mispredicted often: perf).
uint64_t coverage_mask(const TriangleEdges& t, int ox, int oy, const Rect& r);

// A block of a triangle's coverage: the covered pixels of the aligned 8x8
// block at (x, y), as a square's mask.
struct CoveredBlock {
    int x, y;
    uint64_t pixels;
};

// The blocks of r (a rectangle within t's bounding box) where t covers a
// pixel, rows of blocks bottom up, left to right, into `out` (room for
// blocks_spanned(r)); returns how many. One call per triangle and tile: the
// edge values at r's first block are computed once and each block's from
// them by additions. Where the edges' steps allow (edges under about 1000
// pixels), every block's 64 pixels are tested in 32 bits, four a register,
// without a branch on the coverage: the triangles of the lecture's scenes span a few blocks each,
// and branches that skipped the blocks outside an edge or inside all three
// mispredicted at every other block (perf; 6% of the 1080p spot frame).
// Blocks are tested with AVX-512 where rt::cpu_has_avx512(); the overload
// picks (the same blocks either way: tests/raster/coverage.cpp).
size_t covered_blocks(const TriangleEdges& t, const Rect& r, CoveredBlock* out);
size_t covered_blocks(const TriangleEdges& t, const Rect& r, CoveredBlock* out, bool avx512);

// How many aligned blocks r touches.
inline size_t blocks_spanned(const Rect& r) {
    auto span = [](int lo, int hi) { return size_t((hi + kBlockSize - 1) / kBlockSize - lo / kBlockSize); };
    return span(r.x0 & ~(kBlockSize - 1), r.x1) * span(r.y0 & ~(kBlockSize - 1), r.y1);
}

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
// up, left to right (covered_blocks()).
template <class Visit>
void for_each_block(const TriangleEdges& t, const Rect& clip, Visit&& visit) {
    Rect r{std::max(t.bbox.x0, clip.x0), std::max(t.bbox.y0, clip.y0), std::min(t.bbox.x1, clip.x1),
           std::min(t.bbox.y1, clip.y1)};
    if (r.x0 >= r.x1 || r.y0 >= r.y1) return;
    // A tile's blocks fit on the stack; larger rectangles (a whole
    // framebuffer as the clip) take the heap.
    constexpr size_t kOnStack = 81;  // 64x64 pixels at any alignment
    CoveredBlock stack[kOnStack];
    std::vector<CoveredBlock> heap;
    CoveredBlock* blocks = stack;
    if (blocks_spanned(r) > kOnStack) {
        heap.resize(blocks_spanned(r));
        blocks = heap.data();
    }
    const size_t n = covered_blocks(t, r, blocks);
    for (size_t i = 0; i < n; ++i) visit(blocks[i].pixels, ~uint64_t(0), blocks[i].x, blocks[i].y);
}

// Calls visit(x, y, mask) for every 2x2 quad (x, y even) with at least one
// covered pixel inside `clip`, block by block (for_each_block).
template <class Visit>
void for_each_quad(const TriangleEdges& t, const Rect& clip, Visit&& visit) {
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
std::optional<SmallCoverage> small_coverage(const TriangleEdges& t);

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
