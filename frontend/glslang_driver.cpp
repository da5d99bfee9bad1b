// Driving glslang: parse every unit, link each stage on its own (our own
// cross-stage rules replace glslang's, which reject legal gl_TexCoord size
// differences), then lower both stages with one uniform table.
#include <algorithm>
#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>
#include <glslang/Include/PoolAlloc.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/compile.h"
#include "frontend/call_graph.h"
#include "frontend/deep_stack.h"
#include "frontend/diagnostic_hints.h"
#include "frontend/diagnostics.h"
#include "frontend/fold_workaround.h"
#include "frontend/glslang_fold.h"
#include "frontend/includer.h"
#include "frontend/int_builtins.h"
#include "frontend/language_version.h"
#include "frontend/link.h"
#include "frontend/lower.h"
#include "frontend/size_limits.h"
#include "frontend/source_rewrite.h"
#include "frontend/token_budget.h"
#include "frontend/unit_checks.h"

namespace glslrun::frontend {
namespace {

void init_glslang() {
    // Thread-safe once per process (C++ static initialization).
    static const bool initialized = [] { return glslang::InitializeProcess() && glslang_fold_hooks_linked(); }();
    (void)initialized;
}

TBuiltInResource resources() {
    TBuiltInResource r = *GetDefaultResources();
    // GL 2.1-era values (Mesa's legacy limits); they size gl_LightSource[],
    // gl_TexCoord[], gl_TextureMatrix[], gl_ClipPlane[], gl_FragData[].
    r.maxLights = 8;
    r.maxClipPlanes = 6;
    r.maxTextureUnits = 8;
    r.maxTextureCoords = 8;
    r.maxVertexAttribs = 16;
    r.maxVertexUniformComponents = 4096;
    r.maxVaryingFloats = 128;
    r.maxVertexTextureImageUnits = 16;
    r.maxCombinedTextureImageUnits = 32;
    r.maxTextureImageUnits = 16;
    r.maxFragmentUniformComponents = 4096;
    r.maxDrawBuffers = 8;
    return r;
}

constexpr EShMessages kMessages = EShMessages(EShMsgDefault | EShMsgCascadingErrors);

// The thread's current glslang pool. parse()/link() switch it and never switch
// back, so every compile installs this one (which outlives all glslang objects
// of the compile) and frees what was allocated in it at the end.
class PoolScope {
public:
    PoolScope() {
        glslang::SetThreadPoolAllocator(&pool());
        pool().push();
    }
    ~PoolScope() {
        glslang::SetThreadPoolAllocator(&pool());
        pool().pop();
    }
    void reinstall() { glslang::SetThreadPoolAllocator(&pool()); }

private:
    static glslang::TPoolAllocator& pool() {
        static thread_local glslang::TPoolAllocator p;
        return p;
    }
};

struct StageUnits {
    EShLanguage lang;
    std::vector<ShaderSource> sources;
    std::vector<std::string> texts;  // sources after the rewrites (glslang reads them during parse())
    std::vector<std::unique_ptr<glslang::TShader>> shaders;
    std::unique_ptr<glslang::TProgram> program;
    std::string first_file() const { return sources.empty() ? std::string() : sources[0].name; }
};

// The source rewrites that work around glslang before it parses (line
// numbers are kept by each).
std::string prepare_source(const ShaderSource& src, int default_version) {
    std::string s = drop_float_suffixes(define_predefined_macros(expand_defined_macros(splice_line_continuations(src.text))));
    if (unit_version(src, default_version) == 110) s = hoist_nested_structs(s);
    return rewrite_bool_literal_compares(brace_do_while_bodies(accept_extension_directives(s)));
}

struct ParsedUnit {
    std::unique_ptr<glslang::TShader> shader;
    bool ok = false;
    std::vector<Diagnostic> diags;
};

// One unit as one unnamed string (its __FILE__ is 0); `text` must outlive
// the shader. `helpers` go in the preamble, before the unit's first line.
ParsedUnit parse_unit(EShLanguage lang, const std::string& text, const std::string& file, const std::string& helpers,
                      int default_version, glslang::TShader::Includer& includer) {
    static const TBuiltInResource res = resources();
    ParsedUnit out;
    out.shader = std::make_unique<glslang::TShader>(lang);
    const char* str = text.c_str();
    int len = int(text.size());
    out.shader->setStringsWithLengths(&str, &len, 1);
    // GLSL 1.10 makes the *Lod texture functions built-in in the vertex
    // shader; glslang 12 wants the extension.
    std::string preamble;
    for (std::string_view name : kDefaultExtensions) preamble += "#extension " + std::string(name) + " : enable\n";
    if (lang == EShLangVertex) preamble += "#extension GL_ARB_shader_texture_lod : enable\n";
    preamble += extension_macros() + helpers;
    out.shader->setPreamble(preamble.c_str());
    FoldVersionScope fold(unit_version(ShaderSource{file, text}, default_version));
    TokenBudgetScope budget;
    out.ok = out.shader->parse(&res, default_version, ENoProfile, false, false, kMessages, includer);
    if (const TokenBudgetScope::LargeStruct& large = budget.large_struct(); !large.name.empty()) {
        out.ok = false;
        out.diags.push_back(Diagnostic{file, large.line, fmt::format(
            "'{}' : a struct of more than {} members (nested structs' members included) is past glslrun's limit "
            "(docs/limits.md)", large.name, kMaxStructMembers), false});
        return out;
    }
    if (budget.exceeded()) {
        out.ok = false;
        out.diags.push_back(Diagnostic{file, 0, fmt::format(
            "the source's macros expand past glslrun's limit: {} tokens for the parser, {} read back from "
            "macro bodies and arguments (docs/limits.md)", kMaxParserTokens, kMaxMacroTokens), false});
        return out;
    }
    parse_info_log(out.shader->getInfoLog(), file, out.diags);
    return out;
}

// `-D NAME[=VALUE]` as preamble lines: glslang reads them before the
// source's first line without counting them, so #version may still come
// first and every line number stays the file's.
std::string define_lines(const std::vector<std::string>& defines) {
    std::string out;
    for (const std::string& d : defines) {
        size_t eq = d.find('=');
        out += "#define " + d.substr(0, eq) + (eq == std::string::npos ? "" : " " + d.substr(eq + 1)) + "\n";
    }
    return out;
}

bool parse_units(StageUnits& st, int default_version, const std::string& defines,
                 const std::vector<std::string>& include_dirs, std::vector<Diagnostic>& diags) {
    bool ok = true;
    StageTotals stage_totals;
    st.texts.clear();
    size_t include_bytes_left = kMaxSourceBytes;  // included files count toward the stage's source limit
    for (const ShaderSource& src : st.sources) {
        st.texts.push_back(prepare_source(src, default_version));
        include_bytes_left -= std::min(include_bytes_left, src.text.size());
    }
    for (size_t i = 0; i < st.sources.size(); ++i) {
        const ShaderSource& src = st.sources[i];
        // An included file gets the rewrites of the unit that includes it.
        const int version = unit_version(src, default_version);
        auto prepare = [&](std::string text) { return prepare_source(ShaderSource{src.name, std::move(text)}, version); };
        FileIncluder includer(src.name, include_dirs, prepare, include_bytes_left);
        ParsedUnit unit = parse_unit(st.lang, st.texts[i], src.name, defines, default_version, includer);
        if (std::set<int> lines = int_builtin_retry_lines(unit.diags, st.texts[i]); !unit.ok && !lines.empty()) {
            std::string renamed = rename_int_builtin_calls(st.texts[i], lines);
            ParsedUnit retry =
                parse_unit(st.lang, renamed, src.name, defines + int_builtin_helpers(), default_version, includer);
            if (retry.ok) {
                unit = std::move(retry);
                st.texts[i] = std::move(renamed);
            }
        }
        size_t first = diags.size();
        diags.insert(diags.end(), unit.diags.begin(), unit.diags.end());
        add_hints(diags, first, src);
        if (unit.ok && unit.shader->getIntermediate()) {
            check_unit_rules(*unit.shader->getIntermediate(), st.texts[i], src.name, diags);
            check_size_limits(*unit.shader->getIntermediate(), src.name, stage_totals, diags);
        }
        ok = ok && unit.ok;
        st.shaders.push_back(std::move(unit.shader));
    }
    if (ok) check_call_chain(stage_totals, diags);
    return ok;
}

// Each unit is parsed as one unnamed string, so every node's location says
// string 0 (and __FILE__ is 0, as GLSL asks). Before the link merges the units,
// their nodes get the unit's index as string number: the lowering reads it as
// ir::SourceLoc::source, the index into Shader::sources.
class MarkUnitSource : public glslang::TIntermTraverser {
public:
    explicit MarkUnitSource(int unit) : unit_(unit) {}
    void visitSymbol(glslang::TIntermSymbol* n) override { mark(n); }
    void visitConstantUnion(glslang::TIntermConstantUnion* n) override { mark(n); }
    bool visitBinary(glslang::TVisit, glslang::TIntermBinary* n) override { return mark(n); }
    bool visitUnary(glslang::TVisit, glslang::TIntermUnary* n) override { return mark(n); }
    bool visitSelection(glslang::TVisit, glslang::TIntermSelection* n) override { return mark(n); }
    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* n) override { return mark(n); }
    bool visitLoop(glslang::TVisit, glslang::TIntermLoop* n) override { return mark(n); }
    bool visitBranch(glslang::TVisit, glslang::TIntermBranch* n) override { return mark(n); }
    bool visitSwitch(glslang::TVisit, glslang::TIntermSwitch* n) override { return mark(n); }

private:
    bool mark(TIntermNode* n) {
        glslang::TSourceLoc loc = n->getLoc();
        loc.string = unit_;
        n->setLoc(loc);
        return true;
    }
    int unit_;
};

bool link_units(StageUnits& st, std::vector<Diagnostic>& diags) {
    st.program = std::make_unique<glslang::TProgram>();
    for (size_t i = 0; i < st.shaders.size(); ++i) {
        glslang::TShader* sh = st.shaders[i].get();
        prepare_call_graph(*sh->getIntermediate());
        if (TIntermNode* root = sh->getIntermediate()->getTreeRoot()) {
            MarkUnitSource mark{int(i)};
            root->traverse(&mark);
        }
        st.program->addShader(sh);
    }
    bool ok = st.program->link(kMessages);
    parse_info_log(st.program->getInfoLog(), st.first_file(), diags);
    return ok;
}

// A global initialized in several compilation units must get the same
// constant value in each (GLSL 1.10 §4.3, as Mesa links it); a non-constant
// initializer may appear in only one unit.
std::string initializer_key(glslang::TIntermTyped* init) {
    glslang::TIntermConstantUnion* c = init->getAsConstantUnion();
    if (!c) return {};
    std::string key = "=";
    const glslang::TConstUnionArray& values = c->getConstArray();
    for (int i = 0; i < values.size(); ++i) key += fmt::format("{},", values[i].getDConst() + values[i].getIConst() + values[i].getBConst());
    return key;
}

void check_global_initializers(const StageUnits& st, std::vector<Diagnostic>& diags) {
    if (st.shaders.size() < 2) return;
    std::map<std::string, std::vector<std::string>> inits;
    for (const auto& sh : st.shaders) {
        TIntermNode* root = sh->getIntermediate()->getTreeRoot();
        if (!root || !root->getAsAggregate()) continue;
        for (TIntermNode* child : root->getAsAggregate()->getSequence()) {
            glslang::TIntermAggregate* seq = child->getAsAggregate();
            if (!seq || seq->getOp() != glslang::EOpSequence) continue;
            for (TIntermNode* n : seq->getSequence()) {
                glslang::TIntermBinary* b = n->getAsBinaryNode();
                if (b && b->getOp() == glslang::EOpAssign && b->getLeft()->getAsSymbolNode())
                    inits[b->getLeft()->getAsSymbolNode()->getName().c_str()].push_back(initializer_key(b->getRight()));
            }
        }
    }
    for (const auto& [name, keys] : inits) {
        if (keys.size() < 2) continue;
        const std::string& first = keys[0];  // clang 14 cannot capture a structured binding
        bool same = std::all_of(keys.begin(), keys.end(), [&first](const std::string& k) { return !k.empty() && k == first; });
        if (!same)
            diags.push_back(Diagnostic{st.first_file(), 0,
                                       fmt::format("global variable '{}' has different or non-constant initializers "
                                                   "in several compilation units",
                                                   name),
                                       false});
    }
}

bool has_errors(const std::vector<Diagnostic>& diags) {
    for (const Diagnostic& d : diags)
        if (!d.warning) return true;
    return false;
}

Error to_error(std::vector<Diagnostic> diags) {
    Error e;
    std::set<std::string> printed;  // one line once: the same file given twice reports the same errors
    for (Diagnostic& d : diags)
        if (!d.warning && printed.insert(d.str()).second) e.diagnostics.push_back(std::move(d));
    if (e.diagnostics.empty()) e.diagnostics.push_back(Diagnostic{{}, 0, "compilation failed", false});
    return e;
}

// Stand-ins for a missing stage: GL's fixed-function processing, as far as
// the other stage can observe it.
const char* kFixedFunctionVertex =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = gl_Color;\n"
    "  gl_BackColor = gl_Color;\n"
    "  gl_FrontSecondaryColor = gl_SecondaryColor;\n"
    "  gl_BackSecondaryColor = gl_SecondaryColor;\n"
    "  gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;\n"
    "  gl_TexCoord[1] = gl_TextureMatrix[1] * gl_MultiTexCoord1;\n"
    "  gl_TexCoord[2] = gl_TextureMatrix[2] * gl_MultiTexCoord2;\n"
    "  gl_TexCoord[3] = gl_TextureMatrix[3] * gl_MultiTexCoord3;\n"
    "  gl_TexCoord[4] = gl_TextureMatrix[4] * gl_MultiTexCoord4;\n"
    "  gl_TexCoord[5] = gl_TextureMatrix[5] * gl_MultiTexCoord5;\n"
    "  gl_TexCoord[6] = gl_TextureMatrix[6] * gl_MultiTexCoord6;\n"
    "  gl_TexCoord[7] = gl_TextureMatrix[7] * gl_MultiTexCoord7;\n"
    "  float eyeZ = (gl_ModelViewMatrix * gl_Vertex).z;\n"
    "  gl_FogFragCoord = abs(eyeZ);\n"
    // GL 1.4's distance attenuation as Mesa's fixed-function vertex program
    // computes it (d = |eye z|, ARB's RSQ of |x|); the rasterizer takes it
    // only when the attenuation is not (1, 0, 0), as Mesa writes it only then.
    "  vec3 abc = vec3(gl_Point.distanceConstantAttenuation, gl_Point.distanceLinearAttenuation,\n"
    "                  gl_Point.distanceQuadraticAttenuation);\n"
    "  float d = abs(eyeZ);\n"
    "  float size = gl_Point.size * inversesqrt(abs(abc.x + d * (abc.y + d * abc.z)));\n"
    "  gl_PointSize = min(max(size, gl_Point.sizeMin), gl_Point.sizeMax);\n"
    "}\n";
const char* kFixedFunctionFragment = "void main() { gl_FragColor = gl_Color; }\n";

Status check_source_sizes(const std::vector<ShaderSource>& sources) {
    size_t bytes = 0;
    for (const ShaderSource& s : sources) bytes += s.text.size();
    if (bytes <= kMaxSourceBytes) return Ok{};
    return Error(fmt::format("the shader's sources are {} bytes; glslrun's limit is {} KiB per stage", bytes,
                             kMaxSourceBytes >> 10),
                 sources.empty() ? std::string() : sources[0].name);
}

Result<ir::Program> compile_here(const std::vector<ShaderSource>& vs, const std::vector<ShaderSource>& fs,
                                 const CompileOptions& options) {
    init_glslang();
    if (vs.empty() && fs.empty()) return Error("no shaders to link");
    if (auto refused = refuse_unsupported_versions({&vs, &fs}, options.default_version)) return std::move(*refused);
    PoolScope pool;
    std::vector<Diagnostic> diags;
    StageUnits units[2] = {{EShLangVertex, vs, {}, {}, {}}, {EShLangFragment, fs, {}, {}, {}}};
    if (vs.empty()) units[0].sources = {ShaderSource{"", kFixedFunctionVertex}};
    if (fs.empty()) units[1].sources = {ShaderSource{"", kFixedFunctionFragment}};
    bool parsed = true;
    const std::string defines = define_lines(options.defines);
    for (StageUnits& st : units)
        parsed = parse_units(st, options.default_version, defines, options.include_dirs, diags) && parsed;
    if (!parsed || has_errors(diags)) return to_error(std::move(diags));
    for (StageUnits& st : units) check_global_initializers(st, diags);
    bool linked = true;
    for (StageUnits& st : units) linked = link_units(st, diags) && linked;
    if (!linked || has_errors(diags)) return to_error(std::move(diags));

    pool.reinstall();
    UniformTable uniforms;
    StageLowering vlow(ir::Stage::Vertex, uniforms, diags, units[0].first_file());
    StageLowering flow(ir::Stage::Fragment, uniforms, diags, units[1].first_file());
    vlow.check_undefined = flow.check_undefined = options.check_undefined;
    for (int stage = 0; stage < 2; ++stage)
        for (const ShaderSource& source : units[stage].sources)
            (stage == 0 ? vlow : flow).shader.sources.push_back(source.name.empty() ? "(fixed function)" : source.name);
    vlow.run(units[0].program->getIntermediate(EShLangVertex));
    flow.run(units[1].program->getIntermediate(EShLangFragment));
    LinkInput li{&vlow, &flow, !vs.empty(), units[0].first_file(), units[1].first_file()};
    check_interface(li, diags);
    if (has_errors(diags)) return to_error(std::move(diags));

    ir::Program program;
    program.vertex = std::move(vlow.shader);
    program.fragment = std::move(flow.shader);
    program.uniforms = std::move(uniforms.leaves);
    program.uniform_words = uint32_t(uniforms.slot_kinds.size());
    program.uniform_defaults = std::move(uniforms.defaults);
    program.fixed_function_vertex = vs.empty();
    link_varyings(program);
    return program;
}

Status check_here(Stage stage, const ShaderSource& source, const CompileOptions& options) {
    init_glslang();
    const int default_version = options.default_version;
    std::vector<ShaderSource> one{source};
    if (auto refused = refuse_unsupported_versions({&one}, default_version)) return std::move(*refused);
    PoolScope pool;
    std::vector<Diagnostic> diags;
    StageUnits st{stage == Stage::Vertex ? EShLangVertex : EShLangFragment, {source}, {}, {}, {}};
    bool ok = parse_units(st, default_version, define_lines(options.defines), options.include_dirs, diags);
    if (!ok || has_errors(diags)) return to_error(std::move(diags));
    return Ok{};
}

// A lone CR ends a line (old Mac OS files), as glslang's scanner reads it;
// the #version check and the rewrites before glslang split lines at LF. A CR
// not followed by LF becomes one: the same bytes, lines and columns.
ShaderSource with_lf_line_ends(const ShaderSource& source) {
    ShaderSource out = source;
    for (size_t i = 0; i < out.text.size(); ++i)
        if (out.text[i] == '\r' && (i + 1 == out.text.size() || out.text[i + 1] != '\n')) out.text[i] = '\n';
    return out;
}

std::vector<ShaderSource> with_lf_line_ends(const std::vector<ShaderSource>& sources) {
    std::vector<ShaderSource> out;
    for (const ShaderSource& s : sources) out.push_back(with_lf_line_ends(s));
    return out;
}

}  // namespace

