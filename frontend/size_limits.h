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

void check_size_limits(glslang::TIntermediate& unit, const std::string& file, std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
