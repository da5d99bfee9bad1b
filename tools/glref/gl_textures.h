// The scene's textures in Mesa: one texture object per [textures.N], made
// with the glTexImage and glTexParameter calls a GL 2.1 program would make,
// from the texels of the scene's glslrun::Texture objects, so both renderers
// sample identical data.
#pragma once
#include <array>
#include <vector>

#include "tools/glref/gl_context.h"
#include "glslrun/scene/scene.h"

namespace glslrun::glref {

// Creates, fills and binds (glActiveTexture(GL_TEXTURE0 + unit) +
// glBindTexture) every texture of the scene; leaves GL_TEXTURE0 active.
// A texture whose mipmaps glslrun generated gets level 0 and glGenerateMipmap,
// so the comparison covers glslrun's mipmap generation too; with
// `upload_generated_levels` it gets glslrun's generated levels instead (to
// tell a mipmap-generation difference from a sampling one).
// [textures.N] with texels of their own (a render target's are made by make_render_targets).
Status upload_textures(const GLFunctions& gl, const scene::Scene& scene, bool upload_generated_levels);

// A framebuffer object to draw a pass into: the output's or a render target's.
struct GLTarget {
    GLuint fbo = 0;
    int width = 0, height = 0, color_buffers = 1;
};

// One FBO per [render_targets.NAME], as a GL 2.1 program with
// EXT_framebuffer_object makes them: GL_RGBA8 colour textures and a
// GL_DEPTH24_STENCIL8 depth texture. The textures that [textures.N] sample
// are bound to their units with the file's sampler state.
Result<std::vector<GLTarget>> make_render_targets(const GLFunctions& gl, const scene::Scene& scene);

// [objects.textures.N]: texture objects of their own, bound before each
// object's draw. `initial` is every unit's binding once the scene's textures
// and render targets are made: each frame starts from it.
struct TextureBindings {
    std::vector<std::vector<GLuint>> objects;  // per object, per its textures
    std::array<std::array<GLuint, 5>, kMaxTextureUnits> initial{};  // by unit and TextureTarget
};
Result<TextureBindings> upload_object_textures(const GLFunctions& gl, const scene::Scene& scene,
                                               bool upload_generated_levels);
void restore_bindings(const GLFunctions& gl, const TextureBindings& b);
void bind_object_textures(const GLFunctions& gl, const scene::Object& o, const std::vector<GLuint>& ids);

}  // namespace glslrun::glref
