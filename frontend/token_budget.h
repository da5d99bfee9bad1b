// Internal to frontend/: a bound on what glslang's preprocessor makes of a
// source. Macros multiply: with `#define A1 x+x` and `#define A2 A1+A1` up to
// A20, a 427-byte shader holds an expression of 2^20 terms, nested deeper
// than the compile thread's stack allows (frontend/deep_stack.h), and each
// further line doubles the time and memory. CMakeLists.txt links with ld's
// --wrap for three glslang functions, so that while a TokenBudgetScope is
// active on the thread, glslang counts the tokens its parser reads (yylex),
// the tokens of macro bodies it reads (TokenStream::getToken, from Pp.cpp:
// expansions in `#if` count too) and the tokens it stores (putToken: macro
// arguments, expanded before they are substituted). Past either budget
// glslang sees the end of its input, and the scope says so. Not counted:
// re-reading an expanded argument once per use in a body, which repeats
// only what was stored.
#pragma once
#include <cstdint>

#include "frontend/deep_stack.h"

namespace glslrun::frontend {

// As many tokens as the largest source (kMaxSourceBytes) holds without
// macros: the stack that suffices for any such source suffices for all.
constexpr uint64_t kMaxParserTokens = kMaxSourceBytes;
// Macro expansion's own work and memory: tokens of macro bodies read and
// tokens stored.
constexpr uint64_t kMaxMacroTokens = uint64_t(4) << 20;

class TokenBudgetScope {
public:
    TokenBudgetScope();
    ~TokenBudgetScope();
    TokenBudgetScope(const TokenBudgetScope&) = delete;
    TokenBudgetScope& operator=(const TokenBudgetScope&) = delete;
    // Whether glslang was cut off: its diagnostics after that are artefacts.
    bool exceeded() const { return counts_.exceeded; }

    struct Counts {
        uint64_t parser = 0, macro = 0;
        bool exceeded = false;
    };

private:
    Counts counts_;
    Counts* saved_;
};

}  // namespace glslrun::frontend
