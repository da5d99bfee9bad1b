// One [test] command line -> CommandData. The prefixes are tried in
// shader_runner's order, so "clear color" wins over "clear", "draw rect tex"
// over "draw rect", and so on.
#include <cctype>
#include <algorithm>
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

constexpr std::string_view kUnsupportedCommands[] = {
    "ubo ", "block ", "ssbo ", "atomic ", "compute ", "fb ", "blit ", "image texture",
    "memory barrier", "xfb ", "probe xfb", "probe ssbo", "probe atomic", "subuniform ",
    "parameter ", "patch parameter", "provoking vertex", "polygon mode", "viewport ",
    "vertex attrib ", "active uniform", "active shader program", "verify ", "newlist",
    "endlist", "calllist", "deletelist", "resident ", "depthfunc ", "program binary",
    "multidraw ", "blend barrier", "fbfetch barrier", "begin query", "end query",
    "relative probe rect rgba int", "probe rect rgba int",
};

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
        if (!v) return bad("probe depth");
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
    if (starts_with(line, "texture ") || starts_with(line, "texparameter ") ||
        starts_with(line, "texcoord "))
        return CommandData{Unsupported{"textures: issue #4"}};
    if (eat(rest, "uniform ")) return parse_uniform(rest);
    if (eat(rest, "link error")) return CommandData{LinkCheck{false}};
    if (eat(rest, "link success")) return CommandData{LinkCheck{true}};
    if (eat(rest, "light ")) return parse_light(rest, line);
    return error("unknown command \"" + std::string(line) + "\"");
}

}  // namespace glslrun::piglit
