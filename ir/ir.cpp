#include "ir/ir.h"

#include <cstdlib>

namespace glslrun::ir {

namespace {
constexpr TypeClass F = TypeClass::F, I = TypeClass::I, B = TypeClass::B, T = TypeClass::T,
                    X = TypeClass::X;
constexpr OpKind Alu = OpKind::Alu, Special = OpKind::Special;
const OpInfo kOpTable[] = {
#define OP(name, arity, res, opnd, kind, fast, expr) {#name, arity, res, opnd, kind, FastClass::fast},
#include "ir/opcodes.def"
#undef OP
};
static_assert(sizeof(kOpTable) / sizeof(kOpTable[0]) == size_t(Op::Count_));
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
