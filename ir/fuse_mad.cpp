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
#include "ir/mad_scan.h"
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

// The fmul of operand p at block[at], if p is read nowhere else.
const Instr* single_read_product(const std::vector<uint32_t>& reads, const Block& block, size_t at, Reg p) {
    if (p >= reads.size() || reads[p] != 1) return nullptr;
    return mad_scan::product(block, at, p, kWindow, [](const Instr&) { return true; });
}

void fuse(const std::vector<uint32_t>& reads, Block& body) {
    static constexpr Op kOps[3] = {Op::fmad, Op::fmsub, Op::fnmadd};
    mad_scan::for_each_add(body, [&](const Block& block, size_t at, Instr& in) {
        mad_scan::rewrite(in, kOps, [&](Reg p) { return single_read_product(reads, block, at, p); });
    });
}

}  // namespace

void fuse_multiply_add(Shader& shader) {
    std::vector<uint32_t> reads = count_reads(shader);
    fuse(reads, shader.body);
    for (Function& f : shader.functions) fuse(reads, f.body);
}

}  // namespace glslrun::ir
