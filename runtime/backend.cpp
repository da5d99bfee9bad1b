// The backend factory and the per-program cache of compiled shaders.
#include "runtime/backend.h"

#include <map>
#include <mutex>
#include <tuple>

#include "runtime/backend_cache.h"
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

double Program::jit_compile_seconds() const { return state_->backends->jit_compile_seconds(); }

}  // namespace glslrun

namespace glslrun::rt {

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

const CompiledShader& BackendCache::get(const ir::Shader& shader, const Key& key) {
    std::lock_guard lock(mutex_);
    std::unique_ptr<CompiledShader>& slot = shaders_[key];
    if (slot) return *slot;
#ifdef GLSLRUN_HAVE_JIT
    if (key.backend == Backend::Jit) {
        jit::CompileStats stats;
        slot = jit::compile(shader, key.precision, key.fast_ops, key.avx2, &stats);
        if (slot) {
            jit_compile_seconds_ += stats.seconds;
            return *slot;
        }
        // LLVM could not compile it (jit::compile says why in debug builds):
        // the interpreter computes the same bits.
    }
#endif
    slot = std::make_unique<InterpretedShader>(shader);
    return *slot;
}

double BackendCache::jit_compile_seconds() const {
    std::lock_guard lock(mutex_);
    return jit_compile_seconds_;
}

std::unique_ptr<Executor> make_executor(const Program& program, ir::Stage stage,
                                        const GLState::TextureUnit* textures) {
    const Program::State& st = program.state();
    const ir::Shader& shader = stage == ir::Stage::Vertex ? st.ir.vertex : st.ir.fragment;
    ExecParams params{st.uniforms.data(), program.exec.max_loop_iterations, textures, program.exec.precision,
                      st.fast_ops};
    BackendCache::Key key{stage, effective_backend(program.exec.backend, params.precision), params.precision,
                          params.fast_ops, cpu_has_avx2()};
    return st.backends->get(shader, key).instantiate(params);
}

}  // namespace glslrun::rt
