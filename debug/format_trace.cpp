// The trace and the NaN report as text (glslrun trace) and JSON (--json).
#include <cmath>

#include <fmt/format.h>

#include "debug/debugger.h"

namespace glslrun::debug {
namespace {

const char* outcome_text(FragmentTrace::Outcome o) {
    switch (o) {
        case FragmentTrace::Outcome::Written:
            return "passes the depth test, written";
        case FragmentTrace::Outcome::DepthFailed:
            return "fails the depth test";
        case FragmentTrace::Outcome::Discarded:
            return "discarded";
    }
    return "?";
}

const char* outcome_key(FragmentTrace::Outcome o) {
    static constexpr const char* kKeys[] = {"written", "depth_failed", "discarded"};
    return kKeys[size_t(o)];
}

void text_values(std::string& out, const char* title, const std::vector<NamedValue>& list) {
    if (list.empty()) return;
    out += fmt::format("  {}:\n", title);
    for (const NamedValue& v : list) out += fmt::format("    {} = {}\n", v.name, format_value(v.value, v.type));
}

void text_invocation(std::string& out, const InvocationTrace& t) {
    text_values(out, "inputs", t.inputs);
    text_values(out, "uniforms read", t.uniforms);
    out += "  steps:\n";
    for (const TraceStep& s : t.steps) {
        std::string pad(size_t(4 + 2 * s.depth), ' ');
        switch (s.kind) {
            case TraceStep::Kind::Statement:
                out += pad + s.where + "\n";
                break;
            case TraceStep::Kind::Assign:
                out += fmt::format("{}    {} = {}\n", pad, s.name, format_value(s.value, s.type));
                break;
            case TraceStep::Kind::Branch:
                out +=
                    fmt::format("{}{}  if: {}\n", pad, s.where, s.taken ? "true, then-branch" : "false, else-branch");
                break;
            case TraceStep::Kind::Loop:
                out += fmt::format("{}{}  loop iteration {}\n", pad, s.where, s.iteration);
                break;
            case TraceStep::Kind::Jump:
                out += fmt::format("{}{}  {}\n", pad, s.where, s.name);
                break;
            case TraceStep::Kind::Call:
                out += fmt::format("{}{}  call {}\n", pad, s.where, s.name);
                break;
        }
    }
    if (!t.stopped.empty()) out += fmt::format("    ... (stopped: {})\n", t.stopped);
    else if (t.truncated)
        out += fmt::format("    ... (the rest is not shown: at most {} steps per invocation and {} per trace)\n",
                           InvocationTrace::kMaxSteps, InvocationTrace::kMaxTraceSteps);
    if (t.first_nan)
        out += fmt::format("  first NaN/Inf: {} {} -> {}\n", t.first_nan->where, t.first_nan->op,
                           format_value(t.first_nan->result, ""));
    text_values(out, "outputs", t.outputs);
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20)
            out += fmt::format("\\u{:04x}", int(c));
        else
            out += c;
    }
    return out + "\"";
}

// JSON has no NaN or infinity: those are strings.
std::string json_number(const Values& v, double x) {
    if (std::isnan(x)) return "\"NaN\"";
    if (std::isinf(x)) return x > 0 ? "\"Infinity\"" : "\"-Infinity\"";
    if (v.kind == ir::Kind::Bool) return x != 0 ? "true" : "false";
    return v.kind == ir::Kind::F32 && !v.wide ? fmt::format("{}", float(x)) : fmt::format("{}", x);
}

std::string json_values(const Values& v) {
    std::string out = "[";
    for (size_t i = 0; i < v.c.size(); ++i) out += (i ? "," : "") + json_number(v, v.c[i]);
    return out + "]";
}

std::string json_named(const std::vector<NamedValue>& list) {
    std::string out = "[";
    for (size_t i = 0; i < list.size(); ++i)
        out += fmt::format("{}{{\"name\":{},\"type\":{},\"value\":{}}}", i ? "," : "", json_string(list[i].name),
                           json_string(list[i].type), json_values(list[i].value));
    return out + "]";
}

std::string json_step(const TraceStep& s) {
    static constexpr const char* kKinds[] = {"statement", "assign", "branch", "loop", "jump", "call"};
    std::string out = fmt::format("{{\"kind\":\"{}\",\"depth\":{}", kKinds[size_t(s.kind)], s.depth);
    if (!s.where.empty()) out += ",\"where\":" + json_string(s.where);
    if (!s.name.empty()) out += ",\"name\":" + json_string(s.name);
    if (s.kind == TraceStep::Kind::Assign)
        out += ",\"type\":" + json_string(s.type) + ",\"value\":" + json_values(s.value);
    if (s.kind == TraceStep::Kind::Branch) out += fmt::format(",\"taken\":{}", s.taken);
    if (s.kind == TraceStep::Kind::Loop) out += fmt::format(",\"iteration\":{}", s.iteration);
    return out + "}";
}

