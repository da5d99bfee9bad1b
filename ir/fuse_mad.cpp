// Multiply-add fusion: `p = x * y` followed in the same block by `d = p + c`
// (or p - c, c - p), where that is the only read of p anywhere, becomes one
// instruction `d = fmad/fmsub/fnmadd x, y, c`. The fused ops round the product
// and then the sum exactly as the two instructions did, so no bit changes;
// the fmul is left for dce. Saves one dispatch per pair: dot products and
// matrix products are lowered to long fmul/fadd chains.
//
// Lanes: the pair runs under the same mask, except that exits in between
// (break, return, discard) can only switch lanes off, and those never read d
// through this instruction anyway. x and y must not change in between.
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

// How far back from an fadd the fmul may be: bounds the pass's cost on huge
// straight-line blocks; dot products keep their pairs adjacent.
constexpr size_t kWindow = 32;

std::vector<uint32_t> count_reads(const Shader& shader) {
    std::vector<uint32_t> reads(shader.regs.size(), 0);
    auto count = [&](Reg r) {
        if (r < reads.size()) ++reads[r];
    };
    auto visit = [&](const Node& n) { flow::for_each_read(n, count); };
    flow::walk(shader.body, visit);
    for (const Function& f : shader.functions) flow::walk(f.body, visit);
    // The caller reads outputs and writes inputs: neither may disappear.
    for (const auto* list : {&shader.inputs, &shader.outputs})
        for (const Binding& b : *list)
            for (uint32_t i = 0; i < b.count; ++i) count(b.first + i);
    return reads;
}

bool writes_any(const Node& n, Reg a, Reg b, Reg c) {
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

struct Fuser {
    const std::vector<uint32_t>& reads;

    // The fmul at block[i] that the read of `p` at block[at] sees, with its
    // operands unchanged until `at`; nullptr if there is none.
    const Instr* product(const Block& block, size_t at, Reg p) const {
        if (p >= reads.size() || reads[p] != 1) return nullptr;
        size_t stop = at > kWindow ? at - kWindow : 0;
        for (size_t i = at; i-- > stop;) {
            const Node& n = block[i];
            bool is_def = n.kind == NodeKind::Instr && n.instr.dst == p;
            if (!is_def) {
                if (writes_any(n, p, p, p)) return nullptr;
                continue;
            }
            const Instr& mul = n.instr;
            if (mul.op != Op::fmul || mul.src[0] == p || mul.src[1] == p) return nullptr;
            for (size_t j = i + 1; j < at; ++j)
                if (writes_any(block[j], mul.src[0], mul.src[1], p)) return nullptr;
            return &mul;
        }
        return nullptr;
    }

    void fuse(const Block& block, size_t at, Instr& in) const {
        // p + c, c + p (fadd commutes), p - c, c - p.
        for (int k = 0; k < 2; ++k) {
            const Instr* mul = product(block, at, in.src[k]);
            if (!mul) continue;
            Reg c = in.src[1 - k];
            in.op = in.op == Op::fadd ? Op::fmad : (k == 0 ? Op::fmsub : Op::fnmadd);
            in.src[0] = mul->src[0];
            in.src[1] = mul->src[1];
            in.src[2] = c;
            return;
        }
    }

    void run(Block& block) const {
        for (size_t i = 0; i < block.size(); ++i) {
            Node& n = block[i];
            run(n.body);
            run(n.alt);
            if (n.kind == NodeKind::Instr && (n.instr.op == Op::fadd || n.instr.op == Op::fsub))
                fuse(block, i, n.instr);
        }
    }
};

}  // namespace

void fuse_multiply_add(Shader& shader) {
    std::vector<uint32_t> reads = count_reads(shader);
    Fuser fuser{reads};
    fuser.run(shader.body);
    for (Function& f : shader.functions) fuser.run(f.body);
}

}  // namespace glslrun::ir
