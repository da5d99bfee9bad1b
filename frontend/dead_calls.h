// Internal to frontend/: calls in code that constant folding removes.
#pragma once

namespace glslang {
class TIntermediate;
class TIntermSelection;
}

namespace glslrun::frontend {

// The branch of an `if` that constant folding keeps: 1 = then, 0 = else,
// -1 when the condition is not a constant.
int constant_branch(const glslang::TIntermSelection& n);

// Removes from the unit's call graph the calls that only occur in code that
// constant folding removes (the dead branch of an `if` with a constant
// condition), so that glslang's link does not demand a body for them: Mesa
// folds first and links after, and piglit's glsl-const-folding-01 relies on
// it. The lowering skips the same branches (lower_stmt.cpp).
void drop_dead_calls(glslang::TIntermediate& unit);

}  // namespace glslrun::frontend
