// `glslrun check FILE...`: each shader compiled alone, as glslangValidator
// does: `file:line: error:` diagnostics, exit status 0 when every file
// compiles, 1 when one does not, 2 for a usage error.
#pragma once

namespace glslrun::cli {

int check_main(int argc, char** argv);

}  // namespace glslrun::cli
