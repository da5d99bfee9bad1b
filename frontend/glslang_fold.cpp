// Constant folding that glslang 12 leaves out, spliced into glslang's own
// folding at link time: CMakeLists.txt links with ld's --wrap for the two
// fold entry points below, so glslang's parser calls __wrap_X, which folds
// what glslang cannot and hands everything else to __real_X (the original).
// No glslang code changes; the ABI is that of the installed headers.
//
// GLSL 1.20 §4.3.3 makes a built-in call on constant expressions a constant
// expression, usable in array sizes and const initializers. glslang 12:
//  - does not fold transpose() (unary EOpTranspose) nor matrixCompMult()
//    (aggregate EOpMul), so they are rejected there;
//  - folds degrees()/radians() in double from an unrounded literal, so
//    int(degrees(3.1415926535)) is 179 where float arithmetic gives 180.
// GLSL 1.10 has no built-in calls in constant expressions: see
// FoldVersionScope. See docs/semantics.md (glslang 12's gaps).
#include "frontend/glslang_fold.h"

#include <glslang/MachineIndependent/localintermediate.h>

namespace gl = glslang;

extern "C" {
// TIntermConstantUnion::fold(TOperator, const TType&) const: unary folding
// (reached through the node's vtable, which lives in another object file).
gl::TIntermTyped* __real__ZNK7glslang20TIntermConstantUnion4foldENS_9TOperatorERKNS_5TTypeE(
    const gl::TIntermConstantUnion* self, gl::TOperator op, const gl::TType& type);
gl::TIntermTyped* __wrap__ZNK7glslang20TIntermConstantUnion4foldENS_9TOperatorERKNS_5TTypeE(
    const gl::TIntermConstantUnion* self, gl::TOperator op, const gl::TType& type);
// TIntermediate::fold(TIntermAggregate*): built-in calls with several arguments.
gl::TIntermTyped* __real__ZN7glslang13TIntermediate4foldEPNS_16TIntermAggregateE(gl::TIntermediate* self,
                                                                              gl::TIntermAggregate* node);
gl::TIntermTyped* __wrap__ZN7glslang13TIntermediate4foldEPNS_16TIntermAggregateE(gl::TIntermediate* self,
                                                                              gl::TIntermAggregate* node);
}

namespace {

thread_local int parsing_version = 0;  // of the unit being parsed on this thread; 0: none

// Operations that are built-in function calls (not operators or constructors).
bool is_builtin_call(gl::TOperator op) {
    return (op >= gl::EOpRadians && op <= gl::EOpNoise) || op == gl::EOpAny || op == gl::EOpAll ||
           op == gl::EOpVectorLogicalNot;
}

constexpr double kPi = 3.14159265358979323846;

gl::TIntermTyped* constant(const gl::TConstUnionArray& values, const gl::TType& type, const gl::TSourceLoc& loc) {
    auto* node = new gl::TIntermConstantUnion(values, type);
    node->getWritableType().getQualifier().storage = gl::EvqConst;
    node->setLoc(loc);
    return node;
}

// Column-major in and out: element (c, r) of the result is (r, c) of m.
gl::TIntermTyped* fold_transpose(const gl::TIntermConstantUnion& m, const gl::TType& type) {
    int cols = m.getMatrixCols(), rows = m.getMatrixRows();
    const gl::TConstUnionArray& in = m.getConstArray();
    gl::TConstUnionArray out(cols * rows);
    for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r) out[r * cols + c] = in[c * rows + r];
    return constant(out, type, m.getLoc());
}

// GLSL computes in float: the argument is a float (a literal rounds to one)
// and so is the result; only the scaling happens in double.
gl::TIntermTyped* fold_angle(const gl::TIntermConstantUnion& x, gl::TOperator op, const gl::TType& type) {
    const double scale = op == gl::EOpDegrees ? 180.0 / kPi : kPi / 180.0;
    const gl::TConstUnionArray& in = x.getConstArray();
    gl::TConstUnionArray out(in.size());
    for (int i = 0; i < in.size(); ++i) out[i].setDConst(float(double(float(in[i].getDConst())) * scale));
    return constant(out, type, x.getLoc());
}

gl::TIntermTyped* fold_matrix_comp_mult(gl::TIntermAggregate& n) {
    const gl::TIntermSequence& args = n.getSequence();
    const gl::TConstUnionArray& a = args[0]->getAsConstantUnion()->getConstArray();
    const gl::TConstUnionArray& b = args[1]->getAsConstantUnion()->getConstArray();
    gl::TConstUnionArray out(a.size());
    for (int i = 0; i < a.size(); ++i) out[i].setDConst(a[i].getDConst() * b[i].getDConst());
    return constant(out, n.getType(), n.getLoc());
}

bool is_float(const gl::TType& t) { return t.getBasicType() == gl::EbtFloat; }

}  // namespace

gl::TIntermTyped* __wrap__ZNK7glslang20TIntermConstantUnion4foldENS_9TOperatorERKNS_5TTypeE(
    const gl::TIntermConstantUnion* self, gl::TOperator op, const gl::TType& type) {
    if (parsing_version == 110 && is_builtin_call(op)) return nullptr;  // glslang keeps the call
    if (op == gl::EOpTranspose && self->getType().isMatrix() && is_float(self->getType())) return fold_transpose(*self, type);
    if ((op == gl::EOpDegrees || op == gl::EOpRadians) && is_float(self->getType())) return fold_angle(*self, op, type);
    return __real__ZNK7glslang20TIntermConstantUnion4foldENS_9TOperatorERKNS_5TTypeE(self, op, type);
}

gl::TIntermTyped* __wrap__ZN7glslang13TIntermediate4foldEPNS_16TIntermAggregateE(gl::TIntermediate* self,
                                                                              gl::TIntermAggregate* node) {
    bool constructor = node->getOp() > gl::EOpConstructGuardStart && node->getOp() < gl::EOpConstructGuardEnd;
    if (self->getVersion() == 110 && !constructor) return node;  // glslang keeps the call
    const gl::TIntermSequence& args = node->getSequence();
    bool matrix_comp_mult = node->getOp() == gl::EOpMul && args.size() == 2 && node->getType().isMatrix() &&
                            is_float(node->getType()) && args[0]->getAsConstantUnion() && args[1]->getAsConstantUnion();
    if (matrix_comp_mult) return fold_matrix_comp_mult(*node);
    return __real__ZN7glslang13TIntermediate4foldEPNS_16TIntermAggregateE(self, node);
}

namespace glslrun::frontend {

FoldVersionScope::FoldVersionScope(int version) : saved_(parsing_version) { parsing_version = version; }
FoldVersionScope::~FoldVersionScope() { parsing_version = saved_; }

bool glslang_fold_hooks_linked() { return true; }

}  // namespace glslrun::frontend
