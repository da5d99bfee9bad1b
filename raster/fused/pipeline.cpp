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
    auto compile = [state, jit, config = rt::code_cache_config(options), shelf = inputs_](const std::atomic<bool>*) {
        const std::string inputs_key = state_key(inputs_only(state));
        PipelineCompile done;
        done.cache = &config;
        {
            std::lock_guard hold(shelf->lock);
            auto found = shelf->made.find(inputs_key);
            if (found != shelf->made.end()) done.inputs = found->second;
        }
        Slots::Made made;
        made.code = jit->compile_pipeline(state, &done);
        if (made.code) {
            std::lock_guard hold(shelf->lock);
            shelf->made.emplace(inputs_key, done.inputs);
        }
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
