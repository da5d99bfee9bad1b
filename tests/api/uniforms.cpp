// Uniform setting (glUniform semantics and errors), introspection, and
// run_vertices / run_fragments over several batches.
#include <array>
#include <cmath>

#include "helpers.h"

using namespace glslrun;
using api_test::compile;
using api_test::output;

namespace {

const char* kUniformVs = R"(
struct S { float a; vec2 b; };
uniform float f;
uniform vec3 v;
uniform int i;
uniform ivec2 iv;
uniform bool b;
uniform mat3 m;
uniform float arr[4];
uniform S s[2];
varying vec4 r0;
varying vec4 r1;
varying vec4 r2;
void main() {
    r0 = vec4(f, v);
    r1 = vec4(float(i), vec2(iv), b ? 1.0 : 0.0);
    r2 = vec4(m * vec3(1.0, 2.0, 3.0), arr[0] + arr[1] * 10.0 + arr[2] * 100.0 + arr[3] * 1000.0)
       + vec4(s[1].a + s[0].b.y);
    gl_Position = gl_Vertex;
}
)";
const char* kUniformFs = R"(
varying vec4 r0;
varying vec4 r1;
varying vec4 r2;
void main() { gl_FragColor = r0 + r1 + r2; }
)";

std::vector<float> first_vertex(const std::vector<ShaderOutput>& outs, const std::string& name) {
    const ShaderOutput& o = output(outs, name);
    return std::vector<float>(o.data.begin(), o.data.begin() + o.components);
}

}  // namespace

TEST_CASE("set_uniform follows glUniform semantics", "[api][uniform]") {
    Program p = compile(kUniformVs, kUniformFs);
    std::array<float, 1> one{2.5f};
    REQUIRE(p.set_uniform("f", one).ok());
    REQUIRE(p.set_uniform("v", std::array<float, 3>{1, 2, 3}).ok());
    REQUIRE(p.set_uniform("i", std::array<int32_t, 1>{-7}).ok());
    REQUIRE(p.set_uniform("iv", std::array<int32_t, 2>{4, 5}).ok());
    REQUIRE(p.set_uniform("b", std::array<float, 1>{0.5f}).ok());  // bools take floats...
    // mat3 column-major: columns (1,0,0) (0,2,0) (1,1,1)
    REQUIRE(p.set_uniform("m", std::array<float, 9>{1, 0, 0, 0, 2, 0, 1, 1, 1}).ok());
    REQUIRE(p.set_uniform("arr", std::array<float, 2>{1, 2}).ok());     // elements 0, 1
    REQUIRE(p.set_uniform("arr[2]", std::array<float, 2>{3, 4}).ok());  // elements 2, 3
    REQUIRE(p.set_uniform("s[1].a", std::array<float, 1>{0.25f}).ok());
    REQUIRE(p.set_uniform("s[0].b", std::array<float, 2>{0.0f, 0.5f}).ok());
    auto outs = run_vertices(p, {{"gl_Vertex", 4, {0, 0, 0, 1}}}, 1);
    REQUIRE(outs.ok());
    CHECK(first_vertex(*outs, "r0") == std::vector<float>{2.5f, 1, 2, 3});
    CHECK(first_vertex(*outs, "r1") == std::vector<float>{-7, 4, 5, 1});
    CHECK(first_vertex(*outs, "r2") == std::vector<float>{4.75f, 7.75f, 3.75f, 4321.75f});
    REQUIRE(p.set_uniform("b", std::array<int32_t, 1>{0}).ok());  // ...and ints
    outs = run_vertices(p, {{"gl_Vertex", 4, {0, 0, 0, 1}}}, 1);
    REQUIRE(outs.ok());
    CHECK(first_vertex(*outs, "r1")[3] == 0.0f);
}

TEST_CASE("set_uniform takes scalars and glm types", "[api][uniform]") {
    Program p = compile(kUniformVs, kUniformFs);
    REQUIRE(p.set_uniform("f", 2.5).ok());  // double, converted to float
    REQUIRE(p.set_uniform("v", glm::vec3(1, 2, 3)).ok());
    REQUIRE(p.set_uniform("i", -7).ok());
    REQUIRE(p.set_uniform("iv", glm::ivec2(4, 5)).ok());
    REQUIRE(p.set_uniform("b", true).ok());
    // glm is column-major as GL: columns (1,0,0) (0,2,0) (1,1,1)
    REQUIRE(p.set_uniform("m", glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 2, 0), glm::vec3(1, 1, 1))).ok());
    REQUIRE(p.set_uniform("arr", glm::vec4(1, 2, 3, 4)).ok());  // four elements from element 0
    REQUIRE(p.set_uniform("s[1].a", 0.25f).ok());
    REQUIRE(p.set_uniform("s[0].b", glm::vec2(0.0f, 0.5f)).ok());
    auto outs = run_vertices(p, {{"gl_Vertex", 4, {0, 0, 0, 1}}}, 1);
    REQUIRE(outs.ok());
    CHECK(first_vertex(*outs, "r0") == std::vector<float>{2.5f, 1, 2, 3});
    CHECK(first_vertex(*outs, "r1") == std::vector<float>{-7, 4, 5, 1});
    CHECK(first_vertex(*outs, "r2") == std::vector<float>{4.75f, 7.75f, 3.75f, 4321.75f});
    CHECK_FALSE(p.set_uniform("i", 1.0f).ok());  // a float does not set an int
    CHECK_FALSE(p.set_uniform("v", glm::vec4(1)).ok());
}

