// `glslrun trace`: the shader debugger (debug/debugger.h, docs/debugging.md).
//   glslrun trace --pixel X,Y [--target NAME] a.vert a.frag scene.toml [--json]
//   glslrun trace --vertex N [--draw D] a.vert a.frag scene.toml
//   glslrun trace --find-nan [--colour-range] a.vert a.frag scene.toml
// Either shader, or both, may be left out: the draws then run GL's fixed
// function for the missing stages, generated as GLSL 1.10, and the trace
// follows the generated source (--dump-fixed-function DIR writes it).
#include "trace_command.h"

#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "command_line.h"
#include "debug/debugger.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/undefined.h"
#include "output_guard.h"
#include "render_command.h"

namespace glslrun::cli {
namespace {

int fail(const Error& e, int status = kResultError) {
    std::fputs(e.str().c_str(), stderr);
    return status;
}

Result<std::pair<int, int>> parse_pixel(const std::string& text) {
    if (auto pixel = parse_int_pair(text, ",")) return *pixel;
    return Error(fmt::format("--pixel '{}' must be X,Y (image coordinates, top-left origin), e.g. 256,200", text));
}

struct TraceOptions {
    std::vector<std::string> files, defines, include_dirs;
    std::string pixel, size, target, dump_fixed_function;
    std::optional<uint32_t> vertex;
    uint32_t draw = 0;
    bool json = false, find_nan = false, colour_range = false, check_undefined = false;
    Precision precision = Precision::Precise;
};

// --check-undefined: as `glslrun --check-undefined` (glslrun/scene/undefined.h).
int check_undefined(const Inputs& in, const scene::Scene& scene, Precision precision, const CompileOptions& compile) {
    ExecOptions exec;
    exec.precision = precision;
    auto report = scene::check_undefined(in.vertex, in.fragment, scene, exec, compile);
    if (!report) return fail(report.error());
    std::fputs(scene::format_undefined(*report).c_str(), stdout);
    return 0;
}

}  // namespace

int dump_fixed_function(const std::vector<debug::GeneratedStage>& stages, const std::string& dir, const Inputs& in,
                        const scene::Scene& scene) {
    if (stages.empty()) {
        std::fputs("--dump-fixed-function: no draw of the scene runs a generated fixed-function stage (every draw "
                   "has a vertex and a fragment shader)\n",
                   stdout);
        return 0;
    }
    InputFiles inputs;
    for (const auto* stage : {&in.vertex, &in.fragment})
        for (const ShaderSource& s : *stage) inputs.add(s.name);
    inputs.add_scene(scene);
    for (const debug::GeneratedStage& g : stages)
        if (Status st = inputs.check_output((std::filesystem::path(dir) / g.file).string(), "--dump-fixed-function");
            !st)
            return fail(st.error(), kToolError);
    auto written = debug::write_generated_stages(stages, dir);
    if (!written) return fail(written.error(), kToolError);
    for (size_t i = 0; i < stages.size(); ++i)
        fmt::print("wrote {}: GL's fixed-function {} stage generated for the scene's draws (in traces: {})\n",
                   (*written)[i], stages[i].vertex ? "vertex" : "fragment", stages[i].name);
    return 0;
}

namespace {

int run_trace(const TraceOptions& o) {
    auto in = classify(o.files);
    if (!in) return fail(in.error());
    if (in->scene.empty())
        return fail(Error("trace needs a scene file (.toml), and the shaders (.vert, .frag) to trace: a stage "
                          "left out is drawn with GL's fixed function, generated from the scene"),
                    kToolError);
    const bool fixed = in->vertex.empty() && in->fragment.empty();
    if (!o.target.empty() && o.pixel.empty())
        return fail(Error("--target NAME names the render target of --pixel X,Y, which is missing"), kToolError);
    if (o.pixel.empty() && !o.vertex && !o.find_nan && !o.check_undefined && o.dump_fixed_function.empty())
        return fail(Error("trace needs --pixel X,Y, --vertex N, --find-nan, --check-undefined or "
                          "--dump-fixed-function DIR"),
                    kToolError);
    if (fixed && o.check_undefined)
        return fail(Error("--check-undefined checks your shaders: give a .vert or .frag file (without shaders "
                          "every draw is GL's fixed function)"),
                    kToolError);
    std::optional<std::pair<int, int>> pixel;
    if (!o.pixel.empty()) {
        auto parsed = parse_pixel(o.pixel);
        if (!parsed) return fail(parsed.error(), kToolError);
        pixel = *parsed;
    }
    RenderOptions render;
    render.size = o.size;
    auto scene = load_sized_scene(*in, render);
    if (!scene) return fail(scene.error());
    CompileOptions compile;
    compile.defines = o.defines;
    compile.include_dirs = o.include_dirs;
    if (o.check_undefined) return check_undefined(*in, *scene, o.precision, compile);
    // No shaders: every draw in GL's fixed function, as `glslrun scene.toml` draws it.
    if (fixed) {
        if (std::string w = scene::fixed_function_warning(*scene); !w.empty()) fmt::print(stderr, "{}\n", w);
        scene::use_fixed_function(*scene);
    }
    auto program = fixed ? scene::unused_main_program() : Program::compile(in->vertex, in->fragment, compile);
    if (!program) return fail(program.error());
    program->exec.precision = o.precision;
    auto debug = fixed ? scene::unused_main_program()
                       : debug::compile_for_debugging(in->vertex, in->fragment, o.precision, compile);
    if (!debug) return fail(debug.error());
    // The [uniforms] entries that no program uses, as a render prints them (an error here the trace reports).
    if (auto programs = scene::ScenePrograms::compile(*program, *scene); programs)
        for (const Diagnostic& w : programs->warnings()) fmt::print(stderr, "{}\n", w.str());
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    if (!o.dump_fixed_function.empty()) {
        auto stages = debug::generated_stages(*program, *debug, *scene, fb);
        if (!stages) return fail(stages.error());
        if (int status = dump_fixed_function(*stages, o.dump_fixed_function, *in, *scene); status != 0)
            return status;
        if (o.pixel.empty() && !o.vertex && !o.find_nan) return 0;
    }
    if (o.find_nan) {
        auto report = debug::find_nan(*program, *debug, *scene, fb, o.colour_range);
        if (!report) return fail(report.error());
        std::fputs(debug::format_text(*report).c_str(), stdout);
        return 0;
    }
    debug::TraceRequest request;
    request.vertex = o.vertex;
    request.draw = o.draw;
    request.pixel = pixel;
    request.target = o.target;
    request.sources = in->vertex;
    request.sources.insert(request.sources.end(), in->fragment.begin(), in->fragment.end());
    auto trace = debug::trace(*program, *debug, *scene, fb, request);
    if (!trace) return fail(trace.error());
    std::string text = o.json ? debug::format_json(*trace) : debug::format_text(*trace);
    std::fputs(text.c_str(), stdout);
    return 0;
}

}  // namespace

int trace_main(int argc, char** argv) {
    CLI::App app{"Traces shader invocations of a scene at source level, or finds the first NaN", "glslrun trace"};
    TraceOptions o;
    app.add_option("files", o.files,
                   "[shader.vert] [shader.frag] scene.toml (a stage left out: GL's fixed function, generated from "
                   "the scene)")
        ->required();
    app.add_option("--pixel", o.pixel, "trace every fragment at X,Y (image coordinates, top-left origin)")
        ->type_name("X,Y");
    app.add_option("--target", o.target, "--pixel in this render target of the scene, not in the image")
        ->type_name("NAME");
    app.add_option("--vertex", o.vertex, "trace vertex N (of draw --draw)")->type_name("N");
    app.add_option("--draw", o.draw, "the draw (scene object, from 0) of --vertex");
    app.add_flag("--json", o.json, "print the trace as JSON");
    app.add_flag("--find-nan", o.find_nan,
                 "report the first invocation (draw and tile order) computing a NaN or infinity");
    app.add_flag("--check-undefined", o.check_undefined,
                 "report the operations GLSL leaves undefined (pow of x < 0, division by zero, ...) that the "
                 "render computes, per source line, with the first invocation");
    app.add_flag("--colour-range", o.colour_range, "--find-nan: also the first colour output outside [0,1]");
    app.add_option("--size", o.size, "image size WxH, instead of the scene's");
    app.add_option("--dump-fixed-function", o.dump_fixed_function,
                   "write the fixed-function stages generated for the scene's draws to DIR (fixed-function-1.vert, "
                   "...), as traces name them")
        ->type_name("DIR");
    add_define_option(app, o.defines);
    add_include_option(app, o.include_dirs);
    add_precision_option(app, o.precision);
    add_code_cache_options(app);
    if (int status = parse_command_line(app, argc, argv); status >= 0) return status;
    warn_about_code_cache(Backend::Auto);
    return run_trace(o);
}

}  // namespace glslrun::cli
