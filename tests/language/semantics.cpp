// Pins the choices of docs/semantics.md where GLSL leaves results open:
// NaN in min/max, denormal flushing, integer division by zero, int() of huge
// values. Inputs come from uniforms and attributes so nothing is folded away.
#include "harness.h"

#include <cmath>
#include <limits>

using namespace lang;

namespace {

// zero = 0 at run time; the shader builds NaN, denormals and huge values from it.
const char* kShader = R"(
uniform float zero;
attribute vec4 a;
varying vec4 nan_minmax, ints;
void main() {
    float nan = zero / zero;
    nan_minmax = vec4(min(a.x, nan), max(a.x, nan), min(nan, a.x), max(nan, a.x));
    int n = int(a.x * 10.0);
    int z = int(zero);
    ints = vec4(float(n / z), float(int(1e30 + a.x)), float(int(nan)), float(int(-1e30)));
    gl_Position = vec4(0.0);
}
)";

}  // namespace

TEST_CASE("semantics: NaN, denormals and integer edge cases are defined", "[semantics]") {
    glslrun::Program prog = compile_vs(kShader);
    REQUIRE(prog.set_uniform("zero", std::vector<float>{0.0f}).ok());
    Outputs out = run_vs(prog, std_attribs());
    check_output(out, "nan_minmax", 4, [](uint32_t l) {
        float x = in_a(l).x;
        return glm::vec4(x, x, x, x);
    });
    check_output(out, "ints", 4, [](uint32_t) {
        return glm::vec4(0.0f, 2147483647.0f, 0.0f, -2147483648.0f);
    });
}

TEST_CASE("semantics: a product that would be a denormal is flushed to zero", "[semantics]") {
    glslrun::Program prog = compile_vs(R"(
uniform float s;
varying vec4 r;
void main() {
    float denormal = s * s;          // 2^-140: representable only as a denormal
    r = vec4(float(denormal == 0.0), denormal * 1e20, float(s * 0.5 > 0.0), 0.0);
    gl_Position = vec4(0.0);
}
)");
    REQUIRE(prog.set_uniform("s", std::vector<float>{std::ldexp(1.0f, -70)}).ok());
    Outputs out = run_vs(prog, std_attribs());
    check_output(out, "r", 3, [](uint32_t) { return glm::vec4(1.0f, 0.0f, 1.0f, 0.0f); });
}
