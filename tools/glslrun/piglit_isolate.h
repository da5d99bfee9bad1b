// Runs one test in a forked child process, so that a crash (a bug in
// glslrun, not in the test) or a hang inside a draw becomes one failed test
// instead of the end of the whole suite run.
#pragma once
#include <functional>

#include "piglit_suite.h"

namespace glslrun::piglit {

// Forks; the child runs `fn` and sends its result back through a pipe. A child
// that dies from a signal or exits without a result gives a failure naming the
// cause; one that runs longer than `timeout_s` is killed and fails.
// If fork() keeps failing, the test fails with the reason and `fn` does not
// run here: other threads are forking children at the same time, and a lock
// this process held at one of those forks would hang that child.
TestResult run_isolated(const std::function<TestResult()>& fn, double timeout_s);

}  // namespace glslrun::piglit
