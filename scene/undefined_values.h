// What the precision modes and NVIDIA's GPU return for an undefined
// operation's operands (check_undefined(), glslrun/scene/undefined.h).
#pragma once
#include "glslrun/scene/undefined.h"
#include "ir/undefined.h"

namespace glslrun::scene {

// Fills f.mode_values, f.value_note and f.gpu from f.first.operands;
// `length`: an array index's array length.
void describe_values(ir::UndefOp op, uint32_t length, UndefinedFinding& f);

}  // namespace glslrun::scene
