// What ir/fuse_mad.cpp and ir/contract.cpp share: finding the fmul that an
// fadd/fsub reads within one block, and rewriting the pair as one
// three-operand multiply-add.
#pragma once
#include <cstddef>

#include "ir/flow.h"

namespace glslrun::ir::mad_scan {

// Whether node n may write a, b or c (a call, or a nested block, may write anything it writes).
inline bool writes_any(const Node& n, Reg a, Reg b, Reg c) {
    if (n.kind == NodeKind::Call) return true;
    bool hit = false;
    auto check = [&](Reg r) { hit = hit || r == a || r == b || r == c; };
    if (n.kind == NodeKind::Instr) {
        flow::for_each_write(n.instr, check);
        return hit;
    }
    for (const Block* inner : {&n.body, &n.alt}) {
        flow::Writes w = flow::writes_of(*inner);
        if (w.calls) return true;
        for (Reg r : w.regs) check(r);
    }
    return hit;
}

// The fmul at block[i], i within `window` before `at`, that the read of `p`
// at block[at] sees, with its operands unchanged until `at` and accepted by
// `accept(mul)`; nullptr if there is none.
template <class Accept>
const Instr* product(const Block& block, size_t at, Reg p, size_t window, Accept&& accept) {
    size_t stop = at > window ? at - window : 0;
    for (size_t i = at; i-- > stop;) {
        const Node& n = block[i];
        if (!(n.kind == NodeKind::Instr && n.instr.dst == p)) {
            if (writes_any(n, p, p, p)) return nullptr;
            continue;
        }
        const Instr& mul = n.instr;
        if (mul.op != Op::fmul || mul.src[0] == p || mul.src[1] == p || !accept(mul)) return nullptr;
        for (size_t j = i + 1; j < at; ++j)
            if (writes_any(block[j], mul.src[0], mul.src[1], p)) return nullptr;
        return &mul;
    }
    return nullptr;
}

// `in` (p + c, c + p, p - c or c - p) as one op of `ops` (sum, product minus
// c, c minus product) on the fmul `find(k)` finds for operand k, the left one
// first; false if neither operand has one.
template <class Find>
bool rewrite(Instr& in, const Op (&ops)[3], Find&& find) {
    for (int k = 0; k < 2; ++k) {
        const Instr* mul = find(in.src[k]);
        if (!mul) continue;
        Reg c = in.src[1 - k];
        in.op = in.op == Op::fadd ? ops[0] : (k == 0 ? ops[1] : ops[2]);
        in.src[0] = mul->src[0];
        in.src[1] = mul->src[1];
        in.src[2] = c;
        return true;
    }
    return false;
}

// fn(block, i, instr) for every fadd/fsub of `block` and its nested blocks, inner blocks first.
template <class Fn>
void for_each_add(Block& block, Fn&& fn) {
    for (size_t i = 0; i < block.size(); ++i) {
        Node& n = block[i];
        for_each_add(n.body, fn);
        for_each_add(n.alt, fn);
        if (n.kind == NodeKind::Instr && (n.instr.op == Op::fadd || n.instr.op == Op::fsub)) fn(block, i, n.instr);
    }
}

}  // namespace glslrun::ir::mad_scan
