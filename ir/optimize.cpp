// The pass pipeline: inline, then (fold, copyprop, dead_stores, dce) until nothing changes
// (at most a few rounds), then fuse_mad, hoist, dce and regalloc. With
// GLSLRUN_VERIFY the verifier runs after every pass and its first complaint is
// returned, naming the pass.
#include <string>

#include "ir/passes.h"

namespace glslrun::ir {
namespace {

constexpr int kMaxRounds = 3;

// Returns "" or "after <pass>: <verifier message>".
std::string check(const Shader& shader, const char* pass) {
#ifdef GLSLRUN_VERIFY
    std::string error = verify(shader);
    if (!error.empty()) return std::string("after ") + pass + ": " + error;
#else
    (void)shader;
    (void)pass;
#endif
    return {};
}

}  // namespace

std::string optimize(Shader& shader, const PassOptions& options) {
    if (!options.optimize) return check(shader, "frontend");
    std::string error = check(shader, "frontend");
    if (!error.empty()) return error;
    inline_calls(shader, options.inline_budget);
    if (!(error = check(shader, "inline")).empty()) return error;
    for (int round = 0; round < kMaxRounds; ++round) {
        std::string before = print(shader);
        fold_constants(shader);
        if (!(error = check(shader, "fold")).empty()) return error;
        propagate_copies(shader);
        if (!(error = check(shader, "copyprop")).empty()) return error;
        eliminate_dead_stores(shader);
        if (!(error = check(shader, "dead_stores")).empty()) return error;
        eliminate_dead_code(shader);
        if (!(error = check(shader, "dce")).empty()) return error;
        if (print(shader) == before) break;
    }
    fuse_multiply_add(shader);
    if (!(error = check(shader, "fuse_mad")).empty()) return error;
    hoist_uniform_code(shader);
    if (!(error = check(shader, "hoist")).empty()) return error;
    eliminate_dead_code(shader);
    if (!(error = check(shader, "dce")).empty()) return error;
    allocate_registers(shader);
    return check(shader, "regalloc");
}

}  // namespace glslrun::ir
