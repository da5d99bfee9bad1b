// Loop unrolling: a loop that runs a small constant number of times (a loop
// over lights, `for (int i = 0; i < 3; ++i)`) becomes that many copies of
// its body, so that fold sees the counter as a constant in each copy:
// indexed uniform reads become direct ones, tests on the counter fold away.
//
// The loop must have the frontend's shape: straight-line instructions, then
// `if c { break }`, then the rest of the body, and a continue block of
// straight-line instructions; no other break or continue of this loop. Its
// trip count is found by running the header and the continue block on the
// constants known before the loop (as fold knows them); the rest of the body
// must not change what they read. Each iteration becomes
// header, rest of body, continue block, and the exit's header follows, so
// every register ends with the value it had when the loop exited. The masks
// are unchanged: without break or continue every iteration runs with the
// loop's entry lanes. Only the iteration cap (RunLimits::max_loop_iterations)
// counts fewer iterations: these loops cannot run away.
//
// Temporaries get fresh registers in each copy after the first, so that the
// passes that want a register written once (sqrt_divisor) still see one
// write: a register written by one instruction in the whole shader, at the
// top level of some block of the body, and read only after it in that block.
// Every lane that reads it there wrote it in the same iteration, so the
// copies need not share it. Registers addressed by position (inputs,
// outputs, indexed ranges, tex blocks) keep their numbers.
#include <algorithm>
#include <optional>
#include <unordered_map>
#include <vector>

#include "ir/alu_eval.h"
#include "ir/flow.h"
#include "ir/passes.h"
#include "ir/scoped_facts.h"

namespace glslrun::ir {
namespace {

constexpr uint32_t kMaxTrips = 8;
constexpr size_t kMaxAddedNodes = 2000;  // per shader, nested loops included

// Known constants, scoped as fold's are (ir/scoped_facts.h).
using Facts = RegisterFacts<uint32_t>;

// Runs one instruction on the known constants, as fold evaluates it.
void evaluate(const Instr& in, Facts& facts) {
    bool have = false;
    uint32_t value = 0;
    if (in.op == Op::konst) {
        have = true, value = in.imm[0];
    } else if (in.op == Op::mov) {
        if (const uint32_t* known = facts.find(in.src[0])) have = true, value = *known;
    } else if (alu::is_alu(in.op)) {
        uint32_t v[3] = {0, 0, 0};
        have = true;
        for (int k = 0; k < op_info(in.op).arity && have; ++k) {
            const uint32_t* known = facts.find(in.src[k]);
            have = known != nullptr;
            if (have) v[k] = *known;
        }
        if (have) value = alu::eval(in.op, v[0], v[1], v[2]);
    }
    flow::for_each_write(in, [&](Reg r) {
        if (have && r == in.dst) facts.write(r, value);
        else facts.write(r);
    });
}

// Writes and reads of every register in the whole shader, and the
// registers that must keep their numbers.
struct Uses {
    std::vector<uint32_t> writes, reads;
    std::vector<bool> pinned;

