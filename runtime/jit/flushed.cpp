// runtime/jit/flushed.h: flushes of values that cannot be denormal.
#include "runtime/jit/flushed.h"

#include <cfloat>

#include <llvm/IR/InlineAsm.h>
#include <llvm/IR/Instructions.h>
#include <llvm/IR/IntrinsicInst.h>
#include <llvm/IR/PatternMatch.h>

namespace glslrun::rt::jit {

namespace {

namespace pm = llvm::PatternMatch;

// Whether `v` is never denormal when the code runs under FTZ (and DAZ): an
// arithmetic instruction's result (the CPU flushes it), a conversion from
// an integer, or a move, rounding, sign change or pick of such values
// (the masked writes' selects of a register's new and old words included).
// Constants are not: LLVM may have folded them without flushing.
bool never_denormal(const llvm::Value* v, int depth) {
    if (depth > 6) return false;
    const auto* in = llvm::dyn_cast<llvm::Instruction>(v);
    if (!in) return false;
    switch (in->getOpcode()) {
    case llvm::Instruction::FAdd: case llvm::Instruction::FSub: case llvm::Instruction::FMul:
    case llvm::Instruction::FDiv: case llvm::Instruction::SIToFP: case llvm::Instruction::UIToFP:
        return true;
    case llvm::Instruction::FNeg: case llvm::Instruction::BitCast:  // (the register file's words: i32 lanes)
        return never_denormal(in->getOperand(0), depth + 1);
    case llvm::Instruction::Select:
        return never_denormal(in->getOperand(1), depth + 1) && never_denormal(in->getOperand(2), depth + 1);
    case llvm::Instruction::ShuffleVector: {
        const auto* s = llvm::cast<llvm::ShuffleVectorInst>(in);
        for (int lane : s->getShuffleMask()) {
            const unsigned n = llvm::cast<llvm::FixedVectorType>(s->getOperand(0)->getType())->getNumElements();
            if (lane >= 0 && !never_denormal(s->getOperand(unsigned(lane) < n ? 0 : 1), depth + 1)) return false;
        }
        return true;
    }
    case llvm::Instruction::Call: {
        const auto* call = llvm::cast<llvm::CallInst>(in);
        if (llvm::isa<llvm::InlineAsm>(call->getCalledOperand())) return true;  // alu.cpp's + and *
        switch (call->getIntrinsicID()) {
        case llvm::Intrinsic::sqrt: return true;
        case llvm::Intrinsic::fabs: case llvm::Intrinsic::floor: case llvm::Intrinsic::ceil:
            return never_denormal(call->getArgOperand(0), depth + 1);
        default: return false;
        }
    }
    default: return false;
    }
}

// x in flush_denormals' select(|x| < FLT_MIN, copysign(0, x), x); else null.
llvm::Value* flushed_value(llvm::Instruction& in) {
    llvm::Value *x = nullptr, *a = nullptr, *b = nullptr, *zero = nullptr;
    llvm::FCmpInst::Predicate predicate;
    const llvm::APFloat* min = nullptr;
    if (!pm::match(&in, pm::m_Select(pm::m_FCmp(predicate, pm::m_FAbs(pm::m_Value(a)), pm::m_APFloat(min)),
                                     pm::m_Intrinsic<llvm::Intrinsic::copysign>(pm::m_Value(zero), pm::m_Value(b)), pm::m_Value(x))))
        return nullptr;
    if (predicate != llvm::FCmpInst::FCMP_OLT || a != x || b != x || !pm::match(zero, pm::m_PosZeroFP()) ||
        min->isNegative() || min->convertToFloat() != FLT_MIN)
        return nullptr;
    return x;
}

}  // namespace

llvm::PreservedAnalyses DropNeedlessFlushes::run(llvm::Function& fn, llvm::FunctionAnalysisManager&) {
    bool changed = false;
    for (llvm::BasicBlock& block : fn)
        for (llvm::Instruction& in : block)
            if (llvm::Value* x = flushed_value(in); x && never_denormal(x, 0)) {
                in.replaceAllUsesWith(x);
                changed = true;
            }
    return changed ? llvm::PreservedAnalyses::none() : llvm::PreservedAnalyses::all();
}

}  // namespace glslrun::rt::jit
