// Source rewrites run before glslang (see source_rewrite.h). They work on a
// light token stream (identifiers, numbers, punctuation; comments skipped,
// preprocessor lines as one token) and leave the source untouched whenever
// it does not have the shape they expect, e.g. a statement built by a macro.
#include "frontend/source_rewrite.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace glslrun::frontend {
namespace {

struct Token {
    enum Kind { Word, Punct, Directive } kind;
    size_t pos;
    std::string text;
};

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t skip_comment(const std::string& s, size_t i) {  // i at '/'; returns i if no comment starts
    if (i + 1 >= s.size()) return i;
    if (s[i + 1] == '/') {
        size_t e = s.find('\n', i);
        return e == std::string::npos ? s.size() : e;
    }
    if (s[i + 1] == '*') {
        size_t e = s.find("*/", i + 2);
        return e == std::string::npos ? s.size() : e + 2;
    }
    return i;
}

size_t directive_end(const std::string& s, size_t i) {  // the line, with backslash continuations
    while (i < s.size() && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') ++i;
        ++i;
    }
    return i;
}

std::vector<Token> lex(const std::string& s) {
    std::vector<Token> out;
    bool line_start = true;
    for (size_t i = 0; i < s.size();) {
        char c = s[i];
        if (c == '\n') line_start = true;
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
            continue;
        }
        if (c == '/' && skip_comment(s, i) != i) {
            i = skip_comment(s, i);
            continue;
        }
        if (c == '#' && line_start) {
            size_t e = directive_end(s, i);
            out.push_back({Token::Directive, i, s.substr(i, e - i)});
            i = e;
            continue;
        }
        line_start = false;
        size_t e = i + 1;
        if (word_char(c))
            while (e < s.size() && (word_char(s[e]) || s[e] == '.')) ++e;
        out.push_back({word_char(c) ? Token::Word : Token::Punct, i, s.substr(i, e - i)});
        i = e;
    }
    return out;
}

// Recognizes one statement's extent in the token stream; nullopt where the
// tokens do not form one on their own (preprocessor lines, macro bodies).
class StatementScanner {
public:
    explicit StatementScanner(const std::vector<Token>& t) : t_(t) {}

    std::optional<size_t> statement(size_t i, int depth = 0) const {
        if (i >= t_.size() || depth > 64 || t_[i].kind == Token::Directive) return std::nullopt;
        const std::string& w = t_[i].text;
        if (w == "{") return balanced(i, "{", "}");
        if (w == "}") return std::nullopt;
        if (w == "if") {
            auto body = paren_then_statement(i + 1, depth);
            if (body && is(*body, "else")) return statement(*body + 1, depth + 1);
            return body;
        }
        if (w == "for" || w == "while") return paren_then_statement(i + 1, depth);
        if (w == "do") {
            auto body = statement(i + 1, depth + 1);
            if (!body || !is(*body, "while")) return std::nullopt;
            auto test = balanced(*body + 1, "(", ")");
            if (!test || !is(*test, ";")) return std::nullopt;
            return *test + 1;
        }
        return simple(i);
    }

    bool is(size_t i, const char* text) const { return i < t_.size() && t_[i].text == text; }

private:
    std::optional<size_t> paren_then_statement(size_t i, int depth) const {
        auto after = balanced(i, "(", ")");
        if (!after) return std::nullopt;
        return statement(*after, depth + 1);
    }

    // i at `open`; returns one past the matching `close`.
    std::optional<size_t> balanced(size_t i, const char* open, const char* close) const {
        if (!is(i, open)) return std::nullopt;
        int level = 0;
        for (; i < t_.size(); ++i) {
            if (t_[i].kind == Token::Directive) return std::nullopt;
            if (t_[i].text == open) ++level;
            else if (t_[i].text == close && --level == 0) return i + 1;
        }
        return std::nullopt;
    }

