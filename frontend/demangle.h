// Internal to frontend/: glslang's link messages name functions by their
// mangled names (`compute_dotprod(vf3;`); these read them as GLSL
// signatures (`compute_dotprod(vec3)`).
#pragma once
#include <string>

namespace glslrun::frontend {

// Every mangled function name in `text` (an identifier, '(', then one
// `<type>;` per parameter, ending the word) becomes `name(type, type)`.
// Anything that does not parse as one is left as it is.
std::string demangle_signatures(const std::string& text);

}  // namespace glslrun::frontend
