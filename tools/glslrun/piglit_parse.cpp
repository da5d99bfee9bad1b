// .shader_test section structure, [require], [vertex data], and
// glslparsertest's [config] block. Command lines live in piglit_commands.cpp.
#include "piglit_parse.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>

namespace glslrun::piglit {

std::string ParseError::str() const {
    if (line > 0) return "line " + std::to_string(line) + ": " + message;
    return message;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

namespace {

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

size_t skip_space(std::string_view s, size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

bool is_hex_prefix(std::string_view s, size_t i) {
    return i + 1 < s.size() && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X');
}

// Splits text into lines without their '\n' (and '\r').
std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        if (end == text.size()) break;
        start = end + 1;
    }
    if (!lines.empty() && lines.back().empty() && !text.empty() && text.back() == '\n')
        lines.pop_back();
    return lines;
}

std::vector<std::string_view> split_words(std::string_view s) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while ((i = skip_space(s, i)) < s.size()) {
        size_t j = i;
        while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
        words.push_back(s.substr(i, j - i));
        i = j;
    }
    return words;
}

std::string_view strip_hash_comment(std::string_view s) {
    size_t hash = s.find('#');
    return hash == std::string_view::npos ? s : s.substr(0, hash);
}

// "1.10" -> 110 (GLSL) or "2.1" -> 21 (GL); -1 when malformed.
int parse_version_number(std::string_view s, bool glsl) {
    std::string str(trim(s));
    int major = 0, minor = 0;
    char dot = 0;
    int consumed = 0;
    if (std::sscanf(str.c_str(), "%d%c%d%n", &major, &dot, &minor, &consumed) != 3 || dot != '.')
        return -1;
    if (consumed != static_cast<int>(str.size())) return -1;
    // Bounded before multiplying: fuzz_piglit found "glsl_version: 1214748364.0" overflowing.
    if (major < 0 || major > 99 || minor < 0 || minor > (glsl ? 99 : 9)) return -1;
    return glsl ? major * 100 + minor : major * 10 + minor;
}

}  // namespace

// --------------------------------------------------------- number lists ---
std::vector<float> parse_float_list(std::string_view s, size_t* consumed) {
    std::vector<float> out;
    std::string buf(s);
    size_t i = 0;
    while (true) {
        size_t start = skip_space(buf, i);
        if (start >= buf.size()) break;
        const char* begin = buf.c_str() + start;
        char* end = nullptr;
        if (is_hex_prefix(buf, start)) {  // piglit's strtof_hex: the float's bits
            unsigned long bits = std::strtoul(begin, &end, 16);
            uint32_t u = static_cast<uint32_t>(bits);
            float f;
            std::memcpy(&f, &u, sizeof f);
            out.push_back(f);
        } else {
            double d = std::strtod(begin, &end);
            if (end == begin) break;
            out.push_back(static_cast<float>(d));
        }
        i = static_cast<size_t>(end - buf.c_str());
    }
    if (consumed) *consumed = i;
    return out;
}

std::vector<int32_t> parse_int_list(std::string_view s, size_t* consumed) {
    std::vector<int32_t> out;
    std::string buf(s);
    size_t i = 0;
    while (true) {
        size_t start = skip_space(buf, i);
        if (start >= buf.size()) break;
        const char* begin = buf.c_str() + start;
        char* end = nullptr;
        long long v = std::strtoll(begin, &end, 0);
        if (end == begin) break;
        out.push_back(static_cast<int32_t>(v));  // wraps like strtol into an int
        i = static_cast<size_t>(end - buf.c_str());
    }
    if (consumed) *consumed = i;
    return out;
}

