// Register read/write enumeration shared by the passes (inline, fold,
// copyprop, dce). Indexed accesses touch whole ranges: load_ind reads every
// register of its range and store_ind may write any of them.
#pragma once
#include <cstdint>
#include <vector>

#include "ir/ir.h"

namespace glslrun::ir::flow {

// Calls fn(reg) for every register of an indexed range (imm[0], imm[1], imm[2]).
template <class Fn>
void for_each_in_range(const Instr& in, Fn&& fn) {
    for (uint32_t e = 0; e < in.imm[1]; ++e) fn(Reg(in.imm[0] + e * in.imm[2]));
}

inline bool reads_range(Op op) { return has(op, OpProp::ReadsRange); }
inline bool writes_range(Op op) { return has(op, OpProp::WritesRange); }
// Whether the op samples a texture: an operand block and kTexResults results.
inline bool texture(Op op) { return has(op, OpProp::Texture); }
// Whether its only write is dst (none of ranges or result blocks).
inline bool writes_dst_only(const Instr& in) {
    return in.dst != kNoReg && !writes_range(in.op) && !texture(in.op);
}

// Registers an instruction reads explicitly (its operands).
template <class Fn>
void for_each_operand(const Instr& in, Fn&& fn) {
    int arity = op_info(in.op).arity;
    for (int k = 0; k < arity; ++k)
        if (in.src[k] != kNoReg) fn(in.src[k]);
}

// `tex` reads its operand block and writes kTexResults registers from dst.
// Both ranges are addressed by position, so passes must neither rename nor
// split them (inline treats them as shared, copyprop never rewrites imm).
template <class Fn>
void for_each_tex_operand(const Instr& in, Fn&& fn) {
    for (uint32_t k = 0; k < in.imm[1]; ++k) fn(Reg(in.imm[0] + k));
}
template <class Fn>
void for_each_tex_result(const Instr& in, Fn&& fn) {
    for (uint32_t k = 0; k < kTexResults; ++k) fn(Reg(in.dst + k));
}

// Registers a single node reads directly (not its nested blocks): operands,
// load_ind ranges, tex operand blocks and If conditions.
template <class Fn>
void for_each_read(const Node& n, Fn&& fn) {
    if (n.kind == NodeKind::If) fn(n.cond);
    if (n.kind != NodeKind::Instr) return;
    for_each_operand(n.instr, fn);
    if (reads_range(n.instr.op)) for_each_in_range(n.instr, fn);
    if (texture(n.instr.op)) for_each_tex_operand(n.instr, fn);
}

// Registers a single instruction may write.
template <class Fn>
void for_each_write(const Instr& in, Fn&& fn) {
    if (writes_range(in.op))
        for_each_in_range(in, fn);
    else if (texture(in.op))
        for_each_tex_result(in, fn);
    else if (in.dst != kNoReg)
        fn(in.dst);
}

// Applies fn to every node of a block, nested blocks included (pre-order).
template <class Fn>
void walk(const Block& block, Fn&& fn) {
    for (const Node& n : block) {
        fn(n);
        walk(n.body, fn);
        walk(n.alt, fn);
    }
}

// What a block may write: its registers, and whether it calls a function
// (whose writes are not listed; callers then forget everything).
struct Writes {
    std::vector<Reg> regs;
    bool calls = false;
};
inline Writes writes_of(const Block& block) {
    Writes w;
    walk(block, [&](const Node& n) {
        if (n.kind == NodeKind::Call) w.calls = true;
        if (n.kind == NodeKind::Instr) for_each_write(n.instr, [&](Reg r) { w.regs.push_back(r); });
    });
    return w;
}

// True if a Return in `block` can end the enclosing Scope early (returns in
// nested Scopes end those instead; Calls return from their own body).
inline bool returns_early(const Block& block) {
    for (const Node& n : block) {
        if (n.kind == NodeKind::Return) return true;
        if ((n.kind == NodeKind::If || n.kind == NodeKind::Loop) && (returns_early(n.body) || returns_early(n.alt)))
            return true;
    }
    return false;
}

inline bool is_exit(NodeKind k) {
    return k == NodeKind::Break || k == NodeKind::Continue || k == NodeKind::Return || k == NodeKind::Discard;
}

inline uint64_t node_count(const Block& block) {
    uint64_t n = 0;
    walk(block, [&](const Node&) { ++n; });
    return n;
}

}  // namespace glslrun::ir::flow
