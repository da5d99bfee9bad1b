// The shader debugger: renders a scene as glslrun does, with a probe on the
// draws (raster/probe.h), and replays chosen invocations on the traced
// interpreter (runtime/traced_interpreter.h) over the program's unoptimized
// IR, whose registers still carry the variables' names. Tracing never
// changes the image: the render is the ordinary one, and each replay's
// outputs are compared with what the render computed (`matches_render`).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "debug/trace.h"
#include "glslrun/glslrun.h"
#include "glslrun/scene/scene.h"

namespace glslrun::raster {
class DrawProbe;
}

namespace glslrun::debug {

// The program again, unoptimized (the registers keep the variables), with
// the same uniform layout; Fast's sqrt_divisor marks applied so that it
// computes the same values as `program`.
Result<Program> compile_for_debugging(const std::vector<ShaderSource>& vertex,
                                      const std::vector<ShaderSource>& fragment, Precision precision);

struct FragmentTrace {
    enum class Outcome : uint8_t { Written, DepthFailed, Discarded };
    uint32_t draw = 0, primitive = 0;
    std::array<uint32_t, 3> vertices{};
    bool front = true;
    float depth = 0;  // window z
    Outcome outcome = Outcome::Written;
    bool matches_render = true;        // the replay's outputs equal the render's, bit for bit
    std::vector<NamedValue> rendered;  // the render's outputs (before quantization)
    InvocationTrace trace;
};

struct VertexTrace {
    uint32_t draw = 0, vertex = 0;
    bool matches_render = true;
    InvocationTrace trace;
};

struct PixelTrace {
    int x = 0, y = 0;                      // image coordinates, top-left origin
    std::vector<FragmentTrace> fragments;  // in draw order
    std::vector<VertexTrace> vertices;     // of the fragments' primitives, or --vertex
};

struct TraceRequest {
    std::optional<std::pair<int, int>> pixel;  // image coordinates, top-left origin
    std::optional<uint32_t> vertex;            // a vertex of draw `draw`
    uint32_t draw = 0;
};

// Renders the scene into `fb` (one thread, and no early depth test: hidden
// fragments are shaded too; the same image) and traces what `request` asks.
Result<PixelTrace> trace(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                         const TraceRequest& request);

struct NanFinding {
    bool vertex = false;  // in the vertex stage (else a fragment)
    uint32_t draw = 0, primitive = 0, vertex_index = 0;
    int x = 0, y = 0;  // fragments: image coordinates, top-left origin
    NanEvent event;
};

struct NanReport {
    std::optional<NanFinding> nan;
    std::optional<NanFinding> out_of_range;  // the first colour output outside [0,1], when asked
};

// Renders the scene (one thread) and finds the first invocation, in draw and
// tile order, where a NaN or infinity first appears.
Result<NanReport> find_nan(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                           bool colour_range);

// Renders the scene on one thread with `probe` watching every draw.
Status render_with_probe(Program& program, const scene::Scene& scene, Framebuffer& fb, raster::DrawProbe& probe);

std::string format_text(const PixelTrace& t);
std::string format_json(const PixelTrace& t);
std::string format_text(const NanReport& r);

}  // namespace glslrun::debug
