// GLSL 1.10 §8 / 1.20 §8 built-in functions (textures excluded), expanded
// into scalar ops; matrix products.
#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

namespace {
constexpr float kPi = 3.14159265358979323846f;
}

// Component-wise binary op; a scalar operand is broadcast.
Value StageLowering::componentwise(Op op, const Value& a, const Value& b) {
    size_t n = std::max(a.regs.size(), b.regs.size());
    Kind result = ir::op_info(op).result == ir::TypeClass::B ? Kind::Bool
                  : ir::op_info(op).result == ir::TypeClass::I ? Kind::I32
                                                               : Kind::F32;
    Value out;
    for (size_t i = 0; i < n; ++i) {
        Reg x = a.regs[a.regs.size() == 1 ? 0 : i];
        Reg y = b.regs[b.regs.size() == 1 ? 0 : i];
        out.regs.push_back(alu(op, result, x, y));
    }
    return out;
}

// op2(op1(a, b), c) component-wise with broadcasting (clamp = min(max(x, lo), hi)).
Value StageLowering::componentwise3(Op op1, Op op2, const Value& a, const Value& b, const Value& c) {
    return componentwise(op2, componentwise(op1, a, b), c);
}

Reg StageLowering::dot(const Value& a, const Value& b) {
    Reg acc = alu(Op::fmul, Kind::F32, a.regs[0], b.regs[0]);
    for (size_t i = 1; i < a.regs.size(); ++i)
        acc = alu(Op::fadd, Kind::F32, acc, alu(Op::fmul, Kind::F32, a.regs[i], b.regs[i]));
    return acc;
}

Value StageLowering::matrix_times_vector(const Value& m, int cols, int rows, const Value& v) {
    Value out;
    for (int r = 0; r < rows; ++r) {
        Reg acc = alu(Op::fmul, Kind::F32, m.regs[size_t(r)], v.regs[0]);
        for (int c = 1; c < cols; ++c)
            acc = alu(Op::fadd, Kind::F32, acc, alu(Op::fmul, Kind::F32, m.regs[size_t(c * rows + r)], v.regs[size_t(c)]));
        out.regs.push_back(acc);
    }
    return out;
}

Value StageLowering::vector_times_matrix(const Value& v, const Value& m, int cols, int rows) {
    Value out;
    for (int c = 0; c < cols; ++c) {
        Value col;
        col.regs.assign(m.regs.begin() + c * rows, m.regs.begin() + (c + 1) * rows);
        out.regs.push_back(dot(v, col));
    }
    return out;
}

Value StageLowering::matrix_times_matrix(const Value& a, int acols, int arows, const Value& b, int bcols) {
    Value out;
    for (int c = 0; c < bcols; ++c) {
        Value col;
        col.regs.assign(b.regs.begin() + c * acols, b.regs.begin() + (c + 1) * acols);
        Value prod = matrix_times_vector(a, acols, arows, col);
        out.regs.insert(out.regs.end(), prod.regs.begin(), prod.regs.end());
    }
    return out;
}

