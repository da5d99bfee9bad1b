// The per-program cache of fused fragment pipelines (raster/fused/pipeline.h).
#include "raster/fused/pipeline.h"

#include "runtime/code_cache.h"
#include "runtime/compile_queue.h"
#include "runtime/jit_plugin.h"

namespace glslrun::raster::fused {

void Cache::store(const std::string& key, std::unique_ptr<Pipeline>& code, const PipelineCompile& made) {
    compile_seconds_ += made.seconds;
    if (code) ++(made.loaded ? counts_.loaded : counts_.compiled);
    if (done_[key]) return;  // compiled twice (Backend::Jit did not wait): draws may hold the first
    pipelines_[key] = std::move(code);
    done_[key] = true;
}

const Pipeline* Cache::get(const State& state, bool wait, const ExecOptions& options) {
    if (!fusable(state) || unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    const rt::JitEntryPoints* jit = rt::jit_plugin();
    if (!jit) return nullptr;
    const std::string key = state_key(state);
    std::unique_lock lock(mutex_);
    auto compile_here = [&] {
        lock.unlock();
        const rt::CodeCacheConfig config = rt::code_cache_config(options);
        PipelineCompile made{&config};
        std::unique_ptr<Pipeline> code = jit->compile_pipeline(state, &made);
        lock.lock();
        store(key, code, made);
    };
    if (auto found = done_.find(key); found == done_.end()) {
        done_[key] = false;
        std::weak_ptr<Cache> self = weak_from_this();
        auto job = [self, key, state, jit, config = rt::code_cache_config(options)] {
            if (self.expired() || rt::compiles_stopping().load()) return;  // the program is gone, or the process
            PipelineCompile made{&config};
            std::unique_ptr<Pipeline> code = jit->compile_pipeline(state, &made);
            if (std::shared_ptr<Cache> cache = self.lock()) {
                std::lock_guard done(cache->mutex_);
                cache->store(key, code, made);
            }
        };
        if (wait || self.expired() || !rt::submit_compile(job)) compile_here();
    }
    // Backend::Jit asked after Auto had queued it: compile it here rather
    // than wait behind other programs' compiles.
    if (wait && !done_[key]) compile_here();
    return done_[key] ? pipelines_[key].get() : nullptr;
}

Cache::Counts Cache::counts() const {
    std::lock_guard lock(mutex_);
    return counts_;
}

double Cache::compile_seconds() const {
    std::lock_guard lock(mutex_);
    return compile_seconds_;
}

}  // namespace glslrun::raster::fused
