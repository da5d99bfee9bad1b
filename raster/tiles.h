// Screen tiles: draw() bins its set-up primitives into kTileSize tiles in
// submission order, then workers render whole tiles in parallel. Within a
// tile primitives run in submission order, and the tiles (hence the batches
// and their quads) do not depend on the thread count, so neither do images.
#pragma once
#include <cstdint>
#include <cstddef>
#include <vector>

#include "glslrun/glslrun.h"
#include "raster/fragments.h"
#include "raster/framebuffer.h"
#include "raster/stipple.h"
#include "raster/triangle.h"

namespace glslrun::raster {

inline constexpr int kTileSize = 64;
static_assert(kTileSize % kBlockSize == 0);

// From this many threads render() clears in its tile jobs; with fewer it
// clears the whole target first, on the calling thread (TileBins::render).
inline constexpr unsigned kTileClearMinThreads = 4;

struct TileTarget {
    const Program& program;
    const GLState& gl;
    Framebuffer& fb;
    Rect scissor;
    rt::DrawBudget* budget = nullptr;  // the draw's, shared by every worker's executor
    const PolygonStipple* polygon_stipple = nullptr;  // GL_POLYGON_STIPPLE's masks, when it is on
};

// Fragment counts and the first error, by tile order.
struct TileResult {
    uint64_t fragments_shaded = 0, fragments_written = 0, fragments_fused = 0;
    Status status = Ok{};
};

// The bins keep their storage across reset(), so that a renderer that draws
// again (draw() keeps them in the Program) does not allocate them anew.
class TileBins {
public:
    // Empties the bins for a draw into `scissor`.
    void reset(const Rect& scissor);
    // bounds: the pixels `prim` may cover. Primitives are added in submission
    // order and must stay alive and unmoved until render() returns.
    void add(const FsPrimitive* prim, const Rect& bounds);
    // Renders every tile on up to `threads` threads (0: one per core); `stage`
    // serves the calling thread. A shader error is the one of the first
    // failing tile, so it does not depend on the thread count either.
    // With `clear`, every tile of the whole framebuffer is cleared first, by
    // the job that renders it (in cache), tiles without primitives too.
    TileResult render(const TileTarget& target, FragmentStage& stage, unsigned threads,
                      const StoredClear* clear = nullptr) const;

private:
    // One job: a framebuffer tile to clear (with a clear) and the bin to render there, if any.
    struct Job {
        Rect clear;
        size_t bin = SIZE_MAX;
    };
    std::vector<Job> jobs(const Framebuffer& fb, bool clear) const;
    Rect tile_rect(size_t tile) const;
    void render_tile(const TileTarget& target, size_t tile, FragmentStage& stage) const;

    Rect scissor_;
    int columns_ = 0, rows_ = 0;
    std::vector<std::vector<const FsPrimitive*>> bins_;  // per tile, in submission order
    std::vector<size_t> touched_;                        // the bins filled since reset(), each once
    uint64_t area_ = 0;                                  // sum of the primitives' bounds, in pixels
};

}  // namespace glslrun::raster
