// Every Alu op of the table and the Special instructions, over all lanes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ir/alu_eval.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;
using rt::kLanes;

namespace {

Kind operand_kind(ir::TypeClass c) {
    switch (c) {
    case ir::TypeClass::I: return Kind::I32;
    case ir::TypeClass::B: return Kind::Bool;
    default: return Kind::F32;
    }
}

// Varied per-lane operand values (operand k, lane i) covering signs, zero,
// fractions, large magnitudes and the integer edge cases.
uint32_t sample(Kind k, int operand, int lane) {
    static const float fs[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -2.75f, 3.25f, 100.0f,
                               -1e6f, 1e-3f, 7.0f, -0.25f, 2.0f, 0.75f, -3.0f, 1e30f};
    static const int32_t is[] = {0, 1, -1, 7, -7, 3, 100, -100, std::numeric_limits<int32_t>::min(),
                                 std::numeric_limits<int32_t>::max(), 2, -2, 5, 13, -13, 0};
    int j = (lane + operand * 5) % 16;
    switch (k) {
    case Kind::F32: return bits(fs[j]);
    case Kind::I32: return bits(is[j]);
    case Kind::Bool: return uint32_t(((lane >> operand) ^ operand) & 1);
    }
    return 0;
}

bool same_word(Kind k, uint32_t a, uint32_t b) {
    if (k == Kind::F32 && std::isnan(as_float(a)) && std::isnan(as_float(b))) return true;
    return a == b;
}

// dst = op(src[0..arity-1]).
Reg build_alu(Builder& b, Op op, const std::vector<Reg>& src) {
    switch (ir::op_info(op).arity) {
    case 1: return b.alu(op, {src[0]});
    case 2: return b.alu(op, {src[0], src[1]});
    default: return b.alu(op, {src[0], src[1], src[2]});
    }
}

// Runs `op` on constant-free per-lane operands; returns the dst register words.
std::vector<uint32_t> run_op(Op op, const std::vector<std::vector<uint32_t>>& operands, Kind* result) {
    Builder b;
    const ir::OpInfo& info = ir::op_info(op);
    Kind in_kind = operand_kind(info.operand);
    std::vector<Reg> src;
    for (int k = 0; k < info.arity; ++k) src.push_back(b.reg(in_kind));
    Reg d = build_alu(b, op, src);
    *result = b.sh.regs[d];
    Runner r(b.sh);
    for (int k = 0; k < info.arity; ++k) r.set(src[k], [&](int i) { return operands[k][i]; });
    REQUIRE(r.run());
    std::vector<uint32_t> out;
    for (int i = 0; i < kLanes; ++i) out.push_back(r.at(d, i));
    return out;
}

}  // namespace

// Calls f(op, info, operand kind) for every Alu op of the table.
template <class F>
void for_each_alu_op(F&& f) {
    for (size_t o = 0; o < size_t(Op::Count_); ++o) {
        Op op = Op(o);
        if (!ir::alu::is_alu(op)) continue;
        const ir::OpInfo& info = ir::op_info(op);
        INFO("op " << info.name);
        f(op, info, operand_kind(info.operand));
    }
}

TEST_CASE("every Alu op matches the table expression on every lane", "[runtime][alu]") {
    for_each_alu_op([](Op op, const ir::OpInfo& info, Kind in_kind) {
        std::vector<std::vector<uint32_t>> operands(3, std::vector<uint32_t>(kLanes));
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < kLanes; ++i) operands[k][i] = sample(in_kind, k, i);
        Kind result;
        std::vector<uint32_t> out = run_op(op, operands, &result);
        for (int i = 0; i < kLanes; ++i) {
            INFO("lane " << i);
            uint32_t expect = ir::alu::eval(op, operands[0][i], operands[1][i], operands[2][i]);
            CHECK(same_word(result, out[i], expect));
        }
    });
}

// Reference mode: the operands are shader inputs (widened to 64-bit words at
// run()) and the result an output (rounded back to 32 bits after it).
TEST_CASE("Reference: every Alu op is the table expression in double on every lane", "[runtime][alu][precision]") {
    int checked = 0;
    for_each_alu_op([&](Op op, const ir::OpInfo& info, Kind in_kind) {
        Builder b;
        std::vector<Reg> src;
        for (int k = 0; k < 3; ++k) src.push_back(b.reg(in_kind));
        for (int k = 0; k < info.arity; ++k) b.input("operand", src[size_t(k)]);
        Reg d = build_alu(b, op, src);
        b.output("result", d);
        std::vector<uint32_t> uniforms{0};
        rt::Interpreter it(b.sh, uniforms.data(), 16, nullptr, glslrun::Precision::Reference);
        for (int k = 0; k < info.arity; ++k)
            for (int i = 0; i < kLanes; ++i) it.lanes(src[size_t(k)])[i] = sample(in_kind, k, i);
        REQUIRE(it.run(rt::kAllLanes, nullptr));
        for (int i = 0; i < kLanes; ++i) {
            INFO("lane " << i);
            uint64_t w[3] = {};
            for (int k = 0; k < info.arity; ++k) w[k] = rt::widen<uint64_t>(in_kind, sample(in_kind, k, i));
            uint64_t expect = ir::alu::eval<uint64_t>(op, w[0], w[1], w[2]);
            CHECK(same_word(b.sh.regs[d], it.lanes(d)[i], rt::narrow<uint64_t>(b.sh.regs[d], expect)));
            ++checked;
        }
    });
    CHECK(checked > 50 * kLanes);
}