// ---------------------------------------------------------- [require] ---
namespace {

bool parse_comparison(std::string_view s, std::string& op, std::string_view& rest) {
    s = trim(s);
    for (std::string_view candidate : {">=", "<=", "==", "!=", ">", "<"}) {
        if (starts_with(s, candidate)) {
            op = std::string(candidate);
            rest = s.substr(candidate.size());
            return true;
        }
    }
    return false;
}

// "GLSL >= 1.10", "GLSL ES >= 1.00", "GL >= 2.1", "GL ES >= 2.0", "GL CORE >= 3.1".
std::optional<ParseError> parse_version_requirement(std::string_view line, int lineno,
                                                    Requirements& req) {
    bool glsl = starts_with(line, "GLSL");
    std::string_view rest = trim(line.substr(glsl ? 4 : 2));
    bool es = false;
    if (starts_with(rest, "ES")) { es = true; rest = trim(rest.substr(2)); }
    else if (starts_with(rest, "CORE")) { rest = trim(rest.substr(4)); }
    else if (starts_with(rest, "COMPAT")) { rest = trim(rest.substr(6)); }
    std::string op;
    std::string_view number;
    if (!parse_comparison(rest, op, number))
        return ParseError{lineno, "invalid comparison in \"" + std::string(line) + "\""};
    int version = parse_version_number(number, glsl);
    if (version < 0)
        return ParseError{lineno, "malformed version in \"" + std::string(line) + "\""};
    if (glsl) {
        // piglit allows only >= here: the number becomes the implicit #version.
        if (op != ">=") return ParseError{lineno, "unsupported GLSL version comparison " + op};
        req.glsl_version = version;
        req.glsl_es = es || version == 100;
    } else {
        if (op != ">=" && op != ">" && op != "==")
            return ParseError{lineno, "unsupported GL version comparison " + op};
        req.gl_version = version;
        req.gl_es = es;
    }
    return std::nullopt;
}

std::optional<ParseError> parse_requirement(std::string_view raw, int lineno, Requirements& req) {
    std::string_view line = trim(raw);
    if (line.empty() || line[0] == '#') return std::nullopt;
    auto words = split_words(line);
    if (starts_with(line, "GL_MAX_")) {
        Requirements::Limit limit;
        limit.name = std::string(words[0]);
        std::string_view number;
        if (!parse_comparison(line.substr(words[0].size()), limit.op, number))
            return ParseError{lineno, "invalid comparison in \"" + std::string(line) + "\""};
        auto values = parse_int_list(number);
        if (values.empty())
            return ParseError{lineno, "missing number in \"" + std::string(line) + "\""};
        limit.value = values[0];
        req.limits.push_back(limit);
    } else if (starts_with(line, "GL_")) {
        req.extensions.emplace_back(words[0]);
    } else if (starts_with(line, "!GL_")) {
        req.absent_extensions.emplace_back(words[0].substr(1));
    } else if (starts_with(line, "GLSL") || (starts_with(line, "GL") && words[0].size() == 2)) {
        return parse_version_requirement(line, lineno, req);
    } else if (words[0] == "SIZE") {
        auto size = parse_int_list(line.substr(4));
        if (size.size() < 2 || size[0] <= 0 || size[1] <= 0 || size[0] > 16384 || size[1] > 16384)
            return ParseError{lineno, "SIZE needs a width and a height"};
        req.width = size[0];
        req.height = size[1];
    } else if (words[0] == "rlimit") {
        // We stay far below the address-space limits the tests ask for.
        if (parse_int_list(line.substr(6)).empty())
            return ParseError{lineno, "rlimit requires a numeric argument"};
    }
    // Anything else (depthbuffer, fbo, stray comment text) has no effect, as in piglit.
    return std::nullopt;
}

// ------------------------------------------------------- [vertex data] ---
Parsed<VertexColumn> parse_vertex_column(std::string_view header, int lineno) {
    VertexColumn col;
    size_t a = header.find('/');
    size_t b = a == std::string_view::npos ? a : header.find('/', a + 1);
    if (b == std::string_view::npos)
        return ParseError{lineno, "vertex data column \"" + std::string(header) +
                                      "\" is not NAME/TYPE/COUNT"};
    col.name = std::string(header.substr(0, a));
    col.type = std::string(header.substr(a + 1, b - a - 1));
    std::string_view count = header.substr(b + 1);
    if (count.find('/') != std::string_view::npos)
        return ParseError{lineno, "matrix attribute columns are not supported: " + std::string(header)};
    auto n = parse_int_list(count);
    if (n.size() != 1 || n[0] < 1 || n[0] > 4)
        return ParseError{lineno, "bad component count in \"" + std::string(header) + "\""};
    col.components = static_cast<uint32_t>(n[0]);
    if (col.type != "float" && col.type != "int" && col.type != "uint")
        return ParseError{lineno, "unsupported vertex data type \"" + col.type + "\""};
    return col;
}

Parsed<VertexData> parse_vertex_data(const std::vector<std::string_view>& lines, int first_line) {
    VertexData data;
    data.first_line = first_line;
    bool have_header = false;
    size_t row_width = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        int lineno = first_line + static_cast<int>(i);
        std::string_view line = trim(strip_hash_comment(lines[i]));
        if (line.empty()) continue;
        if (!have_header) {
            for (auto word : split_words(line)) {
                auto col = parse_vertex_column(word, lineno);
                if (!parsed_ok(col)) return std::get<ParseError>(col);
                data.columns.push_back(std::get<VertexColumn>(col));
                row_width += data.columns.back().components;
            }
            data.per_column.resize(data.columns.size());
            have_header = true;
            continue;
        }
        size_t consumed = 0;
        auto values = parse_float_list(line, &consumed);
        if (values.size() != row_width || !trim(line.substr(std::min(consumed, line.size()))).empty())
            return ParseError{lineno, "vertex data row needs " + std::to_string(row_width) +
                                          " numbers"};
        size_t k = 0;
        for (size_t c = 0; c < data.columns.size(); ++c)
            for (uint32_t j = 0; j < data.columns[c].components; ++j)
                data.per_column[c].push_back(values[k++]);
        ++data.rows;
    }
    if (!have_header) return ParseError{first_line, "[vertex data] has no header line"};
    return data;
}

