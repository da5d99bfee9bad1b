#include "debug/debugger.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <unordered_map>

#include <fmt/format.h>

#include "debug/recorder.h"
#include "ir/passes.h"
#include "raster/fragments.h"
#include "raster/probe.h"
#include "raster/triangle.h"
#include "runtime/program_state.h"
#include "glslrun/scene/render.h"
#include "scene/ffp.h"

namespace glslrun::debug {

namespace {

// The optimizer's value-changing decisions, with every variable kept: fold
// and copyprop (whose common subexpressions decide which square roots only
// divide, Fast's rsqrt) run as in ir/optimize.cpp, the variables' registers
// count as outputs so dce keeps their writes, then contract (Fast's FMAs),
// which looks through the copies into variables that nothing reads (a
// product first stored in a variable, `vec4 c = 6.0 * t; c += ...`, fuses
// into the add as in the optimized program, whose store is dead, and c still
// shows the rounded product), and sqrt_divisor runs last.
// No inlining (calls stay calls, callees keep their variables' registers),
// no dead_stores (every assignment stays visible), no hoist (no statement
// moves out of its place), no regalloc (registers keep their variables).
void optimize_keeping_variables(ir::Shader& shader) {
    std::vector<ir::Binding> outputs = shader.outputs;
    for (const ir::Variable& v : shader.variables)
        if (v.count > 0) shader.outputs.push_back(ir::Binding{v.name, shader.regs[v.first], v.first, v.count});
    for (int round = 0; round < 3; ++round) {
        ir::fold_constants(shader);
        ir::propagate_copies(shader);
        ir::eliminate_dead_code(shader);
    }
    shader.outputs = std::move(outputs);
    ir::contract_multiply_add(shader, true);
    ir::mark_sqrt_divisors(shader);
}

}  // namespace

Result<Program> compile_for_debugging(const std::vector<ShaderSource>& vertex,
                                      const std::vector<ShaderSource>& fragment, Precision precision,
                                      CompileOptions options) {
    options.optimize = false;
    auto program = Program::compile(vertex, fragment, options);
    if (!program) return program.error();
    for (ir::Shader* s : {&state_of(*program).ir.vertex, &state_of(*program).ir.fragment}) {
        optimize_keeping_variables(*s);
        if (std::string problem = ir::verify(*s); !problem.empty())
            return Error("internal error: the debugging program: " + problem);
    }
    program->exec.precision = precision;
    return program;
}

namespace {

using Words = std::vector<uint32_t>;

// What a draw used: the replays need the same uniforms, textures and vertices.
struct DrawSnapshot {
    const PassProbe::PassPrograms* programs = nullptr;  // stable: PassProbe keeps them for the render
    Words uniforms;
    GLState gl;
    std::vector<VertexAttrib> attribs;
    uint32_t vertex_count = 0;
    exec::VertexOutputs shaded;
};

// A fragment at the traced pixel, as the render saw it.
struct Capture {
    FragmentTrace info;
    int lane = 0;
    rt::LaneMask live = 0;
    std::vector<std::pair<std::string, Words>> inputs;  // optimized input bindings: kLanes words per component
    int pixel = 0;  // which of the probe's pixels
};

// One lane of a binding's registers, as the interpreter's callers see them (32-bit words).
template <class Interp>
NamedValue binding_value(const ir::Binding& b, Interp& in, int lane) {
    NamedValue v{b.name, binding_type(b), {b.kind, false, {}}};
    for (uint32_t c = 0; c < b.count; ++c) {
        uint32_t w = in.lanes(b.first + c)[lane];
        v.value.c.push_back(b.kind == ir::Kind::F32 ? double(std::bit_cast<float>(w)) : double(int32_t(w)));
    }
    return v;
}

template <class Interp>
std::vector<NamedValue> outputs_of(const std::vector<ir::Binding>& outputs, Interp& in, int lane) {
    std::vector<NamedValue> out;
    for (const ir::Binding& b : outputs) out.push_back(binding_value(b, in, lane));
    return out;
}

bool same_bits(const std::vector<NamedValue>& a, const std::vector<NamedValue>& b) {
    for (const NamedValue& x : a)
        for (const NamedValue& y : b)
            if (x.name == y.name) {
                if (x.value.c.size() != y.value.c.size()) return false;
                for (size_t i = 0; i < x.value.c.size(); ++i)
                    if (std::bit_cast<uint64_t>(x.value.c[i]) != std::bit_cast<uint64_t>(y.value.c[i])) return false;
            }
    return true;
}

// Runs one invocation of `shader` traced: `fill` writes the inputs, lane
// `lane` is recorded, with at most `steps_left` steps (the trace's budget,
// InvocationTrace::kMaxTraceSteps), which it uses up.
template <class Fill>
InvocationTrace replay(const Program& debug, const ir::Shader& shader, const DrawSnapshot& draw, rt::LaneMask live,
                       int lane, size_t& steps_left, Fill&& fill) {
    ShaderNames names(shader, state_of(debug).ir);
    LaneRecorder recorder(names, draw.uniforms.data(), lane, std::min(InvocationTrace::kMaxSteps, steps_left),
                          draw.gl.texture_units.data(), debug.exec.precision);
    rt::TracedInterpreter in(shader, draw.uniforms.data(), rt::RunLimits(debug.exec), draw.gl.texture_units.data(),
                             debug.exec.precision, ~0u, recorder);
    fill(in);
    recorder.trace.files = shader.sources;
    for (const ir::Binding& b : shader.inputs) recorder.trace.inputs.push_back(binding_value(b, in, lane));
    rt::RunError error;
    bool ok = in.run(live, &error);
    recorder.finish(nullptr);
    recorder.trace.outputs = outputs_of(shader.outputs, in, lane);
    if (!ok) {
        recorder.trace.truncated = true;
        recorder.trace.stopped = error.message;
    }
    steps_left -= std::min(steps_left, recorder.cost());
    return std::move(recorder.trace);
}

class Probe : public PassProbe {
public:
    void begin_draw(const raster::ProbeDraw& d) override {
        enter_draw(d);
        draws_.push_back({&current(), state_of(*current().program).uniforms, d.gl, d.attribs, d.vertex_count,
                          d.shaded});
    }
    uint32_t draw_index() const { return uint32_t(draws_.size() - 1); }
    const std::vector<DrawSnapshot>& draws() const { return draws_; }

protected:
    std::vector<DrawSnapshot> draws_;
};

FragmentTrace describe(const raster::FsPrimitive& p, uint32_t draw, const PassProbe::PassPrograms& pass, float z) {
    FragmentTrace f;
    f.draw = draw;
    f.pass = pass.name;
    f.program = pass.program_name;
    f.primitive = p.primitive;
    f.vertices = p.vertex_ids;
    f.front = p.front;
    f.depth = z;
    return f;
}

// The tests of lane `lane` as the fragment stage ran them; `alive`: the
// shader did not discard it. A failed test stops the ones after it.
FragmentTests tests_of(const GLState& gl, const raster::ProbeTests& t, int lane, bool front, bool alive) {
    using R = FragmentTests::Result;
    const size_t i = size_t(lane);
    const rt::LaneMask bit = rt::LaneMask(1) << lane;
    bool reached = alive;
    auto result = [&](bool enabled, rt::LaneMask failed) {
        if (!enabled) return R::Off;
        if (!reached) return R::NotReached;
        if (failed & bit) {
            reached = false;
            return R::Failed;
        }
        return R::Passed;
    };
    FragmentTests f;
    f.scissor_test = result(gl.scissor_test, 0);
    f.alpha_test = result(gl.alpha_test, t.alpha_failed);
    f.stencil_test = result(gl.stencil_test, t.stencil_failed);
    f.depth_test = result(gl.depth_test, t.depth_failed);
    f.alpha_func = gl.alpha_func;
    f.alpha = t.alpha[i];
    f.alpha_ref = t.alpha_ref;
    f.alpha_bytes = t.alpha_bytes;
    const StencilFace& face = gl.stencil[front ? 0 : 1];
    f.stencil_func = face.func;
    f.stencil_ref = uint32_t(std::clamp(face.ref, 0, 255));
    f.stencil_mask = face.value_mask & 255u;
    f.stored_stencil = t.stored_stencil[i];
    f.depth_func = gl.depth_func;
    f.z = t.z[i];
    f.stored_depth = t.stored_depth[i];
    return f;
}

// The colour operations of a draw of `fs` under `gl`.
ColorWrites color_writes(const GLState& gl, const ir::Shader& fs) {
    ColorWrites w;
    bool frag_color = false;
    for (const ir::Binding& b : fs.outputs) frag_color |= b.name == "gl_FragColor";
    for (int i = 0; i < gl.draw_buffers && i < kMaxDrawBuffers; ++i) {
        const std::string element = fmt::format("gl_FragData[{}]", i);
        bool written = frag_color;
        for (const ir::Binding& b : fs.outputs) written |= b.name == element;
        if (written) w.buffers.push_back(i);
    }
    w.blend = gl.blend;
    w.blend_state = gl.blend_state;
    w.logic_op = gl.color_logic_op;
    w.logic = gl.logic_op;
    w.mask = gl.color_mask;
    return w;
}

PixelValues pixel_values(const raster::ProbePixel& p, bool bytes) {
    PixelValues v;
    v.bytes = bytes;
    v.color.assign(p.color.begin(), p.color.begin() + std::clamp(p.buffers, 0, kMaxDrawBuffers));
    v.depth = p.depth;
    v.stencil = p.stencil;
    return v;
}

// Captures every fragment at some window pixels of the output framebuffer,
// with the framebuffer there before and after each; `keep_inputs`: with
// the shader inputs of its batch, for a replay.
class PixelProbe final : public Probe {
public:
    // `target`: the render target whose pixels these are; empty: the output framebuffer's.
    PixelProbe(const std::vector<std::pair<int, int>>& window_pixels, bool keep_inputs, std::string target = {})
        : keep_inputs_(keep_inputs), target_(std::move(target)) {
        for (size_t i = 0; i < window_pixels.size(); ++i)
            pixels_.emplace(key(window_pixels[i].first, window_pixels[i].second), int(i));
    }
    // The index into the pixels of lane `lane`'s, or -1.
    int pixel_of(const raster::ProbeBatch& b, int lane) const {
        auto found = pixels_.find(key(b.x[size_t(lane)], b.y[size_t(lane)]));
        return found == pixels_.end() ? -1 : found->second;
    }
    rt::LaneMask watched(const raster::ProbeBatch& b) override {
        rt::LaneMask lanes = 0;
        if (current().target != target_) return 0;  // a pass drawing into another framebuffer
        for (rt::LaneMask bits = b.covered; bits; bits &= bits - 1)
            if (pixel_of(b, std::countr_zero(bits)) >= 0) lanes |= rt::LaneMask(1) << std::countr_zero(bits);
        return lanes;
    }
    void before_run(const raster::ProbeBatch& b) override {
        if (current().target != target_) return;
        const ir::Shader& fs = state_of(*current().program).ir.fragment;
        for (rt::LaneMask bits = b.covered; bits; bits &= bits - 1) {
            int lane = std::countr_zero(bits), pixel = pixel_of(b, lane);
            if (pixel < 0) continue;
            Capture c{describe(*b.quad_prim[lane / 4], draw_index(), current(), b.z[size_t(lane)]),
                      lane,
                      b.lanes == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << b.lanes) - 1,
                      {},
                      pixel};
            for (const ir::Binding& in : keep_inputs_ ? fs.inputs : std::vector<ir::Binding>{}) {
                Words w;
                for (uint32_t k = 0; k < in.count; ++k)
                    w.insert(w.end(), b.interp.lanes(in.first + k), b.interp.lanes(in.first + k) + rt::kLanes);
                c.inputs.emplace_back(in.name, std::move(w));
            }
            pending_.push_back(std::move(c));
        }
    }
    void after_write(const raster::ProbeBatch& b, rt::LaneMask alive, rt::LaneMask written,
                     const raster::ProbeTests& tests) override {
        const ir::Shader& fs = state_of(*current().program).ir.fragment;
        for (Capture& c : pending_) {
            using O = FragmentTrace::Outcome;
            using R = FragmentTests::Result;
            bool is_alive = (alive >> c.lane) & 1, is_written = (written >> c.lane) & 1;
            const GLState& gl = draws_.back().gl;
            c.info.tests = tests_of(gl, tests, c.lane, c.info.front, is_alive);
            const FragmentTests& t = c.info.tests;
            c.info.outcome = !is_alive                        ? O::Discarded
                             : is_written                     ? O::Written
                             : t.alpha_test == R::Failed      ? O::AlphaFailed
                             : t.stencil_test == R::Failed    ? O::StencilFailed
                                                              : O::DepthFailed;
            c.info.rendered = outputs_of(fs.outputs, b.interp, c.lane);
            c.info.before = pixel_values(tests.before[size_t(c.lane)], tests.alpha_bytes);
            c.info.after = pixel_values(tests.after[size_t(c.lane)], tests.alpha_bytes);
            c.info.writes = color_writes(gl, fs);
            captures_.push_back(std::move(c));
        }
        pending_.clear();
    }
    std::vector<Capture> captures_;

private:
    static uint64_t key(int x, int y) { return uint64_t(uint32_t(x)) << 32 | uint32_t(y); }
    std::unordered_map<uint64_t, int> pixels_;  // window pixel -> its index
    bool keep_inputs_;
    std::string target_;
    std::vector<Capture> pending_;
};

FragmentTrace replay_fragment(const Program& debug, const DrawSnapshot& draw, Capture& c, size_t& steps_left) {
    FragmentTrace f = std::move(c.info);
    const ir::Shader& fs = state_of(debug).ir.fragment;
    f.trace = replay(debug, fs, draw, c.live, c.lane, steps_left, [&](rt::TracedInterpreter& in) {
        for (const ir::Binding& b : fs.inputs)
            for (const auto& [name, words] : c.inputs)
                if (name == b.name)
                    for (uint32_t k = 0; k < b.count && (k + 1) * rt::kLanes <= words.size(); ++k)
                        std::memcpy(in.lanes(b.first + k), words.data() + size_t(k) * rt::kLanes, rt::kLanes * 4);
    });
    f.matches_render = same_bits(f.trace.outputs, f.rendered);
    return f;
}

Result<VertexTrace> replay_vertex(const PassProbe::PassPrograms& pass, const DrawSnapshot& draw,
                                  uint32_t draw_index, uint32_t vertex, size_t& steps_left) {
    const Program &program = *pass.program, &debug = *pass.debug;
    const ir::Shader& vs = state_of(debug).ir.vertex;
    auto words = exec::vertex_input_words(vs, draw.attribs, draw.vertex_count, draw.gl, vertex);
    if (!words) return words.error();
    VertexTrace t{draw_index, vertex, pass.name, pass.program_name, true, {}};
    t.trace = replay(debug, vs, draw, 1, 0, steps_left, [&](rt::TracedInterpreter& in) {
        for (size_t i = 0; i < vs.inputs.size(); ++i)
            for (uint32_t k = 0; k < vs.inputs[i].count; ++k) in.lanes(vs.inputs[i].first + k)[0] = (*words)[i][k];
    });
    // The render's outputs of this vertex (VertexOutputs holds floats).
    const std::vector<ir::Binding>& outs = state_of(program).ir.vertex.outputs;
    for (const NamedValue& v : t.trace.outputs)
        for (size_t o = 0; o < outs.size(); ++o)
            if (outs[o].name == v.name)
                for (size_t k = 0; k < v.value.c.size(); ++k) {
                    float rendered = draw.shaded.vertex(vertex)[draw.shaded.offset[o] + k];
                    float traced = float(v.value.c[k]);  // VertexOutputs converts ints and bools to float too
                    if (std::bit_cast<uint32_t>(rendered) != std::bit_cast<uint32_t>(traced)) t.matches_render = false;
                }
    return t;
}

// Whether the scissor test (GL 2.1 §4.1.2) removes window pixel x,y.
bool outside_scissor(const GLState& gl, int x, int y) {
    if (!gl.scissor_test) return false;
    const auto& box = gl.scissor_box;
    auto outside = [](int v, int lo, int size) { return v < lo || int64_t(v) >= int64_t(lo) + std::max(size, 0); };
    return outside(x, box[0], box[2]) || outside(y, box[1], box[3]);
}

// A replay stops early at debug.exec.cancel, as the render stops at
// program.exec.cancel; the trace then ends with an error, not with the rest.
Status check_cancel(const Program& debug) {
    if (debug.exec.cancel && debug.exec.cancel->load(std::memory_order_relaxed))
        return Error("cancelled: the time limit ran out");
    return Ok{};
}

}  // namespace

