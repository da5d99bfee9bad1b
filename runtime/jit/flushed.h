// ir::ftz (a denormal becomes a zero of its sign) is written before the ops
// whose kernels flush their operand (floor, ceil, neg, abs: alu.cpp). The
// generated code runs under FTZ, so the result of an arithmetic instruction
// is never denormal, and where the flushed value is one, the flush is the
// value itself. This pass, run after SROA has made the registers values,
// drops those flushes (marble: most of its floors' operands are products).
#pragma once
#include <llvm/IR/PassManager.h>

namespace glslrun::rt::jit {

struct DropNeedlessFlushes : llvm::PassInfoMixin<DropNeedlessFlushes> {
    llvm::PreservedAnalyses run(llvm::Function& fn, llvm::FunctionAnalysisManager&);
};

}  // namespace glslrun::rt::jit
