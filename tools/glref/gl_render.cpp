#include "tools/glref/gl_render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include "tools/glref/gl_context.h"
#include "tools/glref/gl_fixed.h"
#include "tools/glref/gl_textures.h"
#include "tools/glref/gl_uniforms.h"
#include "scene/bench_report.h"
#include "glslrun/scene/render.h"

namespace glslrun::glref {

namespace {

using scene::Scene;

Status check_gl(const std::string& during) {
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) return Ok{};
    return Error(fmt::format("Mesa reported {} {}", gl_error_name(e), during));
}

// ------------------------------------------------------------ program ---
std::string info_log(const GLFunctions& gl, GLuint object, bool program) {
    GLint length = 0;
    (program ? gl.GetProgramiv : gl.GetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    if (program)
        gl.GetProgramInfoLog(object, GLsizei(log.size()), &length, log.data());
    else
        gl.GetShaderInfoLog(object, GLsizei(log.size()), &length, log.data());
    log.resize(size_t(std::max(length, 0)));
    return log;
}

// Mesa's "0:12(5): error: ..." gives source string, line and column; name
// the file instead, as glslrun's own messages do: "a.vert:12:5: error: ...".
std::string with_file_name(const std::string& log, const std::string& file) {
    std::istringstream in(log);
    std::string out;
    for (std::string line; std::getline(in, line);) {
        int line_no = 0, column = 0, used = 0;
        if (std::sscanf(line.c_str(), "0:%d(%d):%n", &line_no, &column, &used) == 2 && used > 0)
            line = fmt::format("{}:{}:{}:{}", file, line_no, column, line.substr(size_t(used)));
        out += line + "\n";
    }
    return out;
}

// One shader object per source, as glslrun compiles each source as its own unit.
Status attach_shaders(const GLFunctions& gl, GLuint program, GLenum stage, const std::vector<ShaderSource>& sources) {
    for (const ShaderSource& src : sources) {
        GLuint shader = gl.CreateShader(stage);
        const char* text = src.text.c_str();
        gl.ShaderSource(shader, 1, &text, nullptr);
        gl.CompileShader(shader);
        GLint ok = 0;
        gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) return Error(fmt::format("Mesa cannot compile '{}':\n{}", src.name,
                                            with_file_name(info_log(gl, shader, false), src.name)));
        gl.AttachShader(program, shader);
    }
    return Ok{};
}

Result<GLuint> build_program(const GLFunctions& gl, const std::vector<ShaderSource>& vertex,
                             const std::vector<ShaderSource>& fragment) {
    if (vertex.empty() && fragment.empty()) return GLuint(0);  // GL's fixed function for both stages
    GLuint program = gl.CreateProgram();
    if (Status st = attach_shaders(gl, program, GL_VERTEX_SHADER, vertex); !st) return st.error();
    if (Status st = attach_shaders(gl, program, GL_FRAGMENT_SHADER, fragment); !st) return st.error();
    gl.LinkProgram(program);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) return Error("Mesa cannot link the program:\n" + info_log(gl, program, true));
    gl.UseProgram(program);
    return program;
}

// ---------------------------------------------------------- GL state ---
void load_matrix(GLenum mode, const glm::mat4& m) {
    glMatrixMode(mode);
    glLoadMatrixf(glm::value_ptr(m));
}

