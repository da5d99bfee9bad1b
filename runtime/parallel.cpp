#include "runtime/parallel.h"

#include <cerrno>

namespace glslrun::rt {
namespace {

void* run_thread(void* p) {
    auto* t = static_cast<WorkerThreads::Thread*>(p);
    // Started elsewhere (see WorkerThreads); from now on the scheduler may
    // place it anywhere its creator could run.
    if (t->restore) (void)sched_setaffinity(0, sizeof(cpu_set_t), t->restore);
    t->entry(t->arg);
    return nullptr;
}

}  // namespace

WorkerThreads::~WorkerThreads() {
    for (const auto& t : threads_) pthread_join(t->id, nullptr);
}

// The creator's CPU set, less the CPU it runs on now; none when that leaves
// nothing (pinned to one CPU) or the sets cannot be read.
void WorkerThreads::find_other_cpus() {
    looked_ = true;
    int cpu = sched_getcpu();
    if (cpu < 0 || cpu >= CPU_SETSIZE || sched_getaffinity(0, sizeof(cpu_set_t), &inherited_) != 0) return;
    elsewhere_ = inherited_;
    CPU_CLR(cpu, &elsewhere_);
    elsewhere_ok_ = CPU_COUNT(&elsewhere_) > 0;
}

bool WorkerThreads::start(void (*entry)(void*), void* arg) {
    if (!looked_) find_other_cpus();
    auto t = std::make_unique<Thread>(Thread{entry, arg, elsewhere_ok_ ? &inherited_ : nullptr, {}});
    threads_.reserve(threads_.size() + 1);  // no allocation left to fail once it runs
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return false;
    int rc = EINVAL;
    if (elsewhere_ok_ && pthread_attr_setaffinity_np(&attr, sizeof(cpu_set_t), &elsewhere_) == 0)
        rc = pthread_create(&t->id, &attr, run_thread, t.get());
    if (rc != 0) {  // no placement hint to be had: start it as before
        t->restore = nullptr;
        rc = pthread_create(&t->id, nullptr, run_thread, t.get());
    }
    pthread_attr_destroy(&attr);
    if (rc != 0) return false;
    threads_.push_back(std::move(t));
    return true;
}

}  // namespace glslrun::rt
