// Diagnostics: the public Diagnostic/Error formatting and glslang's info log.
#include "frontend/diagnostics.h"

#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "frontend/compile.h"

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

Status check_shader(Stage stage, const ShaderSource& source, int default_version) {
    return frontend::check_shader(stage, source, default_version);
}

namespace frontend {

static std::string trim(const std::string& s) {
    size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

void parse_info_log(const std::string& log, const std::string& unit_file, std::vector<Diagnostic>& out) {
    static const std::regex located(R"(^(ERROR|WARNING): (.+):(\d+): '(.*?)' : +(.*?)\s*$)");
    static const std::regex global(R"(^(ERROR|WARNING): (.*?)\s*$)");
    std::istringstream in(log);
    std::string line;
    bool last_kept = false;
    std::set<std::string> reported;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, located)) {
            std::string token = m[4].str(), text = trim(m[5].str());
            last_kept = false;
            if (token.empty() && text == "compilation terminated") continue;
            std::string message = token.empty() ? text : fmt::format("'{}' : {}", token, text);
            // String 0 is the unit itself; another number comes from `#line L S`.
            std::string file = m[2].str() == "0" ? unit_file : m[2].str();
            int line_no = std::stoi(m[3].str());
            // Later errors on a line that already has one are cascades of
            // the first (glslang recovers by inventing a declaration).
            bool warning = m[1].str() == "WARNING";
            if (!warning && !reported.insert(fmt::format("{}:{}", m[2].str(), line_no)).second) continue;
            out.push_back(Diagnostic{file, line_no, message, warning});
            last_kept = true;
        } else if (std::regex_match(line, m, global)) {
            std::string text = trim(m[2].str());
            last_kept = false;
            if (text.find("compilation errors.") != std::string::npos && text.find("No code generated") != std::string::npos)
                continue;
            if (text.empty()) continue;
            out.push_back(Diagnostic{unit_file, 0, text, m[1].str() == "WARNING"});
            last_kept = true;
        } else if (last_kept && !trim(line).empty() && (line[0] == ' ' || line[0] == '\t')) {
            // Continuation of a multi-line link message.
            std::string& msg = out.back().message;
            msg += (msg.empty() || msg.back() == ':' ? " " : "; ") + trim(line);
        }
    }
}

}  // namespace frontend
}  // namespace glslrun