// GL transforms GL_POSITION and GL_SPOT_DIRECTION by the modelview current at
// glLightfv: here GL itself does what derive_eye_space_lights() computes. A
// position or direction the file left out is not set: it keeps GL's default,
// which no modelview ever transformed.
void set_light(GLenum id, const scene::LightSetting& light, const glm::mat4& view) {
    const LightState& l = light.as_given;
    glLightfv(id, GL_AMBIENT, glm::value_ptr(l.ambient));
    glLightfv(id, GL_DIFFUSE, glm::value_ptr(l.diffuse));
    glLightfv(id, GL_SPECULAR, glm::value_ptr(l.specular));
    glLightf(id, GL_SPOT_EXPONENT, l.spot_exponent);
    glLightf(id, GL_SPOT_CUTOFF, l.spot_cutoff);
    glLightf(id, GL_CONSTANT_ATTENUATION, l.constant_attenuation);
    glLightf(id, GL_LINEAR_ATTENUATION, l.linear_attenuation);
    glLightf(id, GL_QUADRATIC_ATTENUATION, l.quadratic_attenuation);
    load_matrix(GL_MODELVIEW, light.world_space ? view : glm::mat4(1.0f));
    if (light.has_position) glLightfv(id, GL_POSITION, glm::value_ptr(l.position));
    if (light.has_spot_direction) glLightfv(id, GL_SPOT_DIRECTION, glm::value_ptr(l.spot_direction));
    if (light.enabled) glEnable(id);
}

void set_material(GLenum face, const MaterialState& m) {
    glMaterialfv(face, GL_AMBIENT, glm::value_ptr(m.ambient));
    glMaterialfv(face, GL_DIFFUSE, glm::value_ptr(m.diffuse));
    glMaterialfv(face, GL_SPECULAR, glm::value_ptr(m.specular));
    glMaterialfv(face, GL_EMISSION, glm::value_ptr(m.emission));
    glMaterialf(face, GL_SHININESS, m.shininess);
}

void set_lighting(const Scene& s) {
    for (size_t i = 0; i < s.lights.size(); ++i) set_light(GLenum(GL_LIGHT0 + i), s.lights[i], s.view);
    const GLState& g = s.gl;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, glm::value_ptr(g.light_model_ambient));
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, g.light_model_local_viewer);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, g.light_model_two_side);
    set_material(GL_FRONT, g.front_material);
    set_material(GL_BACK, g.back_material);
}

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

// GL's enums in the order of glslrun's (glslrun.h lists them in GL's order).
constexpr GLenum kStencilOps[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
constexpr GLenum kBlendFactors[] = {
    GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
constexpr GLenum kBlendEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};

GLenum compare_enum(CompareFunc f) { return GLenum(GL_NEVER + int(f)); }

void set_stencil(const GLFunctions& gl, const GLState& g) {
    enable(GL_STENCIL_TEST, g.stencil_test);
    const GLenum faces[2] = {GL_FRONT, GL_BACK};
    for (size_t i = 0; i < 2; ++i) {
        const StencilFace& f = g.stencil[i];
        gl.StencilFuncSeparate(faces[i], compare_enum(f.func), f.ref, f.value_mask);
        gl.StencilOpSeparate(faces[i], kStencilOps[int(f.fail)], kStencilOps[int(f.depth_fail)],
                             kStencilOps[int(f.depth_pass)]);
        gl.StencilMaskSeparate(faces[i], f.write_mask);
    }
}

void set_draw_buffers(const GLFunctions& gl, int count) {
    std::array<GLenum, kMaxDrawBuffers> buffers{};
    for (int i = 0; i < count; ++i) buffers[size_t(i)] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    gl.DrawBuffers(count, buffers.data());
}

// GL 2.1 §4.1's state, in the order the operations run.
void set_fragment_state(const GLFunctions& gl, const GLState& g) {
    enable(GL_SCISSOR_TEST, g.scissor_test);
    glScissor(g.scissor_box[0], g.scissor_box[1], g.scissor_box[2], g.scissor_box[3]);
    enable(GL_ALPHA_TEST, g.alpha_test);
    glAlphaFunc(compare_enum(g.alpha_func), g.alpha_ref);
    set_stencil(gl, g);
    glDepthMask(g.depth_mask);
    enable(GL_BLEND, g.blend);
    const BlendState& b = g.blend_state;
    gl.BlendFuncSeparate(kBlendFactors[int(b.src_rgb)], kBlendFactors[int(b.dst_rgb)], kBlendFactors[int(b.src_alpha)],
                         kBlendFactors[int(b.dst_alpha)]);
    gl.BlendEquationSeparate(kBlendEquations[int(b.equation_rgb)], kBlendEquations[int(b.equation_alpha)]);
    gl.BlendColor(b.color.r, b.color.g, b.color.b, b.color.a);
    enable(GL_COLOR_LOGIC_OP, g.color_logic_op);
    glLogicOp(GLenum(GL_CLEAR + int(g.logic_op)));
    glColorMask(g.color_mask[0], g.color_mask[1], g.color_mask[2], g.color_mask[3]);
    set_draw_buffers(gl, g.draw_buffers);
}

// glPointParameter, glLineStipple and glPolygonStipple with their enables.
void set_point_and_stipple_state(const GLFunctions& gl, const GLState& g) {
    gl.PointParameterf(GL_POINT_SIZE_MIN, g.point_size_min);
    gl.PointParameterf(GL_POINT_SIZE_MAX, g.point_size_max);
    gl.PointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, g.point_fade_threshold_size);
    gl.PointParameterfv(GL_POINT_DISTANCE_ATTENUATION, glm::value_ptr(g.point_distance_attenuation));
    gl.PointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, g.point_sprite_coord_lower_left ? GL_LOWER_LEFT : GL_UPPER_LEFT);
    enable(GL_LINE_STIPPLE, g.line_stipple);
    glLineStipple(g.line_stipple_repeat, g.line_stipple_pattern);
    enable(GL_POLYGON_STIPPLE, g.polygon_stipple);
    // glPolygonStipple reads 32 rows of 4 bytes, bottom up, the high bit of
    // each row's first byte leftmost (GL_UNPACK_LSB_FIRST's default).
    std::array<GLubyte, 128> bytes{};
    for (size_t row = 0; row < 32; ++row)
        for (size_t i = 0; i < 4; ++i) bytes[row * 4 + i] = GLubyte(g.polygon_stipple_pattern[row] >> (24 - 8 * i));
    glPolygonStipple(bytes.data());  // 4-byte rows: any GL_UNPACK_ALIGNMENT reads them alike
}

