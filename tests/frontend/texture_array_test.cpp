// EXT_texture_array in GLSL 1.10/1.20 (frontend/texture_array.cpp): which
// programs compile, as Mesa decides, and the `tex` instructions they lower to.
#include <string>

#include "helpers.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

const char* kOn = "#extension GL_EXT_texture_array : enable\n";
// Writes the varying `c` the fragment shaders read.
const char* kVs = "varying vec4 c;\nvoid main() { gl_Position = ftransform(); c = gl_Vertex; }\n";

std::string fs(const std::string& decl, const std::string& body, const char* ext = kOn) {
    return std::string(ext) + decl + "\nvoid main() { gl_FragColor = " + body + "; }\n";
}

std::string vs(const std::string& decl, const std::string& body, const char* ext = kOn) {
    return std::string(ext) + decl + "\nvoid main() { gl_Position = ftransform(); gl_FrontColor = " + body + "; }\n";
}

// The TexInfo of every tex instruction of a shader, in program order.
void collect(const ir::Block& block, std::vector<ir::TexInfo>& out) {
    for (const ir::Node& n : block) {
        if (n.kind == ir::NodeKind::Instr && n.instr.op == ir::Op::tex) out.push_back(ir::TexInfo::decode(n.instr.imm[2]));
        collect(n.body, out);
        collect(n.alt, out);
    }
}

std::vector<ir::TexInfo> lookups(const ir::Shader& s) {
    std::vector<ir::TexInfo> out;
    collect(s.prologue, out);
    collect(s.body, out);
    for (const ir::Function& f : s.functions) collect(f.body, out);
    return out;
}

}  // namespace

TEST_CASE("EXT_texture_array: the array samplers and their functions compile with the extension enabled",
          "[frontend][texture_array]") {
    const std::string decls =
        "uniform sampler1DArray a1; uniform sampler2DArray a2;\n"
        "uniform sampler1DArrayShadow s1; uniform sampler2DArrayShadow s2;\n"
        "varying vec4 c;\n";
    for (int version : {110, 120}) {
        INFO("version " << version);
        const std::string frag = fs(decls,
                                    "texture1DArray(a1, c.xy) + texture2DArray(a2, c.xyz) + shadow1DArray(s1, c.xyz)"
                                    " + shadow2DArray(s2, c) + texture1DArray(a1, c.xy, 1.0) + "
                                    "texture2DArray(a2, c.xyz, c.w) + shadow1DArray(s1, c.xyz, 0.5)");
        const std::string vert = vs("uniform sampler1DArray a1; uniform sampler2DArray a2;\n"
                                    "uniform sampler1DArrayShadow s1;\nvarying vec4 c;\n",
                                    "texture1DArrayLod(a1, gl_Vertex.xy, 1.0) + texture2DArrayLod(a2, gl_Vertex.xyz, "
                                    "0.0) + shadow1DArrayLod(s1, gl_Vertex.xyz, 2.0) + texture2DArray(a2, gl_Vertex.xyz); c = gl_Vertex");
        const ir::Program p = compile_ok(vert, frag, version);
        const std::vector<ir::TexInfo> f = lookups(p.fragment), v = lookups(p.vertex);
        REQUIRE(f.size() == 7);
        CHECK((f[0].target == ir::TexTarget::A1D && !f[0].shadow && f[0].lod == ir::TexLod::Implicit));
        CHECK((f[1].target == ir::TexTarget::A2D && !f[1].shadow));
        CHECK((f[2].target == ir::TexTarget::A1D && f[2].shadow));
        CHECK((f[3].target == ir::TexTarget::A2D && f[3].shadow));
        CHECK(f[4].lod == ir::TexLod::ImplicitBias);
        CHECK((f[6].target == ir::TexTarget::A1D && f[6].shadow && f[6].lod == ir::TexLod::ImplicitBias));
        REQUIRE(v.size() == 4);
        for (const ir::TexInfo& t : v) CHECK(t.lod == ir::TexLod::Explicit);
        CHECK((v[2].target == ir::TexTarget::A1D && v[2].shadow));
        // Operands: coordinates with the layer, the reference, then derivatives of the filtered ones only.
        CHECK(f[1].operand_count() == 3 + 2 + 2);
        CHECK(f[3].operand_count() == 3 + 1 + 2 + 2);
        CHECK(v[1].operand_count() == 3 + 1);
    }
}

