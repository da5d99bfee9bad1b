// draw()'s working memory, kept by the Program between draws (Program::State::
// draw_scratch). A 262k-triangle draw needs tens of MB of vertex, clip,
// primitive and bin storage; allocated afresh per draw, the kernel's page
// faults on it were a fifth of the frame (perf). Every draw empties what it
// uses first, so nothing of one draw reaches the next but capacity.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/assemble.h"
#include "raster/clip.h"
#include "raster/fragments.h"
#include "raster/huge_pages.h"
#include "raster/tiles.h"
#include "runtime/execute.h"

namespace glslrun::raster {

// What setting up one job of primitives produces, in submission order.
struct SetupOut {
    AttrArena arena;  // attributes of clipped and flat-shaded vertices, until the draw ends
    std::vector<FsPrimitive, HugePageAllocator<FsPrimitive>> prims;
    std::vector<Rect> bounds;  // per primitive: the pixels it may cover
    // Per triangle larger than a square, in order: its edges (FsPrimitive::edges,
    // set when the draw bins the primitives, once this no longer grows).
    std::vector<TriangleEdges> edges;
    uint64_t triangles = 0;
    // The primitive being set up and its vertices (FsPrimitive::primitive).
    uint32_t current_primitive = 0;
    std::array<uint32_t, 3> current_ids{};
    // The line stipple counter (raster/stipple.h): a stippled draw sets up
    // in one job, in submission order, so that it runs on along strips.
    uint32_t stipple_counter = 0;
    // The runs of stippled lines made so far, bounded by kMaxStippleRuns:
    // past it the draw fails instead of storing more (raster/stipple.h).
    uint64_t stipple_runs = 0;
    // Counts the stippled lines' runs without making them: the draw's
    // first setup, which refuses it before any run is stored.
    bool count_runs_only = false;

    void clear() {
        arena.clear();
        prims.clear();
        bounds.clear();
        edges.clear();
        triangles = 0;
        stipple_counter = 0;
        stipple_runs = 0;
        count_runs_only = false;
    }
};

struct DrawScratch {
    exec::VertexOutputs shaded;
    std::vector<ClipVertex> vertices;  // per vertex of the arrays
    std::vector<uint32_t> outcodes;    // per vertex of the arrays
    std::vector<float> front_attrs;    // per vertex of the arrays: its fragment attribute vector
    std::vector<FsVertex> window;      // per vertex of the arrays: window coordinates
    std::vector<AssembledPrim> assembled;
    std::vector<SetupOut> setup;  // per job; only the first `jobs` are used by a draw
    TileBins bins;
};

}  // namespace glslrun::raster
