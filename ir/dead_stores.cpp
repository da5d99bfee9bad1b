// Dead store elimination within straight-line code: a write to r that the
// same code overwrites before anything reads r is removed. dce only removes
// writes to registers that are never read at all; variables written in
// several places (a colour accumulated over a light's terms) keep their
// intermediate `mov`s without this pass.
//
// Between the two writes, control flow must neither read r nor let lanes
// leave (return, break, continue, calls) with r's first value still to be
// read after the construct: an If that does neither is passed over (lanes
// that discard in it are dead; no one reads their r). A Scope (an inlined
// function) that cannot return early is searched too: every lane entering it
// runs its body's straight-line code (outputs are zeroed before main's scope
// and written inside it). So every lane that got the first value gets the
// second, under the same mask, before any read.
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// How far ahead the overwrite may be: bounds the cost on huge blocks.
constexpr size_t kWindow = 256;

// A write whose every lane-wise effect is its destination (no ranges, no tex blocks).
bool plain_write(const Instr& in) { return flow::writes_dst_only(in); }

bool reads(const Node& n, Reg r) {
    bool hit = false;
    flow::for_each_read(n, [&](Reg x) { hit = hit || x == r; });
    return hit;
}

enum class Scan { overwritten, kept, unknown };

// True if n's subtree may read r or let lanes leave the code around it (or is
// too large for the remaining budget).
bool blocks(const Node& n, Reg r, size_t& budget) {
    if (budget == 0) return true;
    --budget;
    switch (n.kind) {
    case NodeKind::Return: case NodeKind::Break: case NodeKind::Continue: case NodeKind::Call: return true;
    default: break;
    }
    if (reads(n, r)) return true;
    for (const Block* inner : {&n.body, &n.alt})
        for (const Node& c : *inner)
            if (blocks(c, r, budget)) return true;
    return false;
}

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
        if (n.kind == NodeKind::If) {
            if (blocks(n, r, budget)) return Scan::kept;
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
