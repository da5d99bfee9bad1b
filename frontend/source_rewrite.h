// Internal to frontend/: source rewrites applied before glslang parses a
// unit, for places where glslang 12 departs from GLSL 1.10/1.20 and the AST
// can no longer be repaired. Each keeps line numbers unchanged.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace glslrun::frontend {

// `do S while (E);` with a non-compound body S becomes `do {S} while (E);`.
// GLSL (1.10 §6.3, clarified in later specs) makes the body a scope of its
// own that does not include the test; glslang lets a declaration in a
// non-compound body shadow the test's names. Braces give the spec's scoping.
std::string brace_do_while_bodies(const std::string& src);

// GLSL 1.10 §4.1.8 allows a named structure definition inside another one
// (its name is scoped like the enclosing structure; GLSL 1.20 forbids it, as
// Mesa reads both); glslang rejects it. For 1.10 units only.
// Each nested definition moves, on one line, in front of the outermost
// enclosing `struct`, leaving its name in place.
std::string hoist_nested_structs(const std::string& src);

// Mesa compatibility: backslash-newline line continuation is spliced in every
// GLSL version, as Mesa's preprocessor does (glslang accepts it only from
// GLSL 4.20, even inside a skipped #ifdef, and piglit relies on Mesa here).
// The removed newlines are re-emitted after the logical line, so every line
// after it keeps its number.
std::string splice_line_continuations(const std::string& src);

// __VERSION__, __LINE__ and __FILE__ are predefined macros (GLSL 1.10 §3.3),
// but glslang's `defined` does not see them. In #if/#elif lines,
// `defined X` / `defined(X)` becomes 1, and #ifdef X / #ifndef X become
// #if 1 / #if 0 (they cannot be #undef'd, so this is exact).
std::string define_predefined_macros(const std::string& src);

// Mesa compatibility: `defined` that an object-like macro's expansion puts
// into an #if or #elif is evaluated (glslang refuses it; C leaves it
// undefined). Such macros are expanded in #if/#elif lines before glslang
// sees them, with the definitions in force at that line.
std::string expand_defined_macros(const std::string& src);

// GLSL extensions that glslrun enables in every shader of both stages, as
// Mesa does in a compatibility context, and that glslang 12 does not know:
// their macros are defined to 1 (extension_macros, for the preamble), and
// `#extension NAME : require|enable|warn|disable` lines become blank
// (accept_extension_directives). GL_ARB_draw_buffers adds gl_FragData and
// gl_MaxDrawBuffers, which GLSL 1.10 has anyway.
inline constexpr std::array<std::string_view, 1> kExtraExtensions{"GL_ARB_draw_buffers"};
std::string extension_macros();
// Extensions glslang knows that glslrun enables in every shader of both
// stages, as Mesa does in a compatibility context (the preamble's
// `#extension NAME : enable`; the source may still disable one).
inline constexpr std::array<std::string_view, 1> kDefaultExtensions{"GL_ARB_texture_rectangle"};
// Extensions glslrun implements that a shader enables with `#extension
// NAME : enable|require` (as in Mesa): ARB_shader_texture_lod's *Lod in the
// fragment shader and the *GradARB functions (glslang's, with its macro);
// EXT_texture_array's array samplers (taught to glslang in texture_array.cpp).
inline constexpr std::array<std::string_view, 2> kOptionalExtensions{"GL_ARB_shader_texture_lod",
                                                                     "GL_EXT_texture_array"};
std::string accept_extension_directives(const std::string& src);

// Mesa compatibility: a float literal's `f`/`F` suffix is accepted in GLSL
// 1.10 as Mesa's lexer does (glslang requires 1.20, and piglit relies on
// Mesa). The suffix becomes a space; hex integers are left alone.
std::string drop_float_suffixes(const std::string& src);

// Lines of function-like #define bodies that use the `#` stringification
// operator, which GLSL does not have (glslang accepts it). Only definitions
// outside every #if/#ifdef are checked: one in a skipped region is legal.
std::vector<int> stringification_lines(const std::string& src);

// Directives GLSL 1.10 §3.3 forbids that glslang accepts: #define or #undef
// of __LINE__, __FILE__, __VERSION__ (predefined; Mesa refuses too, and
// define_predefined_macros relies on it), and #extension after code (the
// default granularity is the whole shader, so it comes first).
struct DirectiveProblem {
    int line = 0;
    std::string message;
};
std::vector<DirectiveProblem> directive_problems(const std::string& src);

// Token-level views of the source for checks the AST cannot make (the AST
// drops unary `+` and the type of an array-size expression). Positions are
// 1-based lines and 0-based columns of the token's first character.
struct TokenPos {
    int line = 0, column = 0;
};
// Operands of a unary `+` that are a plain name or a call (`+a`, `+f(...)`),
// with no postfix operator after them; `call` tells which. The position is
// the name's, or a call's closing parenthesis (where glslang locates calls).
struct UnaryPlusOperand {
    TokenPos pos;
    bool call = false;
};
std::vector<UnaryPlusOperand> unary_plus_operands(const std::string& src);
// Identifiers (outside comments and directives) that are one of `words`.
std::vector<TokenPos> word_positions(const std::string& src, const std::vector<std::string>& words);
// The structures defined at global scope (`struct Name {` outside every
// brace), by name, with their positions.
struct NamedPos {
    std::string name;
    TokenPos pos;
};
std::vector<NamedPos> global_struct_names(const std::string& src);
// `[` directly holding nothing but a vector constructor: `[ivec2(2, 2)]`.
std::vector<TokenPos> vector_constructor_subscripts(const std::string& src);

}  // namespace glslrun::frontend
