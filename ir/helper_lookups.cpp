// Whether a helper lane's texture lookups can change what a fragment
// computes (Shader::helper_lookups_matter). A helper lane is a partial
// quad's uncovered pixel: it runs only so that its quad has derivatives,
// and writes nothing. Its lookups are therefore read only through a
// derivative (ddx, ddy: dFdx, dFdy, fwidth and the derivatives of an
// implicit-LOD lookup's coordinates) of a value computed from one, or
// through control flow that depends on one (a branch, and so a loop's
// break or a discard: the loop cap counts a whole batch's iterations).
// Flow-insensitive and conservative: a register that any lookup reaches,
// anywhere, counts as reached everywhere.
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

namespace glslrun::ir {

namespace {

struct Reached {
    std::vector<bool> regs;
    bool changed = false;

    bool has(Reg r) const { return r != kNoReg && r < regs.size() && regs[r]; }
    void add(Reg r) {
        if (r == kNoReg || r >= regs.size() || regs[r]) return;
        regs[r] = true;
        changed = true;
    }
};

// One sweep: a lookup's results, and what an instruction reading a reached
// register writes, are reached.
void sweep(const Block& block, Reached& reached) {
    for (const Node& n : block) {
        if (n.kind == NodeKind::Instr) {
            bool reads = flow::texture(n.instr.op);
            flow::for_each_read(n, [&](Reg r) { reads = reads || reached.has(r); });
            if (reads) flow::for_each_write(n.instr, [&](Reg r) { reached.add(r); });
        }
        sweep(n.body, reached);
        sweep(n.alt, reached);
    }
}

// A branch on a reached register, or a derivative of one.
bool read_across_lanes(const Block& block, const Reached& reached) {
    for (const Node& n : block) {
        if (n.kind == NodeKind::If && reached.has(n.cond)) return true;
        const bool derivative = n.kind == NodeKind::Instr && has(n.instr.op, OpProp::CrossLane);
        if (derivative && reached.has(n.instr.src[0])) return true;
        if (read_across_lanes(n.body, reached) || read_across_lanes(n.alt, reached)) return true;
    }
    return false;
}

}  // namespace

bool helper_lookups_matter(const Shader& shader) {
    Reached reached{std::vector<bool>(shader.regs.size(), false)};
    do {
        reached.changed = false;
        sweep(shader.prologue, reached);
        sweep(shader.body, reached);
        for (const Function& f : shader.functions) sweep(f.body, reached);
    } while (reached.changed);
    if (read_across_lanes(shader.prologue, reached) || read_across_lanes(shader.body, reached)) return true;
    for (const Function& f : shader.functions)
        if (read_across_lanes(f.body, reached)) return true;
    return false;
}

}  // namespace glslrun::ir