TEST_CASE("value() of a failed result throws the diagnostics", "[api][result]") {
    Result<Program> failed = Program::compile({{"a.vert", "void main() { gl_Position = nope; }"}}, {});
    REQUIRE_FALSE(failed.ok());
    try {
        (void)failed.value();
        FAIL("value() returned");
    } catch (const BadResultAccess& e) {
        CHECK_THAT(e.what(), Catch::StartsWith("glslrun: value() of a failed result:"));
        CHECK_THAT(e.what(), Catch::Contains("a.vert:1: error:"));
        CHECK(e.error.str() == failed.error().str());
    }
    CHECK_THROWS_AS(failed->exec, BadResultAccess);
    Status fine = Ok{};
    CHECK_THROWS_AS(fine.error(), std::logic_error);
}

TEST_CASE("set_uniform reports mistakes clearly", "[api][uniform]") {
    Program p = compile(kUniformVs, kUniformFs);
    auto message = [](const Status& s) { return s.ok() ? std::string() : s.error().str(); };
    Status unknown = p.set_uniform("nope", std::array<float, 1>{1});
    CHECK_FALSE(unknown.ok());
    CHECK_THAT(message(unknown), Catch::Contains("nope"));
    CHECK_THAT(message(p.set_uniform("i", std::array<float, 1>{1})), Catch::Contains("int"));
    CHECK_THAT(message(p.set_uniform("f", std::array<int32_t, 1>{1})), Catch::Contains("float"));
    CHECK_FALSE(p.set_uniform("v", std::array<float, 2>{1, 2}).ok());           // vec3 needs 3 per element
    CHECK_FALSE(p.set_uniform("arr", std::array<float, 5>{1, 2, 3, 4, 5}).ok()); // 4 elements only
    CHECK_FALSE(p.set_uniform("arr[3]", std::array<float, 2>{1, 2}).ok());
    CHECK_FALSE(p.set_uniform("arr[4]", std::array<float, 1>{1}).ok());
    CHECK_FALSE(p.set_uniform("f", std::span<const float>{}).ok());
    CHECK_FALSE(p.set_uniform("s[2].a", std::array<float, 1>{1}).ok());
    CHECK(p.has_uniform("arr[3]"));
    CHECK(p.has_uniform("s[1].b"));
    CHECK_FALSE(p.has_uniform("r0"));
}

TEST_CASE("uniforms() lists GL leaf names with GLSL types", "[api][uniform]") {
    Program p = compile(kUniformVs, kUniformFs);
    auto list = p.uniforms();
    auto find = [&](const std::string& name) -> const UniformInfo* {
        for (const auto& u : list)
            if (u.name == name) return &u;
        return nullptr;
    };
    struct Expect { const char* name; const char* type; uint32_t size; };
    for (Expect e : {Expect{"f", "float", 1}, Expect{"v", "vec3", 1}, Expect{"i", "int", 1},
                     Expect{"iv", "ivec2", 1}, Expect{"b", "bool", 1}, Expect{"m", "mat3", 1},
                     Expect{"arr", "float", 4}, Expect{"s[0].a", "float", 1}, Expect{"s[1].b", "vec2", 1}}) {
        INFO(e.name);
        const UniformInfo* u = find(e.name);
        REQUIRE(u);
        CHECK(u->type == e.type);
        CHECK(u->array_size == e.size);
        CHECK_FALSE(u->builtin);
    }
    CHECK_FALSE(p.dump_ir().empty());
}

