// Uniforms of every type set through Program::set_uniform and read back
// through the shader's outputs; arrays, structs, dynamic indexing; errors.
#include "harness.h"

using namespace lang;

namespace {

void set_f(glslrun::Program& p, std::string_view name, const std::vector<float>& values) {
    auto status = p.set_uniform(name, std::span<const float>(values));
    INFO("set_uniform(" << std::string(name) << ") floats: " << (status ? "" : status.error().str()));
    REQUIRE(status.ok());
}

void set_i(glslrun::Program& p, std::string_view name, const std::vector<int32_t>& values) {
    auto status = p.set_uniform(name, std::span<const int32_t>(values));
    INFO("set_uniform(" << std::string(name) << ") ints: " << (status ? "" : status.error().str()));
    REQUIRE(status.ok());
}

}  // namespace

TEST_CASE("float, vec and mat uniforms", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 a;
uniform float uf;
uniform vec2 u2;
uniform vec3 u3;
uniform vec4 u4;
uniform mat2 m2;
uniform mat3 m3;
uniform mat4 m4;
varying vec4 o1, o2, o3, o4;
void main() {
    o1 = vec4(uf * a.x, u2 + a.yz, 0.0);
    o2 = vec4(u3 * a.w, 0.0) + u4;
    o3 = vec4(m2 * a.xy, (m3 * a.xyz).yz);
    o4 = m4 * a;
    gl_Position = vec4(0.0);
})");
    set_f(program, "uf", {2.5f});
    set_f(program, "u2", {-1.0f, 0.5f});
    set_f(program, "u3", {3.0f, 4.0f, 5.0f});
    set_f(program, "u4", {0.25f, -0.5f, 0.75f, 8.0f});
    set_f(program, "m2", {1, 2, 3, 4});                       // column-major
    set_f(program, "m3", {1, 0, 2, 0, 3, 0, -1, 0, 4});
    std::vector<float> m4(16);
    for (int i = 0; i < 16; ++i) m4[i] = float(i) * 0.5f - 3.0f;
    set_f(program, "m4", m4);
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o1", 3, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        return glm::vec4(2.5f * a.x, a.y - 1.0f, a.z + 0.5f, 0);
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        float w = in_a(l).w;
        return glm::vec4(3 * w + 0.25f, 4 * w - 0.5f, 5 * w + 0.75f, 8.0f);
    }, kTight);
    check_output(outs, "o3", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l);
        glm::mat2 m(1, 2, 3, 4);
        glm::mat3 n(1, 0, 2, 0, 3, 0, -1, 0, 4);
        glm::vec3 r = n * glm::vec3(a);
        return glm::vec4(m * glm::vec2(a), r.y, r.z);
    }, kTight);
    check_output(outs, "o4", 4, [&](uint32_t l) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = m4[i];
        return m * in_a(l);
    }, 1e-5f);
}

TEST_CASE("int, ivec, bool and bvec uniforms", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 c;
uniform int ui;
uniform ivec2 i2;
uniform ivec3 i3;
uniform ivec4 i4;
uniform bool ub, ub2;
uniform bvec2 b2;
uniform bvec3 b3;
uniform bvec4 b4;
varying vec4 o1, o2, o3, o4;
void main() {
    ivec4 ic = ivec4(c);
    o1 = vec4(float(ui * ic.x), vec2(i2 + ic.yz), float(i3.z));
    o2 = vec4(i3 * ic.w, 0.0) + vec4(i4);
    o3 = vec4(float(ub), float(ub2), vec2(b2));
    o4 = vec4(float(b3.x && c.x > 0.0), vec2(b3.yz), 0.0) + vec4(b4) * 10.0;
    gl_Position = vec4(0.0);
})");
    set_i(program, "ui", {-3});
    set_i(program, "i2", {7, -8});
    set_i(program, "i3", {1, 2, 3});
    set_i(program, "i4", {10, 20, 30, 40});
    set_i(program, "ub", {1});
    set_f(program, "ub2", {0.0f});                            // bools take floats too
    set_i(program, "b2", {0, 5});                             // any non-zero is true
    set_f(program, "b3", {1.0f, 0.0f, 1.0f});
    set_i(program, "b4", {1, 1, 0, 1});
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o1", 4, [](uint32_t l) {
        glm::vec4 c = in_c(l);
        return glm::vec4(-3.0f * c.x, 7.0f + c.y, -8.0f + c.z, 3.0f);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        float w = in_c(l).w;
        return glm::vec4(w + 10, 2 * w + 20, 3 * w + 30, 40.0f);
    }, kExact);
    check_output(outs, "o3", 4, [](uint32_t) { return glm::vec4(1, 0, 0, 1); }, kExact);
    check_output(outs, "o4", 4, [](uint32_t l) {
        return glm::vec4(b2f(in_c(l).x > 0) + 10, 0 + 10, 1, 10);
    }, kExact);
}

