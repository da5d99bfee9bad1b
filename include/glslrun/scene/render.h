// Draws a Scene with glslrun: per object, modelview = view * model, the
// material overrides, the current colour and the uniforms, then draw().
#pragma once
#include <string>
#include <vector>

#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/scene.h"

namespace glslrun::scene {

// Sets the scene's and the object's user uniforms on the program, converting
// the file's numbers to the declared types. Errors cite the scene's file:line.
Status apply_uniforms(Program& program, const std::vector<UniformSetting>& settings);

// scene.gl with the scene's textures bound to their units.
Result<GLState> bind_scene_textures(const Scene& scene);
// The state one object is drawn with: `bound` (from bind_scene_textures)
// with modelview = view * model, the material overrides and the current colour.
GLState object_gl_state(const Scene& scene, const GLState& bound, const Object& object);

// Draws every object into fb as it is, or cleared first to `clear` (by the
// first draw's tiles: draw() with ClearValues).
Result<DrawStats> draw_scene_objects(Program& program, const Scene& scene, Framebuffer& fb,
                                     const ClearValues& clear = {});

// Clears fb to the scene's clear colour and depth, then draws every object
// (the clear within the first draw).
Result<DrawStats> render_scene(Program& program, const Scene& scene, Framebuffer& fb);

// render_scene into a framebuffer of the scene's size, read back as the PNG
// of `glslrun a.vert a.frag scene.toml` holds it (top row first).
Result<Image> render_image(Program& program, const Scene& scene);

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
