// The frontend: GLSL source -> glslang AST -> ir::Program.
// glslang types never leave frontend/; the result holds no glslang pointers.
#pragma once
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"

namespace glslrun::frontend {

// Compiles every unit of each stage, links each stage, runs our own
// cross-stage checks (varyings, uniforms, gl_Position, global initializers)
// and lowers both stages. A missing stage gets a fixed-function equivalent.
// The IR is not optimized here.
Result<ir::Program> compile_program(const std::vector<ShaderSource>& vs, const std::vector<ShaderSource>& fs,
                                    const CompileOptions& options);

// glslparsertest-style: compiles one unit alone, without linking.
Status check_shader(Stage stage, const ShaderSource& source, const CompileOptions& options);

}  // namespace glslrun::frontend
