// Internal to frontend/: EXT_texture_array in GLSL 1.10/1.20 units, taught
// to glslang 12 (which has the types only from GLSL 1.30 and does not know
// the extension) without patching it. See texture_array.cpp.
#pragma once

namespace glslang {
class TParseContext;
}

namespace glslrun::frontend {

inline constexpr const char* kTextureArrayExtension = "GL_EXT_texture_array";

// While a unit parses on this thread: whether its `#extension
// GL_EXT_texture_array` directives, as glslang's preprocessor reaches them,
// have turned the extension on (enable, require, warn; disable turns it off),
// as Mesa does. glslang's callbacks cannot see the unit, hence a thread-local
// setting for the parse, like FoldVersionScope.
class TextureArrayScope {
public:
    TextureArrayScope();
    ~TextureArrayScope();
    TextureArrayScope(const TextureArrayScope&) = delete;
    TextureArrayScope& operator=(const TextureArrayScope&) = delete;
    bool enabled = false;

private:
    TextureArrayScope* saved_;
};

// Called by the yylex wrapper (token_budget.cpp) with the token glslang's
// scanner returned; gives the token the parser gets. An identifier naming an
// array sampler type becomes that type's keyword where the extension is on;
// at the end of the per-compile built-ins, the extension's functions are
// added to glslang's symbol table.
int texture_array_token(int token, void* value, glslang::TParseContext& context);

}  // namespace glslrun::frontend
