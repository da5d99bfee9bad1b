// The glslrun command line:
//   glslrun test [options] PATH...            piglit tests (shader_runner / glslparsertest)
//   glslrun a.vert a.frag scene.toml [-o out.png] [--stats] [--bench N]   a scene, rendered
//     (--precision reference|precise|fast and --backend interp|jit|auto, here and for `glslrun test`;
//      --error-report DIR measures the mode's error against reference)
//   glslrun --dump-ir a.vert a.frag           the IR of a program
//   glslrun --compare ref.png image.png       image differences
//   glslrun batch JOBS                        many renders in one process
//   glslrun trace --pixel X,Y a.vert a.frag scene.toml   the shader debugger (docs/debugging.md)
//   glslrun check a.frag ...                  each shader compiled alone: diagnostics only
//   glslrun serve a.vert a.frag scene.toml    the debugger as a local web page
#include <cmath>
#include <filesystem>
#include <optional>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "batch_command.h"
#include "check_command.h"
#include "command_line.h"
#include "glslrun/glslrun.h"
#include "piglit_exec.h"
#include "piglit_isolate.h"
#include "output_guard.h"
#include "piglit_suite.h"
#include "progress.h"
#include "render_command.h"
#include "scene/scene_reader.h"
#include "scene/text_file.h"
#include "serve_command.h"
#include "trace_command.h"
#include "watchdog.h"

namespace {

using namespace glslrun;
namespace pg = glslrun::piglit;
using cli::add_backend_option;
using cli::add_define_option;
using cli::add_include_option;
using cli::add_precision_option;
using cli::parse_command_line;

constexpr const char* kVersion = "glslrun " GLSLRUN_VERSION_STRING " (GLSL 1.10/1.20 on the CPU)";

// A number in [lo, hi]; unlike CLI::Range, NaN is refused.
CLI::Validator finite_in(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) {
            char* end = nullptr;
            double v = std::strtod(text.c_str(), &end);
            bool ok = end != text.c_str() && *end == 0 && std::isfinite(v) && v >= lo && v <= hi;
            return ok ? std::string() : fmt::format("'{}' is not a number in [{}, {}]", text, lo, hi);
        },
        fmt::format("NUMBER in [{}, {}]", lo, hi));
}

// Where the documentation is: installed next to this executable
// (bin/../share/doc/glslrun), else the source tree it was built from.
std::string doc_dir() {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path installed = (exe.parent_path() / GLSLRUN_DOC_FROM_BIN).lexically_normal();
        if (fs::exists(installed / "README.md", ec)) return installed.string();
    }
    if (fs::exists(GLSLRUN_SOURCE_DOCS, ec)) return GLSLRUN_SOURCE_DOCS;
    return "docs/ in glslrun's source tree (not installed here)";
}

// ------------------------------------------------------------ glslrun test ---
struct TestOptions {
    std::vector<std::string> paths;
    int jobs = 1;
    std::string tsv, expect, root;
    std::string junit, json, shard;
    double time_limit = 120;
    bool no_isolate = false;
    bool quiet = false, verbose = false;  // per-test lines: none, or passes too (default: the others)
    Precision precision = Precision::Precise;
    Backend backend = Backend::Auto;
};

using cli::Watchdog;

bool write_report(const std::string& path, const std::string& text, const char* what) {
    if (path.empty()) return true;
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (out.flush()) return true;
    fmt::print(stderr, "{}: cannot write the {} file\n", path, what);
    return false;
}

