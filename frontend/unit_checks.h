// Internal to frontend/: GLSL 1.10/1.20 rules that glslang 12 does not
// enforce on one parsed compilation unit (also run by check_shader, which
// does not link).
#pragma once
#include <string>
#include <vector>

#include <glslang/MachineIndependent/localintermediate.h>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// `text` is the source glslang parsed (after our rewrites), for the checks
// that need tokens the AST no longer has.
void check_unit_rules(glslang::TIntermediate& unit, const std::string& text, const std::string& file,
                      std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