    // An expression or declaration statement: up to `;` outside brackets.
    std::optional<size_t> simple(size_t i) const {
        int level = 0;
        for (; i < t_.size(); ++i) {
            const Token& tok = t_[i];
            if (tok.kind == Token::Directive || tok.text == "{" || tok.text == "}") return std::nullopt;
            if (tok.text == "(" || tok.text == "[") ++level;
            else if (tok.text == ")" || tok.text == "]") --level;
            else if (tok.text == ";" && level == 0) return i + 1;
            if (level < 0) return std::nullopt;
        }
        return std::nullopt;
    }

    const std::vector<Token>& t_;
};

}  // namespace

std::string brace_do_while_bodies(const std::string& src) {
    if (src.find("do") == std::string::npos) return src;
    std::vector<Token> tokens = lex(src);
    StatementScanner scan(tokens);
    std::vector<std::pair<size_t, char>> inserts;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].text != "do" || scan.is(i + 1, "{")) continue;
        auto end = scan.statement(i + 1);
        if (!end || !scan.is(*end, "while")) continue;
        inserts.emplace_back(tokens[i + 1].pos, '{');
        inserts.emplace_back(tokens[*end].pos, '}');
    }
    if (inserts.empty()) return src;
    std::stable_sort(inserts.begin(), inserts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string out = src;
    for (const auto& [pos, c] : inserts) out.insert(pos, 1, c);
    return out;
}

std::string splice_line_continuations(const std::string& src) {
    if (src.find('\\') == std::string::npos) return src;
    std::string out;
    out.reserve(src.size());
    size_t pending = 0;
    for (size_t i = 0; i < src.size(); ++i) {
        if (src[i] == '\\') {
            size_t nl = i + 1 < src.size() && src[i + 1] == '\r' ? i + 2 : i + 1;
            if (nl < src.size() && src[nl] == '\n') {
                ++pending;
                i = nl;
                continue;
            }
        }
        out += src[i];
        if (src[i] == '\n') {
            out.append(pending, '\n');
            pending = 0;
        }
    }
    out.append(pending, '\n');
    return out;
}