Value StageLowering::builtin_unary(gl::TIntermUnary* n, const Value& a) {
    auto each = [&](Op op) {
        Value out;
        for (Reg r : a.regs) out.regs.push_back(alu(op, ir::op_info(op).result == ir::TypeClass::I ? Kind::I32 : Kind::F32, r));
        return out;
    };
    auto scaled = [&](float s) {
        Value out;
        Reg k = konst_f(s);
        for (Reg r : a.regs) out.regs.push_back(alu(Op::fmul, Kind::F32, r, k));
        return out;
    };
    bool is_int = !a.regs.empty() && kind(a.regs[0]) == Kind::I32;
    if (check_undefined) check_builtin(n->getOp(), {a});
    switch (n->getOp()) {
    case gl::EOpRadians: return scaled(kPi / 180.0f);
    case gl::EOpDegrees: return scaled(180.0f / kPi);
    case gl::EOpSin: return each(Op::fsin);
    case gl::EOpCos: return each(Op::fcos);
    case gl::EOpTan: return each(Op::ftan);
    case gl::EOpAsin: return each(Op::fasin);
    case gl::EOpAcos: return each(Op::facos);
    case gl::EOpAtan: return each(Op::fatan);
    case gl::EOpExp: return each(Op::fexp);
    case gl::EOpLog: return each(Op::flog);
    case gl::EOpExp2: return each(Op::fexp2);
    case gl::EOpLog2: return each(Op::flog2);
    case gl::EOpSqrt: return each(Op::fsqrt);
    case gl::EOpInverseSqrt: return each(Op::frsqrt);
    case gl::EOpAbs: return each(is_int ? Op::iabs : Op::fabs);
    case gl::EOpSign: return each(is_int ? Op::isign : Op::fsign);
    case gl::EOpFloor: return each(Op::ffloor);
    case gl::EOpCeil: return each(Op::fceil);
    case gl::EOpFract: return each(Op::ffract);
    case gl::EOpLength: return Value{{alu(Op::fsqrt, Kind::F32, dot(a, a))}};
    case gl::EOpNormalize: {
        Reg len = alu(Op::fsqrt, Kind::F32, dot(a, a));
        return componentwise(Op::fdiv, a, Value{{len}});
    }
    case gl::EOpAny:
    case gl::EOpAll: {
        Reg acc = a.regs[0];
        for (size_t i = 1; i < a.regs.size(); ++i)
            acc = alu(n->getOp() == gl::EOpAny ? Op::bor : Op::band, Kind::Bool, acc, a.regs[i]);
        return Value{{mov(acc)}};
    }
    case gl::EOpTranspose: {
        const gl::TType& t = n->getOperand()->getType();
        int cols = t.getMatrixCols(), rows = t.getMatrixRows();
        Value out;  // result has `rows` columns of `cols` rows
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c) out.regs.push_back(a.regs[size_t(c * rows + r)]);
        return out;
    }
    case gl::EOpDPdx:
    case gl::EOpDPdy:
    case gl::EOpFwidth:
        if (stage_ != ir::Stage::Fragment) return fail(n, "derivatives are only available in fragment shaders");
        shader.uses_derivatives = true;
        if (n->getOp() == gl::EOpDPdx) return each(Op::ddx);
        if (n->getOp() == gl::EOpDPdy) return each(Op::ddy);
        {
            Value out;
            for (Reg r : a.regs) {
                Reg dx = alu(Op::fabs, Kind::F32, alu(Op::ddx, Kind::F32, r));
                Reg dy = alu(Op::fabs, Kind::F32, alu(Op::ddy, Kind::F32, r));
                out.regs.push_back(alu(Op::fadd, Kind::F32, dx, dy));
            }
            return out;
        }
    case gl::EOpNoise:
        // noise1..4: GLSL allows any implementation whose range is [-1,1]
        // with average 0; Mesa returns 0 as well, so we do.
        return zeros(n->getType());
    default: break;
    }
    return fail(n, fmt::format("built-in function not supported (glslang op {})", int(n->getOp())));
}

