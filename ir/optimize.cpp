// The pass pipeline: inline, unroll, then (fold, copyprop, dead_stores, dce) until nothing changes
// (at most a few rounds), then contract, fuse_mad, hoist, dce, sqrt_divisor and regalloc. With
// PassOptions::verify the verifier runs after every pass and its first complaint is
// returned, naming the pass.
#include <cstdint>
#include <string>

#include "ir/passes.h"

namespace glslrun::ir {
namespace {

constexpr int kMaxRounds = 3;

// Returns "" or "after <pass>: <verifier message>".
std::string check(const Shader& shader, const char* pass, bool enabled) {
    if (!enabled) return {};
    std::string error = verify(shader);
    if (!error.empty()) return std::string("after ") + pass + ": " + error;
    return {};
}

// A structural hash, to see that a round of passes changed nothing without
// printing the shader twice (that printing was half of the optimizer's time).
// A collision could only end the rounds early: less optimized, never wrong.
struct Fingerprint {
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    void add(uint64_t v) { h = (h ^ v) * 1099511628211ull; }
    void add(const Block& block) {
        add(block.size());
        for (const Node& n : block) {
            add(uint64_t(n.kind));
            const Instr& i = n.instr;
            add(uint64_t(i.op) << 32 | uint64_t(i.type) << 16 | uint64_t(i.unmasked));
            for (uint64_t v : {uint64_t(i.dst), uint64_t(i.src[0]), uint64_t(i.src[1]), uint64_t(i.src[2]),
                               uint64_t(i.imm[0]), uint64_t(i.imm[1]), uint64_t(i.imm[2]), uint64_t(n.cond),
                               uint64_t(n.callee)})
                add(v);
            add(n.body);
            add(n.alt);
        }
    }
};

uint64_t fingerprint(const Shader& shader) {
    Fingerprint f;
    f.add(shader.regs.size());
    f.add(shader.body);
    for (const Function& fn : shader.functions) f.add(fn.body);
    return f.h;
}

}  // namespace

std::string optimize(Shader& shader, const PassOptions& options) {
    shader.helper_lookups_matter = helper_lookups_matter(shader);  // passes add no such reads
    if (!options.optimize) return check(shader, "frontend", options.verify);
    std::string error = check(shader, "frontend", options.verify);
    if (!error.empty()) return error;
    inline_calls(shader, options.inline_budget);
    if (!(error = check(shader, "inline", options.verify)).empty()) return error;
    unroll_loops(shader);
    if (!(error = check(shader, "unroll", options.verify)).empty()) return error;
    for (int round = 0; round < kMaxRounds; ++round) {
        uint64_t before = fingerprint(shader);
        fold_constants(shader);
        if (!(error = check(shader, "fold", options.verify)).empty()) return error;
        propagate_copies(shader);
        if (!(error = check(shader, "copyprop", options.verify)).empty()) return error;
        eliminate_dead_stores(shader);
        if (!(error = check(shader, "dead_stores", options.verify)).empty()) return error;
        eliminate_dead_code(shader);
        if (!(error = check(shader, "dce", options.verify)).empty()) return error;
        if (fingerprint(shader) == before) break;
    }
    contract_multiply_add(shader);
    if (!(error = check(shader, "contract", options.verify)).empty()) return error;
    fuse_multiply_add(shader);
    if (!(error = check(shader, "fuse_mad", options.verify)).empty()) return error;
    hoist_uniform_code(shader);
    if (!(error = check(shader, "hoist", options.verify)).empty()) return error;
    eliminate_dead_code(shader);
    if (!(error = check(shader, "dce", options.verify)).empty()) return error;
    mark_sqrt_divisors(shader);
    if (!(error = check(shader, "sqrt_divisor", options.verify)).empty()) return error;
    allocate_registers(shader);
    return check(shader, "regalloc", options.verify);
}

}  // namespace glslrun::ir