// glPolygonMode, glPolygonOffset, glLineWidth and point sprites.
void set_primitive_state(const GLFunctions& gl, const GLState& g) {
    constexpr GLenum kModes[] = {GL_POINT, GL_LINE, GL_FILL};
    glPolygonMode(GL_FRONT, kModes[int(g.polygon_mode[0])]);
    glPolygonMode(GL_BACK, kModes[int(g.polygon_mode[1])]);
    glPolygonOffset(g.polygon_offset_factor, g.polygon_offset_units);
    enable(GL_POLYGON_OFFSET_FILL, g.polygon_offset_fill);
    enable(GL_POLYGON_OFFSET_LINE, g.polygon_offset_line);
    enable(GL_POLYGON_OFFSET_POINT, g.polygon_offset_point);
    glLineWidth(g.line_width);
    enable(GL_POINT_SPRITE, g.point_sprite);
    for (int unit = 0; unit < 8; ++unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, (g.coord_replace >> unit) & 1u ? GL_TRUE : GL_FALSE);
    }
    gl.ActiveTexture(GL_TEXTURE0);
    set_point_and_stipple_state(gl, g);
}

// glViewport: GLState's width 0 is the whole framebuffer being drawn.
void set_viewport(const GLState& g, const GLTarget& into) {
    std::array<int, 4> vp = g.viewport;
    if (vp[2] <= 0 || vp[3] <= 0) vp = {0, 0, into.width, into.height};
    glViewport(vp[0], vp[1], vp[2], vp[3]);
}

