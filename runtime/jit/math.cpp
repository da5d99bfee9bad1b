// The transcendental built-ins in LLVM IR (runtime/jit/math.h). Each
// function below mirrors the C++ one named in its comment operation for
// operation: the same IEEE operations on the same types in the same order,
// the same polynomial evaluation (Estrin's scheme in Precise, Horner's in
// Fast), selects for the branch-free special cases. No fast-math flags, and
// the target machine forbids FMA contraction, so every lane rounds as the
// interpreter's lane loops do; where two different NaNs meet, the C++ picks
// one explicitly (first_nan), and so does this code. The generated code runs
// under the same FTZ/DAZ control word as the kernels (ir::FlushDenormals).
// tests/runtime/jit_math_test.cpp compares every op with its kernel bit for
// bit.
#include "runtime/jit/math.h"

#include <bit>
#include <cfloat>
#include <string>

#include <llvm/IR/Intrinsics.h>

#include "ir/fast_math.h"
#include "ir/precise_math.h"

namespace glslrun::rt::jit {

namespace {

using ir::Op;
using llvm::Value;
namespace precise = glslrun::math::detail;
namespace fastd = glslrun::math::fast::detail;

constexpr float kInf = precise::kInf;

class MathEmitter {
public:
    // For operands of the type of `like` (kLanes floats).
    MathEmitter(llvm::IRBuilder<>& b, Value* like) : b_(b) { set_lanes(like); }

    Value* emit(Op op, bool fast, Value* a, Value* b) { return fast ? fast_op(op, a, b) : precise_op(op, a, b); }
    Value* pow_common(Value* x, Value* y);
    Value* pow_is_common(Value* x, Value* y);

private:
    // --- vectors of the operands' lane count
    void set_lanes(Value* v);
    Value* f(float v) { return llvm::ConstantFP::get(vf_, v); }
    Value* d(double v) { return llvm::ConstantFP::get(vd_, v); }
    Value* i32(uint32_t v) { return llvm::ConstantInt::get(vi32_, v); }
    Value* f_bits(uint32_t w) { return f(std::bit_cast<float>(w)); }
    Value* as_int(Value* v) { return b_.CreateBitCast(v, vi32_); }
    Value* as_float(Value* v) { return b_.CreateBitCast(v, vf_); }
    Value* sel(Value* c, Value* x, Value* y) { return b_.CreateSelect(c, x, y); }
    Value* fabs(Value* v) { return b_.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, v); }
    Value* is_nan(Value* v) { return b_.CreateFCmpUNO(v, v); }
    Value* ftz(Value* v) { return flush_denormals(b_, v); }
    Value* widen(Value* v) { return b_.CreateFPExt(v, vd_); }
    Value* narrow(Value* v) { return b_.CreateFPTrunc(v, vf_); }
    // t < lo ? lo : (t > hi ? hi : t), a NaN passing
    Value* clamp(Value* t, Value* lo, Value* hi) {
        return sel(b_.CreateFCmpOLT(t, lo), lo, sel(b_.CreateFCmpOGT(t, hi), hi, t));
    }
    Value* bit_set(Value* words, uint32_t bit) { return b_.CreateICmpNE(b_.CreateAnd(words, i32(bit)), i32(0)); }

