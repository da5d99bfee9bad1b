// Triangle setup: snapping to the subpixel grid, edge equations and the fill rule.
#include "raster/triangle.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <type_traits>

#include "runtime/cpu_features.h"
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace glslrun::raster {

int64_t snap(float window_coord) {
    float clamped = std::clamp(window_coord, -kMaxWindowCoord, kMaxWindowCoord);
    // llround (half away from zero) without the library call, which showed at
    // 3.6% of a frame of small triangles: x is exact in double, and so is
    // x +- 0.5 wherever it could round to a different integer.
    double x = double(clamped) * double(kSubpixelOne);
    return int64_t(x + (x < 0.0 ? -0.5 : 0.5));
}

namespace {

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

std::optional<TriangleSetup> setup_triangle(const std::array<glm::vec2, 3>& win, const Rect& scissor) {
    TriangleSetup t;
    if (!setup_triangle(win, scissor, t)) return std::nullopt;
    return t;
}

bool setup_triangle(const std::array<glm::vec2, 3>& win, const Rect& scissor, TriangleSetup& t) {
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(win[i].x) || !std::isfinite(win[i].y)) return false;
        t.fx[i] = snap(win[i].x);
        t.fy[i] = snap(win[i].y);
    }
    t.area2 = (t.fx[1] - t.fx[0]) * (t.fy[2] - t.fy[0]) - (t.fy[1] - t.fy[0]) * (t.fx[2] - t.fx[0]);
    if (t.area2 == 0) return false;
    // Unrolled: as a loop, `% 3` and the indexed loads were a fifth of setup (perf).
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        int64_t dx = t.fx[b] - t.fx[a], dy = t.fy[b] - t.fy[a];
        // E(p) = dx * (py - ay) - dy * (px - ax)
        t.ea[i] = -dy;
        t.eb[i] = dx;
        t.ec[i] = dy * t.fx[a] - dx * t.fy[a];
        // The fill rule looks at the edge as walked counter-clockwise (y up):
        // ties belong to left edges (walking down) and top edges (walking -x).
        int64_t cdx = t.area2 > 0 ? dx : -dx, cdy = t.area2 > 0 ? dy : -dy;
        bool inclusive = cdy < 0 || (cdy == 0 && cdx < 0);
        t.bias[i] = inclusive ? 0 : -1;
        const int64_t sign = t.area2 > 0 ? 1 : -1;
        t.ia[i] = sign * t.ea[i];
        t.ib[i] = sign * t.eb[i];
        t.ic[i] = sign * t.ec[i] + t.bias[i];
    }
    int64_t min_x = std::min({t.fx[0], t.fx[1], t.fx[2]}), max_x = std::max({t.fx[0], t.fx[1], t.fx[2]});
    int64_t min_y = std::min({t.fy[0], t.fy[1], t.fy[2]}), max_y = std::max({t.fy[0], t.fy[1], t.fy[2]});
    // Pixel x is a candidate when its centre x*S + S/2 lies in [min_x, max_x].
    auto first = [](int64_t lo) { return floor_div(lo - kSubpixelOne / 2 + kSubpixelOne - 1, kSubpixelOne); };
    auto last = [](int64_t hi) { return floor_div(hi - kSubpixelOne / 2, kSubpixelOne); };
    t.bbox.x0 = int(std::max<int64_t>(first(min_x), scissor.x0));
    t.bbox.y0 = int(std::max<int64_t>(first(min_y), scissor.y0));
    t.bbox.x1 = int(std::min<int64_t>(last(max_x) + 1, scissor.x1));
    t.bbox.y1 = int(std::min<int64_t>(last(max_y) + 1, scissor.y1));
    return t.bbox.x0 < t.bbox.x1 && t.bbox.y0 < t.bbox.y1;
}

