// Internal to frontend/: declaration rules of GLSL 1.10/1.20 that glslang 12
// accepts (found by the spec-sentence suite, tests/spec/).
#pragma once
#include <string>
#include <vector>

#include <glslang/MachineIndependent/localintermediate.h>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Attribute and varying types, centroid on varyings only, one name space for
// functions and variables,
// the words GLSL 1.20 reserves. `text` is the source glslang parsed.
void check_declarations(glslang::TIntermediate& unit, const std::string& text, const std::string& file,
                        std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
