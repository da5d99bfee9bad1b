// `glslrun serve`'s renders, traces and findings over the edited texts
// (serve_session.h). Each answer is computed afresh from the texts: a
// render is milliseconds for the lecture's scenes, and a cache would be one
// more way to show an image that does not match the sources on the page.
#include "serve_session.h"

#include <chrono>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "debug/debugger.h"
#include "glslrun/scene/error_report.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/undefined.h"
#include "scene/text_file.h"
#include "watchdog.h"

namespace glslrun::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Invalid UTF-8 (a Latin-1 comment) becomes U+FFFD rather than an exception.
std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

std::string error_json(const Error& e) { return dump(json{{"error", e.str()}}); }

const char* stage_kind(bool vertex) { return vertex ? "vert" : "frag"; }

}  // namespace

struct ServeSession::Parsed {
    scene::Scene scene;
    Program program, debug;  // debug: compile_for_debugging's twin, for the replays
};

ServeSession::ServeSession(const Inputs& in, std::string scene_text, const ServeOptions& options,
                           std::string scratch)
    : options_(options), scratch_(std::move(scratch)) {
    for (bool vertex : {true, false})
        for (const ShaderSource& s : vertex ? in.vertex : in.fragment)
            files_.push_back({s.name, stage_kind(vertex), s.text});
    files_.push_back({in.scene, "scene", std::move(scene_text)});
}

std::string ServeSession::files_json() const {
    json files = json::array();
    for (size_t i = 0; i < files_.size(); ++i)
        files.push_back({{"index", i}, {"name", files_[i].name}, {"kind", files_[i].kind}, {"text", files_[i].text}});
    return dump(json{{"files", files}, {"precision", precision_name(options_.precision)},
                     {"time_limit", options_.time_limit}});
}

bool ServeSession::set_text(size_t index, std::string text) {
    if (index >= files_.size()) return false;
    files_[index].text = std::move(text);
    return true;
}

// The scene's relative paths (meshes, textures, passes' shaders) stay
// relative to the scene file's directory: the text is parsed under its path.
Result<scene::Scene> ServeSession::parse_scene_text() const {
    const File& f = files_.back();
    if (f.text.size() > size_t(scene::kMaxSceneFileBytes))
        return Error(fmt::format("the scene is larger than {} bytes (docs/limits.md)", scene::kMaxSceneFileBytes),
                     f.name);
    return scene::parse_scene(f.text, f.name);
}

std::vector<ShaderSource> ServeSession::sources(const char* kind) const {
    std::vector<ShaderSource> out;
    for (const File& f : files_)
        if (f.kind == kind) out.push_back({f.name, f.text});
    return out;
}

bool ServeSession::fixed_function() const { return sources("vert").empty() && sources("frag").empty(); }

// The scene of the current text; with no shader, every draw in GL's fixed function (as `glslrun scene.toml`).
Result<scene::Scene> ServeSession::scene_to_draw() const {
    auto scene = parse_scene_text();
    if (scene && fixed_function()) scene::use_fixed_function(*scene);
    return scene;
}

std::string ServeSession::scratch_path(const std::string& stem) {
    return (fs::path(scratch_) / fmt::format("{}-{}.png", stem, ++generation_)).string();
}

namespace {

// A diagnostic with the index of the file it is in (-1: none of the page's).
json diagnostics_json(const std::vector<Diagnostic>& diagnostics, const auto& files) {
    json out = json::array();
    for (const Diagnostic& d : diagnostics) {
        int index = -1;
        for (size_t i = 0; i < files.size(); ++i)
            if (!d.file.empty() && files[i].name == d.file) index = int(i);
        out.push_back({{"file", d.file}, {"index", index}, {"line", d.line}, {"message", d.message},
                       {"warning", d.warning}, {"text", d.str()}});
    }
    return out;
}

}  // namespace

