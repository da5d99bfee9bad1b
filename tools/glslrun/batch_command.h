// `glslrun batch JOBS`: many (vertex, fragment, scene, output) renders in
// one process, so glslang's start-up is paid once and each distinct program
// is compiled once; a progress bar on a terminal.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::cli {

// One line of a job file split into its fields, as a POSIX shell splits
// words without expansions: blanks separate fields; '...' keeps every byte
// as it is; "..." keeps all but \" and \\, which stand for " and \; a
// backslash outside quotes keeps the next byte; '#' outside quotes starts a
// comment. Empty fields are written "" or ''. nullopt with `why` set for an
// unterminated quote or a NUL byte.
std::optional<std::vector<std::string>> split_job_line(std::string_view line, std::string& why);

// JOBS holds one job per line, `VERT FRAG SCENE OUTPUT` (paths relative to
// the current directory; the output's format by its name, as -o); a job of
// one shader (its stage by its name) or none draws the missing stages with
// GL's fixed function, as the render command does. Returns the
// exit status: 0 every job rendered; 1 a job failed or a line is malformed
// (each error names JOBS:line, and every other job still runs); 2 the job
// file cannot be read or holds no job.
int run_batch_command(const std::string& jobs_path, const ExecOptions& exec);

}  // namespace glslrun::cli
