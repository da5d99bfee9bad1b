// Issue #5, "numerical stability at the extremes": the results that an RGBA8
// probe cannot show (signed zeros, NaN bit patterns, exact values next to
// denormals), pinned bit for bit. tests/extremes/*.shader_test pin the
// classification (NaN / Inf / 0 / number) of many more cases on both glslrun
// and Mesa; docs/extremes.md has the table.
//
// Every lane gets a different special value (see kSpecials), so one run checks
// the whole list, in full and partial batches.
#include "harness.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

using namespace lang;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
float from_bits(uint32_t u) { return std::bit_cast<float>(u); }
uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }

// The inputs, lane by lane (cycled over kVerts lanes).
const float kSpecials[] = {
    0.0f, -0.0f, kInf, -kInf, from_bits(0x7fc00000u) /* +qNaN */, from_bits(0xffc00000u) /* -qNaN */,
    from_bits(0x00000001u) /* smallest denormal */, from_bits(0x80400000u) /* -2^-127, denormal */,
    1.0f, -1.0f, 0.5f, -0.5f, 1e20f, -1e20f, 3.4028235e38f, 1.17549435e-38f /* FLT_MIN */,
};
constexpr uint32_t kNumSpecials = sizeof kSpecials / sizeof kSpecials[0];
float special(uint32_t lane) { return kSpecials[lane % kNumSpecials]; }

// glslrun runs shaders with the SSE control bits FTZ and DAZ set
// (ir/scalar_ops.h FlushDenormals), and its built-ins are plain C++ and libm
// calls. The expected values are the same C++ computed under the same bits:
// arithmetic flushes denormal inputs and results; negation, abs, floor, ceil
// and the libm calls (which work on the bits, out of DAZ's reach) flush their
// operands and results explicitly (ir/scalar_ops.h ftz), as `ftz` does here.
class DenormalsFlushed {
public:
#if defined(__SSE__) || defined(__x86_64__)
    DenormalsFlushed() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
    ~DenormalsFlushed() { _mm_setcsr(saved_); }
private:
    unsigned saved_;
#endif
};

float ftz(float a) { return std::fabs(a) < 1.17549435e-38f ? std::copysign(0.0f, a) : a; }

std::string show(float f) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g (0x%08x)", double(f), bits(f));
    return buf;
}

// Bit-exact comparison, except that any NaN matches any NaN unless
// `exact_nan` asks for the exact bits (pow, a libm call, drops a NaN's sign).
bool same(float got, float want, bool exact_nan) {
    if (std::isnan(want) && !exact_nan) return std::isnan(got);
    return bits(got) == bits(want);
}

// Runs `expr` (a float expression of the attribute value `s`) on every lane
// and compares each lane with `want(s)`.
void check_lanes(const std::string& expr, float (*want)(float), bool exact_nan = false) {
    std::string vs = "attribute float s;\nvarying float r;\nvoid main() {\n    r = " + expr +
                     ";\n    gl_Position = vec4(0.0);\n}\n";
    auto attribs = std::vector{make_attrib("s", 1, kVerts, [](uint32_t l, uint32_t) { return special(l); })};
    Outputs out = eval_vs(vs, attribs, kVerts);
    int bad = 0;
    std::string report;
    for (uint32_t l = 0; l < kVerts; ++l) {
        float got = out.at("r", l), w;
        {
            DenormalsFlushed flushed;
            w = want(special(l));
        }
        if (same(got, w, exact_nan)) continue;
        if (++bad <= 8)
            report += "\n  lane " + std::to_string(l) + ": s = " + show(special(l)) + ": got " + show(got) +
                      ", want " + show(w);
    }
    INFO(expr << report);
    CHECK(bad == 0);
}

}  // namespace

TEST_CASE("extremes: signed zeros survive arithmetic and built-ins", "[extremes]") {
    check_lanes("-s", [](float s) { return ftz(-s); });
    check_lanes("s * 0.0", [](float s) { return s * 0.0f; });  // -1 * 0 = -0, Inf * 0 = NaN
    check_lanes("sqrt(s)", [](float s) { return std::sqrt(s); });  // sqrt(-0) = -0
    check_lanes("abs(s)", [](float s) { return ftz(std::fabs(s)); });
    check_lanes("floor(s)", [](float s) { return std::floor(ftz(s)); });
    check_lanes("ceil(s)", [](float s) { return std::ceil(ftz(s)); });  // ceil(-0.5) = -0
    check_lanes("1.0 / s", [](float s) { return 1.0f / s; });  // 1/-0 = -Inf, 1/-denormal = -Inf
}

TEST_CASE("extremes: the NaNs that glslrun creates are x86's default -qNaN", "[extremes]") {
    // 0/0, Inf-Inf, Inf*0 and sqrt(-1) give the SSE "indefinite" 0xffc00000,
    // as llvmpipe does; an input NaN passes through with its own bits.
    check_lanes("s / s", [](float s) {
        return s / s;  // 0/0, Inf/Inf: the SSE default NaN; a denormal reads as 0
    }, true);
    check_lanes("s - s", [](float s) {
        return s - s;
    }, true);
    check_lanes("abs(s)", [](float s) { return ftz(std::fabs(s)); }, true);  // clears a NaN's sign bit
}

