// The shader debugger: renders a scene as glslrun does, with a probe on the
// draws (raster/probe.h), and replays chosen invocations on the traced
// interpreter (runtime/traced_interpreter.h) over the program's unoptimized
// IR, whose registers still carry the variables' names. Tracing never
// changes the image: the render is the ordinary one, and each replay's
// outputs are compared with what the render computed (`matches_render`).
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "debug/trace.h"
#include "glslrun/glslrun.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"
#include "raster/probe.h"


namespace glslrun::debug {

// The program again, unoptimized (the registers keep the variables), with
// the same uniform layout; Fast's sqrt_divisor marks applied so that it
// computes the same values as `program`.
// `options` are the program's own (its defines and include directories).
Result<Program> compile_for_debugging(const std::vector<ShaderSource>& vertex,
                                      const std::vector<ShaderSource>& fragment, Precision precision,
                                      CompileOptions options = {});

// The per-fragment tests after the shader (GL 2.1 §4.1) as one fragment met
// them, in GL's order, with the values each compared. A fragment that
// reaches the tests passed the scissor test: the rasterizer makes no
// fragment outside the scissor box (PixelTrace::scissored lists the draws
// whose box leaves the pixel out).
struct FragmentTests {
    enum class Result : uint8_t { Off, Passed, Failed, NotReached };
    Result scissor_test = Result::Off, alpha_test = Result::Off, stencil_test = Result::Off,
           depth_test = Result::Off;
    CompareFunc alpha_func = CompareFunc::Always, stencil_func = CompareFunc::Always,
                depth_func = CompareFunc::Less;
    float alpha = 0, alpha_ref = 0;  // as compared: with RGBA8 storage (`alpha_bytes`), the bytes n of n/255
    bool alpha_bytes = false;
    uint32_t stencil_ref = 0, stencil_mask = 255, stored_stencil = 0;  // (ref & mask) func (stored & mask)
    float z = 0, stored_depth = 0;  // z func stored
};

// The framebuffer at the traced pixel (raster::ProbePixel), as stored.
struct PixelValues {
    bool bytes = true;  // RGBA8 colour buffers: each channel is the byte n of n/255; else floats
    std::vector<std::array<float, 4>> color;  // per colour buffer of the framebuffer
    float depth = 1;
    uint32_t stencil = 0;
};

// What a draw does with a fragment's colour after the tests (GL 2.1 §4.1.8
// to §4.2.2): the buffers written, blending, logic op (RGBA8 buffers only)
// and the colour mask.
struct ColorWrites {
    std::vector<int> buffers;  // glDrawBuffers' buffers the shader writes (gl_FragColor: all of them)
    bool blend = false;
    BlendState blend_state;
    bool logic_op = false;
    LogicOp logic = LogicOp::Copy;
    std::array<bool, 4> mask{true, true, true, true};
};

struct FragmentTrace {
    // The first test the fragment failed, or Written; a discarded fragment
    // meets no test.
    enum class Outcome : uint8_t { Written, DepthFailed, Discarded, AlphaFailed, StencilFailed };
    uint32_t draw = 0, primitive = 0;
    std::string pass;     // the scene pass's name; empty in a scene without passes
    std::string program;  // its shaders, "a.vert + a.frag"
    std::array<uint32_t, 3> vertices{};
    bool front = true;
    float depth = 0;  // window z
    Outcome outcome = Outcome::Written;
    FragmentTests tests;
    // The pixel just before and just after this fragment's tests and writes,
    // as the render stored it: `after` of the last fragment is the image's
    // pixel unless a later clear changed it.
    PixelValues before, after;
    ColorWrites writes;
    bool matches_render = true;        // the replay's outputs equal the render's, bit for bit
    std::vector<NamedValue> rendered;  // the render's outputs (before quantization)
    InvocationTrace trace;
};

struct VertexTrace {
    uint32_t draw = 0, vertex = 0;
    std::string pass, program;  // as FragmentTrace's
    bool matches_render = true;
    InvocationTrace trace;
};

// A fixed-function stage generated as GLSL 1.10 for some draws' state
// (glslrun/scene/render.h): its name in the traces, and its source.
struct GeneratedStage {
    std::string name;  // "(generated) fixed-function-1.vert"
    std::string file;  // "fixed-function-1.vert": the file --dump-fixed-function writes
    std::string text;
    bool vertex = true;
};

struct PixelTrace {
    int x = 0, y = 0;                      // image coordinates, top-left origin
    std::string target;                    // the render target traced (TraceRequest::target); empty: the image
    std::vector<FragmentTrace> fragments;  // in draw order
    std::vector<uint32_t> scissored;       // draws whose scissor box leaves the pixel out
    std::vector<VertexTrace> vertices;     // of the fragments' primitives, or --vertex
    // Every program's source lines by file name (ShaderSource::name): the text of each step's line.
    std::map<std::string, std::vector<std::string>> source_lines;
    std::vector<GeneratedStage> generated;  // the fixed-function stages the scene's draws ran
};

// Every fragment at each of `pixels` (image coordinates, top-left origin)
// without the replays: per pixel, in draw order, its header, tests, the
// framebuffer before and after it, and the render's outputs.
struct PixelHistory {
    int x = 0, y = 0;
    std::vector<FragmentTrace> fragments;  // `trace` empty
};
Result<std::vector<PixelHistory>> pixel_history(Program& program, const Program& debug, const scene::Scene& scene,
                                                Framebuffer& fb, const std::vector<std::pair<int, int>>& pixels);

struct TraceRequest {
    std::optional<std::pair<int, int>> pixel;  // image coordinates, top-left origin
    std::optional<uint32_t> vertex;            // a vertex of draw `draw`
    uint32_t draw = 0;                         // counted over every pass
    // The program's shaders: their names name it in passes that use it, and
    // the trace shows their lines' text.
    std::vector<ShaderSource> sources;
    // The framebuffer of `pixel`: a render target's name (its fragments, of
    // the passes that draw into it), or empty: the output image's.
    std::string target;
};

// Renders the scene into `fb` (one thread, and no early depth test: hidden
// fragments are shaded too; the same image) and traces what `request` asks.
Result<PixelTrace> trace(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                         const TraceRequest& request);

struct NanFinding {
    bool vertex = false;  // in the vertex stage (else a fragment)
    uint32_t draw = 0, primitive = 0, vertex_index = 0;
    std::string pass;        // the scene pass's name; empty in a scene without passes
    bool in_target = false;  // the pass draws into a render target: x,y are the target's
    int x = 0, y = 0;  // fragments: image coordinates, top-left origin
    NanEvent event;
};

struct NanReport {
    std::optional<NanFinding> nan;
    std::optional<NanFinding> out_of_range;  // the first colour output outside [0,1], when asked
    // The generated fixed-function stages a finding is in, so that the text
    // says the NaN comes from GL's fixed function and not the user's file.
    std::vector<GeneratedStage> generated;
};

// Renders the scene (one thread) and finds the first invocation, in draw and
// tile order, where a NaN or infinity first appears.
Result<NanReport> find_nan(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                           bool colour_range);

// A probe on every pass's program: render_with_probe() fills `passes` and
// sets `pass` before each pass draws.
class PassProbe : public raster::DrawProbe {
public:
    struct PassPrograms {
        const Program* program = nullptr;  // the one that renders
        const Program* debug = nullptr;    // its twin for replays (compile_for_debugging)
        std::string name, program_name;    // name: empty in a scene without passes
        bool to_output = true;             // draws into the output framebuffer (not a target)
        int height = 0;                    // of the framebuffer it draws into
        std::string target;                // the render target's name; empty: the output framebuffer
    };
    std::vector<PassPrograms> passes;  // one per pass; one in a scene without passes
    size_t pass = 0;
    // The programs of the draw under way (begin_draw calls enter_draw first).
    const PassPrograms& current() const { return current_ ? *current_ : passes[pass]; }
    // The programs compiled for the passes, kept for the replays after the render.
    std::optional<scene::ScenePrograms> scene_programs;
    std::vector<std::shared_ptr<Program>> debug_programs;
    // The generated fixed-function stages the draws ran, in the order first
    // drawn, named as the traces name them.
    std::vector<GeneratedStage> generated;
    // A twin that did not compile: the render's result is this error.
    std::optional<Error> failed;

protected:
    // Makes current() the programs of `draw`: its pass's, or for a draw with
    // a generated stage, that program and a twin of it (made at its first draw).
    void enter_draw(const raster::ProbeDraw& draw);

private:
    const PassPrograms* current_ = nullptr;
    std::map<std::pair<size_t, const Program*>, PassPrograms> drawn_;  // by pass: drawn programs with a generated stage
};

// Renders the scene on one thread with `probe` watching every draw of every
// pass. `debug` is `program`'s twin; a pass's own shaders get theirs
// compiled here. `program_name` names `program` in the pixel history.
Status render_with_probe(Program& program, const Program& debug, const std::string& program_name,
                         const scene::Scene& scene, Framebuffer& fb, PassProbe& probe);

// The fixed-function stages generated for the scene's draws, as a trace
// names them (renders the scene once, on one thread).
Result<std::vector<GeneratedStage>> generated_stages(Program& program, const Program& debug,
                                                     const scene::Scene& scene, Framebuffer& fb);
// Writes each stage to dir/stage.file; returns the paths written.
Result<std::vector<std::string>> write_generated_stages(const std::vector<GeneratedStage>& stages,
                                                        const std::string& dir);
// What the text trace says of the generated stages it names.
std::string describe_generated(const std::vector<GeneratedStage>& stages);

std::string format_text(const PixelTrace& t);
std::string format_json(const PixelTrace& t);
std::string format_text(const NanReport& r);

}  // namespace glslrun::debug