    // --- ir/precise_math.h, double precision
    template <size_t M>
    Value* estrin(Value* x, const double (&c)[M]);
    Value* estrin_part(Value* const* powers, const double* c, size_t n);
    Value* exp2_core(Value* t);
    Value* log2_core(Value* x);
    Value* log_special(Value* x);
    Value* positive_finite(Value* x) {
        return b_.CreateAnd(b_.CreateFCmpOGT(x, f(0.0f)), b_.CreateFCmpOLT(x, f(kInf)));
    }
    Value* log2(Value* x) { return sel(positive_finite(x), narrow(log2_core(x)), log_special(x)); }
    Value* log(Value* x) {
        return sel(positive_finite(x), narrow(b_.CreateFMul(log2_core(x), d(precise::kLn2))), log_special(x));
    }
    struct Reduced {
        Value* r;
        Value* quadrant;
    };
    Reduced reduce_pi2(Value* x);
    Value* sin_quadrant(const Reduced& red, uint32_t shift);
    Value* sin(Value* x);
    Value* cos(Value* x);
    Value* tan(Value* x);
    Value* atan2_core(Value* ay, Value* ax);
    Value* atan(Value* x);
    Value* atan2(Value* y, Value* x);
    Value* asin(Value* x);
    Value* acos(Value* x);
    Value* copysign(Value* magnitude, Value* sign) {
        return b_.CreateBinaryIntrinsic(llvm::Intrinsic::copysign, magnitude, sign);
    }
    // |x| <= 1 ? r : the NaN of asin and acos outside their domain
    Value* inverse_domain(Value* x, Value* r) {
        return sel(b_.CreateFCmpOLE(fabs(x), f(1.0f)), r, sel(is_nan(x), b_.CreateFAdd(x, x), f_bits(0x7FC00000u)));
    }
    // sqrt(1 - ax^2) as (1 - ax)(1 + ax)
    Value* cosine_of(Value* ax) {
        return b_.CreateUnaryIntrinsic(llvm::Intrinsic::sqrt,
                                       b_.CreateFMul(b_.CreateFSub(d(1.0), ax), b_.CreateFAdd(d(1.0), ax)));
    }

    // --- ir/fast_math.h, single precision
    template <size_t M>
    Value* horner(Value* x, const float (&c)[M]);
    Value* pow2i(Value* k) { return as_float(b_.CreateShl(b_.CreateAdd(k, i32(127)), 23)); }
    Value* fast_exp2(Value* x);
    Value* fast_log2(Value* x);
    Value* fast_pow(Value* x, Value* y);
    Reduced fast_reduce_pi2(Value* x);
    Value* fast_sin(Value* x);
    Value* fast_cos(Value* x);

    Value* precise_op(Op op, Value* a, Value* b);
    Value* fast_op(Op op, Value* a, Value* b);

