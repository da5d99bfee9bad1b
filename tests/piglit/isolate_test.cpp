// Crash and hang isolation of single tests.
#include <catch2/catch.hpp>

#include <csignal>
#include <thread>

#include "tools/glslrun/piglit_isolate.h"

using namespace glslrun::piglit;

TEST_CASE("a child's result comes back whole", "[piglit][isolate]") {
    std::string long_message(200000, 'x');  // more than a pipe buffer
    long_message += "end";
    TestResult r = run_isolated([&] { return TestResult{Outcome::Skip, long_message}; }, 10);
    CHECK(r.outcome == Outcome::Skip);
    CHECK(r.message == long_message);
    r = run_isolated([] { return TestResult{Outcome::Pass, ""}; }, 10);
    CHECK(r.outcome == Outcome::Pass);
    CHECK(r.message.empty());
    r = run_isolated([] { return TestResult{Outcome::Fail, "line 3: probe\nsecond line"}; }, 10);
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "line 3: probe\nsecond line");
}

TEST_CASE("a crash fails only that test", "[piglit][isolate]") {
    TestResult r = run_isolated([]() -> TestResult { std::raise(SIGSEGV); return {}; }, 10);
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "crashed: signal 11 (SIGSEGV)");
    r = run_isolated([]() -> TestResult { std::abort(); }, 10);
    CHECK(r.message == "crashed: signal 6 (SIGABRT)");
    r = run_isolated([]() -> TestResult { throw std::runtime_error("oops"); }, 10);
    CHECK(r.message == "internal error: oops");
}

TEST_CASE("a hang is killed at the time limit", "[piglit][isolate]") {
    auto start = std::chrono::steady_clock::now();
    TestResult r = run_isolated([]() -> TestResult {
        std::this_thread::sleep_for(std::chrono::seconds(30));
        return {Outcome::Pass, ""};
    }, 0.5);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.rfind("timed out after", 0) == 0);
    CHECK(secs < 5);
}

TEST_CASE("parallel isolated runs keep their own results", "[piglit][isolate]") {
    std::vector<TestCase> cases;
    for (int i = 0; i < 24; ++i) cases.push_back({std::to_string(i), std::to_string(i)});
    auto results = run_tests(cases, 6, [](const TestCase& tc) {
        return run_isolated([&] {
            int i = std::stoi(tc.path);
            if (i % 5 == 4) std::raise(SIGSEGV);
            return TestResult{Outcome::Pass, "r" + tc.path};
        }, 10);
    }, nullptr);
    for (int i = 0; i < 24; ++i) {
        if (i % 5 == 4) CHECK(results[i].message == "crashed: signal 11 (SIGSEGV)");
        else CHECK(results[i].message == "r" + std::to_string(i));
    }
}
