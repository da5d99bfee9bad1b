// The trace as JSON (glslrun trace --json; the page of `glslrun serve` reads
// it), written with nlohmann-json. docs/debugging.md lists the fields.
#include <array>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "debug/format_common.h"

namespace glslrun::debug {
namespace {

using namespace detail;
using Json = nlohmann::ordered_json;  // the fields in the order written

// JSON has no NaN or infinity: those are strings. An fp32 value is written
// as its shortest decimal (0.8061945, not the double 0.8061944842338562).
Json number(double x, ir::Kind kind = ir::Kind::F32, bool wide = false) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "Infinity" : "-Infinity";
    if (kind == ir::Kind::Bool) return x != 0;
    if (kind == ir::Kind::I32) return int64_t(x);
    const double shortest = wide ? x : std::strtod(fmt::format("{}", float(x)).c_str(), nullptr);
    // Whole numbers as integers ("1", not "1.0"), as the values print in the text; -0 stays a float.
    if (shortest == std::trunc(shortest) && std::fabs(shortest) < 0x1p53 && !(shortest == 0 && std::signbit(shortest)))
        return int64_t(shortest);
    return shortest;
}

Json values(const Values& v) {
    Json out = Json::array();
    for (double x : v.c) out.push_back(number(x, v.kind, v.wide));
    return out;
}

// A matrix's rows (of each matrix of an array in turn), as the text prints
// them; null for other types.
Json rows(const Values& v, const std::string& type) {
    auto [cols, nrows] = matrix_shape(type, v.c.size());
    if (cols == 1) return nullptr;
    Json out = Json::array();
    const size_t per_matrix = size_t(cols) * size_t(nrows);
    for (size_t m = 0; m < v.c.size(); m += per_matrix)
        for (int r = 0; r < nrows; ++r) {
            Json row = Json::array();
            for (int c = 0; c < cols; ++c) {
                size_t i = m + size_t(c) * size_t(nrows) + size_t(r);
                row.push_back(i < v.c.size() ? number(v.c[i], v.kind, v.wide) : Json(nullptr));
            }
            out.push_back(std::move(row));
        }
    return out;
}

Json named(const std::vector<NamedValue>& list) {
    Json out = Json::array();
    for (const NamedValue& v : list) {
        Json j = {{"name", v.name}, {"type", v.type}, {"value", values(v.value)}};
        if (Json r = rows(v.value, v.type); !r.is_null()) j["rows"] = std::move(r);
        out.push_back(std::move(j));
    }
    return out;
}

Json vec4(const glm::vec4& v) { return {number(v[0]), number(v[1]), number(v[2]), number(v[3])}; }

// A texture lookup: its operands, what the sampler computed (lod, lambda,
// levels, texels) and its result.
Json lookup(const TextureLookup& t) {
    // By ir::TexTarget: a target added there without a name here does not compile.
    static constexpr std::array<const char*, size_t(ir::TexTarget::A2D) + 1> kTargets = {
        "1D", "2D", "3D", "cube", "rectangle", "1D array", "2D array"};
    static constexpr const char* kLods[] = {"explicit", "implicit", "bias"};
    const rt::LookupDetails& d = t.details;
    Json coord = Json::array(), levels = Json::array(), texels = Json::array();
    for (float c : t.coord) coord.push_back(number(c));
    for (const rt::LookupLevel& l : d.levels)
        levels.push_back({{"level", l.level}, {"size", {l.width, l.height, l.depth}}, {"linear", l.linear}});
    for (const rt::LookupTexel& x : d.texels)
        texels.push_back({{"level", x.level}, {"texel", {x.i, x.j, x.k}}, {"value", vec4(x.value)}});
    Json j = {{"unit", t.unit},
              {"samplers", t.samplers},
              {"target", kTargets[size_t(t.info.target)]},
              {"shadow", t.info.shadow},
              {"lod_kind", kLods[size_t(t.info.lod)]},
              {"coord", std::move(coord)},
              {"ref", t.info.shadow ? number(t.ref) : Json(nullptr)},
              {"lod", t.info.lod == ir::TexLod::Implicit ? Json(nullptr) : number(t.lod)},
              {"complete", d.complete}};
    if (d.complete) {
        j["face"] = d.face >= 0 ? Json(d.face) : Json(nullptr);
        j["face_coord"] = d.face >= 0 ? Json{number(d.face_coord.x), number(d.face_coord.y)} : Json(nullptr);
        j["lod_implicit"] = t.info.lod == ir::TexLod::Explicit ? Json(nullptr) : number(d.lod_implicit);
        j["lod_used"] = d.lod_used;
        j["lambda"] = number(d.lambda);
        j["magnified"] = d.magnified;
        j["levels"] = std::move(levels);
        j["texels"] = std::move(texels);
    }
    j["result"] = vec4({t.result[0], t.result[1], t.result[2], t.result[3]});
    return j;
}

Json step(const TraceStep& s, const InvocationTrace& t, const SourceLines& lines) {
    static constexpr const char* kKinds[] = {"statement", "assign", "branch", "loop", "jump", "call", "lookup"};
    Json j = {{"kind", kKinds[size_t(s.kind)]}, {"depth", s.depth}};
    if (!s.where.empty()) {
        j["where"] = s.where;
        j["text"] = std::string(line_text(lines, t, s));
    }
    if (!s.name.empty()) j["name"] = s.name;
    if (s.kind == TraceStep::Kind::Assign) {
        j["type"] = s.type;
        j["value"] = values(s.value);
        if (Json r = rows(s.value, s.type); !r.is_null()) j["rows"] = std::move(r);
    }
    if (s.kind == TraceStep::Kind::Branch) j["taken"] = s.taken;
    if (s.kind == TraceStep::Kind::Loop) j["iteration"] = s.iteration;
    if (s.kind == TraceStep::Kind::Lookup && s.lookup < t.lookups.size()) j["lookup"] = lookup(t.lookups[s.lookup]);
    return j;
}

Json invocation(const InvocationTrace& t, const SourceLines& lines) {
    Json steps = Json::array();
    for (const TraceStep& s : t.steps) steps.push_back(step(s, t, lines));
    Json nan = nullptr;
    if (t.first_nan) nan = {{"where", t.first_nan->where}, {"op", t.first_nan->op}, {"result", values(t.first_nan->result)}};
    return {{"inputs", named(t.inputs)},     {"uniforms", named(t.uniforms)},
            {"steps", std::move(steps)},     {"outputs", named(t.outputs)},
            {"discarded", t.discarded},      {"truncated", t.truncated},
            {"stopped", t.stopped.empty() ? Json(nullptr) : Json(t.stopped)}, {"first_nan", std::move(nan)}};
}

Json tests(const FragmentTests& t) {
    return {{"scissor", {{"result", result_key(t.scissor_test)}}},
            {"alpha",
             {{"result", result_key(t.alpha_test)}, {"func", func_name(t.alpha_func)}, {"alpha", number(t.alpha)},
              {"reference", number(t.alpha_ref)}, {"bytes", t.alpha_bytes}}},
            {"stencil",
             {{"result", result_key(t.stencil_test)}, {"func", func_name(t.stencil_func)}, {"reference", t.stencil_ref},
              {"mask", t.stencil_mask}, {"stored", t.stored_stencil}}},
            {"depth",
             {{"result", result_key(t.depth_test)}, {"func", func_name(t.depth_func)}, {"z", number(t.z)},
              {"stored", number(t.stored_depth)}}}};
}

// The framebuffer at the pixel: "format" "rgba8" (channels are the bytes n
// of n/255) or "float"; "color" one RGBA list per colour buffer.
Json pixel(const PixelValues& p) {
    Json color = Json::array();
    for (const auto& c : p.color) color.push_back({number(c[0]), number(c[1]), number(c[2]), number(c[3])});
    return {{"format", p.bytes ? "rgba8" : "float"}, {"color", std::move(color)}, {"depth", number(p.depth)},
            {"stencil", p.stencil}};
}

Json writes(const ColorWrites& w) {
    Json blend = nullptr;
    if (w.blend) {
        const BlendState& b = w.blend_state;
        blend = {{"src_rgb", factor_name(b.src_rgb)},           {"dst_rgb", factor_name(b.dst_rgb)},
                 {"src_alpha", factor_name(b.src_alpha)},       {"dst_alpha", factor_name(b.dst_alpha)},
                 {"equation_rgb", equation_name(b.equation_rgb)}, {"equation_alpha", equation_name(b.equation_alpha)},
                 {"color", {number(b.color[0]), number(b.color[1]), number(b.color[2]), number(b.color[3])}}};
    }
    return {{"buffers", w.buffers},
            {"blend", std::move(blend)},
            {"logic_op", w.logic_op ? Json(logic_name(w.logic)) : Json(nullptr)},
            {"mask", w.mask}};
}

Json fragment(const FragmentTrace& f, const SourceLines& lines) {
    return {{"draw", f.draw},
            {"pass", f.pass.empty() ? Json(nullptr) : Json(f.pass)},
            {"program", f.program},
            {"primitive", f.primitive},
            {"vertices", f.vertices},
            {"front", f.front},
            {"depth", number(f.depth)},
            {"outcome", outcome_key(f.outcome)},
            {"tests", tests(f.tests)},
            {"before", pixel(f.before)},
            {"writes", writes(f.writes)},
            {"after", pixel(f.after)},
            {"matches_render", f.matches_render},
            {"rendered", named(f.rendered)},
            {"trace", invocation(f.trace, lines)}};
}

}  // namespace