std::string ServeSession::render_json() {
    auto failed = [&](const Error& e) {
        return dump(json{{"ok", false}, {"diagnostics", diagnostics_json(e.diagnostics, files_)}});
    };
    auto scene = parse_scene_text();
    if (!scene) return failed(scene.error());
    std::vector<Diagnostic> warnings = scene->warnings;
    if (fixed_function()) {
        // The command line's text is "warning: PATH: message"; the page shows the file and kind itself.
        const std::string prefix = fmt::format("warning: {}: ", scene->path);
        if (std::string w = scene::fixed_function_warning(*scene); !w.empty())
            warnings.push_back(Diagnostic{scene->path, 0, w.starts_with(prefix) ? w.substr(prefix.size()) : w, true});
        scene::use_fixed_function(*scene);
    }
    auto start = Clock::now();
    Inputs in;
    in.vertex = sources("vert");
    in.fragment = sources("frag");
    // As `glslrun` compiles: its notes too.
    auto prog = fixed_function() ? scene::unused_main_program() : compile_program(in, RenderOptions{});
    if (!prog) return failed(prog.error());
    prog->exec.threads = options_.threads;
    prog->exec.precision = options_.precision;
    // A shader edited into an endless loop stops here, not the server.
    prog->exec.set_time_limit(options_.time_limit);
    auto programs = scene::ScenePrograms::compile(*prog, *scene);
    if (!programs) return failed(programs.error());
    warnings.insert(warnings.end(), programs->warnings().begin(), programs->warnings().end());
    const double compile_ms = ms_since(start);
    auto fb = Framebuffer::create(scene->width, scene->height, false, scene::color_buffers(*scene));
    if (!fb) return failed(fb.error());
    auto stats = scene::render_scene(*programs, *scene, *fb);
    if (!stats) return failed(stats.error());
    start = Clock::now();
    std::string path = scratch_path("image");
    if (Status st = scene::write_png(scene::read_framebuffer(*fb), path); !st) return failed(st.error());
    std::error_code ec;  // an old image that cannot be removed goes with the scratch directory
    if (!image_png_.empty()) fs::remove(image_png_, ec);
    image_png_ = path;
    return dump(json{{"ok", true},
                     {"generation", generation_},
                     {"width", scene->width},
                     {"height", scene->height},
                     {"stats", format_stats(*prog, *scene, *stats, compile_ms, ms_since(start))},
                     {"diagnostics", diagnostics_json(warnings, files_)}});
}

// The scene and the program with its debugging twin, under the time limit
// (`cancel`: the replays poll it, not the deadline).
Result<ServeSession::Parsed> ServeSession::parse_for_debugging(const std::atomic<bool>* cancel) const {
    auto scene = scene_to_draw();
    if (!scene) return scene.error();
    const auto vertex = sources("vert"), fragment = sources("frag");
    auto program = fixed_function() ? scene::unused_main_program() : Program::compile(vertex, fragment);
    if (!program) return program.error();
    program->exec.precision = options_.precision;
    program->exec.set_time_limit(options_.time_limit);
    auto debug = fixed_function() ? scene::unused_main_program()
                                  : debug::compile_for_debugging(vertex, fragment, options_.precision);
    if (!debug) return debug.error();
    debug->exec.cancel = cancel;
    return Parsed{std::move(*scene), std::move(*program), std::move(*debug)};
}

std::string ServeSession::trace_json(int x, int y) {
    Watchdog watchdog(options_.time_limit);
    auto p = parse_for_debugging(watchdog.flag());
    if (!p) return error_json(p.error());
    if (x < 0 || y < 0 || x >= p->scene.width || y >= p->scene.height)
        return error_json(Error(fmt::format("pixel {},{} is outside the {}x{} image", x, y, p->scene.width,
                                            p->scene.height)));
    Framebuffer fb(p->scene.width, p->scene.height, false, scene::color_buffers(p->scene));
    debug::TraceRequest request;
    request.pixel = std::pair{x, y};
    request.sources = sources("vert");
    for (ShaderSource& s : sources("frag")) request.sources.push_back(std::move(s));
    auto trace = debug::trace(p->program, p->debug, p->scene, fb, request);
    if (!trace) return error_json(trace.error());
    return debug::format_json(*trace);
}

