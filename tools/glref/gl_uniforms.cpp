#include "tools/glref/gl_uniforms.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace glslrun::glref {

namespace {

struct ActiveUniform {
    std::string name;  // without GL's trailing "[0]" for arrays
    GLenum type = 0;
};

std::vector<ActiveUniform> active_uniforms(const GLFunctions& gl, GLuint program) {
    GLint count = 0, max_length = 0;
    gl.GetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    gl.GetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &max_length);
    std::vector<char> buffer(size_t(max_length) + 1);
    std::vector<ActiveUniform> out;
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        gl.GetActiveUniform(program, GLuint(i), GLsizei(buffer.size()), &length, &size, &type, buffer.data());
        std::string name(buffer.data(), size_t(length));
        if (name.ends_with("[0]")) name.resize(name.size() - 3);
        out.push_back({name, type});
    }
    return out;
}

// "arr[2]" and "s[1].f[0]" name an element of what GL lists as "arr" and
// "s[1].f": drop a trailing subscript to find the declaration.
const ActiveUniform* find_declaration(const std::vector<ActiveUniform>& active, std::string_view name) {
    for (int pass = 0; pass < 2; ++pass) {
        for (const ActiveUniform& u : active)
            if (u.name == name) return &u;
        if (name.empty() || name.back() != ']') break;
        name = name.substr(0, name.rfind('['));
    }
    return nullptr;
}

enum class Kind { Float, Int, Bool, Matrix };

struct TypeInfo {
    Kind kind = Kind::Float;
    int components = 1;  // per array element; columns * rows for matrices
    int columns = 0, rows = 0;
};

TypeInfo matrix(int columns, int rows) { return {Kind::Matrix, columns * rows, columns, rows}; }

std::optional<TypeInfo> type_info(GLenum type) {
    switch (type) {
    case GL_FLOAT: return TypeInfo{Kind::Float, 1};
    case GL_FLOAT_VEC2: return TypeInfo{Kind::Float, 2};
    case GL_FLOAT_VEC3: return TypeInfo{Kind::Float, 3};
    case GL_FLOAT_VEC4: return TypeInfo{Kind::Float, 4};
    case GL_INT: return TypeInfo{Kind::Int, 1};
    case GL_INT_VEC2: return TypeInfo{Kind::Int, 2};
    case GL_INT_VEC3: return TypeInfo{Kind::Int, 3};
    case GL_INT_VEC4: return TypeInfo{Kind::Int, 4};
    case GL_BOOL: return TypeInfo{Kind::Bool, 1};
    case GL_BOOL_VEC2: return TypeInfo{Kind::Bool, 2};
    case GL_BOOL_VEC3: return TypeInfo{Kind::Bool, 3};
    case GL_BOOL_VEC4: return TypeInfo{Kind::Bool, 4};
    case GL_FLOAT_MAT2: return matrix(2, 2);
    case GL_FLOAT_MAT3: return matrix(3, 3);
    case GL_FLOAT_MAT4: return matrix(4, 4);
    case GL_FLOAT_MAT2x3: return matrix(2, 3);
    case GL_FLOAT_MAT3x2: return matrix(3, 2);
    case GL_FLOAT_MAT2x4: return matrix(2, 4);
    case GL_FLOAT_MAT4x2: return matrix(4, 2);
    case GL_FLOAT_MAT3x4: return matrix(3, 4);
    case GL_FLOAT_MAT4x3: return matrix(4, 3);
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_2D_RECT: case GL_SAMPLER_2D_RECT_SHADOW:
    case GL_SAMPLER_1D_ARRAY_EXT: case GL_SAMPLER_2D_ARRAY_EXT:
    case GL_SAMPLER_1D_ARRAY_SHADOW_EXT: case GL_SAMPLER_2D_ARRAY_SHADOW_EXT: return TypeInfo{Kind::Int, 1};
    default: return std::nullopt;
    }
}

