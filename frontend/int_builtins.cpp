// The int overloads of min, max, clamp, abs and sign (int_builtins.h).
#include "frontend/int_builtins.h"

#include <cctype>

#include <fmt/format.h>

namespace glslrun::frontend {
namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string build_helpers() {
    std::string out;
    const char* names[] = {"x", "y", "z", "w"};
    // Scalars: float through the built-in, int by comparison.
    out += "float glslrun_min(float a, float b) { return min(a, b); }\n"
           "float glslrun_max(float a, float b) { return max(a, b); }\n"
           "int glslrun_min(int a, int b) { return a < b ? a : b; }\n"
           "int glslrun_max(int a, int b) { return a > b ? a : b; }\n";
    for (int n = 2; n <= 4; ++n) {
        for (const char* f : {"min", "max"}) {
            out += fmt::format("vec{0} glslrun_{1}(vec{0} a, vec{0} b) {{ return {1}(a, b); }}\n", n, f);
            out += fmt::format("vec{0} glslrun_{1}(vec{0} a, float b) {{ return {1}(a, b); }}\n", n, f);
            std::string comps;
            for (int i = 0; i < n; ++i)
                comps += fmt::format("{}glslrun_{}(a.{}, b.{})", i ? ", " : "", f, names[i], names[i]);
            out += fmt::format("ivec{0} glslrun_{1}(ivec{0} a, ivec{0} b) {{ return ivec{0}({2}); }}\n", n, f, comps);
            out += fmt::format("ivec{0} glslrun_{1}(ivec{0} a, int b) {{ return glslrun_{1}(a, ivec{0}(b)); }}\n", n, f);
        }
    }
    out += "int glslrun_abs(int a) { return a < 0 ? -a : a; }\n"
           "int glslrun_sign(int a) { return a > 0 ? 1 : a < 0 ? -1 : 0; }\n";
    for (int n = 1; n <= 4; ++n) {
        std::string v = n == 1 ? "float" : fmt::format("vec{}", n);
        for (const char* f : {"abs", "sign"}) {
            out += fmt::format("{0} glslrun_{1}({0} a) {{ return {1}(a); }}\n", v, f);
            if (n == 1) continue;
            std::string comps;
            for (int i = 0; i < n; ++i) comps += fmt::format("{}glslrun_{}(a.{})", i ? ", " : "", f, names[i]);
            out += fmt::format("ivec{0} glslrun_{1}(ivec{0} a) {{ return ivec{0}({2}); }}\n", n, f, comps);
        }
    }
    for (std::string t : {"float", "vec2", "vec3", "vec4", "int", "ivec2", "ivec3", "ivec4"}) {
        out += fmt::format("{0} glslrun_clamp({0} x, {0} lo, {0} hi) {{ return glslrun_min(glslrun_max(x, lo), hi); }}\n", t);
        if (t != "float" && t != "int") {
            std::string s = t[0] == 'i' ? "int" : "float";
            out += fmt::format("{0} glslrun_clamp({0} x, {1} lo, {1} hi) {{ return glslrun_min(glslrun_max(x, lo), hi); }}\n",
                               t, s);
        }
    }
    return out;
}

}  // namespace

std::set<int> int_builtin_retry_lines(const std::vector<Diagnostic>& diags, const std::string& src) {
    std::set<int> lines;
    for (const Diagnostic& d : diags)
        if (!d.warning && d.line > 0) lines.insert(d.line);
    // Renaming changes nothing unless one of the lines holds such a call.
    if (lines.empty() || rename_int_builtin_calls(src, lines) == src) return {};
    return lines;
}

std::string rename_int_builtin_calls(const std::string& src, const std::set<int>& lines) {
    std::string out;
    out.reserve(src.size() + 64);
    int line = 1;
    for (size_t i = 0; i < src.size(); ++i) {
        char c = src[i];
        if (c == '\n') ++line;
        bool starts_word = word_char(c) && (i == 0 || (!word_char(src[i - 1]) && src[i - 1] != '.'));
        if (starts_word && lines.count(line)) {
            size_t end = i;
            while (end < src.size() && word_char(src[end])) ++end;
            std::string word = src.substr(i, end - i);
            size_t next = src.find_first_not_of(" \t", end);
            bool renamed = word == "min" || word == "max" || word == "clamp" || word == "abs" || word == "sign";
            if (renamed && next != std::string::npos && src[next] == '(')
                out += "glslrun_";
            out += word;
            i = end - 1;
            continue;
        }
        out += c;
    }
    return out;
}

const std::string& int_builtin_helpers() {
    static const std::string helpers = build_helpers();
    return helpers;
}

}  // namespace glslrun::frontend
