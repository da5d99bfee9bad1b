// Fragment-only built-ins: dFdx, dFdy, fwidth on 2x2 quads, and the
// fragment inputs gl_FragCoord and gl_FrontFacing.
//
// Every input is a linear function of the pixel position whose coefficients
// change from quad to quad, with values exactly representable in float, so
// the differences across a quad are exact whichever row or column the
// implementation uses, and a mix-up between quads shows.
#include "harness.h"

#include <cmath>

using namespace lang;

namespace {

// f = kx * x + ky * y + k0 on quad q; all multiples of 1/8.
glm::vec3 coeffs(uint32_t frag, float scale) {
    float q = float(frag / 4);
    return {scale * (1.0f + 0.5f * q), scale * (-2.0f + 0.25f * q), 0.125f * q};
}

float linear(uint32_t frag, float scale) {
    glm::vec3 k = coeffs(frag, scale);
    glm::vec2 p = frag_xy(frag);
    return k.x * p.x + k.y * p.y + k.z;
}

std::vector<glslrun::VertexAttrib> derivative_inputs() {
    return {make_attrib("f", 1, kFrags, [](uint32_t l, uint32_t) { return linear(l, 1.0f); }),
            make_attrib("v", 4, kFrags, [](uint32_t l, uint32_t c) {
                return linear(l, float(c + 1) * (c % 2 ? -1.0f : 1.0f));
            }),
            make_attrib("gl_FragCoord", 4, kFrags, [](uint32_t l, uint32_t c) {
                glm::vec2 p = frag_xy(l);
                return c == 0 ? p.x + 0.5f : c == 1 ? p.y + 0.5f : c == 2 ? 0.25f : 1.0f;
            })};
}

}  // namespace

TEST_CASE("dFdx and dFdy of linear inputs are exact", "[builtins][derivatives][fragment]") {
    auto outs = eval_fs(R"(
varying float f;
varying vec4 v;
void main() {
    gl_FragColor = vec4(dFdx(f), dFdy(f), dFdx(gl_FragCoord.x), dFdy(gl_FragCoord.y));
})", derivative_inputs());
    check_output(outs, "gl_FragColor", 4, [](uint32_t l) {
        glm::vec3 k = coeffs(l, 1.0f);
        return glm::vec4(k.x, k.y, 1.0f, 1.0f);
    }, kExact);
}

TEST_CASE("derivatives of vectors and of computed expressions", "[builtins][derivatives][fragment]") {
    auto program = compile_fs(R"(
varying float f;
varying vec4 v;
void main() {
    vec4 e = v * 2.0 + vec4(f);          // still linear in x and y
    gl_FragColor = dFdx(e) + dFdy(v) * 100.0;
})", derivative_inputs());
    auto outs = run_fs(program, derivative_inputs());
    check_output(outs, "gl_FragColor", 4, [](uint32_t l) {
        glm::vec4 r;
        for (int c = 0; c < 4; ++c) {
            float scale = float(c + 1) * (c % 2 ? -1.0f : 1.0f);
            r[c] = 2.0f * coeffs(l, scale).x + coeffs(l, 1.0f).x + 100.0f * coeffs(l, scale).y;
        }
        return r;
    }, kExact);
}

TEST_CASE("fwidth is |dFdx| + |dFdy|", "[builtins][derivatives][fragment]") {
    auto outs = eval_fs(R"(
varying float f;
varying vec4 v;
void main() {
    gl_FragColor = vec4(fwidth(f), fwidth(v.yz), fwidth(v).w);
})", derivative_inputs());
    check_output(outs, "gl_FragColor", 4, [](uint32_t l) {
        auto fw = [&](float scale) {
            glm::vec3 k = coeffs(l, scale);
            return std::fabs(k.x) + std::fabs(k.y);
        };
        return glm::vec4(fw(1.0f), fw(-2.0f), fw(3.0f), fw(-4.0f));
    }, kExact);
}

TEST_CASE("derivatives taken before a discard, in a quad that is partly discarded",
          "[builtins][derivatives][fragment]") {
    auto outs = eval_fs(R"(
varying float f;
varying vec4 v;
void main() {
    float d = dFdx(f) + dFdy(f) * 10.0;
    if (gl_FragCoord.x < 1.0) discard;     // the left column of the first quad column
    gl_FragColor = vec4(d);
})", derivative_inputs());
    check_output(outs, "discarded", 1, [](uint32_t l) { return glm::vec4(b2f(frag_xy(l).x < 0.5f)); }, kExact);
    check_output(outs, "gl_FragColor", 1, [&](uint32_t l) {
        glm::vec3 k = coeffs(l, 1.0f);
        return frag_xy(l).x < 0.5f ? outs.vec("gl_FragColor", l) : glm::vec4(k.x + 10.0f * k.y);
    }, kExact);
}

TEST_CASE("gl_FragCoord and gl_FrontFacing inputs", "[builtins][fragment]") {
    auto inputs = derivative_inputs();
    inputs.push_back(make_attrib("gl_FrontFacing", 1, kFrags, [](uint32_t l, uint32_t) {
        return float((l / 4) % 2);   // alternate quads are back-facing
    }));
    auto outs = eval_fs(R"(
void main() {
    vec2 p = gl_FragCoord.xy - vec2(0.5);
    gl_FragColor = vec4(p, gl_FragCoord.z * 4.0, gl_FrontFacing ? 1.0 : -1.0);
})", inputs);
    check_output(outs, "gl_FragColor", 4, [](uint32_t l) {
        glm::vec2 p = frag_xy(l);
        return glm::vec4(p, 1.0f, (l / 4) % 2 ? 1.0f : -1.0f);
    }, kExact);
}
