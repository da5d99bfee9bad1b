// Rewrites glslang's terse messages for the mistakes people actually make in
// legacy GLSL, so that a student can act on them:
//
//   glColor = gl_Color;            'glColor' : undeclared identifier
//                                  -> ... did you mean 'gl_FrontColor' (write) or 'gl_Color' (read)?
//   gl_FrontMaterial.emissive      -> ... gl_FrontMaterial has: emission, ambient, ...; did you mean 'emission'?
//   att = 1 / (c + l*d);           -> ... GLSL 1.10 never converts int to float: write 1.0
//   x = normalize(x)               -> reported on its own line as "missing ';'", not on the next line
#include "frontend/diagnostic_hints.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string_view>
#include <set>
#include <sstream>

#include <fmt/format.h>

namespace glslrun::frontend {
namespace {

// Built-in variables of GLSL 1.10 (§7), the candidates for "did you mean".
constexpr std::array kBuiltinNames = {
    "gl_Position", "gl_PointSize", "gl_ClipVertex", "gl_FragCoord", "gl_FrontFacing", "gl_FragColor",
    "gl_FragData", "gl_FragDepth", "gl_Color", "gl_SecondaryColor", "gl_Normal", "gl_Vertex",
    "gl_MultiTexCoord0", "gl_MultiTexCoord1", "gl_FogCoord", "gl_FrontColor", "gl_BackColor",
    "gl_FrontSecondaryColor", "gl_BackSecondaryColor", "gl_TexCoord", "gl_FogFragCoord",
    "gl_ModelViewMatrix", "gl_ProjectionMatrix", "gl_ModelViewProjectionMatrix", "gl_TextureMatrix",
    "gl_NormalMatrix", "gl_NormalScale", "gl_DepthRange", "gl_ClipPlane", "gl_Point",
    "gl_FrontMaterial", "gl_BackMaterial", "gl_LightSource", "gl_LightModel",
    "gl_FrontLightModelProduct", "gl_BackLightModelProduct", "gl_FrontLightProduct",
    "gl_BackLightProduct", "gl_TextureEnvColor", "gl_Fog", "gl_MaxLights", "gl_MaxClipPlanes",
    "gl_MaxTextureUnits", "gl_MaxTextureCoords",
};

// Legacy GL API names written where the GLSL built-in was meant.
struct ApiMistake { const char* written; const char* hint; };
constexpr std::array kApiMistakes = {
    ApiMistake{"glColor", "'gl_FrontColor' (to set the vertex's colour) or 'gl_Color' (to read it)"},
    ApiMistake{"glVertex", "'gl_Vertex'"},
    ApiMistake{"glNormal", "'gl_Normal'"},
    ApiMistake{"glPosition", "'gl_Position'"},
    ApiMistake{"glTexCoord", "'gl_TexCoord' (a varying) or 'gl_MultiTexCoord0' (the attribute)"},
    ApiMistake{"glFragColor", "'gl_FragColor'"},
};

struct BuiltinStruct { const char* variable_prefix; const char* type; std::vector<std::string> fields; };
const std::vector<BuiltinStruct>& builtin_structs() {
    static const std::vector<BuiltinStruct> structs = {
        {"gl_FrontMaterial", "gl_MaterialParameters", {"emission", "ambient", "diffuse", "specular", "shininess"}},
        {"gl_BackMaterial", "gl_MaterialParameters", {"emission", "ambient", "diffuse", "specular", "shininess"}},
        {"gl_LightSource", "gl_LightSourceParameters",
         {"ambient", "diffuse", "specular", "position", "halfVector", "spotDirection", "spotExponent",
          "spotCutoff", "spotCosCutoff", "constantAttenuation", "linearAttenuation", "quadraticAttenuation"}},
        {"gl_LightModel", "gl_LightModelParameters", {"ambient"}},
        {"gl_FrontLightModelProduct", "gl_LightModelProducts", {"sceneColor"}},
        {"gl_BackLightModelProduct", "gl_LightModelProducts", {"sceneColor"}},
        {"gl_FrontLightProduct", "gl_LightProducts", {"ambient", "diffuse", "specular"}},
        {"gl_BackLightProduct", "gl_LightProducts", {"ambient", "diffuse", "specular"}},
        {"gl_DepthRange", "gl_DepthRangeParameters", {"near", "far", "diff"}},
        {"gl_Fog", "gl_FogParameters", {"color", "density", "start", "end", "scale"}},
        {"gl_Point", "gl_PointParameters",
         {"size", "sizeMin", "sizeMax", "fadeThresholdSize", "distanceConstantAttenuation",
          "distanceLinearAttenuation", "distanceQuadraticAttenuation"}},
    };
    return structs;
}

// The case-insensitive edit distance of a and b if it is below limit, else
// limit: a row whose minimum reaches the limit cannot come back under it, so
// the many far candidates of a long shader cost little. `row` is the caller's
// scratch, reused across candidates.
size_t edit_distance_below(std::string_view a, std::string_view b, size_t limit, std::vector<size_t>& row) {
    if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) >= limit) return limit;
    row.resize(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        size_t row_min = row[0];
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t substitute = diagonal + (std::tolower(a[i - 1]) != std::tolower(b[j - 1]));
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
            row_min = std::min(row_min, row[j]);
        }
        if (row_min >= limit) return limit;
    }
    return std::min(row[b.size()], limit);
}

