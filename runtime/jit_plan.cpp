// How the JIT would compile a shader, decided without LLVM: Backend::Auto
// plans its first draw from this before the JIT plugin is loaded
// (runtime/jit_plugin.h), and the plugin's compile follows the same plan.
#include "runtime/jit/jit.h"

#include <vector>

#include "ir/flow.h"

namespace glslrun::rt::jit {

namespace {

// The emitter writes each function once (an LLVM function of its own, called
// from every call site), so the JIT's code is the main body, the prologue and
// each function reachable from main, once. It takes a shader only if those
// weigh at most this many nodes in all: piglit's inline-explosion tests
// still fit (2^64 call paths, but a few small functions).
constexpr uint64_t kMaxNodes = 20000;
// LLVM's passes grow faster than linearly with one function's control flow:
// 250 loops one after another took 2.8 s of CPU to compile, 1000 took 21 s,
// and 1000 nested ones more than two minutes (#17; `--backend jit --stats`).
// So an If or a Loop counts as this many nodes: 200 of them at most.
constexpr uint64_t kControlFlowNodes = 100;

// Node counts of one block, a call counting as one node.
uint64_t count(const ir::Block& block, uint64_t control_flow) {
    uint64_t n = 0;
    ir::flow::walk(block, [&](const ir::Node& node) {
        n += node.kind == ir::NodeKind::If || node.kind == ir::NodeKind::Loop ? control_flow : 1;
    });
    return n;
}

// The functions reachable from `block`, in `reached`; false for a recursive
// call graph (or a call to a missing function, which the emitter turns into
// a run-time failure: counted as nothing).
bool reach(const ir::Shader& s, const ir::Block& block, std::vector<uint8_t>& state) {
    bool ok = true;
    ir::flow::walk(block, [&](const ir::Node& node) {
        if (!ok || node.kind != ir::NodeKind::Call || node.callee >= s.functions.size()) return;
        uint8_t& st = state[node.callee];
        if (st == 1) ok = false;  // on the path: recursion
        if (st != 0) return;
        st = 1;
        ok = reach(s, s.functions[node.callee].body, state);
        st = 2;
    });
    return ok;
}

}  // namespace

JitPlan plan_compile(const ir::Shader& shader, bool quick_codegen, bool optimised) {
    std::vector<uint8_t> state(shader.functions.size(), 0);
    if (!reach(shader, shader.body, state) || !reach(shader, shader.prologue, state)) return {};
    std::vector<const ir::Block*> units{&shader.body, &shader.prologue};
    for (size_t f = 0; f < shader.functions.size(); ++f)
        if (state[f] == 2) units.push_back(&shader.functions[f].body);
    uint64_t weighted = 0;
    double full = 0;
    for (const ir::Block* unit : units) {
        weighted += count(*unit, kControlFlowNodes);
        if (weighted > kMaxNodes) return {};
        // LLVM's time grows faster than linearly with one function's size.
        const double n = double(count(*unit, 1));
        full += n * kNanosPerInstruction * (1 + n / kInstructionsDoublingCost);
    }
    JitPlan plan;
    // A vertex shader runs once per vertex, far less often than the fragment
    // shader per pixel: without code-generation optimizations its compile
    // costs 4 to 30% less of the program's LLVM time and the corpus's frames
    // did not change (docs/performance.md).
    const bool quick = quick_codegen || full > double(kCompileBudgetNanos) || shader.stage == ir::Stage::Vertex;
    // Whether the JIT takes a shader is the first tier's decision: the
    // second only recompiles what the first runs.
    plan.take = uint64_t(quick ? full * kQuickCodegenShare : full) <= kDeclineNanos;
    plan.optimisable = quick && !quick_codegen;
    plan.quick = quick && !optimised;
    plan.nanos = uint64_t(plan.quick ? full * kQuickCodegenShare : full);
    return plan;
}

}  // namespace glslrun::rt::jit