TEST_CASE("run_vertices runs many vertices in batches, defaults for missing attributes", "[api][run]") {
    Program p = compile(R"(
attribute vec2 offset;
attribute vec4 extra;
varying vec4 col;
varying vec4 ex;
varying float idx;
uniform float scale;
void main() {
    gl_Position = vec4(gl_Vertex.xy * scale + offset, gl_Vertex.z, 1.0);
    col = gl_Color;
    ex = extra;
    idx = gl_Vertex.x * gl_Vertex.x;
}
)", "varying vec4 col; varying vec4 ex; varying float idx; void main() { gl_FragColor = col + ex + vec4(idx); }");
    REQUIRE(p.set_uniform("scale", std::array<float, 1>{3.0f}).ok());
    const uint32_t n = 37;  // several batches plus a partial one
    VertexAttrib vertex{"gl_Vertex", 3, {}}, offset{"offset", 2, {}}, extra{"extra", 2, {}};
    for (uint32_t i = 0; i < n; ++i) {
        vertex.data.insert(vertex.data.end(), {float(i), float(2 * i), -float(i)});
        offset.data.insert(offset.data.end(), {0.5f, -float(i)});
        extra.data.insert(extra.data.end(), {float(i) * 0.25f, 7.0f});
    }
    auto outs = run_vertices(p, {vertex, offset, extra}, n);
    REQUIRE(outs.ok());
    const auto& pos = output(*outs, "gl_Position");
    const auto& col = output(*outs, "col");
    const auto& ex = output(*outs, "ex");
    const auto& idx = output(*outs, "idx");
    REQUIRE(pos.data.size() == n * 4);
    for (uint32_t i = 0; i < n; ++i) {
        INFO("vertex " << i);
        CHECK(pos.data[i * 4 + 0] == float(i) * 3 + 0.5f);
        CHECK(pos.data[i * 4 + 1] == float(2 * i) * 3 - float(i));
        CHECK(pos.data[i * 4 + 2] == -float(i));
        CHECK(pos.data[i * 4 + 3] == 1.0f);
        for (int k = 0; k < 4; ++k) CHECK(col.data[i * 4 + k] == 1.0f);  // GL's current colour
        CHECK(ex.data[i * 4 + 0] == float(i) * 0.25f);
        CHECK(ex.data[i * 4 + 1] == 7.0f);
        CHECK(ex.data[i * 4 + 2] == 0.0f);  // missing components are (.., 0, 1)
        CHECK(ex.data[i * 4 + 3] == 1.0f);
        CHECK(idx.data[i] == float(i * i));
    }
    auto bad = run_vertices(p, {{"offset", 2, {1, 2, 3}}}, 2);
    CHECK_FALSE(bad.ok());
}

TEST_CASE("run_fragments: several lanes, discard, partial quads", "[api][run]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; }", R"(
uniform float limit;
void main() {
    if (gl_FragCoord.x > limit) discard;
    gl_FragColor = vec4(gl_FragCoord.x * 2.0, gl_FragCoord.y, gl_FrontFacing ? 1.0 : 0.0, 1.0);
}
)");
    REQUIRE(p.set_uniform("limit", std::array<float, 1>{20.0f}).ok());
    const uint32_t n = 42;
    VertexAttrib coord{"gl_FragCoord", 4, {}}, facing{"gl_FrontFacing", 1, {}};
    for (uint32_t i = 0; i < n; ++i) {
        coord.data.insert(coord.data.end(), {float(i) + 0.5f, float(i % 3), 0.5f, 1.0f});
        facing.data.push_back(float(i % 2));
    }
    auto outs = run_fragments(p, {coord, facing}, n);
    REQUIRE(outs.ok());
    const auto& color = output(*outs, "gl_FragColor");
    const auto& discarded = output(*outs, "discarded");
    REQUIRE(discarded.data.size() == n);
    for (uint32_t i = 0; i < n; ++i) {
        INFO("fragment " << i);
        bool killed = float(i) + 0.5f > 20.0f;
        CHECK(discarded.data[i] == (killed ? 1.0f : 0.0f));
        if (killed) continue;
        CHECK(color.data[i * 4 + 0] == (float(i) + 0.5f) * 2.0f);
        CHECK(color.data[i * 4 + 1] == float(i % 3));
        CHECK(color.data[i * 4 + 2] == float(i % 2));
    }
}

TEST_CASE("a runaway loop is an error with its line, not a hang", "[api][run]") {
    Program p = compile("void main() { gl_Position = gl_Vertex; }", R"(
uniform float inc;
void main() {
    float x = 0.0;
    for (int i = 0; i < 10; i += 0) {
        x += inc;
    }
    gl_FragColor = vec4(x);
}
)");
    p.exec.max_loop_iterations = 1000;
    auto outs = run_fragments(p, {}, 4);
    REQUIRE_FALSE(outs.ok());
    REQUIRE(!outs.error().diagnostics.empty());
    CHECK(outs.error().diagnostics.front().line == 5);
}
