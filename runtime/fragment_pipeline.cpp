// The caches of fused fragment pipelines (runtime/fragment_pipeline.h).
#include "runtime/fragment_pipeline.h"

#include <system_error>
#include <utility>

#ifdef GLSLRUN_HAVE_JIT
#include "runtime/jit/engine.h"
#endif

namespace glslrun::rt {

namespace {

#ifdef GLSLRUN_HAVE_JIT
// A pipeline's code depends on its key and layout alone, not on the program,
// so the process keeps one per key for every program: piglit's 4,800
// programs share a few hundred (each is LLVM codegen of about 10 ms, which
// the suite paid per program). Kept while the process lives, as the LLJIT
// that holds them (runtime/jit/engine.h) is. *seconds: LLVM's time, 0 when
// the pipeline was there.
const FragmentPipeline* process_pipeline(const PipelineKey& key, const PrimitiveLayout& layout, double* seconds) {
    static std::mutex mutex;
    static auto* const table = new std::map<std::pair<PipelineKey, PrimitiveLayout>, std::unique_ptr<FragmentPipeline>>;
    std::lock_guard hold(mutex);
    auto [entry, added] = table->try_emplace({key, layout});
    if (added) entry->second = jit::compile_pipeline(key, layout, seconds);
    return entry->second.get();
}
#endif

}  // namespace

PipelineCache::~PipelineCache() {
    for (std::thread& t : threads_) t.join();
}

const FragmentPipeline* PipelineCache::get(const PipelineKey& key, const PrimitiveLayout& layout, bool wait) {
#ifdef GLSLRUN_HAVE_JIT
    if (unfused_.load(std::memory_order_relaxed) < kPipelineAfterFragments) return nullptr;
    std::unique_lock lock(mutex_);
    auto compile = [this, key, layout] {
        double seconds = 0;
        const FragmentPipeline* code = process_pipeline(key, layout, &seconds);
        std::lock_guard done(mutex_);
        pipelines_[key] = code;
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
    return done_[key] ? pipelines_[key] : nullptr;
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
