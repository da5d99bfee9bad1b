// The values of an undefined operation in each precision mode, computed by
// the opcode table's own expressions (ir/alu_eval.h: Reference's double and
// Precise's float) and Fast's kernels (runtime/fast_kernels.h), exactly as
// the built-in's expansion in frontend/lower_builtins.cpp computes it; and
// what NVIDIA's driver returned for such operands, measured on the GPU
// (docs/debugging.md, "What GPUs return").
#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "ir/alu_eval.h"
#include "ir/scalar_ops.h"
#include "runtime/fast_kernels.h"
#include "scene/undefined_values.h"

namespace glslrun::scene {
namespace {

using ir::Op;
using ir::UndefOp;

// One op of the table in each mode's words: double (Reference) or float.
template <Op op>
double ref(double a, double b = 0) {
    using L = ir::alu::Lane<op>;
    return std::bit_cast<double>(L::template eval<uint64_t>(std::bit_cast<uint64_t>(a), std::bit_cast<uint64_t>(b), 0));
}
template <Op op>
float precise(float a, float b = 0) {
    using L = ir::alu::Lane<op>;
    return std::bit_cast<float>(L::template eval<uint32_t>(std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b), 0));
}
// Fast's kernel where it has one (FastLane), else Precise's.
template <Op op>
float fast(float a, float b = 0) {
    if constexpr (requires { rt::fast::FastLane<op>::arity; })
        return std::bit_cast<float>(rt::fast::FastLane<op>::eval(std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b), 0));
    else
        return precise<op>(a, b);
}
template <Op op>
int32_t int_op(int32_t a, int32_t b) {
    using L = ir::alu::Lane<op>;
    return int32_t(L::template eval<uint32_t>(uint32_t(a), uint32_t(b), 0));
}

template <Op op>
std::array<double, 3> modes(double a, double b = 0) {
    const double r = ref<op>(a, b);
    ir::FlushDenormals ftz;  // as the fp32 modes run
    return {r, precise<op>(float(a), float(b)), fast<op>(float(a), float(b))};
}

// smoothstep(e0, e1, x) as frontend/lower_builtins.cpp expands it, in one
// mode's words: t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t).
template <class F, class Sub, class Div, class Max, class Min, class Mul>
F smoothstep(F e0, F e1, F x, Sub sub, Div div, Max max, Min min, Mul mul) {
    F t = min(max(div(sub(x, e0), sub(e1, e0)), F(0)), F(1));
    return mul(mul(t, t), sub(F(3), mul(F(2), t)));
}

std::array<double, 3> smoothstep_modes(double e0, double e1, double x) {
    const double r = smoothstep<double>(e0, e1, x, ref<Op::fsub>, ref<Op::fdiv>, ref<Op::fmax>, ref<Op::fmin>, ref<Op::fmul>);
    ir::FlushDenormals ftz;
    const float p = smoothstep<float>(float(e0), float(e1), float(x), precise<Op::fsub>, precise<Op::fdiv>,
                                      precise<Op::fmax>, precise<Op::fmin>, precise<Op::fmul>);
    return {r, p, p};  // no op of it has a Fast kernel
}

// normalize(v) of a zero v: a component 0 / sqrt(0); Fast multiplies by
// its rsqrt (ir/sqrt_divisor.cpp).
std::array<double, 3> normalize_modes(double dot) {
    const double r = ref<Op::fdiv>(0.0, ref<Op::fsqrt>(dot));
    ir::FlushDenormals ftz;
    const float d = float(dot);
    return {r, precise<Op::fdiv>(0.0f, precise<Op::fsqrt>(d)),
            fast<Op::fdiv_by_sqrt>(0.0f, fast<Op::fsqrt_divisor>(d))};
}

std::array<double, 3> same(double v) { return {v, v, v}; }

