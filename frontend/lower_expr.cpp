// Expressions: operators, assignments, constructors, constants.
#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

Value StageLowering::expr(gl::TIntermTyped* n) {
    set_line(n);
    if (gl::TIntermConstantUnion* c = n->getAsConstantUnion()) return constant(c->getConstArray(), c->getType());
    if (gl::TIntermSymbol* s = n->getAsSymbolNode()) return read(variable(s));
    if (gl::TIntermBinary* b = n->getAsBinaryNode()) return binary(b);
    if (gl::TIntermUnary* u = n->getAsUnaryNode()) return unary(u);
    if (gl::TIntermAggregate* a = n->getAsAggregate()) return aggregate(a);
    if (gl::TIntermSelection* s = n->getAsSelectionNode()) return ternary(s);
    return fail(n, "unsupported expression");
}

Value StageLowering::constant(const gl::TConstUnionArray& values, const gl::TType& type) {
    std::vector<Kind> kinds;
    flatten_kinds(type, kinds);
    Value v;
    for (size_t i = 0; i < kinds.size(); ++i) {
        const gl::TConstUnion& c = values[int(i < size_t(values.size()) ? i : 0)];
        switch (c.getType()) {
        case gl::EbtBool: v.regs.push_back(konst_b(c.getBConst())); break;
        case gl::EbtInt: v.regs.push_back(konst_i(c.getIConst())); break;
        case gl::EbtUint: v.regs.push_back(konst_i(int32_t(c.getUConst()))); break;
        default: v.regs.push_back(konst_f(float(c.getDConst()))); break;
        }
        if (kind(v.regs.back()) != kinds[i]) v.regs.back() = convert(Value{{v.regs.back()}}, kinds[i]).regs[0];
    }
    return v;
}

Value StageLowering::convert(const Value& v, Kind to) {
    Value out;
    for (Reg r : v.regs) {
        Kind from = kind(r);
        if (from == to) {
            out.regs.push_back(r);
            continue;
        }
        Op op = Op::mov;
        if (to == Kind::F32) op = from == Kind::I32 ? Op::i2f : Op::b2f;
        else if (to == Kind::I32) op = from == Kind::F32 ? Op::f2i : Op::b2i;
        else op = from == Kind::F32 ? Op::f2b : Op::i2b;
        out.regs.push_back(alu(op, to, r));
    }
    return out;
}

// ------------------------------------------------------------ binary ---
static bool is_index_op(gl::TOperator op) {
    return op == gl::EOpIndexDirect || op == gl::EOpIndexIndirect || op == gl::EOpIndexDirectStruct ||
           op == gl::EOpVectorSwizzle;
}

static gl::TOperator base_of_assign(gl::TOperator op) {
    switch (op) {
    case gl::EOpAddAssign: return gl::EOpAdd;
    case gl::EOpSubAssign: return gl::EOpSub;
    case gl::EOpMulAssign: return gl::EOpMul;
    case gl::EOpDivAssign: return gl::EOpDiv;
    case gl::EOpModAssign: return gl::EOpMod;
    case gl::EOpVectorTimesMatrixAssign: return gl::EOpVectorTimesMatrix;
    case gl::EOpVectorTimesScalarAssign: return gl::EOpVectorTimesScalar;
    case gl::EOpMatrixTimesScalarAssign: return gl::EOpMatrixTimesScalar;
    case gl::EOpMatrixTimesMatrixAssign: return gl::EOpMatrixTimesMatrix;
    default: return gl::EOpNull;
    }
}

Value StageLowering::binary(gl::TIntermBinary* n) {
    gl::TOperator op = n->getOp();
    if (is_index_op(op)) return read(access(n));
    if (op == gl::EOpAssign || base_of_assign(op) != gl::EOpNull) return assign(n);
    if (op == gl::EOpLogicalAnd || op == gl::EOpLogicalOr) return logical(n);
    if (op == gl::EOpComma) {
        expr(n->getLeft());
        return expr(n->getRight());
    }
    Value a = expr(n->getLeft());
    Value b = expr(n->getRight());
    set_line(n);
    return arith(op, n->getLeft()->getType(), a, n->getRight()->getType(), b, n->getType());
}

Value StageLowering::assign(gl::TIntermBinary* n) {
    Access place = access(n->getLeft());
    Value rhs = expr(n->getRight());
    set_line(n);
    gl::TOperator base = base_of_assign(n->getOp());
    if (base != gl::EOpNull) {
        Value old = read(place);
        rhs = arith(base, n->getLeft()->getType(), old, n->getRight()->getType(), rhs, n->getLeft()->getType());
    }
    write(place, rhs, n);
    return rhs;
}

// a && b / a || b: b is evaluated only when it decides the result.
Value StageLowering::logical(gl::TIntermBinary* n) {
    Reg a = condition(n->getLeft());
    Reg res = mov(a);
    ir::Block rhs = build([&] { mov_to(res, condition(n->getRight())); });
    set_line(n);
    if (n->getOp() == gl::EOpLogicalAnd) emit_if(a, std::move(rhs), {});
    else emit_if(a, {}, std::move(rhs));
    return Value{{res}};
}

