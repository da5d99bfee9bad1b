// How the JIT would compile a shader, decided without LLVM: Backend::Auto
// plans its first draw from this before the JIT plugin is loaded
// (runtime/jit_plugin.h), and the plugin's compile follows the same plan.
#include "runtime/jit/jit.h"

#include <vector>

namespace glslrun::rt::jit {

namespace {

// The emitter writes callees out in place (GLSL has no recursion), so the
// JIT takes a shader only if its calls expand to at most this many nodes:
// piglit's glsl-*-inline-explosion calls grow exponentially, and the
// interpreter, which runs calls as calls, serves such shaders.
constexpr uint64_t kMaxExpandedNodes = 20000;
// LLVM's passes grow faster than linearly with one function's control flow:
// 250 loops one after another took 2.8 s of CPU to compile, 1000 took 21 s,
// and 1000 nested ones more than two minutes (#17; `--backend jit --stats`).
// So an If or a Loop counts as this many nodes: 200 of them at most.
constexpr uint64_t kControlFlowNodes = 100;

// The node count of `block` with its calls expanded, memoized per function;
// UINT64_MAX for a recursive call graph or past the limit.
class ExpandedSize {
public:
    // `control_flow`: the weight of an If or a Loop (an instruction weighs 1).
    ExpandedSize(const ir::Shader& s, uint64_t control_flow)
        : shader_(s), control_flow_(control_flow), size_(s.functions.size(), kUnknown) {}
    uint64_t of(const ir::Block& block) {
        uint64_t n = 0;
        for (const ir::Node& node : block) {
            n = add(add(add(n, cost(node)), of(node.body)), of(node.alt));
            if (node.kind == ir::NodeKind::Call && node.callee < shader_.functions.size()) n = add(n, of_function(node.callee));
            if (n == kTooLarge) return n;
        }
        return n;
    }

private:
    static constexpr uint64_t kUnknown = UINT64_MAX - 1, kOnPath = UINT64_MAX - 2, kTooLarge = UINT64_MAX;
    uint64_t cost(const ir::Node& node) const {
        return node.kind == ir::NodeKind::If || node.kind == ir::NodeKind::Loop ? control_flow_ : 1;
    }
    static uint64_t add(uint64_t a, uint64_t b) { return a > kMaxExpandedNodes || b > kMaxExpandedNodes || a + b > kMaxExpandedNodes ? kTooLarge : a + b; }
    uint64_t of_function(uint32_t f) {
        if (size_[f] == kOnPath) return kTooLarge;  // recursion
        if (size_[f] != kUnknown) return size_[f];
        size_[f] = kOnPath;
        return size_[f] = of(shader_.functions[f].body);
    }
    const ir::Shader& shader_;
    uint64_t control_flow_;
    std::vector<uint64_t> size_;
};

}  // namespace

JitPlan plan_compile(const ir::Shader& shader, bool quick_codegen) {
    ExpandedSize weighted(shader, kControlFlowNodes), plain(shader, 1);
    const uint64_t body = weighted.of(shader.body), prologue = weighted.of(shader.prologue);
    if (body > kMaxExpandedNodes || prologue > kMaxExpandedNodes || body + prologue > kMaxExpandedNodes) return {};
    const double n = double(plain.of(shader.body) + plain.of(shader.prologue));
    const double full = n * kNanosPerInstruction * (1 + n / kInstructionsDoublingCost);
    JitPlan plan;
    plan.quick = quick_codegen || full > double(kCompileBudgetNanos);
    plan.nanos = uint64_t(plan.quick ? full * kQuickCodegenShare : full);
    plan.take = plan.nanos <= kDeclineNanos;
    return plan;
}

}  // namespace glslrun::rt::jit