// ------------------------------------------------------------ sections ---
enum class Section { None, Require, Shader, ShaderFile, Passthrough, VertexData, Test };

struct SectionKind {
    std::string_view header;
    Section section;
    ShaderStage stage;
};

constexpr SectionKind kSections[] = {
    {"[require]", Section::Require, ShaderStage::Vertex},
    {"[vertex shader]", Section::Shader, ShaderStage::Vertex},
    {"[vertex shader passthrough]", Section::Passthrough, ShaderStage::Vertex},
    {"[vertex shader file]", Section::ShaderFile, ShaderStage::Vertex},
    {"[fragment shader]", Section::Shader, ShaderStage::Fragment},
    {"[fragment shader file]", Section::ShaderFile, ShaderStage::Fragment},
    {"[vertex data]", Section::VertexData, ShaderStage::Vertex},
    {"[test]", Section::Test, ShaderStage::Vertex},
};

constexpr std::string_view kUnsupportedSections[] = {
    "[geometry shader", "[geometry layout]", "[tessellation", "[compute shader",
    "[vertex program]", "[fragment program]", "[shader include", "[elements]",
    "[vertex shader spirv]", "[fragment shader spirv]", "[vertex shader specializations]",
    "[fragment shader specializations]",
};

bool is_unsupported_section(std::string_view header) {
    for (auto prefix : kUnsupportedSections)
        if (starts_with(header, prefix)) return true;
    return false;
}

struct SectionBuilder {
    explicit SectionBuilder(ShaderTest& t) : test(t) {}
    ShaderTest& test;
    Section section = Section::None;
    std::string label;
    ShaderStage stage = ShaderStage::Vertex;
    int body_line = 0;  // first line after the header
    std::vector<std::string_view> body;

    std::optional<ParseError> finish() {
        switch (section) {
        case Section::Shader: {
            ShaderSection s{stage, label, {}, {}, body_line};
            for (auto line : body) { s.text.append(line); s.text.push_back('\n'); }
            test.shaders.push_back(std::move(s));
            break;
        }
        case Section::Passthrough:
            test.shaders.push_back({ShaderStage::Vertex, label, passthrough_vertex_shader(), {}, body_line});
            break;
        case Section::ShaderFile: {
            ShaderSection s{stage, label, {}, {}, body_line};
            for (auto line : body) {
                line = trim(line);
                if (line.empty() || line[0] == '#') continue;
                if (!s.file.empty()) return ParseError{body_line, "several files in " + label};
                s.file = std::string(split_words(line)[0]);
            }
            if (s.file.empty()) return ParseError{body_line, label + " names no file"};
            test.shaders.push_back(std::move(s));
            break;
        }
        case Section::VertexData: {
            if (test.vertex_data) return ParseError{body_line, "more than one [vertex data] section"};
            auto data = parse_vertex_data(body, body_line);
            if (!parsed_ok(data)) return std::get<ParseError>(data);
            test.vertex_data = std::move(std::get<VertexData>(data));
            break;
        }
        default:
            break;
        }
        body.clear();
        section = Section::None;
        return std::nullopt;
    }
};

