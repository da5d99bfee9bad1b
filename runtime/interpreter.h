// The batched IR interpreter: runs one ir::Shader over kLanes invocations at
// once, structure of arrays. Each instruction loops over the lanes, so the
// dispatch cost is paid once per instruction per batch, not per invocation.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"

namespace glslrun::rt {

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
    kAllFastOps = (1u << 4) - 1,
};

// The work one run() may do before it fails with a RunError (ExecOptions).
struct RunLimits {
    uint64_t max_loop_iterations = ExecOptions{}.max_loop_iterations;
    uint64_t max_instructions = ExecOptions{}.max_instructions;
    const std::atomic<bool>* cancel = nullptr;
    RunLimits(uint64_t loop_iterations) : max_loop_iterations(loop_iterations) {}  // the tests' loop cap alone
    explicit RunLimits(const ExecOptions& o)
        : max_loop_iterations(o.max_loop_iterations), max_instructions(o.max_instructions), cancel(o.cancel) {}
};

struct RunError {
    std::string message;
    int line = 0;
};

class Engine;  // runtime/interpreter.cpp: the interpreter for one register word size

class Interpreter {
public:
    // `uniforms` must stay alive while the interpreter runs; it is the
    // program's uniform store (one 32-bit word per component). Its values
    // must not change during the interpreter's life: the shader's prologue
    // (uniform-only code) runs once, here. `textures` (kMaxTextureUnits
    // units, may be null: nothing bound) must stay alive too.
    // `precision` (glslrun.h): Precise and Fast run fp32 registers, Fast with
    // approximate kernels for a few ops; Reference runs double registers.
    // `fast_ops` (FastOps bits): the classes Fast approximates; the others
    // keep their Precise kernels.
    Interpreter(const ir::Shader& shader, const uint32_t* uniforms, const RunLimits& limits,
                const GLState::TextureUnit* textures = nullptr, Precision precision = Precision::Precise,
                uint32_t fast_ops = kAllFastOps);
    ~Interpreter();

    // kLanes words of register r: floats, ints and bools (0/1) as raw bits.
    // In Reference mode the shader works on doubles behind these words: the
    // inputs (ir::Shader::inputs) are read from them at run() and the outputs
    // (ir::Shader::outputs) rounded back to float into them after it; other
    // registers are not exchanged.
    uint32_t* lanes(ir::Reg r);
    float* lanes_f(ir::Reg r) { return reinterpret_cast<float*>(lanes(r)); }

    // Runs the shader for the lanes in `live` (the others are left alone).
    // Returns false, with *error set, if it ran past one of its RunLimits.
    bool run(LaneMask live, RunError* error);

    // After run(): the lanes that were live and did not discard.
    LaneMask alive() const;

private:
    std::unique_ptr<Engine> engine_;
};

}  // namespace glslrun::rt
