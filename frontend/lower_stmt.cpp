// Statements and control flow, plus the emission helpers.
#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include "frontend/call_graph.h"
#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

// ------------------------------------------------------------ emission ---
Reg StageLowering::new_reg(Kind k) {
    shader.regs.push_back(k);
    return Reg(shader.regs.size() - 1);
}

Reg StageLowering::new_range(const std::vector<Kind>& kinds) {
    Reg first = Reg(shader.regs.size());
    shader.regs.insert(shader.regs.end(), kinds.begin(), kinds.end());
    return first;
}

void StageLowering::emit(const ir::Instr& in) {
    ir::Node n;
    n.kind = ir::NodeKind::Instr;
    n.instr = in;
    emit_node(std::move(n));
}

void StageLowering::emit_node(ir::Node n) {
    n.loc = loc_;
    n.loc.line = line_;
    cur_->push_back(std::move(n));
}

Reg StageLowering::alu(Op op, Kind result, Reg a, Reg b, Reg c) {
    ir::Instr in;
    in.op = op;
    in.type = result;
    in.dst = new_reg(result);
    in.src[0] = a;
    in.src[1] = b;
    in.src[2] = c;
    emit(in);
    return in.dst;
}

Reg StageLowering::mov(Reg src) { return alu(Op::mov, kind(src), src); }

void StageLowering::mov_to(Reg dst, Reg src) {
    ir::Instr in;
    in.op = Op::mov;
    in.type = kind(dst);
    in.dst = dst;
    in.src[0] = src;
    emit(in);
}

Reg StageLowering::konst_f(float f) {
    ir::Instr in;
    in.op = Op::konst;
    in.type = Kind::F32;
    in.dst = new_reg(Kind::F32);
    in.imm[0] = float_bits(f);
    emit(in);
    return in.dst;
}

Reg StageLowering::konst_i(int32_t i) {
    ir::Instr in;
    in.op = Op::konst;
    in.type = Kind::I32;
    in.dst = new_reg(Kind::I32);
    in.imm[0] = uint32_t(i);
    emit(in);
    return in.dst;
}

Reg StageLowering::konst_b(bool b) {
    ir::Instr in;
    in.op = Op::konst;
    in.type = Kind::Bool;
    in.dst = new_reg(Kind::Bool);
    in.imm[0] = b ? 1u : 0u;
    emit(in);
    return in.dst;
}

Reg StageLowering::konst_zero(Kind k) {
    return k == Kind::F32 ? konst_f(0.0f) : k == Kind::I32 ? konst_i(0) : konst_b(false);
}

Value StageLowering::zeros(const gl::TType& t) {
    std::vector<Kind> kinds;
    if (t.getBasicType() != gl::EbtVoid) flatten_kinds(t, kinds);
    Value v;
    for (Kind k : kinds) v.regs.push_back(konst_zero(k));
    return v;
}

void StageLowering::emit_if(Reg cond, ir::Block then_block, ir::Block else_block) {
    ir::Node n;
    n.kind = ir::NodeKind::If;
    n.cond = cond;
    n.body = std::move(then_block);
    n.alt = std::move(else_block);
    emit_node(std::move(n));
}

Value StageLowering::fail(TIntermNode* n, const std::string& message, const gl::TType* type) {
    int line = n ? n->getLoc().line : line_;
    diags_.push_back(Diagnostic{file_, line, message, false});
    if (type) return zeros(*type);
    if (n && n->getAsTyped()) return zeros(n->getAsTyped()->getType());
    return {};
}

void StageLowering::set_line(TIntermNode* n) {
    if (!n || n->getLoc().line <= 0) return;
    const gl::TSourceLoc& at = n->getLoc();
    line_ = at.line;
    // The driver numbers each unit's nodes with the unit's index (MarkUnitSource).
    unsigned source = at.string >= 0 && size_t(at.string) < shader.sources.size() ? unsigned(at.string) : 0;
    loc_ = ir::SourceLoc{line_, uint16_t(std::clamp(at.column, 0, 0xffff)), uint16_t(source)};
}

// For the trace (ir::Variable): locals, parameters and register globals.
void StageLowering::name_variable(const std::string& name, const std::string& function, const gl::TType& type,
                                  Reg first) {
    if (name.empty() || name.starts_with("anon@") || name.starts_with("tempArg")) return;
    uint32_t count = flat_size(type);
    shader.variables.push_back(ir::Variable{name, function, type_signature(type), first, count});
}

