// `glslrun a.vert a.frag scene.toml --precision M --error-report DIR`.
#pragma once
#include <vector>

#include "render_command.h"
#include "glslrun/scene/error_report.h"

namespace glslrun::cli {

// Measures options.precision against Precision::Reference on the scene, writes the
// images into DIR (created when missing) and prints the table and the
// `key value` lines. Returns the process exit status.
int run_error_report(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                     const scene::Scene& scene, const RenderOptions& options);

}  // namespace glslrun::cli