namespace {

// The debugging twin of pass `pass`'s own program, with `debug`'s limits.
Result<std::shared_ptr<Program>> debug_twin(const scene::Pass& pass, const Program& debug) {
    auto twin = compile_for_debugging(pass.vertex, pass.fragment, debug.exec.precision, state_of(debug).options);
    if (!twin) {
        Error e(fmt::format("pass '{}': its debugging program does not compile", pass.name), pass.where.file,
                pass.where.line);
        for (const Diagnostic& d : twin.error().diagnostics) e.diagnostics.push_back(d);
        return e;
    }
    twin->exec = debug.exec;
    return std::make_shared<Program>(std::move(*twin));
}

std::string sources_name(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment) {
    std::string name;
    for (const auto* list : {&vertex, &fragment})
        for (const ShaderSource& s : *list) name += (name.empty() ? "" : " + ") + s.name;
    return name;
}

// The sources' lines, trimmed, by file name.
void add_lines(std::map<std::string, std::vector<std::string>>& lines, const std::vector<ShaderSource>& sources) {
    for (const ShaderSource& source : sources) {
        std::vector<std::string>& out = lines[source.name];
        out.clear();
        for (size_t at = 0; at <= source.text.size();) {
            size_t end = std::min(source.text.find('\n', at), source.text.size());
            std::string_view line(source.text.data() + at, end - at);
            size_t first = line.find_first_not_of(" \t\r\f\v"), last = line.find_last_not_of(" \t\r\f\v");
            out.emplace_back(first == std::string_view::npos ? std::string_view()
                                                             : line.substr(first, last - first + 1));
            at = end + 1;
        }
    }
}

// Every pass's program gets the probe, and the probe the passes' programs.
Status attach_probe(Program& program, const Program& debug, const std::string& program_name,
                    const scene::Scene& scene, int height, PassProbe& probe) {
    auto programs = scene::ScenePrograms::compile(program, scene);
    if (!programs) return programs.error();
    probe.scene_programs = std::move(*programs);
    probe.passes.clear();
    for (size_t i = 0; i < probe.scene_programs->size(); ++i) {
        PassProbe::PassPrograms p{&probe.scene_programs->of_pass(i), &debug, "", program_name, true, height, ""};
        if (!scene.passes.empty()) {
            const scene::Pass& pass = scene.passes[i];
            p.name = pass.name;
            p.to_output = pass.target < 0;
            if (pass.target >= 0) {
                p.height = scene.targets[size_t(pass.target)].height;
                p.target = scene.targets[size_t(pass.target)].name;
            }
            // A pass missing a stage draws programs with a generated one: their twins come at their draws.
            if (!pass.vertex.empty() && !pass.fragment.empty()) {
                auto twin = debug_twin(pass, debug);
                if (!twin) return twin.error();
                probe.debug_programs.push_back(*twin);
                p.debug = twin->get();
                p.program_name = sources_name(pass.vertex, pass.fragment);
                if (state_of(*p.debug).ir.uniform_words != state_of(*p.program).ir.uniform_words)
                    return Error(fmt::format("internal error: pass '{}': the debugging program's uniforms differ",
                                             pass.name));
            }
        }
        state_of(probe.scene_programs->of_pass(i)).probe = &probe;
        probe.passes.push_back(std::move(p));
    }
    probe.pass = 0;
    probe.scene_programs->before_pass = [&probe](size_t pass) { probe.pass = pass; };
    return Ok{};
}

// The name a trace gives the generated stage `text`: numbered per stage in
// the order first drawn, as --dump-fixed-function names its files.
std::string generated_name(std::vector<GeneratedStage>& generated, const std::string& text, bool vertex) {
    int count = 0;
    for (const GeneratedStage& g : generated) {
        if (g.vertex == vertex && g.text == text) return g.name;
        count += g.vertex == vertex;
    }
    std::string file = fmt::format("fixed-function-{}.{}", count + 1, vertex ? "vert" : "frag");
    generated.push_back({"(generated) " + file, file, text, vertex});
    return generated.back().name;
}

bool is_generated(const std::vector<ShaderSource>& sources, const char* name) {
    return sources.size() == 1 && sources[0].name == name;
}

}  // namespace

