// The #version check (language_version.h). GLSL 1.10 §3.3: #version must
// come before anything but comments and white space, so the first directive
// line outside comments is the one that counts.
#include "frontend/language_version.h"

#include <cctype>
#include <sstream>

#include <fmt/format.h>

namespace glslrun::frontend {
namespace {

struct VersionLine {
    int line = 0;
    std::string number, profile;
};

// The first `#version` directive outside comments, if any.
std::optional<VersionLine> find_version_directive(const std::string& s) {
    int line = 1;
    bool line_start = true;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (c == '\n') {
            ++line;
            line_start = true;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i + 1 < s.size() && s[i + 1] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            size_t end = s.find("*/", i + 2);
            end = end == std::string::npos ? s.size() : end + 1;
            for (size_t k = i; k < end && k < s.size(); ++k) line += s[k] == '\n';
            i = end;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        if (c == '#' && line_start) {
            size_t end = s.find('\n', i);
            std::istringstream words(s.substr(i + 1, end == std::string::npos ? std::string::npos : end - i - 1));
            std::string word;
            if (words >> word && word == "version") {
                VersionLine v{line, {}, {}};
                words >> v.number >> v.profile;
                return v;
            }
        }
        line_start = false;
    }
    return std::nullopt;
}

bool is_desktop_version(int n) {
    for (int v : {110, 120, 130, 140, 150, 330, 400, 410, 420, 430, 440, 450, 460})
        if (n == v) return true;
    return false;
}

std::string dotted(int version) { return fmt::format("{}.{:02}", version / 100, version % 100); }

}  // namespace

int unit_version(const ShaderSource& source, int default_version) {
    std::optional<VersionLine> v = find_version_directive(source.text);
    if (!v || v->number.empty() || v->number.size() > 4 || v->number.find_first_not_of("0123456789") != std::string::npos)
        return default_version;
    return std::stoi(v->number);
}

std::optional<VersionRefusal> unsupported_version(const ShaderSource& source, int default_version) {
    constexpr const char* kRuns = "glslrun runs GLSL 1.10 and 1.20 only";
    std::optional<VersionLine> v = find_version_directive(source.text);
    if (!v) {
        if (default_version == 110 || default_version == 120) return std::nullopt;
        return VersionRefusal{Diagnostic{source.name, 0,
                                         fmt::format("GLSL {} (the default version for sources without #version) is "
                                                     "not supported: {}",
                                                     dotted(default_version), kRuns),
                                         false},
                              true};
    }
    bool digits = !v->number.empty() && v->number.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || v->number.size() > 4) return std::nullopt;  // malformed: glslang reports it
    int number = std::stoi(v->number);
    if ((number == 110 || number == 120) && v->profile.empty()) return std::nullopt;
    std::string directive = "#version " + v->number + (v->profile.empty() ? "" : " " + v->profile);
    bool es = v->profile == "es" || number == 100;
    bool known = es ? number == 100 || number == 300 || number == 310 || number == 320
                    : is_desktop_version(number) && (v->profile.empty() || (number >= 150 && (v->profile == "core" || v->profile == "compatibility")));
    if (!known)
        return VersionRefusal{
            Diagnostic{source.name, v->line, fmt::format("'{}' : not a GLSL version: {}", directive, kRuns), false},
            false};
    std::string language = es ? "GLSL ES " + dotted(number) : "GLSL " + dotted(number);
    if (!es && !v->profile.empty()) language += " " + v->profile + " profile";
    return VersionRefusal{
        Diagnostic{source.name, v->line, fmt::format("'{}' : {} is not supported: {}", directive, language, kRuns), false},
        true};
}

std::optional<Error> refuse_unsupported_versions(const std::vector<const std::vector<ShaderSource>*>& stages,
                                                 int default_version) {
    Error e;
    e.unsupported_version = true;
    for (const std::vector<ShaderSource>* units : stages)
        for (const ShaderSource& src : *units)
            if (auto r = unsupported_version(src, default_version)) {
                e.diagnostics.push_back(std::move(r->diagnostic));
                e.unsupported_version = e.unsupported_version && r->other_language;
            }
    if (e.diagnostics.empty()) return std::nullopt;
    return e;
}

}  // namespace glslrun::frontend
