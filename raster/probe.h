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
#include "runtime/backend.h"

namespace glslrun::raster {

struct FsPrimitive;

// One batch of the fragment stage: lanes [0, lanes) hold 2x2 quads;
// `covered` are the lanes inside their primitive.
struct ProbeBatch {
    rt::Executor& interp;  // the optimized fragment shader (Program::State::ir), on any backend
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
    // The program drawing: a scene's draw with a generated fixed-function
    // stage runs another program than the one whose probe this is.
    const Program* program = nullptr;
};

// The framebuffer at one pixel, as stored: an RGBA8 channel as its byte n
// (exact in a float), a float buffer's channel as its float; `buffers` of
// the framebuffer's colour buffers.
struct ProbePixel {
    std::array<std::array<float, 4>, kMaxDrawBuffers> color{};
    int buffers = 0;
    float depth = 0;
    uint8_t stencil = 0;
};

// What the per-fragment tests after the shader did to each lane of a batch
// (GL 2.1 §4.1, in its order), for the debugger's pixel history. A lane
// fails at most one test: the first it fails; the later ones do not run.
// The values are those each test compared, read before the lane's own test
// (an earlier lane of the batch at the same pixel has already written).
struct ProbeTests {
    rt::LaneMask alpha_failed = 0, stencil_failed = 0, depth_failed = 0;
    // The alpha test's operands: colour 0's alpha and the reference, in the
    // colour buffer's precision (RGBA8, `alpha_bytes`: the bytes n of n/255).
    std::array<float, rt::kLanes> alpha{};
    float alpha_ref = 0;
    bool alpha_bytes = false;
    std::array<float, rt::kLanes> z{};             // the fragment's depth (gl_FragDepth when written)
    std::array<float, rt::kLanes> stored_depth{};  // the depth buffer's value
    std::array<uint8_t, rt::kLanes> stored_stencil{};
    // The lanes whose pixel the probe watches (DrawProbe::watched), and
    // their pixel just before and just after the lane's tests and writes
    // (an earlier lane of the batch at that pixel included). A discarded
    // lane's are equal.
    rt::LaneMask watched = 0;
    std::array<ProbePixel, rt::kLanes> before{}, after{};
};

class DrawProbe {
public:
    virtual ~DrawProbe() = default;
    // After the built-in uniforms are set and the vertices shaded.
    virtual void begin_draw(const ProbeDraw& draw) = 0;
    // The batch's inputs are filled; the shader has not run.
    virtual void before_run(const ProbeBatch& batch) = 0;
    // Among the batch's covered lanes (before_run's), those whose pixel's
    // framebuffer values the probe wants before and after each fragment
    // (ProbeTests::before, after). It must name every covered lane at a
    // pixel or none: the stage runs the watched lanes' operations one lane
    // at a time after the others', which touch other pixels only, so the
    // image stays the same.
    virtual rt::LaneMask watched(const ProbeBatch&) { return 0; }
    // After the tests and colour writes: `alive` did not discard, `written`
    // passed every test and were written; `tests` says which test stopped
    // the others. With a probe there is no early depth test: every fragment
    // is shaded.
    virtual void after_write(const ProbeBatch& batch, rt::LaneMask alive, rt::LaneMask written,
                             const ProbeTests& tests) = 0;
};

}  // namespace glslrun::raster