int run_test_command(const TestOptions& o) {
    pg::Expectations expectations;
    if (!o.expect.empty()) {
        auto text = scene::read_text_file(o.expect, "the expectations file");
        if (!text) { fmt::print(stderr, "{}", text.error().str()); return 2; }
        auto parsed = pg::parse_expectations(*text);
        if (!pg::parsed_ok(parsed)) {
            fmt::print(stderr, "{}: {}\n", o.expect, std::get<pg::ParseError>(parsed).str());
            return 2;
        }
        expectations = std::move(std::get<pg::Expectations>(parsed));
    }
    std::vector<std::string> errors;
    auto cases = pg::discover_tests(o.paths, o.root, errors);
    for (const auto& e : errors) fmt::print(stderr, "error: {}\n", e);
    if (!errors.empty()) return 2;
    // A wrong path must not pass CI as an empty, successful run.
    if (cases.empty()) {
        fmt::print(stderr, "error: no tests found in {}\n", fmt::join(o.paths, ", "));
        return 2;
    }
    // No report over the expectations or a test file (a slip of the tab key).
    cli::InputFiles inputs;
    inputs.add(o.expect);
    for (const pg::TestCase& c : cases) inputs.add(c.path);
    for (const auto& [path, option] : {std::pair{&o.tsv, "--tsv"}, {&o.junit, "--junit"}, {&o.json, "--json"}})
        if (!path->empty())
            if (Status st = inputs.check_output(*path, option); !st) {
                std::fputs(st.error().str().c_str(), stderr);
                return 2;
            }
    if (!o.shard.empty()) {
        auto shard = pg::parse_shard(o.shard);
        if (!shard) { fmt::print(stderr, "error: --shard '{}' must be I/N with 0 <= I < N\n", o.shard); return 2; }
        cases = pg::select_shard(std::move(cases), shard->first, shard->second);
    }

    std::ofstream tsv;
    if (!o.tsv.empty()) {
        tsv.open(o.tsv);
        if (!tsv) { fmt::print(stderr, "{}: cannot write the TSV file\n", o.tsv); return 2; }
        tsv << "path\tresult\tseconds\tmessage\n";
    }
    pg::RunOptions run_options;
    run_options.time_limit_s = o.time_limit;
    run_options.precision = o.precision;
    run_options.backend = o.backend;
    // Thousands of passes would bury the few lines that matter: by default
    // only tests that do not pass get a line; a terminal gets a counter and ETA.
    std::optional<cli::Progress> progress;
    progress.emplace("tests", cases.size());
    auto report = [&](size_t i, const pg::TestResult& r) {
        bool print = o.verbose || (!o.quiet && r.outcome != pg::Outcome::Pass);
        if (print) progress->print(pg::format_result_line(cases[i].display, r), stdout);
        progress->step(r.outcome == pg::Outcome::Fail);
        if (tsv) tsv << pg::format_tsv_line(cases[i].display, r) << "\n";
    };
    std::vector<pg::TestResult> results;
    if (o.no_isolate) {
        results = pg::run_tests(cases, o.jobs, [&](const pg::TestCase& tc) {
            Watchdog watchdog(o.time_limit);
            pg::RunOptions limited = run_options;
            limited.cancel = watchdog.flag();
            return pg::run_test_file(tc.path, limited);
        }, report);
    } else {
        // Every thread the warm-up started has ended: the children are forked from this one.
        pg::warm_up_compiler(o.backend);
        // A hard limit a bit above the soft one, which is only checked between commands.
        results = pg::run_isolated_tests(cases.size(), o.jobs, [&](size_t i) {
            return pg::run_test_file(cases[i].path, run_options);
        }, o.time_limit * 1.25 + 5, report);
    }
    progress.reset();  // ends its line before the summary
    bool have_expect = !o.expect.empty();
    auto summary = pg::summarize(cases, results, have_expect ? &expectations : nullptr);
    std::fputs(pg::format_summary(summary, have_expect).c_str(), stdout);
    // The TSV is written as tests finish; a full disk shows at the flush.
    if (tsv.is_open() && !tsv.flush()) {
        fmt::print(stderr, "{}: cannot write the TSV file\n", o.tsv);
        return 2;
    }
    if (!write_report(o.junit, pg::format_junit(cases, results), "JUnit") ||
        !write_report(o.json, pg::format_json(cases, results), "JSON"))
        return 2;
    return summary.ok(have_expect) ? 0 : 1;
}

