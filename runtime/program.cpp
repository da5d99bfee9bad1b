// Program: compile (frontend + IR passes), the uniform store with glUniform
// semantics, and introspection.
#include <algorithm>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "frontend/compile.h"
#include "ir/passes.h"
#include "raster/fused/pipeline.h"
#include "runtime/backend_cache.h"
#include "runtime/program_state.h"

namespace glslrun {

Program::Program() : state_(std::make_unique<State>()) {
    state_->backends = std::make_shared<rt::BackendCache>();
    state_->pipelines = std::make_shared<raster::fused::Cache>();
}
Program::Program(Program&&) noexcept = default;
Program& Program::operator=(Program&&) noexcept = default;
Program::~Program() = default;

Status check_valid(const Program& program) {
    if (program.valid()) return Ok{};
    return Error("the Program was moved from: it holds no compiled program");
}

ProgramUse::ProgramUse(Program& program) {
    if (status_ = check_valid(program); !status_) return;
    if (state_of(program).busy.exchange(true, std::memory_order_acquire)) {
        status_ = Error("the Program is in use on another thread: a Program draws and takes uniforms on one thread "
                        "at a time");
        return;
    }
    claimed_ = &state_of(program);
    ++claimed_->uses;
}

ProgramUse::~ProgramUse() {
    if (claimed_) claimed_->busy.store(false, std::memory_order_release);
}

namespace {

// CompileOptions::verify_ir, or GLSLRUN_VERIFY=1 (anything but empty or "0").
bool verify_requested(const CompileOptions& options) {
    if (options.verify_ir) return true;
    const char* env = std::getenv("GLSLRUN_VERIFY");
    return env && *env && std::string_view(env) != "0";
}

// GL's default is 0, except for GLSL 1.20 uniform initializers.
void initialise_uniforms(const ir::Program& ir, std::vector<uint32_t>& store) {
    store.assign(ir.uniform_words, 0u);
    size_t n = std::min(store.size(), ir.uniform_defaults.size());
    std::copy(ir.uniform_defaults.begin(), ir.uniform_defaults.begin() + n, store.begin());
}

}  // namespace

Result<Program> Program::compile(const std::vector<ShaderSource>& vertex,
                                 const std::vector<ShaderSource>& fragment,
                                 const CompileOptions& options) {
    Result<ir::Program> lowered = frontend::compile_program(vertex, fragment, options);
    if (!lowered) return lowered.error();
    Program program;
    State& st = *program.state_;
    st.ir = std::move(lowered.value());
    ir::PassOptions passes{options.optimize, options.inline_budget, verify_requested(options)};
    for (ir::Shader* shader : {&st.ir.vertex, &st.ir.fragment}) {
        if (options.check_undefined) ir::check_unwritten_reads(*shader);
        std::string problem = ir::optimize(*shader, passes);
        if (!problem.empty()) return Error("internal error: " + problem);
    }
    ir::mark_read_uniforms(st.ir);
    initialise_uniforms(st.ir, st.uniforms);
    if (!vertex.empty()) st.vertex_name = vertex.front().name;
    if (!fragment.empty()) st.fragment_name = fragment.front().name;
    st.options = options;
    if (vertex.empty() || fragment.empty()) {
        st.vertex_sources = vertex;
        st.fragment_sources = fragment;
    }
    return program;
}

namespace {

// Finds the leaf and checks that `count` values fit from the named element on.
Result<const ir::Uniform*> locate(const ir::Program& p, std::string_view name, size_t count,
                                  uint32_t* element) {
    const ir::Uniform* u = ir::find_uniform(p, std::string(name), element);
    if (!u) return Error(fmt::format("no active uniform named '{}'", name));
    uint32_t comps = u->type.components();
    if (count == 0 || count % comps != 0)
        return Error(fmt::format("uniform '{}' has {} components per element; got {} values", name,
                                 comps, count));
    size_t elements = count / comps;
    if (*element + elements > u->array_size)
        return Error(fmt::format("uniform '{}' has {} elements; {} values from element {} overflow it",
                                 name, u->array_size, elements, *element));
    return u;
}

}  // namespace

Status Program::set_uniform(std::string_view name, Span<const float> values) {
    ProgramUse use(*this);
    if (!use.status()) return use.status();
    uint32_t element = 0;
    auto found = locate(state_->ir, name, values.size(), &element);
    if (!found) return found.error();
    const ir::Uniform& u = **found;
    if (u.type.is_sampler || u.type.kind == ir::Kind::I32)
        return Error(fmt::format("uniform '{}' is an integer type; it takes ints, not floats", name));
    uint32_t* dst = state_->uniforms.data() + u.slot + element * u.type.components();
    for (size_t i = 0; i < values.size(); ++i) {
        if (u.type.kind == ir::Kind::Bool)
            dst[i] = values[i] != 0.0f ? 1u : 0u;
        else
            std::memcpy(&dst[i], &values[i], sizeof(float));
    }
    return Ok{};
}

Status Program::set_uniform(std::string_view name, Span<const int32_t> values) {
    ProgramUse use(*this);
    if (!use.status()) return use.status();
    uint32_t element = 0;
    auto found = locate(state_->ir, name, values.size(), &element);
    if (!found) return found.error();
    const ir::Uniform& u = **found;
    if (u.type.kind == ir::Kind::F32 && !u.type.is_sampler)
        return Error(fmt::format("uniform '{}' is a float type; it takes floats, not ints", name));
    if (u.type.is_sampler)  // glUniform1i: GL_INVALID_VALUE, and nothing changes
        for (int32_t unit : values)
            if (unit < 0 || unit >= kMaxTextureUnits)
                return Error(fmt::format("sampler '{}' set to texture unit {}; units are 0..{}", name, unit,
                                         kMaxTextureUnits - 1));
    uint32_t* dst = state_->uniforms.data() + u.slot + element * u.type.components();
    for (size_t i = 0; i < values.size(); ++i) {
        if (u.type.kind == ir::Kind::Bool)
            dst[i] = values[i] != 0 ? 1u : 0u;
        else
            dst[i] = uint32_t(values[i]);
    }
    return Ok{};
}

bool Program::has_uniform(std::string_view name) const {
    if (!valid()) return false;
    uint32_t element = 0;
    return ir::find_uniform(state_->ir, std::string(name), &element) != nullptr;
}

namespace {

std::string glsl_type_name(const ir::ValueType& t) {
    if (t.is_sampler) return "sampler";
    if (t.cols > 1)
        return t.cols == t.rows ? fmt::format("mat{}", t.cols) : fmt::format("mat{}x{}", t.cols, t.rows);
    const char* scalar = t.kind == ir::Kind::F32 ? "float" : t.kind == ir::Kind::I32 ? "int" : "bool";
    const char* prefix = t.kind == ir::Kind::F32 ? "vec" : t.kind == ir::Kind::I32 ? "ivec" : "bvec";
    return t.rows == 1 ? std::string(scalar) : fmt::format("{}{}", prefix, t.rows);
}

}  // namespace

std::vector<UniformInfo> Program::uniforms() const {
    std::vector<UniformInfo> out;
    if (!valid()) return out;
    for (const ir::Uniform& u : state_->ir.uniforms)
        out.push_back({u.name, glsl_type_name(u.type), u.array_size, u.builtin, u.read});
    return out;
}

std::vector<Program::Input> Program::inputs(Stage stage) const {
    std::vector<Input> out;
    if (!valid()) return out;
    const ir::Shader& shader = stage == Stage::Vertex ? state_->ir.vertex : state_->ir.fragment;
    for (const ir::Binding& b : shader.inputs) out.push_back({b.name, b.count});
    return out;
}

std::string Program::dump_ir() const { return valid() ? ir::print(state_->ir) : std::string(); }

}  // namespace glslrun