TEST_CASE("Alu ops have GLSL semantics", "[runtime][alu]") {
    auto f1 = [](Op op, float a) {
        Kind k;
        std::vector<std::vector<uint32_t>> v(1, std::vector<uint32_t>(kLanes, bits(a)));
        return as_float(run_op(op, v, &k)[3]);
    };
    auto f2 = [](Op op, float a, float b) {
        Kind k;
        std::vector<std::vector<uint32_t>> v{std::vector<uint32_t>(kLanes, bits(a)),
                                             std::vector<uint32_t>(kLanes, bits(b))};
        return run_op(op, v, &k)[kLanes - 1];
    };
    auto i2 = [](Op op, int32_t a, int32_t b) {
        Kind k;
        std::vector<std::vector<uint32_t>> v{std::vector<uint32_t>(kLanes, bits(a)),
                                             std::vector<uint32_t>(kLanes, bits(b))};
        return int32_t(run_op(op, v, &k)[5]);
    };
    CHECK(as_float(f2(Op::fmod, -1.0f, 3.0f)) == 2.0f);
    CHECK(as_float(f2(Op::fmod, 5.5f, 2.0f)) == 1.5f);
    CHECK(f1(Op::ffract, -1.25f) == 0.75f);
    CHECK(f1(Op::fsign, -3.0f) == -1.0f);
    CHECK(f1(Op::fsign, 0.0f) == 0.0f);
    CHECK(f1(Op::frsqrt, 4.0f) == 0.5f);
    CHECK(as_float(f2(Op::fmin, 2.0f, -1.0f)) == -1.0f);
    CHECK(as_float(f2(Op::fmax, 2.0f, -1.0f)) == 2.0f);
    CHECK(f2(Op::flt, 1.0f, 2.0f) == 1u);
    CHECK(f2(Op::fge, 1.0f, 2.0f) == 0u);
    CHECK(i2(Op::idiv, 7, 0) == 0);
    CHECK(i2(Op::idiv, -7, 2) == -3);
    CHECK(i2(Op::idiv, std::numeric_limits<int32_t>::min(), -1) == std::numeric_limits<int32_t>::min());
    CHECK(i2(Op::imod, 7, 0) == 0);
    CHECK(i2(Op::imod, 7, 3) == 1);
    CHECK(i2(Op::iadd, std::numeric_limits<int32_t>::max(), 1) == std::numeric_limits<int32_t>::min());
    CHECK(i2(Op::ilt, -1, 1) == 1);
    Kind k;
    std::vector<std::vector<uint32_t>> nan(1, std::vector<uint32_t>(kLanes, bits(std::nanf(""))));
    CHECK(run_op(Op::f2i, nan, &k)[0] == 0u);
    std::vector<std::vector<uint32_t>> big(1, std::vector<uint32_t>(kLanes, bits(-3e9f)));
    CHECK(int32_t(run_op(Op::f2i, big, &k)[0]) == std::numeric_limits<int32_t>::min());
    std::vector<std::vector<uint32_t>> neg(1, std::vector<uint32_t>(kLanes, bits(-2.7f)));
    CHECK(int32_t(run_op(Op::f2i, neg, &k)[0]) == -2);
}

TEST_CASE("writes under a partial mask keep the inactive lanes", "[runtime][mask]") {
    Builder b;
    Reg x = b.reg(Kind::F32), c = b.reg(Kind::Bool), y = b.reg(Kind::F32);
    b.if_(c, [&] { b.alu_to(y, Op::fadd, {x, x}); });
    Runner r(b.sh);
    r.setf(x, [](int i) { return float(i); });
    r.set(c, [](int i) { return uint32_t(i % 3 == 0); });
    r.setf(y, [](int) { return -5.0f; });
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) CHECK(r.f(y, i) == (i % 3 == 0 ? 2.0f * i : -5.0f));
}

TEST_CASE("lanes outside `live` are left alone", "[runtime][mask]") {
    Builder b;
    Reg x = b.reg(Kind::F32);
    b.set_konst(x, bits(9.0f));
    Runner r(b.sh);
    r.setf(x, [](int) { return 1.0f; });
    REQUIRE(r.run(0b1010));
    for (int i = 0; i < kLanes; ++i) CHECK(r.f(x, i) == (i == 1 || i == 3 ? 9.0f : 1.0f));
}

