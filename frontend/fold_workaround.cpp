// Works around glslang 12's constant folding of `(a == b) == true` on
// aggregates: folding a vector/matrix `==` leaves a bool constant whose value
// array still has one slot per component, so comparing it with another bool
// constant compares arrays of different lengths and always yields "not
// equal". The folded result reaches the AST as a plain `false`, so it cannot
// be repaired afterwards; instead the source is rewritten before parsing:
//   (X op Y) == true,  (X op Y) != false   ->  (X op Y)
//   (X op Y) == false, (X op Y) != true    -> !(X op Y)
// (and the mirrored `true == (...)`), where op is == or != at the top level of
// the parentheses. Both sides are scalar bools there, so the rewrite is exact.
// Removed text is replaced by spaces (newlines kept): line numbers stay.
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "frontend/fold_workaround.h"

namespace glslrun::frontend {
namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t skip_ws_back(const std::string& s, size_t pos) {  // pos: one past; returns one past last non-space
    while (pos > 0 && std::isspace(static_cast<unsigned char>(s[pos - 1]))) --pos;
    return pos;
}

size_t skip_ws_fwd(const std::string& s, size_t pos) {
    while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
    return pos;
}

// Does s[open+1, close) hold a top-level == or != ?
bool has_top_level_equality(const std::string& s, size_t open, size_t close) {
    int depth = 0;
    for (size_t i = open + 1; i + 1 < close; ++i) {
        char c = s[i];
        if (c == '(' || c == '[') ++depth;
        else if (c == ')' || c == ']') --depth;
        else if (depth == 0 && (c == '=' || c == '!') && s[i + 1] == '=' && (i == 0 || (s[i - 1] != '=' && s[i - 1] != '<' && s[i - 1] != '>' && s[i - 1] != '!')))
            return true;
    }
    return false;
}

// True when the text ending at `end` (one past) cannot bind tighter than
// `==` to what follows: an opening bracket, separator or low-precedence operator.
bool safe_before(const std::string& s, size_t end) {
    end = skip_ws_back(s, end);
    if (end == 0) return true;
    char c = s[end - 1];
    if (c == '(' || c == ',' || c == ';' || c == '{' || c == '}' || c == '?' || c == ':' || c == '&' || c == '|' ||
        c == '^' || c == '[')
        return true;
    if (c == '=') {  // assignment only, not == != <= >=
        char p = end >= 2 ? s[end - 2] : ' ';
        return p != '=' && p != '!' && p != '<' && p != '>';
    }
    if (end >= 6 && s.compare(end - 6, 6, "return") == 0 && (end == 6 || !ident_char(s[end - 7]))) return true;
    return false;
}

bool safe_after(const std::string& s, size_t pos) {
    pos = skip_ws_fwd(s, pos);
    if (pos >= s.size()) return true;
    char c = s[pos];
    return c == ')' || c == ',' || c == ';' || c == '?' || c == ':' || c == '&' || c == '|' || c == '^' || c == ']' ||
           (c == '=' && pos + 1 < s.size() && s[pos + 1] == '=') || (c == '!' && pos + 1 < s.size() && s[pos + 1] == '=');
}

struct Edit {
    size_t blank_from, blank_to;  // replaced by spaces
    size_t negate_at;             // where to insert '!', or npos
};

void blank(std::string& s, size_t from, size_t to) {
    for (size_t i = from; i < to; ++i)
        if (s[i] != '\n') s[i] = ' ';
}

}  // namespace

std::string rewrite_bool_literal_compares(const std::string& src) {
    std::vector<Edit> edits;
    for (size_t i = 0; i < src.size(); ++i) {
        bool is_true = src.compare(i, 4, "true") == 0;
        bool is_false = src.compare(i, 5, "false") == 0;
        if (!is_true && !is_false) continue;
        size_t lit_end = i + (is_true ? 4 : 5);
        if ((i > 0 && ident_char(src[i - 1])) || (lit_end < src.size() && ident_char(src[lit_end]))) continue;

        // (G) op literal
        size_t op_end = skip_ws_back(src, i);
        if (op_end >= 2 && src[op_end - 1] == '=' && (src[op_end - 2] == '=' || src[op_end - 2] == '!')) {
            bool op_eq = src[op_end - 2] == '=';
            size_t close = skip_ws_back(src, op_end - 2);
            if (close > 0 && src[close - 1] == ')' && safe_after(src, lit_end)) {
                int depth = 0;
                size_t open = std::string::npos;
                for (size_t k = close; k-- > 0;) {
                    if (src[k] == ')') ++depth;
                    else if (src[k] == '(' && --depth == 0) {
                        open = k;
                        break;
                    }
                }
                // safe_before also rejects a call or constructor name before '('.
                if (open != std::string::npos && safe_before(src, open) && has_top_level_equality(src, open, close)) {
                    bool negate = op_eq != is_true;
                    edits.push_back(Edit{close, lit_end, negate ? open : std::string::npos});
                    continue;
                }
            }
        }
        // literal op (G)
        size_t op = skip_ws_fwd(src, lit_end);
        if (op + 1 < src.size() && src[op + 1] == '=' && (src[op] == '=' || src[op] == '!') && safe_before(src, i)) {
            bool op_eq = src[op] == '=';
            size_t open = skip_ws_fwd(src, op + 2);
            if (open < src.size() && src[open] == '(') {
                int depth = 0;
                size_t close = std::string::npos;
                for (size_t k = open; k < src.size(); ++k) {
                    if (src[k] == '(') ++depth;
                    else if (src[k] == ')' && --depth == 0) {
                        close = k + 1;
                        break;
                    }
                }
                if (close != std::string::npos && safe_after(src, close) && has_top_level_equality(src, open, close)) {
                    bool negate = op_eq != is_true;
                    edits.push_back(Edit{i, open, negate ? open : std::string::npos});
                }
            }
        }
    }
    if (edits.empty()) return src;
    std::string out = src;
    for (const Edit& e : edits) blank(out, e.blank_from, e.blank_to);
    std::vector<size_t> inserts;
    for (const Edit& e : edits)
        if (e.negate_at != std::string::npos) inserts.push_back(e.negate_at);
    std::sort(inserts.rbegin(), inserts.rend());
    for (size_t at : inserts) out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), '!');
    return out;
}

}  // namespace glslrun::frontend
