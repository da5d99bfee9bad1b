// Dead store elimination within straight-line code: a write to r that the
// same code overwrites before anything reads r is removed. dce only removes
// writes to registers that are never read at all; variables written in
// several places (a colour accumulated over a light's terms) keep their
// intermediate `mov`s without this pass.
//
// Only instructions may stand between the two writes: control flow could
// read r, or let some lanes leave (return, break, discard) with r's first
// value still to be read after the construct. The one exception is a Scope
// (an inlined function) that cannot return early: every lane entering it runs
// its body's straight-line code, so the search goes on inside it (outputs are
// zeroed before main's scope and written inside it). Without control flow
// between them both writes run under the same mask, so every lane that got
// the first value gets the second before any read.
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// How far ahead the overwrite may be: bounds the cost on huge blocks.
constexpr size_t kWindow = 256;

// A write whose every lane-wise effect is its destination (no ranges, no tex blocks).
bool plain_write(const Instr& in) {
    return in.dst != kNoReg && !flow::writes_range(in.op) && in.op != Op::tex;
}

bool reads(const Node& n, Reg r) {
    bool hit = false;
    flow::for_each_read(n, [&](Reg x) { hit = hit || x == r; });
    return hit;
}

enum class Scan { overwritten, kept, unknown };

// Looks for the overwrite of r in block[from..), within `budget` nodes.
Scan scan(const Block& block, size_t from, Reg r, size_t& budget) {
    for (size_t j = from; j < block.size(); ++j) {
        if (budget-- == 0) return Scan::kept;
        const Node& n = block[j];
        if (n.kind == NodeKind::Scope && !flow::returns_early(n.body)) {
            Scan inside = scan(n.body, 0, r, budget);
            if (inside != Scan::unknown) return inside;
            continue;
        }
        if (n.kind != NodeKind::Instr || reads(n, r)) return Scan::kept;
        if (plain_write(n.instr) && n.instr.dst == r) return Scan::overwritten;
        bool clobbers = false;
        flow::for_each_write(n.instr, [&](Reg w) { clobbers = clobbers || w == r; });
        if (clobbers) return Scan::kept;  // a range write may leave some lanes' r alone
    }
    return Scan::unknown;
}

bool overwritten(const Block& block, size_t i) {
    size_t budget = kWindow;
    return scan(block, i + 1, block[i].instr.dst, budget) == Scan::overwritten;
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
