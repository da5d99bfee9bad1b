// The measuring half of the error report: two renders of one scene into float
// framebuffers, the vertex outputs of both modes, and their comparison.
// Formatting and files: error_report_format.cpp.
#include "glslrun/scene/error_report.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "ir/ir.h"
#include "raster/framebuffer.h"
#include "runtime/interpreter.h"
#include "runtime/program_state.h"
#include "glslrun/scene/render.h"

namespace glslrun::scene {

namespace {

using Clock = std::chrono::steady_clock;


struct Frame {
    FloatImage color, depth;
    double ms = 0;
};

Result<Program> compile_for(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                            Precision precision, const ErrorReportOptions& options) {
    auto prog = Program::compile(vertex, fragment, options.compile);
    if (!prog) return prog.error();
    prog->exec.precision = precision;
    prog->exec.threads = options.threads;
    prog->exec.set_time_limit(options.time_limit);
    return prog;
}

// The scene drawn into a float framebuffer cleared to `clear` (the scene's
// depth and stencil clears); its colour buffer 0.
Result<std::vector<float>> draw_cleared_to(Program& prog, const Scene& scene, glm::vec4 clear,
                                           std::vector<float>* depth) {
    auto created = Framebuffer::create(scene.width, scene.height, /*float_color=*/true, color_buffers(scene));
    if (!created) return created.error();
    Framebuffer& fb = *created;
    if (auto stats = draw_scene_objects(prog, scene, fb, ClearValues{clear, scene.clear_depth, scene.clear_stencil});
        !stats)
        return stats.error();
    if (depth) *depth = std::move(fb.depth);
    std::span<const float> color = fb.color_data<float>(0);
    return std::vector<float>(color.begin(), color.end());
}

// A colour unlike `c` in every channel, within [0, 1] as blending expects.
glm::vec4 other_clear_color(glm::vec4 c) {
    for (int k = 0; k < 4; ++k) c[k] = c[k] >= 0.5f ? 0.0f : 1.0f;
    return c;
}

// Draws the scene into a float framebuffer and splits it into the colour and
// depth planes with their coverage. The framebuffer holds the scene's clear
// colour, as GL's does, so blending reads it; a second draw over another
// clear colour tells the written pixels: one that holds its clear colour
// both times was written by no fragment (or by blending that kept it).
// Unwritten pixels get the clear values an RGBA8 framebuffer would hold.
Result<Frame> render_frame(Program& prog, const Scene& scene) {
    auto start = Clock::now();
    std::vector<float> depth;
    auto color = draw_cleared_to(prog, scene, scene.clear_color, &depth);
    if (!color) return color.error();
    Frame f;
    f.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const glm::vec4 other = other_clear_color(scene.clear_color);
    auto probe = draw_cleared_to(prog, scene, other, nullptr);
    if (!probe) return probe.error();
    size_t pixels = size_t(scene.width) * size_t(scene.height);
    f.color = {scene.width, scene.height, 4, std::move(*color), std::vector<uint8_t>(pixels)};
    for (size_t p = 0; p < pixels; ++p) {
        bool changed = false;
        for (size_t k = 0; k < 4; ++k)
            changed = changed || f.color.values[p * 4 + k] != scene.clear_color[int(k)] ||
                      (*probe)[p * 4 + k] != other[int(k)];
        f.color.covered[p] = changed;
        if (changed) continue;
        // The clear as an RGBA8 buffer of the mode's rounding holds it (to_image gives the byte back).
        const ColorRounding rounding = color_rounding_for(prog.exec.precision);
        for (int k = 0; k < 4; ++k)
            f.color.values[p * 4 + size_t(k)] = float(raster::to_unorm8(scene.clear_color[k], rounding)) / 255.0f;
    }
    f.depth = {scene.width, scene.height, 1, std::move(depth), f.color.covered};
    return f;
}

// An Image (top row first, RGBA8) of a frame's colour plane, its floats
// stored by `rounding` (as the plain render in that mode stores them).
Image to_image(const FloatImage& color, ColorRounding rounding) {
    Image image{color.width, color.height, std::vector<uint8_t>(color.values.size())};
    for (int y = 0; y < color.height; ++y)
        for (size_t i = 0; i < size_t(color.width) * 4; ++i)
            image.rgba[size_t(y) * size_t(color.width) * 4 + i] = uint8_t(
                raster::to_unorm8(color.values[size_t(color.height - 1 - y) * size_t(color.width) * 4 + i], rounding));
    return image;
}

// Every vertex output of every object, objects one after the other.
// Scene entries the program does not declare are skipped, as the renders skip
// them (ErrorReport::warnings names them).
Result<std::vector<std::vector<ShaderOutput>>> shade_scene_vertices(Program& prog, const Scene& scene) {
    const bool skip_undeclared = true;
    if (Status st = apply_uniforms(prog, scene.uniforms, skip_undeclared); !st) return st.error();
    auto bound = bind_scene_textures(scene);
    if (!bound) return bound.error();
    std::vector<std::vector<ShaderOutput>> objects;
    for (const Object& object : scene.objects) {
        GLState gl = object_gl_state(scene, *bound, object);
        if (Status st = apply_uniforms(prog, object.uniforms, skip_undeclared); !st) return st.error();
        if (Status st = apply_builtin_uniforms(prog, gl); !st) return st.error();
        auto out = run_vertices(prog, object.mesh.attribs, object.mesh.vertex_count, &gl);
        if (!out) return out.error();
        objects.push_back(std::move(*out));
    }
    return objects;
}

void compare_varying(VaryingError& v, const ShaderOutput& ref, const ShaderOutput& act, int object) {
    uint32_t n = ref.components;
    for (size_t vertex = 0; vertex * n < ref.data.size(); ++vertex) {
        uint64_t worst = 0;
        for (uint32_t c = 0; c < n; ++c) worst = std::max(worst, v.error.add(ref.data[vertex * n + c], act.data[vertex * n + c]));
        if (v.worst.found && worst <= v.worst.ulp) continue;
        v.worst = {true, int(vertex), object, worst, 0,
                   {ref.data.begin() + std::ptrdiff_t(vertex * n), ref.data.begin() + std::ptrdiff_t(vertex * n + n)},
                   {act.data.begin() + std::ptrdiff_t(vertex * n), act.data.begin() + std::ptrdiff_t(vertex * n + n)}};
    }
}

Result<std::vector<VaryingError>> compare_vertices(Program& reference, Program& actual, const Scene& scene) {
    auto ref = shade_scene_vertices(reference, scene);
    if (!ref) return ref.error();
    auto act = shade_scene_vertices(actual, scene);
    if (!act) return act.error();
    std::vector<VaryingError> out;
    for (size_t object = 0; object < ref->size(); ++object) {
        const auto& r = (*ref)[object];
        const auto& a = (*act)[object];
        if (r.size() != a.size()) return Error("error report: the two programs have different vertex outputs");
        out.resize(r.size());
        for (size_t o = 0; o < r.size(); ++o) {
            if (r[o].data.size() != a[o].data.size() || r[o].components != a[o].components)
                return Error(fmt::format("error report: vertex output {} differs in size between the modes", r[o].name));
            out[o].name = r[o].name;
            out[o].components = r[o].components;
            compare_varying(out[o], r[o], a[o], int(object));
        }
    }
    return out;
}

bool is_color_output(const std::string& name) { return name == "gl_FragColor" || name == "gl_FragData[0]" || name == "gl_FragData"; }

// The colour output's name, and notes about fragment outputs that draw() does not store.
std::string fragment_outputs(const Program& prog, const Scene& scene, bool& writes_depth,
                             std::vector<std::string>& notes) {
    std::string color, unstored;
    writes_depth = false;
    for (const ir::Binding& b : state_of(prog).ir.fragment.outputs) {
        if (is_color_output(b.name) && color.empty()) color = b.name;
        else if (b.name == "gl_FragDepth") writes_depth = true;
        else unstored += (unstored.empty() ? "" : ", ") + b.name;
    }
    if (!unstored.empty())
        notes.push_back(fmt::format("not compared, as draw() stores one colour buffer: {}", unstored));
    if (color.empty()) notes.push_back("the fragment shader writes no colour: no pixel counts as covered");
    if (writes_depth && !scene.gl.depth_test)
        notes.push_back("gl_FragDepth: not compared (the scene's depth test is off, so no depth is stored)");
    return color.empty() ? "color" : color;
}

AblationRow ablation_row(std::string ops, const ImageError& e) {
    return {std::move(ops), e.total(), e.covered_one, e.differing_8bit, e.worst_8bit};
}

// Fast with one class of approximations at a time. `fast` is left as it was.
Result<std::vector<AblationRow>> ablate(Program& fast, const Scene& scene, const FloatImage& reference,
                                        const ImageError& all_fast) {
    static constexpr std::pair<const char*, uint32_t> kClasses[] = {
        // inversesqrt: frsqrt, and the square roots only divided by (normalize, x / sqrt(y); ir/sqrt_divisor.cpp).
        {"none", 0}, {"inversesqrt", rt::kFastRsqrt}, {"exp_log", rt::kFastExpLog}, {"pow", rt::kFastPow},
        {"sin_cos", rt::kFastSinCos}, {"fma", rt::kFastFma}};
    std::vector<AblationRow> rows;
    uint32_t saved = state_of(fast).fast_ops;
    for (const auto& [name, ops] : kClasses) {
        state_of(fast).fast_ops = ops;
        auto frame = render_frame(fast, scene);
        if (!frame) {
            state_of(fast).fast_ops = saved;
            return frame.error();
        }
        auto e = compare_float_images(all_fast.name, reference, frame->color, /*quantized=*/true);
        if (!e) return e.error();
        rows.push_back(ablation_row(name, *e));
    }
    state_of(fast).fast_ops = saved;
    rows.push_back(ablation_row("all", all_fast));
    return rows;
}

}  // namespace

Result<ErrorReport> measure_error(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                                  const Scene& scene, const ErrorReportOptions& options) {
    auto reference = compile_for(vertex, fragment, Precision::Reference, options);
    if (!reference) return reference.error();
    auto actual = compile_for(vertex, fragment, options.mode, options);
    if (!actual) return actual.error();
    ErrorReport report;
    // What a render of the scene warns of (an entry no program uses), and its errors first.
    auto programs = ScenePrograms::compile(*actual, scene, options.compile);
    if (!programs) return programs.error();
    report.warnings = programs->warnings();
    report.mode = options.mode;
    report.scene = scene.path;
    report.width = scene.width;
    report.height = scene.height;
    bool writes_depth = false;
    std::string color_name = fragment_outputs(*reference, scene, writes_depth, report.notes);
    auto ref_frame = render_frame(*reference, scene);
    if (!ref_frame) return ref_frame.error();
    auto act_frame = render_frame(*actual, scene);
    if (!act_frame) return act_frame.error();
    report.reference_ms = ref_frame->ms;
    report.mode_ms = act_frame->ms;
    auto color = compare_float_images(color_name, ref_frame->color, act_frame->color, /*quantized=*/true);
    if (!color) return color.error();
    report.outputs.push_back(std::move(*color));
    if (scene.gl.depth_test) {
        auto depth = compare_float_images(writes_depth ? "gl_FragDepth" : "depth", ref_frame->depth,
                                          act_frame->depth, /*quantized=*/false);
        if (!depth) return depth.error();
        report.outputs.push_back(std::move(*depth));
    }
    if (options.mode == Precision::Fast) {
        auto rows = ablate(*actual, scene, ref_frame->color, report.outputs[0]);
        if (!rows) return rows.error();
        report.ablation = std::move(*rows);
    }
    report.reference_image = to_image(ref_frame->color, color_rounding_for(Precision::Reference));
    report.mode_image = to_image(act_frame->color, color_rounding_for(options.mode));
    auto varyings = compare_vertices(*reference, *actual, scene);
    if (!varyings) return varyings.error();
    report.varyings = std::move(*varyings);
    return report;
}

}  // namespace glslrun::scene
