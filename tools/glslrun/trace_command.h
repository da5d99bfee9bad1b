// `glslrun trace`: the shader debugger's command (docs/debugging.md).
#pragma once
#include <string>
#include <vector>

#include "debug/debugger.h"
#include "render_command.h"

namespace glslrun::cli {

// --dump-fixed-function DIR: writes `stages` into DIR (never over an input
// of `in` or `scene`) and says what each file is. Returns the exit status.
int dump_fixed_function(const std::vector<debug::GeneratedStage>& stages, const std::string& dir, const Inputs& in,
                        const scene::Scene& scene);

// Returns the exit status: 0 traced, 1 a shader, scene or trace error (a
// pixel outside the image, no such vertex), 2 a usage error.
int trace_main(int argc, char** argv);

}  // namespace glslrun::cli
