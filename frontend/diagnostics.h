// Internal to frontend/: turning glslang's text info log into Diagnostics.
#pragma once
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// glslang gets each unit as one unnamed string (so that __FILE__ is the
// source string number, GLSL 1.10 §3.3): its locations "0:line" are lines of
// `unit_file`, and so are messages without a location; another number is
// the string number set by `#line L S`.
void parse_info_log(const std::string& log, const std::string& unit_file, std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
