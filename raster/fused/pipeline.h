// The fused fragment pipeline: per (program, fragment draw state), native
// code made by the JIT for the per-lane work around the fragment shader, as
// llvmpipe's fragment functions do it: depth from the plane equation and the
// early depth (and stencil) test of a quad or of an 8x8 square's pixels; the shader inputs of a batch of quads
// (perspective-correct interpolation from the plane equations,
// gl_FragCoord, gl_FrontFacing, gl_PointCoord); after the shader, the late
// depth test, the depth write, the colour conversion and the colour write
// in lane order. The shader body between them is the program's compiled
// shader (runtime/backend.h), run by the fragment stage's executor.
// The emitter is raster/fused/gen/.
//
// The shader and the plumbing around it run under one denormal mode, held
// by the tile walk (FragmentStage::Walk: denormals flushed, as
// ir::FlushDenormals, except in Reference), for the C++ path
// (raster/fragments.cpp) as for these functions.
//
// The generated code computes the C++ path's bits: the same float operations
// in the same order, no FMA, the same clamps and NaN handling. It reads
// raster's own types (FsPrimitive, FragmentState) where offsetof puts them;
// runtime/jit/ is the LLVM toolkit it is built with. Which states it takes
// is decided in one place, fusable() (raster/fused/state.h).
#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "raster/fused/state.h"
#include "runtime/backend.h"
#include "runtime/tiering.h"

namespace glslrun::rt {
struct CodeCacheConfig;  // runtime/code_cache.h
struct JitEntryPoints;   // runtime/jit_plugin.h
}

namespace glslrun::raster::fused {

using rt::kLanes;
using rt::LaneMask;

// The queued quads of a batch: quad q is lanes 4q..4q+3 at (x[q], y[q]) of
// primitive prim[q].
struct QuadBatch {
    const void* prim[kLanes / 4];
    int32_t x[kLanes / 4], y[kLanes / 4];
    int32_t quads = 0;
};

// The buffers written, rows bottom up: depth, and colour 0 (RGBA: 4 bytes a
// pixel, or 4 floats with FragmentState::float_color).
struct Target {
    float* depth = nullptr;
    uint8_t* stencil = nullptr;
    std::array<void*, kMaxDrawBuffers> color{};  // by draw buffer
    int32_t width = 0, height = 0;
};

// The inputs function of a pipeline: it depends on State::inputs and
// State::avx2 alone (inputs_only()), so the states a program draws with
// share one (mirror draws with four; the inputs function was two thirds of
// each one's LLVM time).
struct InputsCode {
    // Writes the inputs: regs[i] is the register of State::inputs[i].
    using InputsFn = void (*)(const QuadBatch* batch, uint32_t* const* regs);
    virtual ~InputsCode() = default;
    InputsFn inputs = nullptr;
};

// The fragment functions of one State.
struct Pipeline {
    // The early depth test, and the stencil test where it is on (and their
    // writes), of one quad's lanes in `mask`; returns those that pass.
    using QuadDepthFn = uint32_t (*)(const void* prim, int32_t x, int32_t y, uint32_t mask, const Target* t);
    // The same tests on the pixels of the 8x8 square at (ox, oy) in `pixels`
    // (bit j * 8 + i: pixel (ox + i, oy + j)), which must lie in the buffer;
    // returns those that pass.
    using SquareDepthFn = uint64_t (*)(const void* prim, int32_t ox, int32_t oy, uint64_t pixels,
                                       const Target* t);
    using InputsFn = InputsCode::InputsFn;
    // The per-fragment operations of the lanes of `alive` in lane order;
    // regs: colour buffer 0's output's registers (color_channels of them),
    // gl_FragDepth's, then those of buffers 1 and up (State::more_channels). Returns the lanes written.
    using OutputsFn = LaneMask (*)(const QuadBatch* batch, const uint32_t* const* regs, LaneMask alive,
                                   const Target* t);
    virtual ~Pipeline() = default;
    QuadDepthFn quad_depth = nullptr;  // null unless State::early_depth (with the stencil test: both tests)
    SquareDepthFn square_depth = nullptr;  // null unless State::early_depth (with the stencil test: both tests)
    InputsFn inputs = nullptr;  // shared_inputs's
    OutputsFn outputs = nullptr;
    std::shared_ptr<const InputsCode> shared_inputs;
};

// A pipeline's compile: in, the code cache (may be null: none); out,
// LLVM's time (thread CPU) and whether the code came from the cache.
struct PipelineCompile {
    const rt::CodeCacheConfig* cache = nullptr;
    // In: the inputs code of another of the program's states with the same
    // inputs_only() (null: none yet, made with this pipeline); out: the
    // pipeline's.
    std::shared_ptr<const InputsCode> inputs;
    // In: only the code cache's code (null where it has none): no LLVM.
    bool load_only = false;
    double seconds = 0;
    bool loaded = false;
};

// A program's draws take the fused pipeline once it has shaded this many
// fragments without it: a pipeline costs 8 to 15 ms of LLVM's time (thread
// CPU, docs/performance.md), which it saves back over about a million
// fragments (the 1080p spot frame: 400,000 fragments, 2 ms saved). Piglit's
// programs, which draw a few small rectangles each, never compile one.
// A pipeline the code cache holds costs no LLVM time: it is taken at once.
inline constexpr uint64_t kPipelineAfterFragments = uint64_t(1) << 20;

// The pipelines of one Program, by state_key(), compiled once and shared by
// its workers and later draws (runtime/tiering.h). Without `wait`, null
// until a compile queued on the process's compile thread is done.
class Cache {
public:
    Cache() : slots_(Slots::make()) {}
    Cache(const Cache&) = delete;
    Cache& operator=(const Cache&) = delete;
    ~Cache() = default;  // waits for nothing: queued compiles find it gone

