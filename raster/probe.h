// An observer of draw() for the shader debugger (debug/: trace, --find-nan),
// set in Program::State::probe. draw() and the fragment stage test the pointer
// once per draw and per batch; the interpreter knows nothing of it. A probe
// sees all the work only when the draw runs on one thread
// (ExecOptions::threads = 1), which also gives tile order.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "glslrun/glslrun.h"
#include "runtime/execute.h"
#include "runtime/interpreter.h"

namespace glslrun::raster {

struct FsPrimitive;

// One batch of the fragment stage: lanes [0, lanes) hold 2x2 quads;
// `covered` are the lanes inside their primitive.
struct ProbeBatch {
    rt::Interpreter& interp;  // the optimized fragment shader (Program::State::ir)
    int lanes = 0;
    const std::array<int, rt::kLanes>& x;
    const std::array<int, rt::kLanes>& y;
    const std::array<float, rt::kLanes>& z;  // window depth
    const FsPrimitive* const* quad_prim;     // per quad
    rt::LaneMask covered = 0;
};

struct ProbeDraw {
    const GLState& gl;
    const std::vector<VertexAttrib>& attribs;
    uint32_t vertex_count = 0;
    const exec::VertexOutputs& shaded;  // the vertex shader's outputs of every vertex
};

class DrawProbe {
public:
    virtual ~DrawProbe() = default;
    // After the built-in uniforms are set and the vertices shaded.
    virtual void begin_draw(const ProbeDraw& draw) = 0;
    // The batch's inputs are filled; the shader has not run.
    virtual void before_run(const ProbeBatch& batch) = 0;
    // After the depth test and colour writes: `alive` did not discard,
    // `written` passed the depth test (or there is none) and were written.
    // With a probe there is no early depth test: every fragment is shaded.
    virtual void after_write(const ProbeBatch& batch, rt::LaneMask alive, rt::LaneMask written) = 0;
};

}  // namespace glslrun::raster