void PassProbe::enter_draw(const raster::ProbeDraw& draw) {
    current_ = &passes[pass];
    if (!draw.program || failed) return;
    const Program& drawn = *draw.program;
    const Program::State& st = state_of(drawn);
    const bool gen_vs = is_generated(st.vertex_sources, scene::ffp::kVertexStageName);
    const bool gen_fs = is_generated(st.fragment_sources, scene::ffp::kFragmentStageName);
    if (!gen_vs && !gen_fs) return;
    auto found = drawn_.find({pass, &drawn});
    if (found == drawn_.end()) {
        // The twin compiles the generated sources under the names the trace shows.
        std::vector<ShaderSource> vertex = st.vertex_sources, fragment = st.fragment_sources;
        if (gen_vs) vertex[0].name = generated_name(generated, vertex[0].text, true);
        if (gen_fs) fragment[0].name = generated_name(generated, fragment[0].text, false);
        const Program& pass_debug = *passes[pass].debug;
        auto twin = compile_for_debugging(vertex, fragment, pass_debug.exec.precision, st.options);
        if (!twin) {
            Error e("the debugging program of a generated fixed-function stage does not compile");
            for (const Diagnostic& d : twin.error().diagnostics) e.diagnostics.push_back(d);
            failed = std::move(e);
            return;
        }
        if (state_of(*twin).ir.uniform_words != st.ir.uniform_words) {
            failed = Error("internal error: a generated stage's debugging program's uniforms differ");
            return;
        }
        twin->exec = pass_debug.exec;
        debug_programs.push_back(std::make_shared<Program>(std::move(*twin)));
        PassPrograms p = passes[pass];
        p.program = &drawn;
        p.debug = debug_programs.back().get();
        p.program_name = sources_name(vertex, fragment);
        found = drawn_.emplace(std::pair{pass, &drawn}, std::move(p)).first;
    }
    current_ = &found->second;
}

