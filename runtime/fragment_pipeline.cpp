// The per-program cache of fused fragment pipelines (runtime/fragment_pipeline.h).
#include "runtime/fragment_pipeline.h"

#include "runtime/compile_queue.h"
#include "runtime/jit_plugin.h"

namespace glslrun::rt {

void PipelineCache::store(const PipelineKey& key, std::unique_ptr<FragmentPipeline>& code, double seconds) {
    compile_seconds_ += seconds;
    if (done_[key]) return;  // compiled twice (Backend::Jit did not wait): draws may hold the first
    pipelines_[key] = std::move(code);
    done_[key] = true;
}

const FragmentPipeline* PipelineCache::get(const PipelineKey& key, const PrimitiveLayout& layout, bool wait) {
    if (unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    const JitEntryPoints* jit = jit_plugin();
    if (!jit) return nullptr;
    std::unique_lock lock(mutex_);
    auto compile_here = [&] {
        lock.unlock();
        double seconds = 0;
        std::unique_ptr<FragmentPipeline> code = jit->compile_pipeline(key, layout, &seconds);
        lock.lock();
        store(key, code, seconds);
    };
    if (auto found = done_.find(key); found == done_.end()) {
        done_[key] = false;
        std::weak_ptr<PipelineCache> self = weak_from_this();
        auto job = [self, key, layout, jit] {
            if (self.expired() || compiles_stopping().load()) return;  // the program is gone, or the process
            double seconds = 0;
            std::unique_ptr<FragmentPipeline> code = jit->compile_pipeline(key, layout, &seconds);
            if (std::shared_ptr<PipelineCache> cache = self.lock()) {
                std::lock_guard done(cache->mutex_);
                cache->store(key, code, seconds);
            }
        };
        if (wait || self.expired() || !submit_compile(job)) compile_here();
    }
    // Backend::Jit asked after Auto had queued it: compile it here rather
    // than wait behind other programs' compiles.
    if (wait && !done_[key]) compile_here();
    return done_[key] ? pipelines_[key].get() : nullptr;
}

double PipelineCache::compile_seconds() const {
    std::lock_guard lock(mutex_);
    return compile_seconds_;
}

}  // namespace glslrun::rt
