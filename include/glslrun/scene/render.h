// Draws a Scene with glslrun: per object, modelview = view * model, the
// material overrides, the current colour and the uniforms, then draw().
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/scene.h"

namespace glslrun::scene {

// The colour buffers a framebuffer for the scene needs: the most that any
// draw's glDrawBuffers names ([state] draw_buffers, objects' and passes' too).
int color_buffers(const Scene& scene);
// Colour buffer i's image file: out.png for buffer 0, then out.1.png, out.2.png, ...
std::string color_buffer_path(const std::string& output, int buffer);

// Sets the scene's and the object's user uniforms on the program, converting
// the file's numbers to the declared types. Errors cite the scene's file:line;
// with `skip_undeclared`, names the program does not declare are left out.
Status apply_uniforms(Program& program, const std::vector<UniformSetting>& settings, bool skip_undeclared = false);

// scene.gl with the scene's textures bound to their units; with `rounding`
// Gpu (Precision::Fast) generated mipmaps are the GPU's (runtime/mipmap_gpu.h).
Result<GLState> bind_scene_textures(const Scene& scene, ColorRounding rounding = ColorRounding::Nearest);
// The state one object is drawn with: `bound` (from bind_scene_textures)
// with modelview = view * model, the material overrides and the current colour;
// within `pass` (one of scene.passes) the pass's state for the object.
GLState object_gl_state(const Scene& scene, const GLState& bound, const Object& object, const Pass* pass = nullptr);

class FixedFunctionPrograms;  // scene/ffp_programs.cpp

// The programs a scene draws with, one per pass: a pass that names its own
// shaders gets them compiled (with `options`, and `main`'s ExecOptions); the
// others, and a scene without passes, use `main`. `main` must outlive this.
// A program without a vertex or fragment shader, and a `program = "fixed"`
// pass, draw with GL's fixed function for the missing stages: generated per
// draw state (scene/ffp.h) and linked with the program's own shaders.
class ScenePrograms {
public:
    static Result<ScenePrograms> compile(Program& main, const Scene& scene, const CompileOptions& options);
    // The same with the options `main` was compiled with: the passes' shaders
    // see the same -D macros and -I directories as the command line's.
    static Result<ScenePrograms> compile(Program& main, const Scene& scene);
    // Pass i's program; with no passes, 0 is `main`. Uniforms are set on it.
    Program& of_pass(size_t pass) const { return *by_pass_[pass]; }
    // The program a draw of pass i with `gl` runs: of_pass(i) where that has
    // both shaders of its own; else its shaders with the fixed-function
    // stages generated for `gl` (compiled once per distinct source), holding
    // of_pass(i)'s uniform values and ExecOptions. `gl` may change for the
    // draw (two-sided lighting selects gl_BackColor as GL does).
    Result<Program*> for_draw(size_t pass, const Scene& scene, GLState& gl) const;
    size_t size() const { return by_pass_.size(); }
    // Called before pass i draws (the shader debugger's pixel history names
    // each draw's pass); not with a scene without passes.
    std::function<void(size_t pass)> before_pass;
    // The texture `t` binds under `rounding`: with the GPU's rounding a
    // GL_GENERATE_MIPMAP texture's levels as NVIDIA's driver makes them,
    // generated once per texture for these programs' renders (every frame
    // and object binds the same copy).
    std::shared_ptr<const Texture> texture_for(const TextureSetting& t, ColorRounding rounding) const;
    // The scene's, objects' and passes' [uniforms] entries that no program
    // they go to has as an active uniform, each at its file:line with the
    // nearest name the programs have. GL ignores glUniform at location -1,
    // so renders skip them; the command line prints these warnings. An
    // entry with no line (--uniform, or one set in code) is an error of compile().
    const std::vector<Diagnostic>& warnings() const { return warnings_; }
private:
    std::vector<Diagnostic> warnings_;
    std::vector<std::shared_ptr<Program>> own_;
    std::vector<Program*> by_pass_;
    std::shared_ptr<FixedFunctionPrograms> fixed_;
    struct GpuMipmaps;  // scene/render.cpp
    std::shared_ptr<GpuMipmaps> gpu_mipmaps_;
};

// For a scene drawn without shaders (`glslrun scene.toml`): every draw with
// GL's fixed function. A scene without passes gets one `program = "fixed"`
// pass of every object (with their states); passes that would draw with
// the command line's program become fixed ones.
void use_fixed_function(Scene& scene);
// What a scene drawn without shaders (`glslrun scene.toml`) would show as
// nothing but GL's defaults: no lighting, fog, colour sum, texture unit or
// texgen on, no colour of its own (an object's, a mesh's, a [current] one)
// and no `program = "fixed"` pass: every object unlit white. A warning that
// says what to give, or "" when the scene sets fixed-function state.
std::string fixed_function_warning(const Scene& scene);
// The program `glslrun scene.toml` hands ScenePrograms after
// use_fixed_function: no pass draws with it.
Result<Program> unused_main_program();

// Draws every pass's objects into fb as it is, or cleared first to `clear`
// (by the first draw's tiles: draw() with ClearValues). With passes, the
// scene's and objects' uniforms are set on each pass's program that declares
// them; a name that no program declares is skipped, as GL skips location -1
// (ScenePrograms::warnings lists them). fb.rounding is
// set from the programs' precision (color_rounding_for: Fast stores colours
// as the GPU does).
Result<DrawStats> draw_scene_objects(const ScenePrograms& programs, const Scene& scene, Framebuffer& fb,
                                     const ClearValues& clear = {});
// The same, compiling the passes' own programs first.
Result<DrawStats> draw_scene_objects(Program& program, const Scene& scene, Framebuffer& fb,
                                     const ClearValues& clear = {});

// Clears fb to the scene's clear colour and depth, then draws every pass
// (the clear within the first draw).
Result<DrawStats> render_scene(const ScenePrograms& programs, const Scene& scene, Framebuffer& fb);
Result<DrawStats> render_scene(Program& program, const Scene& scene, Framebuffer& fb);

// render_scene into a framebuffer of the scene's size, read back as the PNG
// of `glslrun a.vert a.frag scene.toml` holds it (top row first): colour
// buffer 0 when the scene draws to several.
Result<Image> render_image(Program& program, const Scene& scene);

// The stage a shader file's name gives, as the command line reads it: "vert"
// for .vert and .vs, "frag" for .frag and .fs (also before .glsl:
// a.vert.glsl), any case; "" when the name does not say.
std::string shader_stage_of(const std::string& path);

// Reads shader files; each source is named by its path, so diagnostics say
// "path:line: error: ...", as on the command line.
Result<std::vector<ShaderSource>> read_shader_files(const std::vector<std::string>& paths);
// read_shader_files, then Program::compile.
Result<Program> compile_files(const std::vector<std::string>& vertex_paths,
                              const std::vector<std::string>& fragment_paths, const CompileOptions& options = {});

// `glslrun a.vert a.frag scene.toml`, in memory: the same pixels as its PNG.
// `exec` sets threads, precision and the loop limit (images do not depend on threads).
Result<Image> render_files(const std::string& vertex_path, const std::string& fragment_path,
                           const std::string& scene_path, const ExecOptions& exec = {});

}  // namespace glslrun::scene