    llvm::IRBuilder<>& b_;
    llvm::FixedVectorType* vf_ = nullptr;
    llvm::FixedVectorType* vd_ = nullptr;
    llvm::FixedVectorType* vi32_ = nullptr;
    llvm::FixedVectorType* vi64_ = nullptr;
};

void MathEmitter::set_lanes(Value* v) {
    const unsigned n = llvm::cast<llvm::FixedVectorType>(v->getType())->getNumElements();
    llvm::LLVMContext& c = b_.getContext();
    vf_ = llvm::FixedVectorType::get(llvm::Type::getFloatTy(c), n);
    vd_ = llvm::FixedVectorType::get(llvm::Type::getDoubleTy(c), n);
    vi32_ = llvm::FixedVectorType::get(llvm::Type::getInt32Ty(c), n);
    vi64_ = llvm::FixedVectorType::get(llvm::Type::getInt64Ty(c), n);
}

// detail::estrin and detail::Powers: x, x^2, x^4, x^8 as Powers computes them.
template <size_t M>
Value* MathEmitter::estrin(Value* x, const double (&c)[M]) {
    Value* x2 = b_.CreateFMul(x, x);
    Value* x4 = M > 4 ? b_.CreateFMul(x2, x2) : nullptr;
    Value* x8 = M > 8 ? b_.CreateFMul(x4, x4) : nullptr;
    Value* const powers[9] = {nullptr, x, x2, nullptr, x4, nullptr, nullptr, nullptr, x8};
    return estrin_part(powers, c, M);
}

// estrin<I, N>: L + x^h H, h the largest power of two below n.
Value* MathEmitter::estrin_part(Value* const* powers, const double* c, size_t n) {
    if (n == 1) return d(c[0]);
    const size_t h = std::bit_floor(n - 1);
    return b_.CreateFAdd(estrin_part(powers, c, h), b_.CreateFMul(powers[h], estrin_part(powers, c + h, n - h)));
}

// detail::exp2_core
Value* MathEmitter::exp2_core(Value* t) {
    Value* tc = clamp(t, d(-200.0), d(200.0));
    Value* shifted = b_.CreateFAdd(tc, d(precise::kRoundMagic));
    Value* k = b_.CreateFSub(shifted, d(precise::kRoundMagic));
    Value* kbits = b_.CreateBitCast(shifted, vi64_);
    Value* scale = b_.CreateBitCast(b_.CreateShl(b_.CreateAdd(kbits, llvm::ConstantInt::get(vi64_, 1023)), 52), vd_);
    return b_.CreateFMul(estrin(b_.CreateFSub(tc, k), precise::kExp2Poly), scale);
}

// detail::log2_core: float x in, double out.
Value* MathEmitter::log2_core(Value* x) {
    Value* denormal = b_.CreateFCmpOLT(x, f(0x1p-126f));
    Value* bits = as_int(sel(denormal, b_.CreateFMul(x, f(0x1p23f)), x));
    Value* e = b_.CreateAShr(b_.CreateSub(bits, i32(0x3F3504F3u)), 23);
    Value* m = widen(as_float(b_.CreateSub(bits, b_.CreateShl(e, 23))));
    Value* s = b_.CreateFDiv(b_.CreateFSub(m, d(1.0)), b_.CreateFAdd(m, d(1.0)));
    Value* exponent = b_.CreateFSub(b_.CreateSIToFP(e, vd_), sel(denormal, d(23.0), d(0.0)));
    return b_.CreateFAdd(exponent, b_.CreateFMul(s, estrin(b_.CreateFMul(s, s), precise::kLog2Poly)));
}

// detail::log_special
Value* MathEmitter::log_special(Value* x) {
    return sel(b_.CreateFCmpOEQ(x, f(0.0f)), f(-kInf),
               sel(b_.CreateFCmpOLT(x, f(0.0f)), f_bits(0xFFC00000u), b_.CreateFAdd(x, x)));
}

// math::pow_common
Value* MathEmitter::pow_common(Value* x, Value* y) {
    Value* l = sel(b_.CreateFCmpOEQ(x, f(0.0f)), d(-double(kInf)), log2_core(x));
    return narrow(exp2_core(b_.CreateFMul(widen(y), l)));
}

// math::pow_is_common: x in [+0, Inf), y finite and nonzero.
Value* MathEmitter::pow_is_common(Value* x, Value* y) {
    return b_.CreateAnd(b_.CreateAnd(b_.CreateICmpULT(as_int(x), i32(0x7F800000u)), b_.CreateFCmpOLT(fabs(y), f(kInf))),
                        b_.CreateFCmpUNE(y, f(0.0f)));
}

// detail::reduce_pi2 (double, Cody-Waite in four parts)
MathEmitter::Reduced MathEmitter::reduce_pi2(Value* x) {
    Value* xd = widen(x);
    Value* q = b_.CreateFMul(xd, d(0.6366197723675814));
    Value* shifted = b_.CreateFAdd(clamp(q, d(-0x1p50), d(0x1p50)), d(precise::kRoundMagic));
    Value* k = b_.CreateFSub(shifted, d(precise::kRoundMagic));
    Value* r = b_.CreateFSub(xd, b_.CreateFMul(k, d(0x1.921fb6p+0)));
    r = b_.CreateFSub(r, b_.CreateFMul(k, d(-0x1.777a5cp-25)));
    r = b_.CreateFSub(r, b_.CreateFMul(k, d(-0x1.ee59dap-50)));
    r = b_.CreateFSub(r, b_.CreateFMul(k, d(0x1.98a2e03707345p-77)));
    Value* quadrant = b_.CreateAnd(b_.CreateTrunc(b_.CreateBitCast(shifted, vi64_), vi32_), i32(3));
    return {clamp(r, d(-0.786), d(0.786)), quadrant};
}

// detail::sin_quadrant
Value* MathEmitter::sin_quadrant(const Reduced& red, uint32_t shift) {
    Value* z = b_.CreateFMul(red.r, red.r);
    Value* s = b_.CreateFMul(red.r, estrin(z, precise::kSinPoly));
    Value* c = estrin(z, precise::kCosPoly);
    Value* q = b_.CreateAdd(red.quadrant, i32(shift));
    Value* v = sel(bit_set(q, 1), c, s);
    return sel(bit_set(q, 2), b_.CreateFNeg(v), v);
}

// math::sin, math::cos
Value* MathEmitter::sin(Value* x) {
    Value* r = sel(b_.CreateFCmpOEQ(x, f(0.0f)), x, narrow(sin_quadrant(reduce_pi2(x), 0)));
    return sel(b_.CreateFCmpOLT(fabs(x), f(kInf)), r, b_.CreateFSub(x, x));
}
Value* MathEmitter::cos(Value* x) {
    Value* r = narrow(sin_quadrant(reduce_pi2(x), 1));
    return sel(b_.CreateFCmpOLT(fabs(x), f(kInf)), r, b_.CreateFSub(x, x));
}

// math::tan
Value* MathEmitter::tan(Value* x) {
    const Reduced red = reduce_pi2(x);
    Value* z = b_.CreateFMul(red.r, red.r);
    Value* s = b_.CreateFMul(red.r, estrin(z, precise::kSinPoly));
    Value* c = estrin(z, precise::kCosPoly);
    Value* odd = bit_set(red.quadrant, 1);
    Value* ratio = narrow(b_.CreateFDiv(sel(odd, b_.CreateFNeg(c), s), sel(odd, s, c)));
    Value* r = sel(b_.CreateFCmpOEQ(x, f(0.0f)), x, ratio);
    return sel(b_.CreateFCmpOLT(fabs(x), f(kInf)), r, b_.CreateFSub(x, x));
}

// detail::atan2_core (doubles ay, ax >= 0)
Value* MathEmitter::atan2_core(Value* ay, Value* ax) {
    Value* low = b_.CreateFCmpOLE(ay, b_.CreateFMul(d(precise::kTanPi8), ax));
    Value* high = b_.CreateFCmpOGT(ay, b_.CreateFMul(d(precise::kTan3Pi8), ax));
    Value* num = sel(low, ay, sel(high, b_.CreateFNeg(ax), b_.CreateFSub(ay, ax)));
    Value* den = sel(low, ax, sel(high, ay, b_.CreateFAdd(ay, ax)));
    Value* offset = sel(low, d(0.0), sel(high, d(precise::kPi2), d(precise::kPi4)));
    Value* u = b_.CreateFDiv(num, den);
    return b_.CreateFAdd(offset, b_.CreateFMul(u, estrin(b_.CreateFMul(u, u), precise::kAtanPoly)));
}

// math::atan, math::atan2 (y, x), math::asin, math::acos
Value* MathEmitter::atan(Value* x) { return copysign(narrow(atan2_core(fabs(widen(x)), d(1.0))), x); }

Value* MathEmitter::atan2(Value* y, Value* x) {
    Value* ay = fabs(widen(y));
    Value* ax = fabs(widen(x));
    Value* a = atan2_core(ay, ax);
    a = sel(b_.CreateAnd(b_.CreateFCmpOEQ(ay, d(0.0)), b_.CreateFCmpOEQ(ax, d(0.0))), d(0.0), a);
    Value* inf = d(double(kInf));
    a = sel(b_.CreateAnd(b_.CreateFCmpOEQ(ay, inf), b_.CreateFCmpOEQ(ax, inf)), d(precise::kPi4), a);
    a = sel(b_.CreateICmpSLT(as_int(x), i32(0)), b_.CreateFSub(d(precise::kPi), a), a);
    Value* r = copysign(narrow(a), y);
    Value* nan = sel(is_nan(x), b_.CreateFAdd(x, x), b_.CreateFAdd(y, y));  // detail::first_nan(x, y)
    return sel(b_.CreateOr(is_nan(x), is_nan(y)), nan, r);
}

Value* MathEmitter::asin(Value* x) {
    Value* ax = fabs(widen(x));
    return inverse_domain(x, copysign(narrow(atan2_core(ax, cosine_of(ax))), x));
}

Value* MathEmitter::acos(Value* x) {
    Value* xd = widen(x);
    Value* a = atan2_core(cosine_of(fabs(xd)), fabs(xd));
    return inverse_domain(x, narrow(sel(b_.CreateFCmpOLT(xd, d(0.0)), b_.CreateFSub(d(precise::kPi), a), a)));
}

// fast::detail::poly: c[0] + x (c[1] + x (...)), innermost first.
template <size_t M>
Value* MathEmitter::horner(Value* x, const float (&c)[M]) {
    Value* acc = f(c[M - 1]);
    for (size_t i = M - 1; i-- > 0;) acc = b_.CreateFAdd(b_.CreateFMul(acc, x), f(c[i]));
    return acc;
}

// fast::exp2
Value* MathEmitter::fast_exp2(Value* x) {
    Value* xc = clamp(x, f(-151.0f), f(129.0f));
    Value* shifted = b_.CreateFAdd(xc, f(fastd::kRoundMagic));
    Value* k = b_.CreateFSub(shifted, f(fastd::kRoundMagic));
    Value* ki = b_.CreateAShr(b_.CreateShl(as_int(shifted), 10), 10);
    Value* half = b_.CreateAShr(ki, 1);
    Value* p = horner(b_.CreateFSub(xc, k), fastd::kExp2Poly);
    return b_.CreateFMul(b_.CreateFMul(p, pow2i(half)), pow2i(b_.CreateSub(ki, half)));
}

// fast::log2
Value* MathEmitter::fast_log2(Value* x) {
    Value* bits = as_int(x);
    Value* e = b_.CreateAShr(b_.CreateSub(bits, i32(0x3F3504F3u)), 23);
    Value* m = as_float(b_.CreateSub(bits, b_.CreateShl(e, 23)));
    Value* s = b_.CreateFDiv(b_.CreateFSub(m, f(1.0f)), b_.CreateFAdd(m, f(1.0f)));
    Value* r = b_.CreateFAdd(b_.CreateSIToFP(e, vf_), b_.CreateFMul(s, horner(b_.CreateFMul(s, s), fastd::kLog2Poly)));
    return sel(positive_finite(x), r, log_special(x));  // fast::log2's `special` is detail::log_special's
}

// fast::pow
Value* MathEmitter::fast_pow(Value* x, Value* y) {
    // y * log2(x) with both NaN (y NaN, x < 0) is y's NaN, quieted, picked
    // explicitly as fast::pow picks it: LLVM, like the C++ compilers, may
    // swap the operands (tests/runtime/jit_math_test.cpp checks the pairs).
    Value* quiet_y = as_float(b_.CreateOr(as_int(y), i32(0x00400000u)));
    Value* r = fast_exp2(sel(is_nan(y), quiet_y, b_.CreateFMul(y, fast_log2(x))));
    return sel(b_.CreateOr(b_.CreateFCmpOEQ(x, f(0.0f)), is_nan(x)), f(0.0f), r);
}

// fast::detail::reduce_pi2 (float, three parts)
MathEmitter::Reduced MathEmitter::fast_reduce_pi2(Value* x) {
    Value* q = b_.CreateFMul(x, f(0.636619772f));
    Value* shifted = b_.CreateFAdd(clamp(q, f(-0x1p22f), f(0x1p22f)), f(fastd::kRoundMagic));
    Value* k = b_.CreateFSub(shifted, f(fastd::kRoundMagic));
    Value* r = b_.CreateFSub(x, b_.CreateFMul(k, f(1.5703125f)));
    r = b_.CreateFSub(r, b_.CreateFMul(k, f(4.837512969970703125e-4f)));
    r = b_.CreateFSub(r, b_.CreateFMul(k, f(7.54978995489188216e-8f)));
    return {r, b_.CreateAnd(as_int(shifted), i32(3))};
}

// fast::sin, fast::cos
Value* MathEmitter::fast_sin(Value* x) {
    const Reduced red = fast_reduce_pi2(x);
    Value* z = b_.CreateFMul(red.r, red.r);
    Value* v = sel(bit_set(red.quadrant, 1), horner(z, fastd::kCosPoly),
                   b_.CreateFMul(red.r, horner(z, fastd::kSinPoly)));
    Value* r = sel(bit_set(red.quadrant, 2), b_.CreateFNeg(v), v);
    return sel(b_.CreateFCmpOLT(fabs(x), f(kInf)), r, b_.CreateFSub(x, x));
}
Value* MathEmitter::fast_cos(Value* x) {
    const Reduced red = fast_reduce_pi2(x);
    Value* z = b_.CreateFMul(red.r, red.r);
    Value* v = sel(bit_set(red.quadrant, 1), b_.CreateFMul(red.r, horner(z, fastd::kSinPoly)),
                   horner(z, fastd::kCosPoly));
    Value* r = sel(bit_set(b_.CreateAdd(red.quadrant, i32(1)), 2), b_.CreateFNeg(v), v);
    return sel(b_.CreateFCmpOLT(fabs(x), f(kInf)), r, b_.CreateFSub(x, x));
}

// The table's expressions (ir/opcodes.def): ftz(math::op(ftz(a), ...)); fpow
// as kernels::pow_lanes.
Value* MathEmitter::precise_op(Op op, Value* a, Value* b) {
    switch (op) {
    case Op::fexp2: return ftz(narrow(exp2_core(widen(ftz(a)))));
    case Op::fexp: return ftz(narrow(exp2_core(b_.CreateFMul(widen(ftz(a)), d(precise::kLog2e)))));
    case Op::flog2: return ftz(log2(ftz(a)));
    case Op::flog: return ftz(log(ftz(a)));
    case Op::fsin: return ftz(sin(ftz(a)));
    case Op::fcos: return ftz(cos(ftz(a)));
    case Op::ftan: return ftz(tan(ftz(a)));
    case Op::fasin: return ftz(asin(ftz(a)));
    case Op::facos: return ftz(acos(ftz(a)));
    case Op::fatan: return ftz(atan(ftz(a)));
    case Op::fatan2: return ftz(atan2(ftz(a), ftz(b)));
    default: return nullptr;
    }
}

// runtime/fast_kernels.h's FastLane expressions, ftz(f(ftz(a), ...)),
// without the flushes: the FTZ/DAZ control word makes them. A denormal
// operand reads as a zero of its sign in every arithmetic op and compare,
// every arithmetic result is flushed, and where log2 reads a denormal's
// bits the compares select its special case for zero (-Inf; pow's 0), as
// for the flushed operand. The two flushes were 8 of exp's 35 instructions.
Value* MathEmitter::fast_op(Op op, Value* a, Value* b) {
    switch (op) {
    case Op::fexp2: return fast_exp2(a);
    case Op::fexp: return fast_exp2(b_.CreateFMul(a, f(1.44269504f)));
    case Op::flog2: return fast_log2(a);
    case Op::flog: return b_.CreateFMul(fast_log2(a), f(0.693147181f));
    case Op::fpow: return fast_pow(a, b);
    case Op::fsin: return fast_sin(a);
    case Op::fcos: return fast_cos(a);
    default: return nullptr;
    }
}

}  // namespace

