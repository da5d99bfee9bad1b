// Student-friendly explanations added to glslang's messages (see the .cpp).
#pragma once
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Explains diags[first..] that belong to `source` (matched by file name).
void add_hints(std::vector<Diagnostic>& diags, size_t first, const ShaderSource& source);

}  // namespace glslrun::frontend
