// One [test] command line -> CommandData. The prefixes are tried in
// shader_runner's order, so "clear color" wins over "clear", "draw rect tex"
// over "draw rect", and so on.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "piglit_parse.h"

namespace glslrun::piglit {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

// If `s` starts with `prefix`, drops it and returns true.
bool eat(std::string_view& s, std::string_view prefix) {
    if (!starts_with(s, prefix)) return false;
    s = trim(s.substr(prefix.size()));
    return true;
}

ParseError error(std::string message) { return ParseError{0, std::move(message)}; }

// Exactly `n` numbers at the start of `s` (extra text after them is ignored, as in piglit).
std::optional<std::vector<float>> floats(std::string_view s, size_t n) {
    auto v = parse_float_list(s);
    if (v.size() < n) return std::nullopt;
    v.resize(n);
    return v;
}

template <size_t N>
std::optional<std::array<float, N>> float_array(std::string_view s) {
    auto v = floats(s, N);
    if (!v) return std::nullopt;
    std::array<float, N> a{};
    for (size_t i = 0; i < N; ++i) a[i] = (*v)[i];
    return a;
}

// "( a , b , c )": n numbers (or more) in parentheses, separated by commas.
std::optional<std::vector<float>> paren_group(std::string_view& s, size_t n) {
    s = trim(s);
    if (s.empty() || s[0] != '(') return std::nullopt;
    size_t close = s.find(')');
    if (close == std::string_view::npos) return std::nullopt;
    std::string inner(s.substr(1, close - 1));
    for (char& c : inner)
        if (c == ',') c = ' ';
    size_t consumed = 0;
    auto v = parse_float_list(inner, &consumed);
    // Like shader_runner's sscanf: extra numbers after the first n are ignored.
    if (v.size() < n) return std::nullopt;
    v.resize(n);
    s = trim(s.substr(close + 1));
    return v;
}

// ------------------------------------------------------------- probes ---
// After "probe"/"relative probe" (and "warn"): [rect|all] rgb|rgba coordinates color.
Parsed<CommandData> parse_probe(std::string_view rest, bool relative, bool warn,
                                std::string_view line) {
    Probe p;
    p.relative = relative;
    p.warn = warn;
    if (eat(rest, "rect")) p.region = Probe::Region::Rect;
    else if (eat(rest, "all")) p.region = Probe::Region::All;
    if (eat(rest, "rgba")) p.rgba = true;
    else if (!eat(rest, "rgb")) return error("bad probe command \"" + std::string(line) + "\"");
    size_t ncolor = p.rgba ? 4 : 3;
    auto bad = [&] { return error("bad probe command \"" + std::string(line) + "\""); };
    if (p.region == Probe::Region::All) {
        if (relative) return bad();
        auto c = floats(rest, ncolor);
        if (!c) return bad();
        std::copy(c->begin(), c->end(), p.color.begin());
        return CommandData{p};
    }
    size_t ncoord = p.region == Probe::Region::Rect ? 4 : 2;
    if (p.region == Probe::Region::Pixel && !relative) {  // "probe rgb x y r g b"
        auto v = floats(rest, ncoord + ncolor);
        if (!v) return bad();
        std::copy(v->begin(), v->begin() + 2, p.rect.begin());
        std::copy(v->begin() + 2, v->end(), p.color.begin());
        return CommandData{p};
    }
    auto coords = paren_group(rest, ncoord);
    if (!coords) return bad();
    auto color = paren_group(rest, ncolor);
    if (!color) return bad();
    std::copy(coords->begin(), coords->end(), p.rect.begin());
    std::copy(color->begin(), color->end(), p.color.begin());
    return CommandData{p};
}

// ------------------------------------------------------------ uniforms ---
struct UniformShape {
    bool integer = false;
    size_t count = 0;
};

// Component count and kind of a uniform command type; nullopt if unknown.
std::optional<UniformShape> uniform_shape(std::string_view type) {
    if (type == "float") return UniformShape{false, 1};
    // uint/uvec: glUniform*ui on a bool or int uniform, which GL allows (the
    // values travel as their 32-bit patterns); GLSL 1.30's uint types never get here.
    if (type == "int" || type == "bool" || type == "uint") return UniformShape{true, 1};
    auto digit = [](char c) { return c >= '2' && c <= '4'; };
    if (type.size() == 4 && starts_with(type, "vec") && digit(type[3]))
        return UniformShape{false, size_t(type[3] - '0')};
    if (type.size() == 5 && (starts_with(type, "ivec") || starts_with(type, "bvec") || starts_with(type, "uvec")) &&
        digit(type[4]))
        return UniformShape{true, size_t(type[4] - '0')};
    if (starts_with(type, "mat")) {
        if (type.size() == 4 && digit(type[3])) return UniformShape{false, size_t((type[3] - '0') * (type[3] - '0'))};
        if (type.size() == 6 && digit(type[3]) && type[4] == 'x' && digit(type[5]))
            return UniformShape{false, size_t((type[3] - '0') * (type[5] - '0'))};
    }
    return std::nullopt;
}

Parsed<CommandData> parse_uniform(std::string_view rest) {
    size_t sp = rest.find_first_of(" \t");
    if (sp == std::string_view::npos) return error("uniform command needs a type, a name and values");
    std::string_view type = rest.substr(0, sp);
    rest = trim(rest.substr(sp));
    if (starts_with(type, "double") || starts_with(type, "dvec") || starts_with(type, "dmat") ||
        starts_with(type, "int64") || starts_with(type, "uint64") || starts_with(type, "i64vec") ||
        starts_with(type, "u64vec") || starts_with(type, "handle"))
        return CommandData{Unsupported{"uniform type " + std::string(type) + " needs GL 4"}};
    auto shape = uniform_shape(type);
    if (!shape) return error("unknown uniform type \"" + std::string(type) + "\"");
    sp = rest.find_first_of(" \t");
    if (rest.empty()) return error("uniform command needs a name");
    SetUniform u;
    u.type = std::string(type);
    u.name = std::string(rest.substr(0, sp));
    std::string_view values = sp == std::string_view::npos ? std::string_view{} : rest.substr(sp);
    u.integer = shape->integer;
    size_t got = 0;
    if (u.integer) {
        u.ints = parse_int_list(values);
        got = u.ints.size();
        if (got >= shape->count) u.ints.resize(shape->count);
    } else {
        u.floats = parse_float_list(values);
        got = u.floats.size();
        if (got >= shape->count) u.floats.resize(shape->count);
    }
    // piglit reads a fixed count with strtod and uses whatever it got; tests
    // rely on that ("uniform vec4 v 1 2 3"), so missing values become 0.
    if (got == 0)
        return error("uniform " + std::string(type) + " " + u.name + " needs " +
                     std::to_string(shape->count) + " values, found none");
    if (u.integer) u.ints.resize(shape->count, 0);
    else u.floats.resize(shape->count, 0.0f);
    return CommandData{std::move(u)};
}

// ---------------------------------------------------------------- misc ---
Parsed<CommandData> parse_draw(std::string_view rest, std::string_view line) {
    auto bad = [&] { return error("bad draw command \"" + std::string(line) + "\""); };
    if (eat(rest, "rect")) {
        if (starts_with(rest, "patch") || starts_with(rest, "ortho patch"))
            return CommandData{Unsupported{"patches need tessellation shaders"}};
        DrawRect d;
        if (eat(rest, "tex")) {
            auto v = floats(rest, 8);
            if (!v) return bad();
            d.tex = true;
            std::copy(v->begin(), v->begin() + 4, d.rect.begin());
            std::copy(v->begin() + 4, v->end(), d.tex_rect.begin());
            return CommandData{d};
        }
        d.ortho = eat(rest, "ortho");
        auto r = float_array<4>(rest);
        if (!r) return bad();
        d.rect = *r;
        return CommandData{d};
    }
    if (starts_with(rest, "arrays instanced") || starts_with(rest, "instanced") ||
        starts_with(rest, "elements"))
        return CommandData{Unsupported{"instanced/indexed draws need GL 3"}};
    if (eat(rest, "arrays")) {
        size_t sp = rest.find_first_of(" \t");
        if (sp == std::string_view::npos) return bad();
        DrawArrays d;
        d.mode = std::string(rest.substr(0, sp));
        auto n = parse_int_list(rest.substr(sp));
        if (n.size() < 2) return bad();
        d.first = n[0];
        d.count = n[1];
        if (d.first < 0) return error("draw arrays 'first' must be >= 0");
        if (d.count <= 0) return error("draw arrays 'count' must be > 0");
        return CommandData{d};
    }
    return error("unknown command \"" + std::string(line) + "\"");
}

// "light 0 GL_POSITION float 0.2 0.5 0.8 0.1"
Parsed<CommandData> parse_light(std::string_view rest, std::string_view line) {
    auto bad = [&] { return error("bad light command \"" + std::string(line) + "\""); };
    auto index = parse_int_list(rest.substr(0, rest.find_first_of(" \t")));
    if (index.size() != 1 || index[0] < 0 || index[0] > 7) return bad();
    rest = trim(rest.substr(std::min(rest.size(), rest.find_first_of(" \t"))));
    size_t sp = rest.find_first_of(" \t");
    if (sp == std::string_view::npos) return bad();
    Light l;
    l.index = index[0];
    l.param = std::string(rest.substr(0, sp));
    rest = trim(rest.substr(sp));
    eat(rest, "float");
    l.values = parse_float_list(rest);
    if (l.values.empty() || l.values.size() > 4) return bad();
    return CommandData{std::move(l)};
}

// ------------------------------------------------------------ textures ---
// A cursor for shader_runner's sscanf patterns ("%d ( %d , %d )"): whitespace
// is skipped before every item.
struct Scanner {
    std::string_view s;

