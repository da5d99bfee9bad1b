// Scalar semantics used by the `expr` column of ir/opcodes.def. Shared by the
// constant folder and the interpreter so both compute bit-identical results.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include "ir/precise_math.h"  // math::exp etc., used by opcodes.def
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace glslrun::ir {

// Shaders run with denormals flushed to zero (inputs and results), as GPUs
// and llvmpipe do and as GL permits; piglit's fs-underflow-* tests rely on
// it. Both the interpreter and the constant folder hold this guard, so folded
// and interpreted results stay bit-identical.
class FlushDenormals {
public:
#if defined(__SSE__)
    FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }  // FTZ | DAZ
    ~FlushDenormals() { _mm_setcsr(saved_); }
private:
    unsigned saved_;
#else
    FlushDenormals() = default;
#endif
public:
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;
};

// Flushes a denormal to a zero of its sign. FTZ/DAZ cover SSE arithmetic only:
// libm works on the bits (log2 of 2^-127 gives -150, not -Inf) and negation
// and abs are bit operations, so those ops flush their operands and results
// explicitly to keep "denormals are zero" true for every op.
inline float ftz(float a) { return std::fabs(a) < 1.17549435e-38f ? std::copysign(0.0f, a) : a; }
// The Reference mode evaluates the same expressions in double and keeps
// denormals: its ftz is the identity.
inline double ftz(double a) { return a; }

// T is float, or double in Precision::Reference (ir/alu_eval.h).
//
// `r`, an a + b or a * b, with a's NaN (quieted) when a is one. x86 returns
// the first source operand's NaN when both operands are NaNs, but compilers
// commute + and * freely (GCC in the interpreter's kernels, differently per
// ISA), so those ops say which NaN they return: the CPU's own rule with a
// first, which the JIT gets from one instruction that LLVM cannot commute
// (runtime/jit/alu.cpp). A NaN b passes through, quieted, as before.
// (The passes still treat + and * as commutative: ir/copyprop.cpp,
// ir/fuse_mad.cpp; that may pick the other of two NaNs, the same for both
// backends, which run the same IR.)
template <class T>
T a_nan_first(T a, T r) { return a != a ? a + a : r; }
template <class T>
T glsl_mad(T a, T b, T c) {
    const T p = a_nan_first(a, a * b);
    return a_nan_first(p, p + c);
}
template <class T>
T glsl_sign(T a) { return a > T(0) ? T(1) : (a < T(0) ? T(-1) : T(0)); }
template <class T>
T glsl_fract(T a) { return a - std::floor(a); }
// GLSL 1.10 §8.3: mod(x, y) = x - y * floor(x / y).
template <class T>
T glsl_mod(T a, T b) { return a - a_nan_first(b, b * std::floor(a / b)); }

inline int32_t wrap_add(int32_t a, int32_t b) {
    return static_cast<int32_t>(static_cast<uint32_t>(a) + static_cast<uint32_t>(b));
}
inline int32_t wrap_sub(int32_t a, int32_t b) {
    return static_cast<int32_t>(static_cast<uint32_t>(a) - static_cast<uint32_t>(b));
}
inline int32_t wrap_mul(int32_t a, int32_t b) {
    return static_cast<int32_t>(static_cast<uint32_t>(a) * static_cast<uint32_t>(b));
}
// Integer division by zero is undefined in GLSL; we define it as 0 so that it
// can never trap (SIGFPE). INT_MIN / -1 wraps to INT_MIN for the same reason.
inline int32_t safe_idiv(int32_t a, int32_t b) {
    if (b == 0) return 0;
    if (b == -1) return wrap_sub(0, a);
    return a / b;
}
inline int32_t safe_imod(int32_t a, int32_t b) {
    if (b == 0 || b == -1) return 0;
    return a % b;
}
// float -> int truncates toward zero; NaN gives 0 and out-of-range values
// saturate instead of invoking undefined behaviour.
// (2147483647.0f is 2^31: as a float or a double, every value from it on saturates.)
template <class T>
int32_t f2i_trunc(T a) {
    if (std::isnan(a)) return 0;
    if (a >= T(2147483647.0f)) return std::numeric_limits<int32_t>::max();
    if (a <= T(-2147483648.0f)) return std::numeric_limits<int32_t>::min();
    return static_cast<int32_t>(a);
}

}  // namespace glslrun::ir
