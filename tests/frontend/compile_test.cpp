// End-to-end frontend checks: bindings, uniforms, varyings, and values
// computed by the lowered IR (one-lane reference evaluation).
#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

bool has_binding(const std::vector<ir::Binding>& list, const std::string& name, uint32_t count) {
    for (const ir::Binding& b : list)
        if (b.name == name) return b.count == count;
    return false;
}

const ir::Uniform* uniform(const ir::Program& p, const std::string& name) {
    for (const ir::Uniform& u : p.uniforms)
        if (u.name == name) return &u;
    return nullptr;
}

}  // namespace

TEST_CASE("minimal program: ftransform and a constant colour") {
    ir::Program p = compile_ok(kPassVs, "void main() { gl_FragColor = vec4(1,0,0,1); }\n");
    CHECK(has_binding(p.vertex.inputs, "gl_Vertex", 4));
    CHECK(has_binding(p.vertex.outputs, "gl_Position", 4));
    CHECK(has_binding(p.fragment.outputs, "gl_FragColor", 4));
    CHECK(p.fragment.inputs.empty());
    const ir::Uniform* mvp = uniform(p, "gl_ModelViewProjectionMatrix");
    REQUIRE(mvp);
    CHECK(mvp->builtin);
    CHECK(mvp->type.cols == 4);
    CHECK(mvp->type.rows == 4);

    // gl_Position = MVP * gl_Vertex, column-major.
    std::vector<float> m(16);
    for (int i = 0; i < 16; ++i) m[size_t(i)] = float(i + 1);
    MiniEval vs(p.vertex, uniform_store(p, {{"gl_ModelViewProjectionMatrix", m}}));
    vs.set_input("gl_Vertex", {1, 2, 3, 4});
    vs.run();
    std::vector<float> expect(4);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) expect[size_t(r)] += m[size_t(c * 4 + r)] * float(c + 1);
    CHECK(vs.output("gl_Position") == expect);
    CHECK(run_fs(p) == std::vector<float>{1, 0, 0, 1});
}

TEST_CASE("lecture colours program: gl_Color links to gl_FrontColor/gl_BackColor") {
    ir::Program p = compile_ok("void main(void) {\n gl_FrontColor = gl_Color;\n gl_Position = ftransform();\n}\n",
                               "void main(void) {\n gl_FragColor = gl_Color;\n}\n");
    REQUIRE(p.fragment.inputs.size() == 1);
    CHECK(p.fragment.inputs[0].name == "gl_Color");
    REQUIRE(p.varyings.size() == 1);
    const ir::VaryingLink& l = p.varyings[0];
    REQUIRE(l.vs_output >= 0);
    CHECK(p.vertex.outputs[size_t(l.vs_output)].name == "gl_FrontColor");
    CHECK(l.vs_back_output == -1);
    CHECK(l.is_color);
    auto out = run_fs(p, {}, {{"gl_Color", {0.25f, 0.5f, 0.75f, 1}}});
    CHECK(out == std::vector<float>{0.25f, 0.5f, 0.75f, 1});
}

TEST_CASE("user varyings, gl_FragCoord and gl_FrontFacing bindings") {
    ir::Program p = compile_ok(
        "varying vec3 n; varying float w[2];\n"
        "void main() { n = gl_Normal; w[0] = 1.0; w[1] = 2.0; gl_Position = ftransform(); }\n",
        "varying vec3 n; varying float w[2];\n"
        "void main() { gl_FragColor = gl_FrontFacing ? vec4(n, w[1]) : gl_FragCoord; }\n");
    CHECK(has_binding(p.vertex.outputs, "n", 3));
    CHECK(has_binding(p.vertex.outputs, "w", 2));
    CHECK(has_binding(p.fragment.inputs, "gl_FragCoord", 4));
    CHECK(has_binding(p.fragment.inputs, "gl_FrontFacing", 1));
    for (const ir::VaryingLink& l : p.varyings) {
        const std::string& name = p.fragment.inputs[l.fs_input].name;
        if (name == "n" || name == "w") {
            REQUIRE(l.vs_output >= 0);
            CHECK(p.vertex.outputs[size_t(l.vs_output)].name == name);
        } else {
            CHECK(l.vs_output == -1);
        }
    }
    CHECK(run_fs(p, {}, {{"gl_FrontFacing", {1}}, {"n", {1, 2, 3}}, {"w", {5, 6}}}) == std::vector<float>{1, 2, 3, 6});
    CHECK(run_fs(p, {}, {{"gl_FrontFacing", {0}}, {"gl_FragCoord", {9, 8, 7, 6}}}) == std::vector<float>{9, 8, 7, 6});
}