TEST_CASE("mov, konst and sel", "[runtime][special]") {
    Builder b;
    Reg x = b.reg(Kind::I32), c = b.reg(Kind::Bool);
    Reg k = b.ki(-4);
    Reg m = b.reg(Kind::I32);
    b.mov(m, x);
    Reg s = b.reg(Kind::I32);
    b.instr(Op::sel, Kind::I32, s, {c, x, k});
    Runner r(b.sh);
    r.set(x, [](int i) { return bits(int32_t(i * 10)); });
    r.set(c, [](int i) { return uint32_t(i & 1); });
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) {
        CHECK(r.i(k, i) == -4);
        CHECK(r.i(m, i) == i * 10);
        CHECK(r.i(s, i) == (i & 1 ? i * 10 : -4));
    }
}

TEST_CASE("uniforms and uniform_ind with clamping", "[runtime][special]") {
    Builder b;
    Reg idx = b.reg(Kind::I32);
    Reg u = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::F32, u, {}, {1});
    // an array of 3 vec2 at slot 2: element i component 1 at 2 + 1 + i*2
    Reg e = b.reg(Kind::F32);
    b.instr(Op::uniform_ind, Kind::F32, e, {idx}, {3, 3, 2});
    std::vector<uint32_t> store{bits(0.0f), bits(42.0f), bits(10.0f), bits(11.0f), bits(20.0f),
                                bits(21.0f), bits(30.0f), bits(31.0f)};
    Runner r(b.sh, store);
    r.set(idx, [](int i) { return bits(int32_t(i) - 3); });  // -3..12
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) {
        int want = std::clamp(i - 3, 0, 2);
        CHECK(r.f(u, i) == 42.0f);
        CHECK(r.f(e, i) == 11.0f + 10.0f * want);
    }
}

TEST_CASE("out-of-range load_ind/store_ind clamp", "[runtime][special]") {
    Builder b;
    Reg idx = b.reg(Kind::I32), val = b.reg(Kind::I32);
    Reg arr = b.range(Kind::I32, 4);
    Reg guard = b.reg(Kind::I32);
    b.set_konst(guard, 77);
    for (int e = 0; e < 4; ++e) b.set_konst(arr + e, uint32_t(100 + e));
    Reg loaded = b.reg(Kind::I32);
    b.instr(Op::load_ind, Kind::I32, loaded, {idx}, {arr, 4, 1});
    b.instr(Op::store_ind, Kind::I32, ir::kNoReg, {idx, val}, {arr, 4, 1});
    Runner r(b.sh);
    r.set(idx, [](int i) { return bits(int32_t(i) * 1000003 - 8000000); });
    r.set(val, [](int i) { return bits(int32_t(i)); });
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) {
        int32_t raw = int32_t(i) * 1000003 - 8000000;
        int want = raw < 0 ? 0 : (raw > 3 ? 3 : raw);
        CHECK(r.i(loaded, i) == 100 + want);
        for (int e = 0; e < 4; ++e) CHECK(r.i(arr + e, i) == (e == want ? i : 100 + e));
        CHECK(r.i(guard, i) == 77);
    }
}

TEST_CASE("store_ind only writes active lanes", "[runtime][special]") {
    Builder b;
    Reg idx = b.reg(Kind::I32), val = b.reg(Kind::F32), c = b.reg(Kind::Bool);
    Reg arr = b.range(Kind::F32, 3);
    b.if_(c, [&] { b.instr(Op::store_ind, Kind::F32, ir::kNoReg, {idx, val}, {arr, 3, 1}); });
    Runner r(b.sh);
    r.set(idx, [](int i) { return bits(int32_t(i % 3)); });
    r.setf(val, [](int i) { return float(i); });
    r.set(c, [](int i) { return uint32_t(i < 8); });
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i)
        for (int e = 0; e < 3; ++e) CHECK(r.f(arr + e, i) == (i < 8 && e == i % 3 ? float(i) : 0.0f));
}

TEST_CASE("ddx and ddy are fine derivatives within each quad", "[runtime][special]") {
    Builder b;
    Reg v = b.reg(Kind::F32);
    Reg dx = b.reg(Kind::F32), dy = b.reg(Kind::F32);
    b.instr(Op::ddx, Kind::F32, dx, {v});
    b.instr(Op::ddy, Kind::F32, dy, {v});
    Runner r(b.sh);
    // v = x*x + 3*y + quad, with lane 4q+k at x = k&1, y = k>>1
    auto value = [](int i) {
        int q = i / 4, x = (i & 1) + 2 * q, y = (i >> 1) & 1;
        return float(x * x + 3 * y * (q + 1) + 5 * x * y);
    };
    r.setf(v, value);
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) {
        int q = i / 4, k = i % 4, row = k >> 1, col = k & 1;
        float want_dx = value(4 * q + 2 * row + 1) - value(4 * q + 2 * row);
        float want_dy = value(4 * q + 2 + col) - value(4 * q + col);
        CHECK(r.f(dx, i) == want_dx);
        CHECK(r.f(dy, i) == want_dy);
    }
}