int test_main(int argc, char** argv) {
    CLI::App app{"Runs piglit .shader_test files and glslparsertest .vert/.frag files", "glslrun test"};
    TestOptions o;
    o.jobs = 1;
    app.add_option("paths", o.paths, "test files or directories (searched recursively, in sorted order)")
        ->required();
    app.add_option("-j,--jobs", o.jobs, "tests run in parallel")->check(CLI::Range(1, 256));
    app.add_option("--tsv", o.tsv, "also write path, result, seconds, message to this TSV file");
    app.add_option("--expect", o.expect,
                   "expectations list (\"path fail|skip # reason\"); unlisted tests must pass: an unlisted "
                   "skip or fail is a regression (exit status 1), a listed test that passes is reported");
    app.add_option("--root", o.root, "print paths relative to this directory (and look them up there)");
    app.add_option("--time-limit", o.time_limit, "seconds per test (default 120)")
        ->check(finite_in(1e-3, 1e6));
    app.add_option("--junit", o.junit, "also write the results as JUnit XML to this file");
    app.add_option("--json", o.json, "also write the results as JSON (name, result, time, message per test)");
    app.add_option("--shard", o.shard,
                   "run only shard I of N (0-based, I/N): every N-th test from the I-th, for CI matrices");
    app.add_flag("-q,--quiet", o.quiet, "print no line per test, only the summary (and the reports asked for)");
    app.add_flag("-v,--verbose", o.verbose,
                 "print a line for every test, passes too (default: a line for each test that does not pass)");
    app.add_flag("--no-isolate", o.no_isolate,
                 "run tests in this process (default: one forked process per test, so a crash "
                 "or hang fails only that test)");
    add_precision_option(app, o.precision);
    add_backend_option(app, o.backend);
    cli::add_code_cache_options(app);
    if (int rc = parse_command_line(app, argc, argv); rc >= 0) return rc;
    cli::warn_about_code_cache(o.backend);
    if (o.quiet && o.verbose) {
        fmt::print(stderr, "error: --quiet and --verbose contradict each other\n");
        return 2;
    }
    return run_test_command(o);
}

// ------------------------------------------------------------ glslrun batch ---
int batch_main(int argc, char** argv) {
    CLI::App app{"Renders many (vertex, fragment, scene, output) jobs in one process", "glslrun batch"};
    std::string jobs;
    ExecOptions exec;
    app.add_option("jobs", jobs,
                   "a file of jobs, one `[VERT] [FRAG] SCENE OUTPUT` per line (a shader left out: GL's fixed "
                   "function, generated from the scene, as `glslrun` renders; one shader's stage by its name): "
                   "fields separated by blanks, quoted as in a shell ('a b.png' or \"a b.png\") where they hold "
                   "one; '#' starts a comment; the output's format by its name (.png, .jpg, .bmp, .tga)")
        ->required();
    app.add_option("--threads", exec.threads, "worker threads for drawing (default: one per core)")
        ->check(CLI::Range(1, 256));
    add_precision_option(app, exec.precision);
    add_backend_option(app, exec.backend);
    cli::add_code_cache_options(app);
    if (int rc = parse_command_line(app, argc, argv); rc >= 0) return rc;
    cli::warn_about_code_cache(exec.backend);
    return cli::run_batch_command(jobs, exec);
}

