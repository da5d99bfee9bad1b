// GLSL 1.10 §8.1-8.3: angle, trigonometry, exponential and common functions,
// every genType overload (float, vec2, vec3, vec4) and every mixed
// (genType, float) form, driven by one table.
#include "harness.h"

#include <cmath>
#include <sstream>

using namespace lang;

namespace {

// One argument: a vec4 GLSL expression over the attributes and its C++ value.
struct ArgSource {
    std::string glsl;
    std::function<glm::vec4(uint32_t lane)> value;
};

using ScalarFn = std::function<float(float, float, float)>;

struct BuiltinCase {
    std::string name;
    std::vector<ArgSource> args;
    // Each form says which arguments are scalar (`S`) and which genType (`V`),
    // e.g. {"VV", "VS"} for mod(genType, genType) and mod(genType, float).
    std::vector<std::string> forms;
    ScalarFn fn;
    float tol;
};

const ArgSource kA{"a", in_a};
const ArgSource kB{"b", in_b};
const ArgSource kQuarterA{"(a * 0.25)", [](uint32_t l) { return in_a(l) * 0.25f; }};
const ArgSource kNegB{"(-b)", [](uint32_t l) { return -in_b(l); }};
const ArgSource kBSwapped{"b.yxwz", [](uint32_t l) {
    glm::vec4 b = in_b(l);
    return glm::vec4(b.y, b.x, b.w, b.z);
}};
const ArgSource kARot{"a.yzwx", [](uint32_t l) {
    glm::vec4 a = in_a(l);
    return glm::vec4(a.y, a.z, a.w, a.x);
}};
const ArgSource kFifthB{"(b * 0.2)", [](uint32_t l) { return in_b(l) * 0.2f; }};
const ArgSource kAPlusHalf{"(a + vec4(0.5, -0.5, 0.0, 1.5))", [](uint32_t l) {
    return in_a(l) + glm::vec4(0.5f, -0.5f, 0.0f, 1.5f);
}};

std::string slice(const std::string& expr, uint32_t n, bool scalar) {
    if (scalar || n == 1) return expr + ".x";
    static const char* const kSwz[] = {"", ".x", ".xy", ".xyz", ""};
    return expr + kSwz[n];
}

std::string out_name(size_t form, uint32_t n) {
    return "r" + std::to_string(form) + "_" + std::to_string(n);
}

std::string build_shader(const BuiltinCase& bc) {
    std::ostringstream decls, body;
    decls << "attribute vec4 a, b, c;\n";
    for (size_t f = 0; f < bc.forms.size(); ++f) {
        for (uint32_t n = 1; n <= 4; ++n) {
            decls << "varying " << (n == 1 ? std::string("float") : "vec" + std::to_string(n)) << " "
                  << out_name(f, n) << ";\n";
            body << "    " << out_name(f, n) << " = " << bc.name << "(";
            for (size_t i = 0; i < bc.args.size(); ++i)
                body << (i ? ", " : "") << slice(bc.args[i].glsl, n, bc.forms[f][i] == 'S');
            body << ");\n";
        }
    }
    return decls.str() + "void main() {\n" + body.str() + "    gl_Position = vec4(0.0);\n}\n";
}

void run_case(const BuiltinCase& bc) {
    std::string src = build_shader(bc);
    INFO("shader:\n" << src);
    auto outs = eval_vs(src);
    for (size_t f = 0; f < bc.forms.size(); ++f) {
        for (uint32_t n = 1; n <= 4; ++n) {
            check_output(outs, out_name(f, n), n, [&](uint32_t lane) {
                glm::vec4 v[3];
                for (size_t i = 0; i < bc.args.size(); ++i) {
                    v[i] = bc.args[i].value(lane);
                    if (bc.forms[f][i] == 'S') v[i] = glm::vec4(v[i].x);
                }
                glm::vec4 r;
                for (int k = 0; k < 4; ++k) r[k] = bc.fn(v[0][k], v[1][k], v[2][k]);
                return r;
            }, bc.tol);
        }
    }
}

void run_table(const std::vector<BuiltinCase>& table) {
    for (const auto& bc : table) {
        DYNAMIC_SECTION(bc.name << "/" << bc.args.size() << " args") { run_case(bc); }
    }
}

float glsl_mod(float x, float y) { return x - y * std::floor(x / y); }
float glsl_sign(float x) { return x > 0 ? 1.0f : x < 0 ? -1.0f : 0.0f; }
float glsl_smoothstep(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

TEST_CASE("angle and trigonometry functions", "[builtins]") {
    const float pi = 3.14159265358979f;
    run_table({
        {"radians", {kA}, {"V"}, [=](float x, float, float) { return x * pi / 180.0f; }, kLoose},
        {"degrees", {kA}, {"V"}, [=](float x, float, float) { return x * 180.0f / pi; }, kLoose},
        {"sin", {kA}, {"V"}, [](float x, float, float) { return std::sin(x); }, kLoose},
        {"cos", {kA}, {"V"}, [](float x, float, float) { return std::cos(x); }, kLoose},
        {"tan", {kQuarterA}, {"V"}, [](float x, float, float) { return std::tan(x); }, kLoose},
        {"asin", {kQuarterA}, {"V"}, [](float x, float, float) { return std::asin(x); }, kLoose},
        {"acos", {kQuarterA}, {"V"}, [](float x, float, float) { return std::acos(x); }, kLoose},
        {"atan", {kA}, {"V"}, [](float x, float, float) { return std::atan(x); }, kLoose},
        // atan(y, x) over all four quadrants
        {"atan", {kA, kARot}, {"VV"}, [](float y, float x, float) { return std::atan2(y, x); }, kLoose},
    });
}

TEST_CASE("exponential functions", "[builtins]") {
    run_table({
        {"pow", {kB, kA}, {"VV"}, [](float x, float y, float) { return std::pow(x, y); }, kLoose},
        {"exp", {kA}, {"V"}, [](float x, float, float) { return std::exp(x); }, kLoose},
        {"log", {kB}, {"V"}, [](float x, float, float) { return std::log(x); }, kLoose},
        {"exp2", {kA}, {"V"}, [](float x, float, float) { return std::exp2(x); }, kLoose},
        {"log2", {kB}, {"V"}, [](float x, float, float) { return std::log2(x); }, kLoose},
        {"sqrt", {kB}, {"V"}, [](float x, float, float) { return std::sqrt(x); }, kLoose},
        {"inversesqrt", {kB}, {"V"}, [](float x, float, float) { return 1.0f / std::sqrt(x); }, kLoose},
    });
}

TEST_CASE("common functions", "[builtins]") {
    run_table({
        {"abs", {kA}, {"V"}, [](float x, float, float) { return std::fabs(x); }, kExact},
        {"sign", {kAPlusHalf}, {"V"}, [](float x, float, float) { return glsl_sign(x); }, kExact},
        {"floor", {kA}, {"V"}, [](float x, float, float) { return std::floor(x); }, kExact},
        {"ceil", {kA}, {"V"}, [](float x, float, float) { return std::ceil(x); }, kExact},
        {"fract", {kA}, {"V"}, [](float x, float, float) { return x - std::floor(x); }, kTight},
        {"mod", {kA, kB}, {"VV", "VS"}, [](float x, float y, float) { return glsl_mod(x, y); }, 1e-5f},
        {"min", {kA, kARot}, {"VV", "VS"}, [](float x, float y, float) { return std::min(x, y); }, kExact},
        {"max", {kA, kARot}, {"VV", "VS"}, [](float x, float y, float) { return std::max(x, y); }, kExact},
        {"clamp", {kA, kNegB, kBSwapped}, {"VVV", "VSS"},
         [](float x, float lo, float hi) { return std::min(std::max(x, lo), hi); }, kExact},
        {"mix", {kA, kARot, kFifthB}, {"VVV", "VVS"},
         [](float x, float y, float t) { return x * (1.0f - t) + y * t; }, 1e-5f},
        {"step", {kARot, kA}, {"VV", "SV"},
         [](float edge, float x, float) { return x < edge ? 0.0f : 1.0f; }, kExact},
        {"smoothstep", {kNegB, kBSwapped, kA}, {"VVV", "SSV"},
         [](float e0, float e1, float x) { return glsl_smoothstep(e0, e1, x); }, 1e-5f},
    });
}

TEST_CASE("sign of zero and negative zero inputs, fract of negatives", "[builtins]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o1, o2;
void main() {
    o1 = sign(c);                      // c holds exact zeros on some lanes
    o2 = fract(c * 0.5 - 0.25);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l), r;
        for (int k = 0; k < 4; ++k) r[k] = glsl_sign(c[k]);
        return r;
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        glm::vec4 x = in_c(l) * 0.5f - 0.25f;
        return x - glm::floor(x);
    }, kExact);
}
