// The reference renderer: a Scene drawn by Mesa (llvmpipe or softpipe) with
// the legacy GL calls a GL 2.1 program would make for it. It reads the same
// Scene and Mesh arrays as glslrun's render_scene, so two images of one scene
// differ only by the pipeline. Part of the tests, not of the library.
#pragma once
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/scene.h"

namespace glslrun::glref {

struct MesaRender {
    scene::Image image;    // glReadPixels' RGBA8, flipped to top row first
    std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    // Wall time of each frame. llvmpipe compiles its shaders during the first.
    std::vector<double> frame_seconds;
    std::vector<double> frame_cpu_seconds;  // process CPU time (llvmpipe's threads included)
    double compile_seconds = 0;  // glCompileShader and glLinkProgram (Mesa's front end)
};

struct MesaOptions {
    // Upload glslrun's generated mipmap levels instead of calling
    // glGenerateMipmap (gl_textures.h): tells a mipmap-generation difference
    // from a sampling one.
    bool upload_generated_mipmaps = false;
    // Frames to draw (each: clear, the scene's uniforms, every object,
    // glFinish), for timing; the image is the last one's.
    int frames = 1;
};

// Sets the scene's GL state (matrices, lights transformed by GL itself,
// light model, materials, render state, clip planes, fog, texture matrices,
// textures), then per object the modelview view * model, material overrides, current
// colour and normal, uniforms and vertex arrays from VBOs, and draws.
// `driver` is "llvmpipe" or "softpipe"; one process can use only one of them.
// Mesa's compile and link logs come back in the Error.
Result<MesaRender> render_with_mesa(const std::string& driver, const std::vector<ShaderSource>& vertex,
                                    const std::vector<ShaderSource>& fragment, const scene::Scene& scene,
                                    const MesaOptions& options = {});

}  // namespace glslrun::glref
