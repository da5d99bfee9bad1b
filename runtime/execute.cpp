// run_vertices / run_fragments: the shaders alone, without rasterization.
#include "runtime/execute.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>

#include <fmt/format.h>

#include "runtime/api_checks.h"
#include "runtime/backend_factory.h"
#include "runtime/parallel.h"
#include "runtime/undef_sink.h"

namespace glslrun::exec {

namespace {

float from_bits(ir::Kind kind, uint32_t bits) {
    switch (kind) {
    case ir::Kind::F32: {
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    case ir::Kind::I32: return float(int32_t(bits));
    case ir::Kind::Bool: return bits ? 1.0f : 0.0f;
    }
    return 0.0f;
}

uint32_t to_bits(ir::Kind kind, float value) {
    uint32_t bits = 0;
    switch (kind) {
    case ir::Kind::F32: std::memcpy(&bits, &value, sizeof bits); break;
    case ir::Kind::I32: bits = uint32_t(int32_t(value)); break;
    case ir::Kind::Bool: bits = value != 0.0f ? 1u : 0u; break;
    }
    return bits;
}

}  // namespace

float lane_as_float(rt::Executor& interp, ir::Kind kind, ir::Reg r, int lane) {
    return from_bits(kind, interp.lanes(r)[lane]);
}

void set_lane(rt::Executor& interp, ir::Kind kind, ir::Reg r, int lane, float value) {
    interp.lanes(r)[lane] = to_bits(kind, value);
}

Error run_error(const Program::State& state, ir::Stage stage, const rt::RunError& error) {
    const std::string& file = stage == ir::Stage::Vertex ? state.vertex_name : state.fragment_name;
    return Error(error.message, file, error.line);
}

namespace {

// Where one shader input gets its values from.
struct InputSource {
    const ir::Binding* binding = nullptr;
    const VertexAttrib* attrib = nullptr;  // null: the default below
    glm::vec4 fallback{0, 0, 0, 1};
};

float default_component(uint32_t component, const glm::vec4& fallback) {
    return component < 4 ? fallback[component] : (component % 4 == 3 ? 1.0f : 0.0f);
}

// The value of a component an input lacks: the current value where no array
// feeds it; where an array of fewer components does, GL 2.1 §2.8's (0, 0, 0,
// 1), not the current value (a colour array of 3 has alpha 1, whatever glColor said).
float missing_component(const InputSource& src, uint32_t component) {
    return default_component(component, src.attrib ? glm::vec4(0, 0, 0, 1) : src.fallback);
}

Result<std::vector<InputSource>> plan_inputs(const ir::Shader& shader,
                                             const std::vector<VertexAttrib>& attribs, uint32_t count,
                                             const GLState& current) {
    std::vector<InputSource> plan;
    for (const VertexAttrib& a : attribs) {
        if (a.components == 0 || a.components > 16)
            return Error(fmt::format("attribute '{}': {} components (1..16 allowed)", a.name, a.components));
        if (a.data.size() < size_t(a.components) * count)
            return Error(fmt::format("attribute '{}': {} values for {} elements of {} components", a.name,
                                     a.data.size(), count, a.components));
    }
    for (const ir::Binding& b : shader.inputs) {
        InputSource src{&b};
        for (const VertexAttrib& a : attribs)
            if (a.name == b.name) src.attrib = &a;
        if (b.name == "gl_Color") src.fallback = current.current_color;
        if (b.name == "gl_SecondaryColor") src.fallback = current.current_secondary_color;
        if (b.name == "gl_Normal") src.fallback = glm::vec4(current.current_normal, 1.0f);
        if (b.name == "gl_FrontFacing") src.fallback = {1, 0, 0, 1};
        plan.push_back(src);
    }
    return plan;
}

void fill_input(rt::Executor& interp, const InputSource& src, int lane, uint32_t element) {
    const ir::Binding& b = *src.binding;
    for (uint32_t c = 0; c < b.count; ++c) {
        float v = missing_component(src, c);
        if (src.attrib && c < src.attrib->components)
            v = src.attrib->data[size_t(element) * src.attrib->components + c];
        set_lane(interp, b.kind, b.first + c, lane, v);
    }
}

// Lanes [0, n) of src's registers from elements base..base+n-1: per register,
// not per element (set_lane per element was 7% of a vertex-bound frame).
void fill_batch(rt::Executor& interp, const InputSource& src, uint32_t base, int n) {
    const ir::Binding& b = *src.binding;
    for (uint32_t c = 0; c < b.count; ++c) {
        uint32_t* dst = interp.lanes(b.first + c);
        if (!src.attrib || c >= src.attrib->components) {
            std::fill(dst, dst + n, to_bits(b.kind, missing_component(src, c)));
            continue;
        }
        const float* data = src.attrib->data.data() + size_t(base) * src.attrib->components + c;
        const size_t stride = src.attrib->components;
        // Floats, nearly always, as a plain copy: to_bits()'s switch per lane
        // stayed in the loop (perf: most of a vertex batch's plumbing).
        if (b.kind == ir::Kind::F32)
            for (int lane = 0; lane < n; ++lane) dst[lane] = std::bit_cast<uint32_t>(data[size_t(lane) * stride]);
        else
            for (int lane = 0; lane < n; ++lane) dst[lane] = to_bits(b.kind, data[size_t(lane) * stride]);
    }
}

}  // namespace

std::vector<uint32_t> output_offsets(const ir::Shader& shader, uint32_t* stride) {
    std::vector<uint32_t> offset;
    *stride = 0;
    for (const ir::Binding& b : shader.outputs) {
        offset.push_back(*stride);
        *stride += b.count;
    }
    return offset;
}

namespace {

// Vertices per job of the workers, and the draw size below which starting
// threads costs more than it saves.
constexpr uint32_t kVertexJob = 64 * rt::kLanes;
constexpr uint32_t kParallelVertices = 4096;

// Shades vertices [begin, end) in batches of kLanes starting at `begin` (a
// multiple of kLanes, so batches do not depend on the thread count).
std::optional<Error> shade_range(rt::Executor& interp, const Program::State& st,
                                 const std::vector<InputSource>& plan, uint32_t begin, uint32_t end,
                                 VertexOutputs& out) {
    const ir::Shader& vs = st.ir.vertex;
    for (uint32_t base = begin; base < end; base += rt::kLanes) {
        int n = int(std::min<uint32_t>(rt::kLanes, end - base));
        for (const InputSource& src : plan) fill_batch(interp, src, base, n);
        if (st.undef) [[unlikely]]
            st.undef->vertex_batch(base);
        rt::LaneMask live = n == rt::kLanes ? rt::kAllLanes : (rt::LaneMask(1) << n) - 1;
        rt::RunError error;
        if (!interp.run(live, &error)) return run_error(st, ir::Stage::Vertex, error);
        for (size_t o = 0; o < vs.outputs.size(); ++o) {
            const ir::Binding& b = vs.outputs[o];
            for (uint32_t c = 0; c < b.count; ++c) {
                const uint32_t* src = interp.lanes(b.first + c);
                float* dst = out.data.data() + size_t(base) * out.stride + out.offset[o] + c;
                if (b.kind == ir::Kind::F32)  // as fill_batch
                    for (int lane = 0; lane < n; ++lane) dst[size_t(lane) * out.stride] = std::bit_cast<float>(src[lane]);
                else
                    for (int lane = 0; lane < n; ++lane) dst[size_t(lane) * out.stride] = from_bits(b.kind, src[lane]);
            }
        }
    }
    return std::nullopt;
}

}  // namespace

Result<std::vector<std::vector<uint32_t>>> vertex_input_words(const ir::Shader& shader,
                                                               const std::vector<VertexAttrib>& attribs,
                                                               uint32_t count, const GLState& current,
                                                               uint32_t element) {
    if (element >= count) return Error(fmt::format("vertex {} is out of range ({} vertices)", element, count));
    auto plan = plan_inputs(shader, attribs, count, current);
    if (!plan) return plan.error();
    std::vector<std::vector<uint32_t>> words;
    for (const InputSource& src : *plan) {
        std::vector<uint32_t>& w = words.emplace_back();
        for (uint32_t c = 0; c < src.binding->count; ++c) {
            float v = missing_component(src, c);
            if (src.attrib && c < src.attrib->components) v = src.attrib->data[size_t(element) * src.attrib->components + c];
            w.push_back(to_bits(src.binding->kind, v));
        }
    }
    return words;
}

// Every vertex of the arrays is shaded exactly once, and primitives refer to
// the shaded copies by index: for indexed meshes this is the post-transform
// cache, one that never misses. Large draws shade jobs of vertices on
// ExecOptions::threads workers.
Status shade_vertices(const Program& program, const std::vector<VertexAttrib>& attribs, uint32_t count,
                      const GLState& current, VertexOutputs& out, rt::DrawBudget& budget) {
    const Program::State& st = state_of(program);
    const ir::Shader& vs = st.ir.vertex;
    auto plan = plan_inputs(vs, attribs, count, current);
    if (!plan) return plan.error();
    out.offset = output_offsets(vs, &out.stride);
    if (Status st = rt::check_batch_size(count, out.stride, "vertices"); !st) return st;
    // Not cleared: shade_range writes every component of every vertex.
    out.data.resize(size_t(count) * out.stride);
    size_t jobs = (size_t(count) + kVertexJob - 1) / kVertexJob;
    unsigned workers = count < kParallelVertices ? 1 : rt::thread_count(program.exec.threads, jobs);
    std::vector<std::optional<Error>> errors(jobs);
    rt::JobQueue queue(jobs);
    rt::run_workers(workers, [&](unsigned) {
        std::unique_ptr<rt::Executor> shader =
            rt::make_executor(program, ir::Stage::Vertex, current.texture_units.data(), &budget);
        rt::Executor& interp = *shader;
        for (size_t job; queue.next(&job);) {
            uint32_t begin = uint32_t(job) * kVertexJob, end = std::min(count, begin + kVertexJob);
            errors[job] = shade_range(interp, st, *plan, begin, end, out);
            if (errors[job]) queue.fail(job);
        }
    });
    if (auto failed = queue.first_failure()) return *errors[*failed];
    return Ok{};
}

}  // namespace glslrun::exec

namespace glslrun {

namespace {

// What run_vertices and run_fragments check before they run.
Status check_run_input(const Program& program, const GLState* gl) {
    if (Status st = check_valid(program); !st) return st;
    if (Status st = rt::check_exec_options(program.exec); !st) return st;
    return gl ? rt::check_gl_enums(*gl) : Status(Ok{});
}

Result<std::vector<ShaderOutput>> vertices_of(const Program& program, const std::vector<VertexAttrib>& attribs,
                                              uint32_t count, const GLState* gl) {
    if (Status st = check_run_input(program, gl); !st) return st.error();
    uint32_t stride = 0;
    exec::output_offsets(state_of(program).ir.vertex, &stride);
    // The shaded vertices, then their copy as ShaderOutputs.
    if (Status st = rt::check_batch_size(count, 2 * uint64_t(stride), "vertices"); !st) return st.error();
    exec::VertexOutputs shaded;
    rt::DrawBudget budget(program.exec);
    if (Status st = exec::shade_vertices(program, attribs, count, gl ? *gl : GLState{}, shaded, budget); !st)
        return st.error();
    if (budget.over() != rt::DrawBudget::Stop::None) return Error(budget.message(budget.over()));
    const ir::Shader& vs = state_of(program).ir.vertex;
    std::vector<ShaderOutput> outputs;
    for (size_t o = 0; o < vs.outputs.size(); ++o) {
        ShaderOutput out{vs.outputs[o].name, vs.outputs[o].count, {}};
        out.data.reserve(size_t(count) * out.components);
        for (uint32_t v = 0; v < count; ++v) {
            const float* src = shaded.vertex(v) + shaded.offset[o];
            out.data.insert(out.data.end(), src, src + out.components);
        }
        outputs.push_back(std::move(out));
    }
    return outputs;
}

Result<std::vector<ShaderOutput>> fragments_of(const Program& program, const std::vector<VertexAttrib>& inputs,
                                               uint32_t count, const GLState* gl) {
    if (Status valid = check_run_input(program, gl); !valid) return valid.error();
    const Program::State& st = state_of(program);
    const ir::Shader& fs = st.ir.fragment;
    uint64_t words = 1;  // "discarded"
    for (const ir::Binding& b : fs.outputs) words += b.count;
    if (Status size = rt::check_batch_size(count, words, "fragments"); !size) return size.error();
    const GLState defaults;
    const GLState& state = gl ? *gl : defaults;
    auto plan = exec::plan_inputs(fs, inputs, count, state);
    if (!plan) return plan.error();
    std::vector<ShaderOutput> outputs;
    for (const ir::Binding& b : fs.outputs) outputs.push_back({b.name, b.count, std::vector<float>(size_t(count) * b.count)});
    ShaderOutput discarded{"discarded", 1, std::vector<float>(count)};
    rt::DrawBudget budget(program.exec);
    std::unique_ptr<rt::Executor> shader =
        rt::make_executor(program, ir::Stage::Fragment, state.texture_units.data(), &budget);
    rt::Executor& interp = *shader;
    for (uint32_t base = 0; base < count; base += rt::kLanes) {
        int n = int(std::min<uint32_t>(rt::kLanes, count - base));
        // Padding up to a whole quad repeats the last fragment as helper lanes.
        int live_lanes = (n + 3) & ~3;
        for (int lane = 0; lane < live_lanes; ++lane)
            for (const auto& src : *plan) exec::fill_input(interp, src, lane, base + std::min(lane, n - 1));
        rt::LaneMask live = live_lanes == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << live_lanes) - 1;
        rt::RunError error;
        if (!interp.run(live, &error)) return exec::run_error(st, ir::Stage::Fragment, error);
        rt::LaneMask alive = interp.alive();
        for (int lane = 0; lane < n; ++lane) {
            discarded.data[base + lane] = (alive >> lane) & 1u ? 0.0f : 1.0f;
            for (size_t o = 0; o < fs.outputs.size(); ++o) {
                const ir::Binding& b = fs.outputs[o];
                for (uint32_t c = 0; c < b.count; ++c)
                    outputs[o].data[size_t(base + lane) * b.count + c] =
                        exec::lane_as_float(interp, b.kind, b.first + c, lane);
            }
        }
    }
    shader.reset();  // its last instructions reach the budget
    if (budget.over() != rt::DrawBudget::Stop::None) return Error(budget.message(budget.over()));
    outputs.push_back(std::move(discarded));
    return outputs;
}

}  // namespace

Result<std::vector<ShaderOutput>> run_vertices(const Program& program, const std::vector<VertexAttrib>& attribs,
                                               uint32_t count, const GLState* gl) {
    return rt::without_throwing("run_vertices()", [&] { return vertices_of(program, attribs, count, gl); });
}

Result<std::vector<ShaderOutput>> run_fragments(const Program& program, const std::vector<VertexAttrib>& inputs,
                                                uint32_t count, const GLState* gl) {
    return rt::without_throwing("run_fragments()", [&] { return fragments_of(program, inputs, count, gl); });
}

}  // namespace glslrun
