// `glslrun batch JOBS`: many (vertex, fragment, scene, output) renders in
// one process, so glslang's start-up is paid once; a progress bar on a
// terminal.
#pragma once
#include <string>

#include "glslrun/glslrun.h"

namespace glslrun::cli {

// JOBS holds one job per line, `VERT FRAG SCENE OUTPUT.png` (paths relative
// to the current directory; '#' starts a comment). Returns the exit status:
// 0 every job rendered, 1 some failed (each error names JOBS:line), 2 the
// job file is unreadable or malformed.
int run_batch_command(const std::string& jobs_path, const ExecOptions& exec);

}  // namespace glslrun::cli
