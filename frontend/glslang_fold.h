// Internal to frontend/: the folding that glslang_fold.cpp splices into
// glslang (see there).
#pragma once

namespace glslrun::frontend {

// Always true. Calling it makes the static library's link pull in
// glslang_fold.o, which defines the __wrap_ functions ld redirects to.
bool glslang_fold_hooks_linked();

}  // namespace glslrun::frontend
