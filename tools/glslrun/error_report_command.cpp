#include "error_report_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

namespace glslrun::cli {

namespace {

int fail(const Error& e, int status = 1) {
    std::fputs(e.str().c_str(), stderr);
    return status;
}

// The output directory: made when missing; anything but a directory is an error.
Status prepare_directory(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        return Error("--error-report: exists and is not a directory", dir);
    fs::create_directories(dir, ec);
    if (ec) return Error(fmt::format("--error-report: cannot create the directory: {}", ec.message()), dir);
    return Ok{};
}

}  // namespace

// Writes `text` to DIR/name, unless that is an input.
Status write_text(const std::string& dir, const char* name, const std::string& text, const InputFiles& inputs) {
    std::string path = (std::filesystem::path(dir) / name).string();
    if (Status st = inputs.check_output(path, "--error-report"); !st) return st;
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out.flush()) return Error("--error-report: cannot write the file", path);
    return Ok{};
}

int run_error_report(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                     const scene::Scene& scene, const RenderOptions& o, const InputFiles& inputs) {
    if (Status st = prepare_directory(o.error_report); !st) return fail(st.error());
    scene::ErrorReportOptions options;
    options.mode = o.precision;
    options.threads = o.threads;
    options.time_limit = o.time_limit;  // --time-limit: for the report's renders together
    options.compile.defines = o.defines;
    options.compile.include_dirs = o.include_dirs;
    auto report = scene::measure_error(vertex, fragment, scene, options);
    if (!report) return fail(report.error());
    for (const Diagnostic& w : report->warnings) fmt::print(stderr, "{}\n", w.str());
    auto files = scene::write_error_images(*report, o.error_report, [&](const std::string& path) {
        return inputs.check_output(path, "--error-report");
    });
    if (!files) return fail(files.error(), 2);
    namespace fs = std::filesystem;
    files->push_back((fs::path(o.error_report) / "report.txt").string());
    files->push_back((fs::path(o.error_report) / "report.keys").string());
    const std::string table = scene::format_error_table(*report, *files);
    const std::string keys = scene::format_error_keys(*report);
    if (Status st = write_text(o.error_report, "report.txt", table, inputs); !st) return fail(st.error(), 2);
    if (Status st = write_text(o.error_report, "report.keys", keys, inputs); !st) return fail(st.error(), 2);
    std::fputs(table.c_str(), stdout);
    std::fputs("\n", stdout);
    std::fputs(keys.c_str(), stdout);
    return 0;
}

}  // namespace glslrun::cli