// The closest candidate, if it is close enough to be a plausible typo.
std::string closest(std::string_view word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
    std::vector<size_t> row;
    for (const std::string& c : candidates) {
        if (c == word) continue;
        // A missing "gl_" prefix is the commonest slip of all.
        bool lacks_gl_prefix = c.size() == word.size() + 3 && c.starts_with("gl_") && c.ends_with(word);
        size_t d = lacks_gl_prefix ? 1 : edit_distance_below(word, c, best_distance, row);
        if (d < best_distance) best_distance = d, best = c;
    }
    return best;
}

std::vector<std::string> identifiers_in(const std::string& text) {
    std::set<std::string> seen;
    for (size_t i = 0; i < text.size();) {
        if (std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') {
            size_t j = i;
            while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
            seen.insert(text.substr(i, j - i));
            i = j;
        } else {
            ++i;
        }
    }
    return {seen.begin(), seen.end()};
}

// "'name' : ..." -> name
std::string quoted_token(const std::string& message) {
    if (message.size() < 2 || message[0] != '\'') return {};
    size_t end = message.find('\'', 1);
    return end == std::string::npos ? std::string() : message.substr(1, end - 1);
}

// The built-in variables, then the source's identifiers.
std::vector<std::string> undeclared_candidates(const std::string& source) {
    std::vector<std::string> candidates(kBuiltinNames.begin(), kBuiltinNames.end());
    for (std::string& id : identifiers_in(source)) candidates.push_back(std::move(id));
    return candidates;
}

void explain_undeclared(Diagnostic& d, const std::vector<std::string>& candidates) {
    std::string name = quoted_token(d.message);
    for (const ApiMistake& m : kApiMistakes)
        if (name == m.written) {
            d.message += fmt::format(" ('{}' is the OpenGL API's name; in GLSL use {})", name, m.hint);
            return;
        }
    std::string guess = closest(name, candidates);
    if (!guess.empty()) d.message += fmt::format(" (did you mean '{}'?)", guess);
}

void explain_missing_field(Diagnostic& d) {
    std::string field = quoted_token(d.message);
    for (const BuiltinStruct& s : builtin_structs()) {
        if (d.message.find(fmt::format("structure '{}", s.variable_prefix)) == std::string::npos) continue;
        std::string guess = closest(field, s.fields);
        std::string list;
        for (const std::string& f : s.fields) list += (list.empty() ? "" : ", ") + f;
        d.message += fmt::format(" ({} is a {} with the fields {}{})", s.variable_prefix, s.type, list,
                                 guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess));
        return;
    }
}

bool mixes_int_and_float(const std::string& message) {
    bool has_int = message.find(" int'") != std::string::npos;
    bool has_float = message.find(" float'") != std::string::npos || message.find(" vec") != std::string::npos;
    return has_int && has_float;
}

constexpr const char* kNoImplicitConversion =
    " (GLSL 1.10 never converts int to float implicitly: write float literals with a decimal "
    "point, such as 1.0 and 0.0, or convert with float(...))";

// glslang: "'/' : wrong operand types: no operation '/' exists that takes a
// left-hand operand of type ' const int' and a right operand of type ' temp
// float' (or there is no acceptable conversion)" -> "'/' : int / float: ..."
void explain_int_float_operands(Diagnostic& d) {
    std::vector<std::string> types;
    for (size_t at = 0; (at = d.message.find("of type '", at)) != std::string::npos;) {
        at += 9;
        size_t end = d.message.find('\'', at);
        if (end == std::string::npos) return;
        std::string type = d.message.substr(at, end - at);
        types.push_back(type.substr(type.find_last_of(' ') + 1));  // drop "temp", "const", ...
        at = end;
    }
    std::string op = quoted_token(d.message);
    if (types.size() != 2 || op.empty()) return;
    d.message = fmt::format("'{}' : no operator {} {} {} exists{}", op, types[0], op, types[1],
                            kNoImplicitConversion);
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string strip_line_comment(std::string line) {
    if (size_t c = line.find("//"); c != std::string::npos) line.resize(c);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    return line;
}

// glslang reports a missing ';' at the next token, often on the next line.
// Point at the line that lacks it instead.
// Whether `line` begins with the token glslang calls `unexpected` (RIGHT_BRACE,
// IDENTIFIER, FLOAT, ...). When it does not, code precedes the token on the
// same line, and the ';' is missing there, not on an earlier line.
bool starts_with_token(const std::string& line, const std::string& unexpected) {
    size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) return true;  // nothing to blame on this line
    char c = line[first];
    if (unexpected == "RIGHT_BRACE") return c == '}';
    if (unexpected == "RIGHT_PAREN") return c == ')';
    if (unexpected == "LEFT_BRACE") return c == '{';
    if (unexpected == "LEFT_PAREN") return c == '(';
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';  // a name, keyword or type
}