Value StageLowering::compare_all(bool equal, const Value& a, const Value& b) {
    Reg acc = ir::kNoReg;
    for (size_t i = 0; i < a.regs.size() && i < b.regs.size(); ++i) {
        Kind k = kind(a.regs[i]);
        Op op = k == Kind::F32 ? (equal ? Op::feq : Op::fne)
                : k == Kind::I32 ? (equal ? Op::ieq : Op::ine)
                                 : (equal ? Op::beq : Op::bne);
        Reg c = alu(op, Kind::Bool, a.regs[i], b.regs[i]);
        acc = acc == ir::kNoReg ? c : alu(equal ? Op::band : Op::bor, Kind::Bool, acc, c);
    }
    return Value{{acc == ir::kNoReg ? konst_b(equal) : acc}};
}

static Op pick(Kind k, Op f, Op i) { return k == Kind::I32 ? i : f; }

Value StageLowering::arith(gl::TOperator op, const gl::TType& lt, const Value& a, const gl::TType& rt,
                           const Value& b, const gl::TType& result) {
    Kind k = a.regs.empty() ? Kind::F32 : kind(a.regs[0]);
    if (check_undefined) check_arith(op, a, b);
    switch (op) {
    case gl::EOpAdd: return componentwise(pick(k, Op::fadd, Op::iadd), a, b);
    case gl::EOpSub: return componentwise(pick(k, Op::fsub, Op::isub), a, b);
    case gl::EOpMul:
    case gl::EOpVectorTimesScalar:
    case gl::EOpMatrixTimesScalar: return componentwise(pick(k, Op::fmul, Op::imul), a, b);
    case gl::EOpDiv: return componentwise(pick(k, Op::fdiv, Op::idiv), a, b);
    case gl::EOpMod: return componentwise(pick(k, Op::fmod, Op::imod), a, b);
    case gl::EOpMatrixTimesVector: return matrix_times_vector(a, lt.getMatrixCols(), lt.getMatrixRows(), b);
    case gl::EOpVectorTimesMatrix: return vector_times_matrix(a, b, rt.getMatrixCols(), rt.getMatrixRows());
    case gl::EOpMatrixTimesMatrix:
        return matrix_times_matrix(a, lt.getMatrixCols(), lt.getMatrixRows(), b, rt.getMatrixCols());
    case gl::EOpLessThan: return componentwise(pick(k, Op::flt, Op::ilt), a, b);
    case gl::EOpGreaterThan: return componentwise(pick(k, Op::fgt, Op::igt), a, b);
    case gl::EOpLessThanEqual: return componentwise(pick(k, Op::fle, Op::ile), a, b);
    case gl::EOpGreaterThanEqual: return componentwise(pick(k, Op::fge, Op::ige), a, b);
    case gl::EOpEqual: return compare_all(true, a, b);
    case gl::EOpNotEqual: return compare_all(false, a, b);
    case gl::EOpLogicalXor: return componentwise(Op::bxor, a, b);
    default: break;
    }
    return fail(nullptr, fmt::format("unsupported operator (glslang op {})", int(op)), &result);
}

// ------------------------------------------------------------- unary ---
Value StageLowering::increment(gl::TIntermUnary* n) {
    Access place = access(n->getOperand());
    Value old = read(place);
    gl::TOperator op = n->getOp();
    bool inc = op == gl::EOpPreIncrement || op == gl::EOpPostIncrement;
    Value updated;
    for (Reg r : old.regs) {
        Kind k = kind(r);
        Reg one = k == Kind::I32 ? konst_i(1) : konst_f(1.0f);
        Op o = k == Kind::I32 ? (inc ? Op::iadd : Op::isub) : (inc ? Op::fadd : Op::fsub);
        if (check_undefined && k == Kind::I32) check_op(inc ? ir::UndefOp::IntAdd : ir::UndefOp::IntSub, {Value{{r}}, Value{{one}}});
        updated.regs.push_back(alu(o, k, r, one));
    }
    write(place, updated, n);
    return (op == gl::EOpPreIncrement || op == gl::EOpPreDecrement) ? updated : old;
}

Value StageLowering::unary(gl::TIntermUnary* n) {
    gl::TOperator op = n->getOp();
    switch (op) {
    case gl::EOpPreIncrement:
    case gl::EOpPreDecrement:
    case gl::EOpPostIncrement:
    case gl::EOpPostDecrement: return increment(n);
    default: break;
    }
    Value a = expr(n->getOperand());
    set_line(n);
    Kind k = a.regs.empty() ? Kind::F32 : kind(a.regs[0]);
    Value out;
    switch (op) {
    case gl::EOpNegative:
        if (check_undefined) check_arith(op, a, a);
        for (Reg r : a.regs) out.regs.push_back(alu(k == Kind::I32 ? Op::ineg : Op::fneg, k, r));
        return out;
    case gl::EOpLogicalNot:
    case gl::EOpVectorLogicalNot:
        for (Reg r : a.regs) out.regs.push_back(alu(Op::bnot, Kind::Bool, r));
        return out;
    case gl::EOpConvIntToFloat:
    case gl::EOpConvBoolToFloat:
    case gl::EOpConvUintToFloat: return convert(a, Kind::F32);
    case gl::EOpConvFloatToInt:
    case gl::EOpConvBoolToInt:
    case gl::EOpConvUintToInt:
    case gl::EOpConvIntToUint:
    case gl::EOpConvFloatToUint: return convert(a, Kind::I32);
    case gl::EOpConvIntToBool:
    case gl::EOpConvFloatToBool:
    case gl::EOpConvUintToBool: return convert(a, Kind::Bool);
    default: return builtin_unary(n, a);
    }
}