void set_matrices(const GLFunctions& gl, GLint loc, const TypeInfo& t, GLsizei count, const float* v) {
    // The scene lists matrix columns, which is GL's order without transposing.
    switch (t.columns * 10 + t.rows) {
    case 22: gl.UniformMatrix2fv(loc, count, GL_FALSE, v); break;
    case 33: gl.UniformMatrix3fv(loc, count, GL_FALSE, v); break;
    case 44: gl.UniformMatrix4fv(loc, count, GL_FALSE, v); break;
    case 23: gl.UniformMatrix2x3fv(loc, count, GL_FALSE, v); break;
    case 32: gl.UniformMatrix3x2fv(loc, count, GL_FALSE, v); break;
    case 24: gl.UniformMatrix2x4fv(loc, count, GL_FALSE, v); break;
    case 42: gl.UniformMatrix4x2fv(loc, count, GL_FALSE, v); break;
    case 34: gl.UniformMatrix3x4fv(loc, count, GL_FALSE, v); break;
    case 43: gl.UniformMatrix4x3fv(loc, count, GL_FALSE, v); break;
    }
}

void set_floats(const GLFunctions& gl, GLint loc, const TypeInfo& t, GLsizei count, const std::vector<double>& values) {
    std::vector<float> f(values.begin(), values.end());
    if (t.kind == Kind::Matrix) return set_matrices(gl, loc, t, count, f.data());
    switch (t.components) {
    case 1: gl.Uniform1fv(loc, count, f.data()); break;
    case 2: gl.Uniform2fv(loc, count, f.data()); break;
    case 3: gl.Uniform3fv(loc, count, f.data()); break;
    case 4: gl.Uniform4fv(loc, count, f.data()); break;
    }
}

void set_ints(const GLFunctions& gl, GLint loc, const TypeInfo& t, GLsizei count, const std::vector<double>& values) {
    std::vector<GLint> v;
    for (double d : values) v.push_back(GLint(d));
    switch (t.components) {
    case 1: gl.Uniform1iv(loc, count, v.data()); break;
    case 2: gl.Uniform2iv(loc, count, v.data()); break;
    case 3: gl.Uniform3iv(loc, count, v.data()); break;
    case 4: gl.Uniform4iv(loc, count, v.data()); break;
    }
}

Error error_at(const scene::UniformSetting& s, std::string message) {
    return Error(std::move(message), s.where.file, s.where.line);
}

bool fits_int(const std::vector<double>& values) {
    for (double v : values)
        if (std::abs(v) > 2147483647.0) return false;
    return true;
}

Status apply_one(const GLFunctions& gl, GLuint program, const std::vector<ActiveUniform>& active,
                 const scene::UniformSetting& s) {
    GLint loc = gl.GetUniformLocation(program, s.name.c_str());
    const ActiveUniform* decl = find_declaration(active, s.name);
    if (loc < 0 || !decl) return Ok{};  // inactive: GL ignores location -1
    auto t = type_info(decl->type);
    if (!t) return error_at(s, fmt::format("uniform '{}' has a type (0x{:x}) glref cannot set", s.name, decl->type));
    if (s.values.empty() || s.values.size() % size_t(t->components) != 0)
        return error_at(s, fmt::format("uniform '{}' takes {} value(s) per element; the scene gives {}", s.name,
                                       t->components, s.values.size()));
    auto count = GLsizei(s.values.size() / size_t(t->components));
    bool as_ints = t->kind == Kind::Int || (t->kind == Kind::Bool && s.integral);
    if (t->kind == Kind::Int && !s.integral)
        return error_at(s, fmt::format("uniform '{}' is an integer type: its values must be integers", s.name));
    if (as_ints && !fits_int(s.values))
        return error_at(s, fmt::format("uniform '{}': a value does not fit in an int", s.name));
    for (int i = 0; i < 8 && glGetError() != GL_NO_ERROR; ++i) {
    }  // earlier errors are not this uniform's
    if (as_ints)
        set_ints(gl, loc, *t, count, s.values);
    else
        set_floats(gl, loc, *t, count, s.values);
    if (GLenum e = glGetError(); e != GL_NO_ERROR)
        return error_at(s, fmt::format("Mesa refused uniform '{}': {}", s.name, gl_error_name(e)));
    return Ok{};
}

}  // namespace

Status apply_uniforms(const GLFunctions& gl, GLuint program, const std::vector<scene::UniformSetting>& settings) {
    if (settings.empty()) return Ok{};
    std::vector<ActiveUniform> active = active_uniforms(gl, program);
    for (const scene::UniformSetting& s : settings)
        if (Status st = apply_one(gl, program, active, s); !st) return st;
    return Ok{};
}

}  // namespace glslrun::glref