Result<ir::Program> compile_program(const std::vector<ShaderSource>& vs_in, const std::vector<ShaderSource>& fs_in,
                                    const CompileOptions& options) {
    for (const auto* stage : {&vs_in, &fs_in})
        if (Status st = check_source_sizes(*stage); !st) return st.error();
    const std::vector<ShaderSource> vs = with_lf_line_ends(vs_in), fs = with_lf_line_ends(fs_in);
    Result<ir::Program> out = Error("not compiled");
    run_on_deep_stack([&] { out = compile_here(vs, fs, options); });
    return out;
}

Status check_shader(Stage stage, const ShaderSource& source_in, const CompileOptions& options) {
    if (Status st = check_source_sizes({source_in}); !st) return st;
    const ShaderSource source = with_lf_line_ends(source_in);
    Status out = Ok{};
    run_on_deep_stack([&] { out = check_here(stage, source, options); });
    return out;
}

}  // namespace glslrun::frontend

namespace glslrun {

// The public entry points, here beside the frontend's (not with the
// diagnostics' formatting, which the JIT plugin links without glslang).
Status check_shader(Stage stage, const ShaderSource& source, int default_version) {
    CompileOptions options;
    options.default_version = default_version;
    return frontend::check_shader(stage, source, options);
}

Status check_shader(Stage stage, const ShaderSource& source, const CompileOptions& options) {
    return frontend::check_shader(stage, source, options);
}

}  // namespace glslrun
