// Splitting a suite into shards, and its results as JUnit XML (pugixml) and
// JSON (nlohmann-json) for CI.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

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

using Json = nlohmann::ordered_json;

// Text as XML 1.0 may hold it: invalid UTF-8 becomes U+FFFD (nlohmann's
// replacing dump), and the control characters XML has no way to write,
// even as character references, become '?'.
std::string xml_text(const std::string& s) {
    std::string valid = Json::parse(Json(s).dump(-1, ' ', false, Json::error_handler_t::replace)).get<std::string>();
    for (char& c : valid)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') c = '?';
    return valid;
}

std::string seconds(double s) { return fmt::format("{:.4f}", s); }

}  // namespace

// pugixml writes the document and escapes the attributes.
std::string format_junit(const std::vector<TestCase>& cases, const std::vector<TestResult>& results) {
    const size_t n = std::min(cases.size(), results.size());
    int failures = 0, skipped = 0;
    double total = 0;
    for (size_t i = 0; i < n; ++i) {
        total += results[i].seconds;
        failures += results[i].outcome == Outcome::Fail;
        skipped += results[i].outcome == Outcome::Skip;
    }
    pugi::xml_document doc;
    pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";
    pugi::xml_node suite = doc.append_child("testsuite");
    suite.append_attribute("name") = "glslrun test";
    suite.append_attribute("tests") = static_cast<unsigned long long>(cases.size());
    suite.append_attribute("failures") = failures;
    suite.append_attribute("skipped") = skipped;
    suite.append_attribute("time") = seconds(total).c_str();
    for (size_t i = 0; i < n; ++i) {
        const TestResult& r = results[i];
        pugi::xml_node test = suite.append_child("testcase");
        test.append_attribute("classname") = "glslrun";
        test.append_attribute("name") = xml_text(cases[i].display).c_str();
        test.append_attribute("time") = seconds(r.seconds).c_str();
        if (r.outcome == Outcome::Pass) continue;
        pugi::xml_node why = test.append_child(r.outcome == Outcome::Fail ? "failure" : "skipped");
        why.append_attribute("message") = xml_text(r.message).c_str();
    }
    std::ostringstream out;
    doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
    return out.str();
}

// A JSON array written by nlohmann-json, one test's object a line (a shell
// script can grep it); invalid UTF-8 in a name or message becomes U+FFFD.
// docs/schema/glslrun.schema.json ("test_report") describes it.
std::string format_json(const std::vector<TestCase>& cases, const std::vector<TestResult>& results) {
    std::string out = "[\n";
    const size_t n = std::min(cases.size(), results.size());
    for (size_t i = 0; i < n; ++i) {
        Json test = {{"name", cases[i].display},
                     {"result", outcome_name(results[i].outcome)},
                     {"time", std::round(results[i].seconds * 1e4) / 1e4},
                     {"message", results[i].message}};
        out += "  " + test.dump(-1, ' ', false, Json::error_handler_t::replace) + (i + 1 < n ? ",\n" : "\n");
    }
    return out + "]\n";
}

}  // namespace glslrun::piglit
