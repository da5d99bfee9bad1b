// Dead store elimination within straight-line code: a write to r that the
// same block overwrites before anything reads r is removed. dce only removes
// writes to registers that are never read at all; variables written in
// several places (a colour accumulated over a light's terms) keep their
// intermediate `mov`s without this pass.
//
// Only instructions may stand between the two writes: control flow could
// read r, or let some lanes leave (return, break, discard) with r's first
// value still to be read after the construct. Without control flow between
// them both writes run under the same mask, so every lane that got the first
// value gets the second before any read.
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// How far ahead the overwrite may be: bounds the cost on huge blocks.
constexpr size_t kWindow = 64;

// A write whose every lane-wise effect is its destination (no ranges, no tex blocks).
bool plain_write(const Instr& in) {
    return in.dst != kNoReg && !flow::writes_range(in.op) && in.op != Op::tex;
}

bool reads(const Node& n, Reg r) {
    bool hit = false;
    flow::for_each_read(n, [&](Reg x) { hit = hit || x == r; });
    return hit;
}

// True if block[i]'s destination is overwritten later in the block before
// any read, with only instructions in between.
bool overwritten(const Block& block, size_t i) {
    const Reg r = block[i].instr.dst;
    for (size_t j = i + 1; j < block.size() && j <= i + kWindow; ++j) {
        const Node& n = block[j];
        if (n.kind != NodeKind::Instr || reads(n, r)) return false;
        if (plain_write(n.instr) && n.instr.dst == r) return true;
        bool clobbers = false;
        flow::for_each_write(n.instr, [&](Reg w) { clobbers = clobbers || w == r; });
        if (clobbers) return false;  // a range write may leave some lanes' r alone
    }
    return false;
}

void sweep(Block& block) {
    size_t out = 0;
    for (size_t i = 0; i < block.size(); ++i) {
        Node& n = block[i];
        sweep(n.body);
        sweep(n.alt);
        if (n.kind == NodeKind::Instr && plain_write(n.instr) && overwritten(block, i)) continue;
        if (out != i) block[out] = std::move(n);
        ++out;
    }
    block.resize(out);
}

}  // namespace

void eliminate_dead_stores(Shader& shader) {
    sweep(shader.body);
    for (Function& f : shader.functions) sweep(f.body);
}

}  // namespace glslrun::ir
