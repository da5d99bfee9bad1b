#include "piglit_suite.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

namespace glslrun::piglit {
namespace fs = std::filesystem;

const char* outcome_name(Outcome o) {
    switch (o) {
    case Outcome::Pass: return "pass";
    case Outcome::Fail: return "fail";
    case Outcome::Skip: return "skip";
    }
    return "?";
}

// ----------------------------------------------------------- discovery ---
namespace {

bool has_extension(const std::string& path, std::initializer_list<const char*> exts) {
    std::string ext = fs::path(path).extension().string();
    for (const char* e : exts)
        if (ext == e) return true;
    return false;
}

bool file_contains(const std::string& path, std::string_view needle) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buf;
    buf << in.rdbuf();
    return buf.str().find(needle) != std::string::npos;
}

std::string display_name(const fs::path& p, const std::string& root) {
    if (root.empty()) return p.generic_string();
    std::error_code ec;
    fs::path rel = fs::relative(p, root, ec);
    if (ec || rel.empty() || *rel.begin() == "..") return p.generic_string();
    return rel.generic_string();
}

}  // namespace

bool is_test_file(const std::string& path) {
    if (has_extension(path, {".shader_test"})) return true;
    if (has_extension(path, {".vert", ".frag", ".geom", ".tesc", ".tese", ".comp"}))
        return file_contains(path, "[config]");
    return false;
}

std::vector<TestCase> discover_tests(const std::vector<std::string>& args, const std::string& root,
                                     std::vector<std::string>& errors) {
    std::vector<TestCase> cases;
    for (const auto& arg : args) {
        fs::path p(arg);
        std::error_code ec;
        if (!fs::exists(p, ec) && p.is_relative() && !root.empty() && fs::exists(fs::path(root) / p, ec))
            p = fs::path(root) / p;
        if (!fs::exists(p, ec)) {
            errors.push_back(arg + ": no such file or directory");
            continue;
        }
        if (!fs::is_directory(p, ec)) {  // named explicitly: always a test
            cases.push_back({p.string(), display_name(p, root)});
            continue;
        }
        std::vector<fs::path> found;
        for (auto it = fs::recursive_directory_iterator(p, fs::directory_options::skip_permission_denied, ec);
             it != fs::recursive_directory_iterator(); it.increment(ec)) {
            if (ec) break;
            if (it->is_regular_file(ec) && is_test_file(it->path().string())) found.push_back(it->path());
        }
        if (ec) errors.push_back(arg + ": " + ec.message());
        std::sort(found.begin(), found.end());
        for (const auto& f : found) cases.push_back({f.string(), display_name(f, root)});
    }
    return cases;
}

// ------------------------------------------------------------- running ---
namespace {

TestResult run_guarded(const RunOne& run_one, const TestCase& tc) {
    auto start = std::chrono::steady_clock::now();
    TestResult r;
    try {
        r = run_one(tc);
    } catch (const std::exception& e) {
        r = {Outcome::Fail, std::string("internal error: ") + e.what()};
    } catch (...) {
        r = {Outcome::Fail, "internal error: unknown exception"};
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace

std::vector<TestResult> run_tests(const std::vector<TestCase>& cases, int jobs, const RunOne& run_one,
                                  const Report& report) {
    std::vector<TestResult> results(cases.size());
    std::vector<char> done(cases.size(), 0);
    std::mutex mutex;
    std::condition_variable cv;
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t i; (i = next.fetch_add(1)) < cases.size();) {
            TestResult r = run_guarded(run_one, cases[i]);
            std::lock_guard lock(mutex);
            results[i] = std::move(r);
            done[i] = 1;
            cv.notify_all();
        }
    };
    jobs = std::clamp(jobs, 1, 256);
    std::vector<std::thread> threads;
    for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (size_t i = 0; i < cases.size(); ++i) {  // report in order, as results arrive
        std::unique_lock lock(mutex);
        cv.wait(lock, [&] { return done[i] != 0; });
        TestResult r = results[i];
        lock.unlock();
        if (report) report(i, r);
    }
    for (auto& t : threads) t.join();
    return results;
}

namespace {

std::string one_line(const std::string& s) {
    std::string out;
    for (char c : s) out.push_back(c == '\n' || c == '\t' || c == '\r' ? ' ' : c);
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

std::string first_line(const std::string& s) {
    size_t start = 0;
    while (start < s.size()) {  // the first line that has text
        size_t end = s.find('\n', start);
        if (end == std::string::npos) end = s.size();
        std::string line = one_line(s.substr(start, end - start));
        if (!line.empty()) return line;
        start = end + 1;
    }
    return {};
}

}  // namespace

std::string format_result_line(const std::string& display, const TestResult& r) {
    std::string line = std::string(outcome_name(r.outcome)) + "  " + display;
    std::string msg = first_line(r.message);
    if (r.outcome != Outcome::Pass && !msg.empty()) line += ": " + msg;
    return line;
}

// A TSV field as docs/ci.md states it: backslash, tab, newline and carriage
// return written as \\, \t, \n and \r (PostgreSQL's text format), so any
// message reads back as it was.
std::string tsv_field(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '\\': out += "\\\\"; break;
        case '\t': out += "\\t"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        default: out += c;
        }
    }
    return out;
}