std::array<double, 3> values(UndefOp op, uint32_t length, const std::vector<double>& x, std::string* note) {
    const double a = x.empty() ? 0 : x[0], b = x.size() > 1 ? x[1] : 0, c = x.size() > 2 ? x[2] : 0;
    switch (op) {
    case UndefOp::Pow: return modes<Op::fpow>(a, b);
    case UndefOp::Log: return modes<Op::flog>(a);
    case UndefOp::Log2: return modes<Op::flog2>(a);
    case UndefOp::Sqrt: return modes<Op::fsqrt>(a);
    case UndefOp::InverseSqrt: return modes<Op::frsqrt>(a);
    case UndefOp::FloatDivZero: return modes<Op::fdiv>(a, b);
    case UndefOp::Asin: return modes<Op::fasin>(a);
    case UndefOp::Acos: return modes<Op::facos>(a);
    case UndefOp::Atan: return modes<Op::fatan2>(a, b);
    case UndefOp::Normalize:
        *note = "each component of the zero vector";
        return normalize_modes(a);
    case UndefOp::Smoothstep: return smoothstep_modes(a, b, c);
    case UndefOp::Clamp: {
        const std::array<double, 3> v = modes<Op::fmin>(ref<Op::fmax>(a, b), c);
        *note = "min(max(x, minVal), maxVal): maxVal";
        return v;
    }
    case UndefOp::IntDivZero: return same(int_op<Op::idiv>(int32_t(a), int32_t(b)));
    case UndefOp::IntAdd: return same(int_op<Op::iadd>(int32_t(a), int32_t(b)));
    case UndefOp::IntSub: return same(int_op<Op::isub>(int32_t(a), int32_t(b)));
    case UndefOp::IntMul: return same(int_op<Op::imul>(int32_t(a), int32_t(b)));
    case UndefOp::IntNeg: return same(int_op<Op::isub>(0, int32_t(a)));
    case UndefOp::Unwritten:
        *note = "glslrun reads what the register holds: 0 in a program's first batch, else what an earlier "
                "invocation or instruction left there";
        return same(NAN);
    case UndefOp::Index:
        *note = fmt::format("the element read or written: the index clamped to 0..{}", length - 1);
        return same(a < 0 ? 0 : std::min(a, double(length) - 1));
    case UndefOp::Count_: break;
    }
    return same(NAN);
}

// What NVIDIA's driver returned for such operands: 580.159.04 on an H200,
// measured by tests/undefined/gpu (its cases in cases.txt, the bits in
// nvidia_h200.txt; docs/debugging.md, "What GPUs return"). "" for operands
// that the probe did not cover.
std::string gpu_result(UndefOp op, const std::vector<double>& x) {
    const double a = x.empty() ? 0 : x[0], b = x.size() > 1 ? x[1] : 0, c = x.size() > 2 ? x[2] : 0;
    switch (op) {
    case UndefOp::Pow: return a < 0 ? "NaN" : b == 0 ? "NaN" : "inf";
    case UndefOp::Log: case UndefOp::Log2: return a == 0 ? "-inf" : "NaN";
    case UndefOp::Sqrt: return "NaN";
    case UndefOp::InverseSqrt: return a == 0 ? "inf" : "NaN";
    case UndefOp::FloatDivZero: return "NaN (also for a nonzero dividend: a reciprocal refined by Newton's step)";
    case UndefOp::IntDivZero: return "-1";
    case UndefOp::Asin: case UndefOp::Acos: return "NaN";
    case UndefOp::Atan: return "0";
    case UndefOp::Normalize: return "NaN";
    case UndefOp::Smoothstep:
        if (a > b) {  // the formula, as glslrun computes it
            ir::FlushDenormals ftz;
            return fmt::format("{} (the formula)", smoothstep<float>(float(a), float(b), float(c), precise<Op::fsub>,
                                                                      precise<Op::fdiv>, precise<Op::fmax>,
                                                                      precise<Op::fmin>, precise<Op::fmul>));
        }
        return c < a ? "0" : c > a ? "1" : "";
    case UndefOp::Clamp: return fmt::format("{}, minVal: it computes max(min(x, maxVal), minVal)", float(b));
    case UndefOp::IntAdd: return fmt::format("{} (wrapped)", int_op<Op::iadd>(int32_t(a), int32_t(b)));
    case UndefOp::IntSub: return fmt::format("{} (wrapped)", int_op<Op::isub>(int32_t(a), int32_t(b)));
    case UndefOp::IntMul: return fmt::format("{} (wrapped)", int_op<Op::imul>(int32_t(a), int32_t(b)));
    case UndefOp::IntNeg: return fmt::format("{} (wrapped)", int_op<Op::isub>(0, int32_t(a)));
    case UndefOp::Index: return "0 when reading a local float array (not clamped)";
    case UndefOp::Unwritten:
        return "the one value the shader could have written (1.0 for `float v; if (z > 1.0) v = 1.0;` read with z = 0)";
    case UndefOp::Count_: break;
    }
    return "";
}

}  // namespace