// Every op of the table's Fast classes in Fast, its Libm ops in both (but
// Precise fpow: emit_pow_common). Not Fast's Fma class (llvm.fma, in
// runtime/jit/alu.cpp), nor its Rsqrt class: 1/sqrt(a) and
// a * b, which the native code writes inline (runtime/jit/alu.cpp) with the
// kernels' bits under the kernels' FTZ/DAZ, where a call to a shared
// function cost more than the two instructions (a loop of 16 normalizes
// per fragment: 1.5x Precise's time as a call, Precise's time inline).
bool generates_math(Op op, bool fast) {
    const ir::FastClass fast_class = ir::op_info(op).fast;
    if (fast && (fast_class == ir::FastClass::Rsqrt || fast_class == ir::FastClass::Fma)) return false;
    if (fast && fast_class != ir::FastClass::Exact) return true;
    return ir::has(op, ir::OpProp::Libm) && (fast || op != Op::fpow);
}

namespace {

// A call of the module's function `name`, (a, b) -> float vector, whose body
// `body(builder, a, b)` writes where the module first uses it: one copy of
// each built-in per module, so LLVM's time grows with the ops a shader uses,
// not with how often (inlined, multi_light's unrolled loop took 175 ms).
template <class Body>
Value* call_shared(llvm::IRBuilder<>& builder, const std::string& name, Value* a, Value* b, Body&& body) {
    llvm::Module* module = builder.GetInsertBlock()->getModule();
    llvm::Function* fn = module->getFunction(name);
    if (!fn) {
        auto* type = llvm::FunctionType::get(a->getType(), {a->getType(), a->getType()}, false);
        fn = llvm::Function::Create(type, llvm::Function::InternalLinkage, name, module);
        // The denormal mode the shader's functions declare (runtime/jit/control.cpp).
        fn->addFnAttr("denormal-fp-math", "preserve-sign,preserve-sign");
        fn->addFnAttr("denormal-fp-math-f32", "preserve-sign,preserve-sign");
        for (auto kind : {llvm::Attribute::NoUnwind, llvm::Attribute::NoInline, llvm::Attribute::ReadNone,
                          llvm::Attribute::WillReturn})
            fn->addFnAttr(kind);
        llvm::IRBuilder<> inner(llvm::BasicBlock::Create(builder.getContext(), "entry", fn));
        inner.CreateRet(body(inner, fn->getArg(0), fn->getArg(1)));
    }
    return builder.CreateCall(fn, {a, b ? b : a});
}

}  // namespace

