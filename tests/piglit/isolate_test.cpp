// Crash and hang isolation of single tests.
#include <catch2/catch.hpp>

#include <csignal>
#include <fstream>
#include <string>
#include <thread>

#include <unistd.h>

#include "tools/glslrun/piglit_exec.h"
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

// The threads of this process, from /proc/self/status.
static int thread_count() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
    return -1;
}

TEST_CASE("parallel isolated runs keep their own results, reported in order", "[piglit][isolate]") {
    std::vector<size_t> order;
    std::vector<int> threads_at_report;
    // Earlier test cases may have left threads of their own (a render's
    // background compile thread): the runner must add none.
    const int threads_before = thread_count();
    auto results = run_isolated_tests(24, 6, [](size_t i) {
        if (i % 5 == 4) std::raise(SIGSEGV);
        if (i % 7 == 3) std::this_thread::sleep_for(std::chrono::seconds(30));
        // Later tests end first: the reports must still come in order.
        std::this_thread::sleep_for(std::chrono::milliseconds(10 * (24 - i)));
        return TestResult{Outcome::Pass, "r" + std::to_string(i)};
    }, 2, [&](size_t i, const TestResult&) {
        order.push_back(i);
        threads_at_report.push_back(thread_count());
    });
    for (size_t i = 0; i < 24; ++i) {
        INFO(i);
        CHECK(order[i] == i);
        // Children are forked from this thread alone: no thread of the runner
        // may be allocating at a fork (#17: an ASan child hung on its lock).
        CHECK(threads_at_report[i] <= threads_before);
        if (i % 5 == 4) CHECK(results[i].message == "crashed: signal 11 (SIGSEGV)");
        else if (i % 7 == 3) CHECK(results[i].message == "timed out after 2 s");
        else CHECK(results[i].message == "r" + std::to_string(i));
    }
}

TEST_CASE("children of a warmed-up runner give the same results as in-process runs", "[piglit][isolate]") {
    // glslrun test compiles before it forks (warm_up_compiler), so children
    // inherit glslang's built-in tables and LLVM's engine; results must not depend on it.
    const std::string vs = "[vertex shader]\nvoid main() { gl_Position = gl_Vertex; }\n";
    const std::string fs110 = "[fragment shader]\nuniform vec4 c;\nvoid main() { gl_FragColor = c; }\n";
    const std::string fs120 =
        "[fragment shader]\n#version 120\nuniform vec4 c;\nvoid main() { vec4 a[2] = vec4[2](c, c); gl_FragColor = a[1]; }\n";
    const std::string draw = "[test]\nuniform vec4 c 0.0 1.0 0.0 1.0\ndraw rect -1 -1 2 2\n";
    const std::vector<std::pair<std::string, Outcome>> tests = {
        {"[require]\nGLSL >= 1.10\n\n" + vs + fs110 + draw + "probe all rgba 0 1 0 1\n", Outcome::Pass},
        {"[require]\nGLSL >= 1.20\n\n" + vs + fs120 + draw + "probe all rgba 0 1 0 1\n", Outcome::Pass},
        {"[require]\nGLSL >= 1.10\n\n" + vs + fs110 + draw + "probe rgb 3 4 1 0 0\n", Outcome::Fail},
        {"[require]\nGLSL >= 1.10\n\n" + vs + "[fragment shader]\nvoid main() { gl_FragColor = x; }\n" + draw,
         Outcome::Fail},
    };
    warm_up_compiler(glslrun::Backend::Jit);  // glslang's tables and LLVM's engine
    for (const auto& test : tests) {
        // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
        const std::string& text = test.first;
        const Outcome expected = test.second;
        TestResult in_process = run_shader_test(text, ".", RunOptions{});
        TestResult child = run_isolated([&] { return run_shader_test(text, ".", RunOptions{}); }, 30);
        INFO(text << "\nin process: " << in_process.message << "\nchild: " << child.message);
        CHECK(in_process.outcome == expected);
        CHECK(child.outcome == in_process.outcome);
        CHECK(child.message == in_process.message);
    }
}

TEST_CASE("a runner whose stdin and stdout are closed still isolates its tests", "[piglit][isolate]") {
    // The pipe then gets descriptors 0 and 1; its write end must move above stdio.
    int saved_in = ::dup(0), saved_out = ::dup(1);
    REQUIRE(saved_in >= 0);
    REQUIRE(saved_out >= 0);
    ::close(0);
    ::close(1);
    TestResult r = run_isolated([] { return TestResult{Outcome::Pass, std::to_string(::getpid())}; }, 10);
    ::dup2(saved_in, 0);
    ::dup2(saved_out, 1);
    ::close(saved_in);
    ::close(saved_out);
    CHECK(r.outcome == Outcome::Pass);
    CHECK(r.message != std::to_string(::getpid()));  // it ran in a child
}