void describe_values(UndefOp op, uint32_t length, UndefinedFinding& f) {
    f.mode_values = values(op, length, f.first.operands, &f.value_note);
    const std::string gpu = gpu_result(op, f.first.operands);
    if (!gpu.empty()) f.gpu = "NVIDIA (H200, driver 580.159.04) returns " + gpu + ", measured";
}

}  // namespace glslrun::scene

namespace glslrun::scene {
namespace {

// A value the way a shader author reads it: NaN, inf, an integer in int's
// range as such (ints are exact there; so are such floats), else the
// shortest digits that give back the same float (double where it is not a
// float).
std::string number(double v) {
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
    if (v == std::trunc(v) && std::fabs(v) <= 2147483648.0) return fmt::format("{}", int64_t(v));
    if (double(float(v)) == v) return fmt::format("{}", float(v));
    return fmt::format("{}", v);
}

std::string where(const UndefinedInvocation& inv) {
    std::string s = fmt::format("draw {}", inv.draw);
    s += inv.vertex ? fmt::format(", vertex {}", inv.vertex_index)
                    : fmt::format(", pixel {},{}{}", inv.x, inv.y, inv.in_target ? " of the pass's render target" : "");
    if (!inv.pass.empty()) s += fmt::format(", pass '{}'", inv.pass);
    return s + ", program " + inv.program;
}

std::string block(const UndefinedFinding& f) {
    std::string s = fmt::format("{}:{}: {} in the {} shader: {}\n", f.file, f.line, f.op,
                                f.vertex ? "vertex" : "fragment", f.condition);
    s += fmt::format("  {:>4} | {}\n", f.line, f.line_text);
    s += fmt::format("  {} invocation{}; the first: {}\n", f.count, f.count == 1 ? "" : "s", where(f.first));
    std::string operands;
    for (double v : f.first.operands) operands += (operands.empty() ? "" : ", ") + number(v);
    if (!operands.empty()) s += fmt::format("  operands: {}\n", operands);
    s += fmt::format("  glslrun returns: reference {}, precise {}, fast {}{}\n", number(f.mode_values[0]),
                     number(f.mode_values[1]), number(f.mode_values[2]),
                     f.value_note.empty() ? "" : " (" + f.value_note + ")");
    if (!f.gpu.empty()) s += "  " + f.gpu + "\n";
    return s;
}

}  // namespace

std::string format_undefined(const UndefinedReport& report) {
    if (report.findings.empty())
        return fmt::format("no operation that GLSL leaves undefined in {} draw{}\n", report.draws,
                           report.draws == 1 ? "" : "s");
    std::string out = fmt::format("{} operation{} that GLSL leaves undefined ({} draw{}):\n", report.findings.size(),
                                  report.findings.size() == 1 ? "" : "s", report.draws, report.draws == 1 ? "" : "s");
    for (const UndefinedFinding& f : report.findings) out += block(f);
    return out;
}

}  // namespace glslrun::scene
