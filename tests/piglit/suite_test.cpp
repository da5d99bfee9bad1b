// The suite runner: expectations, ordering under parallelism, output, discovery.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <unistd.h>

#include "tools/glslrun/piglit_suite.h"

using namespace glslrun::piglit;
namespace fs = std::filesystem;

namespace {

Expectations expectations_ok(std::string_view text) {
    auto p = parse_expectations(text);
    if (!parsed_ok(p)) FAIL(std::get<ParseError>(p).str());
    return std::get<Expectations>(p);
}

std::vector<TestCase> cases_named(std::initializer_list<const char*> names) {
    std::vector<TestCase> out;
    for (const char* n : names) out.push_back({n, n});
    return out;
}

}  // namespace

TEST_CASE("expectations file format", "[piglit][suite]") {
    Expectations e = expectations_ok(
        "# header comment\n"
        "\n"
        "tests/a.shader_test\tfail  # glslang folds (v == v) == true wrongly\n"
        "tests/b.vert   skip\n"
        "  tests/c.frag fail#no space before the comment\n");
    REQUIRE(e.size() == 3);
    CHECK(e.at("tests/a.shader_test").outcome == Outcome::Fail);
    CHECK(e.at("tests/a.shader_test").reason == "glslang folds (v == v) == true wrongly");
    CHECK(e.at("tests/a.shader_test").line == 3);
    CHECK(e.at("tests/b.vert").outcome == Outcome::Skip);
    CHECK(e.at("tests/c.frag").reason == "no space before the comment");

    auto bad = [](std::string_view text) {
        auto p = parse_expectations(text);
        REQUIRE_FALSE(parsed_ok(p));
        return std::get<ParseError>(p);
    };
    CHECK(bad("a.shader_test pass\n").line == 1);
    CHECK(bad("a.shader_test\n").line == 1);
    CHECK(bad("ok.vert fail\na.shader_test fail extra\n").line == 2);
    CHECK(bad("a fail\na skip\n").message == "a is listed twice");
}

TEST_CASE("regressions and unexpected passes", "[piglit][suite]") {
    Expectations e = expectations_ok("listed_fail fail\nlisted_skip skip\nfixed fail\nskip_now_fails skip\n");
    auto cases = cases_named({"ok", "broken", "listed_fail", "listed_skip", "fixed", "skip_now_fails", "new_skip"});
    std::vector<TestResult> results = {
        {Outcome::Pass, ""},
        {Outcome::Fail, "line 7: probe rgba at (1, 2): expected ...\nmore"},
        {Outcome::Fail, "known"},
        {Outcome::Skip, "textures"},
        {Outcome::Pass, ""},
        {Outcome::Fail, "boom"},
        {Outcome::Skip, "extension"},
    };
    Summary s = summarize(cases, results, &e);
    CHECK(s.passed == 2);
    CHECK(s.failed == 3);
    CHECK(s.skipped == 2);
    REQUIRE(s.regressions.size() == 3);
    CHECK(s.regressions[0] == "broken: expected pass, got fail: line 7: probe rgba at (1, 2): expected ...");
    CHECK(s.regressions[1] == "skip_now_fails: expected skip, got fail: boom");
    CHECK(s.regressions[2] == "new_skip: expected pass, got skip: extension");
    REQUIRE(s.unexpected_passes.size() == 1);
    CHECK(s.unexpected_passes[0] == "fixed");
    CHECK_FALSE(s.ok(true));
    std::string text = format_summary(s, true);
    CHECK(text.find("3 regression(s):\n  broken:") != std::string::npos);
    CHECK(text.find("1 unexpected pass(es)") != std::string::npos);
    // The closing line is the last line, alone.
    CHECK(text.size() >= 30);
    CHECK(text.substr(text.rfind('\n', text.size() - 2) + 1) == "2 passed, 3 failed, 2 skipped\n");
}

TEST_CASE("all expectations met: the run succeeds despite failures", "[piglit][suite]") {
    Expectations e = expectations_ok("bad fail # known\n");
    auto cases = cases_named({"good", "bad"});
    std::vector<TestResult> results = {{Outcome::Pass, ""}, {Outcome::Fail, "x"}};
    Summary s = summarize(cases, results, &e);
    CHECK(s.ok(true));
    CHECK_FALSE(s.ok(false));  // without --expect any failure fails the run
    CHECK(format_summary(s, true) == "all results match the expectations\n1 passed, 1 failed, 0 skipped\n");
    Summary plain = summarize(cases, results, nullptr);
    CHECK(plain.regressions.empty());
    CHECK(format_summary(plain, false) == "1 passed, 1 failed, 0 skipped\n");
}

