// The Precise mode's built-ins (ir/precise_math.h): ULP error against libm's
// double functions over the whole float range, special values against
// glibc's float functions, bit-exact agreement between the interpreter's
// lanes (AVX2 or baseline kernels) and the scalar functions, and a pinned
// hash of the outputs so that a compiler or machine that changes one bit fails.
#include <catch2/catch.hpp>

#include "ir/precise_math.h"
#include "ir/scalar_ops.h"
#include "tests/ir/math_sweep.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;
using namespace glslrun::test::mathsweep;

namespace {

using FloatFn = float (*)(float);
using DoubleFn = double (*)(double);
using FloatFn2 = float (*)(float, float);
using DoubleFn2 = double (*)(double, double);

struct Unary {
    const char* name;
    Op op;
    FloatFn precise;
    DoubleFn reference;
    FloatFn glibc;
    float lo, hi;  // the swept domain
};

// |x| below this the sin/cos/tan reduction is exact (ir/precise_math.h).
constexpr float kTrigRange = 8.4e8f;

const Unary kUnary[] = {
    {"exp", Op::fexp, [](float x) { return math::exp(x); }, [](double x) { return std::exp(x); },
     [](float x) { return std::exp(x); }, -kInf, kInf},
    {"exp2", Op::fexp2, [](float x) { return math::exp2(x); }, [](double x) { return std::exp2(x); },
     [](float x) { return std::exp2(x); }, -kInf, kInf},
    {"log", Op::flog, [](float x) { return math::log(x); }, [](double x) { return std::log(x); },
     [](float x) { return std::log(x); }, 0x1p-126f, kInf},
    {"log2", Op::flog2, [](float x) { return math::log2(x); }, [](double x) { return std::log2(x); },
     [](float x) { return std::log2(x); }, 0x1p-126f, kInf},
    {"sin", Op::fsin, [](float x) { return math::sin(x); }, [](double x) { return std::sin(x); },
     [](float x) { return std::sin(x); }, -kTrigRange, kTrigRange},
    {"cos", Op::fcos, [](float x) { return math::cos(x); }, [](double x) { return std::cos(x); },
     [](float x) { return std::cos(x); }, -kTrigRange, kTrigRange},
    {"tan", Op::ftan, [](float x) { return math::tan(x); }, [](double x) { return std::tan(x); },
     [](float x) { return std::tan(x); }, -kTrigRange, kTrigRange},
    {"asin", Op::fasin, [](float x) { return math::asin(x); }, [](double x) { return std::asin(x); },
     [](float x) { return std::asin(x); }, -1.0f, 1.0f},
    {"acos", Op::facos, [](float x) { return math::acos(x); }, [](double x) { return std::acos(x); },
     [](float x) { return std::acos(x); }, -1.0f, 1.0f},
    {"atan", Op::fatan, [](float x) { return math::atan(x); }, [](double x) { return std::atan(x); },
     [](float x) { return std::atan(x); }, -kInf, kInf},
};

struct Binary {
    const char* name;
    Op op;
    FloatFn2 precise;
    DoubleFn2 reference;
    FloatFn2 glibc;
};
const Binary kPow = {"pow", Op::fpow, [](float x, float y) { return math::pow(x, y); },
                     [](double x, double y) { return std::pow(x, y); }, [](float x, float y) { return std::pow(x, y); }};
const Binary kAtan2 = {"atan2", Op::fatan2, [](float y, float x) { return math::atan2(y, x); },
                       [](double y, double x) { return std::atan2(y, x); },
                       [](float y, float x) { return std::atan2(y, x); }};

// The documented bound (docs/precision.md): every function rounds a double
// result that is within 2^-40 relative, so at most 0.5 + 2^-16 ULP.
constexpr double kMaxUlp = 0.5 + 0x1p-16;

bool normal_or_zero_result(double ref) { return ref == 0.0 || !(std::fabs(ref) < 0x1p-126); }

void sweep_unary(const Unary& f, uint32_t stride, UlpStats& stats) {
    auto check = [&](float x) {
        if (!(x >= f.lo && x <= f.hi) || is_denormal(x)) return;
        const double ref = f.reference(double(x));
        if (normal_or_zero_result(ref)) stats.add(ulp_error(f.precise(x), ref), x);
    };
    every_float(stride, check);
    // Dense where the functions are used most (and log is near 0).
    floats_in(-4.0f, 4.0f, (int64_t(1) << 32) / stride, check);
    floats_in(0.99f, 1.01f, (int64_t(1) << 32) / stride, check);
}

// pow over x > 0 with |y| in [2^-8, 2^9), and x near 1 with large |y|.
void sweep_pow(uint32_t count, UlpStats& stats) {
    Lcg rng{1};
    auto check = [&](float x, float y) {
        const double ref = std::pow(double(x), double(y));
        if (normal_or_zero_result(ref) && ref != 0.0) stats.add(ulp_error(math::pow(x, y), ref), x);
    };
    for (uint32_t i = 0; i < count; ++i) {
        const float x = std::bit_cast<float>(rng.next() % 0x7F800000u);
        const uint32_t h = rng.next();
        check(x, std::bit_cast<float>((h & 0x807FFFFFu) | ((119u + (h >> 24) % 18u) << 23)));
        check(1.0f + float(int32_t(h >> 8) - (1 << 23)) * 0x1p-26f, float(int32_t(rng.next() % 20001u) - 10000));
    }
}

void sweep_atan2(uint32_t count, UlpStats& stats) {
    Lcg rng{2};
    for (uint32_t i = 0; i < count; ++i) {
        const float y = std::bit_cast<float>(rng.next()), x = std::bit_cast<float>(rng.next());
        if (std::isnan(x) || std::isnan(y) || is_denormal(x) || is_denormal(y)) continue;
        const double ref = std::atan2(double(y), double(x));
        if (normal_or_zero_result(ref)) stats.add(ulp_error(math::atan2(y, x), ref), y);
    }
}

// glibc's results on special inputs, as the opcodes see them (operands and
// results flushed): the same bits for NaN, Inf, zeros and domain errors, and
// within glibc's own error (1.5 ULP, atan2f) elsewhere. (Near-ties differ:
// pow(1 + 2^-23, 0.5) is 2^-26 ULP below a tie, which glibc rounds right
// and glslrun, with a 2^-46 error, does not.)
void check_against_glibc(const char* name, float ours, float theirs, float x, float y) {
    INFO(name << "(" << x << ", " << y << ") = " << ours << " (0x" << std::hex << std::bit_cast<uint32_t>(ours)
              << "), glibc " << theirs << " (0x" << std::bit_cast<uint32_t>(theirs) << ")");
    const bool exact = std::isnan(theirs) || std::isinf(theirs) || theirs == 0.0f;
    if (exact) CHECK(std::bit_cast<uint32_t>(ours) == std::bit_cast<uint32_t>(theirs));
    else CHECK(ulp_error(ours, double(theirs)) <= 1.5);
}

uint64_t fnv1a(uint64_t h, uint32_t word) {
    for (int i = 0; i < 4; ++i) h = (h ^ ((word >> (8 * i)) & 0xFFu)) * 0x100000001B3ull;
    return h;
}

}  // namespace

