// Internal to frontend/: glslang's call graph, corrected before its link.
#pragma once

namespace glslang {
class TIntermediate;
class TIntermSelection;
}

namespace glslrun::frontend {

// The branch of an `if` that constant folding keeps: 1 = then, 0 = else,
// -1 when the condition is not a constant.
int constant_branch(const glslang::TIntermSelection& n);

// Corrects the unit's call graph before glslang's link reads it:
//  - removes the calls that only occur in code that constant folding removes
//    (the dead branch of an `if` with a constant condition), so that the
//    link does not demand a body for them: Mesa folds first and links after,
//    and piglit's glsl-const-folding-01 relies on it. The lowering skips the
//    same branches (lower_stmt.cpp);
//  - adds the calls made by global initializers as calls from main, which
//    runs after them (glslang would drop those functions as never called).
void prepare_call_graph(glslang::TIntermediate& unit);

}  // namespace glslrun::frontend
