// The token budgets of frontend/token_budget.h: the glslang functions that
// ld's --wrap (CMakeLists.txt) redirects here count against the scope active
// on the thread and, past a budget, return the end of the input or drop the
// token.
// TParseContext::structArrayCheck, called once per struct definition with
// the new type, counts its members against kMaxStructMembers and, past it,
// ends the parse.
// No glslang code changes; the ABI is that of the installed headers
// (glslang/MachineIndependent/preprocessor/PpContext.h, Scan.h).
#include "frontend/token_budget.h"

#include "frontend/texture_array.h"

#include <algorithm>

#include <glslang/MachineIndependent/ParseHelper.h>

namespace {

constexpr int kEndOfInput = -1;  // glslang's EndOfInput (Scan.h)
constexpr int kParserEnd = 0;    // what yylex returns at the end of the input (bison's YYEOF)

thread_local glslrun::frontend::TokenBudgetScope::Counts* active = nullptr;

// Counts one token of the active scope's `used` against `budget`: false
// once past either budget.
bool spend(uint64_t& used, uint64_t budget) {
    if (++used > budget) active->exceeded = true;
    return !active->exceeded;
}

// A struct's members, nested ones included, memoised by its member list,
// which every member of that struct type shares: linear in the source even
// when the member tree is exponential.
uint64_t members_of(const glslang::TType& type, std::unordered_map<const void*, uint64_t>& memo) {
    constexpr uint64_t kPast = glslrun::frontend::kMaxStructMembers + 1;
    if (!type.isStruct() || !type.getStruct()) return 0;
    const glslang::TTypeList* list = type.getStruct();
    if (auto it = memo.find(list); it != memo.end()) return it->second;
    uint64_t n = 0;
    for (const glslang::TTypeLoc& member : *list) n = std::min(n + 1 + members_of(*member.type, memo), kPast);
    memo.emplace(list, n);
    return n;
}

}  // namespace

extern "C" {
// int yylex(YYSTYPE*, glslang::TParseContext&): the parser's next token.
int __real__Z5yylexP7YYSTYPERN7glslang13TParseContextE(void* value, void* context);
int __wrap__Z5yylexP7YYSTYPERN7glslang13TParseContextE(void* value, void* context) {
    if (active && !spend(active->parser, glslrun::frontend::kMaxParserTokens)) return kParserEnd;
    const int token = __real__Z5yylexP7YYSTYPERN7glslang13TParseContextE(value, context);
    // EXT_texture_array's types and functions (texture_array.cpp).
    return glslrun::frontend::texture_array_token(token, value, *static_cast<glslang::TParseContext*>(context));
}

// int TPpContext::TokenStream::getToken(TParseContextBase&, TPpToken*): the
// next token of a macro body (the calls from Pp.cpp; glslang's own file
// reads expanded arguments without passing here).
int __real__ZN7glslang10TPpContext11TokenStream8getTokenERNS_17TParseContextBaseEPNS_8TPpTokenE(void* self,
                                                                                                void* context,
                                                                                                void* token);
int __wrap__ZN7glslang10TPpContext11TokenStream8getTokenERNS_17TParseContextBaseEPNS_8TPpTokenE(void* self,
                                                                                                void* context,
                                                                                                void* token) {
    if (active && !spend(active->macro, glslrun::frontend::kMaxMacroTokens)) return kEndOfInput;
    return __real__ZN7glslang10TPpContext11TokenStream8getTokenERNS_17TParseContextBaseEPNS_8TPpTokenE(self, context,
                                                                                                       token);
}

// void TPpContext::TokenStream::putToken(int, TPpToken*): a token stored in
// a macro body or an expanded argument. Past the budget it is dropped.
void __real__ZN7glslang10TPpContext11TokenStream8putTokenEiPNS_8TPpTokenE(void* self, int token, void* pp_token);
void __wrap__ZN7glslang10TPpContext11TokenStream8putTokenEiPNS_8TPpTokenE(void* self, int token, void* pp_token) {
    if (active && !spend(active->macro, glslrun::frontend::kMaxMacroTokens)) return;
    __real__ZN7glslang10TPpContext11TokenStream8putTokenEiPNS_8TPpTokenE(self, token, pp_token);
}

// void TParseContext::structArrayCheck(const TSourceLoc&, const TType&).
void __real__ZN7glslang13TParseContext16structArrayCheckERKNS_10TSourceLocERKNS_5TTypeE(void* self,
                                                                                        const glslang::TSourceLoc& loc,
                                                                                        const glslang::TType& type);
void __wrap__ZN7glslang13TParseContext16structArrayCheckERKNS_10TSourceLocERKNS_5TTypeE(void* self,
                                                                                        const glslang::TSourceLoc& loc,
                                                                                        const glslang::TType& type) {
    __real__ZN7glslang13TParseContext16structArrayCheckERKNS_10TSourceLocERKNS_5TTypeE(self, loc, type);
    if (!active || active->exceeded) return;
    if (members_of(type, active->struct_members) <= glslrun::frontend::kMaxStructMembers) return;
    active->large_struct = {type.getTypeName().c_str(), loc.line};
    active->exceeded = true;  // the parser sees the end of its input from here on
}
}

namespace glslrun::frontend {

TokenBudgetScope::TokenBudgetScope() : saved_(active) { active = &counts_; }
TokenBudgetScope::~TokenBudgetScope() { active = saved_; }

}  // namespace glslrun::frontend
