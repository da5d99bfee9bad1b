// Worker threads for draw(): a queue of numbered jobs that reports the first
// failure by job number (so errors do not depend on the thread count), and a
// helper that runs workers on std::threads owned by the caller's scope.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

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

// Calls work(k) for k in [0, workers), k = 0 on the calling thread, and
// returns when all are done. When a thread cannot be started the others do
// its share, so `work` must take its jobs from a shared JobQueue.
template <class Work>
void run_workers(unsigned workers, Work&& work) {
    std::vector<std::jthread> threads;
    for (unsigned k = 1; k < workers; ++k) {
        try {
            threads.emplace_back([&work, k] { work(k); });
        } catch (const std::system_error&) {
            break;
        }
    }
    work(0u);
}

}  // namespace glslrun::rt
