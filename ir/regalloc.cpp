// Register allocation by liveness: renumbers the registers so that values
// whose live ranges do not overlap share one register, which keeps the
// interpreter's register file (registers * kLanes words) small enough to stay
// in L1. Runs last; every pass before it may create registers freely.
//
// Registers whose bits must survive as they are keep a register of their own
// ("pinned"): inputs and outputs (the caller fills and reads them), the
// prologue's (written once per draw), indexed ranges and tex blocks (addressed
// by position; whole spans stay contiguous), derivative operands (read across
// lanes), registers that some lane may read before writing them (they see an
// older value: ir/assigned.h) and registers that functions touch (a
// function's own temporaries may still be written unmasked).
//
// The others get live intervals over the main body in program order (a lane
// only moves forward through it, except around loops: a register used in a
// loop and outside it lives through the whole loop), and a linear scan gives
// each a register of its kind that no overlapping interval holds.
//
// The sole write of such a register is marked Instr::unmasked: every lane
// that reads the register runs that write first, and the register's other
// tenants are dead there, so the lanes the mask leaves out hold nothing
// anyone reads and the interpreter may skip the blend.
#include <algorithm>
#include <vector>

#include "ir/assigned.h"
#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

struct Interval {
    uint32_t start = kNone, end = 0;
};

struct Allocator {
    Shader& shader;
    std::vector<bool> pinned;
    std::vector<bool> own;  // a function's temporaries: a register of their own, not pinned
    std::vector<Interval> live;
    uint32_t position = 0;

    void pin_span(uint64_t first, uint64_t count) {
        for (uint64_t r = first; r < first + count && r < pinned.size(); ++r) pinned[r] = true;
    }

    void pin_block(const Block& block) {
        flow::walk(block, [&](const Node& n) {
            if (n.kind != NodeKind::Instr) return;
            const Instr& in = n.instr;
            if ((flow::reads_range(in.op) || flow::writes_range(in.op)) && in.imm[1] > 0)
                pin_span(in.imm[0], uint64_t(in.imm[1] - 1) * in.imm[2] + 1);
            if (flow::texture(in.op)) {
                pin_span(in.imm[0], in.imm[1]);
                pin_span(in.dst, kTexResults);
            }
            if (has(in.op, OpProp::CrossLane)) pin_span(in.src[0], 1);
        });
    }

    void pin_all() {
        std::vector<bool> unset = maybe_read_unset(shader);
        for (size_t r = 0; r < pinned.size(); ++r) pinned[r] = unset[r];
        for (const auto* list : {&shader.inputs, &shader.outputs})
            for (const Binding& b : *list) pin_span(b.first, b.count);
        auto pin_refs = [&](const Node& n) {
            flow::for_each_read(n, [&](Reg r) { pin_span(r, 1); });
            if (n.kind == NodeKind::Instr) flow::for_each_write(n.instr, [&](Reg r) { pin_span(r, 1); });
        };
        flow::walk(shader.prologue, pin_refs);
        pin_block(shader.body);
        // Registers that functions touch have no interval over the main body:
        // they keep a register of their own. Those that one function alone
        // touches are that function's temporaries, which it may write unmasked
        // as the main body's (its reads follow its writes in each call); the
        // others (parameters, results, globals) keep their blends too.
        std::vector<int32_t> owner(pinned.size(), -1);
        auto claim = [&](Reg r, int32_t unit) {
            if (r < owner.size()) owner[r] = owner[r] == -1 || owner[r] == unit ? unit : -2;
        };
        auto claim_block = [&](const Block& b, int32_t unit) {
            flow::walk(b, [&](const Node& n) {
                flow::for_each_read(n, [&](Reg r) { claim(r, unit); });
                if (n.kind == NodeKind::Instr) flow::for_each_write(n.instr, [&](Reg r) { claim(r, unit); });
            });
        };
        claim_block(shader.body, 0);
        for (size_t f = 0; f < shader.functions.size(); ++f) {
            pin_block(shader.functions[f].body);
            claim_block(shader.functions[f].body, int32_t(f) + 1);
        }
        for (size_t r = 0; r < owner.size(); ++r) {
            if (owner[r] == -2) pinned[r] = true;
            if (owner[r] > 0) own[r] = true;
        }
    }

    void touch(Reg r) {
        if (r >= live.size()) return;
        live[r].start = std::min(live[r].start, position);
        live[r].end = std::max(live[r].end, position);
    }

    // Numbers the nodes in pre-order; a loop stretches the intervals that
    // reach into it from outside over all of it.
    void intervals(const Block& block) {
        for (const Node& n : block) {
            ++position;
            flow::for_each_read(n, [&](Reg r) { touch(r); });
            if (n.kind == NodeKind::Instr) flow::for_each_write(n.instr, [&](Reg r) { touch(r); });
            uint32_t first = position;
            intervals(n.body);
            intervals(n.alt);
            if (n.kind == NodeKind::Loop) stretch(first, position);
        }
    }

