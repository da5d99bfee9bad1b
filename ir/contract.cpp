// Multiply-add contraction as NVIDIA's GLSL compiler does it (measured on the
// GPU: tools/gpu_probes/fma.frag, fma2.frag; docs/precision.md, "Multiply-add
// contraction"): an fadd/fsub that reads an fmul of the same block becomes
// ffma/ffms/ffnma. Those round once in Precision::Fast (the GPU's FFMA) and
// round the product and then the sum in Precise and Reference, so only Fast's
// bits change. The rule, each part seen on the GPU:
//   - a product is contracted into every add or subtract that reads it, also
//     when it has several (each FFMA multiplies again), but only when every
//     read of it is such an add in the block that computes it: one compare
//     or one read in a nested block keeps it a rounded product everywhere;
//   - an add of two products contracts the left one (x*x - y*y is
//     fma(x, x, -(y*y))), but a built-in's (dot, matrix products) the right
//     one: fma(x1, y1, x0*y0), as the GPU's DP lowering (scenes/programs/
//     gooch.frag's strokes, on the diagonal where dot(p, (k, -k)) is 0);
//     a product by ±1 is none, the GPU's compiler drops it
//     (dot(vec2(1.0, a), vec2(c, b)) is fma(a, b, c));
//   - a product with a factor that is itself a product by a power of two,
//     (2x)*y, is not contracted: the GPU's compiler moves the exact factor
//     out, ((x*y)*2) + c, and the add then fuses with the exact scaling, so
//     x*y keeps its rounding (mandelbrot's 2.0 * z.x * z.y + c.y).
// The fmuls left without readers go to dce. Runs before fuse_mad, which then
// fuses the remaining single-read pairs without changing a bit in any mode.
#include <bit>
#include <vector>

#include "ir/flow.h"
#include "ir/mad_scan.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// How far back from an add its product may be: bounds the pass's cost on
// huge straight-line blocks.
constexpr size_t kWindow = 64;

// Per register: how often it is written and read, and whether every read is
// an operand of an fadd/fsub of one block.
struct RegUse {
    uint32_t writes = 0;
    uint32_t reads = 0;
    uint32_t add_reads = 0;
    const Block* add_block = nullptr;
    bool one_block = true;
    const Instr* def = nullptr;  // the last write (meaningful when writes == 1)
};

struct Census {
    std::vector<RegUse> use;
    std::vector<const Instr*> movs;  // every register-to-register mov

    Census(const Shader& shader, bool display_copies) : use(shader.regs.size()) {
        scan(shader.prologue);
        scan(shader.body);
        for (const Function& f : shader.functions) scan(f.body);
        // The caller reads outputs and writes inputs: neither is a plain product.
        for (const auto* list : {&shader.inputs, &shader.outputs})
            for (const Binding& b : *list)
                for (uint32_t i = 0; i < b.count; ++i) read(b.first + i);
        if (display_copies) unread_display_copies(shader);
    }

    // A mov into a variable's register that nothing reads (after copyprop every later read
    // takes the source itself) is there only to be shown: it is not a read of its source.
    void unread_display_copies(const Shader& shader) {
        std::vector<bool> variable(use.size());
        for (const Variable& v : shader.variables)
            for (uint32_t i = 0; i < v.count; ++i)
                if (v.first + i < use.size()) variable[v.first + i] = true;
        for (const Instr* mov : movs)
            if (variable[mov->dst] && use[mov->dst].reads == 0 && mov->src[0] < use.size()) --use[mov->src[0]].reads;
    }

    void read(Reg r) {
        if (r < use.size()) ++use[r].reads;
    }