void set_render_state(const GLFunctions& gl, const GLState& g) {
    enable(GL_DEPTH_TEST, g.depth_test);
    // GLState::DepthFunc lists the functions in GL's enum order (GL_NEVER..GL_ALWAYS).
    glDepthFunc(GLenum(GL_NEVER + int(g.depth_func)));
    enable(GL_CULL_FACE, g.cull_face);
    glCullFace(g.cull_front_and_back ? GL_FRONT_AND_BACK : g.cull_back ? GL_BACK : GL_FRONT);
    set_primitive_state(gl, g);
    glFrontFace(g.front_ccw ? GL_CCW : GL_CW);
    glShadeModel(g.flat_shading ? GL_FLAT : GL_SMOOTH);
    enable(GL_VERTEX_PROGRAM_TWO_SIDE, g.vertex_program_two_side);
    glPointSize(g.point_size);
    enable(GL_VERTEX_PROGRAM_POINT_SIZE, g.vertex_program_point_size);
    glDepthRange(g.depth_near, g.depth_far);
    glDisable(GL_DITHER);  // on by default in GL; glslrun never dithers
    set_fragment_state(gl, g);
}

// scene.gl.clip_planes are eye-space planes (the parser already applied the
// view's inverse); with an identity modelview glClipPlane stores them as given.
void set_clip_planes(const GLState& g) {
    load_matrix(GL_MODELVIEW, glm::mat4(1.0f));
    for (size_t i = 0; i < g.clip_planes.size(); ++i) {
        const glm::vec4& p = g.clip_planes[i];
        const GLdouble plane[4] = {p.x, p.y, p.z, p.w};
        glClipPlane(GLenum(GL_CLIP_PLANE0 + i), plane);
        enable(GLenum(GL_CLIP_PLANE0 + i), (g.clip_plane_enabled >> i) & 1u);
    }
}

void set_fog_and_textures(const GLFunctions& gl, const GLState& g) {
    glFogfv(GL_FOG_COLOR, glm::value_ptr(g.fog.color));
    glFogf(GL_FOG_DENSITY, g.fog.density);
    glFogf(GL_FOG_START, g.fog.start);
    glFogf(GL_FOG_END, g.fog.end);
    for (size_t i = 0; i < g.texture_matrix.size(); ++i) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + i));
        load_matrix(GL_TEXTURE, g.texture_matrix[i]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
}

// glClear obeys the scissor and the write masks, and clears the current draw
// buffers: with GL's defaults and every colour buffer, as render_scene clears.
void clear(const GLFunctions& gl, const GLTarget& into, const ClearValues& values) {
    GLbitfield bits = 0;
    glViewport(0, 0, into.width, into.height);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    set_draw_buffers(gl, into.color_buffers);
    if (const auto& c = values.color) {
        glClearColor(c->r, c->g, c->b, c->a);
        bits |= GL_COLOR_BUFFER_BIT;
    }
    if (values.depth) {
        glClearDepth(*values.depth);
        bits |= GL_DEPTH_BUFFER_BIT;
    }
    if (values.stencil) {
        glClearStencil(*values.stencil);
        bits |= GL_STENCIL_BUFFER_BIT;
    }
    if (bits) glClear(bits);
}

Status set_scene_state(const GLFunctions& gl, const Scene& s) {
    load_matrix(GL_PROJECTION, s.projection);
    set_lighting(s);
    set_fog_and_textures(gl, s.gl);
    set_fixed_function_state(gl, s);
    glMatrixMode(GL_MODELVIEW);
    return check_gl("while setting the scene's state");
}

// ------------------------------------------------------------ drawing ---
GLenum gl_mode(Primitive p) {
    switch (p) {
    case Primitive::Points: return GL_POINTS;
    case Primitive::Lines: return GL_LINES;
    case Primitive::LineStrip: return GL_LINE_STRIP;
    case Primitive::LineLoop: return GL_LINE_LOOP;
    case Primitive::Triangles: return GL_TRIANGLES;
    case Primitive::TriangleStrip: return GL_TRIANGLE_STRIP;
    case Primitive::TriangleFan: return GL_TRIANGLE_FAN;
    case Primitive::Quads: return GL_QUADS;
    case Primitive::QuadStrip: return GL_QUAD_STRIP;
    case Primitive::Polygon: return GL_POLYGON;
    }
    return GL_TRIANGLES;
}

