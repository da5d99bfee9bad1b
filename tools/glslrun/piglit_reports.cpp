// Splitting a suite into shards, and its results as JUnit XML and JSON for CI.
#include <charconv>

#include <fmt/format.h>

#include "piglit_suite.h"

namespace glslrun::piglit {

std::vector<TestCase> select_shard(std::vector<TestCase> cases, int index, int count) {
    std::vector<TestCase> out;
    for (size_t i = size_t(index); i < cases.size(); i += size_t(count)) out.push_back(std::move(cases[i]));
    return out;
}

std::optional<std::pair<int, int>> parse_shard(std::string_view text) {
    size_t slash = text.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    int index = -1, count = 0;
    auto whole = [](std::string_view s, int& v) {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        return ec == std::errc() && end == s.data() + s.size();
    };
    if (!whole(text.substr(0, slash), index) || !whole(text.substr(slash + 1), count)) return std::nullopt;
    if (count < 1 || index < 0 || index >= count) return std::nullopt;
    return std::pair{index, count};
}

namespace {

std::string xml_escaped(std::string_view s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default:
            // XML 1.0 has no other control characters; a test's message may hold any byte.
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') out += '?';
            else out += c;
        }
    }
    return out;
}

std::string json_escaped(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += {'\\', c};
        else if (c == '\n') out += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
        else out += c;
    }
    return out;
}

}  // namespace

std::string format_junit(const std::vector<TestCase>& cases, const std::vector<TestResult>& results) {
    int failures = 0, skipped = 0;
    double total = 0;
    std::string body;
    for (size_t i = 0; i < cases.size() && i < results.size(); ++i) {
        const TestResult& r = results[i];
        total += r.seconds;
        body += fmt::format("  <testcase classname=\"glslrun\" name=\"{}\" time=\"{:.4f}\"", xml_escaped(cases[i].display),
                            r.seconds);
        if (r.outcome == Outcome::Pass) {
            body += "/>\n";
            continue;
        }
        bool fail = r.outcome == Outcome::Fail;
        (fail ? failures : skipped)++;
        body += fmt::format(">\n    <{} message=\"{}\"/>\n  </testcase>\n", fail ? "failure" : "skipped",
                            xml_escaped(r.message));
    }
    return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<testsuite name=\"glslrun test\" tests=\"{}\" failures=\"{}\" skipped=\"{}\" time=\"{:.4f}\">\n"
                       "{}</testsuite>\n",
                       cases.size(), failures, skipped, total, body);
}

std::string format_json(const std::vector<TestCase>& cases, const std::vector<TestResult>& results) {
    std::string out = "[\n";
    for (size_t i = 0; i < cases.size() && i < results.size(); ++i)
        out += fmt::format("  {{\"name\": \"{}\", \"result\": \"{}\", \"time\": {:.4f}, \"message\": \"{}\"}}{}\n",
                           json_escaped(cases[i].display), outcome_name(results[i].outcome), results[i].seconds,
                           json_escaped(results[i].message), i + 1 < cases.size() ? "," : "");
    return out + "]\n";
}

}  // namespace glslrun::piglit