    // Null where the JIT is not built in or declined the key, and until the
    // program has shaded kPipelineAfterFragments fragments without one,
    // unless the code cache holds its code (looked up once per key).
    // `options`: the code cache's (code_cache_config), read only to compile or load.
    const Pipeline* get(const State& state, bool wait, const ExecOptions& options);
    // Counts fragments the program shaded without a pipeline.
    void count_unfused(uint64_t fragments) { unfused_.fetch_add(fragments, std::memory_order_relaxed); }
    // Seconds LLVM spent on this program's pipelines so far.
    double compile_seconds() const { return slots_->seconds(); }
    // The pipelines compiled by LLVM, and loaded from the code cache, so far.
    Program::JitCompiles counts() const { return slots_->compiles(); }

private:
    using Slots = rt::CodeSlots<std::string, Pipeline>;
    // The inputs functions made so far, by state_key(inputs_only(state)):
    // each state's compile takes its inputs from here.
    struct Inputs {
        std::mutex lock;
        std::map<std::string, std::shared_ptr<const InputsCode>> made;
    };
    // The keys whose code was looked for in the code cache before it was due.
    struct Probed {
        std::mutex lock;
        std::set<std::string> keys;
    };
    const Pipeline* cached(const std::string& key, const State& state, const ExecOptions& options);
    static Slots::Made make(const rt::JitEntryPoints& jit, const State& state, const rt::CodeCacheConfig& config,
                            Inputs& shelf, bool load_only);
    std::shared_ptr<Slots> slots_;
    std::shared_ptr<Inputs> inputs_ = std::make_shared<Inputs>();
    std::shared_ptr<Probed> probed_ = std::make_shared<Probed>();
    std::atomic<uint64_t> unfused_{0};
};

// The generated functions of `state`, from the code cache where it has
// them; null where it is not fusable() or LLVM failed. `compile` may be
// null. (raster/fused/gen/, in the JIT plugin: Cache::get calls it
// through rt::jit_plugin().)
std::unique_ptr<Pipeline> compile(const State& state, PipelineCompile* compile);

}  // namespace glslrun::raster::fused
