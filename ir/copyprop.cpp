// Copy propagation, with local common-subexpression elimination: after
// `mov d, s`, reads of d become reads of s until either is written again; an
// instruction recomputing a value that a register still holds (same op,
// operands and immediates) becomes a `mov` from that register, so later
// reads are forwarded too. Same conservativeness as the folder: facts flow
// through straight-line code, nested blocks see a copy, and joins forget
// every register the nested block may write (store_ind: its whole range).
#include <algorithm>
#include <unordered_map>
#include <vector>

#include "ir/flow.h"
#include "ir/passes.h"

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

bool commutative(Op op) {
    switch (op) {
    case Op::fadd: case Op::fmul: case Op::iadd: case Op::imul: case Op::feq: case Op::fne:
    case Op::ieq: case Op::ine: case Op::beq: case Op::bne: case Op::band: case Op::bor: case Op::bxor:
        return true;
    default: return false;
    }
}

// Pure functions of their operands (and of the uniform store, fixed during a run).
bool reusable(Op op) {
    if (op_info(op).kind == OpKind::Alu) return true;
    return op == Op::konst || op == Op::sel || op == Op::uniform || op == Op::uniform_ind || op == Op::ddx ||
           op == Op::ddy;
}

Expr expr_of(const Instr& in) {
    Expr e{in.op, in.type, {in.src[0], in.src[1], in.src[2]}, {in.imm[0], in.imm[1], in.imm[2]}};
    if (commutative(in.op) && e.src[1] < e.src[0]) std::swap(e.src[0], e.src[1]);
    return e;
}

struct Facts {
    std::unordered_map<Reg, Reg> copy_of;  // d holds the same value as s
    std::unordered_map<Expr, Reg, ExprHash> holder;  // a register holding the expression
    // Reverse index: facts to forget when a register changes (may hold stale entries).
    std::unordered_map<Reg, std::vector<Reg>> copies_from;
    std::unordered_map<Reg, std::vector<Expr>> exprs_using;

    Reg resolve(Reg r) const {
        auto it = copy_of.find(r);
        return it == copy_of.end() ? r : it->second;
    }
    void clear() { *this = Facts{}; }

    void kill(Reg r) {
        copy_of.erase(r);
        if (auto it = copies_from.find(r); it != copies_from.end()) {
            for (Reg d : it->second)
                if (auto c = copy_of.find(d); c != copy_of.end() && c->second == r) copy_of.erase(c);
            copies_from.erase(it);
        }
        if (auto it = exprs_using.find(r); it != exprs_using.end()) {
            for (const Expr& e : it->second) holder.erase(e);
            exprs_using.erase(it);
        }
    }
    void kill(const flow::Writes& writes) {
        if (writes.calls) return clear();
        for (Reg r : writes.regs) kill(r);
    }

    void add_copy(Reg d, Reg s) {
        copy_of[d] = s;
        copies_from[s].push_back(d);
    }
    void add_expr(const Expr& e, Reg d) {
        holder[e] = d;
        exprs_using[d].push_back(e);
        int arity = op_info(e.op).arity;
        for (int k = 0; k < arity; ++k)
            if (e.src[k] != kNoReg) exprs_using[e.src[k]].push_back(e);
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
        if (auto it = facts.holder.find(e); it != facts.holder.end() && it->second != in.dst) {
            make_mov(in, it->second);
            pure = false;
        }
    }
    flow::for_each_write(in, [&](Reg r) { facts.kill(r); });
    if (in.op == Op::mov && in.src[0] != in.dst) {
        facts.add_copy(in.dst, in.src[0]);
    } else if (pure && std::find(e.src, e.src + 3, in.dst) == e.src + 3) {
        facts.add_expr(e, in.dst);
    }
}

void run_block(Block& block, Facts& facts) {
    for (Node& n : block) {
        switch (n.kind) {
        case NodeKind::Instr: instr(n.instr, facts); break;
        case NodeKind::If: {
            n.cond = facts.resolve(n.cond);
            Facts then_facts = facts, else_facts = facts;
            run_block(n.body, then_facts);
            run_block(n.alt, else_facts);
            facts.kill(flow::writes_of(n.body));
            facts.kill(flow::writes_of(n.alt));
            break;
        }
        case NodeKind::Loop: {
            facts.kill(flow::writes_of(n.body));
            facts.kill(flow::writes_of(n.alt));
            Facts body_facts = facts, cont_facts = facts;
            run_block(n.body, body_facts);
            run_block(n.alt, cont_facts);
            break;
        }
        case NodeKind::Scope:
            if (flow::returns_early(n.body)) {
                Facts inner = facts;
                run_block(n.body, inner);
                facts.kill(flow::writes_of(n.body));
            } else {
                run_block(n.body, facts);
            }
            break;
        case NodeKind::Call: facts.clear(); break;
        default: break;
        }
    }
}

}  // namespace

void propagate_copies(Shader& shader) {
    for (Function& f : shader.functions) {
        Facts facts;
        run_block(f.body, facts);
    }
    Facts facts;
    run_block(shader.body, facts);
}

}  // namespace glslrun::ir
