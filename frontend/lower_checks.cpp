// CompileOptions::check_undefined: a check_undef instruction (ir/undefined.h)
// before each built-in call and operator whose result GLSL 1.10/1.20 leaves
// undefined for some operands, over the operands as the source wrote them.
// Checking here, not on the optimized IR, keeps to what the program asked
// for: the expansions of other built-ins (refract's sqrt of a negative k,
// which it never uses; normalize's division) are not the program's
// operations.
#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;
using ir::UndefOp;

// One check per component, the operands broadcast as componentwise() does;
// one site for them all (the call's position).
void StageLowering::check_op(UndefOp op, const std::vector<Value>& operands, uint32_t length) {
    size_t n = 0;
    for (const Value& v : operands) n = std::max(n, v.regs.size());
    if (n == 0) return;
    const Kind k = kind(operands[0].regs[0]);
    if (k != Kind::F32 && k != Kind::I32) return;
    ir::UndefSite site{uint8_t(op), loc_, length};
    site.loc.line = line_;
    shader.undef_sites.push_back(site);
    for (size_t i = 0; i < n; ++i) {
        ir::Instr in;
        in.op = Op::check_undef;
        in.type = k;
        for (size_t j = 0; j < 3; ++j) {
            const Value& v = operands[std::min(j, operands.size() - 1)];
            in.src[j] = v.regs[v.regs.size() == 1 ? 0 : i];
        }
        in.imm[0] = uint32_t(op);
        in.imm[1] = uint32_t(shader.undef_sites.size() - 1);
        in.imm[2] = length;
        emit(in);
    }
}

void StageLowering::check_arith(gl::TOperator op, const Value& a, const Value& b) {
    if (a.regs.empty() || b.regs.empty()) return;
    const bool is_int = kind(a.regs[0]) == Kind::I32;
    switch (op) {
    case gl::EOpDiv: return check_op(is_int ? UndefOp::IntDivZero : UndefOp::FloatDivZero, {a, b});
    case gl::EOpAdd: if (is_int) check_op(UndefOp::IntAdd, {a, b}); return;
    case gl::EOpSub: if (is_int) check_op(UndefOp::IntSub, {a, b}); return;
    case gl::EOpMul:
    case gl::EOpVectorTimesScalar: if (is_int) check_op(UndefOp::IntMul, {a, b}); return;
    case gl::EOpNegative: if (is_int) check_op(UndefOp::IntNeg, {a}); return;
    default: return;
    }
}

void StageLowering::check_builtin(gl::TOperator op, const std::vector<Value>& args) {
    if (args.empty() || args[0].regs.empty()) return;
    switch (op) {
    case gl::EOpPow: return check_op(UndefOp::Pow, {args[0], args[1]});
    case gl::EOpLog: return check_op(UndefOp::Log, {args[0]});
    case gl::EOpLog2: return check_op(UndefOp::Log2, {args[0]});
    case gl::EOpSqrt: return check_op(UndefOp::Sqrt, {args[0]});
    case gl::EOpInverseSqrt: return check_op(UndefOp::InverseSqrt, {args[0]});
    case gl::EOpAsin: return check_op(UndefOp::Asin, {args[0]});
    case gl::EOpAcos: return check_op(UndefOp::Acos, {args[0]});
    case gl::EOpAtan:  // atan(y_over_x) is defined everywhere
        if (args.size() == 2) check_op(UndefOp::Atan, {args[0], args[1]});
        return;
    case gl::EOpNormalize: return check_op(UndefOp::Normalize, {Value{{dot(args[0], args[0])}}});
    case gl::EOpSmoothStep: return check_op(UndefOp::Smoothstep, {args[0], args[1], args[2]});
    case gl::EOpClamp: return check_op(UndefOp::Clamp, {args[0], args[1], args[2]});
    default: return;
    }
}

void StageLowering::check_index(Reg index, uint32_t length) {
    if (check_undefined) check_op(UndefOp::Index, {Value{{index}}}, length);
}

}  // namespace glslrun::frontend
