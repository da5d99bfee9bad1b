// EXT_texture_array in GLSL 1.10/1.20, as Mesa enables it in a compatibility
// context: `#extension GL_EXT_texture_array : enable` (or require, warn)
// makes sampler1DArray, sampler2DArray, sampler1DArrayShadow and
// sampler2DArrayShadow types and adds texture1DArray, texture2DArray,
// shadow1DArray, shadow2DArray (with a bias in the fragment shader) and
// texture1DArrayLod, texture2DArrayLod, shadow1DArrayLod (vertex shader; the
// fragment shader with ARB_shader_texture_lod too). The macro is defined in
// every shader (the preamble), as Mesa's preprocessor does.
//
// glslang 12 has these types only from GLSL 1.30 (its scanner reads the
// names as identifiers before that) and does not know the extension. Three
// hooks give it the same AST a GLSL 1.30 `texture(sampler2DArray, vec3)`
// makes, so the lowering sees glslang's own array sampler types and
// EOpTexture/EOpTextureLod, and every message and line stays glslang's:
//  - ld's --wrap of TParseVersions::updateExtensionBehavior (reached through
//    TParseContext's vtable, in another object file) sees the #extension
//    directives as the preprocessor reaches them (inside #if too) and keeps
//    this extension's state in the thread's TextureArrayScope;
//  - the yylex wrapper (token_budget.cpp) hands an identifier naming an array
//    sampler type to the parser as that type's keyword while it is on;
//  - at the end of the per-compile built-ins (symbol-table level 2, parsed at
//    every compile), the functions are inserted there as built-ins mapped to
//    glslang's texture operators. Without the extension they cannot be
//    called: no value of their sampler types can be declared.
// No glslang code changes; the ABI is that of the installed headers.
#include "frontend/texture_array.h"

#include <cstring>

#include <glslang/MachineIndependent/ParseHelper.h>
#include <glslang/MachineIndependent/glslang_tab.cpp.h>

namespace gl = glslang;

