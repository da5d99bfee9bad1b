// Internal to frontend/: turning glslang's text info log into Diagnostics.
#pragma once
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Source names given to glslang are "#<index>" so that any user name (empty,
// with colons) maps back exactly; `sources` resolves them. Messages without a
// location get `fallback_file`.
void parse_info_log(const std::string& log, const std::vector<ShaderSource>& sources,
                    const std::string& fallback_file, std::vector<Diagnostic>& out);

std::string internal_source_name(size_t index);

}  // namespace glslrun::frontend
