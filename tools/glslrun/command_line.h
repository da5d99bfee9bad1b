// What the glslrun subcommands share on the command line: the exit statuses
// (docs/ci.md), CLI11's parse mapped onto them, and the common options.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include <string_view>
#include <utility>

#include "glslrun/glslrun.h"

namespace CLI {
class App;
}

namespace glslrun::cli {

// 0: done as expected; 1: a result differs or the input is wrong (a shader,
// scene or draw error); 2: a usage or tool error (docs/ci.md).
inline constexpr int kResultError = 1;
inline constexpr int kToolError = 2;

// CLI11's parse: -1 to go on; 0 after --help or --version; kToolError for a
// usage error (CLI11's own codes are 100 and up).
int parse_command_line(CLI::App& app, int argc, char** argv);

// "A<sep>B" of two ints, <sep> one of `separators` ("512x512", "256,200");
// nullopt when malformed or out of int's range. from_chars, not sscanf: "%d"
// of a number past INT_MAX is undefined (glibc wrapped 4294967360 to 64).
std::optional<std::pair<int, int>> parse_int_pair(std::string_view text, std::string_view separators);

// -D NAME[=VALUE] (repeatable) into `defines`: NAME an identifier that GLSL
// does not reserve (GL_..., __...), VALUE on one line; a bad one is a usage error.
void add_define_option(CLI::App& app, std::vector<std::string>& defines);
// -I DIR (repeatable, existing directories) into `dirs`: CompileOptions::include_dirs.
void add_include_option(CLI::App& app, std::vector<std::string>& dirs);

// --precision NAME, for rendering, tracing and `glslrun test`; a bad name is a usage error.
void add_precision_option(CLI::App& app, Precision& precision);
// --backend NAME, for rendering and `glslrun test`; a bad name, or jit in a
// build without it, is a usage error.
void add_backend_option(CLI::App& app, Backend& backend);
// --cache-dir DIR and --no-cache: the JIT's code cache (ExecOptions::code_cache).
// They set GLSLRUN_CACHE_DIR and GLSLRUN_NO_CACHE for this process as the
// command line is parsed (before any thread starts), so that every program
// it compiles, in the forked children of `glslrun test` too, uses them.
void add_code_cache_options(CLI::App& app);
// Prints code_cache_status()'s warning (an unwritable cache directory, ...)
// once, where `backend` may use the JIT; never an error.
void warn_about_code_cache(Backend backend);

}  // namespace glslrun::cli
