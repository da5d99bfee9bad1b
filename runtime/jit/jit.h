// The LLVM JIT backend: compiles an ir::Shader into native vector code that
// computes the interpreter's bits (runtime/backend.h). One function per
// shader runs a batch of kLanes invocations: registers are vectors of kLanes
// words in the same register file layout as the interpreter's, execution
// masks are lane bit masks with the interpreter's semantics
// (runtime/exec_mask.h), and a branch is skipped when no lane takes it.
//
// Files: jit.h (this), context.h (what generated code and its call-outs
// share), module.cpp (LLVM set-up, compiling, the executor), codegen.h and
// control.cpp (blocks, masks, control flow), alu.cpp (the instructions),
// callout.cpp (ops that call the interpreter's kernels), entry.cpp (the
// plugin's exported entry points: runtime/jit/ is libglslrun-jit.so, see
// runtime/jit_plugin.h). plan_compile is defined in the library itself
// (runtime/jit_plan.cpp), which plans without loading LLVM.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>

#include "runtime/backend_factory.h"

namespace glslrun::rt::jit {

struct CompileStats {
    double seconds = 0;  // LLVM's CPU time: IR generation, optimization and machine code
    // In: a background compile gives up (null code) once this is set,
    // checked between its phases (runtime/compile_queue.h).
    const std::atomic<bool>* stop = nullptr;
    // In: the code cache (may be null), read before any LLVM work and
    // written after a compile; `only_load`: null code rather than a compile.
    const CodeCacheConfig* cache = nullptr;
    bool only_load = false;
    // In: the JIT's second tier (JitPlan): all of code generation's
    // optimizations, cached under a key of its own.
    bool optimised = false;
    bool loaded = false;  // out: the code came from the cache
};

// How the JIT would compile `shader`, from the size of each function it
// writes (main, the prologue and each called function, once): LLVM's time
// grows a little faster than linearly with one function's instructions
// (about 10 LLVM instructions per IR instruction; code generation is most
// of it). Measured
// on the lecture's programs and tests/compile_cost (docs/limits.md): 0.45 ms
// of CPU per instruction, twice that per 1000 of them, about half of it
// without LLVM's code-generation optimizations. A shader expected past
// kCompileBudgetNanos compiles without those optimizations; one expected
// past kDeclineNanos even so stays on the interpreter. Between the two, the
// JIT still pays: multi_light's 1080p frame takes 15.5 ms of CPU compiled so
// (190 ms of LLVM) against 20.1 interpreted, and Backend::Auto starts such a compile only once
// the interpreter has spent as long, in the background.
inline constexpr uint64_t kCompileBudgetNanos = 100'000'000, kDeclineNanos = 500'000'000;
inline constexpr double kNanosPerInstruction = 450'000, kInstructionsDoublingCost = 1000, kQuickCodegenShare = 0.55;
// `quick_codegen`: ExecOptions::jit_quick_codegen. `optimised`: the second
// tier's plan (JitPlan), which takes what the first takes, never quick.
JitPlan plan_compile(const ir::Shader& shader, bool quick_codegen, bool optimised = false);

// Native code for `shader` in `precision` (Precise or Fast, with Fast's
// `fast_ops` classes) for the baseline x86-64 ISA or AVX2, with LLVM's
// code-generation optimizations unless `quick_codegen`. Null where the
// JIT does not take the shader (a recursive call graph, functions that
// weigh too much, or LLVM failed):
// the caller runs the interpreter instead, which computes the same bits.
std::unique_ptr<CompiledShader> compile(const ir::Shader& shader, Precision precision, uint32_t fast_ops,
                                        bool avx2, bool quick_codegen, CompileStats* stats);

}  // namespace glslrun::rt::jit