    void scan(const Block& block) {
        for (const Node& n : block) {
            scan(n.body);
            scan(n.alt);
            flow::for_each_read(n, [&](Reg r) { read(r); });
            if (n.kind == NodeKind::Call) continue;
            if (n.kind != NodeKind::Instr) continue;
            const Instr& in = n.instr;
            if (in.op == Op::mov && in.dst < use.size()) movs.push_back(&in);
            flow::for_each_write(in, [&](Reg r) {
                if (r >= use.size()) return;
                ++use[r].writes;
                use[r].def = &in;
            });
            if (in.op != Op::fadd && in.op != Op::fsub) continue;
            for (int k = 0; k < 2; ++k) {
                if (in.src[k] >= use.size() || (k == 1 && in.src[1] == in.src[0])) continue;
                RegUse& u = use[in.src[k]];
                u.add_reads += in.src[0] == in.src[1] ? 2 : 1;
                if (u.add_block && u.add_block != &block) u.one_block = false;
                u.add_block = &block;
            }
        }
    }

    // The magnitude's bits of a register written once, by a konst; or 0.
    uint32_t konst_magnitude(Reg r) const {
        if (r >= use.size() || use[r].writes != 1 || use[r].def->op != Op::konst) return 0;
        return use[r].def->imm[0] & 0x7fffffffu;
    }
    // ±2^e but ±1 (dropped, as by_one says).
    bool power_of_two(Reg r) const {
        uint32_t bits = konst_magnitude(r), exponent = bits >> 23;
        return (bits & 0x7fffffu) == 0 && exponent != 0 && exponent != 255 && bits != 0x3f800000u;
    }
    // x * ±1: the GPU's compiler drops it, so it is no product to contract.
    bool by_one(const Instr& mul) const {
        return konst_magnitude(mul.src[0]) == 0x3f800000u || konst_magnitude(mul.src[1]) == 0x3f800000u;
    }

    // (k * x) * y with k a power of two: the GPU rounds x*y (see the top).
    bool scaled_factor(const Instr& mul) const {
        for (Reg f : mul.src) {
            if (f >= use.size() || use[f].writes != 1 || use[f].def->op != Op::fmul) continue;
            const Instr& inner = *use[f].def;
            if (power_of_two(inner.src[0]) || power_of_two(inner.src[1])) return true;
        }
        return false;
    }
};

// The fmul of operand p at block[at], contractible by the rule above.
const Instr* contractible(const Census& census, const Block& block, size_t at, Reg p) {
    if (p >= census.use.size()) return nullptr;
    const RegUse& u = census.use[p];
    if (u.writes != 1 || u.reads != u.add_reads || !u.one_block || u.add_block != &block) return nullptr;
    return mad_scan::product(block, at, p, kWindow,
                             [&](const Instr& mul) { return !census.by_one(mul) && !census.scaled_factor(mul); });
}

// The source location of the node of block[..at) holding `in`.
const SourceLoc* loc_of(const Block& block, size_t at, const Instr* in) {
    for (size_t i = at; i-- > 0;)
        if (&block[i].instr == in) return &block[i].loc;
    return nullptr;
}

bool same_loc(const SourceLoc* a, const SourceLoc& b) {
    return a && a->line == b.line && a->column == b.column && a->source == b.source;
}

void contract(const Census& census, Block& body) {
    static constexpr Op kOps[3] = {Op::ffma, Op::ffms, Op::ffnma};
    mad_scan::for_each_add(body, [&](const Block& block, size_t at, Instr& in) {
        const Instr* left = contractible(census, block, at, in.src[0]);
        const Instr* right = in.src[1] == in.src[0] ? nullptr : contractible(census, block, at, in.src[1]);
        // A built-in's sum of products (dot, a matrix product: the add and both products at the
        // call's location) accumulates as the GPU's DP: x0*y0 rounded, then fma(x1, y1, it).
        const SourceLoc& here = block[at].loc;
        const bool builtin = left && right && same_loc(loc_of(block, at, left), here) &&
                             same_loc(loc_of(block, at, right), here);
        mad_scan::rewrite(in, kOps, [&](Reg p) {
            if (p == in.src[0]) return builtin ? nullptr : left;
            return right;
        });
    });
}

}  // namespace

void contract_multiply_add(Shader& shader, bool display_copies) {
    const Census census(shader, display_copies);
    contract(census, shader.prologue);
    contract(census, shader.body);
    for (Function& f : shader.functions) contract(census, f.body);
}

}  // namespace glslrun::ir