// ------------------------------------------------ programs and scenes ---
int program_cli(int argc, char** argv) {
    CLI::App app{"glslrun: legacy GLSL (1.10/1.20) on the CPU.\n"
                 "Renders a scene file with a GLSL program, compiles shaders, or compares images.\n"
                 "Commands (each has its own --help):\n"
                 "  glslrun [OPTIONS] [a.vert] [a.frag] scene.toml  render a scene (a shader left out: GL's fixed "
                 "function); without a scene, compile only\n"
                 "  glslrun check [--stage vert|frag] FILE...       compile each shader alone: file:line "
                 "diagnostics, exit 0 or 1\n"
                 "  glslrun test [--quiet] [--expect F] PATH...      run piglit .shader_test and glslparsertest "
                 "files\n"
                 "  glslrun batch JOBS                              render many jobs in one process\n"
                 "  glslrun trace --pixel X,Y a.vert a.frag s.toml  the shader debugger: every statement at "
                 "a pixel\n"
                 "  glslrun serve [--port N] a.vert a.frag s.toml   the debugger as a web page on 127.0.0.1: edit, "
                 "click a pixel",
                 "glslrun"};
    std::vector<std::string> files;
    cli::RenderOptions o;
    app.set_version_flag("--version", kVersion);
    app.add_option("files", files,
                   "shader.vert shader.frag scene.toml (either shader may be left out: GL's fixed "
                   "function is generated for that stage from the scene's state)");
    app.add_option("-o,--output", o.output,
                   "the image to write, its format by the name: .png (lossless, the default), .jpg, .bmp or .tga "
                   "(default: <program>-<scene>.png; - for PNG on standard output); with several draw buffers, "
                   "buffer i > 0 goes to NAME.i.png; never over an input file")
        ->check([](const std::string& path) { return path.empty() ? std::string("the path is empty") : std::string(); });
    app.add_option("--size", o.size, "image size WxH, instead of the scene's");
    app.add_option("--uniform", o.uniforms,
                   "NAME=VALUE: set a uniform after the scene's own settings (the value as in a scene's "
                   "[uniforms]: 0.5, 3, [1, 0, 0] or 1,0,0, true); repeatable")
        ->type_name("NAME=VALUE");
    app.add_option("--frames", o.frames,
                   "render N frames with `uniform float time` = frame / 30 seconds, into OUT.0000.png, "
                   "OUT.0001.png, ... (the name and rate: the scene's [animation], or the two options below)")
        ->type_name("N")
        ->check(CLI::Range(1, 100000));
    app.add_option("--time-uniform", o.time_uniform,
                   "with --frames: the float uniform that gets the time (default: the scene's "
                   "[animation] time_uniform, else `time`)")
        ->type_name("NAME");
    app.add_option("--fps", o.frames_per_second,
                   "with --frames: frames per second, time = frame / FPS (default: the scene's [animation] "
                   "frames_per_second, else 30)")
        ->type_name("FPS")
        ->check(CLI::Range(1e-6, 1e6));
    app.add_flag("--stats", o.stats,
                 "print vertices, triangles, fragments, time per stage and the built-in state read");
    app.add_flag("--dump-ir", o.dump_ir, "print the program's IR");
    app.add_option("--dump-fixed-function", o.dump_fixed_function,
                   "also write the fixed-function stages generated for the scene's draws (a stage left out, "
                   "program = \"fixed\") to DIR as fixed-function-1.vert, fixed-function-1.frag, ...")
        ->type_name("DIR");
    app.add_flag("--check-undefined", o.check_undefined,
                 "render on one thread with checks of the operations GLSL leaves undefined (pow of x < 0, "
                 "division by zero, an array index out of range, ...) and print each one found: file:line, "
                 "how often, the first invocation, what each precision mode and a GPU return");
    app.add_option("--threads", o.threads, "worker threads for drawing (default: one per core); images do not depend on it")
        ->check(CLI::Range(1, 256));
    app.add_option("--time-limit", o.time_limit,
                   "stop a render still drawing after SECONDS of wall-clock time, with an error and exit status 1 "
                   "(no image is written); default: none")
        ->type_name("SECONDS")
        ->check(finite_in(1e-3, 1e9));
    app.add_option("--max-instructions", o.max_instructions,
                   "stop a render whose shaders execute more than N instructions, all its draws and frames "
                   "together, with an error and exit status 1 (default 2^36, about 7 minutes of one core; "
                   "--stats prints a render's count)")
        ->type_name("N")
        ->check(CLI::Range(uint64_t(1), UINT64_MAX));
    add_precision_option(app, o.precision);
    add_backend_option(app, o.backend);
    cli::add_code_cache_options(app);
    app.add_option("--specialize-after", o.specialize_after,
                   "the JIT compiles a stage's uniforms in as constants once this many draws in a row had the "
                   "same values (default 0: never); the images do not change")
        ->type_name("N");
    app.add_option_function<std::string>(
           "--jit-tier",
           [&o](const std::string& name) {
               o.jit_tier = name == "first" ? JitTier::First : name == "optimised" ? JitTier::Optimised : JitTier::Tiered;
           },
           "the JIT's code: tiered (the default: quick code first; a stage that keeps drawing is compiled again "
           "with every optimization in the background), first (the quick code only) or optimised (the "
           "optimised code from the first draw; --backend jit waits for it); the images do not change")
        ->check([](const std::string& name) {
            return name == "tiered" || name == "first" || name == "optimised"
                       ? std::string()
                       : "unknown JIT tier '" + name + "': use tiered, first or optimised";
        })
        ->type_name("TIER");
    app.add_option("--bench", o.bench_frames,
                   "render N more frames into the same framebuffer and print `key value` lines: the "
                   "first frame (compile_ms, first_draw_ms), then median_ms, cpu_median_ms (process CPU "
                   "time), fps and the median per stage (vertex_ms, raster_ms = setup and binning, "
                   "fragment_ms), output_ms (the PNG, once)")
        ->type_name("N")
        ->check(CLI::Range(1, 100000));
    app.add_option("--error-report", o.error_report,
                   "render the scene in --precision's mode and in reference, and write the error of every "
                   "shader output (ULP, 8-bit) as a table, `key value` lines and heat maps into DIR "
                   "(created if missing)")
        ->type_name("DIR");
    add_define_option(app, o.defines);
    add_include_option(app, o.include_dirs);
    app.add_option("--stage,-S", o.stage,
                   "the stage of shader files whose name does not give it (a.glsl): vert or frag")
        ->check(CLI::IsMember({"vert", "frag"}));
    app.add_option("--compare", o.compare,
                   "compare the rendered image, or the PNG given, with this reference PNG");
    app.add_option("--background", o.background,
                   "--compare: the background colour R,G,B,A (0..255); pixels of it in both images are not covered "
                   "(default: the scene's clear colour, else the reference's corners' colour; none: every pixel)");
    app.add_option("--tolerance", o.tolerance, "--compare: per-channel difference allowed (default 0)")
        ->check(CLI::Range(0, 255));
    app.add_option("--min-fraction", o.min_fraction,
                   "--compare: the fraction of covered pixels that must be within --tolerance (default 1; the "
                   "project's rule against Mesa is --tolerance 1 --min-fraction 0.999)")
        ->check(finite_in(0, 1));
    app.add_option("--diff", o.diff, "--compare: write a difference image to this PNG");
    app.footer("Examples:\n"
               "  glslrun shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml -o spot.png\n"
               "  glslrun --dump-ir shaders/minimal.vert shaders/minimal.frag\n"
               "  glslrun --compare mesa.png spot.png --tolerance 1 --diff diff.png\n"
               "  glslrun shaders/minimal.vert shaders/minimal.frag scenes/spot.toml --size 512x512 --bench 100\n"
               "  glslrun shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml --precision fast "
               "--error-report err/\n"
               "Exit status: 0 done, 1 a shader, scene or image comparison failed, 2 a usage or tool error.\n"
               "Documentation: " + doc_dir() + " (README.md; scene-format.md for scene files, ci.md for exit "
               "statuses and CI, debugging.md for trace, limits.md)");
    if (int rc = parse_command_line(app, argc, argv); rc >= 0) return rc;
    if (files.empty()) {
        std::fputs(app.help().c_str(), stdout);
        return 2;
    }
    cli::warn_about_code_cache(o.backend);
    return cli::run_render_command(files, o);
}

