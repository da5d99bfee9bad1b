// The JIT's instructions: the opcode table's semantics (ir/opcodes.def's
// `expr` column, ir/scalar_ops.h) as LLVM vector operations on kLanes lanes,
// written to give the same bits as the interpreter's kernels: the same IEEE
// operations in the same order, no fast-math flags, no FMA (the target
// machine forbids contraction), the same explicit denormal flushes (ftz).
// Ops whose kernels are long (the transcendental built-ins, texture
// sampling, indexed register access, integer division) call the
// interpreter's kernels instead (runtime/jit/callout.cpp).
#include <cfloat>

#include <llvm/IR/Intrinsics.h>

#include "runtime/fast_kernels.h"
#include "runtime/jit/codegen.h"

namespace glslrun::rt::jit {

namespace {

using ir::Op;

// Ops with a kernel too long to write out here: the generated code calls it.
bool calls_kernel(Op op) {
    switch (op) {
    case Op::fexp: case Op::fexp2: case Op::flog: case Op::flog2: case Op::fpow:
    case Op::fsin: case Op::fcos: case Op::ftan: case Op::fasin: case Op::facos: case Op::fatan: case Op::fatan2:
    case Op::idiv: case Op::imod:
    case Op::uniform_ind: case Op::load_ind: case Op::store_ind: case Op::tex:
        return true;
    default: return false;
    }
}

WriteMode write_mode(Op op) {
    return op == Op::ddx || op == Op::ddy ? WriteMode::Blends : WriteMode::Honours;
}

}  // namespace

llvm::Value* Emitter::splat_f(float v) { return llvm::ConstantFP::get(vf32_, v); }
llvm::Value* Emitter::splat_i(uint32_t v) { return llvm::ConstantInt::get(vi32_, v); }

llvm::Value* Emitter::call_intrinsic(unsigned id, std::initializer_list<llvm::Value*> args) {
    return b_.CreateIntrinsic(llvm::Intrinsic::ID(id), {(*args.begin())->getType()}, llvm::ArrayRef(args));
}

llvm::Value* Emitter::reg_ptr(ir::Reg r) {
    const uint64_t index = r == ir::kNoReg || r >= shader_.regs.size() ? shader_.regs.size() : r;
    return b_.CreateConstInBoundsGEP1_64(i32_, regs_, index * kLanes);
}

constexpr unsigned kRegAlign = kLanes * 4 < 64 ? kLanes * 4 : 64;

llvm::Value* Emitter::load_reg(ir::Reg r) {
    return b_.CreateAlignedLoad(vi32_, reg_ptr(r), llvm::Align(kRegAlign));
}
llvm::Value* Emitter::load_float(ir::Reg r) { return b_.CreateBitCast(load_reg(r), vf32_); }

llvm::Value* Emitter::exec_lanes() {
    return b_.CreateBitCast(b_.CreateTrunc(load_mask(exec_), mask_int_), llvm::FixedVectorType::get(i1_, kLanes));
}

void Emitter::write_reg(ir::Reg r, llvm::Value* words, WriteMode mode, bool unmasked) {
    llvm::Value* at = reg_ptr(r);
    if (!(mode == WriteMode::Honours && unmasked)) {
        llvm::Value* old = b_.CreateAlignedLoad(vi32_, at, llvm::Align(kRegAlign));
        words = b_.CreateSelect(exec_lanes(), words, old);
    }
    b_.CreateAlignedStore(words, at, llvm::Align(kRegAlign));
}

llvm::Value* Emitter::as_bool(llvm::Value* words) { return b_.CreateICmpNE(words, splat_i(0)); }
llvm::Value* Emitter::from_bool(llvm::Value* lanes) { return b_.CreateZExt(lanes, vi32_); }

// ir::ftz: a denormal becomes a zero of its sign.
llvm::Value* Emitter::ftz(llvm::Value* v) {
    llvm::Value* tiny = b_.CreateFCmpOLT(call_intrinsic(llvm::Intrinsic::fabs, {v}), splat_f(FLT_MIN));
    return b_.CreateSelect(tiny, call_intrinsic(llvm::Intrinsic::copysign, {splat_f(0.0f), v}), v);
}

void Emitter::emit_instr(const ir::Instr& in) {
    const bool fast = precision_ == Precision::Fast && (fast_op_class(in.op) & fast_ops_);
    llvm::Value* result = nullptr;
    if (fast || calls_kernel(in.op) || !emit_native(in, &result)) {
        emit_call_out(in);
        return;
    }
    write_reg(in.dst, result, write_mode(in.op), in.unmasked);
}

bool Emitter::emit_native(const ir::Instr& in, llvm::Value** result) {
    const ir::OpInfo& info = ir::op_info(in.op);
    switch (in.op) {
    case Op::mov: *result = load_reg(in.src[0]); return true;
    case Op::konst: *result = splat_i(in.imm[0]); return true;
    case Op::sel: *result = b_.CreateSelect(as_bool(load_reg(in.src[0])), load_reg(in.src[1]), load_reg(in.src[2])); return true;
    case Op::uniform: {
        llvm::Value* word = b_.CreateLoad(i32_, b_.CreateConstInBoundsGEP1_64(i32_, uniforms_, in.imm[0]));
        *result = b_.CreateVectorSplat(kLanes, word);
        return true;
    }
    case Op::ddx: case Op::ddy: *result = b_.CreateBitCast(emit_derivative(in.op, load_float(in.src[0])), vi32_); return true;
    default: break;
    }
    if (info.kind != ir::OpKind::Alu) return false;
    llvm::Value* v = nullptr;
    if (info.operand == ir::TypeClass::F) {
        llvm::Value* a = load_float(in.src[0]);
        llvm::Value* b = info.arity > 1 ? load_float(in.src[1]) : nullptr;
        llvm::Value* c = info.arity > 2 ? load_float(in.src[2]) : nullptr;
        if (info.result == ir::TypeClass::F) v = b_.CreateBitCast(emit_float_op(in.op, a, b, c), vi32_);
        else if (info.result == ir::TypeClass::B) v = emit_compare(in.op, a, b);
        else v = emit_conversion(in.op, a);
    } else {
        llvm::Value* a = load_reg(in.src[0]);
        llvm::Value* b = info.arity > 1 ? load_reg(in.src[1]) : nullptr;
        if (info.result == info.operand && info.operand == ir::TypeClass::I) v = emit_int_op(in.op, a, b);
        else if (info.result == ir::TypeClass::B) v = emit_compare(in.op, a, b);
        else v = emit_conversion(in.op, a);
    }
    *result = v;
    return v != nullptr;
}

llvm::Value* Emitter::emit_float_op(Op op, llvm::Value* a, llvm::Value* b, llvm::Value* c) {
    auto floor = [&](llvm::Value* x) { return call_intrinsic(llvm::Intrinsic::floor, {x}); };
    // ir::a_nan_first: + and * return a's NaN when a is one.
    auto nan_first = [&](llvm::Value* x, llvm::Value* r) {
        return b_.CreateSelect(b_.CreateFCmpUNO(x, x), x, r);
    };
    auto product = [&] { return nan_first(a, b_.CreateFMul(a, b)); };
    switch (op) {
    case Op::fadd: return nan_first(a, b_.CreateFAdd(a, b));
    case Op::fsub: return b_.CreateFSub(a, b);
    case Op::fmul: return product();
    case Op::fdiv: case Op::fdiv_by_sqrt: return b_.CreateFDiv(a, b);
    case Op::fneg: return ftz(b_.CreateFNeg(a));
    case Op::fabs: return ftz(call_intrinsic(llvm::Intrinsic::fabs, {a}));
    case Op::fsign:
        return b_.CreateSelect(b_.CreateFCmpOGT(a, splat_f(0.0f)), splat_f(1.0f),
                               b_.CreateSelect(b_.CreateFCmpOLT(a, splat_f(0.0f)), splat_f(-1.0f), splat_f(0.0f)));
    case Op::ffloor: return floor(ftz(a));
    case Op::fceil: return call_intrinsic(llvm::Intrinsic::ceil, {ftz(a)});
    case Op::ffract: return b_.CreateFSub(a, floor(a));
    case Op::fmod: return b_.CreateFSub(a, nan_first(b, b_.CreateFMul(b, floor(b_.CreateFDiv(a, b)))));
    case Op::fmin: return b_.CreateSelect(b_.CreateOr(b_.CreateFCmpOLT(a, b), b_.CreateFCmpUNE(b, b)), a, b);
    case Op::fmax: return b_.CreateSelect(b_.CreateOr(b_.CreateFCmpOLT(b, a), b_.CreateFCmpUNE(b, b)), a, b);
    case Op::fsqrt: case Op::fsqrt_divisor: return call_intrinsic(llvm::Intrinsic::sqrt, {a});
    case Op::frsqrt: return b_.CreateFDiv(splat_f(1.0f), call_intrinsic(llvm::Intrinsic::sqrt, {a}));
    case Op::fmad: {
        llvm::Value* p = product();
        return nan_first(p, b_.CreateFAdd(p, c));
    }
    case Op::fmsub: return b_.CreateFSub(product(), c);
    case Op::fnmadd: return b_.CreateFSub(c, product());
    default: return nullptr;
    }
}

llvm::Value* Emitter::emit_int_op(Op op, llvm::Value* a, llvm::Value* b) {
    llvm::Value* zero = splat_i(0);
    switch (op) {
    case Op::iadd: return b_.CreateAdd(a, b);
    case Op::isub: return b_.CreateSub(a, b);
    case Op::imul: return b_.CreateMul(a, b);
    case Op::ineg: return b_.CreateSub(zero, a);
    case Op::iabs: return b_.CreateSelect(b_.CreateICmpSLT(a, zero), b_.CreateSub(zero, a), a);
    case Op::isign: return b_.CreateSub(from_bool(b_.CreateICmpSGT(a, zero)), from_bool(b_.CreateICmpSLT(a, zero)));
    case Op::imin: return b_.CreateSelect(b_.CreateICmpSLT(b, a), b, a);
    case Op::imax: return b_.CreateSelect(b_.CreateICmpSLT(a, b), b, a);
    default: return nullptr;
    }
}

// Comparisons and logic: bool results as words 0 or 1.
llvm::Value* Emitter::emit_compare(Op op, llvm::Value* a, llvm::Value* b) {
    llvm::Value* r = nullptr;
    switch (op) {
    case Op::flt: r = b_.CreateFCmpOLT(a, b); break;
    case Op::fle: r = b_.CreateFCmpOLE(a, b); break;
    case Op::fgt: r = b_.CreateFCmpOGT(a, b); break;
    case Op::fge: r = b_.CreateFCmpOGE(a, b); break;
    case Op::feq: r = b_.CreateFCmpOEQ(a, b); break;
    case Op::fne: r = b_.CreateFCmpUNE(a, b); break;
    case Op::ilt: r = b_.CreateICmpSLT(a, b); break;
    case Op::ile: r = b_.CreateICmpSLE(a, b); break;
    case Op::igt: r = b_.CreateICmpSGT(a, b); break;
    case Op::ige: r = b_.CreateICmpSGE(a, b); break;
    case Op::ieq: r = b_.CreateICmpEQ(a, b); break;
    case Op::ine: r = b_.CreateICmpNE(a, b); break;
    case Op::beq: r = b_.CreateICmpEQ(as_bool(a), as_bool(b)); break;
    case Op::bne: case Op::bxor: r = b_.CreateICmpNE(as_bool(a), as_bool(b)); break;
    case Op::band: r = b_.CreateAnd(as_bool(a), as_bool(b)); break;
    case Op::bor: r = b_.CreateOr(as_bool(a), as_bool(b)); break;
    case Op::bnot: r = b_.CreateNot(as_bool(a)); break;
    case Op::f2b: r = b_.CreateFCmpUNE(a, splat_f(0.0f)); break;
    case Op::i2b: r = b_.CreateICmpNE(a, splat_i(0)); break;
    default: return nullptr;
    }
    return from_bool(r);
}

llvm::Value* Emitter::emit_conversion(Op op, llvm::Value* a) {
    switch (op) {
    case Op::f2i: {  // ir::f2i_trunc: NaN gives 0, out of range saturates
        llvm::Value* r = b_.CreateFPToSI(a, vi32_);
        r = b_.CreateSelect(b_.CreateFCmpOLE(a, splat_f(-2147483648.0f)), splat_i(0x80000000u), r);
        r = b_.CreateSelect(b_.CreateFCmpOGE(a, splat_f(2147483647.0f)), splat_i(0x7fffffffu), r);
        return b_.CreateSelect(b_.CreateFCmpUNO(a, a), splat_i(0), r);
    }
    case Op::i2f: return b_.CreateBitCast(b_.CreateSIToFP(a, vf32_), vi32_);
    case Op::b2f: return b_.CreateBitCast(b_.CreateSelect(as_bool(a), splat_f(1.0f), splat_f(0.0f)), vi32_);
    case Op::b2i: return from_bool(as_bool(a));
    default: return nullptr;
    }
}

// kernels::ddx / ddy: differences within each 2x2 quad, lanes 4q+0..3 being
// (x,y) (x+1,y) (x,y+1) (x+1,y+1).
llvm::Value* Emitter::emit_derivative(Op op, llvm::Value* a) {
    static constexpr int kDxPlus[4] = {1, 1, 3, 3}, kDxMinus[4] = {0, 0, 2, 2};
    static constexpr int kDyPlus[4] = {2, 3, 2, 3}, kDyMinus[4] = {0, 1, 0, 1};
    const int* p = op == Op::ddx ? kDxPlus : kDyPlus;
    const int* m = op == Op::ddx ? kDxMinus : kDyMinus;
    std::vector<int> plus(kLanes), minus(kLanes);
    for (int q = 0; q < kLanes; q += 4)
        for (int i = 0; i < 4; ++i) plus[size_t(q + i)] = q + p[i], minus[size_t(q + i)] = q + m[i];
    return b_.CreateFSub(b_.CreateShuffleVector(a, plus), b_.CreateShuffleVector(a, minus));
}

void Emitter::emit_call_out(const ir::Instr& in) {
    call_outs_.push_back({kernel_for(in.op, avx2_, precision_, fast_ops_), in});
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, i64_, i64_}, false);
    auto* callee = llvm::ConstantExpr::getIntToPtr(b_.getInt64(reinterpret_cast<uint64_t>(&run_call_out)), ptr_);
    b_.CreateCall(type, callee, {ctx_arg_, regs_, b_.getInt64(call_outs_.size() - 1), load_mask(exec_)});
}

}  // namespace glslrun::rt::jit