namespace {

std::string padded(const std::string& text, size_t width) {
    return text + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

bool is_predefined(std::string_view word) { return word == "__VERSION__" || word == "__LINE__" || word == "__FILE__"; }

// A cursor over one preprocessor line. The rewrites scan by hand, not with
// std::regex: its backtracking recurses once per character and overflows the
// stack on a long line of user text.
struct LineCursor {
    std::string_view s;
    size_t i = 0;

    bool at_end() const { return i >= s.size(); }
    size_t skip_space() {
        size_t from = i;
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        return i - from;
    }
    bool eat(char c) {
        if (i >= s.size() || s[i] != c) return false;
        ++i;
        return true;
    }
    std::string_view word() {
        size_t from = i;
        while (i < s.size() && word_char(s[i])) ++i;
        return s.substr(from, i - from);
    }
    // `#` and the directive's name, after optional blanks; empty if none.
    std::string_view directive() {
        skip_space();
        if (!eat('#')) return {};
        skip_space();
        return word();
    }
};

// At `defined` (i at its first character): the length of `defined X` or
// `defined ( X )` with X predefined, or 0.
size_t defined_predefined_length(std::string_view line, size_t at) {
    LineCursor c{line, at};
    if (c.word() != "defined") return 0;
    size_t blanks = c.skip_space();
    bool paren = c.eat('(');
    if (paren) c.skip_space();
    else if (blanks == 0) return 0;
    if (!is_predefined(c.word())) return 0;
    if (paren && (c.skip_space(), !c.eat(')'))) return 0;
    return c.i - at;
}

std::string rewrite_directive(const std::string& line) {
    LineCursor c{line};
    std::string_view name = c.directive();
    if (name == "ifdef" || name == "ifndef") {
        size_t name_end = c.i;
        LineCursor operand = c;
        if (operand.skip_space() > 0 && is_predefined(operand.word())) {
            std::string repl = line.substr(0, name_end - name.size()) + (name == "ifdef" ? "if 1" : "if 0");
            return padded(repl, operand.i) + line.substr(operand.i);
        }
        return line;
    }
    if (name != "if" && name != "elif") return line;
    std::string out;
    for (size_t i = 0; i < line.size();) {
        bool word_start = i == 0 || !word_char(line[i - 1]);
        size_t n = word_start ? defined_predefined_length(line, i) : 0;
        if (n > 0) {
            out += padded("1", n);
            i += n;
        } else {
            out += line[i++];
        }
    }
    return out;
}

}  // namespace

std::string define_predefined_macros(const std::string& src) {
    if (src.find("__VERSION__") == std::string::npos && src.find("__LINE__") == std::string::npos &&
        src.find("__FILE__") == std::string::npos)
        return src;
    std::string out;
    size_t start = 0;
    while (start < src.size()) {
        size_t end = src.find('\n', start);
        if (end == std::string::npos) end = src.size();
        std::string line = src.substr(start, end - start);
        size_t first = line.find_first_not_of(" \t");
        out += first != std::string::npos && line[first] == '#' ? rewrite_directive(line) : line;
        if (end < src.size()) out += '\n';
        start = end + 1;
    }
    return out;
}

namespace {

TokenPos position_of(const std::string& src, size_t pos) {
    TokenPos p;
    p.line = 1 + int(std::count(src.begin(), src.begin() + long(pos), '\n'));
    size_t line_start = src.rfind('\n', pos == 0 ? 0 : pos - 1);
    p.column = int(line_start == std::string::npos || pos == 0 ? pos : pos - line_start - 1);
    return p;
}

bool is_word(const Token& t) { return t.kind == Token::Word && !std::isdigit(static_cast<unsigned char>(t.text[0])); }

// A `+` token is unary unless it follows an operand.
bool unary_position(const std::vector<Token>& t, size_t i) {
    if (i == 0) return true;
    const Token& prev = t[i - 1];
    if (prev.kind == Token::Word) return prev.text == "return" || prev.text == "else" || prev.text == "do";
    if (prev.text == ")" || prev.text == "]") return false;
    return prev.text != "+" || prev.pos + 1 != t[i].pos;  // `++` is not `+ +`
}

}  // namespace

std::vector<UnaryPlusOperand> unary_plus_operands(const std::string& src) {
    std::vector<UnaryPlusOperand> out;
    if (src.find('+') == std::string::npos) return out;
    std::vector<Token> t = lex(src);
    auto postfix_at = [&](size_t k) { return k < t.size() && (t[k].text == "[" || t[k].text[0] == '.'); };
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        // Words hold their `.field` suffixes; those operands are not plain.
        if (t[i].text != "+" || !unary_position(t, i) || !is_word(t[i + 1]) ||
            t[i + 1].text.find('.') != std::string::npos || postfix_at(i + 2))
            continue;
        bool call = i + 2 < t.size() && t[i + 2].text == "(";
        size_t at = i + 1;
        if (call) {
            int level = 0;
            size_t k = i + 2;
            for (; k < t.size(); ++k) {
                if (t[k].text == "(") ++level;
                else if (t[k].text == ")" && --level == 0) break;
            }
            if (k >= t.size() || postfix_at(k + 1)) continue;
            at = k;
        }
        out.push_back({position_of(src, t[at].pos), call});
    }
    return out;
}

static bool is_vector_type(std::string_view w) {
    if (!w.empty() && (w[0] == 'b' || w[0] == 'i' || w[0] == 'u')) w.remove_prefix(1);
    return w.size() == 4 && w.substr(0, 3) == "vec" && w[3] >= '2' && w[3] <= '4';
}

std::vector<TokenPos> vector_constructor_subscripts(const std::string& src) {
    std::vector<TokenPos> out;
    if (src.find("vec") == std::string::npos) return out;
    std::vector<Token> t = lex(src);
    for (size_t i = 0; i + 2 < t.size(); ++i) {
        if (t[i].text != "[" || !is_vector_type(t[i + 1].text) || t[i + 2].text != "(") continue;
        int level = 0;
        size_t k = i + 2;
        for (; k < t.size(); ++k) {
            if (t[k].kind == Token::Directive) break;
            if (t[k].text == "(") ++level;
            else if (t[k].text == ")" && --level == 0) break;
        }
        if (k + 1 < t.size() && t[k + 1].text == "]") out.push_back(position_of(src, t[i].pos));
    }
    return out;
}

