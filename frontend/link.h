// Internal to frontend/: cross-stage checks and assembly of the ir::Program.
#pragma once
#include <string>
#include <vector>

#include "frontend/lower.h"

namespace glslrun::frontend {

struct LinkInput {
    StageLowering* vs = nullptr;
    StageLowering* fs = nullptr;
    bool vs_is_user = true;  // false: the fixed-function stand-in
    std::string vs_file, fs_file;
};

// GL link rules glslang 12 does not check: gl_Position written, varyings read
// by the FS written by the VS with the same type.
void check_interface(const LinkInput& in, std::vector<Diagnostic>& diags);

// Fills program.varyings from the two stages' bindings.
void link_varyings(ir::Program& program);

}  // namespace glslrun::frontend