namespace {

int64_t pixel_centre(int v) { return int64_t(v) * kSubpixelOne + kSubpixelOne / 2; }

// Within a square an edge's values are its value at the square's first
// pixel plus offsets of at most 7 (|dx| + |dy|). Where that is below
// kClamp, clamping the first value to [-kClamp, kClamp] (clamped()) keeps
// every value's sign and brings them all within 32 bits: far from an edge
// only the side matters. Edges longer than about 1000 pixels take 64 bits.
constexpr int64_t kClamp = int64_t(1) << 30;

bool steps_fit_32(const std::array<int64_t, 3>& dx, const std::array<int64_t, 3>& dy) {
    bool fit = true;
    for (size_t i = 0; i < 3; ++i) fit = fit && (kSquareSize - 1) * (std::abs(dx[i]) + std::abs(dy[i])) < kClamp;
    return fit;
}

std::array<int64_t, 3> clamped(const std::array<int64_t, 3>& e) {
    return {std::clamp(e[0], -kClamp, kClamp), std::clamp(e[1], -kClamp, kClamp), std::clamp(e[2], -kClamp, kClamp)};
}

#if defined(__SSE2__)
// The pixels of a square where all three edges are >= 0, given their values
// at its first pixel (clamped()) and their steps per pixel (steps_fit_32()),
// so that every value fits in 32 bits: a row is two registers per edge, and
// the sign bits of (e0 | e1 | e2) are the pixels outside. The first `rows`
// rows, in the mask's first rows.
[[gnu::always_inline]] inline uint64_t rows_covered_32(const std::array<int64_t, 3>& first,
                                                       const std::array<int64_t, 3>& dx,
                                                       const std::array<int64_t, 3>& dy, int rows) {
    auto first_four = [&](size_t i) {
        return _mm_add_epi32(_mm_set1_epi32(int32_t(first[i])),
                             _mm_setr_epi32(0, int32_t(dx[i]), int32_t(2 * dx[i]), int32_t(3 * dx[i])));
    };
    auto next_four = [&](__m128i e, size_t i) { return _mm_add_epi32(e, _mm_set1_epi32(int32_t(4 * dx[i]))); };
    __m128i a0 = first_four(0), b0 = first_four(1), c0 = first_four(2);
    __m128i a1 = next_four(a0, 0), b1 = next_four(b0, 1), c1 = next_four(c0, 2);
    const __m128i sa = _mm_set1_epi32(int32_t(dy[0])), sb = _mm_set1_epi32(int32_t(dy[1])),
                  sc = _mm_set1_epi32(int32_t(dy[2]));
    uint64_t mask = 0;
#pragma GCC unroll 8
    for (int y = 0; y < rows; ++y) {
        const unsigned outside = unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(_mm_or_si128(a0, b0), c0)))) |
                                 unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(_mm_or_si128(a1, b1), c1)))) << 4;
        mask |= uint64_t(~outside & 0xFFu) << (y * kSquareSize);
        a0 = _mm_add_epi32(a0, sa), b0 = _mm_add_epi32(b0, sb), c0 = _mm_add_epi32(c0, sc);
        a1 = _mm_add_epi32(a1, sa), b1 = _mm_add_epi32(b1, sb), c1 = _mm_add_epi32(c1, sc);
    }
    return mask;
}

// All eight rows: without a branch on the row count (data-dependent
// branches mispredicted at every other block of a tile's walk: perf).
[[gnu::always_inline]] inline uint64_t square_covered_32(const std::array<int64_t, 3>& first,
                                                         const std::array<int64_t, 3>& dx,
                                                         const std::array<int64_t, 3>& dy) {
    return rows_covered_32(first, dx, dy, kSquareSize);
}
#endif

