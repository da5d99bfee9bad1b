// User uniforms of a scene, set on a Mesa program with glUniform*: the same
// names and numbers scene/render.cpp gives glslrun.
#pragma once
#include <vector>

#include "tools/glref/gl_context.h"
#include "glslrun/scene/scene.h"

namespace glslrun::glref {

// Sets each setting on the program in use. A name GL reports as inactive
// (location -1) is skipped, as glUniform* itself ignores location -1; wrong
// value counts and fractions for integer uniforms are errors at the
// setting's file:line.
Status apply_uniforms(const GLFunctions& gl, GLuint program, const std::vector<scene::UniformSetting>& settings);

}  // namespace glslrun::glref
