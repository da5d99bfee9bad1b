// The glslrun command line:
//   glslrun test [options] PATH...            piglit tests (shader_runner / glslparsertest)
//   glslrun a.vert a.frag scene.toml [-o out.png] [--stats] [--bench N]   a scene, rendered
//     (--precision reference|precise|fast, here and for `glslrun test`;
//      --error-report DIR measures the mode's error against reference)
//   glslrun --dump-ir a.vert a.frag           the IR of a program
//   glslrun --compare ref.png image.png       image differences
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "glslrun/glslrun.h"
#include "piglit_exec.h"
#include "piglit_isolate.h"
#include "piglit_suite.h"
#include "render_command.h"
#include "scene/text_file.h"

namespace {

using namespace glslrun;
namespace pg = glslrun::piglit;

constexpr const char* kVersion = "glslrun 0.1 (GLSL 1.10/1.20 on the CPU)";

// --precision NAME, for rendering and for `glslrun test`; a bad name is a usage error.
void add_precision_option(CLI::App& app, Precision& precision) {
    app.add_option_function<std::string>(
           "--precision",
           [&precision](const std::string& name) { precision = parse_precision(name).value(); },
           "reference (double, slow), precise (fp32, the default) or fast (fp32, GPU-style approximations)")
        ->check([](const std::string& name) {
            auto parsed = parse_precision(name);
            return parsed ? std::string() : parsed.error().diagnostics.front().message;
        });
}

// ------------------------------------------------------------ glslrun test ---
struct TestOptions {
    std::vector<std::string> paths;
    int jobs = 1;
    std::string tsv, expect, root;
    double time_limit = 120;
    bool no_isolate = false;
    Precision precision = Precision::Precise;
};

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

    std::ofstream tsv;
    if (!o.tsv.empty()) {
        tsv.open(o.tsv);
        if (!tsv) { fmt::print(stderr, "{}: cannot write the TSV file\n", o.tsv); return 2; }
        tsv << "path\tresult\tseconds\tmessage\n";
    }
    pg::RunOptions run_options;
    run_options.time_limit_s = o.time_limit;
    run_options.precision = o.precision;
    if (!o.no_isolate) pg::warm_up_compiler();
    auto run_one = [&](const pg::TestCase& tc) {
        if (o.no_isolate) return pg::run_test_file(tc.path, run_options);
        // A hard limit a bit above the soft one, which is only checked between commands.
        return pg::run_isolated([&] { return pg::run_test_file(tc.path, run_options); },
                                o.time_limit * 1.25 + 5);
    };
    auto results = pg::run_tests(
        cases, o.jobs, run_one,
        [&](size_t i, const pg::TestResult& r) {
            std::fputs((pg::format_result_line(cases[i].display, r) + "\n").c_str(), stdout);
            std::fflush(stdout);
            if (tsv) tsv << pg::format_tsv_line(cases[i].display, r) << "\n";
        });
    bool have_expect = !o.expect.empty();
    auto summary = pg::summarize(cases, results, have_expect ? &expectations : nullptr);
    std::fputs(pg::format_summary(summary, have_expect).c_str(), stdout);
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
                   "expectations list (\"path fail|skip # reason\"); unlisted tests must pass");
    app.add_option("--root", o.root, "print paths relative to this directory (and look them up there)");
    app.add_option("--time-limit", o.time_limit, "seconds per test (default 120)");
    app.add_flag("--no-isolate", o.no_isolate,
                 "run tests in this process (default: one forked process per test, so a crash "
                 "or hang fails only that test)");
    add_precision_option(app, o.precision);
    CLI11_PARSE(app, argc, argv);
    return run_test_command(o);
}

// ------------------------------------------------ programs and scenes ---
int program_cli(int argc, char** argv) {
    CLI::App app{"glslrun: legacy GLSL (1.10/1.20) on the CPU.\n"
                 "Renders a scene file with a GLSL program, compiles shaders, or compares images.",
                 "glslrun"};
    std::vector<std::string> files;
    cli::RenderOptions o;
    app.set_version_flag("--version", kVersion);
    app.add_option("files", files,
                   "shader.vert shader.frag scene.toml (the vertex shader may be left out: a "
                   "pass-through one is used)");
    app.add_option("-o,--output", o.output, "the PNG to write (default: <program>-<scene>.png)")
        ->check([](const std::string& path) { return path.empty() ? std::string("the path is empty") : std::string(); });
    app.add_option("--size", o.size, "image size WxH, instead of the scene's");
    app.add_flag("--stats", o.stats,
                 "print vertices, triangles, fragments, time per stage and the built-in state read");
    app.add_flag("--dump-ir", o.dump_ir, "print the program's IR");
    app.add_option("--threads", o.threads, "worker threads for drawing (default: one per core); images do not depend on it")
        ->check(CLI::Range(1, 256));
    add_precision_option(app, o.precision);
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
    app.add_option("--compare", o.compare,
                   "compare the rendered image, or the PNG given, with this reference PNG");
    app.add_option("--tolerance", o.tolerance, "--compare: per-channel difference allowed (default 0)")
        ->check(CLI::Range(0, 255));
    app.add_option("--diff", o.diff, "--compare: write a difference image to this PNG");
    app.footer("Examples:\n"
               "  glslrun shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml -o spot.png\n"
               "  glslrun --dump-ir shaders/minimal.vert shaders/minimal.frag\n"
               "  glslrun --compare mesa.png spot.png --tolerance 1 --diff diff.png\n"
               "  glslrun shaders/minimal.vert shaders/minimal.frag scenes/spot.toml --size 512x512 --bench 100\n"
               "  glslrun shaders/spot_pix_fixed.vert shaders/spot_pix_fixed.frag scenes/spot.toml --precision fast "
               "--error-report err/\n"
               "Scene files: docs/scene-format.md. Piglit tests: glslrun test --help");
    CLI11_PARSE(app, argc, argv);
    if (files.empty()) {
        std::fputs(app.help().c_str(), stdout);
        return 2;
    }
    return cli::run_render_command(files, o);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::string_view(argv[1]) == "test") return test_main(argc - 1, argv + 1);
    return program_cli(argc, argv);
}