// `a`'s data with n components per vertex, for GL's pointer calls that take
// only some sizes: missing components are GL's (0,0,0,1), extra ones dropped.
std::vector<float> with_components(const VertexAttrib& a, uint32_t n) {
    if (a.components == n) return a.data;
    size_t vertices = a.data.size() / a.components;
    std::vector<float> out(vertices * n);
    for (size_t v = 0; v < vertices; ++v)
        for (uint32_t k = 0; k < n; ++k)
            out[v * n + k] = k < a.components ? a.data[v * a.components + k] : (k == 3 ? 1.0f : 0.0f);
    return out;
}

// What one object enabled, to disable after its draw: the next object may
// lack an array and must then read the current value (glColor, ...).
struct BoundArrays {
    std::vector<GLenum> client_states;
    std::vector<GLenum> texture_units;
    std::vector<GLuint> generic;
};

void upload(const GLFunctions& gl, const std::vector<float>& data) {
    GLuint vbo = 0;
    gl.GenBuffers(1, &vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
}

// The texture unit of "gl_MultiTexCoord0".."gl_MultiTexCoord7", else -1.
int multi_tex_coord_unit(const std::string& name) {
    constexpr std::string_view prefix = "gl_MultiTexCoord";
    if (name.size() != prefix.size() + 1 || !name.starts_with(prefix)) return -1;
    char d = name.back();
    return d >= '0' && d <= '7' ? d - '0' : -1;
}

// A conventional attribute's array: upload with GL's accepted size, then point.
void bind_builtin(const GLFunctions& gl, const VertexAttrib& a, GLenum array, uint32_t size, BoundArrays& bound) {
    upload(gl, with_components(a, size));
    auto n = GLint(size);
    switch (array) {
    case GL_VERTEX_ARRAY: glVertexPointer(n, GL_FLOAT, 0, nullptr); break;
    case GL_NORMAL_ARRAY: glNormalPointer(GL_FLOAT, 0, nullptr); break;
    case GL_COLOR_ARRAY: glColorPointer(n, GL_FLOAT, 0, nullptr); break;
    case GL_SECONDARY_COLOR_ARRAY: gl.SecondaryColorPointer(n, GL_FLOAT, 0, nullptr); break;
    case GL_FOG_COORD_ARRAY: gl.FogCoordPointer(GL_FLOAT, 0, nullptr); break;
    case GL_TEXTURE_COORD_ARRAY: glTexCoordPointer(n, GL_FLOAT, 0, nullptr); break;
    }
    glEnableClientState(array);
    if (array != GL_TEXTURE_COORD_ARRAY) bound.client_states.push_back(array);
}

Status bind_array(const GLFunctions& gl, GLuint program, const VertexAttrib& a, BoundArrays& bound) {
    if (a.components < 1 || a.components > 4)
        return Error(fmt::format("attribute '{}' has {} components; GL takes 1..4", a.name, a.components));
    const std::string& n = a.name;
    // GL 2.1's pointer calls: vertex 2..4, normal 3, colour 3..4, secondary 3, fog 1.
    if (n == "gl_Vertex") bind_builtin(gl, a, GL_VERTEX_ARRAY, std::max(a.components, 2u), bound);
    else if (n == "gl_Normal") bind_builtin(gl, a, GL_NORMAL_ARRAY, 3, bound);
    else if (n == "gl_Color") bind_builtin(gl, a, GL_COLOR_ARRAY, std::max(a.components, 3u), bound);
    else if (n == "gl_SecondaryColor") bind_builtin(gl, a, GL_SECONDARY_COLOR_ARRAY, 3, bound);
    else if (n == "gl_FogCoord") bind_builtin(gl, a, GL_FOG_COORD_ARRAY, 1, bound);
    else if (int unit = multi_tex_coord_unit(n); unit >= 0) {
        gl.ClientActiveTexture(GLenum(GL_TEXTURE0 + unit));
        bind_builtin(gl, a, GL_TEXTURE_COORD_ARRAY, a.components, bound);
        bound.texture_units.push_back(GLenum(GL_TEXTURE0 + unit));
        gl.ClientActiveTexture(GL_TEXTURE0);
    } else if (n.starts_with("gl_")) {
        return Error(fmt::format("'{}' is not a built-in attribute of GLSL 1.10", n));
    } else {
        GLint loc = program ? gl.GetAttribLocation(program, n.c_str()) : -1;
        if (loc < 0) return Ok{};  // not read by the program (fixed function reads none)
        upload(gl, a.data);
        gl.VertexAttribPointer(GLuint(loc), GLint(a.components), GL_FLOAT, GL_FALSE, 0, nullptr);
        gl.EnableVertexAttribArray(GLuint(loc));
        bound.generic.push_back(GLuint(loc));
    }
    return Ok{};
}

void unbind_arrays(const GLFunctions& gl, const BoundArrays& bound) {
    for (GLenum array : bound.client_states) glDisableClientState(array);
    for (GLenum unit : bound.texture_units) {
        gl.ClientActiveTexture(unit);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    gl.ClientActiveTexture(GL_TEXTURE0);
    for (GLuint loc : bound.generic) gl.DisableVertexAttribArray(loc);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
}

// Mesa would read past a short array; glslrun refuses it, and so does this.
Status check_mesh(const scene::Object& o) {
    const scene::Mesh& m = o.mesh;
    uint64_t needed = m.vertex_count;
    if (!m.indices.empty()) needed = uint64_t(*std::max_element(m.indices.begin(), m.indices.end())) + 1;
    for (const VertexAttrib& a : m.attribs)
        if (a.components >= 1 && a.data.size() / a.components < needed)
            return Error(fmt::format("object '{}': attribute '{}' has {} vertices, the draw reads {}", o.name, a.name,
                                     a.data.size() / a.components, needed));
    return Ok{};
}

void draw_mesh(const GLFunctions& gl, const scene::Mesh& m) {
    GLenum mode = gl_mode(m.primitive);
    if (m.indices.empty()) {
        glDrawArrays(mode, 0, GLsizei(m.vertex_count));
        return;
    }
    GLuint ebo = 0;
    gl.GenBuffers(1, &ebo);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(uint32_t)), m.indices.data(),
                  GL_STATIC_DRAW);
    glDrawElements(mode, GLsizei(m.indices.size()), GL_UNSIGNED_INT, nullptr);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

// Stops at the first array GL cannot take; `bound` lists what to undo.
Status bind_arrays(const GLFunctions& gl, GLuint program, const scene::Mesh& m, BoundArrays& bound) {
    for (const VertexAttrib& a : m.attribs)
        if (Status st = bind_array(gl, program, a, bound); !st) return st;
    return Ok{};
}

// [current]'s other values: glMultiTexCoord4f, glFogCoordf, glVertexAttrib4f
// (for the attributes the program has; an array, when bound, takes over).
void set_current_attributes(const GLFunctions& gl, GLuint program, const Scene& s) {
    for (const scene::CurrentAttribute& a : s.current_attributes) {
        if (int unit = multi_tex_coord_unit(a.name); unit >= 0)
            glMultiTexCoord4fv(GLenum(GL_TEXTURE0 + unit), glm::value_ptr(a.value));
        else if (a.name == "gl_FogCoord")
            gl.FogCoordf(a.value.x);
        else if (GLint loc = program ? gl.GetAttribLocation(program, a.name.c_str()) : -1; loc >= 0)
            gl.VertexAttrib4fv(GLuint(loc), glm::value_ptr(a.value));
    }
}

// render_scene's per-object state, in the same order: modelview, materials,
// current attributes, the object's uniforms, then the arrays and the draw.
Status draw_object(const GLFunctions& gl, GLuint program, const Scene& s, const scene::Object& o,
                   const scene::Pass* pass, const GLTarget& into, const TextureBindings& textures, GLState& bound) {
    if (Status st = check_mesh(o); !st) return st;
    const GLState* state = o.state ? &*o.state : &s.gl;
    if (pass) {
        const auto& own = pass->object_states[size_t(&o - s.objects.data())];
        state = own ? &*own : &pass->state;
    }
    set_render_state(gl, *state);
    set_viewport(*state, into);
    set_clip_planes(*state);
    load_matrix(GL_PROJECTION, state->projection);  // a pass's camera has its own
    // The product glslrun uses, rather than glMultMatrixf's own rounding.
    load_matrix(GL_MODELVIEW, (pass && pass->view ? *pass->view : s.view) * o.model);
    set_material(GL_FRONT, o.front_material.value_or(s.gl.front_material));
    set_material(GL_BACK, o.back_material.value_or(s.gl.back_material));
    glColor4fv(glm::value_ptr(o.color.value_or(s.gl.current_color)));
    // GL sets only rgb; the current secondary alpha stays GL's 1.
    gl.SecondaryColor3fv(glm::value_ptr(s.gl.current_secondary_color));
    glNormal3fv(glm::value_ptr(s.gl.current_normal));
    set_current_attributes(gl, program, s);
    bind_object_textures(gl, o, textures.objects[size_t(&o - s.objects.data())]);
    for (const scene::TextureSetting& t : o.textures)
        if (Status st = bound.bind_texture(t.unit, t.texture); !st) return st;
    enable_texture_targets(gl, s, bound);
    if (program != 0)
        if (Status st = apply_uniforms(gl, program, o.uniforms); !st) return st;
    BoundArrays arrays;
    Status st = bind_arrays(gl, program, o.mesh, arrays);
    if (st) draw_mesh(gl, o.mesh);
    unbind_arrays(gl, arrays);
    if (!st) return st;
    return check_gl(fmt::format("while drawing object '{}'", o.name));
}

// One pass (the scene's one pass when `pass` is null): glUseProgram, the
// scene's and the pass's uniforms, then its objects.
Status draw_pass(const GLFunctions& gl, GLuint program, const Scene& scene, const scene::Pass* pass,
                 const GLTarget& into, const TextureBindings& textures, GLState& bound) {
    gl.UseProgram(program);
    if (program != 0)
        if (Status st = apply_uniforms(gl, program, scene.uniforms); !st) return st;
    if (pass && program != 0)
        if (Status st = apply_uniforms(gl, program, pass->uniforms); !st) return st;
    if (!pass)
        for (const scene::Object& o : scene.objects)
            if (Status st = draw_object(gl, program, scene, o, nullptr, into, textures, bound); !st) return st;
    if (pass)
        for (size_t i : pass->objects)
            if (Status st = draw_object(gl, program, scene, scene.objects[i], pass, into, textures, bound); !st)
                return st;
    return Ok{};
}

// One frame: the clears (the output's, and the render targets' to their
// starting contents, so every frame starts alike), every pass in its
// framebuffer (each starting with the scene's uniforms, so every frame
// starts from the same program state), and glFinish, so the frame is done.
// programs[i] is pass i's (or the one program without passes); targets[0]
// is the output, targets[1 + t] render target t.
Status draw_frame(const GLFunctions& gl, const std::vector<GLuint>& programs, const Scene& scene,
                  const std::vector<GLTarget>& targets, const TextureBindings& textures) {
    restore_bindings(gl, textures);  // objects' glBindTexture calls last into the next frame
    // The bindings as glslrun tracks them: which target fixed-function texturing samples.
    auto bound = scene::bind_scene_textures(scene);
    if (!bound) return bound.error();
    for (size_t t = 1; t < targets.size(); ++t) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, targets[t].fbo);
        clear(gl, targets[t], ClearValues{glm::vec4(0), 1.0f, 0});
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, targets[0].fbo);
    clear(gl, targets[0], ClearValues{scene.clear_color, scene.clear_depth, scene.clear_stencil});
    if (scene.passes.empty()) {
        if (Status st = draw_pass(gl, programs[0], scene, nullptr, targets[0], textures, *bound); !st) return st;
    }
    for (size_t i = 0; i < scene.passes.size(); ++i) {
        const scene::Pass& pass = scene.passes[i];
        const GLTarget& into = targets[size_t(pass.target + 1)];
        gl.BindFramebuffer(GL_FRAMEBUFFER, into.fbo);
        clear(gl, into, pass.clear);
        if (Status st = draw_pass(gl, programs[i], scene, &pass, into, textures, *bound); !st) return st;
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, targets[0].fbo);
    glFinish();
    return Ok{};
}

