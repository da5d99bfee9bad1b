// The backend factory and the per-program cache of compiled shaders.
#include "runtime/backend.h"

#include <system_error>

#include <fmt/format.h>

#include "ir/passes.h"
#include "runtime/backend_cache.h"
#include "runtime/fragment_pipeline.h"
#include "runtime/interp_kernels.h"
#include "runtime/interpreter.h"
#include "runtime/program_state.h"
#ifdef GLSLRUN_HAVE_JIT
#include "runtime/jit/jit.h"
#endif

namespace glslrun {

bool jit_available() {
#ifdef GLSLRUN_HAVE_JIT
    return true;
#else
    return false;
#endif
}

Backend effective_backend(Backend requested, Precision precision) {
    if (precision == Precision::Reference || !jit_available()) return Backend::Interp;
    return requested == Backend::Interp ? Backend::Interp : Backend::Jit;
}

double Program::jit_compile_seconds() const {
    if (!valid()) return 0;  // moved from: nothing compiled
    return state_->backends->jit_compile_seconds() + state_->pipelines->compile_seconds();
}

}  // namespace glslrun

namespace glslrun::rt {

std::string RunLimits::loop_cap_message() const {
    return fmt::format("loop exceeded {} iterations", max_loop_iterations);
}

std::string RunLimits::instructions_message() const {
    return fmt::format("the shader executed more than {} instructions in one batch (calls that multiply, or a loop "
                       "too long)",
                       max_instructions);
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

std::unique_ptr<CompiledShader> compile_shader(const ir::Shader& shader, Backend backend, Precision precision,
                                               uint32_t fast_ops, bool avx2, double* llvm_seconds,
                                               bool quick_codegen) {
    if (llvm_seconds) *llvm_seconds = 0;
#ifdef GLSLRUN_HAVE_JIT
    if (backend == Backend::Jit) {
        jit::CompileStats stats;
        std::unique_ptr<CompiledShader> code = jit::compile(shader, precision, fast_ops, avx2, quick_codegen, &stats);
        if (llvm_seconds) *llvm_seconds = stats.seconds;
        if (code) return code;
    }
#endif
    return std::make_unique<InterpretedShader>(shader);
}

BackendCache::~BackendCache() {
    for (std::thread& t : threads_) t.join();
}

namespace {

// A specialized shader's code and the IR it was made from (which the
// interpreter's code refers to, where the JIT declines it).
class SpecializedShader final : public CompiledShader {
public:
    std::unique_ptr<ir::Shader> shader;
    std::unique_ptr<CompiledShader> code;
    std::unique_ptr<Executor> instantiate(const ExecParams& params) const override {
        return code->instantiate(params);
    }
};

}  // namespace

std::unique_ptr<CompiledShader> BackendCache::compile(const ir::Shader& shader, const Key& key, double* seconds) {
    if (key.specialization.empty())
        return compile_shader(shader, key.backend, key.precision, key.fast_ops, key.avx2, seconds, key.quick_codegen);
    const std::vector<uint32_t> read = ir::uniform_words_read(shader);
    std::vector<uint32_t> store(read.empty() ? 0 : read.back() + 1);
    for (size_t i = 0; i < read.size(); ++i) store[read[i]] = key.specialization[i];
    auto specialized = std::make_unique<SpecializedShader>();
    specialized->shader = std::make_unique<ir::Shader>(shader);
    const uint32_t approximated = key.precision == Precision::Fast ? key.fast_ops : 0;
    if (!ir::specialize(*specialized->shader, store, approximated).empty()) *specialized->shader = shader;  // a bug: unspecialized
    specialized->code = compile_shader(*specialized->shader, key.backend, key.precision, key.fast_ops, key.avx2,
                                       seconds, key.quick_codegen);
    return specialized;
}

// Called with the lock held.
const CompiledShader& BackendCache::compile_now(const ir::Shader& shader, const Key& key) {
    std::unique_ptr<CompiledShader>& slot = shaders_[key];
    if (!slot) {
        double seconds = 0;
        slot = compile(shader, key, &seconds);
        jit_compile_seconds_ += seconds;
    }
    return *slot;
}

const CompiledShader& BackendCache::get(const ir::Shader& shader, const Key& key, bool wait) {
    std::unique_lock lock(mutex_);
    return get_locked(lock, shader, key, wait);
}

const CompiledShader& BackendCache::get_locked(std::unique_lock<std::mutex>& lock, const ir::Shader& shader,
                                               const Key& key, bool wait) {
    if (auto found = shaders_.find(key); found != shaders_.end() && found->second) return *found->second;
    if (key.backend != Backend::Jit) return compile_now(shader, key);
    if (compiling_[key]) {
        if (wait) {
            compiled_.wait(lock, [&] { return shaders_[key] != nullptr; });
            return *shaders_[key];
        }
    } else if (!wait) {
        try {
            threads_.emplace_back([this, &shader, key] {
                double seconds = 0;
                auto code = compile(shader, key, &seconds);
                std::lock_guard done(mutex_);
                shaders_[key] = std::move(code);
                jit_compile_seconds_ += seconds;
                compiled_.notify_all();
            });
            compiling_[key] = true;
        } catch (const std::system_error&) {
            return compile_now(shader, key);  // no thread to be had: compile here
        }
    } else {
        return compile_now(shader, key);
    }
    // Meanwhile: the unspecialized code for a specialized key, the interpreter for that.
    Key fallback = key;
    if (!key.specialization.empty()) fallback.specialization.clear();
    else fallback.backend = Backend::Interp;
    return get_locked(lock, shader, fallback, false);
}

std::vector<uint32_t> BackendCache::specialization(const ir::Shader& shader, const std::vector<uint32_t>& store,
                                                   uint64_t use, uint32_t after) {
    std::lock_guard lock(mutex_);
    Streak& streak = streaks_[size_t(shader.stage)];
    if (!streak.surveyed) streak.read = ir::uniform_words_read(shader), streak.surveyed = true;
    if (streak.read.empty() || after == 0) return {};
    std::vector<uint32_t> words;
    for (uint32_t w : streak.read) words.push_back(w < store.size() ? store[w] : 0);
    if (words != streak.words) {
        streak.words = words;
        streak.draws = 1;
    } else if (use != streak.last_use) {
        ++streak.draws;
    }
    streak.last_use = use;
    return streak.draws >= after ? words : std::vector<uint32_t>{};
}

double BackendCache::jit_compile_seconds() const {
    std::lock_guard lock(mutex_);
    return jit_compile_seconds_;
}

std::unique_ptr<Executor> make_executor(const Program& program, ir::Stage stage,
                                        const GLState::TextureUnit* textures, DrawBudget* budget) {
    const Program::State& st = state_of(program);
    const ir::Shader& shader = stage == ir::Stage::Vertex ? st.ir.vertex : st.ir.fragment;
    ExecParams params{st.uniforms.data(), RunLimits(program.exec), textures, program.exec.precision,
                      st.fast_ops};
    params.limits.draw = budget;
    if (budget) params.limits.cancel = nullptr;  // the budget polls it
    BackendCache::Key key{stage, effective_backend(program.exec.backend, params.precision), params.precision,
                          params.fast_ops, cpu_has_avx2(), program.exec.jit_quick_codegen};
    if (key.backend == Backend::Jit)
        key.specialization = st.backends->specialization(shader, st.uniforms, st.uses, program.exec.jit_specialize_after);
    return st.backends->get(shader, key, program.exec.backend == Backend::Jit).instantiate(params);
}

}  // namespace glslrun::rt