// The pixels of rows [r.y0, r.y1) of the square at (ox, oy), all eight
// columns, where all three edges are >= 0, given their values at the
// centre of pixel (ox, r.y0) and their steps per pixel: where some value
// does not fit in 32 bits.
uint64_t rows_covered_64(std::array<int64_t, 3> row, const std::array<int64_t, 3>& dx,
                         const std::array<int64_t, 3>& dy, int oy, const Rect& r) {
    uint64_t mask = 0;
#if defined(__SSE2__)
    // Two pixels per register: the sign bits of (e0 | e1 | e2) are the
    // pixels outside an edge, and movmskpd gathers them.
    __m128i step[3][kSquareSize / 2];
    for (size_t i = 0; i < 3; ++i)
        for (int j = 0; j < kSquareSize / 2; ++j)
            step[i][j] = _mm_set_epi64x(dx[i] * (2 * j + 1), dx[i] * (2 * j));
    for (int y = r.y0; y < r.y1; ++y) {
        const __m128i e0 = _mm_set1_epi64x(row[0]), e1 = _mm_set1_epi64x(row[1]), e2 = _mm_set1_epi64x(row[2]);
        unsigned outside = 0;
        for (int j = 0; j < kSquareSize / 2; ++j) {
            __m128i any = _mm_or_si128(_mm_or_si128(_mm_add_epi64(e0, step[0][j]), _mm_add_epi64(e1, step[1][j])),
                                       _mm_add_epi64(e2, step[2][j]));
            outside |= unsigned(_mm_movemask_pd(_mm_castsi128_pd(any))) << (2 * j);
        }
        mask |= uint64_t(~outside & 0xFFu) << ((y - oy) * kSquareSize);
        for (size_t i = 0; i < 3; ++i) row[i] += dy[i];
    }
#else
    for (int y = r.y0; y < r.y1; ++y) {
        int64_t e0 = row[0], e1 = row[1], e2 = row[2];
        for (int x = 0; x < kSquareSize; ++x) {
            uint64_t inside = ~uint64_t(e0 | e1 | e2) >> 63;  // 1 when no edge value is negative
            mask |= inside << ((y - oy) * kSquareSize + x);
            e0 += dx[0], e1 += dx[1], e2 += dx[2];
        }
        for (size_t i = 0; i < 3; ++i) row[i] += dy[i];
    }
#endif
    return mask;
}

// rows_covered_64() of block b (rows from by), given the edges' values at
// the centre of its first pixel, for edges too long for 32 bits. Those
// triangles are large, so most of their blocks lie wholly inside or wholly
// outside an edge: the extremes of each edge over the block's 64 pixels
// (at its corners) settle those without testing pixels, and the branches
// predict well. (perf: the pixel tests of a 1080p floor plane clipped at
// the guard band were 5% of the multi-pass frame.)
uint64_t block_covered_64(const std::array<int64_t, 3>& e, const std::array<int64_t, 3>& dx,
                          const std::array<int64_t, 3>& dy, int by, const Rect& b) {
    constexpr int64_t kLast = kBlockSize - 1;
    bool inside = true;
    for (size_t i = 0; i < 3; ++i) {
        const int64_t low = e[i] + std::min<int64_t>(0, kLast * dx[i]) + std::min<int64_t>(0, kLast * dy[i]);
        const int64_t high = e[i] + std::max<int64_t>(0, kLast * dx[i]) + std::max<int64_t>(0, kLast * dy[i]);
        if (high < 0) return 0;
        inside = inside && low >= 0;
    }
    if (inside) return ~uint64_t(0);
    std::array<int64_t, 3> first_row;
    for (size_t i = 0; i < 3; ++i) first_row[i] = e[i] + int64_t(b.y0 - by) * dy[i];
    return rows_covered_64(first_row, dx, dy, by, b);
}

}  // namespace

