// Internal to frontend/: the folding that glslang_fold.cpp splices into
// glslang (see there).
#pragma once

namespace glslrun::frontend {

// GLSL 1.10 §4.3.3 does not count built-in function calls as constant
// expressions (1.20 does): while a 1.10 unit parses on this thread, the
// folding leaves them to run time, so `const float c = sin(1.0);` and
// array sizes using them are errors, as in Mesa. glslang's fold callbacks
// cannot see the unit, hence a thread-local setting for the parse, like
// glslang's own current pool.
class FoldVersionScope {
public:
    explicit FoldVersionScope(int version);
    ~FoldVersionScope();
    FoldVersionScope(const FoldVersionScope&) = delete;
    FoldVersionScope& operator=(const FoldVersionScope&) = delete;

private:
    int saved_;
};

// Always true. Calling it makes the static library's link pull in
// glslang_fold.o, which defines the __wrap_ functions ld redirects to.
bool glslang_fold_hooks_linked();

}  // namespace glslrun::frontend
