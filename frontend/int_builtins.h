// Internal to frontend/: min, max, clamp, abs and sign on int and ivec
// before GLSL 1.30.
//
// GLSL 1.10/1.20 define them for float types only; Mesa (and piglit tests
// that rely on it) accepts the int overloads in every version, with an int
// result. glslrun follows Mesa (docs/semantics.md). glslang 12 has no such
// overloads and adding user functions named min would hide the built-in ones
// in GLSL 1.20, so a unit that glslang rejects on a line with such a call
// ("no matching overloaded function" in 1.10; in 1.20 the int arguments
// convert to float and the float result is the error) is parsed again with
// the calls on those lines renamed to glslrun_min/max/clamp/abs/sign,
// defined in the preamble for float and int types. The retry is kept only if it compiles.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Lines of `src` with an error and a min/max/clamp/abs/sign call.
std::set<int> int_builtin_retry_lines(const std::vector<Diagnostic>& diags, const std::string& src);

// `src` with the min/max/clamp/abs/sign calls on `lines` renamed to glslrun_*.
std::string rename_int_builtin_calls(const std::string& src, const std::set<int>& lines);

// GLSL definitions of glslrun_min/max/clamp/abs/sign for float, vecN, int
// and ivecN (with the scalar second/third argument forms), for the preamble.
const std::string& int_builtin_helpers();

}  // namespace glslrun::frontend
