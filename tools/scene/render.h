// Draws a Scene with glslrun: per object, modelview = view * model, the
// material overrides, the current colour and the uniforms, then draw().
#pragma once
#include "tools/scene/scene.h"

namespace glslrun::scene {

// Sets the scene's and the object's user uniforms on the program, converting
// the file's numbers to the declared types. Errors cite the scene's file:line.
Status apply_uniforms(Program& program, const std::vector<UniformSetting>& settings);

// Clears fb to the scene's clear colour and depth, then draws every object.
Result<DrawStats> render_scene(Program& program, const Scene& scene, Framebuffer& fb);

}  // namespace glslrun::scene