TEST_CASE("precise built-ins stay within their ULP bound over the float range", "[ir][math]") {
    for (const Unary& f : kUnary) {
        UlpStats stats;
        sweep_unary(f, 2039, stats);
        INFO(f.name << ": max " << stats.max << " ULP at " << stats.worst << ", " << stats.count << " inputs");
        CHECK(stats.count > 1000000);
        CHECK(stats.max <= kMaxUlp);
    }
    UlpStats pow_stats, atan2_stats;
    sweep_pow(400000, pow_stats);
    sweep_atan2(1000000, atan2_stats);
    INFO("pow: max " << pow_stats.max << " ULP at x = " << pow_stats.worst);
    INFO("atan2: max " << atan2_stats.max << " ULP at y = " << atan2_stats.worst);
    CHECK(pow_stats.count > 400000);
    CHECK(pow_stats.max <= kMaxUlp);
    CHECK(atan2_stats.count > 900000);
    CHECK(atan2_stats.max <= kMaxUlp);
}

TEST_CASE("precise built-ins give glibc's special values", "[ir][math]") {
    const std::vector<float> special = special_inputs();
    for (const Unary& f : kUnary)
        for (float x : special)
            if (!(std::fabs(x) > kTrigRange && std::fabs(x) < kInf && f.hi == kTrigRange))  // glibc reduces exactly there
                check_against_glibc(f.name, ir::ftz(f.precise(ir::ftz(x))), ir::ftz(f.glibc(ir::ftz(x))), x, 0.0f);
    for (const Binary* f : {&kPow, &kAtan2})
        for (float x : special)
            for (float y : special)
                check_against_glibc(f->name, ir::ftz(f->precise(ir::ftz(x), ir::ftz(y))),
                                    ir::ftz(f->glibc(ir::ftz(x), ir::ftz(y))), x, y);
    // C99 Annex F's cases, spelled out.
    CHECK(math::pow(0.0f, 0.0f) == 1.0f);
    CHECK(math::pow(0.0f, -1.0f) == kInf);
    CHECK(math::pow(-0.0f, -3.0f) == -kInf);
    CHECK(math::pow(-2.0f, 3.0f) == -8.0f);
    CHECK(math::pow(-2.0f, 2.0f) == 4.0f);
    CHECK(std::isnan(math::pow(-8.0f, 1.0f / 3.0f)));
    CHECK(math::pow(-1.0f, kInf) == 1.0f);
    CHECK(math::pow(1.0f, std::numeric_limits<float>::quiet_NaN()) == 1.0f);
    CHECK(std::bit_cast<uint32_t>(math::atan2(0.0f, -0.0f)) == std::bit_cast<uint32_t>(3.14159274f));
    CHECK(std::bit_cast<uint32_t>(math::atan2(-0.0f, 0.0f)) == std::bit_cast<uint32_t>(-0.0f));
}