    void stretch(uint32_t first, uint32_t last) {
        for (Interval& i : live) {
            bool inside = i.start != kNone && i.end >= first && i.start <= last;
            if (inside && (i.start < first || i.end > last)) {
                i.start = std::min(i.start, first);
                i.end = std::max(i.end, last);
            }
        }
    }

    // The new number of every register (kNone: never referenced).
    std::vector<Reg> assign(std::vector<Kind>& kinds) {
        std::vector<Reg> map(shader.regs.size(), kNone);
        for (size_t r = 0; r < map.size(); ++r)
            if (pinned[r] || own[r]) {
                map[r] = Reg(kinds.size());
                kinds.push_back(shader.regs[r]);
            }
        std::vector<Reg> order;
        for (size_t r = 0; r < map.size(); ++r)
            if (!pinned[r] && !own[r] && live[r].start != kNone) order.push_back(Reg(r));
        std::stable_sort(order.begin(), order.end(), [&](Reg a, Reg b) { return live[a].start < live[b].start; });
        // Per new register: the end of the interval it holds now.
        std::vector<uint32_t> busy_until;
        std::vector<Reg> shared;
        for (Reg r : order) {
            Reg slot = kNone;
            for (size_t k = 0; k < shared.size() && slot == kNone; ++k)
                if (kinds[shared[k]] == shader.regs[r] && busy_until[k] < live[r].start) slot = Reg(k);
            if (slot == kNone) {
                slot = Reg(shared.size());
                shared.push_back(Reg(kinds.size()));
                busy_until.push_back(0);
                kinds.push_back(shader.regs[r]);
            }
            busy_until[slot] = live[r].end;
            map[r] = shared[slot];
        }
        return map;
    }
};

// Marks the instructions that are the only write of a register that is not pinned.
void mark_unmasked(Block& block, const std::vector<bool>& pinned, const std::vector<uint32_t>& writes) {
    for (Node& n : block) {
        if (n.kind == NodeKind::Instr) {
            Reg d = n.instr.dst;
            n.instr.unmasked = d < pinned.size() && !pinned[d] && writes[d] == 1 && flow::writes_dst_only(n.instr);
        }
        mark_unmasked(n.body, pinned, writes);
        mark_unmasked(n.alt, pinned, writes);
    }
}

std::vector<uint32_t> count_writes(const Shader& shader) {
    std::vector<uint32_t> writes(shader.regs.size(), 0);
    auto count = [&](const Node& n) {
        if (n.kind == NodeKind::Instr)
            flow::for_each_write(n.instr, [&](Reg r) {
                if (r < writes.size()) ++writes[r];
            });
    };
    flow::walk(shader.prologue, count);
    flow::walk(shader.body, count);
    for (const Function& f : shader.functions) flow::walk(f.body, count);
    return writes;
}

void rename(Block& block, const std::vector<Reg>& map) {
    auto re = [&](Reg& r) {
        if (r != kNoReg && r < map.size()) r = map[r];
    };
    for (Node& n : block) {
        if (n.kind == NodeKind::If) re(n.cond);
        if (n.kind == NodeKind::Instr) {
            Instr& in = n.instr;
            re(in.dst);
            for (int k = 0; k < op_info(in.op).arity; ++k) re(in.src[k]);
            // Pinned spans keep their layout, so renaming the base renames the span.
            if (flow::reads_range(in.op) || flow::writes_range(in.op) || flow::texture(in.op)) re(in.imm[0]);
        }
        rename(n.body, map);
        rename(n.alt, map);
    }
}

}  // namespace

void allocate_registers(Shader& shader) {
    size_t regs = shader.regs.size();
    Allocator a{shader, std::vector<bool>(regs, false), std::vector<bool>(regs, false), std::vector<Interval>(regs)};
    a.pin_all();
    a.intervals(shader.body);
    std::vector<uint32_t> writes = count_writes(shader);
    mark_unmasked(shader.prologue, a.pinned, writes);
    mark_unmasked(shader.body, a.pinned, writes);
    for (Function& f : shader.functions) mark_unmasked(f.body, a.pinned, writes);
    std::vector<Kind> kinds;
    std::vector<Reg> map = a.assign(kinds);
    rename(shader.prologue, map);
    rename(shader.body, map);
    for (Function& f : shader.functions) rename(f.body, map);
    for (auto* list : {&shader.inputs, &shader.outputs})
        for (Binding& b : *list) b.first = map[b.first];
    shader.regs = std::move(kinds);
    shader.variables.clear();  // their registers are shared now
}

}  // namespace glslrun::ir
