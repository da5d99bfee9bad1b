// GLState -> built-in uniforms: derived matrices, lights, materials, ranges,
// checked through a vertex shader that reads them.
#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "helpers.h"

using namespace glslrun;
using api_test::compile;
using api_test::output;

namespace {

const char* kStateVs = R"(
varying vec3 nm0;
varying vec3 nm1;
varying vec3 nm2;
varying vec4 mvp_v;
varying vec4 ft;
varying vec4 inv_check;
varying vec4 half0;
varying vec4 spot;
varying vec4 scene;
varying vec4 prod;
varying vec4 defaults;
varying vec4 ranges;
varying vec4 tex;
void main() {
    nm0 = gl_NormalMatrix[0];
    nm1 = gl_NormalMatrix[1];
    nm2 = gl_NormalMatrix[2];
    mvp_v = gl_ModelViewProjectionMatrix * gl_Vertex;
    ft = ftransform();
    inv_check = gl_ModelViewMatrixInverse * (gl_ModelViewMatrix * gl_Vertex);
    half0 = gl_LightSource[0].halfVector;
    spot = vec4(gl_LightSource[0].spotCosCutoff, gl_LightSource[1].spotCosCutoff,
                gl_LightSource[0].spotExponent, gl_LightSource[0].quadraticAttenuation);
    scene = gl_FrontLightModelProduct.sceneColor;
    prod = gl_FrontLightProduct[0].diffuse;
    defaults = vec4(gl_LightSource[1].diffuse.r, gl_LightSource[1].diffuse.a,
                    gl_LightSource[0].specular.g, gl_LightModel.ambient.r);
    ranges = vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, gl_ClipPlane[2].y);
    tex = gl_TextureMatrix[1] * vec4(1.0) + gl_TextureMatrixTranspose[0] * vec4(0.0, 0.0, 0.0, 1.0);
    gl_Position = ftransform();
}
)";
const char* kStateFs = "void main() { gl_FragColor = vec4(1.0); }\n";

glm::vec4 vec(const std::vector<ShaderOutput>& outs, const std::string& name, uint32_t vertex = 0) {
    const ShaderOutput& o = output(outs, name);
    glm::vec4 r(0.0f);
    for (uint32_t i = 0; i < o.components && i < 4; ++i) r[int(i)] = o.data[vertex * o.components + i];
    return r;
}

void check_vec(glm::vec4 got, glm::vec4 want, float eps = 1e-5f) {
    for (int i = 0; i < 4; ++i) CHECK(got[i] == Approx(want[i]).margin(eps));
}

// The lecture's material and light set-up (scenes/directional.toml).
GLState lecture_state() {
    GLState gl;
    gl.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5));
    gl.projection = glm::perspective(glm::radians(45.0f), 1.0f, 1.0f, 100.0f);
    gl.lights[0].ambient = {0.2f, 0.2f, 0.2f, 1};
    gl.lights[0].position = {1, 1, 1, 0};
    gl.front_material.ambient = {0.25f, 0.20f, 0.07f, 1};
    gl.front_material.diffuse = {0.75f, 0.61f, 0.23f, 1};
    gl.front_material.specular = {0.8f, 0.8f, 0.8f, 1};
    gl.front_material.emission = {0, 0, 0.05f, 1};
    gl.front_material.shininess = 64;
    return gl;
}

}  // namespace

TEST_CASE("GLState defaults are OpenGL 2.1's", "[api][glstate]") {
    GLState gl;
    CHECK(gl.lights[0].diffuse == glm::vec4(1, 1, 1, 1));
    CHECK(gl.lights[0].specular == glm::vec4(1, 1, 1, 1));
    CHECK(gl.lights[1].diffuse == glm::vec4(0, 0, 0, 1));
    CHECK(gl.texture_matrix[7] == glm::mat4(1.0f));
    Program p = compile(kStateVs, kStateFs);
    REQUIRE(apply_builtin_uniforms(p, gl).ok());
    auto outs = run_vertices(p, {{"gl_Vertex", 4, {1, 2, 3, 1}}}, 1);
    REQUIRE(outs.ok());
    check_vec(vec(*outs, "defaults"), {0, 1, 1, 0.2f});
    check_vec(vec(*outs, "spot"), {-1, -1, 0, 0});
    check_vec(vec(*outs, "ranges"), {0, 1, 1, 0});
    check_vec(vec(*outs, "half0"), {0, 0, 1, 1});  // position (0,0,1,0): normalize((0,0,1)+(0,0,1))
    check_vec(vec(*outs, "tex"), {1, 1, 1, 2});
}