// The interpreter inlines the functions into vectorized lane loops (AVX2 when
// the CPU has it); every lane must hold the scalar function's bits.
TEST_CASE("interpreter lanes compute the precise built-ins bit for bit", "[ir][math]") {
    Builder b;
    const Reg x = b.reg(Kind::F32), y = b.reg(Kind::F32);
    b.input("x", x);
    b.input("y", y);
    std::vector<Reg> outs;
    for (const Unary& f : kUnary) outs.push_back(b.alu(f.op, {x}));
    outs.push_back(b.alu(Op::fpow, {x, y}));
    outs.push_back(b.alu(Op::fatan2, {y, x}));
    for (Reg r : outs) b.output("out", r);
    const std::vector<float> special = special_inputs();
    Lcg rng{3};
    for (int batch = 0; batch < 64; ++batch) {
        Runner run(b.sh);
        std::vector<float> xs(rt::kLanes), ys(rt::kLanes);
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            // Half the lanes special inputs, half random floats of every magnitude.
            const uint32_t pick = rng.next();
            xs[lane] = lane % 2 ? special[pick % special.size()] : std::bit_cast<float>(rng.next());
            ys[lane] = lane % 3 ? float(int32_t(pick % 9u) - 4) * 0.75f : std::bit_cast<float>(rng.next());
        }
        run.setf(x, [&](int lane) { return xs[lane]; });
        run.setf(y, [&](int lane) { return ys[lane]; });
        REQUIRE(run.run());
        ir::FlushDenormals flush;  // as the interpreter runs
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            const float a = ir::ftz(xs[lane]), c = ir::ftz(ys[lane]);
            for (size_t i = 0; i < std::size(kUnary); ++i) {
                INFO(kUnary[i].name << "(" << xs[lane] << ") lane " << lane);
                CHECK(run.at(outs[i], lane) == std::bit_cast<uint32_t>(ir::ftz(kUnary[i].precise(a))));
            }
            INFO("pow/atan2 (" << xs[lane] << ", " << ys[lane] << ") lane " << lane);
            CHECK(run.at(outs[std::size(kUnary)], lane) == std::bit_cast<uint32_t>(ir::ftz(math::pow(a, c))));
            CHECK(run.at(outs[std::size(kUnary) + 1], lane) == std::bit_cast<uint32_t>(ir::ftz(math::atan2(c, a))));
        }
    }
}