std::string json_invocation(const InvocationTrace& t) {
    std::string steps = "[";
    for (size_t i = 0; i < t.steps.size(); ++i) steps += (i ? ",\n" : "\n") + json_step(t.steps[i]);
    std::string nan = "null";
    if (t.first_nan)
        nan = fmt::format("{{\"where\":{},\"op\":{},\"result\":{}}}", json_string(t.first_nan->where),
                          json_string(t.first_nan->op), json_values(t.first_nan->result));
    return fmt::format(
        "{{\"inputs\":{},\"uniforms\":{},\"steps\":{}],\"outputs\":{},\"discarded\":{},"
        "\"truncated\":{},\"stopped\":{},\"first_nan\":{}}}",
        json_named(t.inputs), json_named(t.uniforms), steps, json_named(t.outputs), t.discarded, t.truncated,
        t.stopped.empty() ? "null" : json_string(t.stopped), nan);
}

}  // namespace

std::string format_text(const PixelTrace& t) {
    std::string out;
    if (t.fragments.empty() && t.vertices.empty()) return fmt::format("pixel {},{}: no fragment\n", t.x, t.y);
    for (size_t i = 0; i < t.fragments.size(); ++i) {
        const FragmentTrace& f = t.fragments[i];
        out +=
            fmt::format("fragment {} at pixel {},{}: draw {}, primitive {} (vertices {}, {}, {}), {}, depth {}: {}\n",
                        i, t.x, t.y, f.draw, f.primitive, f.vertices[0], f.vertices[1], f.vertices[2],
                        f.front ? "front" : "back", f.depth, outcome_text(f.outcome));
        text_invocation(out, f.trace);
        if (!f.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    for (const VertexTrace& v : t.vertices) {
        out += fmt::format("vertex {} of draw {}:\n", v.vertex, v.draw);
        text_invocation(out, v.trace);
        if (!v.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    return out;
}

std::string format_json(const PixelTrace& t) {
    std::string fragments = "[";
    for (size_t i = 0; i < t.fragments.size(); ++i) {
        const FragmentTrace& f = t.fragments[i];
        fragments += fmt::format(
            "{}{{\"draw\":{},\"primitive\":{},\"vertices\":[{},{},{}],\"front\":{},\"depth\":{},"
            "\"outcome\":\"{}\",\"matches_render\":{},\"rendered\":{},\"trace\":{}}}",
            i ? ",\n" : "\n", f.draw, f.primitive, f.vertices[0], f.vertices[1], f.vertices[2], f.front, f.depth,
            outcome_key(f.outcome), f.matches_render, json_named(f.rendered), json_invocation(f.trace));
    }
    std::string vertices = "[";
    for (size_t i = 0; i < t.vertices.size(); ++i)
        vertices += fmt::format("{}{{\"draw\":{},\"vertex\":{},\"matches_render\":{},\"trace\":{}}}", i ? ",\n" : "\n",
                                t.vertices[i].draw, t.vertices[i].vertex, t.vertices[i].matches_render,
                                json_invocation(t.vertices[i].trace));
    return fmt::format("{{\"pixel\":[{},{}],\"fragments\":{}],\"vertices\":{}]}}\n", t.x, t.y, fragments, vertices);
}

std::string format_text(const NanReport& r) {
    auto finding = [](const char* what, const NanFinding& f) {
        std::string who = f.vertex ? fmt::format("vertex {} of draw {}", f.vertex_index, f.draw)
                                   : fmt::format("pixel {},{} (draw {}, primitive {})", f.x, f.y, f.draw, f.primitive);
        std::string operands;
        for (size_t i = 0; i < f.event.operands.size(); ++i)
            operands += (i ? ", " : "") + format_value(f.event.operands[i], "");
        std::string into = f.event.variable.empty() ? "" : fmt::format(" (into {})", f.event.variable);
        if (f.event.where.empty())
            return fmt::format("{}: {}: {} = {}\n", what, who, f.event.op, format_value(f.event.result, ""));
        return fmt::format("{}: {}: {}: {}({}) = {}{}\n", what, who, f.event.where, f.event.op, operands,
                           format_value(f.event.result, ""), into);
    };
    std::string out = r.nan ? finding("first NaN/Inf", *r.nan) : "no NaN or infinity in any invocation\n";
    if (r.out_of_range) out += finding("first colour outside [0,1]", *r.out_of_range);
    return out;
}

}  // namespace glslrun::debug
