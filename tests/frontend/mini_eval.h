// A one-lane reference evaluator for the IR, for frontend tests only: it
// checks that lowered shaders compute GLSL's values without depending on the
// batched runtime. Semantics of Alu ops come from ir/opcodes.def.
#pragma once
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ir/ir.h"
#include "ir/scalar_ops.h"

namespace glslrun::test {

class MiniEval {
public:
    MiniEval(const ir::Shader& s, std::vector<uint32_t> uniforms) : s_(s), u_(std::move(uniforms)), r_(s.regs.size()) {}

    void set_input(const std::string& name, const std::vector<float>& v) {
        const ir::Binding& b = binding(s_.inputs, name);
        for (uint32_t i = 0; i < b.count && i < v.size(); ++i) {
            if (b.kind == ir::Kind::F32) setf(b.first + i, v[i]);
            else if (b.kind == ir::Kind::I32) r_[b.first + i] = uint32_t(int32_t(v[i]));
            else r_[b.first + i] = v[i] != 0.0f;
        }
    }
    std::vector<float> output(const std::string& name) const {
        const ir::Binding& b = binding(s_.outputs, name);
        std::vector<float> out;
        for (uint32_t i = 0; i < b.count; ++i) out.push_back(as_float(b.first + i));
        return out;
    }
    bool run() {  // false: discarded
        steps_ = 0;
        return exec(s_.body) != Flow::Discard;
    }

private:
    enum class Flow { Normal, Break, Continue, Return, Discard };

    static const ir::Binding& binding(const std::vector<ir::Binding>& list, const std::string& name) {
        for (const ir::Binding& b : list)
            if (b.name == name) return b;
        throw std::runtime_error("no binding " + name);
    }
    float getf(ir::Reg r) const { float x; std::memcpy(&x, &r_[r], 4); return x; }
    int32_t geti(ir::Reg r) const { return int32_t(r_[r]); }
    bool getb(ir::Reg r) const { return r_[r] != 0; }
    void setf(ir::Reg r, float x) { std::memcpy(&r_[r], &x, 4); }
    float as_float(ir::Reg r) const {
        switch (s_.regs[r]) {
        case ir::Kind::F32: return getf(r);
        case ir::Kind::I32: return float(geti(r));
        case ir::Kind::Bool: return getb(r) ? 1.0f : 0.0f;
        }
        return 0;
    }
    uint32_t addr(const ir::Instr& in) const {
        int32_t idx = std::max(0, std::min(geti(in.src[0]), int32_t(in.imm[1]) - 1));
        return in.imm[0] + uint32_t(idx) * in.imm[2];
    }

    void instr(const ir::Instr& in) {
        using ir::Op;
        switch (in.op) {
        case Op::mov: r_[in.dst] = r_[in.src[0]]; return;
        case Op::konst: r_[in.dst] = in.imm[0]; return;
        case Op::sel: r_[in.dst] = getb(in.src[0]) ? r_[in.src[1]] : r_[in.src[2]]; return;
        case Op::uniform: r_[in.dst] = u_.at(in.imm[0]); return;
        case Op::uniform_ind: r_[in.dst] = u_.at(addr(in)); return;
        case Op::load_ind: r_[in.dst] = r_.at(addr(in)); return;
        case Op::store_ind: r_.at(addr(in)) = r_[in.src[1]]; return;
        case Op::ddx:
        case Op::ddy: setf(in.dst, 0.0f); return;
        default: break;
        }
        ir::Reg s0 = in.src[0] == ir::kNoReg ? 0 : in.src[0];
        ir::Reg s1 = in.src[1] == ir::kNoReg ? 0 : in.src[1];
        ir::Reg s2 = in.src[2] == ir::kNoReg ? 0 : in.src[2];
#define LD_F(r) getf(r)
#define LD_I(r) geti(r)
#define LD_B(r) getb(r)
#define ST_F(v) setf(in.dst, float(v))
#define ST_I(v) r_[in.dst] = uint32_t(int32_t(v))
#define ST_B(v) r_[in.dst] = (v) ? 1u : 0u
#define EVAL_Alu(res, opnd, expr)                 \
    {                                             \
        [[maybe_unused]] auto a = LD_##opnd(s0);  \
        [[maybe_unused]] auto b = LD_##opnd(s1);  \
        [[maybe_unused]] auto c = LD_##opnd(s2);  \
        ST_##res(expr);                           \
    }
#define EVAL_Special(res, opnd, expr)
#define OP(name, arity, res, opnd, kind, fast, props, expr) \
    case Op::name: EVAL_##kind(res, opnd, expr) return;
        using namespace ir;
        switch (in.op) {
#include "ir/opcodes.def"
        default: break;
        }
#undef OP
#undef EVAL_Alu
#undef EVAL_Special
    }

    Flow exec(const ir::Block& blk) {
        for (const ir::Node& n : blk) {
            Flow fl = node(n);
            if (fl != Flow::Normal) return fl;
        }
        return Flow::Normal;
    }
    Flow node(const ir::Node& n) {
        if (++steps_ > 10'000'000) throw std::runtime_error("step limit");
        switch (n.kind) {
        case ir::NodeKind::Instr: instr(n.instr); return Flow::Normal;
        case ir::NodeKind::If: return getb(n.cond) ? exec(n.body) : exec(n.alt);
        case ir::NodeKind::Loop:
            for (;;) {
                Flow fl = exec(n.body);
                if (fl == Flow::Break) break;
                if (fl == Flow::Return || fl == Flow::Discard) return fl;
                fl = exec(n.alt);
                if (fl == Flow::Break) break;
                if (fl == Flow::Return || fl == Flow::Discard) return fl;
            }
            return Flow::Normal;
        case ir::NodeKind::Break: return Flow::Break;
        case ir::NodeKind::Continue: return Flow::Continue;
        case ir::NodeKind::Return: return Flow::Return;
        case ir::NodeKind::Discard: return Flow::Discard;
        case ir::NodeKind::Call: return exec(s_.functions.at(n.callee).body) == Flow::Discard ? Flow::Discard : Flow::Normal;
        case ir::NodeKind::Scope: return exec(n.body) == Flow::Discard ? Flow::Discard : Flow::Normal;
        }
        return Flow::Normal;
    }

    const ir::Shader& s_;
    std::vector<uint32_t> u_;
    std::vector<uint32_t> r_;
    uint64_t steps_ = 0;
};

}  // namespace glslrun::test
