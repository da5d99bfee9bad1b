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
    // Only the bins the last draw filled hold anything: a draw of a few
    // tiles does not visit the 510 of a 1080p target (many_draws' 240
    // draws: a visit of every bin in reset and jobs per draw was 1.6% of
    // its frame).
    for (size_t t : touched_) bins_[t].clear();
    touched_.clear();
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
        for (int tx = r.x0 / kTileSize; tx <= (r.x1 - 1) / kTileSize; ++tx) {
            const size_t t = size_t(ty - cy0) * size_t(columns_) + size_t(tx - cx0);
            if (bins_[t].empty()) touched_.push_back(t);
            bins_[t].push_back(prim);
        }
}

void TileBins::render_tile(const TileTarget& target, size_t tile, FragmentStage& stage) const {
    Rect clip = tile_rect(tile);
    const std::vector<const FsPrimitive*>& bin = bins_[tile];
    stage.prefetch(clip);
    for (size_t i = 0; i < bin.size(); ++i) {
        const FsPrimitive& p = *bin[i];
        // Consecutive primitives of a bin are rarely adjacent in memory: the
        // loads of p missed the cache (perf: 15% of render_tile on one load).
        if (i + 1 < bin.size()) prefetch(bin[i + 1]);
        auto add_quads = [&](uint64_t pixels, uint64_t part, int ox, int oy) {
            // Polygon stipple masks a filled polygon's pixels before any
            // other test (GL 2.1 §3.6.2), so they are never shaded.
            if (target.polygon_stipple) pixels &= target.polygon_stipple->square(ox, oy);
            stage.add_quads(p, pixels, part, ox, oy);
        };
        if (p.count == 3 && p.cover.mask) {
            for_each_small_part(p.cover, clip, add_quads);
        } else if (p.count == 3) {
            for_each_block(*p.edges, clip, add_quads);
        } else if (p.count == 2) {
            rasterize_line(stage, p, clip);
        } else {
            rasterize_point(stage, p, clip);
        }
        if (stage.error()) break;
    }
    stage.flush();
}

std::vector<TileBins::Job> TileBins::jobs(const Framebuffer& fb, bool clear) const {
    std::vector<Job> out;
    if (!clear) {
        // The filled bins in tile order, as a walk over all of them gives.
        std::vector<size_t> filled = touched_;
        std::sort(filled.begin(), filled.end());
        for (size_t t : filled) out.push_back({Rect{}, t});
        return out;
    }
    // Both grids are aligned to the framebuffer's origin and row-major, so
    // the jobs keep the bins' order (and the first failure stays the same).
    int cx0 = scissor_.x0 / kTileSize, cy0 = scissor_.y0 / kTileSize;
    for (int y = 0; y < fb.height; y += kTileSize) {
        for (int x = 0; x < fb.width; x += kTileSize) {
            Job job{{x, y, std::min(x + kTileSize, fb.width), std::min(y + kTileSize, fb.height)}};
            int bx = x / kTileSize - cx0, by = y / kTileSize - cy0;
            if (bx >= 0 && by >= 0 && bx < columns_ && by < rows_) {
                size_t t = size_t(by) * size_t(columns_) + size_t(bx);
                if (!bins_[t].empty()) job.bin = t;
            }
            out.push_back(job);
        }
    }
    return out;
}

TileResult TileBins::render(const TileTarget& target, FragmentStage& stage, unsigned threads,
                            const StoredClear* clear) const {
    // Clearing in the tile jobs pays off only with several workers: at 16 threads it halved
    // a 1080p spot frame (8.1-9.6 -> 4.0-4.7 ms), while with one or two a single sequential
    // clear was cheaper (first 512x512 spot draw 7.09 -> 7.66 ms at 1 thread; 16-core device
    // and 2-vCPU machine, docs/performance.md "Thread scaling"). Measured again under the fused
    // pipeline (1080p spot, 1 thread, 2026-11-26): 9.6 -> 10.6 ms CPU per frame with the clear
    // in the tile jobs, 10.1 with streaming stores for the tiles no primitive touches, while the
    // early depth test's share of the profile stayed the same (docs/performance.md, #12).
    // (kTileClearMinThreads; with 2 or 3, draw() may clear ahead on a thread of its own.)
    if (clear && rt::thread_count(threads, SIZE_MAX) < kTileClearMinThreads) {
        clear_rect(target.fb, *clear, 0, 0, target.fb.width, target.fb.height);
        clear = nullptr;
    }
    const std::vector<Job> todo = jobs(target.fb, clear != nullptr);
    std::vector<std::optional<Error>> errors(todo.size());
    std::vector<char> started(todo.size(), 0);  // each written by the one worker that takes the job
    // Clearing a pixel costs far less than shading one.
    uint64_t work = area_ + (clear ? uint64_t(target.fb.width) * uint64_t(target.fb.height) / 16 : 0);
    unsigned workers = work < kParallelPixels ? 1 : rt::thread_count(threads, todo.size());
    // Each worker has its own stage (interpreter, batch); stage 0 is the caller's.
    std::vector<std::unique_ptr<FragmentStage>> stages(workers);
    rt::JobQueue queue(todo.size());
    rt::run_workers(workers, [&](unsigned k) {
        if (k > 0) stages[k] = std::make_unique<FragmentStage>(target.program, target.gl, target.fb, target.budget);
        FragmentStage& s = k > 0 ? *stages[k] : stage;
        FragmentStage::Walk walk(s);
        for (size_t i; queue.next(&i);) {
            const Job& job = todo[i];
            started[i] = 1;
            if (clear) clear_rect(target.fb, *clear, job.clear.x0, job.clear.y0, job.clear.x1, job.clear.y1);
            if (job.bin == SIZE_MAX) continue;
            render_tile(target, job.bin, s);
            if (!s.error()) continue;
            errors[i] = *s.error();
            s.clear_error();
            queue.fail(i);
        }
    });
    TileResult result{stage.fragments_shaded(), stage.fragments_written(), stage.fragments_fused()};
    for (const auto& s : stages) {
        if (!s) continue;
        result.fragments_shaded += s->fragments_shaded();
        result.fragments_written += s->fragments_written();
        result.fragments_fused += s->fragments_fused();
    }
    if (auto failed = queue.first_failure()) {
        result.status = *errors[*failed];
        // The jobs after a failure are skipped; their tiles are still cleared.
        for (size_t i = 0; clear && i < todo.size(); ++i)
            if (!started[i]) clear_rect(target.fb, *clear, todo[i].clear.x0, todo[i].clear.y0, todo[i].clear.x1, todo[i].clear.y1);
    }
    return result;
}

}  // namespace glslrun::raster