TEST_CASE("unwritten outputs read as zero and gl_Position is always an output") {
    ir::Program p = compile_ok("varying vec4 v;\nvoid main() { if (gl_Vertex.x > 0.0) v = vec4(1.0); gl_Position = vec4(0.0); }\n",
                               "varying vec4 v;\nvoid main() { gl_FragColor = v; }\n");
    MiniEval vs(p.vertex, uniform_store(p, {}));
    vs.set_input("gl_Vertex", {-1, 0, 0, 1});
    vs.run();
    CHECK(vs.output("v") == std::vector<float>{0, 0, 0, 0});
}

TEST_CASE("gl_TexCoord: one binding per element, sizes may differ between stages") {
    ir::Program p = compile_ok(
        "void main() { gl_TexCoord[0] = vec4(1.0); gl_TexCoord[1] = vec4(2.0); gl_Position = ftransform(); }\n",
        "varying vec4 gl_TexCoord[4];\nvoid main() { gl_FragColor = gl_TexCoord[1] + gl_TexCoord[3]; }\n");
    CHECK(has_binding(p.vertex.outputs, "gl_TexCoord[0]", 4));
    CHECK(has_binding(p.vertex.outputs, "gl_TexCoord[1]", 4));
    CHECK(has_binding(p.fragment.inputs, "gl_TexCoord[3]", 4));
    for (const ir::VaryingLink& l : p.varyings) {
        const std::string& name = p.fragment.inputs[l.fs_input].name;
        if (name == "gl_TexCoord[1]") {
            REQUIRE(l.vs_output >= 0);
            CHECK(p.vertex.outputs[size_t(l.vs_output)].name == "gl_TexCoord[1]");
        }
        if (name == "gl_TexCoord[3]") CHECK(l.vs_output == -1);
    }
    CHECK(run_fs(p, {}, {{"gl_TexCoord[1]", {1, 2, 3, 4}}, {"gl_TexCoord[3]", {10, 20, 30, 40}}}) ==
          std::vector<float>{11, 22, 33, 44});
}

