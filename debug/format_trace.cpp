// The trace and the NaN report as text (glslrun trace) and JSON (--json).
#include <cmath>
#include <map>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "debug/debugger.h"

namespace glslrun::debug {
namespace {

const char* outcome_text(FragmentTrace::Outcome o) {
    switch (o) {
        case FragmentTrace::Outcome::Written:
            return "written";
        case FragmentTrace::Outcome::DepthFailed:
            return "fails the depth test";
        case FragmentTrace::Outcome::Discarded:
            return "discarded";
        case FragmentTrace::Outcome::AlphaFailed:
            return "fails the alpha test";
        case FragmentTrace::Outcome::StencilFailed:
            return "fails the stencil test";
    }
    return "?";
}

const char* outcome_key(FragmentTrace::Outcome o) {
    static constexpr const char* kKeys[] = {"written", "depth_failed", "discarded", "alpha_failed", "stencil_failed"};
    return kKeys[size_t(o)];
}

const char* func_name(CompareFunc f) {
    static constexpr const char* kNames[] = {"never",   "less",     "equal",  "lequal",
                                             "greater", "notequal", "gequal", "always"};
    return kNames[size_t(f)];
}

const char* result_key(FragmentTests::Result r) {
    static constexpr const char* kKeys[] = {"off", "passed", "failed", "not_reached"};
    return kKeys[size_t(r)];
}

// "alpha 0.25 greater 0.5 (reference): fails", "depth off", "stencil not reached".
std::string test_text(const char* name, FragmentTests::Result r, const std::string& comparison) {
    using R = FragmentTests::Result;
    if (r == R::Off) return fmt::format("{} off", name);
    if (r == R::NotReached) return fmt::format("{} not reached", name);
    return fmt::format("{} {}: {}", name, comparison, r == R::Passed ? "passes" : "fails");
}

// The tests in GL's order (GL 2.1 §4.1), each with the values it compared.
std::string tests_text(const FragmentTests& t) {
    return fmt::format(
        "  tests: {}; {}; {}; {}\n", test_text("scissor", t.scissor_test, "(inside the box)"),
        test_text("alpha", t.alpha_test,
                  t.alpha_bytes ? fmt::format("{}/255 {} {}/255 (reference)", t.alpha, func_name(t.alpha_func),
                                              t.alpha_ref)
                                : fmt::format("{} {} {} (reference)", t.alpha, func_name(t.alpha_func), t.alpha_ref)),
        test_text("stencil", t.stencil_test,
                  fmt::format("(ref {} & {}) {} (stored {} & {})", t.stencil_ref, t.stencil_mask,
                              func_name(t.stencil_func), t.stored_stencil, t.stencil_mask)),
        test_text("depth", t.depth_test,
                  fmt::format("{} {} {} (stored)", t.z, func_name(t.depth_func), t.stored_depth)));
}

std::string json_number(const Values& v, double x);

std::string tests_json(const FragmentTests& t) {
    auto num = [](float x) { return json_number(Values{}, double(x)); };
    return fmt::format(
        "{{\"scissor\":{{\"result\":\"{}\"}},"
        "\"alpha\":{{\"result\":\"{}\",\"func\":\"{}\",\"alpha\":{},\"reference\":{},\"bytes\":{}}},"
        "\"stencil\":{{\"result\":\"{}\",\"func\":\"{}\",\"reference\":{},\"mask\":{},\"stored\":{}}},"
        "\"depth\":{{\"result\":\"{}\",\"func\":\"{}\",\"z\":{},\"stored\":{}}}}}",
        result_key(t.scissor_test), result_key(t.alpha_test), func_name(t.alpha_func), num(t.alpha),
        num(t.alpha_ref), t.alpha_bytes, result_key(t.stencil_test), func_name(t.stencil_func), t.stencil_ref,
        t.stencil_mask,
        t.stored_stencil, result_key(t.depth_test), func_name(t.depth_func), num(t.z), num(t.stored_depth));
}

// " (pass 'light', program a.vert + a.frag)"; nothing in a scene without passes.
std::string pass_text(const std::string& pass, const std::string& program) {
    return pass.empty() ? "" : fmt::format(" (pass '{}', program {})", pass, program);
}

// "name = value" at `pad`; a matrix as rows under its name, as --stats prints it.
void text_value(std::string& out, const std::string& pad, const std::string& name, const Values& value,
                const std::string& type) {
    if (!type.starts_with("mat")) {
        out += fmt::format("{}{} = {}\n", pad, name, format_value(value, type));
        return;
    }
    out += fmt::format("{}{} =\n", pad, name);
    for (const std::string& row : format_matrix_rows(value, type)) out += fmt::format("{}  {}\n", pad, row);
}

void text_values(std::string& out, const char* title, const std::vector<NamedValue>& list) {
    if (list.empty()) return;
    out += fmt::format("  {}:\n", title);
    for (const NamedValue& v : list) text_value(out, "    ", v.name, v.value, v.type);
}

using SourceLines = std::map<std::string, std::vector<std::string>>;

// The trimmed text of a step's line; empty when its source is unknown.
std::string_view line_text(const SourceLines& lines, const InvocationTrace& t, const TraceStep& s) {
    if (s.source >= t.files.size() || s.line == 0) return {};
    auto file = lines.find(t.files[s.source]);
    if (file == lines.end() || s.line > file->second.size()) return {};
    return file->second[s.line - 1];
}

// "file:line  text": the line's text after its place.
std::string where_text(const SourceLines& lines, const InvocationTrace& t, const TraceStep& s) {
    std::string_view text = line_text(lines, t, s);
    return text.empty() ? s.where : fmt::format("{}  {}", s.where, text);
}

void text_invocation(std::string& out, const InvocationTrace& t, const SourceLines& lines) {
    text_values(out, "inputs", t.inputs);
    text_values(out, "uniforms read", t.uniforms);
    out += "  steps:\n";
    for (const TraceStep& s : t.steps) {
        std::string pad(size_t(4 + 2 * s.depth), ' ');
        switch (s.kind) {
            case TraceStep::Kind::Statement:
                out += pad + where_text(lines, t, s) + "\n";
                break;
            case TraceStep::Kind::Assign:
                text_value(out, pad + "    ", s.name, s.value, s.type);
                break;
            case TraceStep::Kind::Branch:
                out += fmt::format("{}{}  => if: {}\n", pad, where_text(lines, t, s),
                                   s.taken ? "true, then-branch" : "false, else-branch");
                break;
            case TraceStep::Kind::Loop:
                out += fmt::format("{}{}  => loop iteration {}\n", pad, where_text(lines, t, s), s.iteration);
                break;
            case TraceStep::Kind::Jump:
                out += fmt::format("{}{}  => {}\n", pad, where_text(lines, t, s), s.name);
                break;
            case TraceStep::Kind::Call:
                out += fmt::format("{}{}  => call {}\n", pad, where_text(lines, t, s), s.name);
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

// A matrix's rows (",\"rows\":[[...],...]", of each matrix of an array in
// turn), as the text prints them; nothing for other types.
std::string json_rows(const Values& v, const std::string& type) {
    auto [cols, rows] = matrix_shape(type, v.c.size());
    if (cols == 1) return "";
    std::string out = ",\"rows\":[";
    const size_t per_matrix = size_t(cols) * size_t(rows);
    for (size_t m = 0; m < v.c.size(); m += per_matrix)
        for (int r = 0; r < rows; ++r) {
            out += m + size_t(r) ? ",[" : "[";
            for (int c = 0; c < cols; ++c) {
                size_t i = m + size_t(c) * size_t(rows) + size_t(r);
                out += (c ? "," : "") + (i < v.c.size() ? json_number(v, v.c[i]) : std::string("null"));
            }
            out += "]";
        }
    return out + "]";
}

std::string json_named(const std::vector<NamedValue>& list) {
    std::string out = "[";
    for (size_t i = 0; i < list.size(); ++i)
        out += fmt::format("{}{{\"name\":{},\"type\":{},\"value\":{}{}}}", i ? "," : "", json_string(list[i].name),
                           json_string(list[i].type), json_values(list[i].value),
                           json_rows(list[i].value, list[i].type));
    return out + "]";
}

std::string json_step(const TraceStep& s, const InvocationTrace& t, const SourceLines& lines) {
    static constexpr const char* kKinds[] = {"statement", "assign", "branch", "loop", "jump", "call"};
    std::string out = fmt::format("{{\"kind\":\"{}\",\"depth\":{}", kKinds[size_t(s.kind)], s.depth);
    if (!s.where.empty())
        out += ",\"where\":" + json_string(s.where) + ",\"text\":" + json_string(std::string(line_text(lines, t, s)));
    if (!s.name.empty()) out += ",\"name\":" + json_string(s.name);
    if (s.kind == TraceStep::Kind::Assign)
        out += ",\"type\":" + json_string(s.type) + ",\"value\":" + json_values(s.value) + json_rows(s.value, s.type);
    if (s.kind == TraceStep::Kind::Branch) out += fmt::format(",\"taken\":{}", s.taken);
    if (s.kind == TraceStep::Kind::Loop) out += fmt::format(",\"iteration\":{}", s.iteration);
    return out + "}";
}

std::string json_invocation(const InvocationTrace& t, const SourceLines& lines) {
    std::string steps = "[";
    for (size_t i = 0; i < t.steps.size(); ++i) steps += (i ? ",\n" : "\n") + json_step(t.steps[i], t, lines);
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
    for (uint32_t d : t.scissored)
        out += fmt::format("draw {}: the pixel is outside its scissor box: the scissor test removes its fragments here\n",
                           d);
    if (t.fragments.empty() && t.vertices.empty()) return out + fmt::format("pixel {},{}: no fragment\n", t.x, t.y);
    for (size_t i = 0; i < t.fragments.size(); ++i) {
        const FragmentTrace& f = t.fragments[i];
        out += fmt::format("fragment {} at pixel {},{}: draw {}{}, primitive {} (vertices {}, {}, {}), {}, depth {}: {}\n",
                           i, t.x, t.y, f.draw, pass_text(f.pass, f.program), f.primitive, f.vertices[0],
                           f.vertices[1], f.vertices[2], f.front ? "front" : "back", f.depth,
                           outcome_text(f.outcome));
        out += tests_text(f.tests);
        text_invocation(out, f.trace, t.source_lines);
        if (!f.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    for (const VertexTrace& v : t.vertices) {
        out += fmt::format("vertex {} of draw {}{}:\n", v.vertex, v.draw, pass_text(v.pass, v.program));
        text_invocation(out, v.trace, t.source_lines);
        if (!v.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    return out;
}

std::string format_json(const PixelTrace& t) {
    std::string fragments = "[";
    for (size_t i = 0; i < t.fragments.size(); ++i) {
        const FragmentTrace& f = t.fragments[i];
        fragments += fmt::format(
            "{}{{\"draw\":{},\"pass\":{},\"program\":{},\"primitive\":{},\"vertices\":[{},{},{}],\"front\":{},\"depth\":{},"
            "\"outcome\":\"{}\",\"tests\":{},\"matches_render\":{},\"rendered\":{},\"trace\":{}}}",
            i ? ",\n" : "\n", f.draw, f.pass.empty() ? "null" : json_string(f.pass), json_string(f.program),
            f.primitive, f.vertices[0], f.vertices[1], f.vertices[2], f.front, f.depth,
            outcome_key(f.outcome), tests_json(f.tests), f.matches_render, json_named(f.rendered),
            json_invocation(f.trace, t.source_lines));
    }
    std::string vertices = "[";
    for (size_t i = 0; i < t.vertices.size(); ++i)
        vertices += fmt::format("{}{{\"draw\":{},\"pass\":{},\"program\":{},\"vertex\":{},\"matches_render\":{},\"trace\":{}}}",
                                i ? ",\n" : "\n", t.vertices[i].draw,
                                t.vertices[i].pass.empty() ? "null" : json_string(t.vertices[i].pass),
                                json_string(t.vertices[i].program), t.vertices[i].vertex, t.vertices[i].matches_render,
                                json_invocation(t.vertices[i].trace, t.source_lines));
    return fmt::format("{{\"pixel\":[{},{}],\"scissored\":[{}],\"fragments\":{}],\"vertices\":{}]}}\n", t.x, t.y,
                       fmt::join(t.scissored, ","), fragments, vertices);
}

std::string format_text(const NanReport& r) {
    auto finding = [](const char* what, const NanFinding& f) {
        std::string pass = f.pass.empty() ? "" : fmt::format(", pass '{}'", f.pass);
        std::string who = f.vertex ? fmt::format("vertex {} of draw {}{}", f.vertex_index, f.draw, pass)
                                   : fmt::format("{}pixel {},{} (draw {}{}, primitive {})",
                                                 f.in_target ? "render target " : "", f.x, f.y, f.draw, pass,
                                                 f.primitive);
        std::string operands;
        for (size_t i = 0; i < f.event.operands.size(); ++i)
            operands += (i ? ", " : "") + format_value(f.event.operands[i], "");
        std::string into = f.event.variable.empty() ? "" : fmt::format(" (into {})", f.event.variable);
        if (f.event.where.empty())
            return fmt::format("{}: {}: {} = {}\n", what, who, f.event.op, format_value(f.event.result, ""));
        return fmt::format("{}: {}: {}: {}({}) = {}{}\n", what, who, f.event.where, f.event.op, operands,
                           format_value(f.event.result, ""), into);
    };
    std::string out = r.nan ? finding("first NaN/Inf", *r.nan) : "no NaN or infinity in any invocation (operations that GLSL leaves undefined, such as pow(x, y) "
                                  "with x < 0, can still return garbage on a GPU: try --check-undefined)\n";
    if (r.out_of_range) out += finding("first colour outside [0,1]", *r.out_of_range);
    return out;
}

}  // namespace glslrun::debug
