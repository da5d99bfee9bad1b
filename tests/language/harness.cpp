#include "harness.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace lang {

glm::vec4 in_a(uint32_t lane) {
    float l = float(lane);
    return {-3.05f + 0.17f * l, 2.5f * std::sin(0.7f * l + 0.3f), 1.27f - 0.09f * l,
            0.5f * std::cos(1.3f * l) + 0.05f * l - 0.93f};
}

glm::vec4 in_b(uint32_t lane) {
    float l = float(lane);
    return {0.25f + 0.11f * l, 3.9f - 0.1f * l, 1.0f + 0.5f * std::sin(l), 0.1f + 0.023f * l};
}

glm::vec4 in_c(uint32_t lane) {
    return {float(int(lane % 7) - 3), float(int((lane * 5) % 9) - 4), float(lane % 4),
            float(int((lane / 3) % 5) - 2)};
}

float b2f(bool b) { return b ? 1.0f : 0.0f; }

glm::vec2 frag_xy(uint32_t i) {
    uint32_t q = i / 4, k = i % 4;
    return {float(2 * (q % 5) + (k & 1)), float(2 * (q / 5) + (k >> 1))};
}

glslrun::VertexAttrib make_attrib(std::string name, uint32_t components, uint32_t count,
                                  const std::function<float(uint32_t, uint32_t)>& value) {
    glslrun::VertexAttrib attrib{std::move(name), components, {}};
    attrib.data.reserve(size_t(count) * components);
    for (uint32_t lane = 0; lane < count; ++lane)
        for (uint32_t c = 0; c < components; ++c) attrib.data.push_back(value(lane, c));
    return attrib;
}

std::vector<glslrun::VertexAttrib> std_attribs(uint32_t count) {
    return {make_attrib("a", 4, count, [](uint32_t l, uint32_t c) { return in_a(l)[c]; }),
            make_attrib("b", 4, count, [](uint32_t l, uint32_t c) { return in_b(l)[c]; }),
            make_attrib("c", 4, count, [](uint32_t l, uint32_t c) { return in_c(l)[c]; })};
}

namespace {

std::string numbered(const std::string& src) {
    std::ostringstream out;
    std::istringstream in(src);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) out << n << ": " << line << "\n";
    return out.str();
}

// "#version 120\n" when the shader starts with one, so the helper stage matches.
std::string version_line(const std::string& src) {
    auto start = src.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || src.compare(start, 8, "#version") != 0) return {};
    auto end = src.find('\n', start);
    return src.substr(start, end - start) + "\n";
}

std::string glsl_vec_type(uint32_t components) {
    return components == 1 ? "float" : "vec" + std::to_string(components);
}

}  // namespace

// The suite can rerun with the optimizer or the inliner off (both paths
// must give the same results): GLSLRUN_LANG_OPTIMIZE=0, GLSLRUN_LANG_INLINE_BUDGET=0.
static glslrun::CompileOptions with_env_overrides(glslrun::CompileOptions options) {
    if (const char* opt = std::getenv("GLSLRUN_LANG_OPTIMIZE")) options.optimize = std::atoi(opt) != 0;
    if (const char* budget = std::getenv("GLSLRUN_LANG_INLINE_BUDGET"))
        options.inline_budget = uint32_t(std::strtoul(budget, nullptr, 10));
    return options;
}

// And in another precision mode: GLSLRUN_LANG_PRECISION=reference|fast (the
// comparisons then allow kModeTolerance, see check_output).
glslrun::Precision suite_precision() {
    const char* name = std::getenv("GLSLRUN_LANG_PRECISION");
    if (!name) return glslrun::Precision::Precise;
    auto parsed = glslrun::parse_precision(name);
    if (!parsed) FAIL("GLSLRUN_LANG_PRECISION: " << parsed.error().str());
    return *parsed;
}

// And on one backend: GLSLRUN_LANG_BACKEND=interp|jit|auto (default jit
// where built in: auto would run most of these one-draw programs on the
// interpreter while LLVM compiles).
glslrun::Backend suite_backend() {
    const char* name = std::getenv("GLSLRUN_LANG_BACKEND");
    if (!name) return glslrun::jit_available() ? glslrun::Backend::Jit : glslrun::Backend::Interp;
    auto parsed = glslrun::parse_backend(name);
    if (!parsed) FAIL("GLSLRUN_LANG_BACKEND: " << parsed.error().str());
    return *parsed;
}

glslrun::Program compile_or_fail(const std::string& vs, const std::string& fs,
                                 const glslrun::CompileOptions& options) {
    auto result = glslrun::Program::compile({{"test.vert", vs}}, {{"test.frag", fs}},
                                            with_env_overrides(options));
    if (!result) {
        FAIL("compile failed:\n" << result.error().str() << "\n--- vertex shader:\n" << numbered(vs)
                                 << "--- fragment shader:\n" << numbered(fs));
    }
    result->exec.precision = suite_precision();
    result->exec.backend = suite_backend();
    return std::move(result.value());
}

