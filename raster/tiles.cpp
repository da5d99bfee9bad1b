#include "raster/tiles.h"

#include <algorithm>
#include <memory>
#include <optional>

#include "raster/points_lines.h"
#include "runtime/parallel.h"

namespace glslrun::raster {

namespace {

// Below this many pixels of primitive bounds a draw stays on the calling
// thread: starting threads would cost more than it saves (piglit draws
// thousands of tiny primitives).
constexpr uint64_t kParallelPixels = 128 * 128;

void prefetch(const FsPrimitive* p) {
    const char* bytes = reinterpret_cast<const char*>(p);
    for (size_t offset = 0; offset < sizeof(FsPrimitive); offset += 64) __builtin_prefetch(bytes + offset);
}

Rect intersect(const Rect& a, const Rect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

}  // namespace

void TileBins::reset(const Rect& scissor) {
    scissor_ = scissor;
    area_ = 0;
    // Tiles are aligned to the framebuffer's origin, so 2x2 quads never straddle two.
    columns_ = std::max(0, (scissor.x1 + kTileSize - 1) / kTileSize - scissor.x0 / kTileSize);
    rows_ = std::max(0, (scissor.y1 + kTileSize - 1) / kTileSize - scissor.y0 / kTileSize);
    for (auto& bin : bins_) bin.clear();
    bins_.resize(size_t(columns_) * size_t(rows_));
}

Rect TileBins::tile_rect(size_t tile) const {
    int x = (scissor_.x0 / kTileSize + int(tile % size_t(columns_))) * kTileSize;
    int y = (scissor_.y0 / kTileSize + int(tile / size_t(columns_))) * kTileSize;
    return intersect(Rect{x, y, x + kTileSize, y + kTileSize}, scissor_);
}

void TileBins::add(const FsPrimitive* prim, const Rect& bounds) {
    Rect r = intersect(bounds, scissor_);
    if (r.x0 >= r.x1 || r.y0 >= r.y1) return;
    area_ += uint64_t(r.x1 - r.x0) * uint64_t(r.y1 - r.y0);
    int cx0 = scissor_.x0 / kTileSize, cy0 = scissor_.y0 / kTileSize;
    for (int ty = r.y0 / kTileSize; ty <= (r.y1 - 1) / kTileSize; ++ty)
        for (int tx = r.x0 / kTileSize; tx <= (r.x1 - 1) / kTileSize; ++tx)
            bins_[size_t(ty - cy0) * size_t(columns_) + size_t(tx - cx0)].push_back(prim);
}

void TileBins::render_tile(const TileTarget& target, size_t tile, FragmentStage& stage) const {
    Rect clip = tile_rect(tile);
    const std::vector<const FsPrimitive*>& bin = bins_[tile];
    for (size_t i = 0; i < bin.size(); ++i) {
        const FsPrimitive& p = *bin[i];
        // Consecutive primitives of a bin are rarely adjacent in memory: the
        // loads of p missed the cache (perf: 15% of render_tile on one load).
        if (i + 1 < bin.size()) prefetch(bin[i + 1]);
        auto add_quad = [&](int x, int y, unsigned mask) { stage.add_quad(p, x, y, mask); };
        if (p.count == 3 && p.cover.mask) {
            for_each_small_quad(p.cover, clip, add_quad);
        } else if (p.count == 3) {
            // Larger triangles are set up again rather than stored: they are
            // few, and it saves the memory of their edge functions.
            TriangleSetup setup;
            if (setup_triangle({p.v[0].win, p.v[1].win, p.v[2].win}, target.scissor, setup))
                for_each_quad(setup, clip, add_quad);
        } else if (p.count == 2) {
            rasterize_line(stage, p, clip);
        } else {
            rasterize_point(stage, p, clip);
        }
        if (stage.error()) break;
    }
    stage.flush();
}

TileResult TileBins::render(const TileTarget& target, FragmentStage& stage, unsigned threads) const {
    std::vector<size_t> tiles;  // the non-empty ones, in order
    for (size_t t = 0; t < bins_.size(); ++t)
        if (!bins_[t].empty()) tiles.push_back(t);
    std::vector<std::optional<Error>> errors(tiles.size());
    unsigned workers = area_ < kParallelPixels ? 1 : rt::thread_count(threads, tiles.size());
    // Each worker has its own stage (interpreter, batch); stage 0 is the caller's.
    std::vector<std::unique_ptr<FragmentStage>> stages(workers);
    rt::JobQueue queue(tiles.size());
    rt::run_workers(workers, [&](unsigned k) {
        if (k > 0) stages[k] = std::make_unique<FragmentStage>(target.program, target.gl, target.fb);
        FragmentStage& s = k > 0 ? *stages[k] : stage;
        for (size_t i; queue.next(&i);) {
            render_tile(target, tiles[i], s);
            if (!s.error()) continue;
            errors[i] = *s.error();
            s.clear_error();
            queue.fail(i);
        }
    });
    TileResult result{stage.fragments_shaded(), stage.fragments_written()};
    for (const auto& s : stages) {
        if (!s) continue;
        result.fragments_shaded += s->fragments_shaded();
        result.fragments_written += s->fragments_written();
    }
    if (auto failed = queue.first_failure()) result.status = *errors[*failed];
    return result;
}

}  // namespace glslrun::raster