std::string format_json(const PixelTrace& t) {
    Json fragments = Json::array(), vertices = Json::array();
    for (const FragmentTrace& f : t.fragments) fragments.push_back(fragment(f, t.source_lines));
    for (const VertexTrace& v : t.vertices)
        vertices.push_back({{"draw", v.draw},
                            {"pass", v.pass.empty() ? Json(nullptr) : Json(v.pass)},
                            {"program", v.program},
                            {"vertex", v.vertex},
                            {"matches_render", v.matches_render},
                            {"trace", invocation(v.trace, t.source_lines)}});
    // The fixed-function stages generated for the draws, whole: a step's file may be one of them.
    Json generated = Json::array();
    for (const GeneratedStage& g : t.generated)
        generated.push_back({{"name", g.name}, {"file", g.file}, {"stage", g.vertex ? "vertex" : "fragment"},
                             {"text", g.text}});
    Json out = {{"pixel", {t.x, t.y}},
                {"target", t.target.empty() ? Json(nullptr) : Json(t.target)},
                {"scissored", t.scissored},
                {"fragments", std::move(fragments)},
                {"vertices", std::move(vertices)},
                {"generated", std::move(generated)}};
    // Invalid UTF-8 in a shader's text is replaced, not thrown on.
    return out.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace glslrun::debug
