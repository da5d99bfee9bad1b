// Precision::Fast's kernels: the ops that GPUs approximate (inversesqrt,
// exp/exp2/log/log2, pow, sin, cos) call glslrun::math::fast (ir/fast_math.h),
// texture lookups filter with the GPU's arithmetic (kernels::tex_gpu),
// the multiply-adds the GPU's compiler contracts round once (ffma, ffms, ffnma),
// and a square root read only as a divisor (normalize, x / sqrt(y):
// ir/sqrt_divisor.cpp) becomes the fast rsqrt and multiplies; every other op
// keeps its Precise kernel.
//
// Division too: a * math::fast::rcp(b) was measured slower than the CPU's
// divider (vdivps), which is also exact. glslrun_bench (the spot shader alone,
// 13 fdiv per invocation): Precise 27 M invocations per CPU-second, Fast with
// rcp division 30 M, Fast with hardware division 37.5 M. GPUs approximate
// division because they lack a divider; a CPU has one. The fast functions
// are plain float arithmetic, so Fast images are identical on every x86-64
// machine and for every thread count, as Precise ones are.
//
// Denormals: the kernels run under the interpreter's FTZ/DAZ control word
// (ir::FlushDenormals), which flushes them as the table's explicit ftz
// does: a denormal operand reads as a zero of its sign in every arithmetic
// op and compare (where log2 reads a denormal's bits, its compares select
// the result for zero), and every arithmetic result is flushed. Explicit
// flushes of operand and result were 8 of exp's 35 instructions per lane
// (without them Fast's exp, log2, sin and pow loops run 9 to 13% faster in
// the interpreter); tests/runtime/jit_math_test.cpp checks every lane,
// denormals included, against the JIT, which omits them too.
#pragma once
#include <bit>
#include <cstdint>

#include "ir/fast_math.h"
#include "ir/scalar_ops.h"
#include "runtime/interp_kernels.h"
#include "runtime/interpreter.h"

