// Definite assignment, per lane: which registers some lane may read before it
// has written them in the current run (it then sees whatever an earlier run
// or instruction left there). Passes that move or share registers must keep
// those reads seeing the same bits, so they leave such registers alone.
#pragma once
#include <vector>

#include "ir/ir.h"

namespace glslrun::ir {

// Indexed by register. The prologue's registers count as written; reads in
// function bodies count as maybe unset (a callee runs wherever it is called).
std::vector<bool> maybe_read_unset(const Shader& shader);

}  // namespace glslrun::ir