TEST_CASE("uniforms: leaves, unused user uniforms, merging across stages") {
    ir::Program p = compile_ok(
        "uniform vec4 shared; uniform float unusedV;\n"
        "void main() { gl_Position = ftransform() + shared + gl_LightSource[1].position; }\n",
        "uniform vec4 shared; uniform mat3 m; uniform bool flag; uniform int arr[3]; uniform sampler2D tex;\n"
        "void main() { gl_FragColor = flag ? shared : vec4(m[1], float(arr[2])) + gl_FrontMaterial.diffuse; }\n");
    const ir::Uniform* shared = uniform(p, "shared");
    REQUIRE(shared);
    CHECK_FALSE(shared->builtin);
    int count = 0;
    for (const ir::Uniform& u : p.uniforms) count += u.name == "shared";
    CHECK(count == 1);
    CHECK(uniform(p, "unusedV"));
    REQUIRE(uniform(p, "arr"));
    CHECK(uniform(p, "arr")->array_size == 3);
    CHECK(uniform(p, "arr")->is_array);
    REQUIRE(uniform(p, "tex"));
    CHECK(uniform(p, "tex")->type.is_sampler);
    CHECK(uniform(p, "flag")->type.kind == ir::Kind::Bool);
    const ir::Uniform* pos0 = uniform(p, "gl_LightSource[0].position");
    const ir::Uniform* pos3 = uniform(p, "gl_LightSource[3].position");
    REQUIRE(pos0);
    REQUIRE(pos3);
    CHECK(pos0->builtin);
    CHECK(uniform(p, "gl_LightSource[7].spotCosCutoff"));
    CHECK_FALSE(uniform(p, "gl_LightSource[8].position"));
    uint32_t stride = (pos3->slot - pos0->slot) / 3;
    CHECK(uniform(p, "gl_LightSource[1].position")->slot == pos0->slot + stride);
    CHECK(uniform(p, "gl_FrontMaterial.diffuse"));
    CHECK(uniform(p, "gl_FrontMaterial.shininess"));

    auto out = run_fs(p, {{"flag", {0}}, {"m", {1, 2, 3, 4, 5, 6, 7, 8, 9}}, {"arr", {0, 0, 7}},
                          {"gl_FrontMaterial.diffuse", {0.5f, 0.5f, 0.5f, 0.5f}}});
    CHECK(out == std::vector<float>{4.5f, 5.5f, 6.5f, 7.5f});
    out = run_fs(p, {{"flag", {1}}, {"shared", {1, 2, 3, 4}}});
    CHECK(out == std::vector<float>{1, 2, 3, 4});
}

TEST_CASE("dynamic indexing of uniform arrays of structs") {
    ir::Program p = compile_ok(kPassVs,
                               "uniform int i;\n"
                               "void main() { gl_FragColor = gl_LightSource[i].diffuse * gl_LightSource[i].spotExponent; }\n");
    auto out = run_fs(p, {{"i", {2}},
                          {"gl_LightSource[2].diffuse", {1, 2, 3, 4}},
                          {"gl_LightSource[2].spotExponent", {2}},
                          {"gl_LightSource[1].diffuse", {9, 9, 9, 9}}});
    CHECK(out == std::vector<float>{2, 4, 6, 8});
}

TEST_CASE("a missing vertex shader gets a fixed-function stand-in") {
    auto r = compile("", "void main() { gl_FragColor = gl_Color; }\n");
    REQUIRE(r.ok());
    CHECK(ir::verify(r->vertex) == "");
    REQUIRE(r->varyings.size() == 1);
    CHECK(r->varyings[0].vs_output >= 0);
}

#include <fstream>
#include <sstream>

TEST_CASE("lecture per-pixel spot light program compiles, verifies and computes") {
    auto slurp = [](const std::string& name) {
        std::ifstream in(std::string(GLSLRUN_SOURCE_DIR) + "/shaders/" + name);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    std::string vs = slurp("pos_pix.vert"), fs = slurp("spot_pix_fixed.frag");
    REQUIRE_FALSE(vs.empty());
    REQUIRE_FALSE(fs.empty());
    ir::Program p = compile_ok(vs, fs);
    CHECK(has_binding(p.vertex.inputs, "gl_Normal", 3));
    CHECK(has_binding(p.vertex.outputs, "normal", 3));
    CHECK(has_binding(p.fragment.inputs, "ecPos", 3));
    // Outside the cone (spotCosCutoff = 2): only global ambient + emission.
    auto out = run_fs(p,
                      {{"gl_LightSource[0].position", {0, 0, 1, 1}},
                       {"gl_LightSource[0].spotCosCutoff", {2}},
                       {"gl_LightSource[0].constantAttenuation", {1}},
                       {"gl_LightModel.ambient", {0.5f, 0.5f, 0.5f, 1}},
                       {"gl_FrontMaterial.ambient", {0.2f, 0.4f, 0.6f, 1}},
                       {"gl_FrontMaterial.emission", {0, 0, 0.05f, 0}}},
                      {{"normal", {0, 0, 1}}, {"ecPos", {0, 0, 0}}});
    CHECK(near(out, {0.1f, 0.2f, 0.35f, 1}));
}
