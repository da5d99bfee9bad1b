// The backend factory: a shader compiled by the backend that runs it
// (runtime/backend.h is the contract both keep), what the JIT would make of
// it, and the way from a Program to an executor, through the code cached on
// the Program (runtime/backend_cache.h: Backend::Auto's policy).
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "runtime/backend.h"

namespace glslrun::rt {

struct CodeCacheConfig;  // runtime/code_cache.h

// How a JIT compile uses the code cache (runtime/code_cache.h). `config`
// null or without a directory: not at all. `only_load`: the cached code or
// nothing (null), never an LLVM compile. *loaded (may be null): whether the
// code came from the cache.
struct CodeCacheUse {
    const CodeCacheConfig* config = nullptr;
    bool only_load = false;
    bool* loaded = nullptr;
};

// Who runs what `requested` asks for in `precision`: Interp and Jit say;
// Auto is the JIT where its plugin is there (the policy then picks, stage by
// stage: runtime/backend_cache.h). Reference always runs on the interpreter,
// and without the JIT so does everything else (the same bits).
Runner runner_for(Backend requested, Precision precision);

// `shader` compiled for `runner` to run, for `precision`,
// `fast_ops` and the vector ISA (`avx2`, else baseline x86-64). The JIT
// declines what it cannot take (Reference, a recursive call graph, calls
// that expand to too much code, a build without it): the interpreter then serves, with the same bits.
// *llvm_seconds (may be null) receives LLVM's compile time; `quick_codegen`:
// ExecOptions::jit_quick_codegen; `stop` (may be null): the JIT gives up
// between its phases once it is set (the interpreter then serves); `cache`:
// the code cache, and with only_load, null where it has no code;
// `optimised`: the JIT's second tier (JitPlan below).
std::unique_ptr<CompiledShader> compile_shader(const ir::Shader& shader, Runner runner, Precision precision,
                                               uint32_t fast_ops, bool avx2, double* llvm_seconds = nullptr,
                                               bool quick_codegen = false, const std::atomic<bool>* stop = nullptr,
                                               CodeCacheUse cache = {}, bool optimised = false);

// How the JIT would compile `shader` (runtime/jit/jit.h: plan_compile; not
// at all without the JIT). The JIT has two tiers: the first keeps a
// compile near its time budget (a draw may wait for it), so large shaders
// and every vertex shader get quick code generation; the second,
// `optimised`, compiles a stage whose draws keep running again with all of
// LLVM's code-generation optimizations, in the background
// (runtime/backend_cache.h). Both compute the same bits.
struct JitPlan {
    bool take = false;   // whether the JIT compiles it at all
    bool quick = false;  // without code-generation optimizations (same bits)
    uint64_t nanos = 0;  // LLVM's expected CPU time
    // The first tier's plan: whether the optimised tier would make other
    // code (this plan is quick, and ExecOptions::jit_quick_codegen is off).
    bool optimisable = false;
};
JitPlan plan_jit(const ir::Shader& shader, bool quick_codegen, bool optimised = false);

// An executor of `program`'s shader for `stage`, from the code cached on the
// program (compiled at the first call for its key; thread-safe). The
// program's uniforms, options and `textures` as the draw has them; the
// draw's `budget` (ExecOptions' cancel flag and deadline with it).
std::unique_ptr<Executor> make_executor(const Program& program, ir::Stage stage,
                                        const GLState::TextureUnit* textures, DrawBudget* budget);

}  // namespace glslrun::rt
