// Internal to frontend/: the documented limits on what one compilation unit
// may declare (docs/limits.md), checked on the AST before lowering, so that no
// pass allocates per element of a huge array.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glslang/MachineIndependent/localintermediate.h>

#include "glslrun/glslrun.h"

namespace glslrun::frontend {

// Scalar components in one variable (a float[16384] of vec4s, a mat4[4096]);
// GPU compilers refuse far less for registers.
constexpr uint64_t kMaxVariableComponents = 65536;
// Scalar components in all the variables of one stage together (its units'
// globals, locals, parameters and uniforms, each counted once): every
// component becomes an IR register, about 170 bytes of compile and run
// state, and 400 variables at the limit above needed 3.4 GB for a 1x1
// image. 16 variables at the limit (180 MB).
constexpr uint64_t kMaxStageComponents = uint64_t(1) << 20;

// Distinct calls (caller and callee pairs) in one stage: glslang's link
// checks its call graph in time quadratic in them (8192 functions each
// called from main spent 0.7 s of CPU there).
constexpr uint64_t kMaxStageCalls = 4096;

// Calls nested in one another from main, the longest chain of the stage's
// call graph: shaders nest a handful. The JIT's LLVM spent minutes on a
// chain 1000 deep, and the interpreter's call stack stops at 1024 at run
// time; refused at compile time instead, at the call that crosses it.
constexpr uint64_t kMaxCallChain = 256;

// One call in the source: the caller and callee (glslang's mangled names)
// and where it is.
struct CallSite {
    std::string caller, callee, file;
    int line = 0;
};

// What the units of one stage hold together, accumulated unit by unit.
struct StageTotals {
    uint64_t components = 0, calls = 0;
    std::vector<CallSite> call_sites;  // one per distinct caller and callee pair
};

void check_size_limits(glslang::TIntermediate& unit, const std::string& file, StageTotals& stage,
                       std::vector<Diagnostic>& out);
// After every unit of the stage: the longest call chain from main against
// kMaxCallChain (a cycle, which glslang's link refuses, is not followed).
void check_call_chain(const StageTotals& stage, std::vector<Diagnostic>& out);

}  // namespace glslrun::frontend