std::optional<ParseError> parse_test_lines(const std::vector<std::string_view>& lines, size_t from,
                                           ShaderTest& test) {
    test.has_test_section = true;
    for (size_t i = from; i < lines.size(); ++i) {
        int lineno = static_cast<int>(i) + 1;
        auto cmd = parse_command(lines[i]);
        if (!parsed_ok(cmd)) {
            ParseError e = std::get<ParseError>(cmd);
            e.line = lineno;
            return e;
        }
        if (std::holds_alternative<Ignored>(std::get<CommandData>(cmd))) continue;
        test.commands.push_back({lineno, std::move(std::get<CommandData>(cmd))});
    }
    return std::nullopt;
}

}  // namespace

Parsed<ShaderTest> parse_shader_test(std::string_view text) {
    ShaderTest test;
    auto lines = split_lines(text);
    SectionBuilder builder(test);
    for (size_t i = 0; i < lines.size(); ++i) {
        int lineno = static_cast<int>(i) + 1;
        std::string_view line = lines[i];
        if (line.empty() || line[0] != '[') {
            if (builder.section == Section::Require) {
                if (auto e = parse_requirement(line, lineno, test.require)) return *e;
            } else if (builder.section != Section::None) {
                builder.body.push_back(line);
            }
            continue;
        }
        if (auto e = builder.finish()) return *e;
        std::string_view header = trim(line);
        const SectionKind* kind = nullptr;
        for (const auto& k : kSections)
            if (header == k.header) kind = &k;
        if (!kind) {
            if (!is_unsupported_section(header))
                return ParseError{lineno, "unknown section " + std::string(header)};
            if (!test.skip_reason) test.skip_reason = "unsupported section " + std::string(header);
            builder.section = Section::None;
            continue;
        }
        if (kind->section == Section::Test) {
            if (auto e = parse_test_lines(lines, i + 1, test)) return *e;
            break;
        }
        if (kind->section == Section::Require) test.has_require = true;
        builder.section = kind->section;
        builder.stage = kind->stage;
        builder.label = std::string(kind->header);
        builder.body_line = lineno + 1;
    }
    if (auto e = builder.finish()) return *e;
    if (!test.has_require) return ParseError{0, "[require] section missing"};
    return test;
}

std::string passthrough_vertex_shader() {
    return "#if __VERSION__ >= 130\n"
           "in vec4 piglit_vertex;\n"
           "#else\n"
           "attribute vec4 piglit_vertex;\n"
           "#endif\n"
           "void main() { gl_Position = piglit_vertex; }\n";
}

std::string effective_source(const std::string& text, const Requirements& require) {
    if (text.find("#version ") != std::string::npos || require.glsl_version == 0) return text;
    std::string version = "#version " + std::to_string(require.glsl_version);
    if (require.glsl_es && require.glsl_version != 100) version += " es";
    return version + "\n" + text;
}

std::string source_at_file_lines(const std::string& text, const Requirements& require, int first_line) {
    std::string source = effective_source(text, require);
    const bool version_added = source.size() != text.size();
    const int blank = first_line - 1 - (version_added ? 1 : 0);
    if (blank <= 0) return source;
    source.insert(version_added ? source.find('\n') + 1 : 0, size_t(blank), '\n');
    return source;
}

// ------------------------------------------------------ requirements ---
namespace {

bool compare(long required, const std::string& op, long actual) {
    // The requirement holds when "actual OP required" (piglit compares so).
    if (op == ">=") return actual >= required;
    if (op == ">") return actual > required;
    if (op == "<=") return actual <= required;
    if (op == "<") return actual < required;
    if (op == "==") return actual == required;
    return actual != required;
}

std::optional<long> capability(const Capabilities& caps, const std::string& name) {
    if (name == "GL_MAX_VARYING_COMPONENTS" || name == "GL_MAX_VARYING_FLOATS")
        return caps.max_varying_components;
    if (name == "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS") return caps.max_fragment_uniform_components;
    if (name == "GL_MAX_VERTEX_UNIFORM_COMPONENTS") return caps.max_vertex_uniform_components;
    if (name == "GL_MAX_VERTEX_ATTRIBS") return caps.max_vertex_attribs;
    if (name == "GL_MAX_CLIP_PLANES") return caps.max_clip_planes;
    return std::nullopt;
}

}  // namespace

