// Internal to frontend/: glslang's parser and its AST traversals recurse once
// per nesting level (`x+x+...+x` nests as deep as it is long), and so does the
// lowering. Compiles run on a thread with a large stack, and sources are
// limited in size (kMaxSourceBytes), so that no source can overflow it.
#pragma once
#include <cstddef>
#include <functional>

namespace glslrun::frontend {

// Bytes of one stage's sources together (docs/limits.md).
constexpr size_t kMaxSourceBytes = size_t(1) << 20;
// Reserved, not committed: only the pages a deep source touches are used.
constexpr size_t kCompileStackBytes = size_t(512) << 20;

// Runs fn on a thread with a kCompileStackBytes stack and waits for it (on
// this thread, if no such thread can be started).
void run_on_deep_stack(const std::function<void()>& fn);

}  // namespace glslrun::frontend
