// run_workers: every worker index runs once, each thread on its own, and a
// thread started away from its creator's CPU (runtime/parallel.h) runs with
// its creator's CPU set once it starts, so pinning a process still holds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include <sched.h>

#include "runtime/parallel.h"

using namespace glslrun;

TEST_CASE("run_workers calls each worker index once", "[parallel]") {
    for (unsigned workers : {1u, 2u, 3u, 9u}) {
        std::vector<std::atomic<int>> calls(workers);
        std::mutex m;
        std::vector<std::thread::id> ids;
        rt::run_workers(workers, [&](unsigned k) {
            calls[k].fetch_add(1);
            std::lock_guard lock(m);
            ids.push_back(std::this_thread::get_id());
        });
        for (unsigned k = 0; k < workers; ++k) CHECK(calls[k].load() == 1);
        std::sort(ids.begin(), ids.end());
        CHECK(std::unique(ids.begin(), ids.end()) == ids.end());
    }
}

TEST_CASE("worker threads run with their creator's CPU set", "[parallel]") {
    cpu_set_t creator;
    REQUIRE(sched_getaffinity(0, sizeof(cpu_set_t), &creator) == 0);
    std::vector<cpu_set_t> seen(4);
    std::vector<int> ok(4, 0);
    rt::run_workers(4, [&](unsigned k) { ok[k] = sched_getaffinity(0, sizeof(cpu_set_t), &seen[k]) == 0; });
    for (unsigned k = 0; k < 4; ++k) {
        REQUIRE(ok[k]);
        CHECK(CPU_EQUAL(&seen[k], &creator));
    }
}