Status render_with_probe(Program& program, const Program& debug, const std::string& program_name,
                         const scene::Scene& scene, Framebuffer& fb, PassProbe& probe) {
    unsigned threads = program.exec.threads;
    program.exec.threads = 1;  // one fragment stage, in tile order (the passes' programs copy it)
    Status st = attach_probe(program, debug, program_name, scene, fb.height, probe);
    if (st) {
        auto stats = scene::render_scene(*probe.scene_programs, scene, fb);
        if (!stats) st = stats.error();
        if (st && probe.failed) st = *probe.failed;
    }
    if (probe.scene_programs)
        for (size_t i = 0; i < probe.scene_programs->size(); ++i)
            state_of(probe.scene_programs->of_pass(i)).probe = nullptr;
    program.exec.threads = threads;
    return st;
}

Result<std::vector<PixelHistory>> pixel_history(Program& program, const Program& debug, const scene::Scene& scene,
                                                Framebuffer& fb, const std::vector<std::pair<int, int>>& pixels) {
    std::vector<PixelHistory> out;
    std::vector<std::pair<int, int>> window;
    for (auto [x, y] : pixels) {
        if (x < 0 || y < 0 || x >= fb.width || y >= fb.height)
            return Error(fmt::format("pixel {},{} is outside the {}x{} image", x, y, fb.width, fb.height));
        out.push_back({x, y, {}});
        window.emplace_back(x, fb.height - 1 - y);  // the framebuffer's row 0 is the bottom
    }
    PixelProbe probe(window, false);
    if (Status st = render_with_probe(program, debug, "the command line's program", scene, fb, probe); !st)
        return st.error();
    for (Capture& c : probe.captures_) out[size_t(c.pixel)].fragments.push_back(std::move(c.info));
    return out;
}

