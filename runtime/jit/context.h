// What the generated code of one executor and its call-outs share. The
// generated function reads and writes these fields by their offsets.
#pragma once
#include <cstddef>
#include <atomic>
#include <cstdint>

#include "runtime/interp_kernels.h"

namespace glslrun::rt::jit {

// Why a run stopped early (the generated function's return value).
enum class Failure : int32_t { None = 0, LoopCap = 1, MissingFunction = 2, Instructions = 3, Cancelled = 4 };

struct Context {
    uint64_t max_loop_iterations = 0;  // read at entry
    // The work budget, read at entry: instructions charged per block entered
    // and the cancel flag polled every kCancelPoll of them, as the
    // interpreter does (runtime/interpreter.cpp). `cancel` may be null.
    uint64_t max_instructions = 0;
    const std::atomic<bool>* cancel = nullptr;
    uint64_t alive = 0;                // written at exit: the lanes that did not discard
    int32_t error_line = 0;            // with a Failure
    // The call-outs run the interpreter's kernels over this machine (its
    // regs and mask set per call).
    Machine<uint32_t> machine;
    uint32_t reg_count = 0;  // register reg_count is the zero register
};

inline constexpr size_t kMaxLoopOffset = offsetof(Context, max_loop_iterations);
inline constexpr size_t kMaxInstructionsOffset = offsetof(Context, max_instructions);
inline constexpr size_t kCancelOffset = offsetof(Context, cancel);
inline constexpr size_t kAliveOffset = offsetof(Context, alive);
inline constexpr size_t kErrorLineOffset = offsetof(Context, error_line);

// One instruction that the generated code runs with an interpreter kernel.
struct CallOut {
    Kernel<uint32_t> kernel;
    ir::Instr instr;
};

// The generated functions: a batch (`live` lanes), and the prologue (all
// lanes, before any batch). `regs` is the executor's register file.
using ShaderFn = int32_t (*)(Context* ctx, uint32_t* regs, const uint32_t* uniforms, uint64_t live);

// Runs `call`'s kernel on the lanes in `exec` (a plain C++ function whose
// address the generated code holds).
void run_call_out(Context* ctx, uint32_t* regs, const CallOut* call, uint64_t exec);

}  // namespace glslrun::rt::jit
