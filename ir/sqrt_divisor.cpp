// Square roots that are only ever divided by: `t = fsqrt y` where every read
// of t is the divisor of an fdiv becomes `t = fsqrt_divisor y`, and those
// reads `fdiv_by_sqrt x, t`. Precise and Reference evaluate the two ops
// exactly as fsqrt and fdiv (the opcode table gives them the same
// expressions), so no bit changes there. Precision::Fast evaluates them as
// t = rsqrt(y) (ir/fast_math.h) and x * t (runtime/fast_kernels.h): one
// estimate with Newton steps and multiplies instead of a square root and one
// division per component.
//
// Worked example, GLSL `n = normalize(v);` (frontend/lower_builtins.cpp):
//   d = fmad v.z, v.z, (fmad v.y, v.y, (fmul v.x, v.x))
//   t = fsqrt d            ->  t = fsqrt_divisor d      Fast: t = rsqrt(d)
//   n.x = fdiv v.x, t      ->  n.x = fdiv_by_sqrt v.x, t  Fast: n.x = v.x * t
//   n.y, n.z likewise
// `a / sqrt(b)` in the source is the same pattern. `length(v)` read as a
// length (d = length(l); att = 1.0 / (k0 + k1 * d)) keeps its fsqrt: t must
// have no other reader, since in Fast the register holds 1/sqrt(y).
//
// Safety: the rewrite changes what the register t holds in Fast, so t must
// be written by this fsqrt alone (one write in the whole shader), read only as
// a divisor (never as a dividend, a condition, a range or an output), and
// never read before the fsqrt has written it in the same run (a stale value
// would mean something else in each mode). It runs after the passes that
// could copy, fold or move t's reads (fold would evaluate fsqrt_divisor as a
// square root), just before regalloc, which only renames registers.
#include <vector>

#include "ir/assigned.h"
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

struct Uses {
    std::vector<uint32_t> writes, reads, divisor_reads;
};

Uses count_uses(const Shader& shader) {
    const size_t n = shader.regs.size();
    Uses u{std::vector<uint32_t>(n, 0), std::vector<uint32_t>(n, 0), std::vector<uint32_t>(n, 0)};
    auto bump = [n](std::vector<uint32_t>& v, Reg r) {
        if (r < n) ++v[r];
    };
    auto visit = [&](const Node& node) {
        flow::for_each_read(node, [&](Reg r) { bump(u.reads, r); });
        if (node.kind != NodeKind::Instr) return;
        flow::for_each_write(node.instr, [&](Reg r) { bump(u.writes, r); });
        const Instr& in = node.instr;
        if (in.op == Op::fdiv && in.src[0] != in.src[1]) bump(u.divisor_reads, in.src[1]);
    };
    for (const Block* b : {&shader.prologue, &shader.body}) flow::walk(*b, visit);
    for (const Function& f : shader.functions) flow::walk(f.body, visit);
    // The caller writes inputs and reads outputs: they have other meanings.
    for (const auto* list : {&shader.inputs, &shader.outputs})
        for (const Binding& b : *list)
            for (uint32_t i = 0; i < b.count; ++i) {
                bump(u.writes, b.first + i);
                bump(u.reads, b.first + i);
            }
    return u;
}

void rewrite(Block& block, const std::vector<bool>& marked) {
    for (Node& n : block) {
        rewrite(n.body, marked);
        rewrite(n.alt, marked);
        if (n.kind != NodeKind::Instr) continue;
        Instr& in = n.instr;
        if (in.op == Op::fsqrt && in.dst < marked.size() && marked[in.dst]) in.op = Op::fsqrt_divisor;
        if (in.op == Op::fdiv && in.src[1] < marked.size() && marked[in.src[1]]) in.op = Op::fdiv_by_sqrt;
    }
}

}  // namespace

void mark_sqrt_divisors(Shader& shader) {
    const Uses u = count_uses(shader);
    const std::vector<bool> unset = maybe_read_unset(shader);
    std::vector<bool> marked(shader.regs.size(), false);
    bool any = false;
    auto visit = [&](const Node& node) {
        if (node.kind != NodeKind::Instr || node.instr.op != Op::fsqrt) return;
        const Reg t = node.instr.dst;
        if (t >= marked.size() || u.writes[t] != 1 || unset[t]) return;
        if (u.reads[t] == 0 || u.reads[t] != u.divisor_reads[t]) return;
        marked[t] = any = true;
    };
    for (const Block* b : {&shader.prologue, &shader.body}) flow::walk(*b, visit);
    for (const Function& f : shader.functions) flow::walk(f.body, visit);
    if (!any) return;
    rewrite(shader.prologue, marked);
    rewrite(shader.body, marked);
    for (Function& f : shader.functions) rewrite(f.body, marked);
}

}  // namespace glslrun::ir