// A first argument that is neither an option nor a file, and looks like a
// command ("trac"): a usage error that names the closest command, rather
// than "unknown kind of file".
std::optional<int> unknown_command(std::string_view word) {
    static const std::vector<std::string_view> kCommands = {"test", "batch", "trace", "check", "serve"};
    if (word.empty() || word[0] == '-' || word.find_first_of("./\\") != std::string_view::npos) return std::nullopt;
    std::error_code ec;
    if (std::filesystem::exists(std::string(word), ec)) return std::nullopt;
    std::string best = scene::detail::closest(word, kCommands);
    fmt::print(stderr, "glslrun: error: '{}' is neither a command nor a file{}\n", word,
               best.empty() ? fmt::format("; the commands are {} (glslrun --help)", fmt::join(kCommands, ", "))
                            : fmt::format("; did you mean 'glslrun {}'?", best));
    return 2;
}

int run_command(int argc, char** argv) {
    std::string_view first = argc >= 2 ? std::string_view(argv[1]) : std::string_view();
    if (first == "test") return test_main(argc - 1, argv + 1);
    if (first == "batch") return batch_main(argc - 1, argv + 1);
    if (first == "trace") return glslrun::cli::trace_main(argc - 1, argv + 1);
    if (first == "check") return glslrun::cli::check_main(argc - 1, argv + 1);
    if (first == "serve") return glslrun::cli::serve_main(argc - 1, argv + 1);
    if (auto status = unknown_command(first)) return *status;
    return program_cli(argc, argv);
}

}  // namespace

int main(int argc, char** argv) {
    // Sizes are checked before allocating (docs/limits.md); what is left is a
    // machine with less memory than the limits assume: a message, not an abort.
    int status = 0;
    try {
        status = run_command(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fputs("glslrun: error: out of memory\n", stderr);
        status = 2;
    }
    glslrun::stop_background_compiles();  // before any exit handler runs
    // A trace, the IR or a report cut short by a full disk is an error, not a success.
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fputs("glslrun: error: cannot write standard output\n", stderr);
        return status == 0 ? 2 : status;
    }
    return status;
}
