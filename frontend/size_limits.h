// Internal to frontend/: the documented limits on what one compilation unit
// may declare (docs/limits.md), checked on the AST before lowering, so that no
// pass allocates per element of a huge array.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glslang/MachineIndependent/localintermediate.h>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Scalar components in one variable (a float[16384] of vec4s, a mat4[4096]);
// GPU compilers refuse far less for registers.
constexpr uint64_t kMaxVariableComponents = 65536;
// Scalar components in all the variables of one stage together (its units'
// globals, locals, parameters and uniforms, each counted once): every
// component becomes an IR register, about 170 bytes of compile and run
// state, and 400 variables at the limit above needed 3.4 GB for a 1x1
// image. 16 variables at the limit (180 MB).
constexpr uint64_t kMaxStageComponents = uint64_t(1) << 20;

// `stage_components` accumulates over the units of one stage.
void check_size_limits(glslang::TIntermediate& unit, const std::string& file, uint64_t& stage_components,
                       std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
