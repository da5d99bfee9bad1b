// The trace and the NaN report as text (glslrun trace); format_json.cpp writes the JSON.
#include <array>
#include <cmath>
#include <map>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "debug/format_common.h"

namespace glslrun::debug::detail {

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

const char* factor_name(BlendFactor f) {
    static constexpr const char* kNames[] = {
        "zero", "one", "src_color", "one_minus_src_color", "dst_color", "one_minus_dst_color", "src_alpha",
        "one_minus_src_alpha", "dst_alpha", "one_minus_dst_alpha", "constant_color", "one_minus_constant_color",
        "constant_alpha", "one_minus_constant_alpha", "src_alpha_saturate"};
    return kNames[size_t(f)];
}

const char* equation_name(BlendEquation e) {
    static constexpr const char* kNames[] = {"func_add", "func_subtract", "func_reverse_subtract", "min", "max"};
    return kNames[size_t(e)];
}

const char* logic_name(LogicOp op) {
    static constexpr const char* kNames[] = {"clear", "and", "and_reverse", "copy", "and_inverted", "noop",
                                             "xor", "or", "nor", "equiv", "invert", "or_reverse",
                                             "copy_inverted", "or_inverted", "nand", "set"};
    return kNames[size_t(op)];
}

// The trimmed text of a step's line; empty when its source is unknown.
std::string_view line_text(const SourceLines& lines, const InvocationTrace& t, const TraceStep& s) {
    if (s.source >= t.files.size() || s.line == 0) return {};
    auto file = lines.find(t.files[s.source]);
    if (file == lines.end() || s.line > file->second.size()) return {};
    return file->second[s.line - 1];
}

}  // namespace glslrun::debug::detail