// ---------------------------------------------------------- statements ---
void StageLowering::stmt(TIntermNode* n) {
    if (!n) return;
    set_line(n);
    if (gl::TIntermAggregate* agg = n->getAsAggregate(); agg && agg->getOp() == gl::EOpSequence) {
        for (TIntermNode* child : agg->getSequence()) stmt(child);
        return;
    }
    if (gl::TIntermSelection* sel = n->getAsSelectionNode(); sel && sel->getBasicType() == gl::EbtVoid) {
        selection(sel);
        return;
    }
    if (gl::TIntermLoop* l = n->getAsLoopNode()) {
        loop(l);
        return;
    }
    if (gl::TIntermBranch* b = n->getAsBranchNode()) {
        branch(b);
        return;
    }
    if (n->getAsSwitchNode()) {
        fail(n, "switch statements are not supported (GLSL 1.30)");
        return;
    }
    if (gl::TIntermTyped* t = n->getAsTyped()) {
        expr(t);
        return;
    }
}

Reg StageLowering::condition(gl::TIntermTyped* n) {
    Value v = expr(n);
    if (v.regs.size() != 1 || kind(v.regs[0]) != Kind::Bool) {
        fail(n, "condition is not a scalar bool");
        return konst_b(false);
    }
    return v.regs[0];
}

void StageLowering::selection(gl::TIntermSelection* n) {
    // Code that constant folding removes is not lowered: its calls may have
    // no body (call_graph.h).
    if (int branch = constant_branch(*n); branch >= 0) {
        stmt(branch ? n->getTrueBlock() : n->getFalseBlock());
        return;
    }
    Reg c = condition(n->getCondition());
    ir::Block then_block = build([&] { stmt(n->getTrueBlock()); });
    ir::Block else_block = build([&] { stmt(n->getFalseBlock()); });
    set_line(n);
    emit_if(c, std::move(then_block), std::move(else_block));
}

// for/while: loop { if (!cond) break; body } continue { increment }
// do-while:  loop { body } continue { if (!cond) break; }
void StageLowering::loop(gl::TIntermLoop* n) {
    auto exit_unless = [&](gl::TIntermTyped* test) {
        Reg c = condition(test);
        Reg nc = alu(Op::bnot, Kind::Bool, c);
        ir::Node brk;
        brk.kind = ir::NodeKind::Break;
        ir::Block then_block;
        brk.loc = loc_;
        brk.loc.line = line_;
        then_block.push_back(brk);
        emit_if(nc, std::move(then_block), {});
    };
    ir::Node node;
    node.kind = ir::NodeKind::Loop;
    node.body = build([&] {
        if (n->testFirst() && n->getTest()) exit_unless(n->getTest());
        stmt(n->getBody());
    });
    node.alt = build([&] {
        if (n->getTerminal()) {
            set_line(n->getTerminal());
            expr(n->getTerminal());
        }
        if (!n->testFirst() && n->getTest()) exit_unless(n->getTest());
    });
    set_line(n);
    emit_node(std::move(node));
}

void StageLowering::branch(gl::TIntermBranch* n) {
    ir::Node node;
    switch (n->getFlowOp()) {
    case gl::EOpBreak: node.kind = ir::NodeKind::Break; break;
    case gl::EOpContinue: node.kind = ir::NodeKind::Continue; break;
    case gl::EOpKill:
        node.kind = ir::NodeKind::Discard;
        shader.uses_discard = true;
        if (stage_ != ir::Stage::Fragment) {
            fail(n, "'discard' : not supported in this stage");
            return;
        }
        break;
    case gl::EOpReturn:
        if (gl::TIntermTyped* e = n->getExpression()) {
            Value v = expr(e);
            if (cur_info_ && cur_info_->ret != ir::kNoReg && v.regs.size() == cur_info_->ret_size)
                for (uint32_t i = 0; i < cur_info_->ret_size; ++i) mov_to(cur_info_->ret + i, v.regs[i]);
        }
        set_line(n);
        node.kind = ir::NodeKind::Return;
        break;
    default: fail(n, "unsupported branch statement"); return;
    }
    emit_node(std::move(node));
}

}  // namespace glslrun::frontend
