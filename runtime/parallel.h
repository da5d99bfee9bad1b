// Worker threads for draw(): a queue of numbered jobs that reports the first
// failure by job number (so errors do not depend on the thread count), and a
// helper that runs workers on threads owned by the caller's scope.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <type_traits>
#include <vector>

#include <pthread.h>
#include <sched.h>

namespace glslrun::rt {

// More workers than this never help and only cost memory.
inline constexpr unsigned kMaxThreads = 256;

// ExecOptions::threads (0: one per core), at most one per job.
inline unsigned thread_count(unsigned requested, size_t jobs) {
    unsigned n = requested ? requested : std::max(1u, std::thread::hardware_concurrency());
    return unsigned(std::clamp<size_t>(std::min<size_t>(n, kMaxThreads), 1, std::max<size_t>(jobs, 1)));
}

// Jobs [0, count), handed out in increasing order. After a failure at job i
// the jobs past i are skipped, while those before it still run, so the first
// failing job is the same whatever the number of workers.
class JobQueue {
public:
    explicit JobQueue(size_t count) : count_(count) {}
    bool next(size_t* job) {
        for (size_t i; (i = next_.fetch_add(1)) < count_;) {
            if (i < failed_.load()) {
                *job = i;
                return true;
            }
        }
        return false;
    }
    void fail(size_t job) {
        size_t seen = failed_.load();
        while (job < seen && !failed_.compare_exchange_weak(seen, job)) {}
    }
    std::optional<size_t> first_failure() const {
        size_t f = failed_.load();
        return f == SIZE_MAX ? std::nullopt : std::optional<size_t>(f);
    }

private:
    size_t count_;
    std::atomic<size_t> next_{0}, failed_{SIZE_MAX};
};

// Threads started by one thread, joined when this goes out of scope.
// Linux (6.18 on the machine of docs/performance.md) often starts a new
// thread on its creator's CPU, where it waits for the creator's time slice
// (about 3 ms) while other CPUs idle: a draw's workers then ran one after
// the other. So each thread starts on the other CPUs the creator may use,
// and takes the creator's CPU set back as soon as it runs.
class WorkerThreads {
public:
    WorkerThreads() = default;
    WorkerThreads(const WorkerThreads&) = delete;
    WorkerThreads& operator=(const WorkerThreads&) = delete;
    ~WorkerThreads();
    // Runs entry(arg) on a new thread; false when none could be started.
    bool start(void (*entry)(void*), void* arg);

    struct Thread {
        void (*entry)(void*);
        void* arg;
        const cpu_set_t* restore;  // the creator's CPU set, or null
        pthread_t id;
    };

private:
    void find_other_cpus();

    std::vector<std::unique_ptr<Thread>> threads_;
    bool looked_ = false, elsewhere_ok_ = false;
    cpu_set_t inherited_, elsewhere_;
};

// Calls work(k) for k in [0, workers), k = 0 on the calling thread, and
// returns when all are done. When a thread cannot be started the others do
// its share, so `work` must take its jobs from a shared JobQueue. An
// exception of any worker (std::bad_alloc) reaches the caller once all are
// done, instead of std::terminate on the worker's thread.
template <class Work>
void run_workers(unsigned workers, Work&& work) {
    using Fn = std::remove_reference_t<Work>;
    struct Call {
        Fn* work;
        unsigned k;
        std::exception_ptr error;
    };
    std::vector<Call> calls;
    calls.reserve(workers);  // the threads hold pointers into it
    std::exception_ptr error;
    {
        WorkerThreads threads;  // joined at the end of this scope, before `calls` is read
        for (unsigned k = 1; k < workers; ++k) {
            calls.push_back({&work, k, nullptr});
            auto entry = [](void* p) {
                auto* call = static_cast<Call*>(p);
                try {
                    (*call->work)(call->k);
                } catch (...) {
                    call->error = std::current_exception();
                }
            };
            if (!threads.start(entry, &calls.back())) break;
        }
        try {
            work(0u);
        } catch (...) {
            error = std::current_exception();
        }
    }
    for (const Call& call : calls)
        if (!error) error = call.error;
    if (error) std::rethrow_exception(error);
}

}  // namespace glslrun::rt
