// `glslrun trace`: the shader debugger's command (docs/debugging.md).
#pragma once
#include "glslrun/glslrun.h"

namespace CLI {
class App;
}

namespace glslrun::cli {

// `add_precision` adds the shared --precision option.
int trace_main(int argc, char** argv, void (*add_precision)(CLI::App&, Precision&));

}  // namespace glslrun::cli
