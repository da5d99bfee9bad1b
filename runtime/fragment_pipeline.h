// The fused fragment pipeline: per (program, fragment draw state), native
// code made by the JIT for the per-lane work around the fragment shader, as
// llvmpipe's fragment functions do it: depth from the plane equation and the
// early depth test of a quad or of an 8x8 square's pixels; the shader inputs of a batch of quads
// (perspective-correct interpolation from the plane equations,
// gl_FragCoord, gl_FrontFacing, gl_PointCoord); after the shader, the late
// depth test, the depth write, the colour conversion and the colour write
// in lane order. The shader body between them is the program's compiled
// shader (runtime/backend.h), run by the fragment stage's executor.
//
// Why three functions and not one: the shader runs with denormals flushed
// (ir::FlushDenormals) and the plumbing around it, like the C++ path it
// replaces (raster/fragments.cpp), does not; the MXCSR switch stays in C++.
//
// The generated code computes the C++ path's bits: the same float operations
// in the same order, no FMA, the same clamps and NaN handling. The
// rasterizer's primitive is read through PrimitiveLayout's offsets (the
// runtime does not know raster/'s types).
#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "glslrun/glslrun.h"
#include "runtime/backend.h"

namespace glslrun::rt {

// Byte offsets into the rasterizer's primitive (raster::FsPrimitive).
struct PrimitiveLayout {
    uint32_t vertices = 0, vertex_size = 0;      // the three vertices
    uint32_t vertex_inv_w = 0, vertex_attrs = 0;  // in a vertex: 1/w (float), attributes (const float*)
    uint32_t weights = 0;  // three planes of {a, b, c} floats: the vertices' screen-space weights
    uint32_t depth = 0;    // the window depth's plane
    uint32_t ox = 0, oy = 0;  // int32: the planes' origin
    uint32_t front = 0;       // bool
    uint32_t count = 0;       // int32: 1 point, 2 line, 3 triangle
    uint32_t point_coord_origin = 0, point_coord_step = 0;  // two floats each
};

// Where a shader input component comes from.
enum class InputSource : uint8_t { Varying, FragCoord, FrontFacing, PointCoord, Zero };

struct PipelineInput {
    InputSource source = InputSource::Zero;
    uint32_t index = 0;  // Varying: the attribute; the built-ins: the component
    bool is_bool = false;  // the register holds 0/1 words (gl_FrontFacing), else floats
    auto tie() const { return std::tie(source, index, is_bool); }
    bool operator<(const PipelineInput& o) const { return tie() < o.tie(); }
};

// Blending into RGBA8 storage and the colour mask (raster/fragment_ops.h:
// blend_unorm8's 8-bit steps): with either on, the colour write reads the
// buffer's bytes first.
struct ColorOps {
    bool blend = false;
    BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
    BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
    BlendEquation equation_rgb = BlendEquation::Add, equation_alpha = BlendEquation::Add;
    std::array<uint8_t, 4> constant{};  // the blend colour as bytes
    std::array<bool, 4> mask{true, true, true, true};
    bool reads_color() const { return blend || mask != std::array<bool, 4>{true, true, true, true}; }
    auto tie() const {
        return std::tie(blend, src_rgb, dst_rgb, src_alpha, dst_alpha, equation_rgb, equation_alpha, constant, mask);
    }
    bool operator<(const ColorOps& o) const { return tie() < o.tie(); }
};

// What one pipeline is compiled for: the program's inputs and outputs and
// the draw's per-fragment state. The fused path takes the depth test (any
// function, with or without writes) and stores into one colour buffer,
// with blending and the colour mask where the buffer is RGBA8 and the depth
// test, if any, is early; other states keep the C++ path.
struct PipelineKey {
    std::vector<PipelineInput> inputs;  // per input register, in the order the fragment stage passes them
    uint32_t color_channels = 0;        // components of the colour output (0: none written)
    bool float_color = false;           // float storage, else RGBA8 (clamped, rounded to n/255)
    bool gpu_rounding = false;          // RGBA8 bytes as ColorRounding::Gpu rounds them, else Nearest
    bool depth_output = false;          // gl_FragDepth written
    bool depth_test = false, depth_write = false, early_depth = false;
    CompareFunc depth_func = CompareFunc::Less;
    ColorOps color_ops;  // only with RGBA8 storage, colour written and no late depth test
    bool avx2 = false;
    auto tie() const {
        return std::tie(inputs, color_channels, float_color, gpu_rounding, depth_output, depth_test, depth_write,
                        early_depth, depth_func, color_ops, avx2);
    }
    bool operator<(const PipelineKey& o) const { return tie() < o.tie(); }
};

// The queued quads of a batch: quad q is lanes 4q..4q+3 at (x[q], y[q]) of
// primitive prim[q].
struct QuadBatch {
    const void* prim[kLanes / 4];
    int32_t x[kLanes / 4], y[kLanes / 4];
    int32_t quads = 0;
};

// The buffers written, rows bottom up: depth, and colour 0 (RGBA: 4 bytes a
// pixel, or 4 floats with PipelineKey::float_color).
struct PipelineTarget {
    float* depth = nullptr;
    void* color = nullptr;
    int32_t width = 0, height = 0;
};

struct FragmentPipeline {
    // The early depth test (and write) of one quad's lanes in `mask`; returns those that pass.
    using QuadDepthFn = uint32_t (*)(const void* prim, int32_t x, int32_t y, uint32_t mask, const PipelineTarget* t);
    // The same test on the pixels of the 8x8 square at (ox, oy) in `pixels`
    // (bit j * 8 + i: pixel (ox + i, oy + j)), which must lie in the buffer;
    // returns those that pass.
    using SquareDepthFn = uint64_t (*)(const void* prim, int32_t ox, int32_t oy, uint64_t pixels,
                                       const PipelineTarget* t);
    // Writes the inputs: regs[i] is the register of key.inputs[i].
    using InputsFn = void (*)(const QuadBatch* batch, uint32_t* const* regs);
    // The per-fragment operations of the lanes of `alive` in lane order;
    // regs: the colour output's registers (color_channels of them), then
    // gl_FragDepth's. Returns the lanes written.
    using OutputsFn = LaneMask (*)(const QuadBatch* batch, const uint32_t* const* regs, LaneMask alive,
                                   const PipelineTarget* t);
    virtual ~FragmentPipeline() = default;
    QuadDepthFn quad_depth = nullptr;  // null unless key.early_depth
    SquareDepthFn square_depth = nullptr;  // null unless key.early_depth
    InputsFn inputs = nullptr;
    OutputsFn outputs = nullptr;
};

// A program's draws take the fused pipeline once it has shaded this many
// fragments without it: a pipeline costs 8 to 15 ms of LLVM's time (thread
// CPU, docs/performance.md), which it saves back over about a million
// fragments (the 1080p spot frame: 400,000 fragments, 2 ms saved). Piglit's
// programs, which draw a few small rectangles each, never compile one.
inline constexpr uint64_t kPipelineAfterFragments = uint64_t(1) << 20;

// The pipelines of one Program, by key, compiled once and shared by its
// workers and later draws. Without `wait`, null until a compile queued on
// the process's compile thread (runtime/compile_queue.h) is done.
class PipelineCache : public std::enable_shared_from_this<PipelineCache> {
public:
    PipelineCache() = default;
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;
    ~PipelineCache() = default;  // waits for nothing: queued compiles find it gone

    // Null where the JIT is not built in or declined the key, and until the
    // program has shaded kPipelineAfterFragments fragments without one.
    const FragmentPipeline* get(const PipelineKey& key, const PrimitiveLayout& layout, bool wait);
    // Counts fragments the program shaded without a pipeline.
    void count_unfused(uint64_t fragments) { unfused_.fetch_add(fragments, std::memory_order_relaxed); }
    // Seconds LLVM spent on this program's pipelines so far.
    double compile_seconds() const;

private:
    mutable std::mutex mutex_;
    std::map<PipelineKey, std::unique_ptr<FragmentPipeline>> pipelines_;
    std::map<PipelineKey, bool> done_;  // compiled (the pipeline may still be null: declined)
    // Stores a compile's result (under the lock); leaves `code` where the key has one.
    void store(const PipelineKey& key, std::unique_ptr<FragmentPipeline>& code, double seconds);
    double compile_seconds_ = 0;
    std::atomic<uint64_t> unfused_{0};
};

}  // namespace glslrun::rt
