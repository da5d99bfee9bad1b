// The per-program cache of fused fragment pipelines (raster/fused/pipeline.h).
#include "raster/fused/pipeline.h"

#include "runtime/compile_queue.h"
#include "runtime/jit_plugin.h"

namespace glslrun::raster::fused {

void Cache::store(const std::string& key, std::unique_ptr<Pipeline>& code, double seconds) {
    compile_seconds_ += seconds;
    if (done_[key]) return;  // compiled twice (Backend::Jit did not wait): draws may hold the first
    pipelines_[key] = std::move(code);
    done_[key] = true;
}

const Pipeline* Cache::get(const State& state, bool wait) {
    if (!fusable(state) || unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    const rt::JitEntryPoints* jit = rt::jit_plugin();
    if (!jit) return nullptr;
    const std::string key = state_key(state);
    std::unique_lock lock(mutex_);
    auto compile_here = [&] {
        lock.unlock();
        double seconds = 0;
        std::unique_ptr<Pipeline> code = jit->compile_pipeline(state, &seconds);
        lock.lock();
        store(key, code, seconds);
    };
    if (auto found = done_.find(key); found == done_.end()) {
        done_[key] = false;
        std::weak_ptr<Cache> self = weak_from_this();
        auto job = [self, key, state, jit] {
            if (self.expired() || rt::compiles_stopping().load()) return;  // the program is gone, or the process
            double seconds = 0;
            std::unique_ptr<Pipeline> code = jit->compile_pipeline(state, &seconds);
            if (std::shared_ptr<Cache> cache = self.lock()) {
                std::lock_guard done(cache->mutex_);
                cache->store(key, code, seconds);
            }
        };
        if (wait || self.expired() || !rt::submit_compile(job)) compile_here();
    }
    // Backend::Jit asked after Auto had queued it: compile it here rather
    // than wait behind other programs' compiles.
    if (wait && !done_[key]) compile_here();
    return done_[key] ? pipelines_[key].get() : nullptr;
}

double Cache::compile_seconds() const {
    std::lock_guard lock(mutex_);
    return compile_seconds_;
}

}  // namespace glslrun::raster::fused