namespace {

json finding_json(const char* kind, const debug::NanFinding& f) {
    return {{"kind", kind},       {"x", f.x},           {"y", f.y},
            {"vertex", f.vertex}, {"in_target", f.in_target},
            {"where", f.event.where}, {"op", f.event.op}, {"pass", f.pass}};
}

json undefined_json(const scene::UndefinedFinding& f) {
    return {{"kind", "undefined"},
            {"x", f.first.x},
            {"y", f.first.y},
            {"vertex", f.first.vertex},
            {"in_target", f.first.in_target},
            {"where", fmt::format("{}:{}", f.file, f.line)},
            {"op", fmt::format("{} ({}, {} invocations)", f.op, f.condition, f.count)},
            {"pass", f.first.pass}};
}

}  // namespace

std::string ServeSession::findings_json() {
    Watchdog watchdog(options_.time_limit);
    auto p = parse_for_debugging(watchdog.flag());
    if (!p) return error_json(p.error());
    Framebuffer fb(p->scene.width, p->scene.height, false, scene::color_buffers(p->scene));
    auto report = debug::find_nan(p->program, p->debug, p->scene, fb, true);
    if (!report) return error_json(report.error());
    json findings = json::array();
    if (report->nan) findings.push_back(finding_json("nan", *report->nan));
    if (report->out_of_range) findings.push_back(finding_json("colour_range", *report->out_of_range));
    std::string summary = debug::format_text(*report);
    if (fixed_function()) return dump(json{{"findings", findings}, {"summary", summary}});  // no shader to check
    // GLSL's undefined operations (glslrun --check-undefined), each at its first invocation's pixel.
    ExecOptions exec;
    exec.precision = options_.precision;
    exec.set_time_limit(options_.time_limit);
    auto undefined = scene::check_undefined(sources("vert"), sources("frag"), p->scene, exec);
    if (!undefined) return error_json(undefined.error());
    for (const scene::UndefinedFinding& f : undefined->findings) findings.push_back(undefined_json(f));
    summary += scene::format_undefined(*undefined);
    return dump(json{{"findings", findings}, {"summary", summary}});
}

std::string ServeSession::heat_json() {
    if (fixed_function())
        return error_json(Error("the error heat map measures the precision of your shaders: without a shader every "
                                "draw is GL's fixed function"));
    auto scene = parse_scene_text();
    if (!scene) return error_json(scene.error());
    scene::ErrorReportOptions options;
    options.mode = options_.precision;
    options.threads = options_.threads;
    options.time_limit = options_.time_limit;
    auto report = scene::measure_error(sources("vert"), sources("frag"), *scene, options);
    if (!report) return error_json(report.error());
    if (report->outputs.empty()) return error_json(Error("the program writes no colour to measure"));
    std::string path = scratch_path("heat");
    if (Status st = scene::write_png(scene::heat_map(report->outputs[0]), path); !st) return error_json(st.error());
    std::error_code ec;
    if (!heat_png_.empty()) fs::remove(heat_png_, ec);
    heat_png_ = path;
    return dump(json{{"ok", true},
                     {"output", report->outputs[0].name},
                     {"table", scene::format_error_table(*report, {})},
                     {"legend", scene::heat_map_legend()}});
}

std::string serve_page_dir() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path installed = (exe.parent_path() / GLSLRUN_SERVE_FROM_BIN).lexically_normal();
        if (fs::exists(installed / "index.html", ec)) return installed.string();
    }
    if (fs::exists(fs::path(GLSLRUN_SOURCE_SERVE) / "index.html", ec)) return GLSLRUN_SOURCE_SERVE;
    return {};
}

}  // namespace glslrun::cli
