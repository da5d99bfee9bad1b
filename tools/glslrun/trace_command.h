// `glslrun trace`: the shader debugger's command (docs/debugging.md).
#pragma once

namespace glslrun::cli {

// Returns the exit status: 0 traced, 1 a shader, scene or trace error (a
// pixel outside the image, no such vertex), 2 a usage error.
int trace_main(int argc, char** argv);

}  // namespace glslrun::cli
