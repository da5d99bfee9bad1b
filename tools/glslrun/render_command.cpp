// `glslrun a.vert a.frag scene.toml`: renders a scene file to a PNG, with
// --stats, and `--compare REF.png` on the result or on a given PNG.
#include "render_command.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <thread>

#include <fmt/format.h>

#include "command_line.h"
#include "error_report_command.h"
#include "image_output.h"
#include "output_guard.h"
#include "progress.h"
#include "trace_command.h"
#include "debug/debugger.h"
#include "debug/recorder.h"
#include "ir/ir.h"
#include "raster/fused/pipeline.h"
#include "runtime/backend_cache.h"
#include "runtime/program_state.h"
#include "scene/bench_report.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/undefined.h"
#include "scene/text_file.h"

namespace glslrun::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

int fail(const Error& e, int status = kResultError) {
    std::string text = e.str();
    std::fputs(text.c_str(), stderr);
    return status;
}

}  // namespace

namespace {

std::string lower(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace

// What each file is, by its name; a file of no known kind is a usage error.
// Shaders get their stage ("vert", "frag"): --stage names it for every
// shader whose name does not.
Result<std::vector<std::pair<std::string, std::string>>> sort_files(const std::vector<std::string>& files,
                                                                      const std::string& stage) {
    std::vector<std::pair<std::string, std::string>> kinds;
    int scenes = 0, images = 0;
    for (const std::string& path : files) {
        if (Status st = scene::check_path(path, "input"); !st) return st.error();
        std::string ext = lower(fs::path(path).extension().string());
        std::string kind = scene::shader_stage_of(path);
        if (ext == ".toml") {
            if (scenes++) return Error("only one scene file may be given", path);
            kind = "scene";
        } else if (ext == ".png") {
            if (images++) return Error("only one image may be given", path);
            kind = "image";
        } else if (kind.empty() && !stage.empty()) {
            kind = stage;
        } else if (kind.empty() && ext == ".glsl") {
            return Error("cannot tell the shader's stage from its name: give --stage vert or --stage frag, "
                         "or name it a.vert.glsl / a.frag.glsl",
                         path);
        } else if (kind.empty()) {
            return Error("unknown kind of file: shaders end in .vert or .frag (or .glsl, with --stage), scenes "
                         "in .toml, images in .png",
                         path);
        }
        kinds.emplace_back(path, kind);
    }
    return kinds;
}

Result<Inputs> classify(const std::vector<std::string>& files, const std::string& stage) {
    auto kinds = sort_files(files, stage);
    if (!kinds) return kinds.error();
    Inputs in;
    for (const auto& [path, kind] : *kinds) {
        if (kind == "scene") {
            in.scene = path;
        } else if (kind == "image") {
            in.image = path;
        } else {
            auto text = scene::read_text_file(path, "shader");
            if (!text) return text.error();
            (kind == "vert" ? in.vertex : in.fragment).push_back({path, *text});
        }
    }
    return in;
}

Status check_image_name(const std::string& output) {
    if (!image_format_of(output))
        return Error(fmt::format("cannot write '{}': glslrun writes PNG (lossless), JPEG, BMP and TGA images, "
                                 "chosen by the name's ending (.png, .jpg/.jpeg, .bmp, .tga), or - for PNG on "
                                 "standard output", output));
    return Ok{};
}

namespace {

Result<std::pair<int, int>> parse_size(const std::string& text) {
    if (auto size = parse_int_pair(text, "xX")) return *size;
    return Error(fmt::format("--size '{}' must be WxH, e.g. 512x512", text));
}

std::string default_output(const Inputs& in) {
    if (in.vertex.empty() && in.fragment.empty()) return fs::path(in.scene).stem().string() + ".png";
    std::string program = in.fragment.empty() ? fs::path(in.vertex[0].name).stem().string()
                                              : fs::path(in.fragment[0].name).stem().string();
    return fmt::format("{}-{}.png", program, fs::path(in.scene).stem().string());
}

// -o takes PNG names and "-" (standard output); any other extension is an error
// rather than PNG data under a misleading name.
Status check_output(const std::string& output, const RenderOptions& o, int buffers) {
    if (output == "-") {
        if (buffers > 1)
            return Error(fmt::format("-o - writes one image, and the scene draws {} colour buffers (draw_buffers); "
                                     "give a file name", buffers));
        if (o.frames > 1) return Error("-o - writes one image; --frames writes one per frame: give a file name");
        if (o.stats || o.bench_frames > 0 || o.dump_ir || !o.compare.empty() || !o.dump_fixed_function.empty())
            return Error("-o - writes the PNG to standard output: it does not combine with --stats, --bench, "
                         "--dump-ir, --dump-fixed-function or --compare, which print there too");
        return Ok{};
    }
    return check_image_name(output);
}

// Frame i's image name: out.png -> out.0000.png, out.0001.png, ...
std::string frame_path(const std::string& output, int frame) {
    fs::path p(output);
    return (p.parent_path() / fmt::format("{}.{:04}{}", p.stem().string(), frame, p.extension().string())).string();
}

Status write_buffers(const Framebuffer& fb, const std::string& output) {
    for (int i = 0; i < fb.color_buffers(); ++i)
        if (Status st = write_image(fb, i, scene::color_buffer_path(output, i)); !st) return st;
    return Ok{};
}

// Every file the command reads, so that no output is opened over one.
InputFiles input_files(const Inputs& in, const scene::Scene* scene, const RenderOptions& o) {
    InputFiles files;
    for (const auto* stage : {&in.vertex, &in.fragment})
        for (const ShaderSource& s : *stage) files.add(s.name);
    if (!in.image.empty()) files.add(in.image);
    if (!o.compare.empty()) files.add(o.compare);
    if (scene) files.add_scene(*scene);
    return files;
}

// The images -o names (per frame and colour buffer) and --diff: none may be an input.
Status check_outputs(const InputFiles& inputs, const std::string& output, int buffers, const RenderOptions& o) {
    if (!o.diff.empty())
        if (Status st = inputs.check_output(o.diff, "--diff"); !st) return st;
    if (output.empty() || output == "-") return Ok{};
    const int frames = std::max(o.frames, 1);
    for (int frame = 0; frame < frames; ++frame)
        for (int i = 0; i < buffers; ++i) {
            std::string name = scene::color_buffer_path(o.frames > 0 ? frame_path(output, frame) : output, i);
            if (Status st = inputs.check_output(name, "-o"); !st) return st;
        }
    return Ok{};
}

}  // namespace

// Without a vertex shader the draws run GL's fixed-function vertex stage,
// generated per draw (the compile here links a stand-in, for the checks);
// an error about the vertex stage or a varying says so.
Result<Program> compile_program(const Inputs& in, const RenderOptions& o) {
    CompileOptions options;
    options.defines = o.defines;
    options.include_dirs = o.include_dirs;
    auto prog = Program::compile(in.vertex, in.fragment, options);
    if (prog || !in.vertex.empty()) return prog;
    Error e = prog.error();
    for (Diagnostic& d : e.diagnostics)
        if (d.message.find("vertex") != std::string::npos || d.message.find("varying") != std::string::npos) {
            d.message += "\n  note: no vertex shader was given, so the vertex stage is GL's fixed function, "
                         "generated from the scene's state for each draw: it writes gl_Position, gl_FrontColor and "
                         "gl_BackColor, the secondary colours, gl_TexCoord[] and gl_FogFragCoord; a varying of your "
                         "own needs a .vert file that writes it";
            break;
        }
    return e;
}

namespace {

// The built-in uniforms read with their values, one per line (matrices one
// row per line), wrapped to `width` columns.
std::string builtin_values(const Program& prog, size_t width) {
    std::string out;
    const std::string indent(25, ' ');
    for (const ir::Uniform& u : state_of(prog).ir.uniforms) {
        if (!u.builtin || !u.read) continue;
        debug::NamedValue v = debug::uniform_value(u, state_of(prog).uniforms.data());
        std::vector<std::string> lines = debug::format_matrix_rows(v.value, v.type);
        std::string head = (out.empty() ? "" : indent) + u.name + " =";
        if (lines.size() > 1) out += head + "\n";  // a matrix: its rows below the name
        for (size_t i = 0; i < lines.size(); ++i) {
            std::string line = lines.size() > 1 ? indent + "  " + lines[i] : head + " " + lines[i];
            while (line.size() > width && width > indent.size() + 8) {  // wrap at a space where possible
                size_t cut = line.rfind(' ', width);
                if (cut == std::string::npos || cut <= indent.size()) cut = width;
                out += line.substr(0, cut) + "\n";
                line = indent + "  " + line.substr(cut + (line[cut] == ' ' ? 1 : 0));
            }
            out += line + "\n";
        }
    }
    return out.empty() ? "none\n" : out;
}

// $COLUMNS, else 100.
size_t terminal_width() {
    const char* columns = std::getenv("COLUMNS");
    int n = columns ? std::atoi(columns) : 0;
    return n >= 40 ? size_t(n) : 100;
}

std::string join_builtin_attributes(const Program& prog) {
    std::string list;
    for (const ir::Binding& b : state_of(prog).ir.vertex.inputs)
        if (b.name.starts_with("gl_")) list += (list.empty() ? "" : ", ") + b.name;
    return list.empty() ? "none" : list;
}

// "unit 0: 2D 256x256 RGBA8, 9 levels" per bound texture; an incomplete one
// samples as (0, 0, 0, 1), which is worth seeing next to a black image.
std::string describe_textures(const scene::Scene& scene) {
    // By TextureTarget: a target added there without a name here does not compile.
    static constexpr std::array<const char*, size_t(TextureTarget::Tex2DArray) + 1> kTargets = {
        "1D", "2D", "3D", "cube", "rectangle", "1D array", "2D array"};
    static_assert(kTargets.back() != nullptr);
    static constexpr std::array<const char*, size_t(TextureFormat::RGBA16F) + 1> kFormats = {"RGBA8", "RGBA32F", "depth",
                                                                                             "RGBA16F"};
    std::string out;
    for (const scene::TextureSetting& t : scene.textures) {
        const TextureImage& base = t.texture->levels(0).front();
        size_t levels = t.texture->levels(0).size();
        out += fmt::format("{}unit {}: {} {}x{}{} {}, {} level{}{}", out.empty() ? "" : "; ", t.unit,
                           kTargets[size_t(t.texture->target())], base.width, base.height,
                           base.depth > 1 ? fmt::format("x{}", base.depth) : "",
                           kFormats[size_t(t.texture->format())], levels, levels == 1 ? "" : "s",
                           t.texture->complete() ? "" : ", incomplete");
    }
    return out.empty() ? "none" : out;
}

}  // namespace

std::string format_stats(const Program& prog, const scene::Scene& scene, const DrawStats& s, double compile_ms,
                         double output_ms) {
    std::string text;
    auto out = std::back_inserter(text);
    fmt::format_to(out, "scene        {} ({}x{}, {} object{})\n", scene.path, scene.width, scene.height,
               scene.objects.size(), scene.objects.size() == 1 ? "" : "s");
    fmt::format_to(out, "precision    {}\n", precision_name(prog.exec.precision));
    const Backend backend = effective_backend(prog.exec.backend, prog.exec.precision);
    fmt::format_to(out, "backend      {}{}, LLVM compile so far {:.2f} ms\n", backend_name(backend),
               backend == Backend::Jit && prog.exec.backend == Backend::Auto
                   ? " (auto: the interpreter until compiled)" : "",
               prog.jit_compile_seconds() * 1e3);
    const Program::JitCompiles compiles = prog.jit_compiles();
    fmt::format_to(out, "JIT code     {} shader{} compiled, {} loaded from the code cache; {} of them optimised (LLVM {:.2f} ms)\n",
               compiles.compiled, compiles.compiled == 1 ? "" : "s", compiles.loaded, compiles.optimised,
               state_of(prog).backends->optimise_seconds() * 1e3);
    fmt::format_to(out, "vertices     {}\ntriangles    {}\n", s.vertices, s.triangles);
    // The fused pipeline's fragments, and its share of LLVM's time above.
    const raster::fused::Cache& pipelines = *state_of(prog).pipelines;
    const Program::JitCompiles made = pipelines.counts();
    fmt::format_to(out, "fragments    {} shaded, {} written; fused pipeline: {}\n", s.fragments_shaded,
                   s.fragments_written, s.fragments_fused);
    fmt::format_to(out, "pipelines    {} pipeline{} compiled, {} loaded from the code cache (LLVM {:.2f} ms)\n",
                   made.compiled, made.compiled == 1 ? "" : "s", made.loaded, pipelines.compile_seconds() * 1e3);
    fmt::format_to(out, "instructions {} (bounded per draw, and per render by --max-instructions)\n",
                   s.instructions);
    fmt::format_to(out, "time (ms)    compile {:.2f}, vertex {:.2f}, setup+raster {:.2f}, fragment {:.2f}, output {:.2f}\n",
               compile_ms, s.vertex_seconds * 1e3, s.raster_seconds * 1e3, s.fragment_seconds * 1e3, output_ms);
    fmt::format_to(out, "built-in uniforms read   {}", builtin_values(prog, terminal_width()));
    fmt::format_to(out, "built-in attributes read {}\n", join_builtin_attributes(prog));
    fmt::format_to(out, "textures     {}\n", describe_textures(scene));
    return text;
}

namespace {

// Which pixels --compare counts as covered: those that differ from the
// background colour in either image. The background is --background's, else
// the rendered scene's clear colour, else the colour of the reference's four
// corners where they agree; else every pixel is covered.
struct Background {
    std::optional<scene::Rgba8> colour;
    std::string description;  // "covered: pixels ..."
};

Result<Background> compare_background(const RenderOptions& o, std::optional<scene::Rgba8> clear,
                                      const scene::Image& reference) {
    auto rgba = [](const scene::Rgba8& c) { return fmt::format("{},{},{},{}", c[0], c[1], c[2], c[3]); };
    if (o.background == "none") return Background{std::nullopt, "all (--background none)"};
    if (!o.background.empty()) {
        scene::Rgba8 c{};
        std::string_view text = o.background;
        for (size_t i = 0; i < 4; ++i) {
            size_t comma = i < 3 ? text.find(',') : text.size();
            if (comma == std::string_view::npos) comma = text.size();
            auto v = parse_int_pair(fmt::format("{},0", text.substr(0, comma)), ",");
            if (!v || v->first < 0 || v->first > 255 || (i < 3 && comma == text.size()))
                return Error(fmt::format("--background '{}' must be R,G,B,A with each in 0..255, or none", o.background));
            c[i] = uint8_t(v->first);
            text.remove_prefix(std::min(text.size(), comma + 1));
        }
        if (!text.empty())
            return Error(fmt::format("--background '{}' must be R,G,B,A with each in 0..255, or none", o.background));
        return Background{c, fmt::format("that differ from --background {} in either image", rgba(c))};
    }
    if (clear) return Background{clear, fmt::format("that differ from the scene's clear colour {} in either image",
                                                    rgba(*clear))};
    if (reference.width > 0 && reference.height > 0) {
        const int w = reference.width - 1, h = reference.height - 1;
        const uint8_t* corner = reference.pixel(0, 0);
        bool same = true;
        for (auto [x, y] : {std::pair{w, 0}, std::pair{0, h}, std::pair{w, h}})
            same = same && std::equal(corner, corner + 4, reference.pixel(x, y));
        if (same) {
            scene::Rgba8 c{corner[0], corner[1], corner[2], corner[3]};
            return Background{c, fmt::format("that differ from {} (the reference's corners) in either image",
                                             rgba(c))};
        }
    }
    return Background{std::nullopt, "all (the reference's corners differ: give --background R,G,B,A)"};
}

// Exit status 0: the images agree within the thresholds; 1: they differ
// (in size too); 2: a file could not be read or written.
int compare_with(const scene::Image& actual, const RenderOptions& o, std::optional<scene::Rgba8> clear) {
    auto reference = scene::read_png(o.compare);
    if (!reference) return fail(reference.error(), kToolError);
    scene::CompareOptions options;
    options.tolerance = o.tolerance;
    options.min_fraction_within = o.min_fraction;
    auto background = compare_background(o, clear, *reference);
    if (!background) return fail(background.error(), kToolError);
    options.clear_color = background->colour;
    auto stats = scene::compare_images(*reference, actual, options);
    if (!stats) return fail(stats.error());
    fmt::print("{}\n", stats->summary());
    fmt::print("covered: pixels {}\n", background->description);
    if (!o.diff.empty()) {
        auto diff = scene::diff_image(*reference, actual, o.tolerance);
        if (!diff) return fail(diff.error(), kToolError);
        if (Status st = write_image(*diff, o.diff); !st) return fail(st.error(), kToolError);
    }
    return stats->passed ? 0 : 1;
}

// --bench N: N more frames into the same framebuffer, each timed whole
// and per stage. The first frame (compile and first draw) is timed by render().
// fused_fragments: the last frame's fragments that the fused JIT pipeline drew.
Status bench_frames(const scene::ScenePrograms& programs, const scene::Scene& scene, Framebuffer& fb, int frames,
                    scene::BenchReport& report) {
    report.stage_s = {{"vertex", {}}, {"raster", {}}, {"fragment", {}}};
    uint64_t fused = 0;
    Progress progress("bench frames", size_t(frames));  // on a terminal only; drawn between the timed frames
    for (int i = 0; i < frames; ++i) {
        auto start = Clock::now();
        double cpu_start = scene::process_cpu_seconds();
        auto stats = scene::render_scene(programs, scene, fb);
        if (!stats) return stats.error();
        report.frame_s.push_back(ms_since(start) / 1e3);
        report.frame_cpu_s.push_back(scene::process_cpu_seconds() - cpu_start);
        report.stage_s[0].second.push_back(stats->vertex_seconds);
        report.stage_s[1].second.push_back(stats->raster_seconds);
        report.stage_s[2].second.push_back(stats->fragment_seconds);
        fused = stats->fragments_fused;
        progress.step();
    }
    report.counts.push_back({"fused_fragments", fused});
    return Ok{};
}

scene::BenchReport bench_header(const scene::Scene& scene, const RenderOptions& o, const DrawStats& first,
                                double compile_ms, double first_draw_ms) {
    scene::BenchReport r;
    r.renderer = "glslrun";
    r.width = scene.width;
    r.height = scene.height;
    r.threads = o.threads == 0 ? "auto" : std::to_string(o.threads);
    r.precision = precision_name(o.precision);
    r.backend = backend_name(effective_backend(o.backend, o.precision));
    r.compile_s = compile_ms / 1e3;
    r.first_draw_s = first_draw_ms / 1e3;
    r.counts = {{"vertices", first.vertices}, {"triangles", first.triangles},
                {"fragments", first.fragments_shaded}};
    return r;
}

// The "#version" line of a shader source, or "" without one (GLSL 1.10).
std::string version_line(const std::string& text) {
    size_t at = text.find("#version");
    if (at == std::string::npos) return {};
    return text.substr(at, text.find('\n', at) - at) + "\n";
}

// glslang builds its built-in symbol tables at the first compile of each
// version and stage in a process (about 2.5 ms, docs/performance.md). A
// one-line program of the same versions, compiled on a thread while the
// scene loads and the framebuffer is allocated, builds them there; the real
// compile then finds them built. Its result (and any error) is not used.
std::jthread warm_up_compiler(const Inputs& in) {
    auto tiny = [](const std::vector<ShaderSource>& stage, const char* name, const char* body) {
        std::vector<ShaderSource> out;
        if (!stage.empty()) out.push_back({name, version_line(stage[0].text) + body});
        return out;
    };
    try {
        return std::jthread([vs = tiny(in.vertex, "warm-up.vert", "void main() { gl_Position = vec4(0.0); }\n"),
                             fs = tiny(in.fragment, "warm-up.frag", "void main() { gl_FragColor = vec4(0.0); }\n")] {
            (void)Program::compile(vs, fs);
        });
    } catch (const std::system_error&) {
        return {};  // no thread to be had: the compile builds the tables itself
    }
}

}  // namespace

// --size and --uniform, checked before anything is read: a malformed one is a usage error.
Status check_option_values(const RenderOptions& o) {
    for (const std::string& arg : o.uniforms)
        if (auto settings = scene::parse_uniform_override(arg); !settings) return settings.error();
    if (!o.size.empty())
        if (auto size = parse_size(o.size); !size) return size.error();
    return Ok{};
}

// The scene file, with --size and --uniform applied; its warnings are printed.
Result<scene::Scene> load_sized_scene(const Inputs& in, const RenderOptions& o) {
    auto scene = scene::load_scene(in.scene);
    if (!scene) return scene.error();
    for (const std::string& arg : o.uniforms) {
        auto settings = scene::parse_uniform_override(arg);
        if (!settings) return settings.error();
        scene::override_uniforms(*scene, *settings);
    }
    // Legal but likely unintended (an incomplete texture samples as black).
    for (const Diagnostic& w : scene->warnings) fmt::print(stderr, "{}\n", w.str());
    if (!o.size.empty()) {
        auto size = parse_size(o.size);
        if (!size) return size.error();
        if (Status st = scene::resize_scene(*scene, size->first, size->second); !st) return st.error();
    }
    return scene;
}

namespace {

// --check-undefined: the scene rendered once with the checks
// (glslrun/scene/undefined.h), its image written where `output` is given,
// and the findings printed.
int run_check_undefined(const Inputs& in, const RenderOptions& o, const scene::Scene& scene, Framebuffer& fb,
                        const std::string& output) {
    ExecOptions exec;
    exec.precision = o.precision;
    exec.backend = o.backend;
    exec.set_time_limit(o.time_limit);
    exec.max_render_instructions = o.max_instructions;
    exec.threads = o.threads;
    CompileOptions compile;
    compile.defines = o.defines;
    compile.include_dirs = o.include_dirs;
    auto report = scene::check_undefined(in.vertex, in.fragment, scene, exec, fb, compile);
    if (!report) return fail(report.error());
    for (const Diagnostic& w : report->warnings) fmt::print(stderr, "{}\n", w.str());
    if (!output.empty())
        if (Status st = write_buffers(fb, output); !st) return fail(st.error(), kToolError);
    std::fputs(scene::format_undefined(*report).c_str(), stdout);
    return 0;
}

void set_exec_options(Program& prog, const RenderOptions& o) {
    prog.exec.threads = o.threads;
    prog.exec.precision = o.precision;
    prog.exec.backend = o.backend;
    prog.exec.jit_specialize_after = o.specialize_after;
    prog.exec.jit_tier = o.jit_tier;
    prog.exec.max_render_instructions = o.max_instructions;
    prog.exec.set_time_limit(o.time_limit);
}

int render(const Inputs& in, const RenderOptions& o) {
    std::jthread warm_up = warm_up_compiler(in);
    auto scene = load_sized_scene(in, o);
    if (!scene) return fail(scene.error(), kResultError);
    std::string output = o.output.empty() ? default_output(in) : o.output;
    if (Status st = check_output(output, o, scene::color_buffers(*scene)); !st) return fail(st.error(), kToolError);
    const InputFiles inputs = input_files(in, &*scene, o);
    if (!o.error_report.empty()) return run_error_report(in.vertex, in.fragment, *scene, o, inputs);
    bool writes_image = !o.output.empty() || !o.dump_ir;
    if (Status st = check_outputs(inputs, writes_image ? output : "", scene::color_buffers(*scene), o); !st)
        return fail(st.error(), kToolError);
    // Allocated before the compile, so that its page faults (2.7 ms at
    // 512x512, perf) overlap the warm-up too.
    auto fb = Framebuffer::create(scene->width, scene->height, false, scene::color_buffers(*scene));
    if (!fb) return fail(fb.error());
    // The clock starts before the wait: what is left of building glslang's
    // tables is part of the compile a user waits for.
    auto start = Clock::now();
    if (warm_up.joinable()) warm_up.join();
    if (o.check_undefined) return run_check_undefined(in, o, *scene, *fb, writes_image ? output : "");
    // No shaders: every draw in GL's fixed function.
    const bool fixed = in.vertex.empty() && in.fragment.empty();
    if (fixed) {
        if (std::string w = scene::fixed_function_warning(*scene); !w.empty()) fmt::print(stderr, "{}\n", w);
        scene::use_fixed_function(*scene);
    }
    auto prog = fixed ? scene::unused_main_program() : compile_program(in, o);
    if (!prog) return fail(prog.error());
    set_exec_options(*prog, o);  // before the passes' programs copy them
    auto programs = scene::ScenePrograms::compile(*prog, *scene);
    if (!programs) return fail(programs.error());
    for (const Diagnostic& w : programs->warnings()) fmt::print(stderr, "{}\n", w.str());
    double compile_ms = ms_since(start);
    if (o.dump_ir) std::fputs(prog->dump_ir().c_str(), stdout);
    start = Clock::now();
    auto stats = scene::render_scene(*programs, *scene, *fb);
    if (!stats) return fail(stats.error());
    scene::BenchReport bench = bench_header(*scene, o, *stats, compile_ms, ms_since(start));
    if (o.bench_frames > 0)
        if (Status st = bench_frames(*programs, *scene, *fb, o.bench_frames, bench); !st) return fail(st.error());
    start = Clock::now();
    // --dump-ir alone prints the IR: it writes no image unless -o asks for one.
    // An image that cannot be written is a tool error (docs/ci.md), standard output full too.
    if (writes_image)
        if (Status st = write_buffers(*fb, output); !st) return fail(st.error(), kToolError);
    double output_ms = ms_since(start);
    if (o.stats) std::fputs(format_stats(*prog, *scene, *stats, compile_ms, output_ms).c_str(), stdout);
    if (o.bench_frames > 0) {
        // The first tier's compiles (what a draw may wait for) apart from the
        // second's, made in the background once the program is hot.
        const double optimise = state_of(*prog).backends->optimise_seconds();
        bench.once_s = {{"output", output_ms / 1e3},
                        {"llvm_compile", prog->jit_compile_seconds() - optimise},
                        {"llvm_optimise", optimise}};
        std::fputs(scene::format_bench(bench).c_str(), stdout);
    }
    if (!o.dump_fixed_function.empty()) {
        // A render with a probe on the draws' programs names the stages as trace does.
        auto stages = debug::generated_stages(*prog, *prog, *scene, *fb);
        if (!stages) return fail(stages.error());
        if (int status = dump_fixed_function(*stages, o.dump_fixed_function, in, *scene); status != 0) return status;
    }
    if (!o.compare.empty()) return compare_with(scene::read_framebuffer(*fb), o, scene::to_rgba8(scene->clear_color));
    return 0;
}

// Whether any pass's program has the uniform.
bool any_program_has(const scene::ScenePrograms& programs, const std::string& name) {
    for (size_t i = 0; i < programs.size(); ++i)
        if (programs.of_pass(i).has_uniform(name)) return true;
    return false;
}

// --frames N: frame i with `uniform float time` = i / frames per second (the
// scene's [animation], or --time-uniform and --fps), into out.0000.png, ...
int render_frames(const Inputs& in, const RenderOptions& o) {
    auto scene = load_sized_scene(in, o);
    if (!scene) return fail(scene.error(), kResultError);
    std::string output = o.output.empty() ? default_output(in) : o.output;
    if (Status st = check_output(output, o, scene::color_buffers(*scene)); !st) return fail(st.error(), kToolError);
    if (Status st = check_outputs(input_files(in, &*scene, o), output, scene::color_buffers(*scene), o); !st)
        return fail(st.error(), kToolError);
    auto prog = compile_program(in, o);
    if (!prog) return fail(prog.error());
    set_exec_options(*prog, o);
    // Every frame's draws count toward one render's instructions, as the time limit covers them all.
    std::atomic<uint64_t> instructions{0};
    prog->exec.render_instructions = &instructions;
    auto programs = scene::ScenePrograms::compile(*prog, *scene);
    if (!programs) return fail(programs.error());
    for (const Diagnostic& w : programs->warnings()) fmt::print(stderr, "{}\n", w.str());
    const std::string time = o.time_uniform.empty() ? scene->animation.time_uniform : o.time_uniform;
    const double fps = o.frames_per_second > 0 ? o.frames_per_second : scene->animation.frames_per_second;
    const bool timed = any_program_has(*programs, time);
    if (!timed)
        fmt::print(stderr, "warning: --frames: the program has no active 'uniform float {}', so every frame is the "
                           "same\n", time);
    else
        scene->uniforms.push_back({time, {0.0}, false, {"--frames", 0}});
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    Progress progress("frames", size_t(o.frames));
    for (int frame = 0; frame < o.frames; ++frame) {
        if (timed) scene->uniforms.back().values = {frame / fps};
        auto stats = scene::render_scene(*programs, *scene, fb);
        if (!stats) return fail(stats.error());
        if (Status st = write_buffers(fb, frame_path(output, frame)); !st) return fail(st.error(), kToolError);
        progress.step();
    }
    return 0;
}

}  // namespace

// `glslrun --compare REF.png IMAGE.png`: any other file is a usage error.
int compare_files(const std::vector<std::string>& files, const RenderOptions& o) {
    if (o.bench_frames > 0 || o.stats || o.frames > 0 || o.dump_ir || !o.output.empty() || !o.error_report.empty())
        return fail(Error("comparing two images takes only --tolerance, --min-fraction, --background and --diff: "
                          "-o, --bench, --stats, --frames, --dump-ir and --error-report need shaders and a scene"),
                    kToolError);
    for (const std::string& f : files)
        if (fs::path(f).extension() != ".png" || files.size() != 1)
            return fail(Error("--compare takes one image besides the reference (`glslrun --compare REF.png "
                              "IMAGE.png`), or a scene to render: PNG images only",
                              f),
                        kToolError);
    auto image = scene::read_png(files[0]);
    if (!image) return fail(image.error(), kToolError);
    Inputs in;
    in.image = files[0];
    if (Status st = check_outputs(input_files(in, nullptr, o), "", 1, o); !st) return fail(st.error(), kToolError);
    return compare_with(*image, o, std::nullopt);
}

int run_render_command(const std::vector<std::string>& files, const RenderOptions& o) {
    // Two images: no shader or scene in sight, so no message about them.
    bool only_images = !files.empty() && std::none_of(files.begin(), files.end(), [](const std::string& f) {
        std::string ext = lower(fs::path(f).extension().string());
        return ext == ".toml" || !scene::shader_stage_of(f).empty() || ext == ".glsl";
    });
    if (!o.compare.empty() && only_images && o.stage.empty()) return compare_files(files, o);
    if (auto kinds = sort_files(files, o.stage); !kinds) return fail(kinds.error(), kToolError);
    if (Status st = check_option_values(o); !st) return fail(st.error(), kToolError);
    auto in = classify(files, o.stage);
    if (!in) return fail(in.error());
    bool has_shaders = !in->vertex.empty() || !in->fragment.empty();
    if (!in->image.empty())
        return fail(Error("a PNG is only accepted as `glslrun --compare REF.png IMAGE.png`", in->image), kToolError);
    if (!has_shaders && in->scene.empty())
        return fail(Error("no shaders given (files ending in .vert or .frag), and no scene to draw with GL's fixed "
                          "function"), kToolError);
    if (!has_shaders && (o.stats || o.dump_ir || o.frames > 0 || o.check_undefined || !o.error_report.empty()))
        return fail(Error("without shaders the scene is drawn with GL's fixed function; --stats, --dump-ir, --frames, "
                          "--check-undefined and --error-report need a program of yours"), kToolError);
    if (!o.error_report.empty() && in->scene.empty())
        return fail(Error("--error-report needs a scene file (scene.toml) to render"), kToolError);
    if (!o.error_report.empty() &&
        (o.bench_frames > 0 || !o.compare.empty() || !o.output.empty() || o.stats || o.dump_ir))
        return fail(Error("--error-report writes its own images and numbers: it does not combine with -o, "
                          "--bench, --compare, --stats or --dump-ir"), kToolError);
    if (o.frames > 0 && (o.bench_frames > 0 || !o.compare.empty() || o.stats || !o.error_report.empty()))
        return fail(Error("--frames writes a sequence of images: it does not combine with --bench, --compare, "
                          "--stats or --error-report"), kToolError);
    if (o.check_undefined && (o.frames > 0 || o.bench_frames > 0 || !o.compare.empty() || o.stats || o.dump_ir ||
                              !o.error_report.empty() || in->scene.empty()))
        return fail(Error("--check-undefined renders the scene once with checks (shaders and a scene file): it does "
                          "not combine with --frames, --bench, --compare, --stats, --dump-ir or --error-report"),
                    kToolError);
    if (!o.dump_fixed_function.empty() &&
        (in->scene.empty() || o.frames > 0 || o.check_undefined || !o.error_report.empty()))
        return fail(Error("--dump-fixed-function writes the stages generated for a scene's draws while it renders "
                          "the scene once (a scene file; not with --frames, --check-undefined or --error-report)"),
                    kToolError);
    if (o.frames == 0 && (!o.time_uniform.empty() || o.frames_per_second > 0))
        return fail(Error("--time-uniform and --fps set what --frames animates: give --frames N too"), kToolError);
    if (o.time_uniform.starts_with("gl_"))
        return fail(Error(fmt::format("--time-uniform '{}': the time goes to a user uniform, not a built-in one",
                                      o.time_uniform)), kToolError);
    if (o.frames > 0 && !in->scene.empty()) return render_frames(*in, o);
    if (!in->scene.empty()) return render(*in, o);
    if (!o.output.empty() || o.stats || o.bench_frames > 0 || !o.compare.empty())
        return fail(Error("rendering needs a scene file (scene.toml); see scenes/ and docs/scene-format.md"),
                    kToolError);
    // Compile only: diagnostics, and the IR with --dump-ir.
    auto prog = compile_program(*in, o);
    if (!prog) return fail(prog.error());
    if (o.dump_ir) std::fputs(prog->dump_ir().c_str(), stdout);
    return 0;
}

}  // namespace glslrun::cli