namespace glslrun::rt {

namespace fast {

// FastLane<op>: arity and eval on raw 32-bit words, as ir::alu::Lane<op>.
template <ir::Op op>
struct FastLane;

#define GLSLRUN_FAST_LANE(op_name, arity_, expr)                                                       \
    template <>                                                                                        \
    struct FastLane<ir::Op::op_name> {                                                                 \
        static constexpr int arity = arity_;                                                           \
        static uint32_t eval(uint32_t wa, [[maybe_unused]] uint32_t wb, uint32_t) {                    \
            [[maybe_unused]] const float a = std::bit_cast<float>(wa);                                 \
            [[maybe_unused]] const float b = std::bit_cast<float>(wb);                                 \
            return std::bit_cast<uint32_t>(expr);                                                       \
        }                                                                                              \
    };
GLSLRUN_FAST_LANE(frsqrt, 1, math::fast::rsqrt(a))
// A square root read only as a divisor (ir/sqrt_divisor.cpp): its register
// holds 1/sqrt(a) in Fast, and the divisions by it are multiplies.
GLSLRUN_FAST_LANE(fsqrt_divisor, 1, math::fast::rsqrt(a))
GLSLRUN_FAST_LANE(fdiv_by_sqrt, 2, ir::a_nan_first(a, a * b))
GLSLRUN_FAST_LANE(fexp, 1, math::fast::exp(a))
GLSLRUN_FAST_LANE(fexp2, 1, math::fast::exp2(a))
GLSLRUN_FAST_LANE(flog, 1, math::fast::log(a))
GLSLRUN_FAST_LANE(flog2, 1, math::fast::log2(a))
GLSLRUN_FAST_LANE(fpow, 2, math::fast::pow(a, b))
GLSLRUN_FAST_LANE(fsin, 1, math::fast::sin(a))
GLSLRUN_FAST_LANE(fcos, 1, math::fast::cos(a))
#undef GLSLRUN_FAST_LANE

// The contracted multiply-adds (ir/contract.cpp): one rounding, as the GPU's
// FFMA. A NaN operand is passed on quieted, a's before b's before c's, as
// the FMA instructions do with a as their first source (the JIT's
// vfmadd213ps, runtime/jit/alu.cpp); only without one does an invalid
// product or sum give the default NaN. ffms and ffnma negate c or a first
// (a NaN's sign too), in both back ends.
inline float fma_a_nan_first(float a, float b, float c) {
    if (a != a) return a + a;
    if (b != b) return b + b;
    if (c != c) return c + c;
    return std::fma(a, b, c);
}
template <ir::Op op>
struct FmaLane {
    static constexpr int arity = 3;
    static uint32_t eval(uint32_t wa, uint32_t wb, uint32_t wc) {
        const float a = std::bit_cast<float>(wa), b = std::bit_cast<float>(wb), c = std::bit_cast<float>(wc);
        if constexpr (op == ir::Op::ffma) return std::bit_cast<uint32_t>(fma_a_nan_first(a, b, c));
        else if constexpr (op == ir::Op::ffms) return std::bit_cast<uint32_t>(fma_a_nan_first(a, b, -c));
        else return std::bit_cast<uint32_t>(fma_a_nan_first(-a, b, c));
    }
};
template <>
struct FastLane<ir::Op::ffma> : FmaLane<ir::Op::ffma> {};
template <>
struct FastLane<ir::Op::ffms> : FmaLane<ir::Op::ffms> {};
template <>
struct FastLane<ir::Op::ffnma> : FmaLane<ir::Op::ffnma> {};

template <ir::Op op>
void alu(const Step<uint32_t>& s, Machine<uint32_t>& m) {
    kernels::emit(s, m, [&](uint32_t* out) { kernels::alu_lanes<uint32_t, FastLane<op>>(s, out); });
}

// Fast's kernel of every op of a Fast class in the table (an op of a class
// without its FastLane does not compile), Precise's of the others.
template <bool kAvx2>
Kernel<uint32_t> kernel_for(ir::Op op) {
    switch (op) {
#define GLSLRUN_FAST_CASE(name) \
    case ir::Op::name: return pick_kernel<uint32_t, kAvx2, &alu<ir::Op::name>>();
#define GLSLRUN_FAST_CASE_Exact(name)
#define GLSLRUN_FAST_CASE_Rsqrt GLSLRUN_FAST_CASE
#define GLSLRUN_FAST_CASE_ExpLog GLSLRUN_FAST_CASE
#define GLSLRUN_FAST_CASE_Pow GLSLRUN_FAST_CASE
#define GLSLRUN_FAST_CASE_SinCos GLSLRUN_FAST_CASE
#define GLSLRUN_FAST_CASE_Fma GLSLRUN_FAST_CASE
#define OP(name, arity, res, opnd, kind, fast, props, expr) GLSLRUN_FAST_CASE_##fast(name)
#include "ir/opcodes.def"
#undef OP
#undef GLSLRUN_FAST_CASE_Fma
#undef GLSLRUN_FAST_CASE_SinCos
#undef GLSLRUN_FAST_CASE_Pow
#undef GLSLRUN_FAST_CASE_ExpLog
#undef GLSLRUN_FAST_CASE_Rsqrt
#undef GLSLRUN_FAST_CASE_Exact
#undef GLSLRUN_FAST_CASE
    default: return rt::kernel_for<uint32_t, kAvx2>(op);
    }
}

}  // namespace fast

// The FastOps bit of an op's class (ir/opcodes.def's `fast` column); 0 for Exact ops.
inline uint32_t fast_op_class(ir::Op op) { return ir::fast_class_bit(ir::op_info(op).fast); }
static_assert(kFastRsqrt == 1u << (uint32_t(ir::FastClass::Rsqrt) - 1) &&
              kFastSinCos == 1u << (uint32_t(ir::FastClass::SinCos) - 1) &&
              kFastFma == ir::fast_class_bit(ir::FastClass::Fma));

// The fp32 modes' kernel of `op`: Fast's where it has one and its class is in
// `fast_ops`, else Precise's.
inline Kernel<uint32_t> kernel_for(ir::Op op, bool avx2, Precision precision, uint32_t fast_ops = kAllFastOps) {
    if (op == ir::Op::tex && precision == Precision::Fast && (fast_ops & kFastTexture))
        return avx2 ? pick_kernel<uint32_t, true, &kernels::tex_gpu>() : &kernels::tex_gpu;
    if (precision != Precision::Fast || !(fast_op_class(op) & fast_ops)) return kernel_for(op, avx2);
    return avx2 ? fast::kernel_for<true>(op) : fast::kernel_for<false>(op);
}

}  // namespace glslrun::rt