// The programs of the passes: a pass's own shaders, or the given ones.
Result<std::vector<GLuint>> build_programs(const GLFunctions& gl, const std::vector<ShaderSource>& vertex,
                                           const std::vector<ShaderSource>& fragment, const Scene& scene) {
    auto main = build_program(gl, vertex, fragment);
    if (!main) return main.error();
    std::vector<GLuint> programs;
    if (scene.passes.empty()) programs.push_back(*main);
    for (const scene::Pass& pass : scene.passes) {
        if (pass.fixed_function) {
            programs.push_back(0);  // glUseProgram(0): GL's fixed function
            continue;
        }
        if (pass.vertex.empty() && pass.fragment.empty()) {
            programs.push_back(*main);
            continue;
        }
        auto own = build_program(gl, pass.vertex, pass.fragment);
        if (!own) return Error(fmt::format("pass '{}': {}", pass.name, own.error().str()));
        programs.push_back(*own);
    }
    return programs;
}

Result<scene::Image> read_back(int width, int height, int buffer) {
    glFinish();
    std::vector<uint8_t> pixels(size_t(width) * size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + buffer));
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    if (Status st = check_gl("while reading the pixels back"); !st) return st.error();
    return scene::image_from_bottom_up(width, height, pixels);
}

}  // namespace

