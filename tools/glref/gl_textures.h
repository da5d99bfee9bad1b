// The scene's textures in Mesa: one texture object per [textures.N], made
// with the glTexImage and glTexParameter calls a GL 2.1 program would make,
// from the texels of the scene's glslrun::Texture objects, so both renderers
// sample identical data.
#pragma once
#include "tools/glref/gl_context.h"
#include "glslrun/scene/scene.h"

namespace glslrun::glref {

// Creates, fills and binds (glActiveTexture(GL_TEXTURE0 + unit) +
// glBindTexture) every texture of the scene; leaves GL_TEXTURE0 active.
// A texture whose mipmaps glslrun generated gets level 0 and glGenerateMipmap,
// so the comparison covers glslrun's mipmap generation too; with
// `upload_generated_levels` it gets glslrun's generated levels instead (to
// tell a mipmap-generation difference from a sampling one).
Status upload_textures(const GLFunctions& gl, const scene::Scene& scene, bool upload_generated_levels);

}  // namespace glslrun::glref
