// Reading the text files that glslrun is given (shaders, scenes, OBJ files,
// piglit tests): regular files only, size checked before reading, so that
// /dev/zero, a FIFO or a directory ends in an Error, not in a hang or bad_alloc.
#pragma once
#include <cstdint>
#include <string>

#include "glslrun/glslrun.h"

namespace glslrun::scene {

// The largest text file glslrun reads (docs/limits.md).
constexpr int64_t kMaxTextFileBytes = int64_t(64) << 20;

// `what` names the file in messages ("shader", "scene file", ...); errors cite the path.
Result<std::string> read_text_file(const std::string& path, const char* what);

// A path with a NUL byte is refused: the C library would read it only up to
// the NUL, and open another file than the one named ("a\0b" opens "a").
Status check_path(const std::string& path, const char* what);
// check_path, and the path names a regular file (not a FIFO, which would
// block the open, nor a device or a directory).
Status check_regular_file(const std::string& path, const char* what);

}  // namespace glslrun::scene