TEST_CASE("EXT_texture_array: require, warn, and #extension inside #if, as Mesa", "[frontend][texture_array]") {
    const std::string decl = "uniform sampler2DArray a;\nvarying vec4 c;\n";
    const std::string body = "texture2DArray(a, c.xyz)";
    compile_ok(kVs, fs(decl, body, "#extension GL_EXT_texture_array : require\n"));
    compile_ok(kVs, fs(decl, body, "#extension GL_EXT_texture_array : warn\n"));
    compile_ok(kVs, fs(decl, body, "#extension all : warn\n"));
    compile_ok(kVs, fs(decl, body, "#ifdef GL_EXT_texture_array\n#extension GL_EXT_texture_array : enable\n#endif\n"));
    // The macro is defined whether or not the extension is enabled, as in Mesa.
    compile_ok(kVs, fs("", "vec4(GL_EXT_texture_array)", ""));
}

TEST_CASE("EXT_texture_array: without the extension the names are not types, and its functions do not exist",
          "[frontend][texture_array]") {
    const std::string decl = "uniform sampler2DArray a;\nvarying vec4 c;\n";
    CHECK_THAT(compile_error(kVs, fs(decl, "texture2DArray(a, c.xyz)", "")),
               Catch::Contains("t.frag:1: error: 'sampler2DArray' is EXT_texture_array's: add '#extension "
                               "GL_EXT_texture_array : enable' before the code"));
    CHECK_THAT(compile_error(kVs, fs(decl, "texture2DArray(a, c.xyz)", "#extension GL_EXT_texture_array : disable\n")),
               Catch::Contains("t.frag:2:"));
    compile_error(kVs, fs(decl, "texture2DArray(a, c.xyz)",
                              "#extension GL_EXT_texture_array : enable\n#extension GL_EXT_texture_array : disable\n"));
    compile_error(kVs, fs(decl, "texture2DArray(a, c.xyz)", "#if 0\n#extension GL_EXT_texture_array : enable\n#endif\n"));
    // Without the extension the names are ordinary identifiers (Mesa: not reserved in 1.10).
    compile_ok(kVs, fs("float sampler2DArray = 1.0;", "vec4(sampler2DArray)", ""));
    // With it they are types.
    compile_error(kVs, fs("float sampler2DArray = 1.0;", "vec4(sampler2DArray)"));
}

TEST_CASE("EXT_texture_array: the Lod forms need ARB_shader_texture_lod in a fragment shader, the bias forms a "
          "fragment shader, as in Mesa", "[frontend][texture_array]") {
    const std::string decl = "uniform sampler2DArray a;\nuniform sampler2DArrayShadow s;\nvarying vec4 c;\n";
    compile_error(kVs, fs(decl, "texture2DArrayLod(a, c.xyz, 1.0)"));
    compile_ok(kVs, fs(decl, "texture2DArrayLod(a, c.xyz, 1.0)",
                           "#extension GL_EXT_texture_array : enable\n#extension GL_ARB_shader_texture_lod : enable\n"));
    compile_error(vs(decl, "texture2DArray(a, gl_Vertex.xyz, 1.0)"), "void main() { gl_FragColor = vec4(1.0); }\n");
    // Mesa 22.3.6 accepts shadow2DArray with a bias, which the extension does not list.
    compile_ok(kVs, fs(decl, "shadow2DArray(s, c, 1.0)"));
    compile_error(kVs, fs(decl, "shadow2DArrayLod(s, c, 1.0)"));
    // Wrong coordinate sizes are glslang's "no matching overloaded function".
    CHECK_THAT(compile_error(kVs, fs(decl, "texture2DArray(a, c.xy)")), Catch::Contains("t.frag:6:"));
}
