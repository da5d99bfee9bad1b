// The transcendental built-ins as generated vector code (runtime/jit/math.cpp):
// ir/precise_math.h's functions (Precise) and ir/fast_math.h's (Fast) written
// out in LLVM IR operation for operation, with the kernels' denormal flushes
// (runtime/interp_kernels.h, runtime/fast_kernels.h), so that they give the
// interpreter's bits without calling its kernels.
#pragma once
#include <llvm/IR/IRBuilder.h>

#include "ir/ir.h"

namespace glslrun::rt::jit {

// Whether `op` is generated here, in Fast's form (`fast`: Precision::Fast
// with the op's class among the fast ops) or in Precise's (not Precise
// fpow: emit_pow_common).
bool generates_math(ir::Op op, bool fast);

// The result of `op` (generates_math) on the float vectors `a` and `b` (b
// only for two-operand ops): a float vector, the kernel's bits in every lane.
llvm::Value* emit_math(llvm::IRBuilder<>& builder, ir::Op op, bool fast, llvm::Value* a, llvm::Value* b);

// Precise fpow (kernels::pow_lanes) where every lane is common: the flushed
// math::pow_common in every lane, and whether some lane needs pow's special
// cases (math::pow_is_common false), where the caller runs the kernel.
struct PowCommon {
    llvm::Value* value;     // kLanes floats
    llvm::Value* any_rare;  // i1
};
PowCommon emit_pow_common(llvm::IRBuilder<>& builder, llvm::Value* a, llvm::Value* b);

// ir::ftz on a float vector: a denormal becomes a zero of its sign.
llvm::Value* flush_denormals(llvm::IRBuilder<>& builder, llvm::Value* v);

}  // namespace glslrun::rt::jit
