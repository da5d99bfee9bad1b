// Declaration rules glslang 12 does not enforce (declaration_checks.h).
#include "frontend/declaration_checks.h"

#include <map>

#include <fmt/format.h>

#include "frontend/source_rewrite.h"

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

bool is_builtin_name(const gl::TString& name) { return name.compare(0, 3, "gl_") == 0; }

// §4.3.3: attributes are float, vec2-4 or mat2-4 (arrays and structures
// glslang already rejects). §4.3.5 (1.10; §4.3.6 in 1.20): varyings are
// float, float vectors or matrices, or arrays of them; glslang lets int
// through (it wants `flat`, a GLSL 1.30 word, only for fragment inputs).
void check_interface_type(const gl::TIntermSymbol& sym, EShLanguage stage, const std::string& file,
                          std::vector<Diagnostic>& out) {
    const gl::TType& t = sym.getType();
    gl::TStorageQualifier q = t.getQualifier().storage;
    bool attribute = stage == EShLangVertex && q == gl::EvqVaryingIn;
    bool varying = (stage == EShLangVertex && q == gl::EvqVaryingOut) || (stage == EShLangFragment && q == gl::EvqVaryingIn);
    // 1.20 §4.3.6: centroid qualifies varyings only (glslang takes `centroid vec4 v;` as a global).
    if (t.getQualifier().centroid && !varying)
        out.push_back(Diagnostic{file, sym.getLoc().line,
                                 fmt::format("'{}' : centroid applies to varyings only", sym.getName().c_str()), false});
    if ((!attribute && !varying) || is_builtin_name(sym.getName())) return;
    if (t.getBasicType() == gl::EbtFloat && !t.isStruct()) return;
    const char* what = attribute ? "an attribute must be float, a float vector or a float matrix (GLSL §4.3.3)"
                                 : "a varying must be float, a float vector or matrix, or an array of them (GLSL 1.10 §4.3.5)";
    out.push_back(Diagnostic{file, sym.getLoc().line, fmt::format("'{}' : {}", sym.getName().c_str(), what), false});
}

// §4.2 (1.20): variables, structures and functions share one name space per
// scope, so a global variable and a function cannot have the same name.
// GLSL 1.10 keeps functions apart (as Mesa reads it), so only from 1.20.
void check_function_names(gl::TIntermAggregate& root, const std::map<std::string, int>& globals,
                          const std::string& file, std::vector<Diagnostic>& out) {
    for (TIntermNode* child : root.getSequence()) {
        gl::TIntermAggregate* fn = child->getAsAggregate();
        if (!fn || fn->getOp() != gl::EOpFunction) continue;
        std::string name = fn->getName().c_str();
        name = name.substr(0, name.find('('));
        if (globals.count(name))
            out.push_back(Diagnostic{file, fn->getLoc().line,
                                     fmt::format("'{}' : redefinition: a global variable has this name, and "
                                                 "functions and variables share one name space",
                                                 name),
                                     false});
    }
}

// §4.2: a structure's name and a function's share the global name space
// (the structure's constructor is a function of that name). glslang refuses
// a function after the structure, not a structure after the function; Mesa
// refuses both, in 1.10 too.
void check_struct_names(gl::TIntermAggregate& root, const std::string& text, const std::string& file,
                        std::vector<Diagnostic>& out) {
    std::vector<NamedPos> structs = global_struct_names(text);
    if (structs.empty()) return;
    for (TIntermNode* child : root.getSequence()) {
        gl::TIntermAggregate* fn = child->getAsAggregate();
        if (!fn || fn->getOp() != gl::EOpFunction) continue;
        std::string name = fn->getName().c_str();
        name = name.substr(0, name.find('('));
        for (const NamedPos& s : structs)
            if (s.name == name && s.pos.line >= fn->getLoc().line)
                out.push_back(Diagnostic{file, s.pos.line,
                                         fmt::format("'{}' : redefinition: a function has this name, and structures "
                                                     "and functions share one name space",
                                                     name),
                                         false});
    }
}

}  // namespace

void check_declarations(gl::TIntermediate& unit, const std::string& text, const std::string& file,
                        std::vector<Diagnostic>& out) {
    gl::TIntermAggregate* root = unit.getTreeRoot() ? unit.getTreeRoot()->getAsAggregate() : nullptr;
    if (!root || root->getSequence().empty()) return;
    std::map<std::string, int> globals;
    if (gl::TIntermAggregate* objects = root->getSequence().back()->getAsAggregate();
        objects && objects->getOp() == gl::EOpLinkerObjects) {
        for (TIntermNode* n : objects->getSequence()) {
            gl::TIntermSymbol* sym = n->getAsSymbolNode();
            if (!sym) continue;
            check_interface_type(*sym, unit.getStage(), file, out);
            if (!is_builtin_name(sym->getName())) globals.emplace(sym->getName().c_str(), sym->getLoc().line);
        }
    }
    if (unit.getVersion() >= 120) check_function_names(*root, globals, file, out);
    check_struct_names(*root, text, file, out);
    // GLSL 1.20 §3.6 reserves these (1.10 does not; glslang lets them be names).
    if (unit.getVersion() == 120)
        for (const TokenPos& p : word_positions(text, {"lowp", "mediump", "highp", "precision"}))
            out.push_back(Diagnostic{file, p.line, "reserved word in GLSL 1.20 (lowp, mediump, highp, precision)", false});
}

}  // namespace glslrun::frontend