std::optional<std::string> skip_reason(const ShaderTest& test, const Capabilities& caps) {
    if (test.skip_reason) return test.skip_reason;
    const Requirements& req = test.require;
    if (req.glsl_es || req.gl_es) return std::string("GLSL ES / GL ES tests are not supported");
    if (req.glsl_version > caps.max_glsl_version)
        return "requires GLSL " + std::to_string(req.glsl_version / 100) + "." +
               std::to_string(req.glsl_version % 100);
    if (req.gl_version > caps.max_gl_version)
        return "requires GL " + std::to_string(req.gl_version / 10) + "." +
               std::to_string(req.gl_version % 10);
    for (const auto& e : req.extensions)
        if (!caps.has_extension(e)) return "extension " + e + " is not supported";
    for (const auto& e : req.absent_extensions)
        if (caps.has_extension(e)) return "requires " + e + " to be absent";
    for (const auto& limit : req.limits) {
        auto value = capability(caps, limit.name);
        if (!value) return "unknown limit " + limit.name;
        if (!compare(limit.value, limit.op, *value))
            return "requires " + limit.name + " " + limit.op + " " + std::to_string(limit.value);
    }
    for (const auto& cmd : test.commands)
        if (auto* u = std::get_if<Unsupported>(&cmd.data)) return u->reason;
    return std::nullopt;
}

// ------------------------------------------------------- glslparsertest ---
namespace {

// Strips the comment leaders of a config line: "// key: v", " * key: v", "/* key: v".
std::string_view config_body(std::string_view line) {
    line = trim(line);
    for (std::string_view lead : {"//", "/*", "*"}) {
        if (starts_with(line, lead)) { line = trim(line.substr(lead.size())); break; }
    }
    return line;
}

std::optional<ParseError> apply_config_entry(std::string_view key, std::string_view value,
                                             int lineno, ParserTest& t, bool& have_result,
                                             bool& have_version) {
    if (key == "expect_result") {
        if (value != "pass" && value != "fail")
            return ParseError{lineno, "expect_result must be pass or fail"};
        t.expect_pass = value == "pass";
        have_result = true;
    } else if (key == "glsl_version") {
        auto words = split_words(value);
        int v = words.empty() ? -1 : parse_version_number(words[0], true);
        if (v < 0) return ParseError{lineno, "malformed glsl_version"};
        t.glsl_version = v;
        t.glsl_es = v == 100 || (words.size() > 1 && words[1] == "es");
        have_version = true;
    } else if (key == "require_extensions") {
        for (auto w : split_words(value)) t.extensions.emplace_back(w);
    } else if (key == "check_link") {
        t.check_link = value == "true";
    }
    return std::nullopt;
}

}  // namespace

Parsed<ParserTest> parse_parser_test(std::string_view text) {
    ParserTest t;
    auto lines = split_lines(text);
    bool in_config = false, saw_config = false, have_result = false, have_version = false;
    for (size_t i = 0; i < lines.size(); ++i) {
        int lineno = static_cast<int>(i) + 1;
        std::string_view body = config_body(lines[i]);
        if (!in_config) {
            if (body == "[config]") { in_config = saw_config = true; }
            continue;
        }
        if (body == "[end config]") { in_config = false; break; }
        if (body.empty()) continue;
        size_t colon = body.find(':');
        if (colon == std::string_view::npos) continue;
        auto e = apply_config_entry(trim(body.substr(0, colon)), trim(body.substr(colon + 1)),
                                    lineno, t, have_result, have_version);
        if (e) return *e;
    }
    if (!saw_config) return ParseError{0, "no [config] block"};
    if (in_config) return ParseError{0, "[config] block has no [end config]"};
    if (!have_result) return ParseError{0, "[config] block has no expect_result"};
    if (!have_version) return ParseError{0, "[config] block has no glsl_version"};
    return t;
}

}  // namespace glslrun::piglit
