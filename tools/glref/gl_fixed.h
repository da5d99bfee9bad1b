// GL's fixed-function state of a scene in Mesa: the glEnable, glTexEnv,
// glTexGen, glFog and glLightModel calls that scene::FixedFunction stands for,
// so that a pass without a vertex or fragment shader draws with Mesa's own
// fixed function (not with glslrun's generated stages).
#pragma once
#include "tools/glref/gl_context.h"
#include "glslrun/scene/scene.h"

namespace glslrun::glref {

// The scene-wide state: lighting, colour material, normals, the colour sum,
// fog, and each unit's texture environment and texgen. Leaves GL_TEXTURE0
// active and an identity modelview.
void set_fixed_function_state(const GLFunctions& gl, const scene::Scene& scene);

// glEnable of the one target fixed-function texturing samples on each unit
// (scene/ffp.h's unit_target for `bound`, the draw's bindings), the others disabled.
void enable_texture_targets(const GLFunctions& gl, const scene::Scene& scene, const GLState& bound);

}  // namespace glslrun::glref