std::string format_tsv_line(const std::string& display, const TestResult& r) {
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.4f", r.seconds);
    return tsv_field(display) + "\t" + outcome_name(r.outcome) + "\t" + secs + "\t" + tsv_field(r.message);
}

// -------------------------------------------------------- expectations ---
Parsed<Expectations> parse_expectations(std::string_view text) {
    Expectations out;
    int lineno = 0;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view raw = text.substr(start, end - start);
        ++lineno;
        start = end + 1;
        std::string reason;
        size_t hash = raw.find('#');
        if (hash != std::string_view::npos) {
            reason = std::string(trim(raw.substr(hash + 1)));
            raw = raw.substr(0, hash);
        }
        std::string_view line = trim(raw);
        if (line.empty()) {
            if (end == text.size()) break;
            continue;
        }
        std::istringstream words{std::string(line)};
        std::string path, outcome, extra;
        words >> path >> outcome >> extra;
        if (outcome.empty() || !extra.empty())
            return ParseError{lineno, "expected \"path fail|skip  # reason\""};
        Expectation e;
        e.reason = reason;
        e.line = lineno;
        if (outcome == "fail") e.outcome = Outcome::Fail;
        else if (outcome == "skip") e.outcome = Outcome::Skip;
        else return ParseError{lineno, "outcome must be fail or skip, not \"" + outcome + "\""};
        if (!out.emplace(path, e).second)
            return ParseError{lineno, path + " is listed twice"};
        if (end == text.size()) break;
    }
    return out;
}

bool Summary::ok(bool have_expectations) const {
    if (have_expectations) return regressions.empty() && unexpected_passes.empty();
    return failed == 0;
}

Summary summarize(const std::vector<TestCase>& cases, const std::vector<TestResult>& results,
                  const Expectations* expectations) {
    Summary s;
    for (size_t i = 0; i < cases.size() && i < results.size(); ++i) {
        const TestResult& r = results[i];
        if (r.outcome == Outcome::Pass) ++s.passed;
        else if (r.outcome == Outcome::Fail) ++s.failed;
        else ++s.skipped;
        if (!expectations) continue;
        Outcome expected = Outcome::Pass;
        if (auto it = expectations->find(cases[i].display); it != expectations->end())
            expected = it->second.outcome;
        if (r.outcome == expected) continue;
        if (r.outcome == Outcome::Pass) {
            s.unexpected_passes.push_back(cases[i].display);
        } else {
            std::string entry = cases[i].display + ": expected " + outcome_name(expected) + ", got " +
                                outcome_name(r.outcome);
            std::string msg = first_line(r.message);
            if (!msg.empty()) entry += ": " + msg;
            s.regressions.push_back(entry);
        }
    }
    return s;
}

std::string format_summary(const Summary& s, bool have_expectations) {
    std::string out;
    if (have_expectations) {
        if (!s.regressions.empty()) {
            out += std::to_string(s.regressions.size()) + " regression(s):\n";
            for (const auto& r : s.regressions) out += "  " + r + "\n";
        }
        if (!s.unexpected_passes.empty()) {
            out += std::to_string(s.unexpected_passes.size()) +
                   " unexpected pass(es) (remove them from the expectations list):\n";
            for (const auto& p : s.unexpected_passes) out += "  " + p + "\n";
        }
        if (s.regressions.empty() && s.unexpected_passes.empty())
            out += "all results match the expectations\n";
    }
    out += std::to_string(s.passed) + " passed, " + std::to_string(s.failed) + " failed, " +
           std::to_string(s.skipped) + " skipped\n";
    return out;
}

}  // namespace glslrun::piglit