uint64_t coverage_mask(const TriangleEdges& t, int ox, int oy, const Rect& r) {
    // Whole rows of the square, from column ox; the pixels outside r are cut at the end.
    // Small triangles' rows only: most span two or three (the subdivided
    // teapot was 2% slower with all eight).
    std::array<int64_t, 3> row, dx, dy;
    for (size_t i = 0; i < 3; ++i) {
        row[i] = t.ia[i] * pixel_centre(ox) + t.ib[i] * pixel_centre(r.y0) + t.ic[i];
        dx[i] = t.ia[i] * kSubpixelOne;
        dy[i] = t.ib[i] * kSubpixelOne;
    }
    const uint64_t in_r = square_rect(ox, oy, r);
#if defined(__SSE2__)
    if (steps_fit_32(dx, dy))
        return (rows_covered_32(clamped(row), dx, dy, r.y1 - r.y0) << ((r.y0 - oy) * kSquareSize)) & in_r;
#endif
    return rows_covered_64(row, dx, dy, oy, r) & in_r;
}

namespace {

#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX512 __attribute__((target("avx512f,avx512dq")))
// square_covered_32() with AVX-512: per edge, the offsets x * dx + y * dy of
// a block's 64 pixels in four registers of two rows each, so that a block is
// 12 additions, 8 ORs and 4 sign masks (the SSE2 rows were about 100
// instructions; covered_blocks was the spot frame's first function). The
// same 32-bit sums, so the same pixels.
struct BlockOffsets {
    __m512i at[3][4];
};
GLSLRUN_AVX512 inline BlockOffsets block_offsets(const std::array<int64_t, 3>& dx, const std::array<int64_t, 3>& dy) {
    // Column j % 8 and row j / 8 of lane j; steps_fit_32() keeps each product and sum in 32 bits.
    const __m512i column = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
    const __m512i row = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
    BlockOffsets o;
    for (size_t i = 0; i < 3; ++i) {
        const __m512i step = _mm512_set1_epi32(int32_t(2 * dy[i]));
        o.at[i][0] = _mm512_add_epi32(_mm512_mullo_epi32(column, _mm512_set1_epi32(int32_t(dx[i]))),
                                      _mm512_mullo_epi32(row, _mm512_set1_epi32(int32_t(dy[i]))));
        for (int k = 1; k < 4; ++k) o.at[i][k] = _mm512_add_epi32(o.at[i][k - 1], step);
    }
    return o;
}
GLSLRUN_AVX512 inline uint64_t square_covered_512(const std::array<int64_t, 3>& first,
                                                                          const BlockOffsets& o) {
    const __m512i a = _mm512_set1_epi32(int32_t(first[0])), b = _mm512_set1_epi32(int32_t(first[1])),
                  c = _mm512_set1_epi32(int32_t(first[2]));
    uint64_t mask = 0;
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
        const __m512i any = _mm512_or_si512(_mm512_or_si512(_mm512_add_epi32(a, o.at[0][k]), _mm512_add_epi32(b, o.at[1][k])),
                                            _mm512_add_epi32(c, o.at[2][k]));
        mask |= uint64_t(uint16_t(~_mm512_movepi32_mask(any))) << (16 * k);
    }
    return mask;
}
#endif

