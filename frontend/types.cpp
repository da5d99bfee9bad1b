// Flattening of glslang types into register layouts, and the uniform table.
#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {

ir::Kind kind_of(const gl::TType& t) {
    switch (t.getBasicType()) {
    case gl::EbtBool: return ir::Kind::Bool;
    case gl::EbtInt:
    case gl::EbtUint:
    case gl::EbtSampler: return ir::Kind::I32;
    default: return ir::Kind::F32;
    }
}

uint32_t array_length(const gl::TType& t) {
    if (!t.isArray()) return 1;
    int n = t.isUnsizedArray() ? t.getImplicitArraySize() : t.getOuterArraySize();
    return n > 0 ? uint32_t(n) : 1u;
}

gl::TType element_type(const gl::TType& t) { return gl::TType(t, 0); }

static uint32_t basic_size(const gl::TType& t) {
    if (t.isMatrix()) return uint32_t(t.getMatrixCols() * t.getMatrixRows());
    return uint32_t(t.getVectorSize() > 0 ? t.getVectorSize() : 1);
}

uint64_t components_of(const gl::TType& t) {
    constexpr uint64_t kSaturated = uint64_t(1) << 40;  // no overflow in the products below
    if (t.isArray()) return std::min(kSaturated, array_length(t) * components_of(element_type(t)));
    if (t.isStruct()) {
        uint64_t n = 0;
        for (const gl::TTypeLoc& m : *t.getStruct()) n = std::min(kSaturated, n + components_of(*m.type));
        return n;
    }
    return basic_size(t);
}

uint32_t flat_size(const gl::TType& t) { return uint32_t(components_of(t)); }

void flatten_kinds(const gl::TType& t, std::vector<ir::Kind>& out) {
    if (t.isArray()) {
        gl::TType elem = element_type(t);
        for (uint32_t i = 0, n = array_length(t); i < n; ++i) flatten_kinds(elem, out);
    } else if (t.isStruct()) {
        for (const gl::TTypeLoc& m : *t.getStruct()) flatten_kinds(*m.type, out);
    } else {
        out.insert(out.end(), basic_size(t), kind_of(t));
    }
}

uint32_t member_offset(const gl::TType& struct_type, int member) {
    uint32_t off = 0;
    const gl::TTypeList& members = *struct_type.getStruct();
    for (int i = 0; i < member; ++i) off += flat_size(*members[size_t(i)].type);
    return off;
}

static std::string basic_name(const gl::TType& t) {
    if (t.getBasicType() == gl::EbtSampler) return t.getSampler().getString().c_str();
    std::string prefix = t.getBasicType() == gl::EbtInt ? "i" : t.getBasicType() == gl::EbtBool ? "b" : "";
    std::string scalar = t.getBasicType() == gl::EbtInt ? "int" : t.getBasicType() == gl::EbtBool ? "bool" : "float";
    if (t.isMatrix()) {
        if (t.getMatrixCols() == t.getMatrixRows()) return fmt::format("mat{}", t.getMatrixCols());
        return fmt::format("mat{}x{}", t.getMatrixCols(), t.getMatrixRows());
    }
    if (t.getVectorSize() > 1) return fmt::format("{}vec{}", prefix, t.getVectorSize());
    return scalar;
}

std::string type_signature(const gl::TType& t) {
    if (t.isArray()) return fmt::format("{}[{}]", type_signature(element_type(t)), array_length(t));
    if (t.isStruct()) {
        std::string s = fmt::format("struct {}{{", t.getTypeName().c_str());
        for (const gl::TTypeLoc& m : *t.getStruct())
            s += fmt::format("{} {};", type_signature(*m.type), m.type->getFieldName().c_str());
        return s + "}";
    }
    return basic_name(t);
}

ir::ValueType value_type(const gl::TType& t) {
    ir::ValueType v;
    v.kind = kind_of(t);
    v.is_sampler = t.getBasicType() == gl::EbtSampler;
    if (t.isMatrix()) {
        v.cols = uint8_t(t.getMatrixCols());
        v.rows = uint8_t(t.getMatrixRows());
    } else {
        v.rows = uint8_t(t.getVectorSize() > 0 ? t.getVectorSize() : 1);
    }
    return v;
}

uint32_t float_bits(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

// GL leaf names: basic arrays are one leaf, arrays of structs one leaf per
// element per field, so element i's field sits at base + i * stride.
static void add_leaves(const gl::TType& t, const std::string& name, uint32_t slot, bool builtin,
                       std::vector<ir::Uniform>& out) {
    if (t.isArray()) {
        gl::TType elem = element_type(t);
        uint32_t n = array_length(t);
        if (elem.isStruct() || elem.isArray()) {
            uint32_t stride = flat_size(elem);
            for (uint32_t i = 0; i < n; ++i) add_leaves(elem, fmt::format("{}[{}]", name, i), slot + i * stride, builtin, out);
            return;
        }
        out.push_back(ir::Uniform{name, value_type(elem), n, true, slot, builtin});
        return;
    }
    if (t.isStruct()) {
        uint32_t off = 0;
        for (const gl::TTypeLoc& m : *t.getStruct()) {
            add_leaves(*m.type, name + "." + m.type->getFieldName().c_str(), slot + off, builtin, out);
            off += flat_size(*m.type);
        }
        return;
    }
    out.push_back(ir::Uniform{name, value_type(t), 1, false, slot, builtin});
}

const UniformTable::Var* UniformTable::declare(const std::string& name, const gl::TType& type, bool builtin,
                                               std::string* error) {
    std::string sig = type_signature(type);
    auto it = vars.find(name);
    if (it != vars.end()) {
        if (it->second.signature != sig) {
            *error = fmt::format("uniform '{}' declared with different types: {} and {}", name, it->second.signature, sig);
            return nullptr;
        }
        return &it->second;
    }
    Var v;
    v.slot = uint32_t(slot_kinds.size());
    v.signature = sig;
    flatten_kinds(type, slot_kinds);
    v.size = uint32_t(slot_kinds.size()) - v.slot;
    defaults.resize(slot_kinds.size(), 0u);
    add_leaves(type, name, v.slot, builtin, leaves);
    return &(vars[name] = v);
}

void UniformTable::set_default(const Var& var, const gl::TConstUnionArray& values) {
    for (uint32_t i = 0; i < var.size && int(i) < values.size(); ++i) {
        const gl::TConstUnion& c = values[int(i)];
        uint32_t word = 0;
        switch (slot_kinds[var.slot + i]) {
        case ir::Kind::F32:
            word = float_bits(c.getType() == gl::EbtInt ? float(c.getIConst()) : float(c.getDConst()));
            break;
        case ir::Kind::I32: word = uint32_t(c.getType() == gl::EbtDouble || c.getType() == gl::EbtFloat ? int32_t(c.getDConst()) : c.getIConst()); break;
        case ir::Kind::Bool: word = c.getType() == gl::EbtBool ? c.getBConst() : c.getIConst() != 0; break;
        }
        defaults[var.slot + i] = word;
    }
}

}  // namespace glslrun::frontend
