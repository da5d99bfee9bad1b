// GLSL 1.10 §7: built-in vertex attributes, built-in varyings and special
// outputs, built-in constants and the state-derived built-in uniforms.
#include "harness.h"

#include <cmath>

using namespace lang;

namespace {
glslrun::VertexAttrib from(const char* name, uint32_t comps, glm::vec4 (*fn)(uint32_t), float scale = 1.0f) {
    return make_attrib(name, comps, kVerts, [=](uint32_t l, uint32_t c) { return fn(l)[c] * scale; });
}
}  // namespace

TEST_CASE("built-in attributes in, built-in varyings out", "[builtin-vars]") {
    auto program = compile_vs(R"(
void main() {
    gl_Position = gl_Vertex * 2.0;
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_SecondaryColor;
    gl_FrontSecondaryColor = vec4(gl_Normal, 1.0) * 0.25 + 0.5;
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_MultiTexCoord3 + vec4(gl_FogCoord);
    gl_FogFragCoord = gl_FogCoord * 3.0;
    gl_PointSize = 4.0 + gl_Vertex.x;
})");
    std::vector<glslrun::VertexAttrib> attribs{
        from("gl_Vertex", 4, in_a),
        from("gl_Color", 4, in_b, 0.2f),          // colours stay in [0, 1]
        from("gl_SecondaryColor", 3, in_b, 0.1f),  // w defaults to 1
        from("gl_Normal", 3, in_a, 0.25f),
        from("gl_MultiTexCoord0", 2, in_c),        // z, w default to 0, 1
        from("gl_MultiTexCoord3", 4, in_b),
        from("gl_FogCoord", 1, in_b),
    };
    auto outs = run_vs(program, attribs);
    check_output(outs, "gl_Position", 4, [](uint32_t l) { return in_a(l) * 2.0f; }, kTight);
    check_output(outs, "gl_FrontColor", 4, [](uint32_t l) { return in_b(l) * 0.2f; }, kTight);
    check_output(outs, "gl_BackColor", 4, [](uint32_t l) {
        return glm::vec4(glm::vec3(in_b(l)) * 0.1f, 1.0f);
    }, kTight);
    check_output(outs, "gl_FrontSecondaryColor", 4, [](uint32_t l) {
        return glm::vec4(glm::vec3(in_a(l)) * 0.25f, 1.0f) * 0.25f + 0.5f;
    }, kTight);
    check_output(outs, "gl_TexCoord[0]", 4, [](uint32_t l) {
        return glm::vec4(in_c(l).x, in_c(l).y, 0.0f, 1.0f);
    }, kExact);
    check_output(outs, "gl_TexCoord[1]", 4, [](uint32_t l) { return in_b(l) + in_b(l).x; }, kTight);
    check_output(outs, "gl_FogFragCoord", 1, [](uint32_t l) { return glm::vec4(in_b(l).x * 3.0f); }, kTight);
    check_output(outs, "gl_PointSize", 1, [](uint32_t l) { return glm::vec4(4.0f + in_a(l).x); }, kTight);
}

TEST_CASE("built-in constants", "[builtin-vars]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
void main() {
    o = vec4(float(gl_MaxLights), float(gl_MaxClipPlanes), float(gl_MaxTextureCoords) * 0.0 + a.x,
             float(gl_MaxVertexAttribs >= 16));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) { return glm::vec4(8.0f, 6.0f, in_a(l).x, 1.0f); }, kExact);
}

TEST_CASE("state-derived built-in uniforms", "[builtin-vars]") {
    auto program = compile_vs(R"(
attribute vec4 a;
varying vec4 n, inv, light, prod, misc;
void main() {
    n = vec4(gl_NormalMatrix * a.xyz, 0.0);
    inv = gl_ModelViewMatrixInverse * (gl_ModelViewMatrix * a);
    light = gl_LightSource[1].diffuse * a.x + gl_LightSource[1].position;
    prod = gl_FrontLightProduct[1].diffuse + gl_FrontMaterial.ambient * gl_LightModel.ambient * a.y;
    misc = vec4(gl_LightSource[1].spotCosCutoff, gl_FrontMaterial.shininess,
                gl_DepthRange.near + gl_DepthRange.diff * a.z, gl_DepthRange.far);
    gl_Position = vec4(0.0);
})");
    glslrun::GLState gl;
    gl.modelview = glm::mat4(glm::vec4(0.8f, 0.1f, -0.2f, 0.0f), glm::vec4(-0.3f, 0.9f, 0.05f, 0.0f),
                             glm::vec4(0.25f, -0.1f, 0.7f, 0.0f), glm::vec4(0.5f, -1.0f, -6.0f, 1.0f));
    gl.lights[1].diffuse = {0.5f, 0.25f, 1.0f, 1.0f};
    gl.lights[1].position = {1.0f, 2.0f, 3.0f, 1.0f};
    gl.lights[1].spot_cutoff = 30.0f;
    gl.front_material.diffuse = {0.2f, 0.4f, 0.6f, 0.8f};
    gl.front_material.shininess = 12.0f;
    gl.light_model_ambient = {0.1f, 0.2f, 0.3f, 1.0f};
    gl.depth_near = 0.25f;
    gl.depth_far = 0.75f;
    auto status = glslrun::apply_builtin_uniforms(program, gl);
    INFO((status ? std::string() : status.error().str()));
    REQUIRE(status.ok());
    auto outs = run_vs(program, std_attribs());
    glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(gl.modelview)));
    check_output(outs, "n", 3, [&](uint32_t l) { return glm::vec4(normal_matrix * glm::vec3(in_a(l)), 0); },
                 1e-5f);
    check_output(outs, "inv", 4, [](uint32_t l) { return in_a(l); }, 1e-4f);
    check_output(outs, "light", 4, [&](uint32_t l) {
        return gl.lights[1].diffuse * in_a(l).x + gl.lights[1].position;
    }, kTight);
    check_output(outs, "prod", 4, [&](uint32_t l) {
        return gl.lights[1].diffuse * gl.front_material.diffuse +
               gl.front_material.ambient * gl.light_model_ambient * in_a(l).y;
    }, kTight);
    check_output(outs, "misc", 4, [](uint32_t l) {
        return glm::vec4(std::cos(30.0f * 3.14159265f / 180.0f), 12.0f, 0.25f + 0.5f * in_a(l).z, 0.75f);
    }, 1e-5f);
}

TEST_CASE("gl_FragColor, gl_FragData and gl_FragDepth outputs", "[builtin-vars][fragment]") {
    auto inputs = std::vector{make_attrib("v", 4, kFrags, [](uint32_t l, uint32_t c) { return in_b(l)[c]; })};
    auto depth = eval_fs(R"(
varying vec4 v;
void main() {
    gl_FragColor = v.wzyx;
    gl_FragDepth = v.x * 0.125;
})", inputs);
    check_output(depth, "gl_FragColor", 4, [](uint32_t l) {
        glm::vec4 b = in_b(l);
        return glm::vec4(b.w, b.z, b.y, b.x);
    }, kExact);
    check_output(depth, "gl_FragDepth", 1, [](uint32_t l) { return glm::vec4(in_b(l).x * 0.125f); }, kExact);
    auto data = eval_fs(R"(
varying vec4 v;
void main() {
    gl_FragData[0] = v;
    gl_FragData[1] = v * 2.0;
})", inputs);
    check_output(data, "gl_FragData[0]", 4, [](uint32_t l) { return in_b(l); }, kExact);
    check_output(data, "gl_FragData[1]", 4, [](uint32_t l) { return in_b(l) * 2.0f; }, kExact);
}