Result<PixelTrace> trace(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                         const TraceRequest& request) {
    if (state_of(debug).ir.uniform_words != state_of(program).ir.uniform_words)
        return Error("internal error: the debugging program's uniforms differ from the program's");
    PixelTrace out;
    out.target = request.target;
    int width = fb.width, height = fb.height;
    std::string framebuffer = "image";
    if (!request.target.empty()) {
        auto t = std::ranges::find(scene.targets, request.target, &scene::RenderTarget::name);
        if (t == scene.targets.end()) {
            std::string names;
            for (const scene::RenderTarget& rt : scene.targets) names += (names.empty() ? "" : ", ") + rt.name;
            return Error(fmt::format("the scene has no render target '{}' ({})", request.target,
                                     names.empty() ? "it has none" : "it has " + names));
        }
        width = t->width, height = t->height;
        framebuffer = fmt::format("render target '{}'", t->name);
    }
    int wy = -1;
    if (request.pixel) {
        out.x = request.pixel->first;
        out.y = request.pixel->second;
        if (out.x < 0 || out.y < 0 || out.x >= width || out.y >= height)
            return Error(fmt::format("pixel {},{} is outside the {}x{} {}", out.x, out.y, width, height, framebuffer));
        wy = height - 1 - out.y;  // the framebuffer's row 0 is the bottom
    }
    PixelProbe probe({{out.x, wy}}, true, request.target);
    std::string name = request.sources.empty() ? "the command line's program" : sources_name(request.sources, {});
    add_lines(out.source_lines, request.sources);
    for (const scene::Pass& pass : scene.passes) {
        add_lines(out.source_lines, pass.vertex);
        add_lines(out.source_lines, pass.fragment);
    }
    if (Status st = render_with_probe(program, debug, name, scene, fb, probe); !st) return st.error();
    out.generated = probe.generated;
    for (const GeneratedStage& g : out.generated) add_lines(out.source_lines, {{g.name, g.text}});
    const auto& draws = probe.draws();
    if (request.pixel)
        for (uint32_t d = 0; d < draws.size(); ++d)
            if (draws[d].programs->target == request.target && outside_scissor(draws[d].gl, out.x, wy))
                out.scissored.push_back(d);
    std::optional<FragmentTrace> visible;  // the last one written: the pixel shows it
    size_t steps_left = InvocationTrace::kMaxTraceSteps;
    for (Capture& c : probe.captures_) {
        const DrawSnapshot& draw = draws[c.info.draw];
        out.fragments.push_back(replay_fragment(*draw.programs->debug, draw, c, steps_left));
        if (Status st = check_cancel(debug); !st) return st.error();
        if (out.fragments.back().outcome == FragmentTrace::Outcome::Written) visible = out.fragments.back();
    }
    if (visible)
        for (uint32_t v : visible->vertices) {
            const DrawSnapshot& draw = draws[visible->draw];
            auto vt = replay_vertex(*draw.programs, draw, visible->draw, v, steps_left);
            if (!vt) return vt.error();
            if (Status st = check_cancel(debug); !st) return st.error();
            out.vertices.push_back(std::move(*vt));
        }
    if (request.vertex) {
        if (request.draw >= draws.size())
            return Error(fmt::format("draw {} does not exist ({} draws)", request.draw, draws.size()));
        const DrawSnapshot& draw = draws[request.draw];
        auto vt = replay_vertex(*draw.programs, draw, request.draw, *request.vertex, steps_left);
        if (!vt) return vt.error();
        if (Status st = check_cancel(debug); !st) return st.error();
        out.vertices.push_back(std::move(*vt));
    }
    return out;
}

}  // namespace glslrun::debug