// c ? a : b: only the taken operand is evaluated.
Value StageLowering::ternary(gl::TIntermSelection* n) {
    Reg c = condition(n->getCondition());
    std::vector<Kind> kinds;
    flatten_kinds(n->getType(), kinds);
    Reg res = new_range(kinds);
    auto branch_of = [&](TIntermNode* e) {
        return build([&] {
            Value v = expr(e->getAsTyped());
            for (size_t i = 0; i < kinds.size() && i < v.regs.size(); ++i) mov_to(res + Reg(i), v.regs[i]);
        });
    };
    ir::Block t = branch_of(n->getTrueBlock());
    ir::Block f = branch_of(n->getFalseBlock());
    set_line(n);
    emit_if(c, std::move(t), std::move(f));
    Value out;
    for (size_t i = 0; i < kinds.size(); ++i) out.regs.push_back(mov(res + Reg(i)));
    return out;
}

// --------------------------------------------------------- aggregates ---
Value StageLowering::aggregate(gl::TIntermAggregate* n) {
    gl::TOperator op = n->getOp();
    if (op == gl::EOpFunctionCall) return call(n);
    if (op > gl::EOpConstructGuardStart && op < gl::EOpConstructGuardEnd) return construct(n);
    if (op == gl::EOpSequence) {
        Value last;
        for (TIntermNode* c : n->getSequence()) {
            if (gl::TIntermTyped* t = c->getAsTyped()) last = expr(t);
            else stmt(c);
        }
        return last;
    }
    if (op == gl::EOpComma) {
        note_out_conversions(n);
        Value last;
        for (TIntermNode* c : n->getSequence()) last = expr(c->getAsTyped());
        return last;
    }
    if (n->isTexture()) return texture(n);
    if (op == gl::EOpFtransform) return ftransform();
    std::vector<Value> args;
    for (TIntermNode* c : n->getSequence()) args.push_back(expr(c->getAsTyped()));
    set_line(n);
    return builtin_aggregate(n, args);
}

// Constructors per GLSL 1.10 §5.4 / 1.20 §5.4.
Value StageLowering::construct(gl::TIntermAggregate* n) {
    const gl::TType& t = n->getType();
    std::vector<Kind> kinds;
    flatten_kinds(t, kinds);
    std::vector<Value> args;
    std::vector<const gl::TType*> arg_types;
    for (TIntermNode* c : n->getSequence()) {
        args.push_back(expr(c->getAsTyped()));
        arg_types.push_back(&c->getAsTyped()->getType());
    }
    set_line(n);
    Kind k = kinds.empty() ? Kind::F32 : kinds[0];
    Value out;
    if (t.isMatrix() && !t.isArray() && args.size() == 1 && arg_types[0]->isScalarOrVec1()) {
        // mat(s): s on the diagonal, 0 elsewhere.
        Reg s = convert(args[0], k).regs[0];
        Reg zero = konst_f(0.0f);
        for (int c = 0; c < t.getMatrixCols(); ++c)
            for (int r = 0; r < t.getMatrixRows(); ++r) out.regs.push_back(c == r ? s : zero);
        return out;
    }
    if (t.isMatrix() && !t.isArray() && args.size() == 1 && arg_types[0]->isMatrix()) {
        // mat(m): the overlapping part of m, identity elsewhere.
        int ac = arg_types[0]->getMatrixCols(), ar = arg_types[0]->getMatrixRows();
        Reg zero = konst_f(0.0f), one = konst_f(1.0f);
        for (int c = 0; c < t.getMatrixCols(); ++c)
            for (int r = 0; r < t.getMatrixRows(); ++r)
                out.regs.push_back(c < ac && r < ar ? args[0].regs[size_t(c * ar + r)] : (c == r ? one : zero));
        return out;
    }
    Value all;
    for (const Value& a : args) all.regs.insert(all.regs.end(), a.regs.begin(), a.regs.end());
    if (!t.isStruct() && !t.isArray() && args.size() == 1 && all.regs.size() == 1) {
        // vec(s): broadcast.
        Reg s = convert(all, k).regs[0];
        out.regs.assign(kinds.size(), s);
        return out;
    }
    if (all.regs.size() < kinds.size()) return fail(n, "constructor has too few components");
    for (size_t i = 0; i < kinds.size(); ++i) out.regs.push_back(convert(Value{{all.regs[i]}}, kinds[i]).regs[0]);
    return out;
}

}  // namespace glslrun::frontend
