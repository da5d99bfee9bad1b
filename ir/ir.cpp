#include "ir/ir.h"

#include <cstdlib>

namespace glslrun::ir {

namespace {
constexpr TypeClass F = TypeClass::F, I = TypeClass::I, B = TypeClass::B, T = TypeClass::T,
                    X = TypeClass::X;
constexpr OpKind Alu = OpKind::Alu, Special = OpKind::Special;
// The `props` column's names, as bits.
constexpr uint16_t None = 0, Pure = uint16_t(OpProp::Pure), Commutative = uint16_t(OpProp::Commutative),
                   Libm = uint16_t(OpProp::Libm), CrossLane = uint16_t(OpProp::CrossLane),
                   ReadsRange = uint16_t(OpProp::ReadsRange), WritesRange = uint16_t(OpProp::WritesRange),
                   Texture = uint16_t(OpProp::Texture), Effect = uint16_t(OpProp::Effect),
                   Blends = uint16_t(OpProp::Blends), CallOut = uint16_t(OpProp::CallOut);
constexpr OpInfo kOpTable[] = {
#define OP(name, arity, res, opnd, kind, fast, props, expr) \
    {#name, arity, res, opnd, kind, FastClass::fast, uint16_t((props) | (kind == Alu ? Pure : None))},
#include "ir/opcodes.def"
#undef OP
};
static_assert(sizeof(kOpTable) / sizeof(kOpTable[0]) == size_t(Op::Count_));

// What the columns must agree on, so that a new op whose row leaves out
// what it does fails here instead of being miscompiled by some stage.
constexpr bool row_consistent(const OpInfo& op) {
    const bool float_alu = op.kind == Alu && op.operand == F && op.result == F;
    // Alu ops are lane-wise functions of their operands and nothing else.
    if (op.kind == Alu && (op.props & (CrossLane | ReadsRange | WritesRange | Texture | Effect | Blends | CallOut)))
        return false;
    // A Special op says what it touches: a result of its operands (Pure),
    // ranges of registers, a texture, or an effect. Without one, no pass
    // could tell whether it may remove, move or reuse it.
    if (op.kind == Special && !(op.props & (Pure | ReadsRange | WritesRange | Texture | Effect))) return false;
    if ((op.props & Commutative) && !(op.kind == Alu && op.arity == 2)) return false;
    if ((op.props & Libm) && !float_alu) return false;
    if (op.fast != FastClass::Exact && !float_alu) return false;  // runtime/fast_kernels.h: f32 lanes
    // A pure op has no effect and writes one register.
    if ((op.props & Pure) && (op.props & (Effect | WritesRange | Texture | ReadsRange))) return false;
    return true;
}
constexpr bool table_consistent() {
    for (const OpInfo& op : kOpTable)
        if (!row_consistent(op)) return false;
    return true;
}
static_assert(table_consistent(), "a row of ir/opcodes.def contradicts its own columns");
}  // namespace

const OpInfo& op_info(Op op) { return kOpTable[size_t(op)]; }

const char* kind_name(Kind k) {
    switch (k) {
    case Kind::F32: return "f32";
    case Kind::I32: return "i32";
    case Kind::Bool: return "bool";
    }
    return "?";
}

// Splits "s[1].f[2]" into the uniform leaf name "s[1].f" and element 2, and
// accepts "a" / "a[0]" for arrays as GL's glGetUniformLocation does.
const Uniform* find_uniform(const Program& p, const std::string& name, uint32_t* element) {
    *element = 0;
    for (const Uniform& u : p.uniforms)
        if (u.name == name) return &u;
    if (name.empty() || name.back() != ']') return nullptr;
    size_t open = name.rfind('[');
    if (open == std::string::npos || open == 0) return nullptr;
    std::string digits = name.substr(open + 1, name.size() - open - 2);
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
        return nullptr;
    uint32_t index = uint32_t(std::strtoul(digits.c_str(), nullptr, 10));
    std::string base = name.substr(0, open);
    for (const Uniform& u : p.uniforms)
        if (u.name == base && u.is_array && index < u.array_size) {
            *element = index;
            return &u;
        }
    return nullptr;
}

}  // namespace glslrun::ir
