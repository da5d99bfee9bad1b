// What module.cpp's LLVM set-up offers the JIT's other code generators
// (raster/fused/gen/emit.cpp): the same target, the same optimization pipeline, hence
// the same rules for bits (no FMA contraction, no InstCombine).
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include <llvm/ExecutionEngine/ObjectCache.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/IR/Module.h>
#include <llvm/Target/TargetMachine.h>

#include "runtime/backend.h"

namespace glslrun::rt::jit {

// LLVM's machinery for one vector ISA and code-generation level, made once per process at its first
// compile (a target machine and an LLJIT with the process's symbols: about
// 20 ms each time it was made per shader): every module (a shader's, a
// fragment pipeline's) joins the one LLJIT under names of its own, and its
// code goes when its owner does (a ResourceTracker). Compiles take turns
// (`lock`): the target machine and the LLJIT's single compiler are not for
// concurrent use; tiering compiles in the background anyway.
struct Engine {
    std::mutex lock;
    std::unique_ptr<llvm::TargetMachine> machine;  // for the optimization passes and code generation
    std::unique_ptr<llvm::orc::LLJIT> jit;
    uint64_t modules = 0;  // names them apart
    // What every code cache key of this engine's code holds
    // (runtime/code_cache.h): glslrun's build ID, LLVM's version, the
    // target, its CPU features and code-generation level, the batch width.
    // Empty where the binary has no build ID: no cache then, since code
    // from another build of the same version could be loaded.
    std::string cache_salt;

    // Null where LLVM could not make it. `quick`: ExecOptions::jit_quick_codegen.
    static Engine* of(bool avx2, bool quick);

    // A new module for this engine's target, in a context of its own. Under `lock`.
    struct NewModule {
        std::unique_ptr<llvm::LLVMContext> context;
        std::unique_ptr<llvm::Module> module;
    };
    NewModule new_module(const char* name);

private:
    void make(llvm::orc::JITTargetMachineBuilder target);
};

// One module's code in an Engine's LLJIT, in a JITDylib of its own (so
// that code loaded from the code cache, whose names were chosen by another
// process, meets no other module's names); the code goes when this does.
// Its destructor takes the engine's lock, so an owner is made before the
// lock is taken and never destroyed under it.
class EngineCode {
public:
    EngineCode() = default;
    EngineCode(const EngineCode&) = delete;
    EngineCode& operator=(const EngineCode&) = delete;
    ~EngineCode();
    // Adds machine code (compile_object's, or the code cache's) to
    // `engine`'s LLJIT, under its lock; false where LLVM refused it.
    bool add_object(Engine& engine, std::unique_ptr<llvm::MemoryBuffer> object);
    // The address of the module's function `name`; null where absent (or
    // where its object could not be linked).
    void* lookup(const std::string& name) const;

private:
    void open(Engine& engine);
    Engine* engine_ = nullptr;
    llvm::orc::JITDylib* dylib_ = nullptr;
};

// `module`'s machine code for `engine`'s target, under its lock; null where
// LLVM failed. `cache` (may be null): LLVM's object cache, told of the code
// (runtime/jit/cached_shader.cpp stores it on disk).
std::unique_ptr<llvm::MemoryBuffer> compile_object(Engine& engine, llvm::Module& module, llvm::ObjectCache* cache);

// LLVM's native target, registered once per process.
void initialise_llvm();
// The compiling thread's CPU time: LLVM's cost without the machine's load
// or the wait for another compile.
double thread_cpu_seconds();
// The baseline x86-64 ISA or AVX2 (x86-64-v3), never fusing a * b + c;
// `quick`: LLVM's code generation without its optimizations (same bits).
// Where avx512() says so, AVX2's target is AVX-512 (x86-64-v4) instead.
llvm::orc::JITTargetMachineBuilder target_for(bool avx2, bool quick);
// Whether the AVX2 target generates AVX-512 code, 512-bit vectors included:
// where the CPU has AVX-512 F, BW, DQ and VL and GLSLRUN_NO_AVX512 is not 1.
// A batch's <kLanes x float> registers then take 2 of its 32 registers, not
// 4 of AVX2's 16: the ray tracer's and the marble's frames spent most of
// their time spilling and reloading them. The same IEEE operations, so the
// same bits (tests/cli/isa_determinism.sh).
bool avx512();
// The JIT's short function pass pipeline (module.cpp says why it is short).
void optimise(llvm::Module& module, llvm::TargetMachine& machine);

}  // namespace glslrun::rt::jit
