// GLSL 1.10/1.20's undefined operations, as `check_undef` instructions test
// them (ir/opcodes.def). The frontend emits one before each built-in call or
// operator whose result the spec leaves undefined for some operands, when
// CompileOptions::check_undefined asks for it (frontend/lower_checks.cpp;
// reads of variables never written: ir/unwritten_reads.cpp);
// without it the IR holds none, so checking costs nothing when it is off.
// Both backends run the same kernel (runtime/interp_kernels.h; the JIT calls
// it out), so their findings agree.
//
// A check_undef reads up to three operands (src[0..2], as the built-in's
// arguments: pow(x, y) gives x, y), of kind `type` (F32 or I32);
// imm[0] = UndefOp, imm[1] = the site (an index into Shader::undef_sites,
// which keeps the source position through inlining), imm[2] = the array
// length (Index).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

namespace glslrun::ir {

enum class UndefOp : uint8_t {
    Pow,            // pow(x, y): x < 0, or x = 0 and y <= 0
    Log,            // log(x): x <= 0
    Log2,           // log2(x): x <= 0
    Sqrt,           // sqrt(x): x < 0
    InverseSqrt,    // inversesqrt(x): x <= 0
    FloatDivZero,   // x / y, float: y = 0
    IntDivZero,     // x / y, int: y = 0
    Asin,           // asin(x): |x| > 1
    Acos,           // acos(x): |x| > 1
    Atan,           // atan(y, x): x = 0 and y = 0
    Normalize,      // normalize(v): v = 0 (the operand is dot(v, v))
    Smoothstep,     // smoothstep(edge0, edge1, x): edge0 >= edge1
    Clamp,          // clamp(x, minVal, maxVal): minVal > maxVal
    Index,          // a[i]: i < 0 or i >= the array's length (imm[2])
    IntAdd,         // x + y, int: the sum does not fit 32 bits
    IntSub,         // x - y, int
    IntMul,         // x * y, int
    IntNeg,         // -x, int: x = -2^31
    Unwritten,      // a read of a variable no write has reached (the operand: its shadow, 0 or 1;
                    // ir/unwritten_reads.cpp)
    Count_,
};

struct UndefInfo {
    const char* name;       // "pow", "float division", ...
    const char* condition;  // when it is undefined, in the spec's terms
    int operands;           // read from src[0..operands)
};

inline const UndefInfo& undef_info(UndefOp op) {
    static constexpr UndefInfo kInfo[] = {
        {"pow", "pow(x, y) with x < 0, or x = 0 and y <= 0", 2},
        {"log", "log(x) with x <= 0", 1},
        {"log2", "log2(x) with x <= 0", 1},
        {"sqrt", "sqrt(x) with x < 0", 1},
        {"inversesqrt", "inversesqrt(x) with x <= 0", 1},
        {"float division", "x / y with y = 0", 2},
        {"int division", "x / y (int) with y = 0", 2},
        {"asin", "asin(x) with |x| > 1", 1},
        {"acos", "acos(x) with |x| > 1", 1},
        {"atan", "atan(y, x) with x = 0 and y = 0", 2},
        {"normalize", "normalize(v) with v = 0", 1},
        {"smoothstep", "smoothstep(edge0, edge1, x) with edge0 >= edge1", 3},
        {"clamp", "clamp(x, minVal, maxVal) with minVal > maxVal", 3},
        {"array index", "an array index out of range", 1},
        {"int addition", "int x + y past 32 bits", 2},
        {"int subtraction", "int x - y past 32 bits", 2},
        {"int multiplication", "int x * y past 32 bits", 2},
        {"int negation", "-x with x = -2147483648", 1},
        {"unwritten variable", "a read of a variable that no write has reached", 0},
    };
    static_assert(sizeof(kInfo) / sizeof(kInfo[0]) == size_t(UndefOp::Count_));
    return kInfo[size_t(op)];
}

// Whether `op` is undefined for these operands: floats as doubles (exact for
// fp32 and for Reference's doubles), ints as their int32 values. A NaN
// operand is not itself an undefined operation (it came from one, reported
// where it arose), so the comparisons are false for it.
inline bool undefined_for(UndefOp op, double a, double b, double c, uint32_t length) {
    constexpr double kMin = double(std::numeric_limits<int32_t>::min());
    constexpr double kMax = double(std::numeric_limits<int32_t>::max());
    auto outside = [&](double v) { return v < kMin || v > kMax; };
    switch (op) {
    case UndefOp::Pow: return a < 0 || (a == 0 && b <= 0);
    case UndefOp::Log: case UndefOp::Log2: case UndefOp::InverseSqrt: return a <= 0;
    case UndefOp::Sqrt: return a < 0;
    case UndefOp::FloatDivZero: case UndefOp::IntDivZero: return b == 0;
    case UndefOp::Asin: case UndefOp::Acos: return std::fabs(a) > 1;
    case UndefOp::Atan: return a == 0 && b == 0;
    case UndefOp::Normalize: return a == 0;
    case UndefOp::Smoothstep: return a >= b;
    case UndefOp::Clamp: return b > c;
    case UndefOp::Index: return a < 0 || a >= double(length);
    case UndefOp::IntAdd: return outside(a + b);
    case UndefOp::IntSub: return outside(a - b);
    case UndefOp::IntMul: return outside(a * b);  // rounding is monotonic and 2^31 is a double
    case UndefOp::IntNeg: return a == kMin;
    case UndefOp::Unwritten: return a == 0;
    case UndefOp::Count_: break;
    }
    return false;
}

}  // namespace glslrun::ir