TEST_CASE("extremes: issue #5's built-in cases, exactly", "[extremes]") {
    // pow follows C's powf: pow(0, 0) = 1, pow(x < 0, integer y) is defined.
    check_lanes("pow(s, 0.0)", [](float s) { return ftz(std::pow(ftz(s), 0.0f)); });
    check_lanes("pow(s, 2.0)", [](float s) { return ftz(std::pow(ftz(s), 2.0f)); });
    check_lanes("pow(s, -1.0)", [](float s) { return ftz(std::pow(ftz(s), -1.0f)); });  // pow(0,-1) = +Inf
    // atan(y, x) is C's atan2f: atan(0, 0) = 0, atan(0, -0) = pi, signs of zero kept.
    check_lanes("atan(s, 0.0)", [](float s) { return ftz(std::atan2(ftz(s), 0.0f)); });
    check_lanes("atan(0.0, s)", [](float s) { return ftz(std::atan2(0.0f, ftz(s))); });
    check_lanes("inversesqrt(s)", [](float s) { return 1.0f / std::sqrt(s); });
    check_lanes("log(s)", [](float s) { return ftz(std::log(ftz(s))); });
    check_lanes("mod(s, 0.0)", [](float s) { return s - 0.0f * std::floor(s / 0.0f); });
    check_lanes("normalize(vec3(s, 0.0, 0.0)).x", [](float s) {
        return s / std::sqrt(s * s);  // 0/0 = NaN for a zero vector, Inf/Inf = NaN for 1e20
    });
    // length squares its input: 1e20 and FLT_MAX overflow to +Inf instead of |s|.
    check_lanes("length(vec2(s, 0.0))", [](float s) { return std::sqrt(s * s); });
}

TEST_CASE("extremes: the bit patterns that docs/extremes.md quotes", "[extremes]") {
    // Written out, not computed, so that a change of libm or of the
    // interpreter's float environment shows here. Lane l reads kSpecials[l].
    struct Pin { const char* expr; float s; uint32_t want; };
    const Pin pins[] = {
        {"sqrt(s)", -0.0f, 0x80000000u},                  // -0
        {"s / s", 0.0f, 0xffc00000u},                     // the SSE default NaN
        {"pow(s, 0.0)", 0.0f, 0x3f800000u},               // pow(0, 0) = 1
        {"atan(0.0, s)", -0.0f, 0x40490fdbu},             // atan(0, -0) = pi
        {"atan(s, 0.0)", 0.0f, 0x00000000u},              // atan(0, 0) = 0
        {"-s", from_bits(0x00000001u), 0x80000000u},      // negation flushes a denormal: -0
        {"s * 1.0", from_bits(0x00000001u), 0x00000000u}, // arithmetic flushes it
        {"log(s)", from_bits(0x00000001u), 0xff800000u},  // the input is flushed: -Inf
        {"log2(s)", from_bits(0x00000001u), 0xff800000u}, // -Inf, as llvmpipe
        {"atan(s, 0.0)", from_bits(0x00000001u), 0x00000000u},  // atan(0, 0) = 0: flushed
        {"1.0 / s", 3.4028235e38f, 0x00000000u},          // 1/FLT_MAX is a denormal: flushed
    };
    for (const Pin& pin : pins) {
        uint32_t lane = 0;
        while (bits(special(lane)) != bits(pin.s)) ++lane;  // every pin's input is in kSpecials
        std::string vs = std::string("attribute float s;\nvarying float r;\nvoid main() {\n    r = ") + pin.expr +
                         ";\n    gl_Position = vec4(0.0);\n}\n";
        auto attribs = std::vector{make_attrib("s", 1, kVerts, [](uint32_t l, uint32_t) { return special(l); })};
        Outputs out = eval_vs(vs, attribs, kVerts);
        INFO(pin.expr << " with s = " << show(pin.s) << ": got " << show(out.at("r", lane)));
        CHECK(bits(out.at("r", lane)) == pin.want);
    }
}

TEST_CASE("extremes: a loop bounded by +Inf stops with an error instead of hanging", "[extremes]") {
    // t < +Inf is always true (and t += 1.0 stops growing at 2^24), so the
    // loop never ends; GPUs and llvmpipe would hang. Lanes with a finite bound
    // share the batch with lanes bounded by +Inf.
    glslrun::Program prog = compile_vs(R"(
attribute float s;
varying float r;
void main() {
    float n = 0.0;
    for (float t = 0.0; t < s; t += 1.0) n += 1.0;
    r = n;
    gl_Position = vec4(0.0);
}
)");
    prog.exec.max_loop_iterations = 100000;
    auto finite = std::vector{make_attrib("s", 1, kVerts, [](uint32_t l, uint32_t) { return float(l % 5); })};
    auto ok = glslrun::run_vertices(prog, finite, kVerts);
    REQUIRE(ok);
    auto infinite = std::vector{make_attrib("s", 1, kVerts, [](uint32_t l, uint32_t) {
        return l % 3 == 0 ? kInf : float(l % 5);
    })};
    auto result = glslrun::run_vertices(prog, infinite, kVerts);
    REQUIRE_FALSE(result);
    INFO(result.error().str());
    CHECK(result.error().str().find("loop exceeded 100000 iterations") != std::string::npos);
}