TEST_CASE("normal matrix of a non-orthogonal modelview is the inverse transpose", "[api][glstate]") {
    GLState gl;
    glm::mat4 mv(1.0f);
    mv = glm::translate(mv, glm::vec3(1, -2, -7));
    mv = glm::rotate(mv, 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    mv = glm::scale(mv, glm::vec3(2.0f, 0.5f, 3.0f));
    mv[1][0] += 0.8f;  // shear
    gl.modelview = mv;
    gl.projection = glm::frustum(-1.0f, 1.0f, -0.75f, 0.75f, 1.0f, 50.0f);
    Program p = compile(kStateVs, kStateFs);
    REQUIRE(apply_builtin_uniforms(p, gl).ok());
    const uint32_t n = 5;
    VertexAttrib v{"gl_Vertex", 4, {}};
    for (uint32_t i = 0; i < n; ++i) v.data.insert(v.data.end(), {float(i), 1.0f - float(i), 0.5f * float(i), 1.0f});
    auto outs = run_vertices(p, {v}, n);
    REQUIRE(outs.ok());
    glm::mat3 nm(glm::vec3(vec(*outs, "nm0")), glm::vec3(vec(*outs, "nm1")), glm::vec3(vec(*outs, "nm2")));
    glm::mat3 upper(mv);
    glm::mat3 expected = glm::transpose(glm::inverse(upper));
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) CHECK(nm[c][r] == Approx(expected[c][r]).epsilon(1e-4));
    // Independent check: normals stay perpendicular to transformed tangents.
    glm::vec3 normal(0.3f, -0.5f, 0.8f), tangent(0.5f, 0.3f, 0.0f);
    REQUIRE(glm::dot(normal, tangent) == Approx(0.0f).margin(1e-7));
    CHECK(glm::dot(nm * normal, upper * tangent) == Approx(0.0f).margin(1e-4));
    for (uint32_t i = 0; i < n; ++i) {
        INFO("vertex " << i);
        glm::vec4 in(v.data[i * 4], v.data[i * 4 + 1], v.data[i * 4 + 2], 1.0f);
        glm::vec4 want = gl.projection * (mv * in);
        check_vec(vec(*outs, "mvp_v", i), want, 1e-4f);
        check_vec(vec(*outs, "ft", i), want, 1e-4f);
        check_vec(vec(*outs, "inv_check", i), in, 1e-4f);
    }
}

TEST_CASE("lights, materials and products of the lecture scenes", "[api][glstate]") {
    GLState gl = lecture_state();
    gl.lights[0].spot_cutoff = 20;
    gl.lights[0].spot_exponent = 12;
    gl.lights[0].quadratic_attenuation = 0.02f;
    gl.depth_near = 0.25f;
    gl.depth_far = 0.75f;
    gl.clip_planes[2] = {0, -3, 0, 1};
    gl.texture_matrix[1] = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
    Program p = compile(kStateVs, kStateFs);
    REQUIRE(apply_builtin_uniforms(p, gl).ok());
    auto outs = run_vertices(p, {{"gl_Vertex", 4, {0, 0, 0, 1}}}, 1);
    REQUIRE(outs.ok());
    check_vec(vec(*outs, "half0"), {0.3250576f, 0.3250576f, 0.8880738f, 1.0f});
    check_vec(vec(*outs, "spot"), {0.9396926f, -1.0f, 12.0f, 0.02f});
    // emission + material ambient * model ambient; alpha from the diffuse material
    check_vec(vec(*outs, "scene"), {0.05f, 0.04f, 0.014f + 0.05f, 1.0f});
    check_vec(vec(*outs, "prod"), {0.75f, 0.61f, 0.23f, 1.0f});
    check_vec(vec(*outs, "ranges"), {0.25f, 0.75f, 0.5f, -3.0f});
    check_vec(vec(*outs, "tex"), {2, 3, 4, 2});
    // The projection of the lecture (scenes/*.toml) through ftransform.
    check_vec(vec(*outs, "ft"), gl.projection * glm::vec4(0, 0, -5, 1), 1e-5f);
    CHECK(gl.projection[2][2] == Approx(-1.020202f));
}

#include "runtime/program_state.h"

