// The process-wide compile queue (runtime/compile_queue.h).
#include "runtime/compile_queue.h"

#include "glslrun/glslrun.h"

#include <pthread.h>

#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>

namespace glslrun::rt {

namespace {

// Made at the first submit and never destroyed: its thread may still be
// blocked on it while the process exits (a joined thread would make exit
// wait). The exit handler empties it and waits for the running job, which
// gives up at its next phase, so that no compile runs on while static
// destructors do.
class Queue {
public:
    static Queue& get() {
        static Queue* queue = new Queue;
        return *queue;
    }

    // A forked child (the piglit runner isolates tests so) has no compile
    // thread: it starts its own, with nothing queued or running.
    Queue() {
        ::pthread_atfork([] { get().mutex_.lock(); }, [] { get().mutex_.unlock(); },
                         [] {
                             Queue& q = get();
                             new (&q.mutex_) std::mutex;
                             new (&q.ready_) std::condition_variable;
                             new (&q.idle_) std::condition_variable;
                             q.jobs_.clear();
                             q.started_ = q.running_ = false;
                         });
    }

    bool submit(std::function<void()> job) {
        std::lock_guard lock(mutex_);
        if (stopping_.load()) return true;  // exiting: nothing will use it
        if (!started_) {
            try {
                std::thread(&Queue::work, this).detach();
            } catch (const std::system_error&) {
                return false;
            }
            started_ = true;
            stop_compiles_before_exit();
        }
        jobs_.push_back(std::move(job));
        ready_.notify_one();
        return true;
    }

    const std::atomic<bool>& stopping() const { return stopping_; }

    // Idempotent: the queue is empty and nothing runs once it returns.
    void stop() {
        std::unique_lock lock(mutex_);
        stopping_.store(true);
        jobs_.clear();
        idle_.wait(lock, [&] { return !running_; });
    }

    size_t pending() {
        std::lock_guard lock(mutex_);
        return jobs_.size() + (running_ ? 1 : 0);
    }

private:
    void work() {
        std::unique_lock lock(mutex_);
        for (;;) {
            ready_.wait(lock, [&] { return !jobs_.empty(); });
            std::function<void()> job = std::move(jobs_.front());
            jobs_.pop_front();
            running_ = true;
            lock.unlock();
            try {
                job();
            } catch (...) {
                // Out of memory, most likely: the code stays uncompiled and
                // the interpreter keeps serving, with the same bits.
            }
            job = nullptr;  // what it held goes before the next one starts
            lock.lock();
            running_ = false;
            idle_.notify_all();
        }
    }

    std::mutex mutex_;
    std::condition_variable ready_, idle_;
    std::deque<std::function<void()>> jobs_;
    bool started_ = false, running_ = false;
    std::atomic<bool> stopping_{false};
};

}  // namespace

bool submit_compile(std::function<void()> job) { return Queue::get().submit(std::move(job)); }

const std::atomic<bool>& compiles_stopping() { return Queue::get().stopping(); }

size_t compiles_pending() { return Queue::get().pending(); }

void stop_compiles_before_exit() {
    std::atexit([] { Queue::get().stop(); });
}

}  // namespace glslrun::rt

namespace glslrun {

void stop_background_compiles() { rt::Queue::get().stop(); }

}  // namespace glslrun