Result<MesaRender> render_with_mesa(const std::string& driver, const std::vector<ShaderSource>& vertex,
                                    const std::vector<ShaderSource>& fragment, const Scene& scene,
                                    const MesaOptions& options) {
    if (scene.width < 1 || scene.height < 1 || scene.width > scene::kMaxImageSide ||
        scene.height > scene::kMaxImageSide)
        return Error(fmt::format("size {}x{} is not 1..{} per side", scene.width, scene.height, scene::kMaxImageSide));
    auto context = MesaContext::create(driver);  // fresh: GL's default state
    if (!context) return context.error();
    const GLFunctions& gl = (*context)->gl();
    const int buffers = scene::color_buffers(scene);
    if (Status st = (*context)->make_framebuffer(scene.width, scene.height, buffers); !st) return st.error();
    auto compile_start = std::chrono::steady_clock::now();
    auto programs = build_programs(gl, vertex, fragment, scene);
    if (!programs) return programs.error();
    double compile_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - compile_start).count();
    if (Status st = set_scene_state(gl, scene); !st) return st.error();
    if (Status st = upload_textures(gl, scene, options.upload_generated_mipmaps); !st) return st.error();
    GLint output = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &output);
    auto made = make_render_targets(gl, scene);
    if (!made) return made.error();
    std::vector<GLTarget> targets{{GLuint(output), scene.width, scene.height, buffers}};
    targets.insert(targets.end(), made->begin(), made->end());
    auto textures = upload_object_textures(gl, scene, options.upload_generated_mipmaps);
    if (!textures) return textures.error();
    std::vector<double> seconds, cpu_seconds;
    for (int frame = 0; frame < std::max(1, options.frames); ++frame) {
        auto start = std::chrono::steady_clock::now();
        double cpu_start = scene::process_cpu_seconds();
        if (Status st = draw_frame(gl, *programs, scene, targets, *textures); !st) return st.error();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        cpu_seconds.push_back(scene::process_cpu_seconds() - cpu_start);
    }
    auto image = read_back(scene.width, scene.height, 0);
    if (!image) return image.error();
    MesaRender render{std::move(*image), {}, (*context)->renderer(), std::move(seconds), std::move(cpu_seconds),
                      compile_seconds};
    for (int i = 1; i < buffers; ++i) {
        auto more = read_back(scene.width, scene.height, i);
        if (!more) return more.error();
        render.more_images.push_back(std::move(*more));
    }
    return render;
}

}  // namespace glslrun::glref
