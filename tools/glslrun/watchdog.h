// A wall-clock limit for work that polls a flag (ExecOptions::cancel): the
// flag is set once `seconds` have passed, unless the Watchdog is destroyed
// first. `glslrun test --no-isolate` limits each test with one, and
// `glslrun serve` each trace and NaN search (whose replays poll `cancel`).
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stop_token>
#include <thread>

namespace glslrun::cli {

class Watchdog {
public:
    explicit Watchdog(double seconds)
        : thread_([this, seconds](std::stop_token stop) {
              std::mutex m;
              std::unique_lock lock(m);
              std::condition_variable_any cv;
              cv.wait_for(lock, stop, std::chrono::duration<double>(seconds), [] { return false; });
              if (!stop.stop_requested()) fired_ = true;
          }) {}
    const std::atomic<bool>* flag() const { return &fired_; }

private:
    std::atomic<bool> fired_{false};
    std::jthread thread_;  // last: it stops and joins before fired_ goes
};

}  // namespace glslrun::cli
