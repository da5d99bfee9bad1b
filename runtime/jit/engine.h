// What module.cpp's LLVM set-up offers the JIT's other code generators
// (pipeline.cpp): the same target, the same optimization pipeline, hence
// the same rules for bits (no FMA contraction, no InstCombine).
#pragma once
#include <memory>

#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/IR/Module.h>
#include <llvm/Target/TargetMachine.h>

#include "runtime/fragment_pipeline.h"

namespace glslrun::rt::jit {

// LLVM's native target, registered once per process.
void initialise_llvm();
// The baseline x86-64 ISA or AVX2 (x86-64-v3), never fusing a * b + c.
llvm::orc::JITTargetMachineBuilder target_for(bool avx2);
// The JIT's short function pass pipeline (module.cpp says why it is short).
void optimise(llvm::Module& module, llvm::TargetMachine& machine);

// pipeline.cpp: the fused fragment pipeline's functions for `key`; null
// where LLVM failed. *seconds (may be null): LLVM's time.
std::unique_ptr<FragmentPipeline> compile_pipeline(const PipelineKey& key, const PrimitiveLayout& layout,
                                                   double* seconds);

}  // namespace glslrun::rt::jit