// covered_blocks(), with AVX-512's block test where kWide.
template <bool kWide>
[[gnu::always_inline]] inline size_t walk_blocks(const TriangleEdges& t, const Rect& r, CoveredBlock* out) {
    const int x0 = r.x0 & ~(kBlockSize - 1), y0 = r.y0 & ~(kBlockSize - 1);
    // Per edge: its value at the centre of pixel (x0, y0) and its steps per pixel.
    std::array<int64_t, 3> row_start, dx, dy;
    for (size_t i = 0; i < 3; ++i) {
        dx[i] = t.ia[i] * kSubpixelOne;
        dy[i] = t.ib[i] * kSubpixelOne;
        row_start[i] = t.ia[i] * pixel_centre(x0) + t.ib[i] * pixel_centre(y0) + t.ic[i];
    }
    const bool fits_32 = steps_fit_32(dx, dy);
#if defined(__x86_64__) && defined(__GNUC__)
    [[maybe_unused]] std::conditional_t<kWide, BlockOffsets, char> offsets;  // read only where fits_32
    if constexpr (kWide)
        if (fits_32) offsets = block_offsets(dx, dy);
#endif
    // r's pixels in a block: the first block column and the last cut
    // columns, the first and last block rows cut rows; the others are
    // whole (square_rect() per block was a fifth of the walk: perf).
    const int last_bx = x0 + (r.x1 - 1 - x0) / kBlockSize * kBlockSize;
    const uint64_t first_columns = square_columns(r.x0 - x0, kBlockSize);
    const uint64_t last_columns = square_columns(0, r.x1 - last_bx);
    // Where no edge value of the walk can leave [-kClamp, kClamp],
    // clamped() changes nothing and is skipped.
    bool unclamped = fits_32;
    for (size_t i = 0; i < 3; ++i)
        unclamped = unclamped && std::abs(row_start[i]) + (last_bx - x0 + kBlockSize) * std::abs(dx[i]) +
                                         (r.y1 - y0 + kBlockSize) * std::abs(dy[i]) < kClamp;
    // Without branches on the coverage (they mispredicted at every other
    // block: perf): every block's eight rows are computed, and blocks
    // without pixels are written over.
    size_t n = 0;
    for (int by = y0; by < r.y1; by += kBlockSize) {
        std::array<int64_t, 3> e = row_start;
        const uint64_t rows = square_rows(r.y0 - by, r.y1 - by);
        for (int bx = x0; bx < r.x1; bx += kBlockSize) {
            uint64_t pixels = rows & (bx == x0 ? first_columns : ~uint64_t(0)) &
                              (bx == last_bx ? last_columns : ~uint64_t(0));
            // The block's pixels in r, for the 64-bit test's rows.
            auto block = [&] {
                return Rect{std::max(bx, r.x0), std::max(by, r.y0), std::min(bx + kBlockSize, r.x1),
                            std::min(by + kBlockSize, r.y1)};
            };
            if (!fits_32) pixels &= block_covered_64(e, dx, dy, by, block());
#if defined(__x86_64__) && defined(__GNUC__)
            else if constexpr (kWide) pixels &= square_covered_512(unclamped ? e : clamped(e), offsets);
#endif
#if defined(__SSE2__)
            else pixels &= square_covered_32(unclamped ? e : clamped(e), dx, dy);
#else
            else pixels &= block_covered_64(e, dx, dy, by, block());
#endif
            out[n] = {bx, by, pixels};
            n += pixels != 0;
            for (size_t i = 0; i < 3; ++i) e[i] += kBlockSize * dx[i];
        }
        for (size_t i = 0; i < 3; ++i) row_start[i] += kBlockSize * dy[i];
    }
    return n;
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx512f,avx512dq"), flatten)) size_t covered_blocks_avx512(const TriangleEdges& t, const Rect& r,
                                                                                  CoveredBlock* out) {
    return walk_blocks<true>(t, r, out);
}
#endif

}  // namespace

size_t covered_blocks(const TriangleEdges& t, const Rect& r, CoveredBlock* out, bool avx512) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (avx512) return covered_blocks_avx512(t, r, out);
#endif
    return walk_blocks<false>(t, r, out);
}

size_t covered_blocks(const TriangleEdges& t, const Rect& r, CoveredBlock* out) {
    return covered_blocks(t, r, out, rt::cpu_has_avx512());
}

std::optional<SmallCoverage> small_coverage(const TriangleEdges& t) {
    SmallCoverage c{t.bbox.x0 & ~1, t.bbox.y0 & ~1, 0};
    if (t.bbox.x1 - c.x > kSquareSize || t.bbox.y1 - c.y > kSquareSize) return std::nullopt;
    c.mask = coverage_mask(t, c.x, c.y, t.bbox);
    return c;
}

}  // namespace glslrun::raster
