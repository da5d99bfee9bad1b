// GL's fixed-function stages as GLSL 1.10 source generated from a draw's
// state, as Mesa's own fixed-function emulation generates its programs
// (ffvertex_prog.c, ff_fragment_shader.cpp): the same terms in the same
// order, so that the stages compiled through the normal frontend, IR,
// interpreter and JIT draw what Mesa draws. Internal to the scene library
// and its tools (glref picks the same texture targets).
#pragma once
#include <cstdint>
#include <string>

#include "glslrun/scene/scene.h"

namespace glslrun::scene::ffp {

// The names of the generated stages' sources in a program (ShaderSource::name):
// how the shader debugger tells a generated stage from the user's.
inline constexpr const char* kVertexStageName = "(fixed-function vertex stage)";
inline constexpr const char* kFragmentStageName = "(fixed-function fragment stage)";

// The texture target fixed-function texturing samples on `unit` for a draw
// with `gl`'s bindings: the bound texture of the highest-priority target
// (cube map, 3D, rectangle, 2D, 1D) when [texture_env.unit] enables the
// unit, or -1 where it is disabled, nothing is bound or the texture is
// incomplete (GL 2.1 §3.8.10: texturing is then off on the unit).
int unit_target(const FixedFunction& f, const GLState& gl, int unit);

// What the generated vertex stage writes besides position and colours:
// gl_TexCoord[i] for the bits of `texcoords`.
struct VertexNeeds {
    uint8_t texcoords = 0xff;
};

// The vertex stage: transform, lighting (every enabled light), texgen and
// the texture matrices, the fog coordinate, gl_ClipVertex when clip planes
// are on. `gl` is the draw's state (materials, light model, clip planes).
std::string vertex_source(const Scene& scene, const GLState& gl, const VertexNeeds& needs);

// The fragment stage: the texture environment of every enabled unit in
// order, the colour sum and fog. Its samplers are the uniforms
// sampler_uniform(unit), which the caller sets to their unit.
std::string fragment_source(const Scene& scene, const GLState& gl);
std::string sampler_uniform(int unit);
// The units whose samplers fragment_source declares.
uint8_t fragment_units(const Scene& scene, const GLState& gl);

// Whether the draw's fixed-function vertex stage uses gl_BackColor: GL's
// two-sided lighting (lighting and GL_LIGHT_MODEL_TWO_SIDE).
bool two_sided_lighting(const Scene& scene, const GLState& gl);

// A float as a GLSL literal that reads back as the same float.
std::string literal(float v);
std::string literal(const glm::vec4& v);

}  // namespace glslrun::scene::ffp