std::string drop_float_suffixes(const std::string& src) {
    if (src.find_first_of("fF") == std::string::npos) return src;
    std::string out = src;
    for (size_t i = 0; i < out.size();) {
        if (out[i] == '/' && skip_comment(out, i) != i) {
            i = skip_comment(out, i);
            continue;
        }
        bool starts_number = std::isdigit(static_cast<unsigned char>(out[i])) ||
                             (out[i] == '.' && i + 1 < out.size() && std::isdigit(static_cast<unsigned char>(out[i + 1])));
        if (!starts_number || (i > 0 && word_char(out[i - 1]))) {
            ++i;
            continue;
        }
        size_t e = i;
        while (e < out.size() && (word_char(out[e]) || out[e] == '.' ||
                                  ((out[e] == '+' || out[e] == '-') && (out[e - 1] == 'e' || out[e - 1] == 'E'))))
            ++e;
        std::string lit = out.substr(i, e - i);
        bool hex = lit.size() > 1 && lit[0] == '0' && (lit[1] == 'x' || lit[1] == 'X');
        bool is_float = lit.find_first_of(".eE") != std::string::npos;
        if (!hex && is_float && (lit.back() == 'f' || lit.back() == 'F')) out[e - 1] = ' ';
        i = e;
    }
    return out;
}

std::vector<int> stringification_lines(const std::string& src) {
    std::vector<int> out;
    if (src.find("define") == std::string::npos) return out;
    int conditional_depth = 0;  // only definitions outside any #if are surely not skipped
    for (const Token& t : lex(src)) {
        if (t.kind != Token::Directive) continue;
        LineCursor c{t.text};
        std::string_view name = c.directive();
        if (name.substr(0, 2) == "if") ++conditional_depth;
        if (name.substr(0, 5) == "endif" && conditional_depth > 0) --conditional_depth;
        if (conditional_depth > 0 || name != "define" || c.skip_space() == 0 || c.word().empty() || !c.eat('('))
            continue;
        size_t close = t.text.find(')', c.i);
        if (close == std::string::npos) continue;
        std::string_view body = std::string_view(t.text).substr(close + 1);
        for (size_t k = 0; k < body.size(); ++k) {
            if (body[k] != '#') continue;
            if (k + 1 < body.size() && body[k + 1] == '#') {
                ++k;  // `##` token pasting
                continue;
            }
            out.push_back(position_of(src, t.pos).line);
            break;
        }
    }
    return out;
}

}  // namespace glslrun::frontend

namespace glslrun::frontend {

std::vector<TokenPos> word_positions(const std::string& src, const std::vector<std::string>& words) {
    std::vector<TokenPos> out;
    bool any = false;
    for (const std::string& w : words) any = any || src.find(w) != std::string::npos;
    if (!any) return out;
    for (const Token& t : lex(src))
        if (t.kind == Token::Word && std::find(words.begin(), words.end(), t.text) != words.end())
            out.push_back(position_of(src, t.pos));
    return out;
}

}  // namespace glslrun::frontend

