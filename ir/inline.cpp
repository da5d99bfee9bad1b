// Inlining: a Call becomes a Scope holding a copy of the callee's body, so
// Return keeps its meaning. Callees are processed before their callers
// (innermost calls first) and inlining stops when the shader would grow by
// the budget: piglit's inline-explosion tests have 2^64 call paths. Large
// functions that main reaches more than once stay calls (kMinCalledNodes).
//
// Functions have static frames: parameters and return values are registers
// that the caller writes and reads around the call, so they are shared by
// every copy. A callee's private temporaries (registers referenced by no other
// function, no binding, no indexed range, and written before they are read)
// get fresh registers in each copy, so copies do not alias each other.
#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

constexpr int32_t kNoOwner = -1, kShared = -2;
// A function of at least this many nodes (its own calls inlined) that main
// reaches by two call paths or more stays a call: the JIT compiles it once,
// as a function of its own (runtime/jit/control.cpp), instead of once per
// copy. Measured on bench/corpus (docs/performance.md): wood's value_noise
// (about 270 nodes, 3 calls) and the ray tracer's trace (about 200, 2 call
// sites in loops) halve their fragment shaders' LLVM time and draw as fast
// or faster (fewer spills); at 100 or 60 nodes, smaller callees left as
// calls (marble's gradient, the ray tracer's intersect_sphere, which keeps
// its loop from being unrolled) made frames up to twice as slow.
constexpr uint64_t kMinCalledNodes = 150;

struct Inliner {
    Shader& shader;
    uint64_t budget;
    uint64_t added = 0;
    std::vector<int32_t> owner{};                    // per register: the one function referencing it
    std::vector<std::unordered_set<Reg>> private_{}; // per function: registers renamed in copies
    enum class State : uint8_t { Unvisited, InProgress, Done };
    std::vector<State> state{};
    std::vector<uint64_t> paths{};  // per function: the copies inlining every call would make

    uint32_t main_index() const { return uint32_t(shader.functions.size()); }

    void claim(Reg r, int32_t fn) {
        if (r >= owner.size()) return;
        if (owner[r] == kNoOwner) owner[r] = fn;
        else if (owner[r] != fn) owner[r] = kShared;
    }

    void compute_owners() {
        owner.assign(shader.regs.size(), kNoOwner);
        auto claim_block = [&](const Block& b, int32_t fn) {
            flow::walk(b, [&](const Node& n) {
                flow::for_each_read(n, [&](Reg r) { claim(r, fn); });
                if (n.kind == NodeKind::Instr) {
                    flow::for_each_write(n.instr, [&](Reg r) { claim(r, fn); });
                    if (flow::reads_range(n.instr.op) || flow::writes_range(n.instr.op))
                        flow::for_each_in_range(n.instr, [&](Reg r) { claim(r, kShared); });
                    if (flow::texture(n.instr.op)) {
                        flow::for_each_tex_operand(n.instr, [&](Reg r) { claim(r, kShared); });
                        flow::for_each_tex_result(n.instr, [&](Reg r) { claim(r, kShared); });
                    }
                }
            });
        };
        for (size_t f = 0; f < shader.functions.size(); ++f) claim_block(shader.functions[f].body, int32_t(f));
        claim_block(shader.body, int32_t(main_index()));
        for (const auto* list : {&shader.inputs, &shader.outputs})
            for (const Binding& b : *list)
                for (uint32_t i = 0; i < b.count; ++i) claim(b.first + i, kShared);
    }

    // Registers only `fn` references whose first reference is a write: a
    // read before any write could observe the previous call's value.
    std::unordered_set<Reg> private_registers(uint32_t fn) const {
        std::unordered_set<Reg> result, seen;
        flow::walk(shader.functions[fn].body, [&](const Node& n) {
            flow::for_each_read(n, [&](Reg r) { seen.insert(r); });
            if (n.kind != NodeKind::Instr) return;
            flow::for_each_write(n.instr, [&](Reg r) {
                if (seen.insert(r).second && r < owner.size() && owner[r] == int32_t(fn)) result.insert(r);
            });
        });
        return result;
    }

    void process_function(uint32_t fn) {
        state[fn] = State::InProgress;
        std::vector<uint32_t> callees;
        flow::walk(shader.functions[fn].body, [&](const Node& n) {
            if (n.kind == NodeKind::Call && n.callee < shader.functions.size()) callees.push_back(n.callee);
        });
        for (uint32_t c : callees)
            if (state[c] == State::Unvisited) process_function(c);
        private_[fn] = private_registers(fn);
        inline_calls_in(shader.functions[fn].body, fn);
        state[fn] = State::Done;
    }

