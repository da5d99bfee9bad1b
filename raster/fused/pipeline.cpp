// The per-program cache of fused fragment pipelines (raster/fused/pipeline.h).
#include "raster/fused/pipeline.h"

#include "runtime/code_cache.h"
#include "runtime/jit_plugin.h"

namespace glslrun::raster::fused {

// When a pipeline is due is this policy's; how it is made and kept,
// runtime/tiering.h's.
// `state`'s pipeline, its inputs function shared through `shelf` with the
// program's other states; with `load_only`, only from the code cache.
Cache::Slots::Made Cache::make(const rt::JitEntryPoints& jit, const State& state, const rt::CodeCacheConfig& config,
                               Inputs& shelf, bool load_only) {
    const std::string inputs_key = state_key(inputs_only(state));
    PipelineCompile done;
    done.cache = &config;
    done.load_only = load_only;
    {
        std::lock_guard hold(shelf.lock);
        auto found = shelf.made.find(inputs_key);
        if (found != shelf.made.end()) done.inputs = found->second;
    }
    Slots::Made made;
    made.code = jit.compile_pipeline(state, &done);
    if (made.code) {
        std::lock_guard hold(shelf.lock);
        shelf.made.emplace(inputs_key, done.inputs);
    }
    made.seconds = done.seconds;
    made.loaded = done.loaded;
    return made;
}

// Before a pipeline is due, the code cache's copy: loading it costs no LLVM
// time, so there is nothing to save back first (skinning's 1080p frames,
// 100,000 fragments each, took the C++ path for their first ten). One look
// per key; callers wait for it rather than look again.
const Pipeline* Cache::cached(const std::string& key, const State& state, const ExecOptions& options) {
    if (const Pipeline* ready = slots_->ready(key)) return ready;
    std::lock_guard hold(probed_->lock);
    if (!probed_->keys.insert(key).second) return slots_->ready(key);
    const rt::JitEntryPoints* jit = rt::jit_plugin();
    const rt::CodeCacheConfig config = rt::code_cache_config(options);
    if (!jit || config.dir.empty()) return nullptr;
    Slots::Made made = make(*jit, state, config, *inputs_, true);
    if (!made.code) return nullptr;
    slots_->put(key, std::move(made));
    return slots_->ready(key);
}

const Pipeline* Cache::get(const State& state, bool wait, const ExecOptions& options) {
    if (!fusable(state)) return nullptr;
    if (unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments)
        return cached(state_key(state), state, options);
    const rt::JitEntryPoints* jit = rt::jit_plugin();
    if (!jit) return nullptr;
    const std::string key = state_key(state);
    auto compile = [state, jit, config = rt::code_cache_config(options), shelf = inputs_](const std::atomic<bool>*) {
        return make(*jit, state, config, *shelf, false);
    };
    // Backend::Jit: compiled here where it is not yet, rather than wait
    // behind other programs' compiles.
    if (wait) return slots_->get(key, compile);
    slots_->queue(key, compile);
    return slots_->ready(key);
}

}  // namespace glslrun::raster::fused
