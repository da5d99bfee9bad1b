// Internal to frontend/: source rewrite that sidesteps glslang 12's wrong
// constant folding of `(vecN == vecN) == true` (see fold_workaround.cpp).
#pragma once
#include <string>

namespace glslrun::frontend {

std::string rewrite_bool_literal_compares(const std::string& src);

}  // namespace glslrun::frontend
