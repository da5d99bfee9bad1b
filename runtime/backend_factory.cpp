// The backend factory and the way from a Program to an executor
// (runtime/backend_factory.h).
#include "runtime/backend_factory.h"

#include <fmt/format.h>

#include "ir/passes.h"
#include "raster/fused/pipeline.h"
#include "runtime/backend_cache.h"
#include "runtime/interp_kernels.h"
#include "runtime/interpreter.h"
#include "runtime/program_state.h"
#include "runtime/jit/jit.h"
#include "runtime/jit_plugin.h"

namespace glslrun {

bool jit_available() { return rt::jit_plugin() != nullptr; }

Backend effective_backend(Backend requested, Precision precision) {
    return rt::runner_for(requested, precision) == rt::Runner::Jit ? Backend::Jit : Backend::Interp;
}

Program::JitCompiles Program::jit_compiles() const {
    if (!valid()) return {};
    return state_->backends->jit_compiles();
}

double Program::jit_compile_seconds() const {
    if (!valid()) return 0;  // moved from: nothing compiled
    return state_->backends->jit_compile_seconds() + state_->pipelines->compile_seconds();
}

}  // namespace glslrun

namespace glslrun::rt {

Runner runner_for(Backend requested, Precision precision) {
    if (precision == Precision::Reference || requested == Backend::Interp) return Runner::Interp;
    // Auto must not load the plugin before it compiles anything: its file's presence is enough here
    // (a plugin that then fails to load leaves the interpreter running, the same bits).
    const bool jit = requested == Backend::Jit ? jit_available() : jit_plugin_present();
    return jit ? Runner::Jit : Runner::Interp;
}

namespace {

// The interpreter compiles its Steps per instance (they hold pointers into
// the instance's register file), so its shared part is the shader itself.
class InterpretedShader final : public CompiledShader {
public:
    explicit InterpretedShader(const ir::Shader& shader) : shader_(shader) {}
    std::unique_ptr<Executor> instantiate(const ExecParams& params) const override {
        return std::make_unique<Interpreter>(shader_, params);
    }

private:
    const ir::Shader& shader_;
};

}  // namespace

std::unique_ptr<CompiledShader> compile_shader(const ir::Shader& shader, Runner runner, Precision precision,
                                               uint32_t fast_ops, bool avx2, double* llvm_seconds,
                                               bool quick_codegen, const std::atomic<bool>* stop,
                                               CodeCacheUse cache, bool optimised) {
    if (llvm_seconds) *llvm_seconds = 0;
    if (cache.loaded) *cache.loaded = false;
    const JitEntryPoints* jit = runner == Runner::Jit ? jit_plugin() : nullptr;
    if (jit) {
        jit::CompileStats stats;
        stats.stop = stop;
        stats.cache = cache.config;
        stats.only_load = cache.only_load;
        stats.optimised = optimised;
        std::unique_ptr<CompiledShader> code = jit->compile(shader, precision, fast_ops, avx2, quick_codegen, &stats);
        if (llvm_seconds) *llvm_seconds = stats.seconds;
        if (cache.loaded) *cache.loaded = stats.loaded;
        if (code) return code;
    }
    if (cache.only_load) return nullptr;
    return std::make_unique<InterpretedShader>(shader);
}

JitPlan plan_jit(const ir::Shader& shader, bool quick_codegen, bool optimised) {
    if (!jit_plugin_present()) return {};
    return jit::plan_compile(shader, quick_codegen, optimised);
}

std::unique_ptr<Executor> make_executor(const Program& program, ir::Stage stage,
                                        const GLState::TextureUnit* textures, DrawBudget* budget) {
    const Program::State& st = state_of(program);
    const ir::Shader& shader = stage == ir::Stage::Vertex ? st.ir.vertex : st.ir.fragment;
    ExecParams params{st.uniforms.data(), RunLimits(program.exec), textures, program.exec.precision,
                      st.fast_ops};
    params.limits.draw = budget;
    if (budget) params.limits.cancel = nullptr;  // the budget polls it
    BackendCache::Key key{stage, runner_for(program.exec.backend, params.precision), params.precision,
                          params.fast_ops, cpu_has_avx2(), program.exec.jit_quick_codegen};
    const bool tiered = program.exec.jit_tier == JitTier::Tiered;
    key.optimised = key.runner == Runner::Jit && program.exec.jit_tier == JitTier::Optimised &&
                    !program.exec.jit_quick_codegen;
    std::unique_ptr<Executor> executor;
    if (key.runner != Runner::Jit) {
        executor = st.backends->get(shader, key).instantiate(params);
    } else {
        key.specialization =
            st.backends->specialization(shader, st.uniforms, st.uses, program.exec.jit_specialize_after);
        const CodeCacheConfig cache = code_cache_config(program.exec);
        if (program.exec.backend == Backend::Jit) {
            executor = st.backends->jit_executor(shader, key, params, &cache, tiered);
        } else {
            BackendCache::Key interp = key;
            interp.runner = Runner::Interp;
            interp.specialization.clear();
            interp.optimised = false;
            executor = st.backends->auto_executor(shader, key, interp, params, &cache, tiered);
        }
    }
    if (st.undef) executor->watch_undefined(st.undef);
    return executor;
}

}  // namespace glslrun::rt