TEST_CASE("result lines and TSV", "[piglit][suite]") {
    CHECK(format_result_line("a/b.shader_test", {Outcome::Pass, "ignored"}) == "pass  a/b.shader_test");
    CHECK(format_result_line("x.frag", {Outcome::Fail, "\nline 3: first\nsecond"}) == "fail  x.frag: line 3: first");
    CHECK(format_result_line("y.vert", {Outcome::Skip, "GLSL ES"}) == "skip  y.vert: GLSL ES");
    CHECK(format_result_line("z.vert", {Outcome::Fail, ""}) == "fail  z.vert");
    TestResult r{Outcome::Fail, "a\tb\nc\\d\r", 0.25};
    // Escaped as docs/ci.md says: the message reads back whole.
    CHECK(format_tsv_line("p\tq", r) == "p\\tq\tfail\t0.2500\ta\\tb\\nc\\\\d\\r");
}

TEST_CASE("parallel runs report in input order with every result", "[piglit][suite]") {
    std::vector<TestCase> cases;
    for (int i = 0; i < 40; ++i) cases.push_back({std::to_string(i), "t" + std::to_string(i)});
    std::atomic<int> running{0}, max_running{0};
    auto run_one = [&](const TestCase& tc) -> TestResult {
        int now = ++running;
        int prev = max_running.load();
        while (now > prev && !max_running.compare_exchange_weak(prev, now)) {}
        int i = std::stoi(tc.path);
        // Later tests finish first, so completion order differs from input order.
        std::this_thread::sleep_for(std::chrono::milliseconds((40 - i) % 7));
        --running;
        if (i == 13) throw std::runtime_error("kaboom");
        return {i % 3 == 0 ? Outcome::Fail : Outcome::Pass, "n" + std::to_string(i)};
    };
    std::vector<size_t> order;
    auto results = run_tests(cases, 4, run_one, [&](size_t i, const TestResult&) { order.push_back(i); });
    REQUIRE(order.size() == 40);
    for (size_t i = 0; i < order.size(); ++i) CHECK(order[i] == i);
    REQUIRE(results.size() == 40);
    for (int i = 0; i < 40; ++i) {
        if (i == 13) {
            CHECK(results[i].outcome == Outcome::Fail);
            CHECK(results[i].message == "internal error: kaboom");
        } else {
            CHECK(results[i].outcome == (i % 3 == 0 ? Outcome::Fail : Outcome::Pass));
            CHECK(results[i].message == "n" + std::to_string(i));
        }
        CHECK(results[i].seconds >= 0);
    }
    CHECK(max_running.load() > 1);
    CHECK(max_running.load() <= 4);
}

TEST_CASE("discovery: recursive, sorted, test files only, relative to root", "[piglit][suite]") {
    fs::path root = fs::temp_directory_path() / ("glslrun_piglit_discover_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "spec" / "b");
    fs::create_directories(root / "spec" / "a");
    auto write = [&](const fs::path& p, const std::string& text) { std::ofstream(p) << text; };
    write(root / "spec" / "b" / "z.shader_test", "[require]\n");
    write(root / "spec" / "a" / "y.shader_test", "[require]\n");
    write(root / "spec" / "a" / "x.frag", "// [config]\n// expect_result: pass\n// [end config]\n");
    write(root / "spec" / "a" / "helper.vert", "void main(){}\n");  // no [config]: not a test
    write(root / "spec" / "a" / "notes.txt", "hello\n");
    std::vector<std::string> errors;
    auto cases = discover_tests({"spec", (root / "missing").string()}, root.string(), errors);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].find("missing") != std::string::npos);
    REQUIRE(cases.size() == 3);
    CHECK(cases[0].display == "spec/a/x.frag");
    CHECK(cases[1].display == "spec/a/y.shader_test");
    CHECK(cases[2].display == "spec/b/z.shader_test");
    CHECK(fs::exists(cases[2].path));
    // A file named explicitly is a test even without [config].
    errors.clear();
    auto one = discover_tests({(root / "spec" / "a" / "helper.vert").string()}, root.string(), errors);
    REQUIRE(one.size() == 1);
    CHECK(one[0].display == "spec/a/helper.vert");
    fs::remove_all(root);
}
