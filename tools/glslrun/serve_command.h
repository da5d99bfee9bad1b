// `glslrun serve`: the shader debugger as a local web page (docs/debugging.md).
#pragma once

namespace glslrun::cli {

int serve_main(int argc, char** argv);

}  // namespace glslrun::cli