Value StageLowering::builtin_aggregate(gl::TIntermAggregate* n, const std::vector<Value>& args) {
    auto arg = [&](size_t i) -> const Value& { return args[i]; };
    bool is_int = !args.empty() && !args[0].regs.empty() && kind(args[0].regs[0]) == Kind::I32;
    const gl::TIntermSequence& seq = n->getSequence();
    if (check_undefined) check_builtin(n->getOp(), args);
    switch (n->getOp()) {
    case gl::EOpAtan: return componentwise(Op::fatan2, arg(0), arg(1));
    case gl::EOpPow: return componentwise(Op::fpow, arg(0), arg(1));
    case gl::EOpMod: return componentwise(is_int ? Op::imod : Op::fmod, arg(0), arg(1));
    case gl::EOpMin: return componentwise(is_int ? Op::imin : Op::fmin, arg(0), arg(1));
    case gl::EOpMax: return componentwise(is_int ? Op::imax : Op::fmax, arg(0), arg(1));
    case gl::EOpClamp:
        return is_int ? componentwise3(Op::imax, Op::imin, arg(0), arg(1), arg(2))
                      : componentwise3(Op::fmax, Op::fmin, arg(0), arg(1), arg(2));
    case gl::EOpMix: {
        // x * (1 - a) + y * a
        Value one{{konst_f(1.0f)}};
        Value inv = componentwise(Op::fsub, one, arg(2));
        Value x = componentwise(Op::fmul, arg(0), inv);
        Value y = componentwise(Op::fmul, arg(1), arg(2));
        return componentwise(Op::fadd, x, y);
    }
    case gl::EOpStep: {
        Value lt = componentwise(Op::flt, arg(1), arg(0));
        Reg zero = konst_f(0.0f), one = konst_f(1.0f);
        Value out;
        for (Reg c : lt.regs) out.regs.push_back(alu(Op::sel, Kind::F32, c, zero, one));
        return out;
    }
    case gl::EOpSmoothStep: {
        Value t = componentwise(Op::fdiv, componentwise(Op::fsub, arg(2), arg(0)), componentwise(Op::fsub, arg(1), arg(0)));
        t = componentwise3(Op::fmax, Op::fmin, t, Value{{konst_f(0.0f)}}, Value{{konst_f(1.0f)}});
        Value three_minus = componentwise(Op::fsub, Value{{konst_f(3.0f)}}, componentwise(Op::fmul, Value{{konst_f(2.0f)}}, t));
        return componentwise(Op::fmul, componentwise(Op::fmul, t, t), three_minus);
    }
    case gl::EOpDistance: {
        Value d = componentwise(Op::fsub, arg(0), arg(1));
        return Value{{alu(Op::fsqrt, Kind::F32, dot(d, d))}};
    }
    case gl::EOpDot: return Value{{dot(arg(0), arg(1))}};
    case gl::EOpCross: {
        const auto& x = arg(0).regs;
        const auto& y = arg(1).regs;
        auto term = [&](int i, int j) {
            return alu(Op::fsub, Kind::F32, alu(Op::fmul, Kind::F32, x[size_t(i)], y[size_t(j)]),
                       alu(Op::fmul, Kind::F32, y[size_t(i)], x[size_t(j)]));
        };
        return Value{{term(1, 2), term(2, 0), term(0, 1)}};
    }
    case gl::EOpFaceForward: {
        // dot(Nref, I) < 0 ? N : -N
        Reg d = dot(arg(2), arg(1));
        Reg neg = alu(Op::flt, Kind::Bool, d, konst_f(0.0f));
        Value out;
        for (Reg r : arg(0).regs) out.regs.push_back(alu(Op::sel, Kind::F32, neg, r, alu(Op::fneg, Kind::F32, r)));
        return out;
    }
    case gl::EOpReflect: {
        // I - 2 * dot(N, I) * N
        Reg d2 = alu(Op::fmul, Kind::F32, konst_f(2.0f), dot(arg(1), arg(0)));
        return componentwise(Op::fsub, arg(0), componentwise(Op::fmul, Value{{d2}}, arg(1)));
    }
    case gl::EOpRefract: {
        // k = 1 - eta^2 (1 - dot(N,I)^2); k < 0 ? 0 : eta*I - (eta*dot(N,I) + sqrt(k))*N
        Reg eta = arg(2).regs[0];
        Reg d = dot(arg(1), arg(0));
        Reg one = konst_f(1.0f);
        Reg k = alu(Op::fsub, Kind::F32, one,
                    alu(Op::fmul, Kind::F32, alu(Op::fmul, Kind::F32, eta, eta),
                        alu(Op::fsub, Kind::F32, one, alu(Op::fmul, Kind::F32, d, d))));
        Reg neg = alu(Op::flt, Kind::Bool, k, konst_f(0.0f));
        Reg f = alu(Op::fadd, Kind::F32, alu(Op::fmul, Kind::F32, eta, d), alu(Op::fsqrt, Kind::F32, k));
        Value r = componentwise(Op::fsub, componentwise(Op::fmul, Value{{eta}}, arg(0)),
                                componentwise(Op::fmul, Value{{f}}, arg(1)));
        Reg zero = konst_f(0.0f);
        for (Reg& c : r.regs) c = alu(Op::sel, Kind::F32, neg, zero, c);
        return r;
    }
    case gl::EOpMul: return componentwise(Op::fmul, arg(0), arg(1));  // matrixCompMult
    case gl::EOpOuterProduct: {
        // column j = c * r[j]
        Value out;
        for (Reg rj : arg(1).regs)
            for (Reg ci : arg(0).regs) out.regs.push_back(alu(Op::fmul, Kind::F32, ci, rj));
        return out;
    }
    case gl::EOpLessThan:
    case gl::EOpGreaterThan:
    case gl::EOpLessThanEqual:
    case gl::EOpGreaterThanEqual:
    case gl::EOpVectorEqual:
    case gl::EOpVectorNotEqual: {
        gl::TOperator op = n->getOp();
        Kind k = kind(arg(0).regs[0]);
        Op o = Op::feq;
        if (op == gl::EOpLessThan) o = is_int ? Op::ilt : Op::flt;
        if (op == gl::EOpGreaterThan) o = is_int ? Op::igt : Op::fgt;
        if (op == gl::EOpLessThanEqual) o = is_int ? Op::ile : Op::fle;
        if (op == gl::EOpGreaterThanEqual) o = is_int ? Op::ige : Op::fge;
        if (op == gl::EOpVectorEqual) o = k == Kind::Bool ? Op::beq : is_int ? Op::ieq : Op::feq;
        if (op == gl::EOpVectorNotEqual) o = k == Kind::Bool ? Op::bne : is_int ? Op::ine : Op::fne;
        return componentwise(o, arg(0), arg(1));
    }
    default: break;
    }
    (void)seq;
    return fail(n, fmt::format("built-in function not supported (glslang op {})", int(n->getOp())));
}

}  // namespace glslrun::frontend
