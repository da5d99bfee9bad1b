// Copy propagation, with local common-subexpression elimination: after
// `mov d, s`, reads of d become reads of s until either is written again; an
// instruction recomputing a value that a register still holds (same op,
// operands and immediates) becomes a `mov` from that register, so later
// reads are forwarded too. Same conservativeness as the folder: facts flow
// through straight-line code, nested blocks start from their parent's facts,
// and joins forget every register the nested block may write (store_ind: its
// whole range), in time linear in the IR (ir/scoped_facts.h).
#include <algorithm>
#include <unordered_map>
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"
#include "ir/scoped_facts.h"

namespace glslrun::ir {
namespace {

// What an instruction computes, independently of where it writes.
struct Expr {
    Op op;
    Kind type;
    Reg src[3];
    uint32_t imm[3];
    bool operator==(const Expr& o) const {
        return op == o.op && type == o.type && std::equal(src, src + 3, o.src) && std::equal(imm, imm + 3, o.imm);
    }
};
struct ExprHash {
    size_t operator()(const Expr& e) const {
        uint64_t h = uint64_t(e.op) * 31 + uint64_t(e.type);
        for (int k = 0; k < 3; ++k) h = (h ^ e.src[k]) * 0x9E3779B97F4A7C15ull + e.imm[k];
        return size_t(h ^ (h >> 29));
    }
};

// Pure functions of their operands (and of the uniform store, fixed during
// a run); a mov is a copy, followed as such.
bool reusable(Op op) { return has(op, OpProp::Pure) && op != Op::mov; }

Expr expr_of(const Instr& in) {
    Expr e{in.op, in.type, {in.src[0], in.src[1], in.src[2]}, {in.imm[0], in.imm[1], in.imm[2]}};
    if (has(in.op, OpProp::Commutative) && e.src[1] < e.src[0]) std::swap(e.src[0], e.src[1]);
    return e;
}

// Copies (d holds the value of `src`) per destination, and the register
// holding each expression, checked against the versions of the registers
// they mention (ir/scoped_facts.h).
struct Copy {
    Reg src;
    uint64_t src_version;
};
struct Holder {
    Reg reg;
    uint64_t version;
    uint64_t src_versions[3];
};

struct Facts {
    RegisterFacts<Copy> regs;
    UndoMap<Expr, Holder, ExprHash> holders;

    explicit Facts(size_t n) : regs(n) {}

    Reg resolve(Reg r) const {
        const Copy* c = regs.find(r);
        return c && regs.version(c->src) == c->src_version ? c->src : r;
    }
    const Holder* holder(const Expr& e) const {
        const Holder* h = holders.find(e);
        if (!h || !regs.current(h->reg, h->version)) return nullptr;
        for (int k = 0; k < 3; ++k)
            if (e.src[k] != kNoReg && regs.version(e.src[k]) != h->src_versions[k]) return nullptr;
        return h;
    }
    void add_expr(const Expr& e, Reg d) {
        regs.reference(d);
        for (Reg r : e.src)
            if (r != kNoReg) regs.reference(r);
        Holder h{d, regs.version(d), {0, 0, 0}};
        for (int k = 0; k < 3; ++k) h.src_versions[k] = e.src[k] == kNoReg ? 0 : regs.version(e.src[k]);
        holders.set(e, h);
    }

    void restart() {
        regs.restart();
        holders.clear();
    }

    struct Mark {
        size_t regs, holders;
    };
    Mark mark() const { return {regs.mark(), holders.mark()}; }
    void undo(Mark m, BlockWrites& out) {
        regs.undo(m.regs, out);
        holders.undo(m.holders);
    }
};

void make_mov(Instr& in, Reg src) {
    in.op = Op::mov;
    in.src[0] = src;
    in.src[1] = in.src[2] = kNoReg;
    in.imm[0] = in.imm[1] = in.imm[2] = 0;
}

void instr(Instr& in, Facts& facts) {
    int arity = op_info(in.op).arity;
    for (int k = 0; k < arity; ++k)
        if (in.src[k] != kNoReg) in.src[k] = facts.resolve(in.src[k]);
    bool pure = in.dst != kNoReg && reusable(in.op);
    Expr e{};
    if (pure) {
        e = expr_of(in);
        if (const Holder* h = facts.holder(e); h && h->reg != in.dst) {
            make_mov(in, h->reg);
            pure = false;
        }
    }
    bool copy = in.op == Op::mov && in.src[0] != in.dst;
    flow::for_each_write(in, [&](Reg r) {
        if (copy && r == in.dst) {
            facts.regs.reference(in.src[0]);
            facts.regs.write(r, Copy{in.src[0], facts.regs.version(in.src[0])});
        }
        else {
            facts.regs.write(r);
        }
    });
    if (!copy && pure && std::find(e.src, e.src + 3, in.dst) == e.src + 3) {
        facts.add_expr(e, in.dst);
    }
}

void run_block(Block& block, Facts& facts) {
    for (Node& n : block) {
        switch (n.kind) {
        case NodeKind::Instr: instr(n.instr, facts); break;
        case NodeKind::If: {
            n.cond = facts.resolve(n.cond);
            Facts::Mark before = facts.mark();
            BlockWrites written;
            run_block(n.body, facts);
            facts.undo(before, written);
            run_block(n.alt, facts);
            facts.undo(before, written);
            facts.regs.forget(written);
            break;
        }
        case NodeKind::Loop: {
            facts.regs.enter_loop(n);
            Facts::Mark before = facts.mark();
            BlockWrites ignored;  // already forgotten
            run_block(n.body, facts);
            facts.undo(before, ignored);
            run_block(n.alt, facts);
            facts.undo(before, ignored);
            facts.regs.leave_loop();
            break;
        }
        case NodeKind::Scope:
            if (flow::returns_early(n.body)) {
                Facts::Mark before = facts.mark();
                BlockWrites written;
                run_block(n.body, facts);
                facts.undo(before, written);
                facts.regs.forget(written);
            } else {
                run_block(n.body, facts);
            }
            break;
        case NodeKind::Call: facts.regs.forget_all(); break;
        default: break;
        }
    }
}

}  // namespace

void propagate_copies(Shader& shader) {
    Facts facts(shader.regs.size());
    for (Function& f : shader.functions) {
        run_block(f.body, facts);
        facts.restart();
    }
    run_block(shader.body, facts);
}

}  // namespace glslrun::ir