void explain_missing_semicolon(Diagnostic& d, const std::string& source) {
    std::vector<std::string> lines = split_lines(source);
    if (d.line < 1 || d.line > int(lines.size())) return;
    const size_t at = d.message.find("unexpected ");
    const std::string unexpected =
        at == std::string::npos ? "" : d.message.substr(at + 11, d.message.find(',', at) - at - 11);
    if (!unexpected.empty() && !starts_with_token(lines[d.line - 1], unexpected)) return;
    for (int l = d.line - 1; l >= 1; --l) {
        std::string code = strip_line_comment(lines[l - 1]);
        if (code.empty()) continue;
        char last = code.back();
        if (last == ';' || last == '{' || last == '}' || last == ',' || last == '(') return;
        size_t first = lines[d.line - 1].find_first_not_of(" \t");
        std::string next = first == std::string::npos ? "" : lines[d.line - 1].substr(first);
        d.message = fmt::format("missing ';' at the end of this line (line {} continues with '{}')",
                                d.line, next);
        d.line = l;
        return;
    }
}

// Syntax of GLSL 1.30 and later that legacy programs meet when they are
// ported back, or when a newer tutorial is followed: glslang says "not
// supported for this version", "Reserved word", or only "syntax error".
// Each gets the feature, the version it needs and the GLSL 1.10/1.20 way.
struct NewerFeature {
    const char* glslang;  // a piece of glslang's message, or "word:" + a word on the line of a syntax error
    const char* message;
};
constexpr std::array kNewerFeatures = {
    NewerFeature{"'uniform block' : not supported",
                 "uniform blocks need GLSL 1.40: in GLSL 1.10/1.20 declare each member as a uniform of its own"},
    NewerFeature{"'in for stage inputs' : not supported",
                 "'in' on a global variable needs GLSL 1.30: in GLSL 1.10/1.20 write 'attribute' in a vertex shader, "
                 "'varying' in a fragment shader"},
    NewerFeature{"'out for stage outputs' : not supported",
                 "'out' on a global variable needs GLSL 1.30: in GLSL 1.10/1.20 write 'varying' in a vertex shader; "
                 "a fragment shader writes gl_FragColor or gl_FragData[n]"},
    NewerFeature{"'%' : not supported", "the '%' operator needs GLSL 1.30: in GLSL 1.10/1.20 write mod(a, b)"},
    NewerFeature{"'bit shift", "bit shifts need GLSL 1.30; GLSL 1.10/1.20 have no bitwise operators"},
    NewerFeature{"'bitwise", "bitwise operators need GLSL 1.30; GLSL 1.10/1.20 have none"},
    NewerFeature{"'switch' : Reserved word", "switch statements need GLSL 1.30: in GLSL 1.10/1.20 write if / else if"},
    NewerFeature{"'uint' : undeclared identifier", "unsigned integers ('uint') need GLSL 1.30; GLSL 1.10/1.20 have int"},
    NewerFeature{"'texture' : no matching overloaded function",
                 "texture() needs GLSL 1.30: in GLSL 1.10/1.20 write texture1D, texture2D, texture3D, textureCube, "
                 "shadow1D or shadow2D (and their Proj forms)"},
    NewerFeature{"word:layout", "layout qualifiers need GLSL 1.40 (attribute locations: 3.30); GLSL 1.10/1.20 have none"},
    NewerFeature{"word:flat", "interpolation qualifiers ('flat') need GLSL 1.30"},
    NewerFeature{"word:smooth", "interpolation qualifiers ('smooth') need GLSL 1.30"},
    NewerFeature{"word:noperspective", "interpolation qualifiers ('noperspective') need GLSL 1.30"},
};

bool line_has_word(const std::string& line, std::string_view word) {
    for (size_t at = line.find(word); at != std::string::npos; at = line.find(word, at + 1)) {
        auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
        bool starts = at == 0 || !ident(line[at - 1]);
        bool ends = at + word.size() >= line.size() || !ident(line[at + word.size()]);
        if (starts && ends) return true;
    }
    return false;
}