namespace glslrun::debug {
namespace {

using namespace detail;

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



// "rgba", with a masked channel as '-'.
std::string mask_text(const std::array<bool, 4>& mask) {
    std::string out = "rgba";
    for (size_t k = 0; k < 4; ++k)
        if (!mask[k]) out[k] = '-';
    return out;
}

// A colour as stored: "rgba8(204, 51, 0, 255)" (the bytes n of n/255) or "vec4(...)".
std::string stored_color(const std::array<float, 4>& c, bool bytes) {
    if (bytes) return fmt::format("rgba8({}, {}, {}, {})", c[0], c[1], c[2], c[3]);
    return fmt::format("vec4({}, {}, {}, {})", c[0], c[1], c[2], c[3]);
}

// "colour 0 rgba8(...), depth 1, stencil 0".
std::string pixel_text(const PixelValues& p) {
    std::string out;
    for (size_t b = 0; b < p.color.size(); ++b) out += fmt::format("colour {} {}, ", b, stored_color(p.color[b], p.bytes));
    return out + fmt::format("depth {}, stencil {}", p.depth, p.stencil);
}

// "buffers 0; blend (src_alpha, one_minus_src_alpha) func_add; logic op off; mask rgba".
std::string writes_text(const ColorWrites& w, bool bytes) {
    std::string blend = "off";
    if (w.blend) {
        const BlendState& b = w.blend_state;
        blend = fmt::format("(src {}, dst {}) {}", factor_name(b.src_rgb), factor_name(b.dst_rgb),
                            equation_name(b.equation_rgb));
        if (b.src_alpha != b.src_rgb || b.dst_alpha != b.dst_rgb || b.equation_alpha != b.equation_rgb)
            blend += fmt::format(", alpha (src {}, dst {}) {}", factor_name(b.src_alpha), factor_name(b.dst_alpha),
                                 equation_name(b.equation_alpha));
        auto constant = [](BlendFactor f) { return f >= BlendFactor::ConstantColor && f <= BlendFactor::OneMinusConstantAlpha; };
        if (constant(b.src_rgb) || constant(b.dst_rgb) || constant(b.src_alpha) || constant(b.dst_alpha))
            blend += fmt::format(", constant vec4({}, {}, {}, {})", b.color[0], b.color[1], b.color[2], b.color[3]);
    }
    std::string logic = !w.logic_op ? "off" : bytes ? logic_name(w.logic) : "ignored (float buffers)";
    return fmt::format("buffers {}; blend {}; logic op {}; mask {}",
                       w.buffers.empty() ? std::string("none") : fmt::format("{}", fmt::join(w.buffers, ", ")), blend,
                       logic, mask_text(w.mask));
}

// The framebuffer at the pixel before and after a fragment, and what its draw does with colour.
std::string framebuffer_text(const FragmentTrace& f) {
    return fmt::format("  before: {}\n  writes: {}\n  after:  {}\n", pixel_text(f.before),
                       writes_text(f.writes, f.before.bytes), pixel_text(f.after));
}


// " (pass 'light', program a.vert + a.frag)"; nothing in a scene without passes.
// Without passes the program is the command line's, unless a stage of it is generated.
std::string pass_text(const std::string& pass, const std::string& program) {
    if (pass.empty())
        return program.find("(generated)") == std::string::npos ? "" : fmt::format(" (program {})", program);
    return fmt::format(" (pass '{}', program {})", pass, program);
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


// "file:line  text": the line's text after its place.
std::string where_text(const SourceLines& lines, const InvocationTrace& t, const TraceStep& s) {
    std::string_view text = line_text(lines, t, s);
    return text.empty() ? s.where : fmt::format("{}  {}", s.where, text);
}

// By ir::TexTarget: a target added there without a name here does not compile.
const char* target_name(ir::TexTarget t) {
    static constexpr std::array<const char*, size_t(ir::TexTarget::A2D) + 1> kNames = {
        "1D", "2D", "3D", "cube", "rectangle", "1D array", "2D array"};
    return kNames[size_t(t)];
}

std::string vec_text(const glm::vec4& v) { return fmt::format("vec4({}, {}, {}, {})", v[0], v[1], v[2], v[3]); }

// "level 1 (64x64, linear): texel (15, 47) = vec4(...), ..." per level sampled.
void text_levels(std::string& out, const std::string& pad, const rt::LookupDetails& d) {
    for (const rt::LookupLevel& l : d.levels) {
        std::string size = l.depth > 1 ? fmt::format("{}x{}x{}", l.width, l.height, l.depth)
                                       : fmt::format("{}x{}", l.width, l.height);
        out += fmt::format("{}level {} ({}, {}):", pad, l.level, size, l.linear ? "linear" : "nearest");
        const char* sep = " ";
        for (const rt::LookupTexel& x : d.texels) {
            if (x.level != l.level) continue;
            std::string at = x.i < 0 || x.j < 0 || x.k < 0 ? std::string("border")
                             : l.depth > 1                   ? fmt::format("({}, {}, {})", x.i, x.j, x.k)
                             : l.height > 1                  ? fmt::format("({}, {})", x.i, x.j)
                                                             : fmt::format("({})", x.i);
            out += fmt::format("{}texel {} = {}", sep, at, vec_text(x.value));
            sep = ", ";
        }
        out += "\n";
    }
}

// A texture lookup's operands, level of detail, levels and texels, and result.
void text_lookup(std::string& out, const std::string& pad, const TextureLookup& t) {
    const rt::LookupDetails& d = t.details;
    std::string samplers = t.samplers.empty() ? "" : fmt::format(" ({})", fmt::join(t.samplers, ", "));
    out += fmt::format("{}texture lookup: unit {}{}, {}{}, coord ({})", pad, t.unit, samplers,
                       target_name(t.info.target), t.info.shadow ? " shadow" : "", fmt::join(t.coord, ", "));
    if (t.info.shadow) out += fmt::format(", ref {}", t.ref);
    if (!d.complete) {
        out += ": no complete texture bound, (0, 0, 0, 1)\n";
        return;
    }
    if (d.face >= 0) {
        static constexpr const char* kFaces[] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
        out += fmt::format(", face {} at ({}, {})", kFaces[d.face], d.face_coord.x, d.face_coord.y);
    }
    if (t.info.lod == ir::TexLod::Explicit) out += fmt::format("; lod {} (explicit)", t.lod);
    else {
        out += fmt::format("; lod {} (from the derivatives{})", d.lod_implicit,
                           d.lod_used ? "" : ", not needed: no mipmaps, one filter");
        if (t.info.lod == ir::TexLod::ImplicitBias) out += fmt::format(", bias {}", t.lod);
    }
    out += fmt::format(", lambda {}: {}\n", d.lambda, d.magnified ? "magnified" : "minified");
    text_levels(out, pad + "  ", d);
    out += fmt::format("{}  => {}\n", pad, vec_text({t.result[0], t.result[1], t.result[2], t.result[3]}));
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
            case TraceStep::Kind::Lookup:
                if (s.lookup < t.lookups.size()) text_lookup(out, pad + "    ", t.lookups[s.lookup]);
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


}  // namespace

std::string format_text(const PixelTrace& t) {
    std::string out;
    for (uint32_t d : t.scissored)
        out += fmt::format("draw {}: the pixel is outside its scissor box: the scissor test removes its fragments here\n",
                           d);
    // "pixel 12,34", or "render target 'image' pixel 12,34".
    const std::string pixel = t.target.empty() ? fmt::format("pixel {},{}", t.x, t.y)
                                               : fmt::format("render target '{}' pixel {},{}", t.target, t.x, t.y);
    if (t.fragments.empty() && t.vertices.empty()) return out + pixel + ": no fragment\n";
    for (size_t i = 0; i < t.fragments.size(); ++i) {
        const FragmentTrace& f = t.fragments[i];
        out += fmt::format("fragment {} at {}: draw {}{}, primitive {} (vertices {}, {}, {}), {}, depth {}: {}\n",
                           i, pixel, f.draw, pass_text(f.pass, f.program), f.primitive, f.vertices[0],
                           f.vertices[1], f.vertices[2], f.front ? "front" : "back", f.depth,
                           outcome_text(f.outcome));
        out += tests_text(f.tests);
        out += framebuffer_text(f);
        text_invocation(out, f.trace, t.source_lines);
        if (!f.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    for (const VertexTrace& v : t.vertices) {
        out += fmt::format("vertex {} of draw {}{}:\n", v.vertex, v.draw, pass_text(v.pass, v.program));
        text_invocation(out, v.trace, t.source_lines);
        if (!v.matches_render) out += "  WARNING: the replay's outputs differ from the render's\n";
    }
    if (!t.generated.empty()) out += "\n" + describe_generated(t.generated);
    return out;
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
    if (!r.generated.empty()) out += "\n" + describe_generated(r.generated);
    return out;
}

}  // namespace glslrun::debug