// The interpreter's fpow kernel computes pow_common where pow_is_common and
// pow elsewhere (math::pow_batch): the two must agree bit for bit there.
TEST_CASE("pow's common case gives pow's bits", "[ir][math]") {
    ir::FlushDenormals flush;
    Lcg rng{5};
    const std::vector<float> special = special_inputs();
    uint32_t common = 0;
    auto check = [&](float x, float y) {
        if (!math::pow_is_common(x, y)) return;
        ++common;
        INFO("pow(" << x << ", " << y << ")");
        CHECK(std::bit_cast<uint32_t>(math::pow_common(x, y)) == std::bit_cast<uint32_t>(math::pow(x, y)));
    };
    for (float x : special)
        for (float y : special) check(ir::ftz(x), ir::ftz(y));
    for (int i = 0; i < 200000; ++i) {
        const float x = std::bit_cast<float>(rng.next()), y = std::bit_cast<float>(rng.next());
        check(std::fabs(x), y);
        check(std::fabs(x), float(int32_t(rng.next() % 61u) - 30) * 0.25f);
        check(0.0f, y);
        check(1.0f, y);
    }
    CHECK(common > 600000);
    // Whole batches: all common (the fast path), and one rare lane among them.
    for (int batch = 0; batch < 1000; ++batch) {
        float xs[rt::kLanes], ys[rt::kLanes], out[rt::kLanes];
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            xs[lane] = lane % 5 == 0 ? 0.0f : std::fabs(std::bit_cast<float>(rng.next() & 0x7F7FFFFFu));
            ys[lane] = float(int32_t(rng.next() % 257u) - 128) * 0.5f;
        }
        if (batch % 2) xs[rng.next() % rt::kLanes] = special[rng.next() % special.size()];
        math::pow_batch<rt::kLanes>(xs, ys, out);
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            INFO("pow_batch(" << xs[lane] << ", " << ys[lane] << ") lane " << lane);
            CHECK(std::bit_cast<uint32_t>(out[lane]) == std::bit_cast<uint32_t>(math::pow(xs[lane], ys[lane])));
        }
    }
}

// If this fails, some function's bits changed: on purpose (update the hash
// and say so in docs/precision.md) or through a compiler or machine
// difference (a determinism bug).
TEST_CASE("precise built-ins' outputs are pinned", "[ir][math]") {
    ir::FlushDenormals flush;
    uint64_t h = 0xCBF29CE484222325ull;
    const std::vector<float> special = special_inputs();
    std::vector<float> inputs = special;
    every_float(65521, [&](float x) { inputs.push_back(x); });
    for (float x : inputs)
        for (const Unary& f : kUnary) h = fnv1a(h, std::bit_cast<uint32_t>(ir::ftz(f.precise(ir::ftz(x)))));
    for (float x : special)
        for (float y : special) {
            h = fnv1a(h, std::bit_cast<uint32_t>(ir::ftz(math::pow(ir::ftz(x), ir::ftz(y)))));
            h = fnv1a(h, std::bit_cast<uint32_t>(ir::ftz(math::atan2(ir::ftz(x), ir::ftz(y)))));
        }
    Lcg rng{4};
    for (int i = 0; i < 20000; ++i) {
        const float x = std::bit_cast<float>(rng.next()), y = float(int32_t(rng.next() % 61u) - 30) * 0.25f;
        h = fnv1a(h, std::bit_cast<uint32_t>(ir::ftz(math::pow(ir::ftz(std::fabs(x)), y))));
        h = fnv1a(h, std::bit_cast<uint32_t>(ir::ftz(math::atan2(ir::ftz(x), ir::ftz(y)))));
    }
    INFO("output hash 0x" << std::hex << h);
    CHECK(h == 0x06b2c4d7114086f4ull);
}
