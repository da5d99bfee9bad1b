// Running many piglit tests: discovery, parallel execution with a
// deterministic order, the expectations list, and result formatting.
// Knows nothing about how one test runs (that is a callback), so it can be
// unit-tested without the rest of glslrun.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "piglit_parse.h"

namespace glslrun::piglit {

enum class Outcome { Pass, Fail, Skip };
const char* outcome_name(Outcome o);  // "pass", "fail", "skip"

struct TestResult {
    Outcome outcome = Outcome::Pass;
    std::string message;  // why it failed or skipped (may span lines)
    double seconds = 0;
};

struct TestCase {
    std::string path;     // what to open
    std::string display;  // what to print: relative to --root when given
};

// Is this file a test? .shader_test always; .vert/.frag/.geom/... only with a [config] block.
bool is_test_file(const std::string& path);

// Expands files and directories (recursively, sorted) into test cases.
// A relative argument is looked up as given, then under `root`.
// Missing paths are reported in `errors`.
std::vector<TestCase> discover_tests(const std::vector<std::string>& args, const std::string& root,
                                     std::vector<std::string>& errors);

// Shard `index` of `count` (0-based): every count-th case from the index-th,
// so that CI jobs or machines split a sorted suite deterministically.
std::vector<TestCase> select_shard(std::vector<TestCase> cases, int index, int count);
// "I/N" (0 <= I < N); nullopt for anything else.
std::optional<std::pair<int, int>> parse_shard(std::string_view text);

// Runs every case with `jobs` worker threads. `report` is called once per
// test, in the order of `cases`, as soon as that test and all before it are done.
// Exceptions thrown by `run_one` become failures.
using RunOne = std::function<TestResult(const TestCase&)>;
using Report = std::function<void(size_t index, const TestResult&)>;
std::vector<TestResult> run_tests(const std::vector<TestCase>& cases, int jobs, const RunOne& run_one,
                                  const Report& report);

// "pass  path", "fail  path: first line of message", "skip  path: reason".
std::string format_result_line(const std::string& display, const TestResult& r);
// "path\tresult\tseconds\tmessage" (message on one line).
std::string format_tsv_line(const std::string& display, const TestResult& r);

// Machine-readable results: a JUnit XML file (one testcase per test, failures
// and skips with their message) and a JSON array of {name, result, time, message}.
std::string format_junit(const std::vector<TestCase>& cases, const std::vector<TestResult>& results);
std::string format_json(const std::vector<TestCase>& cases, const std::vector<TestResult>& results);

// ------------------------------------------------------- expectations ---
// Lines: "path  fail|skip  # reason"; '#' starts a comment; blank lines are ignored.
struct Expectation {
    Outcome outcome = Outcome::Fail;
    std::string reason;
    int line = 0;
};
using Expectations = std::map<std::string, Expectation>;
Parsed<Expectations> parse_expectations(std::string_view text);

struct Summary {
    int passed = 0, failed = 0, skipped = 0;
    std::vector<std::string> regressions;        // "path: expected X, got Y: message"
    std::vector<std::string> unexpected_passes;  // paths
    bool ok(bool have_expectations) const;
};
// Tallies results; with expectations, finds regressions (an outcome other than
// the expected one; unlisted tests are expected to pass) and unexpected passes.
Summary summarize(const std::vector<TestCase>& cases, const std::vector<TestResult>& results,
                  const Expectations* expectations);
// The expectation report (may be empty) followed by "N passed, N failed, N skipped".
std::string format_summary(const Summary& s, bool have_expectations);

}  // namespace glslrun::piglit
