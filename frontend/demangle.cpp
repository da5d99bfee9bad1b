// glslang's mangled parameter types (TType::buildMangledName, glslang 12):
// 'm' (matrix) or 'v' (vector), a basic-type letter, then the vector size or
// the matrix's columns and rows as digits, then `[N]` per array dimension,
// then ';'. Samplers are 's' with 'A' (array) and 'S' (shadow), the
// dimension (1, 2, 3, C, R2) and the vector size 1, after 'i'/'u' for
// integer ones; structures are `struct-Name`, then '-' and each member's
// type, then the size 1.
#include "frontend/demangle.h"

#include <cctype>
#include <optional>

namespace glslrun::frontend {
namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class Parser {
public:
    Parser(const std::string& s, size_t i) : s_(s), i_(i) {}
    size_t pos() const { return i_; }

    // One type, without the ';'.
    std::optional<std::string> type() {
        std::optional<std::string> t = base();
        if (!t) return std::nullopt;
        while (eat('[')) {
            size_t start = i_;
            while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
            std::string size = s_.substr(start, i_ - start);
            if (size.empty() || !eat(']')) return std::nullopt;
            *t += "[" + size + "]";
        }
        return t;
    }
    bool eat(char c) {
        if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
        return false;
    }

private:
    std::optional<std::string> base() {
        if (s_.compare(i_, 7, "struct-") == 0) return structure();
        bool matrix = eat('m'), vector = !matrix && eat('v');
        char kind = next();
        if (kind == 'i' || kind == 'u') {
            if (!matrix && !vector && peek() == 's') return sampler(kind == 'i' ? "isampler" : "usampler");
        } else if (kind == 's' && !matrix && !vector) {
            --i_;
            return sampler("sampler");
        } else if (kind != 'f' && kind != 'b') {
            return std::nullopt;
        }
        int a = digit(), b = matrix ? digit() : 0;
        if (matrix) {
            if (kind != 'f' || a < 2 || a > 4 || b < 2 || b > 4) return std::nullopt;
            return a == b ? "mat" + std::to_string(a) : "mat" + std::to_string(a) + "x" + std::to_string(b);
        }
        static const char* const kScalars[] = {"float", "int", "uint", "bool"};
        static const char* const kVectors[] = {"vec", "ivec", "uvec", "bvec"};
        int k = kind == 'f' ? 0 : kind == 'i' ? 1 : kind == 'u' ? 2 : 3;
        if (!vector) return a == 1 ? std::optional<std::string>(kScalars[k]) : std::nullopt;
        if (a < 2 || a > 4) return std::nullopt;
        return kVectors[k] + std::to_string(a);
    }
    std::optional<std::string> sampler(std::string name) {
        if (!eat('s')) return std::nullopt;
        bool array = eat('A'), shadow = eat('S');
        char d = next();
        std::string dim = d == '1' ? "1D" : d == '2' ? "2D" : d == '3' ? "3D" : d == 'C' ? "Cube" : "";
        if (d == 'R' && eat('2')) dim = "2DRect";
        if (dim.empty() || digit() != 1) return std::nullopt;
        return name + dim + (array ? "Array" : "") + (shadow ? "Shadow" : "");
    }
    std::optional<std::string> structure() {
        i_ += 7;
        size_t start = i_;
        while (i_ < s_.size() && ident_char(s_[i_])) ++i_;
        if (start == i_) return std::nullopt;
        std::string name = s_.substr(start, i_ - start);
        while (eat('-'))
            if (!type()) return std::nullopt;
        if (digit() != 1) return std::nullopt;
        return name;
    }
    char next() { return i_ < s_.size() ? s_[i_++] : '\0'; }
    char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
    int digit() {
        char c = next();
        return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : -1;
    }

    const std::string& s_;
    size_t i_;
};

// The signature of the mangled name whose '(' is at `open`, and where it ends.
std::optional<std::pair<std::string, size_t>> parameters(const std::string& s, size_t open) {
    Parser p(s, open + 1);
    std::string list;
    while (p.pos() < s.size() && !std::isspace(static_cast<unsigned char>(s[p.pos()]))) {
        std::optional<std::string> t = p.type();
        if (!t || !p.eat(';')) return std::nullopt;
        list += (list.empty() ? "" : ", ") + *t;
    }
    return std::pair{"(" + list + ")", p.pos()};
}

}  // namespace

std::string demangle_signatures(const std::string& text) {
    std::string out;
    size_t copied = 0;
    for (size_t open = text.find('('); open != std::string::npos; open = text.find('(', open + 1)) {
        if (open == 0 || !ident_char(text[open - 1])) continue;
        auto params = parameters(text, open);
        if (!params) continue;
        out += text.substr(copied, open - copied) + params->first;
        copied = params->second;
        open = copied - 1;
    }
    return out + text.substr(copied);
}

}  // namespace glslrun::frontend