    bool literal(char c) {
        s = trim(s);
        if (s.empty() || s[0] != c) return false;
        s.remove_prefix(1);
        return true;
    }
    // A decimal int; nullopt if there is none or it does not fit an int.
    std::optional<int> integer() {
        s = trim(s);
        std::string buf(s.substr(0, std::min<size_t>(s.size(), 32)));
        char* end = nullptr;
        errno = 0;
        long long v = std::strtoll(buf.c_str(), &end, 10);
        if (end == buf.c_str() || errno == ERANGE || v < INT32_MIN || v > INT32_MAX) return std::nullopt;
        s.remove_prefix(size_t(end - buf.c_str()));
        return int(v);
    }
    // "( a , b , c , d )": n numbers.
    std::optional<std::array<float, 4>> color() {
        auto v = paren_group(s, 4);
        if (!v) return std::nullopt;
        return std::array<float, 4>{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
    }
    // The next whitespace-delimited word ("" at the end).
    std::string_view word() {
        s = trim(s);
        size_t n = std::min(s.size(), s.find_first_of(" \t"));
        std::string_view w = s.substr(0, n);
        s.remove_prefix(n);
        return w;
    }
};

// "( w )" or "( w , h )".
bool scan_size(Scanner& in, int& w, int* h) {
    if (!in.literal('(')) return false;
    auto a = in.integer();
    if (!a) return false;
    w = *a;
    if (h) {
        if (!in.literal(',')) return false;
        auto b = in.integer();
        if (!b) return false;
        *h = *b;
    }
    return in.literal(')');
}

// The internal formats "texture rgbw N (w, h) FORMAT" can have here: ours
// store RGBA8 or floats, and rgbw's texels (0 or 1, alpha 1) survive every one
// of these unchanged.
std::optional<bool> rgbw_format_is_float(std::string_view f) {
    for (std::string_view n : {"GL_RGBA", "GL_RGBA8", "GL_RGB", "GL_RGB8"})
        if (f == n) return false;
    for (std::string_view n : {"GL_RGBA32F", "GL_RGBA16F", "GL_RGB32F", "GL_RGB16F"})
        if (f == n) return true;
    return std::nullopt;
}

Parsed<CommandData> parse_rgbw(Scanner in, std::string_view line) {
    TextureCommand t;
    auto unit = in.integer();
    if (!unit || !scan_size(in, t.width, &t.height)) return error("bad texture rgbw command \"" + std::string(line) + "\"");
    t.unit = *unit;
    std::string_view format = in.word();
    if (!format.empty()) {
        auto is_float = rgbw_format_is_float(format);
        if (!is_float) return CommandData{Unsupported{"texture format " + std::string(format) + " is not supported"}};
        t.format = std::string(format);
        t.float_format = *is_float;
    }
    return CommandData{t};
}

Parsed<CommandData> parse_checkerboard(Scanner in, std::string_view line) {
    TextureCommand t;
    t.kind = TextureCommand::Kind::Checkerboard;
    auto unit = in.integer();
    auto level = unit ? in.integer() : std::nullopt;
    if (!level || !scan_size(in, t.width, &t.height))
        return error("bad texture checkerboard command \"" + std::string(line) + "\"");
    auto black = in.color();
    auto white = black ? in.color() : std::nullopt;
    if (!white) return error("bad texture checkerboard command \"" + std::string(line) + "\"");
    t.unit = *unit;
    t.level = *level;
    t.black = *black;
    t.white = *white;
    return CommandData{t};
}

// "texture shadow1D N (w)", "texture shadow2D N (w, h)", "texture shadowRect N (w, h)".
Parsed<CommandData> parse_shadow(Scanner in, TextureCommand::Kind kind, std::string_view line) {
    TextureCommand t;
    t.kind = kind;
    const bool two_d = kind != TextureCommand::Kind::Shadow1D;
    auto unit = in.integer();
    if (!unit || !scan_size(in, t.width, two_d ? &t.height : nullptr))
        return error("bad texture command \"" + std::string(line) + "\"");
    t.unit = *unit;
    return CommandData{t};
}

// "texture rgbw 1D N", "texture rgbw 3D N", "texture miptree N": piglit's
// fixed 4-texel, 2x2x2 and 8x8-with-mipmaps textures.
Parsed<CommandData> parse_fixed_rgbw(Scanner in, TextureCommand::Kind kind, std::string_view line) {
    TextureCommand t;
    t.kind = kind;
    auto unit = in.integer();
    if (!unit) return error("bad texture command \"" + std::string(line) + "\"");
    t.unit = *unit;
    return CommandData{t};
}

// "texture rgbw 1DArray N (w, l)", "texture rgbw 2DArray N (w, h, l)",
// "texture shadow1DArray N (w, l)", "texture shadow2DArray N (w, h, l)"
// (EXT_texture_array): the size, then the layer count.
Parsed<CommandData> parse_array(Scanner in, TextureCommand::Kind kind, std::string_view line) {
    TextureCommand t;
    t.kind = kind;
    const bool two_d = kind == TextureCommand::Kind::Rgbw2DArray || kind == TextureCommand::Kind::Shadow2DArray;
    auto unit = in.integer();
    bool ok = unit && in.literal('(');
    std::optional<int> w = ok ? in.integer() : std::nullopt;
    ok = w && in.literal(',');
    std::optional<int> h = ok && two_d ? in.integer() : std::optional<int>(1);
    ok = ok && h && (!two_d || in.literal(','));
    std::optional<int> l = ok ? in.integer() : std::nullopt;
    if (!l || !in.literal(')')) return error("bad texture command \"" + std::string(line) + "\"");
    t.unit = *unit;
    t.width = *w;
    t.height = *h;
    t.layers = *l;
    return CommandData{t};
}

// After "texture ". The integer variants need GL 3 or extensions we do not
// expose; the other helpers are not used by GLSL 1.x tests.
Parsed<CommandData> parse_texture(std::string_view rest, std::string_view line) {
    using K = TextureCommand::Kind;
    if (eat(rest, "rgbw 1DArray")) return parse_array({rest}, K::Rgbw1DArray, line);
    if (eat(rest, "rgbw 2DArray")) return parse_array({rest}, K::Rgbw2DArray, line);
    if (eat(rest, "shadow1DArray")) return parse_array({rest}, K::Shadow1DArray, line);
    if (eat(rest, "shadow2DArray")) return parse_array({rest}, K::Shadow2DArray, line);
    if (eat(rest, "rgbw 1D")) return parse_fixed_rgbw({rest}, TextureCommand::Kind::Rgbw1D, line);
    if (eat(rest, "rgbw 3D")) return parse_fixed_rgbw({rest}, TextureCommand::Kind::Rgbw3D, line);
    if (eat(rest, "miptree")) return parse_fixed_rgbw({rest}, TextureCommand::Kind::Miptree, line);
    if (eat(rest, "rgbw")) return parse_rgbw({rest}, line);
    if (eat(rest, "checkerboard")) return parse_checkerboard({rest}, line);
    if (eat(rest, "shadow2D")) return parse_shadow({rest}, TextureCommand::Kind::Shadow2D, line);
    if (eat(rest, "shadow1D")) return parse_shadow({rest}, TextureCommand::Kind::Shadow1D, line);
    if (eat(rest, "shadowRect")) return parse_shadow({rest}, TextureCommand::Kind::ShadowRect, line);
    std::string_view kind = Scanner{rest}.word();
    return CommandData{Unsupported{"unsupported command \"texture " + std::string(kind) + "\""}};
}

// The values shader_runner's handle_texparameter accepts for each enum parameter.
using Names = std::initializer_list<std::string_view>;
const Names kCompareFuncs = {"greater", "gequal", "less", "lequal", "equal", "notequal", "never", "always"};
const Names kDepthModes = {"intensity", "luminance", "alpha"};
const Names kMinFilters = {"nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear",
                           "linear_mipmap_linear", "nearest", "linear"};
const Names kMagFilters = {"nearest", "linear"};
const Names kWrapModes = {"repeat", "clamp_to_edge", "clamp_to_border"};

struct ParamSpec {
    std::string_view word;
    TexParameter::Name name;
    const Names* values;  // null: numbers follow
};
const ParamSpec kParams[] = {
    {"compare_func", TexParameter::Name::CompareFunc, &kCompareFuncs},
    {"depth_mode", TexParameter::Name::DepthMode, &kDepthModes},
    {"min", TexParameter::Name::Min, &kMinFilters},
    {"mag", TexParameter::Name::Mag, &kMagFilters},
    {"wrap_s", TexParameter::Name::WrapS, &kWrapModes},
    {"wrap_t", TexParameter::Name::WrapT, &kWrapModes},
    {"wrap_r", TexParameter::Name::WrapR, &kWrapModes},
    {"lod_bias", TexParameter::Name::LodBias, nullptr},
    {"max_level", TexParameter::Name::MaxLevel, nullptr},
    {"base_level", TexParameter::Name::BaseLevel, nullptr},
    {"border_color", TexParameter::Name::BorderColor, nullptr},
};

std::optional<TexParameter::Target> tex_target(std::string_view w) {
    if (w == "1D") return TexParameter::Target::Tex1D;
    if (w == "2D") return TexParameter::Target::Tex2D;
    if (w == "3D") return TexParameter::Target::Tex3D;
    if (w == "Cube") return TexParameter::Target::Cube;
    if (w == "Rect") return TexParameter::Target::Rect;
    if (w == "1DArray") return TexParameter::Target::Tex1DArray;
    if (w == "2DArray") return TexParameter::Target::Tex2DArray;
    return std::nullopt;
}

// lod_bias: one float; max_level/base_level: one int; border_color: four floats.
bool texparameter_numbers(TexParameter& p, std::string_view rest) {
    if (p.name == TexParameter::Name::MaxLevel || p.name == TexParameter::Name::BaseLevel) {
        auto v = Scanner{rest}.integer();
        if (v) p.numbers[0] = float(*v);
        return v.has_value();
    }
    size_t n = p.name == TexParameter::Name::BorderColor ? 4 : 1;
    auto v = floats(rest, n);
    if (v) std::copy(v->begin(), v->end(), p.numbers.begin());
    return v.has_value();
}

// After "texparameter ".
Parsed<CommandData> parse_texparameter(std::string_view rest, std::string_view line) {
    Scanner in{rest};
    std::string_view target = in.word();
    if (target == "CubeArray") return CommandData{Unsupported{"texparameter CubeArray needs GL 4 or extensions"}};
    std::string_view name = in.word();
    if (name == "swizzle_r") return CommandData{Unsupported{"texparameter swizzle_r needs GL_EXT_texture_swizzle"}};
    TexParameter p;
    auto t = tex_target(target);
    if (!t) return error("bad texture target \"" + std::string(target) + "\" in \"" + std::string(line) + "\"");
    p.target = *t;
    const ParamSpec* spec = nullptr;
    for (const auto& s : kParams)
        if (s.word == name) spec = &s;
    if (!spec) return error("unknown texture parameter \"" + std::string(name) + "\"");
    p.name = spec->name;
    if (!spec->values) {
        if (!texparameter_numbers(p, in.s)) return error("bad " + std::string(name) + " value in \"" + std::string(line) + "\"");
        return CommandData{p};
    }
    std::string_view value = in.word();
    if (p.name == TexParameter::Name::DepthMode && value == "red")
        return CommandData{Unsupported{"depth_mode red needs GL 3.0"}};
    if (std::find(spec->values->begin(), spec->values->end(), value) == spec->values->end())
        return error("bad " + std::string(name) + " \"" + std::string(value) + "\"");
    p.value = std::string(value);
    return CommandData{p};
}

constexpr std::string_view kUnsupportedCommands[] = {
    "ubo ", "block ", "ssbo ", "atomic ", "compute ", "fb ", "blit ", "image texture",
    "memory barrier", "xfb ", "probe xfb", "probe ssbo", "probe atomic", "subuniform ",
    "parameter ", "patch parameter", "provoking vertex", "polygon mode", "viewport ",
    "vertex attrib ", "active uniform", "active shader program", "verify ", "newlist",
    "endlist", "calllist", "deletelist", "resident ", "program binary",
    "multidraw ", "blend barrier", "fbfetch barrier", "begin query", "end query",
    "relative probe rect rgba int", "probe rect rgba int",
};

// `depthfunc GL_LEQUAL`: glDepthFunc's eight functions.
Parsed<CommandData> parse_depth_func(std::string_view rest, std::string_view line) {
    static constexpr std::pair<std::string_view, CompareFunc> kFuncs[] = {
        {"GL_NEVER", CompareFunc::Never},     {"GL_LESS", CompareFunc::Less},     {"GL_EQUAL", CompareFunc::Equal},
        {"GL_LEQUAL", CompareFunc::Lequal},   {"GL_GREATER", CompareFunc::Greater},
        {"GL_NOTEQUAL", CompareFunc::Notequal}, {"GL_GEQUAL", CompareFunc::Gequal}, {"GL_ALWAYS", CompareFunc::Always},
    };
    for (const auto& [name, func] : kFuncs)
        if (trim(rest) == name) return CommandData{DepthFunc{func}};
    return error("bad depthfunc command \"" + std::string(line) + "\" (GL_NEVER, GL_LESS, ..., GL_ALWAYS)");
}

}  // namespace

Parsed<CommandData> parse_command(std::string_view raw) {
    std::string_view line = trim(raw);
    if (line.empty() || line[0] == '#' || starts_with(line, "//")) return CommandData{Ignored{}};
    std::string_view rest = line;
    auto bad = [&](const char* what) { return error(std::string("bad ") + what + " command \"" + std::string(line) + "\""); };

    for (auto prefix : kUnsupportedCommands)
        if (starts_with(line, prefix))
            return CommandData{Unsupported{"unsupported command \"" + std::string(prefix) + "\""}};
    if (eat(rest, "clear color")) {
        auto c = float_array<4>(rest);
        if (!c) return bad("clear color");
        return CommandData{ClearColor{*c}};
    }
    if (eat(rest, "clear depth")) {
        auto d = floats(rest, 1);
        if (!d) return bad("clear depth");
        return CommandData{ClearDepth{(*d)[0]}};
    }
    if (eat(rest, "clear")) return CommandData{Clear{}};
    if (eat(rest, "clip plane")) {
        auto idx = parse_int_list(rest.substr(0, rest.find_first_of(" \t")));
        auto v = parse_float_list(rest);
        if (idx.size() != 1 || v.size() < 5) return bad("clip plane");
        ClipPlane c;
        c.index = idx[0];
        for (int i = 0; i < 4; ++i) c.plane[i] = v[i + 1];
        return CommandData{c};
    }
    if (eat(rest, "color ")) {
        auto c = float_array<4>(rest);
        if (!c) return bad("color");
        return CommandData{CurrentColor{*c}};
    }
    if (eat(rest, "depthfunc")) return parse_depth_func(rest, line);
    if (eat(rest, "draw")) return parse_draw(rest, line);
    if (eat(rest, "disable")) return CommandData{Enable{std::string(rest), false}};
    if (eat(rest, "enable")) return CommandData{Enable{std::string(rest), true}};
    if (eat(rest, "frustum")) {
        auto f = float_array<6>(rest);
        if (!f) return bad("frustum");
        return CommandData{Frustum{*f}};
    }
    if (eat(rest, "hint")) return CommandData{Ignored{}};  // derivative hints change nothing here
    if (eat(rest, "ortho")) {
        if (rest.empty()) return CommandData{Ortho{}};
        auto o = float_array<4>(rest);
        if (!o) return bad("ortho");
        return CommandData{Ortho{*o}};
    }
    if (eat(rest, "probe depth")) {
        auto v = floats(rest, 3);
        // Pixel coordinates become ints: an infinite or huge value is refused, not converted (UB).
        auto pixel = [](float c) { return std::isfinite(c) && std::fabs(c) < 1e9f; };
        if (!v || !pixel((*v)[0]) || !pixel((*v)[1])) return bad("probe depth");
        return CommandData{ProbeDepth{int((*v)[0]), int((*v)[1]), (*v)[2]}};
    }
    if (eat(rest, "relative probe")) {
        bool warn = eat(rest, "warn");
        return parse_probe(rest, true, warn, line);
    }
    if (eat(rest, "probe")) {
        bool warn = eat(rest, "warn");
        return parse_probe(rest, false, warn, line);
    }
    if (eat(rest, "tolerance")) {
        auto t = float_array<4>(rest);
        if (!t) return bad("tolerance");
        return CommandData{Tolerance{*t}};
    }
    if (eat(rest, "shade model")) {
        if (rest == "flat") return CommandData{ShadeModel{true}};
        if (rest == "smooth") return CommandData{ShadeModel{false}};
        return bad("shade model");
    }
    if (eat(rest, "texture ")) return parse_texture(rest, line);
    if (eat(rest, "texparameter ")) return parse_texparameter(rest, line);
    // glMultiTexCoord: GLState has no current texture coordinate yet.
    if (starts_with(line, "texcoord ")) return CommandData{Unsupported{"unsupported command \"texcoord\""}};
    if (eat(rest, "uniform ")) return parse_uniform(rest);
    if (eat(rest, "link error")) return CommandData{LinkCheck{false}};
    if (eat(rest, "link success")) return CommandData{LinkCheck{true}};
    if (eat(rest, "light ")) return parse_light(rest, line);
    return error("unknown command \"" + std::string(line) + "\"");
}

}  // namespace glslrun::piglit
