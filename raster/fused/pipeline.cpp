// The per-program cache of fused fragment pipelines (raster/fused/pipeline.h).
#include "raster/fused/pipeline.h"

#include "runtime/code_cache.h"
#include "runtime/jit_plugin.h"

namespace glslrun::raster::fused {

// When a pipeline is due is this policy's; how it is made and kept,
// runtime/tiering.h's.
const Pipeline* Cache::get(const State& state, bool wait, const ExecOptions& options) {
    if (!fusable(state) || unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    const rt::JitEntryPoints* jit = rt::jit_plugin();
    if (!jit) return nullptr;
    const std::string key = state_key(state);
    auto compile = [state, jit, config = rt::code_cache_config(options)](const std::atomic<bool>*) {
        PipelineCompile done{&config};
        Slots::Made made;
        made.code = jit->compile_pipeline(state, &done);
        made.seconds = done.seconds;
        made.loaded = done.loaded;
        return made;
    };
    // Backend::Jit: compiled here where it is not yet, rather than wait
    // behind other programs' compiles.
    if (wait) return slots_->get(key, compile);
    slots_->queue(key, compile);
    return slots_->ready(key);
}

}  // namespace glslrun::raster::fused