    explicit Uses(const Shader& shader)
        : writes(shader.regs.size()), reads(shader.regs.size()), pinned(shader.regs.size()) {
        auto visit = [&](const Node& n) {
            flow::for_each_read(n, [&](Reg r) { count(reads, r); });
            if (n.kind != NodeKind::Instr) return;
            flow::for_each_write(n.instr, [&](Reg r) { count(writes, r); });
            const Instr& in = n.instr;
            if (flow::reads_range(in.op) || flow::writes_range(in.op)) flow::for_each_in_range(in, [&](Reg r) { pin(r); });
            if (flow::texture(in.op)) {
                flow::for_each_tex_operand(in, [&](Reg r) { pin(r); });
                flow::for_each_tex_result(in, [&](Reg r) { pin(r); });
            }
        };
        for (const Block* b : {&shader.prologue, &shader.body}) flow::walk(*b, visit);
        for (const Function& f : shader.functions) flow::walk(f.body, visit);
        for (const auto* list : {&shader.inputs, &shader.outputs})
            for (const Binding& b : *list)
                for (uint32_t i = 0; i < b.count; ++i) pin(b.first + i);
    }
    void count(std::vector<uint32_t>& v, Reg r) {
        if (r < v.size()) ++v[r];
    }
    void pin(Reg r) {
        if (r < pinned.size()) pinned[r] = true;
    }
};

// The temporaries of `block` and its nested blocks (see the file comment).
void find_temporaries(const Block& block, const Uses& uses, std::vector<Reg>& out) {
    for (size_t i = 0; i < block.size(); ++i) {
        const Node& n = block[i];
        find_temporaries(n.body, uses, out);
        find_temporaries(n.alt, uses, out);
        const Reg r = n.kind == NodeKind::Instr ? n.instr.dst : kNoReg;
        if (r >= uses.writes.size() || uses.pinned[r] || uses.writes[r] != 1) continue;
        uint32_t later_reads = 0;
        auto count = [&](const Node& m) { flow::for_each_read(m, [&](Reg read) { later_reads += read == r; }); };
        for (size_t j = i + 1; j < block.size(); ++j) {
            count(block[j]);
            flow::walk(block[j].body, count);
            flow::walk(block[j].alt, count);
        }
        if (later_reads == uses.reads[r]) out.push_back(r);
    }
}

void rename(Block& block, const std::unordered_map<Reg, Reg>& to) {
    auto renamed = [&](Reg& r) {
        auto it = to.find(r);
        if (it != to.end()) r = it->second;
    };
    for (Node& n : block) {
        rename(n.body, to);
        rename(n.alt, to);
        renamed(n.cond);
        if (n.kind != NodeKind::Instr) continue;
        renamed(n.instr.dst);
        for (int k = 0; k < op_info(n.instr.op).arity; ++k) renamed(n.instr.src[k]);
    }
}

void forget(Facts& facts, const Block& block) { facts.forget(flow::writes_of(block)); }

// The number of trips `loop` makes from `facts` (which it leaves as it found
// them), or nothing.
std::optional<uint32_t> trip_count(const Node& loop, size_t exit, const Block& rest, Facts& facts) {
    const Block& body = loop.body;
    const Node& test = body[exit];
    size_t before = facts.mark();
    BlockWrites ignored;
    std::optional<uint32_t> trips = 0;
    for (;;) {
        for (size_t i = 0; i < exit; ++i) evaluate(body[i].instr, facts);
        const uint32_t* cond = facts.find(test.cond);
        if (cond && *cond != 0) break;
        if (!cond || ++*trips > kMaxTrips) {
            trips.reset();
            break;
        }
        forget(facts, rest);
        for (const Node& n : loop.alt) evaluate(n.instr, facts);
    }
    facts.undo(before, ignored);
    return trips;
}

bool straight_line(const Block& block) {
    return std::all_of(block.begin(), block.end(), [](const Node& n) { return n.kind == NodeKind::Instr; });
}

// A break or continue of this loop (not of a loop nested in it).
bool leaves_loop(const Block& block) {
    for (const Node& n : block) {
        if (n.kind == NodeKind::Break || n.kind == NodeKind::Continue) return true;
        if (n.kind != NodeKind::Loop && (leaves_loop(n.body) || leaves_loop(n.alt))) return true;
    }
    return false;
}

size_t node_count(const Block& block) {
    size_t n = 0;
    flow::walk(block, [&](const Node&) { ++n; });
    return n;
}

// The unrolled copy of `loop`, or nothing when it does not qualify.
std::optional<Block> unrolled(Shader& shader, const Node& loop, Facts& facts, size_t& budget) {
    const Block& body = loop.body;
    size_t exit = 0;
    while (exit < body.size() && body[exit].kind == NodeKind::Instr) ++exit;
    if (exit == body.size()) return std::nullopt;
    const Node& test = body[exit];
    if (test.kind != NodeKind::If || test.body.size() != 1 || test.body[0].kind != NodeKind::Break ||
        !test.alt.empty())
        return std::nullopt;
    const Block rest(body.begin() + std::ptrdiff_t(exit) + 1, body.end());
    if (!straight_line(loop.alt) || leaves_loop(rest)) return std::nullopt;
    if (flow::writes_of(rest).calls) return std::nullopt;

    std::optional<uint32_t> counted = trip_count(loop, exit, rest, facts);
    if (!counted) return std::nullopt;
    uint32_t trips = *counted;
    const Block header(body.begin(), body.begin() + std::ptrdiff_t(exit));
    const size_t added = trips * (node_count(rest) + header.size() + loop.alt.size());
    if (added > budget) return std::nullopt;
    budget -= added;
    std::vector<Reg> temporaries;
    find_temporaries(rest, Uses(shader), temporaries);
    Block out;
    for (uint32_t t = 0; t < trips; ++t) {
        Block copy = rest;
        if (t > 0) {
            std::unordered_map<Reg, Reg> fresh;
            for (Reg r : temporaries) {
                fresh[r] = Reg(shader.regs.size());
                shader.regs.push_back(shader.regs[r]);
            }
            rename(copy, fresh);
        }
        out.insert(out.end(), header.begin(), header.end());
        out.insert(out.end(), std::make_move_iterator(copy.begin()), std::make_move_iterator(copy.end()));
        out.insert(out.end(), loop.alt.begin(), loop.alt.end());
    }
    out.insert(out.end(), header.begin(), header.end());
    return out;
}

void run_block(Shader& shader, Block& block, Facts& facts, size_t& budget) {
    for (size_t i = 0; i < block.size();) {
        Node& n = block[i];
        switch (n.kind) {
        case NodeKind::Instr: evaluate(n.instr, facts); break;
        case NodeKind::Loop:
            // Past kMaxListedLoopDepth the facts are forgotten at every loop.
            if (std::optional<Block> copy = facts.loop_depth() < kMaxListedLoopDepth
                                                ? unrolled(shader, n, facts, budget)
                                                : std::nullopt) {
                block.erase(block.begin() + std::ptrdiff_t(i));
                block.insert(block.begin() + std::ptrdiff_t(i), std::make_move_iterator(copy->begin()),
                             std::make_move_iterator(copy->end()));
                continue;  // the copies are visited next (nested loops, facts)
            }
            facts.enter_loop(n);
            for (Block* inner : {&n.body, &n.alt}) {
                size_t before = facts.mark();
                BlockWrites ignored;  // already forgotten
                run_block(shader, *inner, facts, budget);
                facts.undo(before, ignored);
            }
            facts.leave_loop();
            break;
        case NodeKind::If: case NodeKind::Scope: {
            size_t before = facts.mark();
            BlockWrites written;
            for (Block* inner : {&n.body, &n.alt}) {
                run_block(shader, *inner, facts, budget);
                facts.undo(before, written);
            }
            facts.forget(written);
            break;
        }
        case NodeKind::Call: facts.forget_all(); break;
        default: break;
        }
        ++i;
    }
}

}  // namespace

void unroll_loops(Shader& shader) {
    FlushDenormals ftz;  // evaluate() computes as fold does
    size_t budget = kMaxAddedNodes;
    Facts facts(shader.regs.size());
    for (Function& f : shader.functions) {
        run_block(shader, f.body, facts, budget);
        facts.restart();
    }
    run_block(shader, shader.body, facts, budget);
}

}  // namespace glslrun::ir
