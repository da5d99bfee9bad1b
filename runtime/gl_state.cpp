// GLState defaults and the derivation of GLSL 1.10's built-in uniforms (§7.5)
// from it. Derived values follow Mesa's state tracker (prog_statevars.c) where
// the GL specification leaves the built-in's value open.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <glm/gtc/matrix_inverse.hpp>

#include "ir/precise_math.h"
#include "runtime/program_state.h"

namespace glslrun {

GLState::GLState() {
    texture_matrix.fill(glm::mat4(1.0f));
    lights[0].diffuse = {1, 1, 1, 1};
    lights[0].specular = {1, 1, 1, 1};
}

namespace {

// Texture-unit arrays are emitted this long; apply_builtin_uniforms copies as
// many elements as the program declares.
constexpr int kMaxUnits = 32;

using Emit = std::function<void(std::string_view name, const float* values, size_t count)>;
// The built-ins the program reads: state nobody reads is never derived
// (the inverses of 32 texture matrices, light products, ...), and groups
// nobody reads are not even named. This runs at every draw: a scene of
// many small draws spent 6% of its frame naming the ~150 built-ins (perf).
// A program reads a few built-ins: a list searched in order beats a hash.
struct Wants {
    std::vector<std::pair<std::string_view, const ir::Uniform*>> names;
    const ir::Uniform* find(std::string_view n) const {
        for (const auto& entry : names)
            if (entry.first == n) return entry.second;
        return nullptr;
    }
    bool name(std::string_view n) const { return find(n) != nullptr; }
    bool prefix(std::string_view p) const {
        for (const auto& entry : names)
            if (entry.first.starts_with(p)) return true;
        return false;
    }
};

void emit_vec(const Emit& emit, std::string_view name, const glm::vec4& v) { emit(name, &v[0], 4); }
void emit_vec3(const Emit& emit, std::string_view name, const glm::vec3& v) { emit(name, &v[0], 3); }
void emit_float(const Emit& emit, std::string_view name, float f) { emit(name, &f, 1); }

// The four variants of one matrix: M, Inverse, Transpose, InverseTranspose.
void emit_matrix_family(const Emit& emit, const Wants& wants, const std::string& base,
                        const std::vector<glm::mat4>& ms) {
    if (!wants.prefix(base)) return;
    auto each = [&](const char* suffix, auto transform) {
        if (!wants.name(base + suffix)) return;
        std::vector<float> words;
        for (const glm::mat4& m : ms) {
            glm::mat4 t = transform(m);
            words.insert(words.end(), &t[0][0], &t[0][0] + 16);
        }
        emit(base + suffix, words.data(), words.size());
    };
    each("", [](const glm::mat4& m) { return m; });
    each("Inverse", [](const glm::mat4& m) { return glm::inverse(m); });
    each("Transpose", [](const glm::mat4& m) { return glm::transpose(m); });
    each("InverseTranspose", [](const glm::mat4& m) { return glm::inverseTranspose(m); });
}

glm::vec3 normalize_or_zero(glm::vec3 v) {
    float len = glm::length(v);
    return len > 0.0f ? v / len : v;
}

// A prefix and a field's name, without a heap string per field: every draw
// names a light's 13 fields (many_draws: a string made and freed per name
// was most of the built-ins' cost, perf).
class FieldName {
public:
    explicit FieldName(std::string_view prefix) : size_(std::min(prefix.size(), sizeof text_)) {
        std::memcpy(text_, prefix.data(), size_);
    }
    std::string_view operator()(std::string_view field) {
        const size_t n = std::min(field.size(), sizeof text_ - size_);
        std::memcpy(text_ + size_, field.data(), n);
        return {text_, size_ + n};
    }

private:
    char text_[64];
    size_t size_;
};

void emit_light(const Emit& emit, int i, const LightState& l) {
    FieldName p(fmt::format("gl_LightSource[{}].", i));
    emit_vec(emit, p("ambient"), l.ambient);
    emit_vec(emit, p("diffuse"), l.diffuse);
    emit_vec(emit, p("specular"), l.specular);
    emit_vec(emit, p("position"), l.position);
    // Mesa: normalize(normalize(position.xyz) + (0,0,1)) for the infinite viewer, w = 1.
    glm::vec3 half = normalize_or_zero(normalize_or_zero(glm::vec3(l.position)) + glm::vec3(0, 0, 1));
    emit_vec(emit, p("halfVector"), glm::vec4(half, 1.0f));
    emit_vec3(emit, p("spotDirection"), l.spot_direction);
    emit_float(emit, p("spotExponent"), l.spot_exponent);
    emit_float(emit, p("spotCutoff"), l.spot_cutoff);
    // math::cos, not libm: the uniform reaches the image, so it must not depend on the libm version.
    float cos_cutoff = l.spot_cutoff == 180.0f ? -1.0f : math::cos(glm::radians(l.spot_cutoff));
    emit_float(emit, p("spotCosCutoff"), cos_cutoff);
    emit_float(emit, p("constantAttenuation"), l.constant_attenuation);
    emit_float(emit, p("linearAttenuation"), l.linear_attenuation);
    emit_float(emit, p("quadraticAttenuation"), l.quadratic_attenuation);
}

void emit_material(const Emit& emit, const Wants& wants, const std::string& side, const MaterialState& m,
                   const GLState& gl) {
    FieldName p("gl_" + side + "Material.");
    emit_vec(emit, p("emission"), m.emission);
    emit_vec(emit, p("ambient"), m.ambient);
    emit_vec(emit, p("diffuse"), m.diffuse);
    emit_vec(emit, p("specular"), m.specular);
    emit_float(emit, p("shininess"), m.shininess);
    // Mesa: rgb = emission + ambient * model ambient, alpha = diffuse alpha.
    glm::vec4 scene = m.emission + m.ambient * gl.light_model_ambient;
    scene.a = m.diffuse.a;
    emit_vec(emit, "gl_" + side + "LightModelProduct.sceneColor", scene);
    for (int i = 0; i < 8; ++i) {
        const LightState& l = gl.lights[i];
        std::string prefix = fmt::format("gl_{}LightProduct[{}].", side, i);
        if (!wants.prefix(prefix)) continue;
        FieldName lp(prefix);
        emit_vec(emit, lp("ambient"), l.ambient * m.ambient);
        emit_vec(emit, lp("diffuse"), l.diffuse * m.diffuse);
        emit_vec(emit, lp("specular"), l.specular * m.specular);
    }
}

void emit_matrices(const Emit& emit, const Wants& wants, const GLState& gl) {
    emit_matrix_family(emit, wants, "gl_ModelViewMatrix", {gl.modelview});
    emit_matrix_family(emit, wants, "gl_ProjectionMatrix", {gl.projection});
    emit_matrix_family(emit, wants, "gl_ModelViewProjectionMatrix", {gl.projection * gl.modelview});
    if (wants.prefix("gl_TextureMatrix")) {
        // glslang may size the texture-unit arrays beyond GLState's 8 units: those are identity.
        std::vector<glm::mat4> textures(kMaxUnits, glm::mat4(1.0f));
        std::copy(gl.texture_matrix.begin(), gl.texture_matrix.end(), textures.begin());
        emit_matrix_family(emit, wants, "gl_TextureMatrix", textures);
    }
    if (wants.name("gl_NormalMatrix")) {
        glm::mat3 normal = glm::inverseTranspose(glm::mat3(gl.modelview));
        emit("gl_NormalMatrix", &normal[0][0], 9);
    }
    if (!wants.name("gl_NormalScale")) return;
    // Mesa: 1 / |row 2 of the inverse modelview's upper 3x3|.
    glm::mat4 inv = glm::inverse(gl.modelview);
    float f = inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2];
    emit_float(emit, "gl_NormalScale", f < 1e-12f ? 1.0f : 1.0f / std::sqrt(f));
}

void emit_fixed_defaults(const Emit& emit, const Wants& wants, const GLState& gl) {
    if (wants.prefix("gl_DepthRange.")) {
        emit_float(emit, "gl_DepthRange.near", gl.depth_near);
        emit_float(emit, "gl_DepthRange.far", gl.depth_far);
        emit_float(emit, "gl_DepthRange.diff", gl.depth_far - gl.depth_near);
    }
    if (wants.name("gl_ClipPlane")) emit("gl_ClipPlane", &gl.clip_planes[0][0], 24);
    if (wants.prefix("gl_Point.")) {
        emit_float(emit, "gl_Point.size", gl.point_size);
        emit_float(emit, "gl_Point.sizeMin", gl.point_size_min);
        emit_float(emit, "gl_Point.sizeMax", gl.point_size_max);
        emit_float(emit, "gl_Point.fadeThresholdSize", gl.point_fade_threshold_size);
        emit_float(emit, "gl_Point.distanceConstantAttenuation", gl.point_distance_attenuation[0]);
        emit_float(emit, "gl_Point.distanceLinearAttenuation", gl.point_distance_attenuation[1]);
        emit_float(emit, "gl_Point.distanceQuadraticAttenuation", gl.point_distance_attenuation[2]);
    }
    emit_vec(emit, "gl_LightModel.ambient", gl.light_model_ambient);
    if (wants.name("gl_TextureEnvColor")) {
        // glslang may size the array beyond GLState's 8 units: those keep GL's default, zero.
        std::vector<float> words(kMaxUnits * 4, 0.0f);
        std::memcpy(words.data(), &gl.texture_env_color[0][0], sizeof gl.texture_env_color);
        emit("gl_TextureEnvColor", words.data(), words.size());
    }
    const char* coord = "STRQ";
    for (int c = 0; c < 4 && (wants.prefix("gl_EyePlane") || wants.prefix("gl_ObjectPlane")); ++c) {
        const std::array<std::array<glm::vec4, 4>, 8> defaults = GLState::default_texgen_planes();
        auto planes = [&](const std::array<std::array<glm::vec4, 4>, 8>& units) {
            std::vector<float> words;
            for (int unit = 0; unit < kMaxUnits; ++unit) {
                const glm::vec4& p = unit < 8 ? units[size_t(unit)][size_t(c)] : defaults[0][size_t(c)];
                words.insert(words.end(), &p[0], &p[0] + 4);
            }
            return words;
        };
        std::vector<float> eye = planes(gl.eye_planes), object = planes(gl.object_planes);
        emit(fmt::format("gl_EyePlane{}", coord[c]), eye.data(), eye.size());
        emit(fmt::format("gl_ObjectPlane{}", coord[c]), object.data(), object.size());
    }
    if (!wants.prefix("gl_Fog.")) return;
    emit_vec(emit, "gl_Fog.color", gl.fog.color);
    emit_float(emit, "gl_Fog.density", gl.fog.density);
    emit_float(emit, "gl_Fog.start", gl.fog.start);
    emit_float(emit, "gl_Fog.end", gl.fog.end);
    // Mesa: 1 / (end - start), and 1 when they are equal (GL leaves that case open).
    float span = gl.fog.end - gl.fog.start;
    emit_float(emit, "gl_Fog.scale", span != 0.0f ? 1.0f / span : 1.0f);
}

void for_each_builtin(const GLState& gl, const Wants& wants, const Emit& emit) {
    emit_matrices(emit, wants, gl);
    emit_fixed_defaults(emit, wants, gl);
    for (int i = 0; i < 8 && wants.prefix("gl_LightSource["); ++i)
        if (wants.prefix(fmt::format("gl_LightSource[{}]", i))) emit_light(emit, i, gl.lights[i]);
    if (wants.prefix("gl_Front")) emit_material(emit, wants, "Front", gl.front_material, gl);
    if (wants.prefix("gl_Back")) emit_material(emit, wants, "Back", gl.back_material, gl);
}

}  // namespace

Status apply_builtin_uniforms(Program& program, const GLState& gl) {
    if (Status valid = check_valid(program); !valid) return valid;
    Program::State& st = state_of(program);
    Wants wants;
    for (const ir::Uniform& u : st.ir.uniforms)
        if (u.builtin && u.read) wants.names.emplace_back(u.name, &u);
    if (wants.names.empty()) return Ok{};
    for_each_builtin(gl, wants, [&](std::string_view name, const float* values, size_t count) {
        const ir::Uniform* found = wants.find(name);
        if (!found) return;
        const ir::Uniform& u = *found;
        size_t words = std::min<size_t>(count, size_t(u.type.components()) * u.array_size);
        if (u.slot + words > st.uniforms.size()) return;  // malformed layout: never write past the store
        std::memcpy(st.uniforms.data() + u.slot, values, words * sizeof(float));
    });
    return Ok{};
}

}  // namespace glslrun
