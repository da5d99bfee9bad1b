// Per-lane evaluation of the opcode table's Alu expressions on raw register
// words (32-bit, or 64-bit for Precision::Reference). The interpreter's kernels and the constant folder both go through
// `Lane<op>::eval`, so a folded constant is bit-identical to what the
// interpreter would have computed at run time.
#pragma once
#include <bit>
#include <cstdint>

#include "ir/ir.h"
#include "ir/scalar_ops.h"

namespace glslrun::ir::alu {

// How a table type class reads from / writes to a register word `W`:
// uint32_t for the fp32 modes, uint64_t for Precision::Reference, where F is a
// double. Integers stay 32-bit (wrapping) in the low half, bools are 0/1.
template <TypeClass C, class W = uint32_t>
struct Word;
template <>
struct Word<TypeClass::F, uint32_t> {
    using T = float;
    static float in(uint32_t w) { return std::bit_cast<float>(w); }
    static uint32_t out(float v) { return std::bit_cast<uint32_t>(v); }
};
template <>
struct Word<TypeClass::F, uint64_t> {
    using T = double;
    static double in(uint64_t w) { return std::bit_cast<double>(w); }
    static uint64_t out(double v) { return std::bit_cast<uint64_t>(v); }
};
template <class W>
struct Word<TypeClass::I, W> {
    using T = int32_t;
    static int32_t in(W w) { return static_cast<int32_t>(static_cast<uint32_t>(w)); }
    static W out(int32_t v) { return static_cast<uint32_t>(v); }
};
template <class W>
struct Word<TypeClass::B, W> {
    using T = bool;
    static bool in(W w) { return w != 0; }
    static W out(bool v) { return v ? 1u : 0u; }
};

// Lane<Op::x>: arity and eval(a, b, c) for every Alu op of the table.
template <Op op>
struct Lane;

#define GLSLRUN_ALU_Special(name, arity_, res, opnd, expr)
#define GLSLRUN_ALU_Alu(name, arity_, res, opnd, expr)                                              \
    template <>                                                                                     \
    struct Lane<Op::name> {                                                                         \
        static constexpr int arity = arity_;                                                        \
        template <class W>                                                                          \
        static W eval(W wa, [[maybe_unused]] W wb, [[maybe_unused]] W wc) {                         \
            using In = Word<TypeClass::opnd, W>;                                                    \
            using Out = Word<TypeClass::res, W>;                                                    \
            [[maybe_unused]] const typename In::T a = In::in(wa);                                   \
            [[maybe_unused]] const typename In::T b = In::in(wb);                                   \
            [[maybe_unused]] const typename In::T c = In::in(wc);                                   \
            return Out::out(static_cast<typename Out::T>(expr));                                    \
        }                                                                                           \
    };
#define OP(name, arity, res, opnd, kind, fast, props, expr) GLSLRUN_ALU_##kind(name, arity, res, opnd, expr)
#include "ir/opcodes.def"
#undef OP
#undef GLSLRUN_ALU_Alu
#undef GLSLRUN_ALU_Special

// Dynamic form for the folder (and the tests): evaluates Alu op `op` on raw
// words W (uint32_t, or uint64_t: Reference's doubles).
template <class W>
W eval(Op op, W a, W b, W c) {
    switch (op) {
#define GLSLRUN_ALU_Special(name)
#define GLSLRUN_ALU_Alu(name) \
    case Op::name: return Lane<Op::name>::eval<W>(a, b, c);
#define OP(name, arity, res, opnd, kind, fast, props, expr) GLSLRUN_ALU_##kind(name)
#include "ir/opcodes.def"
#undef OP
#undef GLSLRUN_ALU_Alu
#undef GLSLRUN_ALU_Special
    default: return 0;
    }
}

inline bool is_alu(Op op) { return size_t(op) < size_t(Op::Count_) && op_info(op).kind == OpKind::Alu; }

}  // namespace glslrun::ir::alu
