// What module.cpp's LLVM set-up offers the JIT's other code generators
// (pipeline.cpp): the same target, the same optimization pipeline, hence
// the same rules for bits (no FMA contraction, no InstCombine).
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>

#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/IR/Module.h>
#include <llvm/Target/TargetMachine.h>

#include "runtime/fragment_pipeline.h"

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
    std::unique_ptr<llvm::TargetMachine> machine;  // for the optimization passes
    std::unique_ptr<llvm::orc::LLJIT> jit;
    uint64_t modules = 0;  // names them apart

    // Null where LLVM could not make it. `quick`: ExecOptions::jit_quick_codegen.
    static Engine* of(bool avx2, bool quick);

private:
    void make(llvm::orc::JITTargetMachineBuilder target);
};

// LLVM's native target, registered once per process.
void initialise_llvm();
// The compiling thread's CPU time: LLVM's cost without the machine's load
// or the wait for another compile.
double thread_cpu_seconds();
// The baseline x86-64 ISA or AVX2 (x86-64-v3), never fusing a * b + c;
// `quick`: LLVM's code generation without its optimizations (same bits).
llvm::orc::JITTargetMachineBuilder target_for(bool avx2, bool quick);
// The JIT's short function pass pipeline (module.cpp says why it is short).
void optimise(llvm::Module& module, llvm::TargetMachine& machine);

// pipeline.cpp: the fused fragment pipeline's functions for `key`; null
// where LLVM failed. *seconds (may be null): LLVM's time (thread CPU).
std::unique_ptr<FragmentPipeline> compile_pipeline(const PipelineKey& key, const PrimitiveLayout& layout,
                                                   double* seconds);

}  // namespace glslrun::rt::jit