namespace {

thread_local glslrun::frontend::TextureArrayScope* active = nullptr;

struct ArraySampler {
    const char* name;
    int token;
    gl::TSamplerDim dim;
    bool shadow;
};
constexpr ArraySampler kSamplers[] = {
    {"sampler1DArray", SAMPLER1DARRAY, gl::Esd1D, false},
    {"sampler2DArray", SAMPLER2DARRAY, gl::Esd2D, false},
    {"sampler1DArrayShadow", SAMPLER1DARRAYSHADOW, gl::Esd1D, true},
    {"sampler2DArrayShadow", SAMPLER2DARRAYSHADOW, gl::Esd2D, true},
};

// One signature: sampler kSamplers[sampler], a vecN coordinate, and a float
// (the bias of an EOpTexture, the level of an EOpTextureLod) where `extra`.
struct Signature {
    const char* name;
    int sampler, coord;
    bool extra;
    gl::TOperator op;
};
// EXT_texture_array's list (its section 8.7), and Mesa's shadow2DArray with
// a bias, which the extension does not list (Mesa 22.3.6 compiles it).
constexpr Signature kFunctions[] = {
    {"texture1DArray", 0, 2, false, gl::EOpTexture},
    {"texture2DArray", 1, 3, false, gl::EOpTexture},
    {"shadow1DArray", 2, 3, false, gl::EOpTexture},
    {"shadow2DArray", 3, 4, false, gl::EOpTexture},
    {"texture1DArray", 0, 2, true, gl::EOpTexture},
    {"texture2DArray", 1, 3, true, gl::EOpTexture},
    {"shadow1DArray", 2, 3, true, gl::EOpTexture},
    {"shadow2DArray", 3, 4, true, gl::EOpTexture},
    {"texture1DArrayLod", 0, 2, true, gl::EOpTextureLod},
    {"texture2DArrayLod", 1, 3, true, gl::EOpTextureLod},
    {"shadow1DArrayLod", 2, 3, true, gl::EOpTextureLod},
};

bool legacy(const gl::TParseContext& c) { return c.version < 130 && !c.isEsProfile(); }

// Level 2 of glslang's symbol table holds the built-ins of this compile
// (TSymbolTable's convention); the id counter carries the level in its top bits.
bool at_compile_builtins(gl::TParseContext& c) {
    return c.symbolTable.atBuiltInLevel() && (c.symbolTable.getMaxSymbolId() >> 56) == 2;
}

gl::TFunction* make_function(const Signature& sig) {
    const gl::TType result(gl::EbtFloat, gl::EvqTemporary, 4);
    auto* f = new gl::TFunction(gl::NewPoolTString(sig.name), result, sig.op);
    const ArraySampler& s = kSamplers[sig.sampler];
    gl::TSampler sampler;
    sampler.set(gl::EbtFloat, s.dim, true, s.shadow);
    // Debian's glslang is built with ENABLE_HLSL, whose TSampler::clear() also
    // resets these two fields; the header's inline clear() here does not, and
    // the library's mangled names read them ("-tx-struct0" otherwise).
    sampler.vectorSize = 4;
    sampler.structReturnIndex = gl::TSampler::noReturnStruct;
    gl::TParameter p{nullptr, new gl::TType(sampler, gl::EvqIn), nullptr};
    f->addParameter(p);
    p.type = new gl::TType(gl::EbtFloat, gl::EvqIn, sig.coord);
    f->addParameter(p);
    if (sig.extra) {
        p.type = new gl::TType(gl::EbtFloat, gl::EvqIn, 1);
        f->addParameter(p);
    }
    return f;
}

// Mesa: the bias forms need derivatives (fragment shader only); the Lod
// forms exist in the vertex shader, and in the fragment shader where
// ARB_shader_texture_lod is enabled, as glslang gates texture2DLod.
void add_functions(gl::TParseContext& c) {
    const bool fragment = c.language == EShLangFragment;
    for (const Signature& sig : kFunctions) {
        const bool bias = sig.extra && sig.op == gl::EOpTexture;
        if (bias && !fragment) continue;
        gl::TFunction* f = make_function(sig);
        if (c.symbolTable.find(f->getMangledName())) return;  // already added on this table
        if (sig.op == gl::EOpTextureLod && fragment) f->setExtensions(1, &gl::E_GL_ARB_shader_texture_lod);
        c.symbolTable.insert(*f);
    }
}

bool valid_behavior(const char* b) {
    return !std::strcmp(b, "require") || !std::strcmp(b, "enable") || !std::strcmp(b, "warn") ||
           !std::strcmp(b, "disable");
}

}  // namespace

extern "C" {
// void TParseVersions::updateExtensionBehavior(int line, const char* extension, const char* behavior):
// an #extension directive, from the preprocessor.
void __real__ZN7glslang14TParseVersions23updateExtensionBehaviorEiPKcS2_(void* self, int line, const char* extension,
                                                                         const char* behavior);
void __wrap__ZN7glslang14TParseVersions23updateExtensionBehaviorEiPKcS2_(void* self, int line, const char* extension,
                                                                         const char* behavior) {
    if (active && extension && behavior && valid_behavior(behavior)) {
        const bool disable = !std::strcmp(behavior, "disable");
        if (!std::strcmp(extension, glslrun::frontend::kTextureArrayExtension)) {
            active->enabled = !disable;
            return;
        }
        // Mesa: `all : warn` turns every extension on (with warnings), `all : disable` off.
        if (!std::strcmp(extension, "all")) active->enabled = !disable;
    }
    __real__ZN7glslang14TParseVersions23updateExtensionBehaviorEiPKcS2_(self, line, extension, behavior);
}
}

namespace glslrun::frontend {

TextureArrayScope::TextureArrayScope() : saved_(active) { active = this; }
TextureArrayScope::~TextureArrayScope() { active = saved_; }

int texture_array_token(int token, void* value, gl::TParseContext& context) {
    if (!legacy(context)) return token;
    if (token == 0) {  // the end of the input
        if (at_compile_builtins(context)) add_functions(context);
        return token;
    }
    if ((token != IDENTIFIER && token != TYPE_NAME) || !active || !active->enabled) return token;
    const gl::TString* name = static_cast<YYSTYPE*>(value)->lex.string;
    if (!name) return token;
    for (const ArraySampler& s : kSamplers)
        if (*name == s.name) return s.token;
    return token;
}

}  // namespace glslrun::frontend
