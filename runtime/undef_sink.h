// Where check_undef instructions (ir/undefined.h) report: the debugger's
// observer of GLSL's undefined operations (debug/undefined.cpp), set on a
// Program compiled with CompileOptions::check_undefined
// (Program::State::undef). Both backends call it from the same kernel
// (runtime/interp_kernels.h), in the run that computes the operation.
#pragma once
#include <cstdint>

#include "ir/ir.h"

namespace glslrun::rt {

class UndefSink {
public:
    // The vertex stage is about to shade vertices first..first+kLanes-1
    // (lane i is vertex first + i) of the current draw. The fragment stage's
    // batches are announced through raster::DrawProbe::before_run.
    virtual void vertex_batch(uint32_t first) = 0;
    // Site `site` (Shader::undef_sites of the running stage) is undefined in
    // `lanes`; a, b, c: every lane's operands (floats exactly, ints as
    // their values).
    virtual void undefined(uint32_t site, uint64_t lanes, const double* a, const double* b, const double* c) = 0;

protected:
    ~UndefSink() = default;
};

}  // namespace glslrun::rt
