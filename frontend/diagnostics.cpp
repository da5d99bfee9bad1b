// Diagnostics: the public Diagnostic/Error formatting and glslang's info log.
#include "frontend/diagnostics.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "frontend/compile.h"
#include "frontend/demangle.h"

namespace glslrun {

std::string Diagnostic::str() const {
    std::string s;
    if (!file.empty()) s += file + ":";
    if (line > 0) s += fmt::format("{}:", line);
    if (!s.empty()) s += " ";
    s += warning ? "warning: " : "error: ";
    return s + message;
}

Error::Error(std::string message, std::string file, int line) {
    diagnostics.push_back(Diagnostic{std::move(file), line, std::move(message), false});
}

std::string Error::str() const {
    std::string s;
    for (const Diagnostic& d : diagnostics) s += d.str() + "\n";
    return s;
}

namespace frontend {

static std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

namespace {

// One line of glslang's info log, split by hand: the log quotes user text
// (#error, tokens), so a backtracking regex could recurse as deep as the line
// is long.
struct LogLine {
    bool warning = false;
    bool located = false;
    std::string file, token, text;
    int line = 0;  // 0 where `#line` made it negative: the file, without a line
};

std::optional<LogLine> split_log_line(std::string_view s) {
    LogLine out;
    for (std::string_view kind : {"ERROR: ", "WARNING: "})
        if (s.substr(0, kind.size()) == kind) {
            out.warning = kind[0] == 'W';
            s.remove_prefix(kind.size());
            // Located: `file:line: 'token' : text`, at the first `:digits: '`.
            for (size_t colon = s.find(':'); colon != std::string_view::npos; colon = s.find(':', colon + 1)) {
                size_t digits = colon + 1 + (s.substr(colon + 1, 1) == "-");
                size_t d = digits;
                while (d < s.size() && std::isdigit(static_cast<unsigned char>(s[d]))) ++d;
                // 10 digits: `#line 2147483647` makes glslang's next lines -2147483648 and on.
                if (d == digits || d - digits > 10 || s.substr(d, 3) != ": '" || colon == 0) continue;
                size_t token_end = s.find("' :", d + 3);
                if (token_end == std::string_view::npos) break;
                size_t text_begin = token_end + 3;
                if (text_begin >= s.size() || s[text_begin] != ' ') break;
                out.file = std::string(s.substr(0, colon));
                out.located = true;
                long long line = std::stoll(std::string(s.substr(colon + 1, d - colon - 1)));
                out.line = int(std::clamp<long long>(line, 0, INT_MAX));
                out.token = std::string(s.substr(d + 3, token_end - d - 3));
                out.text = trim(std::string(s.substr(text_begin)));
                break;
            }
            if (!out.located) out.text = trim(std::string(s));
            return out;
        }
    return std::nullopt;
}

}  // namespace

void parse_info_log(const std::string& log, const std::string& unit_file, std::vector<Diagnostic>& out) {
    std::istringstream in(log);
    std::string line;
    bool last_kept = false;
    std::set<std::string> reported;
    while (std::getline(in, line)) {
        if (std::optional<LogLine> l = split_log_line(line); l && l->located) {
            const std::string &token = l->token, &text = l->text;
            last_kept = false;
            if (token.empty() && text == "compilation terminated") continue;
            std::string message = token.empty() ? text : fmt::format("'{}' : {}", token, text);
            // Bison's message when glslang's parser stack overflows.
            if (text == "memory exhausted")
                message = "expressions or blocks nest too deeply for the parser (glslang: memory exhausted)";
            // String 0 is the unit itself; another number comes from `#line L S`.
            // A number past INT_MAX (`#line 1 4294967295`) reaches glslang
            // wrapped to a negative one, which names no source string.
            std::string file = l->file == "0" || l->file.starts_with('-') ? unit_file : l->file;
            // Later errors on a line that already has one are cascades of
            // the first (glslang recovers by inventing a declaration).
            if (!l->warning && !reported.insert(fmt::format("{}:{}", l->file, l->line)).second) continue;
            out.push_back(Diagnostic{file, l->line, message, l->warning});
            last_kept = true;
        } else if (l) {
            const std::string& text = l->text;
            last_kept = false;
            if (text.find("compilation errors.") != std::string::npos && text.find("No code generated") != std::string::npos)
                continue;
            if (text.empty()) continue;
            // Link messages name functions mangled: `f(vf3;` reads `f(vec3)`.
            out.push_back(Diagnostic{unit_file, 0, demangle_signatures(text), l->warning});
            last_kept = true;
        } else if (last_kept && !trim(line).empty() && (line[0] == ' ' || line[0] == '\t')) {
            // Continuation of a multi-line link message.
            std::string& msg = out.back().message;
            msg += (msg.empty() || msg.back() == ':' ? " " : "; ") + demangle_signatures(trim(line));
        }
    }
}

}  // namespace frontend
}  // namespace glslrun
