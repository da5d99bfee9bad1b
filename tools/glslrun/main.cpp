// The glslrun command line:
//   glslrun test [options] PATH...            piglit tests (shader_runner / glslparsertest)
//   glslrun --dump-ir a.vert a.frag           the IR of a program
//   glslrun a.vert a.frag -o out.png          the lecture quad, rendered
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "glslrun/glslrun.h"
#include "piglit_exec.h"
#include "piglit_isolate.h"
#include "piglit_suite.h"

namespace {

using namespace glslrun;
namespace pg = glslrun::piglit;

constexpr const char* kVersion = "glslrun 0.1 (GLSL 1.10/1.20 on the CPU)";

std::optional<std::string> read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream buf;
    buf << in.rdbuf();
    return buf.str();
}

// ------------------------------------------------------------ glslrun test ---
struct TestOptions {
    std::vector<std::string> paths;
    int jobs = 1;
    std::string tsv, expect, root;
    double time_limit = 120;
    bool no_isolate = false;
};

int run_test_command(const TestOptions& o) {
    pg::Expectations expectations;
    if (!o.expect.empty()) {
        auto text = read_text(o.expect);
        if (!text) { fmt::print(stderr, "{}: cannot read the expectations file\n", o.expect); return 2; }
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
    CLI11_PARSE(app, argc, argv);
    return run_test_command(o);
}

// ------------------------------------------------------- programs, quad ---
struct MainOptions {
    std::vector<std::string> shaders;
    std::string output;
    std::string size = "512x512";
    bool dump_ir = false;
};

std::optional<Stage> stage_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".vert" || ext == ".vs") return Stage::Vertex;
    if (ext == ".frag" || ext == ".fs") return Stage::Fragment;
    return std::nullopt;
}

// The lecture's state (notes/scenes.md): camera, light 0 "directional", material.
GLState lecture_state(int width, int height) {
    GLState gl;
    gl.projection = glm::perspective(glm::radians(45.0f), float(width) / float(height), 1.0f, 100.0f);
    gl.modelview = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    gl.depth_test = true;
    LightState& l = gl.lights[0];
    l.ambient = {0.2f, 0.2f, 0.2f, 1};
    l.diffuse = {1, 1, 1, 1};
    l.specular = {1, 1, 1, 1};
    l.position = {1, 1, 1, 0};  // eye space: directions are unchanged by the camera
    MaterialState m;
    m.ambient = {0.25f, 0.20f, 0.07f, 1};
    m.diffuse = {0.75f, 0.61f, 0.23f, 1};
    m.specular = {0.80f, 0.80f, 0.80f, 1};
    m.emission = {0.0f, 0.0f, 0.05f, 1};
    m.shininess = 64;
    gl.front_material = gl.back_material = m;
    return gl;
}

int render_quad(Program& prog, const MainOptions& o) {
    int width = 0, height = 0;
    char x = 0;
    if (std::sscanf(o.size.c_str(), "%d%c%d", &width, &x, &height) != 3 || (x != 'x' && x != 'X') ||
        width <= 0 || height <= 0) {
        fmt::print(stderr, "error: --size must be WxH with positive sizes, e.g. 512x512\n");
        return 2;
    }
    if (width > 16384 || height > 16384) {
        fmt::print(stderr, "error: --size {}x{} is too large: at most 16384x16384\n", width, height);
        return 2;
    }
    GLState gl = lecture_state(width, height);
    Framebuffer fb(width, height);
    fb.clear_color({0, 0, 0, 1});
    fb.clear_depth(1);
    std::vector<VertexAttrib> quad = {
        {"gl_Vertex", 3, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}},
        {"gl_Color", 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0}},
        {"gl_Normal", 3, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}},
    };
    auto stats = draw(prog, gl, fb, Primitive::Quads, quad, 4);
    if (!stats) { fmt::print(stderr, "{}", stats.error().str() + "\n"); return 1; }
    auto st = write_png(fb, o.output);
    if (!st) { fmt::print(stderr, "{}", st.error().str() + "\n"); return 1; }
    return 0;
}

int program_main(const MainOptions& o) {
    std::vector<ShaderSource> vs, fs;
    for (const auto& path : o.shaders) {
        auto stage = stage_of(path);
        if (!stage) {
            fmt::print(stderr, "{}: error: unknown shader stage (use .vert or .frag)\n", path);
            return 2;
        }
        auto text = read_text(path);
        if (!text) { fmt::print(stderr, "{}: error: cannot read the file\n", path); return 2; }
        (*stage == Stage::Vertex ? vs : fs).push_back({path, *text});
    }
    auto prog = Program::compile(vs, fs);
    if (!prog) {
        std::string msg = prog.error().str();
        if (!msg.empty() && msg.back() != '\n') msg += '\n';
        std::fputs(msg.c_str(), stderr);
        return 1;
    }
    if (o.dump_ir) std::fputs(prog->dump_ir().c_str(), stdout);
    if (!o.output.empty()) return render_quad(*prog, o);
    return 0;
}

int program_cli(int argc, char** argv) {
    CLI::App app{"glslrun: legacy GLSL (1.10/1.20) on the CPU", "glslrun"};
    MainOptions o;
    app.set_version_flag("--version", kVersion);
    app.add_flag("--dump-ir", o.dump_ir, "print the program's IR");
    app.add_option("-o,--output", o.output, "render the lecture quad into this PNG");
    app.add_option("--size", o.size, "image size WxH (default 512x512)");
    app.add_option("shaders", o.shaders, "shader files (.vert, .frag); several per stage allowed");
    app.footer("Piglit tests: glslrun test [-j N] [--root DIR] [--expect FILE] [--tsv FILE] PATH...\n"
               "(see glslrun test --help)");
    CLI11_PARSE(app, argc, argv);
    if (o.shaders.empty()) {
        std::fputs(app.help().c_str(), stdout);
        return 2;
    }
    return program_main(o);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::string_view(argv[1]) == "test") return test_main(argc - 1, argv + 1);
    return program_cli(argc, argv);
}
