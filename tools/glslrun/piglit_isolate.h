// Runs each test in a forked child process, so that a crash (a bug in
// glslrun, not in the test) or a hang inside a draw becomes one failed test
// instead of the end of the whole suite run.
#pragma once
#include <functional>
#include <vector>

#include "piglit_suite.h"

namespace glslrun::piglit {

// Runs tests 0 to count - 1, each in a child forked from the calling thread,
// at most `jobs` at a time; `report` is called as run_tests' is. Each child
// runs `fn(index)` and sends its result back through a pipe. A child that dies
// from a signal or exits without a result gives a failure naming the cause; one
// that runs longer than `timeout_s` is killed and fails. If fork() keeps
// failing, the test fails with the reason.
//
// The caller must have no other threads: a child inherits only the forking
// thread, so a lock another thread held at the fork (the sanitizers'
// allocator takes no care of this) would stay locked in the child and hang it.
// That is why the children are watched from this one thread, not from a
// pool of workers.
using IsolatedTest = std::function<TestResult(size_t index)>;
std::vector<TestResult> run_isolated_tests(size_t count, int jobs, const IsolatedTest& fn, double timeout_s,
                                           const Report& report);

// One test, as above.
TestResult run_isolated(const std::function<TestResult()>& fn, double timeout_s);

}  // namespace glslrun::piglit
