// The per-program cache of fused fragment pipelines (runtime/fragment_pipeline.h).
#include "runtime/fragment_pipeline.h"

#include <system_error>

#ifdef GLSLRUN_HAVE_JIT
#include "runtime/jit/engine.h"
#endif

namespace glslrun::rt {

PipelineCache::~PipelineCache() {
    for (std::thread& t : threads_) t.join();
}

const FragmentPipeline* PipelineCache::get(const PipelineKey& key, const PrimitiveLayout& layout, bool wait) {
#ifdef GLSLRUN_HAVE_JIT
    if (unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    std::unique_lock lock(mutex_);
    auto compile = [this, key, layout] {
        double seconds = 0;
        std::unique_ptr<FragmentPipeline> code = jit::compile_pipeline(key, layout, &seconds);
        std::lock_guard done(mutex_);
        pipelines_[key] = std::move(code);
        done_[key] = true;
        compile_seconds_ += seconds;
        compiled_.notify_all();
    };
    if (auto found = done_.find(key); found == done_.end()) {
        done_[key] = false;
        if (wait) {
            lock.unlock();
            compile();
            lock.lock();
        } else {
            try {
                threads_.emplace_back(compile);
            } catch (const std::system_error&) {
                lock.unlock();
                compile();  // no thread to be had: compile here
                lock.lock();
            }
        }
    }
    if (wait) compiled_.wait(lock, [&] { return done_[key]; });
    return done_[key] ? pipelines_[key].get() : nullptr;
#else
    (void)key, (void)layout, (void)wait;
    return nullptr;
#endif
}

double PipelineCache::compile_seconds() const {
    std::lock_guard lock(mutex_);
    return compile_seconds_;
}

}  // namespace glslrun::rt
