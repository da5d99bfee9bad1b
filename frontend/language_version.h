// Internal to frontend/: glslrun runs GLSL 1.10 and 1.20 and nothing else.
// Other versions and profiles are refused before glslang sees the source:
// glslang would accept many of them and glslrun would then run them with
// 1.10 semantics (an `out vec4` of GLSL 1.30 would render zeros).
#pragma once
#include <optional>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// The unit's GLSL version: its #version number, else `default_version`.
int unit_version(const ShaderSource& source, int default_version);

struct VersionRefusal {
    Diagnostic diagnostic;
    bool other_language = false;  // a real GLSL or GLSL ES version (else not a version at all)
};

// The refusal of a unit whose #version (or, without one, `default_version`)
// is not 110 or 120, or names a profile; nullopt when glslrun runs it.
std::optional<VersionRefusal> unsupported_version(const ShaderSource& source, int default_version);

// The refusals of every unit of both stages, as one Error (marked
// unsupported_version when every refusal is of a real version); nullopt if none.
std::optional<Error> refuse_unsupported_versions(const std::vector<const std::vector<ShaderSource>*>& stages,
                                                 int default_version);

}  // namespace glslrun::frontend