TEST_CASE("uniform arrays with dynamic index, set whole and per element", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 c;
uniform vec4 arr[4];
uniform float weights[3];
uniform int ids[4];
varying vec4 o1, o2;
void main() {
    int i = int(c.z);
    int j = i == 3 ? 0 : i;
    o1 = arr[i] + arr[3 - i] * weights[j];
    o2 = vec4(float(ids[i]), weights[0], weights[1], weights[2]);
    gl_Position = vec4(0.0);
})");
    std::vector<float> all(16);
    for (int i = 0; i < 16; ++i) all[i] = float(i) - 4.5f;
    set_f(program, "arr", all);                           // all four elements
    set_f(program, "arr[2]", {100, 200, 300, 400});       // then one element
    set_f(program, "weights", {0.5f, 2.0f});              // fills weights[0..1]
    set_f(program, "weights[2]", {-1.0f});
    set_i(program, "ids", {9, 8, 7, 6});
    auto outs = run_vs(program, std_attribs());
    auto element = [&](int i) {
        if (i == 2) return glm::vec4(100, 200, 300, 400);
        return glm::vec4(all[i * 4], all[i * 4 + 1], all[i * 4 + 2], all[i * 4 + 3]);
    };
    const float weights[3] = {0.5f, 2.0f, -1.0f};
    check_output(outs, "o1", 4, [&](uint32_t l) {
        int i = int(in_c(l).z), j = i == 3 ? 0 : i;
        return element(i) + element(3 - i) * weights[j];
    }, kTight);
    check_output(outs, "o2", 4, [](uint32_t l) {
        return glm::vec4(9.0f - in_c(l).z, 0.5f, 2.0f, -1.0f);
    }, kExact);
}

TEST_CASE("struct uniforms and arrays of structs", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 c;
struct Light { vec3 pos; float power; };
uniform Light main_light;
uniform Light lights[3];
varying vec4 o1, o2;
void main() {
    int i = int(c.z);
    if (i == 3) i = 1;
    o1 = vec4(main_light.pos, main_light.power);
    o2 = vec4(lights[i].pos * lights[i].power, lights[2 - i].power);
    gl_Position = vec4(0.0);
})");
    set_f(program, "main_light.pos", {1, 2, 3});
    set_f(program, "main_light.power", {0.5f});
    for (int k = 0; k < 3; ++k) {
        std::string base = "lights[" + std::to_string(k) + "]";
        set_f(program, base + ".pos", {float(k), float(k) + 0.5f, -float(k)});
        set_f(program, base + ".power", {float(k) * 2.0f + 1.0f});
    }
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o1", 4, [](uint32_t) { return glm::vec4(1, 2, 3, 0.5f); }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        int i = int(in_c(l).z);
        if (i == 3) i = 1;
        float k = float(i), power = k * 2.0f + 1.0f;
        return glm::vec4(glm::vec3(k, k + 0.5f, -k) * power, float(2 - i) * 2.0f + 1.0f);
    }, kExact);
}

TEST_CASE("1.20 non-square matrix uniform", "[uniforms][120]") {
    auto program = compile_vs(R"(#version 120
attribute vec4 a;
uniform mat2x3 m;
varying vec3 o;
void main() {
    o = m * a.xy;
    gl_Position = vec4(0.0);
})");
    set_f(program, "m", {1, 2, 3, 4, 5, 6});  // two columns of three
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o", 3, [](uint32_t l) {
        glm::mat2x3 m(1, 2, 3, 4, 5, 6);
        return glm::vec4(m * glm::vec2(in_a(l)), 0);
    }, kTight);
}

TEST_CASE("uniforms start at zero and keep their values across runs", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 a;
uniform vec4 u;
varying vec4 o;
void main() { o = u + a * 0.0; gl_Position = vec4(0.0); }
)");
    check_output(run_vs(program, std_attribs()), "o", 4, [](uint32_t) { return glm::vec4(0.0f); }, kExact);
    set_f(program, "u", {1, 2, 3, 4});
    check_output(run_vs(program, std_attribs()), "o", 4, [](uint32_t) { return glm::vec4(1, 2, 3, 4); },
                 kExact);
    check_output(run_vs(program, std_attribs()), "o", 4, [](uint32_t) { return glm::vec4(1, 2, 3, 4); },
                 kExact);
}