TEST_CASE("every built-in uniform leaf the program reads gets a value, and only those", "[api][glstate]") {
    Program p = compile(R"(
varying vec4 sink;
void main() {
    vec4 s = vec4(0.0);
    s += gl_ModelViewMatrixInverseTranspose[0] + gl_ProjectionMatrixInverse[1] + gl_ModelViewProjectionMatrixTranspose[2];
    s += gl_TextureMatrixInverseTranspose[3][1] + gl_TextureMatrixInverse[0][0] + gl_ModelViewMatrixTranspose[3];
    s += gl_ProjectionMatrixTranspose[0] + gl_ProjectionMatrixInverseTranspose[1] + gl_ModelViewProjectionMatrixInverse[2];
    s += gl_ModelViewProjectionMatrixInverseTranspose[3] + gl_ModelViewMatrixInverse[0];
    s.xyz += gl_NormalMatrix[1] * gl_NormalScale;
    s += vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, 0.0) + gl_ClipPlane[5];
    s += vec4(gl_Point.size, gl_Point.sizeMin, gl_Point.sizeMax, gl_Point.fadeThresholdSize);
    s += vec4(gl_Point.distanceConstantAttenuation, gl_Point.distanceLinearAttenuation,
              gl_Point.distanceQuadraticAttenuation, 0.0);
    s += gl_FrontMaterial.emission + gl_BackMaterial.ambient + gl_FrontMaterial.diffuse + gl_BackMaterial.specular;
    s.x += gl_FrontMaterial.shininess + gl_BackMaterial.shininess;
    for (int i = 0; i < 2; ++i) {
        s += gl_LightSource[i].ambient + gl_LightSource[i].diffuse + gl_LightSource[i].specular;
        s += gl_LightSource[i].position + gl_LightSource[i].halfVector;
        s.xyz += gl_LightSource[i].spotDirection;
        s += vec4(gl_LightSource[i].spotExponent, gl_LightSource[i].spotCutoff, gl_LightSource[i].spotCosCutoff,
                  gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation
                  + gl_LightSource[i].quadraticAttenuation);
        s += gl_FrontLightProduct[i].ambient + gl_BackLightProduct[i].diffuse + gl_FrontLightProduct[i].specular;
    }
    s += gl_LightModel.ambient + gl_FrontLightModelProduct.sceneColor + gl_BackLightModelProduct.sceneColor;
    s += gl_TextureEnvColor[1] + gl_EyePlaneS[0] + gl_EyePlaneT[1] + gl_EyePlaneR[2] + gl_EyePlaneQ[3];
    s += gl_ObjectPlaneS[0] + gl_ObjectPlaneT[1] + gl_ObjectPlaneR[2] + gl_ObjectPlaneQ[3];
    s += gl_Fog.color + vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end, gl_Fog.scale);
    sink = s;
    gl_Position = ftransform();
}
)", "varying vec4 sink; void main() { gl_FragColor = sink; }");
    Program::State& st = state_of(p);
    const uint32_t sentinel = 0xdeadbeefu;
    std::fill(st.uniforms.begin(), st.uniforms.end(), sentinel);
    REQUIRE(apply_builtin_uniforms(p, GLState{}).ok());
    int builtins = 0;
    for (const ir::Uniform& u : st.ir.uniforms) {
        if (!u.builtin) continue;
        INFO(u.name);
        if (!u.read) {
            // Not derived at all: e.g. gl_FrontMaterial.ambient, which the shader never names.
            CHECK(st.uniforms[u.slot] == sentinel);
            continue;
        }
        ++builtins;
        for (uint32_t w = 0; w < u.type.components() * u.array_size; ++w) REQUIRE(st.uniforms[u.slot + w] != sentinel);
    }
    CHECK(builtins > 40);
    uint32_t element = 0;
    const ir::Uniform* unread = ir::find_uniform(st.ir, "gl_FrontMaterial.ambient", &element);
    REQUIRE(unread);
    CHECK_FALSE(unread->read);
}

TEST_CASE("an array of fewer components fills the rest with GL's (0, 0, 0, 1), not the current value",
          "[api][glstate]") {
    // GL 2.1 §2.8: a colour array of 3 has alpha 1 whatever glColor said;
    // without an array the current colour is read whole.
    Program p = compile("varying vec4 c, t; void main() { c = gl_Color; t = gl_MultiTexCoord0; "
                        "gl_Position = gl_Vertex; }",
                        "varying vec4 c, t; void main() { gl_FragColor = c + t; }");
    GLState gl;
    gl.current_color = {0.1f, 0.2f, 0.3f, 0.25f};
    auto with = run_vertices(p, {{"gl_Vertex", 2, {0, 0}}, {"gl_Color", 3, {0.5f, 0.6f, 0.7f}},
                                 {"gl_MultiTexCoord0", 2, {0.75f, 0.5f}}}, 1, &gl);
    REQUIRE(with.ok());
    check_vec(vec(*with, "c"), {0.5f, 0.6f, 0.7f, 1.0f});
    check_vec(vec(*with, "t"), {0.75f, 0.5f, 0.0f, 1.0f});
    auto without = run_vertices(p, {{"gl_Vertex", 2, {0, 0}}}, 1, &gl);
    REQUIRE(without.ok());
    check_vec(vec(*without, "c"), {0.1f, 0.2f, 0.3f, 0.25f});
}
