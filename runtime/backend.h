// The backend seam, the contract between who runs a shader and its callers:
// a backend turns an ir::Shader into a `CompiledShader`, and each worker
// instantiates its own `Executor` from it: a register file, the uniforms
// and textures of the draw, and the code. The interpreter
// (runtime/interpreter.h) is one backend; the LLVM JIT (runtime/jit/) is the
// other. Both compute the same bits: the interpreter is the JIT's oracle
// (tests/runtime/backend_*). Which backend compiles what, and the way from
// a Program to an executor, is the factory's (runtime/backend_factory.h).
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "runtime/budget.h"

namespace glslrun::rt {

class UndefSink;

// Compile-time batch width (8..64). Fragment batches hold kLanes/4 2x2 quads:
// lanes 4q+0..3 are (x,y) (x+1,y) (x,y+1) (x+1,y+1).
// GLSLRUN_LANES exists so that a test can build other widths and check that
// images do not depend on it (tools/setup.sh test).
#ifndef GLSLRUN_LANES
#define GLSLRUN_LANES 16
#endif
inline constexpr int kLanes = GLSLRUN_LANES;
static_assert(kLanes % 4 == 0 && kLanes >= 8 && kLanes <= 64);
using LaneMask = uint64_t;  // bit i = lane i
inline constexpr LaneMask kAllLanes = kLanes == 64 ? ~LaneMask(0) : ((LaneMask(1) << kLanes) - 1);

// Precision::Fast's approximations by class (runtime/fast_kernels.h), as bits
// of a mask: the error report switches them on one class at a time to find
// which one causes an error (an ablation). Not part of the public API.
enum FastOps : uint32_t {
    kFastRsqrt = 1u << 0,   // frsqrt, and fsqrt_divisor with fdiv_by_sqrt (normalize)
    kFastExpLog = 1u << 1,  // fexp, fexp2, flog, flog2
    kFastPow = 1u << 2,     // fpow
    kFastSinCos = 1u << 3,  // fsin, fcos
    kFastTexture = 1u << 4,  // tex: the GPU's filter weights and level of detail (runtime/sampling_rules.h)
    kFastFma = 1u << 5,  // ffma, ffms, ffnma: one rounding (ir/contract.cpp)
    kAllFastOps = (1u << 6) - 1,
};

// Who runs a shader's code: the interpreter, or the JIT's native code. The
// user's glslrun::Backend is a request, `Auto` among its values: a policy
// (runtime/backend_cache.h) that picks a Runner per stage, draw by draw.
enum class Runner : uint8_t { Interp, Jit };

struct RunError {
    std::string message;
    int line = 0;
};

// The work one run() may do before it fails with a RunError (ExecOptions),
// honoured alike by both backends (docs/limits.md): loop iterations, and
// instructions charged per block as it is entered, with `cancel` polled
// whenever the count passes a multiple of kCancelPoll.
struct RunLimits {
    static constexpr uint64_t kCancelPoll = 1u << 16;
    uint64_t max_loop_iterations = ExecOptions{}.max_loop_iterations;
    uint64_t max_instructions = ExecOptions{}.max_instructions;
    const std::atomic<bool>* cancel = nullptr;
    // The draw's budget as a whole (its instructions, cancel and deadline),
    // which each executor reports to through a BudgetShare; null: the run's
    // own limits only (the debugger's replays, the tests' executors).
    DrawBudget* draw = nullptr;
    RunLimits(uint64_t loop_iterations) : max_loop_iterations(loop_iterations) {}  // the tests' loop cap alone
    explicit RunLimits(const ExecOptions& o)
        : max_loop_iterations(o.max_loop_iterations), max_instructions(o.max_instructions), cancel(o.cancel) {}
    // The RunError messages of the three ways to stop.
    std::string loop_cap_message() const;
    std::string instructions_message() const;
    static constexpr const char* kCancelledMessage = "cancelled: the time limit ran out";
};

// What an executor needs of the draw. `uniforms` (the program's store, one
// 32-bit word per component) must stay alive and unchanged while the
// executor lives: uniform-only code (the shader's prologue) runs once, when
// it is made. `textures` (kMaxTextureUnits units, may be null: nothing
// bound) must stay alive and bound as they are: the JIT binds their samplers once (jit/tex_direct.cpp).
struct ExecParams {
    const uint32_t* uniforms = nullptr;
    RunLimits limits{ExecOptions{}.max_loop_iterations};
    const GLState::TextureUnit* textures = nullptr;
    Precision precision = Precision::Precise;
    uint32_t fast_ops = kAllFastOps;  // FastOps bits: the classes Fast approximates
};

// One worker's instance of a shader: kLanes invocations per run().
class Executor {
public:
    virtual ~Executor() = default;
    // kLanes words of register r: floats, ints and bools (0/1) as raw bits.
    // The caller fills the shader's inputs (ir::Shader::inputs) here before
    // run() and reads its outputs after it; what other registers hold after
    // a run is the backend's (the JIT keeps the body's temporaries in its
    // own values, runtime/jit/codegen.h).
    virtual uint32_t* lanes(ir::Reg r) = 0;
    float* lanes_f(ir::Reg r) { return reinterpret_cast<float*>(lanes(r)); }
    // Runs the shader for the lanes in `live` (the others are left alone).
    // Returns false, with *error set, if a loop ran past the iteration cap.
    virtual bool run(LaneMask live, RunError* error) = 0;
    // After run(): the lanes that were live and did not discard.
    virtual LaneMask alive() const = 0;
    // The following runs' texture lookups skip `lanes` (they read 0): a
    // fragment batch's helper lanes, where ir::Shader::helper_lookups_matter
    // says nothing reads their lookups.
    virtual void skip_lookups(LaneMask lanes) = 0;
    // Who runs this executor's code.
    virtual Runner runner() const = 0;
    // The following runs' check_undef instructions report to `sink`
    // (runtime/undef_sink.h; null: to no one).
    virtual void watch_undefined(UndefSink* sink) = 0;
    // With `held`, the caller holds ir::FlushDenormals around the following
    // runs (a tile walk), so run() leaves the control register alone: its
    // two switches cost 20 ns a batch on AMD's cores, a tenth of a small
    // shader's frame. Without, run() sets the mode itself again. Returns
    // whether the executor takes the request; one whose runs do not flush
    // denormals (Reference) does not, and its caller must not flush them.
    virtual bool hold_denormal_mode(bool held) {
        (void)held;
        return false;
    }
};

// A shader compiled for one specialization key, shared by the workers.
class CompiledShader {
public:
    virtual ~CompiledShader() = default;
    virtual std::unique_ptr<Executor> instantiate(const ExecParams& params) const = 0;
};

}  // namespace glslrun::rt
