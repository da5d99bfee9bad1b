// `glslrun a.vert a.frag scene.toml --precision M --error-report DIR`.
#pragma once
#include <vector>

#include "output_guard.h"
#include "render_command.h"
#include "glslrun/scene/error_report.h"

namespace glslrun::cli {

// Measures options.precision against Precision::Reference on the scene and
// writes into DIR (created when missing) the images, the table (report.txt)
// and the `key value` lines (report.keys), none of them over an input; prints
// the table and the lines too. Returns the process exit status.
int run_error_report(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                     const scene::Scene& scene, const RenderOptions& options, const InputFiles& inputs);

}  // namespace glslrun::cli