TEST_CASE("uniform introspection", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 a;
uniform mat3 m;
uniform float w[3];
varying vec4 o;
void main() { o = vec4(m * a.xyz, w[int(a.w > 0.0)] + w[2]); gl_Position = vec4(0.0); }
)");
    CHECK(program.has_uniform("m"));
    CHECK(program.has_uniform("w"));
    CHECK_FALSE(program.has_uniform("nope"));
    bool found_m = false, found_w = false;
    for (const auto& u : program.uniforms()) {
        if (u.name == "m") { found_m = true; CHECK(u.type == "mat3"); CHECK(u.array_size == 1); }
        if (u.name == "w") { found_w = true; CHECK(u.type == "float"); CHECK(u.array_size == 3); }
    }
    CHECK(found_m);
    CHECK(found_w);
}

TEST_CASE("set_uniform errors are values, not exceptions", "[uniforms][errors]") {
    auto program = compile_vs(R"(
attribute vec4 a;
uniform vec4 v;
uniform int n;
uniform float arr[2];
varying vec4 o;
void main() { o = v * float(n) + a * arr[1] + vec4(arr[0]); gl_Position = vec4(0.0); }
)");
    const std::vector<float> four{1, 2, 3, 4}, three{1, 2, 3}, one{1};
    const std::vector<int32_t> ints{1, 2, 3, 4};
    auto expect_error = [&](const char* what, auto call) {
        INFO(what);
        glslrun::Status status = glslrun::Ok{};
        CHECK_NOTHROW(status = call());
        CHECK_FALSE(status.ok());
        if (!status.ok()) CHECK_FALSE(status.error().str().empty());
    };
    expect_error("unknown name", [&] { return program.set_uniform("missing", std::span<const float>(four)); });
    expect_error("unknown member", [&] { return program.set_uniform("v.q", std::span<const float>(four)); });
    expect_error("floats to an int", [&] { return program.set_uniform("n", std::span<const float>(one)); });
    expect_error("ints to a vec4", [&] { return program.set_uniform("v", std::span<const int32_t>(ints)); });
    expect_error("too few components", [&] { return program.set_uniform("v", std::span<const float>(three)); });
    expect_error("past the end of an array", [&] {
        return program.set_uniform("arr[1]", std::span<const float>(three));
    });
    expect_error("index out of range", [&] { return program.set_uniform("arr[5]", std::span<const float>(one)); });
    // After the failures the program still works with valid values.
    set_f(program, "v", four);
    set_i(program, "n", {2});
    set_f(program, "arr", {0.5f, -1.0f});
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o", 4, [](uint32_t l) {
        return glm::vec4(2, 4, 6, 8) - in_a(l) + glm::vec4(0.5f);
    }, kTight);
}

TEST_CASE("uniform arrays of matrices and structs containing arrays", "[uniforms]") {
    auto program = compile_vs(R"(
attribute vec4 c;
struct W { float w[2]; vec2 p; };
uniform mat2 ms[2];
uniform W s;
varying vec4 o1, o2;
void main() {
    int i = int(c.z) / 2;     // 0 or 1
    int j = 1 - i;
    o1 = vec4(ms[i][j], ms[j][i]);
    o2 = vec4(s.w[i], s.w[j], s.p);
    gl_Position = vec4(0.0);
})");
    set_f(program, "ms", {1, 2, 3, 4, 5, 6, 7, 8});
    set_f(program, "ms[1]", {-5, -6, -7, -8});
    set_f(program, "s.w", {0.5f, 0.25f});
    set_f(program, "s.w[1]", {9.0f});
    set_f(program, "s.p", {3, 4});
    auto outs = run_vs(program, std_attribs());
    const glm::mat2 ms[2] = {glm::mat2(1, 2, 3, 4), glm::mat2(-5, -6, -7, -8)};
    check_output(outs, "o1", 4, [&](uint32_t l) {
        int i = int(in_c(l).z) / 2, j = 1 - i;
        return glm::vec4(ms[i][j], ms[j][i]);
    }, kExact);
    check_output(outs, "o2", 4, [](uint32_t l) {
        int i = int(in_c(l).z) / 2;
        float w[2] = {0.5f, 9.0f};
        return glm::vec4(w[i], w[1 - i], 3, 4);
    }, kExact);
}