namespace glslrun::frontend {
namespace {

// The first named structure definition nested in another one's braces:
// {outer `struct` position, nested `struct` position, one past its `}`}.
struct NestedStruct {
    size_t outer, begin, end, name_end;
};

std::optional<NestedStruct> find_nested_struct(const std::vector<Token>& t) {
    std::vector<std::pair<size_t, int>> open;  // enclosing definitions: `struct` position, brace depth inside
    int depth = 0;
    for (size_t i = 0; i < t.size(); ++i) {
        if (t[i].text == "{") ++depth;
        if (t[i].text == "}") {
            --depth;
            if (!open.empty() && depth < open.back().second) open.pop_back();
        }
        bool named_definition = t[i].text == "struct" && i + 2 < t.size() && t[i + 1].kind == Token::Word && t[i + 2].text == "{";
        if (!named_definition) continue;
        if (!open.empty()) {
            int level = 0;
            for (size_t k = i + 2; k < t.size(); ++k) {
                if (t[k].text == "{") ++level;
                else if (t[k].text == "}" && --level == 0)
                    return NestedStruct{open.back().first, t[i].pos, t[k].pos + 1, t[i + 1].pos + t[i + 1].text.size()};
            }
            return std::nullopt;
        }
        open.emplace_back(t[i].pos, depth + 1);
    }
    return std::nullopt;
}

}  // namespace

std::string hoist_nested_structs(const std::string& src) {
    if (src.find("struct") == std::string::npos) return src;
    std::string s = src;
    for (int round = 0; round < 64; ++round) {
        std::optional<NestedStruct> n = find_nested_struct(lex(s));
        if (!n) break;
        std::string definition = s.substr(n->begin, n->end - n->begin);
        std::replace(definition.begin(), definition.end(), '\n', ' ');
        std::string in_place = s.substr(n->begin, n->end - n->begin);
        size_t name_at = n->name_end - n->begin;
        std::string name = s.substr(n->begin, name_at);  // "struct NAME"
        for (size_t k = 0; k < in_place.size(); ++k)
            if (in_place[k] != '\n') in_place[k] = ' ';
        std::string type = name.substr(name.find_last_of(" \t\n") + 1);
        in_place.replace(0, type.size(), type);
        s = s.substr(0, n->outer) + definition + "; " + s.substr(n->outer, n->begin - n->outer) + in_place + s.substr(n->end);
    }
    return s;
}

}  // namespace glslrun::frontend

namespace glslrun::frontend {

std::vector<DirectiveProblem> directive_problems(const std::string& src) {
    std::vector<DirectiveProblem> out;
    if (src.find('#') == std::string::npos) return out;
    bool seen_code = false;
    for (const Token& t : lex(src)) {
        if (t.kind != Token::Directive) {
            seen_code = true;
            continue;
        }
        std::istringstream words(t.text.substr(1));
        std::string directive, name;
        words >> directive >> name;
        name = name.substr(0, name.find('('));
        int line = position_of(src, t.pos).line;
        if ((directive == "define" || directive == "undef") &&
            (name == "__LINE__" || name == "__FILE__" || name == "__VERSION__"))
            out.push_back({line, "'#" + directive + "' : the predefined macro " + name + " cannot be redefined or undefined"});
        if (directive == "extension" && seen_code)
            out.push_back({line, "'#extension' : must come before any code that is not a preprocessor directive"});
    }
    return out;
}

}  // namespace glslrun::frontend

namespace glslrun::frontend {

std::string extension_macros() {
    std::string out;
    for (std::string_view name : kExtraExtensions) out += "#define " + std::string(name) + " 1\n";
    return out;
}

std::string accept_extension_directives(const std::string& src) {
    if (src.find("extension") == std::string::npos) return src;
    std::string out = src;
    for (const Token& t : lex(src)) {
        // One after code stays, for directive_problems to refuse.
        if (t.kind != Token::Directive) break;
        // `# extension NAME : behavior // comment`, spaces optional around ':'.
        std::string line = t.text.substr(0, t.text.find("//")).substr(1);
        bool one_colon = std::count(line.begin(), line.end(), ':') == 1;
        std::replace(line.begin(), line.end(), ':', ' ');
        std::istringstream words(line);
        std::string directive, name, behavior, rest;
        words >> directive >> name >> behavior >> rest;
        bool known = std::find(kExtraExtensions.begin(), kExtraExtensions.end(), name) != kExtraExtensions.end();
        bool valid = one_colon && rest.empty() &&
                     (behavior == "require" || behavior == "enable" || behavior == "warn" || behavior == "disable");
        if (directive != "extension" || !known || !valid) continue;
        for (size_t k = t.pos; k < t.pos + t.text.size(); ++k)
            if (out[k] != '\n') out[k] = ' ';
    }
    return out;
}

}  // namespace glslrun::frontend
