// Places (l-values and indexed r-values): constant indexing selects
// registers directly, dynamic indexing becomes load_ind/store_ind/uniform_ind.
#include <algorithm>
#include <numeric>

#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

namespace {

std::vector<uint32_t> iota_comps(uint32_t n) {
    std::vector<uint32_t> c(n);
    std::iota(c.begin(), c.end(), 0u);
    return c;
}

// Size of one step of indexing into `t`: array element, matrix column or
// vector component; and how many steps there are.
void index_shape(const gl::TType& t, uint32_t* elem_size, uint32_t* count) {
    if (t.isArray()) {
        *elem_size = flat_size(element_type(t));
        *count = array_length(t);
    } else if (t.isMatrix()) {
        *elem_size = uint32_t(t.getMatrixRows());
        *count = uint32_t(t.getMatrixCols());
    } else {
        *elem_size = 1;
        *count = uint32_t(t.getVectorSize());
    }
}

// The components of element e of size `size` are regular if they sit at
// comps[0..size) + e * size: no swizzle has reordered them.
bool regular(const std::vector<uint32_t>& comps) {
    for (size_t i = 1; i < comps.size(); ++i)
        if (comps[i] != comps[0] + i) return false;
    return true;
}

}  // namespace

Access StageLowering::materialize(const Value& v) {
    std::vector<Kind> kinds;
    for (Reg r : v.regs) kinds.push_back(kind(r));
    Access a;
    a.base = new_range(kinds);
    for (size_t i = 0; i < v.regs.size(); ++i) mov_to(a.base + Reg(i), v.regs[i]);
    a.comps = iota_comps(uint32_t(v.regs.size()));
    return a;
}

void StageLowering::index_constant(Access& a, uint32_t offset) {
    for (uint32_t& c : a.comps) c += offset;
}

void StageLowering::index_dynamic(Access& a, Reg idx, uint32_t count, uint32_t stride) {
    if (a.index == ir::kNoReg) {
        a.index = idx;
        a.count = count;
        a.stride = stride;
        return;
    }
    // Two dynamic indices (a[i].m[j], m[i][j]): clamp each, then address in
    // units of gcd(stride) from one combined index.
    auto clamp = [&](Reg i, uint32_t n) {
        Reg lo = alu(Op::imax, Kind::I32, i, konst_i(0));
        return alu(Op::imin, Kind::I32, lo, konst_i(int32_t(n) - 1));
    };
    uint32_t g = std::gcd(a.stride, stride);
    Reg i1 = alu(Op::imul, Kind::I32, clamp(a.index, a.count), konst_i(int32_t(a.stride / g)));
    Reg i2 = alu(Op::imul, Kind::I32, clamp(idx, count), konst_i(int32_t(stride / g)));
    a.index = alu(Op::iadd, Kind::I32, i1, i2);
    a.count = ((a.count - 1) * a.stride + (count - 1) * stride) / g + 1;
    a.stride = g;
}