    // Copies `block` renaming the callee's private registers; fresh registers
    // become private to `into` (the function receiving the copy).
    Block copy_renamed(const Block& block, uint32_t callee, uint32_t into, std::unordered_map<Reg, Reg>& renamed) {
        auto rename = [&](Reg r) -> Reg {
            if (r == kNoReg || !private_[callee].count(r)) return r;
            auto it = renamed.find(r);
            if (it != renamed.end()) return it->second;
            Reg fresh = Reg(shader.regs.size());
            shader.regs.push_back(shader.regs[r]);
            renamed.emplace(r, fresh);
            if (into < private_.size()) private_[into].insert(fresh);
            return fresh;
        };
        Block out = block;
        std::vector<Block*> pending{&out};
        while (!pending.empty()) {
            Block* b = pending.back();
            pending.pop_back();
            for (Node& n : *b) {
                if (n.kind == NodeKind::If) n.cond = rename(n.cond);
                if (n.kind == NodeKind::Instr) {
                    n.instr.dst = rename(n.instr.dst);
                    for (Reg& s : n.instr.src) s = rename(s);
                }
                pending.push_back(&n.body);
                pending.push_back(&n.alt);
            }
        }
        return out;
    }

    void inline_calls_in(Block& block, uint32_t into) {
        for (Node& n : block) {
            if (n.kind != NodeKind::Call) {
                inline_calls_in(n.body, into);
                inline_calls_in(n.alt, into);
                continue;
            }
            if (n.callee >= shader.functions.size() || state[n.callee] != State::Done) continue;
            uint64_t cost = flow::node_count(shader.functions[n.callee].body);
            if (paths[n.callee] >= 2 && cost >= kMinCalledNodes) continue;
            if (added + cost >= budget) continue;
            added += cost;
            std::unordered_map<Reg, Reg> renamed;
            Block copy = copy_renamed(shader.functions[n.callee].body, n.callee, into, renamed);
            n.kind = NodeKind::Scope;
            n.body = std::move(copy);
            n.callee = 0;
        }
    }

    // The call paths from main to each function (saturating): how many
    // copies of its body inlining every call would make.
    void count_paths() {
        const uint32_t n = main_index();
        std::vector<std::vector<uint32_t>> sites(n + 1);
        auto list = [&](const Block& b, std::vector<uint32_t>& out) {
            flow::walk(b, [&](const Node& node) {
                if (node.kind == NodeKind::Call && node.callee < n) out.push_back(node.callee);
            });
        };
        for (uint32_t f = 0; f < n; ++f) list(shader.functions[f].body, sites[f]);
        list(shader.body, sites[n]);
        std::vector<uint32_t> order;  // post-order from main: callees before callers
        std::vector<uint8_t> seen(n + 1, 0);
        auto visit = [&](auto&& self, uint32_t f) -> void {
            seen[f] = 1;
            for (uint32_t c : sites[f])
                if (!seen[c]) self(self, c);
            order.push_back(f);
        };
        visit(visit, n);
        paths.assign(n + 1, 0);
        paths[n] = 1;
        for (auto it = order.rbegin(); it != order.rend(); ++it)
            for (uint32_t c : sites[*it]) paths[c] = std::min<uint64_t>(paths[c] + paths[*it], UINT32_MAX);
    }

    void run() {
        count_paths();
        compute_owners();
        private_.assign(shader.functions.size(), {});
        state.assign(shader.functions.size(), State::Unvisited);
        std::vector<uint32_t> roots;
        flow::walk(shader.body, [&](const Node& n) {
            if (n.kind == NodeKind::Call && n.callee < shader.functions.size()) roots.push_back(n.callee);
        });
        for (uint32_t c : roots)
            if (state[c] == State::Unvisited) process_function(c);
        inline_calls_in(shader.body, main_index());
        remove_uncalled_functions();
    }

    void remove_uncalled_functions() {
        std::vector<bool> called(shader.functions.size(), false);
        std::vector<const Block*> pending{&shader.body};
        while (!pending.empty()) {
            const Block* b = pending.back();
            pending.pop_back();
            flow::walk(*b, [&](const Node& n) {
                if (n.kind == NodeKind::Call && n.callee < called.size() && !called[n.callee]) {
                    called[n.callee] = true;
                    pending.push_back(&shader.functions[n.callee].body);
                }
            });
        }
        std::vector<uint32_t> new_index(shader.functions.size(), 0);
        std::vector<Function> kept;
        for (size_t f = 0; f < shader.functions.size(); ++f)
            if (called[f]) {
                new_index[f] = uint32_t(kept.size());
                kept.push_back(std::move(shader.functions[f]));
            }
        shader.functions = std::move(kept);
        auto remap = [&](Block& b) {
            std::vector<Block*> todo{&b};
            while (!todo.empty()) {
                Block* cur = todo.back();
                todo.pop_back();
                for (Node& n : *cur) {
                    if (n.kind == NodeKind::Call && n.callee < new_index.size()) n.callee = new_index[n.callee];
                    todo.push_back(&n.body);
                    todo.push_back(&n.alt);
                }
            }
        };
        remap(shader.body);
        for (Function& f : shader.functions) remap(f.body);
    }
};

}  // namespace

void inline_calls(Shader& shader, uint32_t budget) {
    Inliner inliner{shader, budget};
    inliner.run();
}

}  // namespace glslrun::ir
