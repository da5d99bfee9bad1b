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
#include <string>
#include <unordered_map>

#include "frontend/deep_stack.h"

namespace glslrun::frontend {

// As many tokens as the largest source (kMaxSourceBytes) holds without
// macros: the stack that suffices for any such source suffices for all.
constexpr uint64_t kMaxParserTokens = kMaxSourceBytes;
// Macro expansion's own work and memory: tokens of macro bodies read and
// tokens stored.
constexpr uint64_t kMaxMacroTokens = uint64_t(4) << 20;
// Members of one struct type, its nested structs' members included (an
// array of structs counts its element's members once). glslang walks a
// struct's whole member tree at every declaration, parameter and mangled
// name, and a struct of two copies of the previous one doubles that tree at
// each line: 40 such lines (1.4 KB) took glslang exponential time. The
// wrapped TParseContext::structArrayCheck sees each struct as it is defined,
// before any variable of it, and ends the parse past this limit. It bounds
// the nesting depth of structs as well.
constexpr uint64_t kMaxStructMembers = 4096;

class TokenBudgetScope {
public:
    TokenBudgetScope();
    ~TokenBudgetScope();
    TokenBudgetScope(const TokenBudgetScope&) = delete;
    TokenBudgetScope& operator=(const TokenBudgetScope&) = delete;
    // Whether glslang was cut off: its diagnostics after that are artefacts.
    bool exceeded() const { return counts_.exceeded; }

    // The first struct past kMaxStructMembers (its name empty if none).
    struct LargeStruct {
        std::string name;
        int line = 0;
    };
    const LargeStruct& large_struct() const { return counts_.large_struct; }

    struct Counts {
        uint64_t parser = 0, macro = 0;
        bool exceeded = false;
        LargeStruct large_struct;
        // Members per struct type seen (glslang's TTypeList*), so that a
        // struct's size costs its own fields only.
        std::unordered_map<const void*, uint64_t> struct_members;
    };

private:
    Counts counts_;
    Counts* saved_;
};

}  // namespace glslrun::frontend