Access StageLowering::access(gl::TIntermTyped* n) {
    set_line(n);
    if (auto it = prebound_places_.find(n); it != prebound_places_.end()) {
        Access a = std::move(it->second);
        prebound_places_.erase(it);
        return a;
    }
    if (gl::TIntermSymbol* sym = n->getAsSymbolNode()) return variable(sym);
    gl::TIntermBinary* b = n->getAsBinaryNode();
    if (!b) return materialize(expr(n));
    gl::TOperator op = b->getOp();
    if (op != gl::EOpIndexDirect && op != gl::EOpIndexIndirect && op != gl::EOpIndexDirectStruct &&
        op != gl::EOpVectorSwizzle)
        return materialize(expr(n));

    const gl::TType& lt = b->getLeft()->getType();
    Access a = access(b->getLeft());
    set_line(n);
    if (op == gl::EOpVectorSwizzle) {
        std::vector<uint32_t> comps;
        for (TIntermNode* s : b->getRight()->getAsAggregate()->getSequence()) {
            int i = s->getAsConstantUnion()->getConstArray()[0].getIConst();
            comps.push_back(a.comps[size_t(i)]);
        }
        a.comps = comps;
        return a;
    }
    if (op == gl::EOpIndexDirectStruct) {
        int m = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
        uint32_t off = member_offset(lt, m);
        uint32_t size = flat_size(*(*lt.getStruct())[size_t(m)].type);
        a.comps = std::vector<uint32_t>(a.comps.begin() + off, a.comps.begin() + off + size);
        return a;
    }
    uint32_t elem, count;
    index_shape(lt, &elem, &count);
    if (op == gl::EOpIndexDirect || b->getRight()->getAsConstantUnion()) {
        int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
        // Out-of-range constant indices are compile errors in glslang; clamp
        // anyway so that nothing here can read past the variable.
        uint32_t e = uint32_t(std::clamp(i, 0, int(count) - 1));
        a.comps = std::vector<uint32_t>(a.comps.begin() + e * elem, a.comps.begin() + (e + 1) * elem);
        return a;
    }
    std::vector<uint32_t> first(a.comps.begin(), a.comps.begin() + elem);
    if (!regular(a.comps) && elem == 1 && a.index == ir::kNoReg) {
        // A swizzle feeding a dynamic index (v.wzyx[i], also as an l-value):
        // map i through a table of the swizzle's component offsets.
        Value idx = expr(b->getRight());
        if (idx.regs.size() != 1 || kind(idx.regs[0]) != Kind::I32) return materialize(fail(n, "array index is not an int"));
        check_index(idx.regs[0], count);
        uint32_t lo = *std::min_element(a.comps.begin(), a.comps.end());
        uint32_t hi = *std::max_element(a.comps.begin(), a.comps.end());
        Reg table = new_range(std::vector<Kind>(count, Kind::I32));
        for (uint32_t e = 0; e < count; ++e) mov_to(table + e, konst_i(int32_t(a.comps[e] - lo)));
        ir::Instr in;
        in.op = Op::load_ind;
        in.type = Kind::I32;
        in.dst = new_reg(Kind::I32);
        in.src[0] = idx.regs[0];
        in.imm[0] = table;
        in.imm[1] = count;
        in.imm[2] = 1;
        emit(in);
        a.comps = {lo};
        index_dynamic(a, in.dst, hi - lo + 1, 1);
        return a;
    }
    if (!regular(a.comps)) {
        // Other irregular layouts (a swizzle of a dynamically indexed
        // element): read through a copy.
        Access copy = materialize(read(a));
        copy.comps = iota_comps(count * elem);
        a = copy;
        first = std::vector<uint32_t>(a.comps.begin(), a.comps.begin() + elem);
    }
    Value idx = expr(b->getRight());
    if (idx.regs.size() != 1 || kind(idx.regs[0]) != Kind::I32) return materialize(fail(n, "array index is not an int"));
    check_index(idx.regs[0], count);
    a.comps = first;
    index_dynamic(a, idx.regs[0], count, elem);
    return a;
}

Kind StageLowering::access_kind(const Access& a, size_t i) const {
    uint32_t pos = a.base + a.comps[i];
    return a.uniform ? uniforms_.slot_kinds[pos] : shader.regs[pos];
}

Value StageLowering::read(const Access& a) {
    Value v;
    for (size_t i = 0; i < a.comps.size(); ++i) {
        Kind k = access_kind(a, i);
        uint32_t pos = a.base + a.comps[i];
        if (a.index == ir::kNoReg && !a.uniform) {
            v.regs.push_back(mov(pos));
            continue;
        }
        ir::Instr in;
        in.type = k;
        in.dst = new_reg(k);
        in.imm[0] = pos;
        if (a.index == ir::kNoReg) {
            in.op = Op::uniform;
        } else {
            in.op = a.uniform ? Op::uniform_ind : Op::load_ind;
            in.src[0] = a.index;
            in.imm[1] = a.count;
            in.imm[2] = a.stride;
            for (uint32_t e = 0; e < a.count; ++e) {
                uint32_t p = pos + e * a.stride;
                Kind ke = a.uniform ? uniforms_.slot_kinds[p] : shader.regs[p];
                if (ke != k) return fail(nullptr, "unsupported: nested dynamic indexing into a structure with mixed types");
            }
        }
        emit(in);
        v.regs.push_back(in.dst);
    }
    return v;
}

void StageLowering::write(const Access& a, const Value& v, TIntermNode* where) {
    if (a.uniform) {
        fail(where, "cannot assign to a uniform");
        return;
    }
    if (v.regs.size() != a.comps.size()) {
        fail(where, fmt::format("internal: assigning {} components to {}", v.regs.size(), a.comps.size()));
        return;
    }
    for (size_t i = 0; i < a.comps.size(); ++i) {
        uint32_t pos = a.base + a.comps[i];
        Kind k = shader.regs[pos];
        Reg src = kind(v.regs[i]) == k ? v.regs[i] : convert(Value{{v.regs[i]}}, k).regs[0];
        if (a.index == ir::kNoReg) {
            mov_to(pos, src);
            continue;
        }
        for (uint32_t e = 0; e < a.count; ++e)
            if (shader.regs[pos + e * a.stride] != k) {
                fail(where, "unsupported: nested dynamic indexing into a structure with mixed types");
                return;
            }
        ir::Instr in;
        in.op = Op::store_ind;
        in.type = k;
        in.dst = ir::kNoReg;
        in.src[0] = a.index;
        in.src[1] = src;
        in.imm[0] = pos;
        in.imm[1] = a.count;
        in.imm[2] = a.stride;
        emit(in);
    }
}

}  // namespace glslrun::frontend