// True when the message was replaced.
bool explain_newer_syntax(Diagnostic& d, const std::string& source) {
    const bool syntax_error = d.message.rfind("syntax error", 0) == 0;
    std::string line;
    if (syntax_error) {
        std::vector<std::string> lines = split_lines(source);
        if (d.line >= 1 && d.line <= int(lines.size())) line = strip_line_comment(lines[size_t(d.line - 1)]);
    }
    for (const NewerFeature& f : kNewerFeatures) {
        std::string_view key = f.glslang;
        bool hit = key.rfind("word:", 0) == 0 ? syntax_error && line_has_word(line, key.substr(5))
                                              : d.message.find(key) != std::string::npos;
        if (!hit) continue;
        d.message = f.message;
        return true;
    }
    return false;
}

// EXT_texture_array's types are plain names until a shader enables the
// extension (as in Mesa), so glslang reports only a syntax error.
bool explain_array_sampler(Diagnostic& d, const std::string& source) {
    if (d.message.rfind("syntax error", 0) != 0 || source.find("GL_EXT_texture_array") != std::string::npos)
        return false;
    std::vector<std::string> lines = split_lines(source);
    if (d.line < 1 || d.line > int(lines.size())) return false;
    const std::string line = strip_line_comment(lines[size_t(d.line - 1)]);
    for (const char* type : {"sampler1DArray", "sampler2DArray", "sampler1DArrayShadow", "sampler2DArrayShadow"}) {
        if (!line_has_word(line, type)) continue;
        d.message = fmt::format("'{}' is EXT_texture_array's: add '#extension GL_EXT_texture_array : enable' "
                                "before the code", type);
        return true;
    }
    return false;
}

// glslang says only "'constructor' : not enough data provided for
// construction" (or "too many arguments") for `vec4(1, 0, 0)`: name the
// type the line constructs and what it needs.
void explain_constructor(Diagnostic& d, const std::string& source) {
    const bool too_few = d.message.find("not enough data provided for construction") != std::string::npos;
    const bool too_many = d.message.find("'constructor' : too many arguments") != std::string::npos;
    if (!too_few && !too_many) return;
    std::vector<std::string> lines = split_lines(source);
    if (d.line < 1 || d.line > int(lines.size())) return;
    const std::string line = strip_line_comment(lines[size_t(d.line - 1)]);
    std::vector<std::pair<std::string, int>> types;  // the constructors on the line, with their component counts
    for (const char* prefix : {"vec", "ivec", "bvec", "mat"})
        for (int n = 2; n <= 4; ++n) {
            std::string type = fmt::format("{}{}", prefix, n);
            if (line_has_word(line, type)) types.emplace_back(type, prefix == std::string_view("mat") ? n * n : n);
        }
    if (types.size() != 1) {
        d.message += too_few ? " (a constructor needs as many components as its type has, or a single scalar)"
                             : " (a constructor takes at most as many components as its type has)";
        return;
    }
    const auto& [type, components] = types[0];
    d.message += too_few ? fmt::format(" ({} takes {} components, or one scalar for all of them: the arguments give "
                                       "fewer)", type, components)
                         : fmt::format(" ({} takes {} components: the arguments give more)", type, components);
}

}  // namespace

void add_hints(std::vector<Diagnostic>& diags, size_t first, const ShaderSource& source) {
    std::optional<std::vector<std::string>> candidates;  // gathered at the first undeclared name
    for (size_t i = first; i < diags.size(); ++i) {
        Diagnostic& d = diags[i];
        if (d.warning || d.file != source.name) continue;
        const std::string& m = d.message;
        if (explain_array_sampler(d, source.text) || explain_newer_syntax(d, source.text)) continue;
        if (m.find(": undeclared identifier") != std::string::npos) {
            if (!candidates) candidates = undeclared_candidates(source.text);
            explain_undeclared(d, *candidates);
        } else if (m.find(": no such field in structure") != std::string::npos) {
            explain_missing_field(d);
        } else if (m.find("wrong operand types") != std::string::npos && mixes_int_and_float(m)) {
            explain_int_float_operands(d);
        } else if (m.find("cannot convert") != std::string::npos && mixes_int_and_float(m)) {
            d.message += kNoImplicitConversion;
        } else if (m.rfind("'constructor' : ", 0) == 0) {
            explain_constructor(d, source.text);
        } else if (m.find("expecting COMMA or SEMICOLON") != std::string::npos ||
                   m.find("expecting SEMICOLON") != std::string::npos) {
            explain_missing_semicolon(d, source.text);
        }
    }
}

}  // namespace glslrun::frontend