Value* emit_math(llvm::IRBuilder<>& builder, Op op, bool fast, Value* a, Value* b) {
    const std::string name = std::string("glslrun_") + (fast ? "fast_" : "precise_") + ir::op_info(op).name;
    return call_shared(builder, name, a, b, [&](llvm::IRBuilder<>& inner, Value* x, Value* y) {
        return MathEmitter(inner, x).emit(op, fast, x, y);
    });
}

PowCommon emit_pow_common(llvm::IRBuilder<>& builder, Value* a, Value* b) {
    Value* x = flush_denormals(builder, a);
    Value* y = flush_denormals(builder, b);
    Value* some_rare = builder.CreateNot(MathEmitter(builder, a).pow_is_common(x, y));
    const unsigned n = llvm::cast<llvm::FixedVectorType>(a->getType())->getNumElements();
    Value* any_rare = builder.CreateICmpNE(builder.CreateBitCast(some_rare, builder.getIntNTy(n)), builder.getIntN(n, 0));
    Value* common = call_shared(builder, "glslrun_precise_pow_common", x, y, [](llvm::IRBuilder<>& inner, Value* u, Value* v) {
        return flush_denormals(inner, MathEmitter(inner, u).pow_common(u, v));
    });
    return {common, any_rare};
}

Value* flush_denormals(llvm::IRBuilder<>& b, Value* v) {
    Value* tiny = b.CreateFCmpOLT(b.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, v), llvm::ConstantFP::get(v->getType(), FLT_MIN));
    return b.CreateSelect(tiny, b.CreateBinaryIntrinsic(llvm::Intrinsic::copysign, llvm::ConstantFP::get(v->getType(), 0.0), v), v);
}

}  // namespace glslrun::rt::jit