glslrun::Program compile_vs(const std::string& vs) {
    return compile_or_fail(vs, version_line(vs) + "void main() { gl_FragColor = vec4(0.0); }\n");
}

glslrun::Program compile_fs(const std::string& fs, const std::vector<glslrun::VertexAttrib>& inputs) {
    std::string decls, writes;
    for (const auto& input : inputs) {
        if (input.name.rfind("gl_", 0) == 0) continue;
        std::string type = glsl_vec_type(input.components);
        decls += "varying " + type + " " + input.name + ";\n";
        writes += "    " + input.name + " = " + type + "(0.0);\n";
    }
    std::string vs = version_line(fs) + decls + "void main() {\n" + writes +
                     "    gl_Position = vec4(0.0);\n}\n";
    return compile_or_fail(vs, fs);
}

Outputs::Outputs(std::vector<glslrun::ShaderOutput> outputs, uint32_t count)
    : outputs_(std::move(outputs)), count_(count) {}

bool Outputs::has(std::string_view name) const {
    for (const auto& o : outputs_)
        if (o.name == name) return true;
    return false;
}

std::string Outputs::names() const {
    std::string s;
    for (const auto& o : outputs_) s += o.name + "(" + std::to_string(o.components) + ") ";
    return s;
}

const glslrun::ShaderOutput& Outputs::get(std::string_view name) const {
    for (const auto& o : outputs_) {
        if (o.name != name) continue;
        if (o.data.size() != size_t(o.components) * count_)
            FAIL("output " << name << " has " << o.data.size() << " values, expected "
                           << o.components << " x " << count_);
        return o;
    }
    FAIL("no output named " << name << "; outputs: " << names());
    return outputs_.front();  // not reached: FAIL throws
}

float Outputs::at(std::string_view name, uint32_t lane, uint32_t comp) const {
    const auto& o = get(name);
    REQUIRE(comp < o.components);
    return o.data[size_t(lane) * o.components + comp];
}

glm::vec4 Outputs::vec(std::string_view name, uint32_t lane) const {
    const auto& o = get(name);
    glm::vec4 v(0.0f);
    for (uint32_t c = 0; c < o.components && c < 4; ++c) v[c] = o.data[size_t(lane) * o.components + c];
    return v;
}

Outputs run_vs(const glslrun::Program& program, const std::vector<glslrun::VertexAttrib>& attribs,
               uint32_t count) {
    auto result = glslrun::run_vertices(program, attribs, count);
    if (!result) FAIL("run_vertices failed:\n" << result.error().str());
    return Outputs(std::move(result.value()), count);
}

Outputs run_fs(const glslrun::Program& program, const std::vector<glslrun::VertexAttrib>& inputs,
               uint32_t count) {
    auto result = glslrun::run_fragments(program, inputs, count);
    if (!result) FAIL("run_fragments failed:\n" << result.error().str());
    return Outputs(std::move(result.value()), count);
}

Outputs eval_vs(const std::string& vs, uint32_t count) {
    return eval_vs(vs, std_attribs(count), count);
}

Outputs eval_vs(const std::string& vs, const std::vector<glslrun::VertexAttrib>& attribs, uint32_t count) {
    auto program = compile_vs(vs);
    return run_vs(program, attribs, count);
}

Outputs eval_fs(const std::string& fs, const std::vector<glslrun::VertexAttrib>& inputs, uint32_t count) {
    auto program = compile_fs(fs, inputs);
    return run_fs(program, inputs, count);
}

int count_mismatches(const Outputs& outs, std::string_view name, uint32_t components,
                     const Expected& expected, float tol, std::string* report) {
    const auto& out = outs.get(name);
    REQUIRE(out.components >= components);
    std::ostringstream text;
    text.precision(9);
    int bad = 0;
    for (uint32_t lane = 0; lane < outs.count(); ++lane) {
        glm::vec4 want = expected(lane);
        for (uint32_t c = 0; c < components; ++c) {
            float got = out.data[size_t(lane) * out.components + c];
            float w = want[c];
            bool ok = tol == 0.0f ? got == w
                                  : std::fabs(got - w) <= tol * std::max(1.0f, std::fabs(w));
            if (ok) continue;
            if (++bad <= 8)
                text << "  lane " << lane << " ." << "xyzw"[c] << ": got " << got << ", want " << w << "\n";
        }
    }
    if (report) *report = text.str();
    return bad;
}

void check_output(const Outputs& outs, std::string_view name, uint32_t components,
                  const Expected& expected, float tol) {
    // The expectations are fp32 results (C++ floats, libm), exact for most
    // tests: another mode may differ from them by its own error.
    if (suite_precision() != glslrun::Precision::Precise) tol = std::max(tol, kModeTolerance);
    std::string report;
    int bad = count_mismatches(outs, name, components, expected, tol, &report);
    INFO("output '" << std::string(name) << "': " << bad << " mismatches\n" << report);
    CHECK(bad == 0);
}

}  // namespace lang
