#include "error_report_command.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

namespace glslrun::cli {

namespace {

int fail(const Error& e) {
    std::fputs(e.str().c_str(), stderr);
    return 1;
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

int run_error_report(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                     const scene::Scene& scene, const RenderOptions& o) {
    if (Status st = prepare_directory(o.error_report); !st) return fail(st.error());
    scene::ErrorReportOptions options;
    options.mode = o.precision;
    options.threads = o.threads;
    auto report = scene::measure_error(vertex, fragment, scene, options);
    if (!report) return fail(report.error());
    auto files = scene::write_error_images(*report, o.error_report);
    if (!files) return fail(files.error());
    std::fputs(scene::format_error_table(*report, *files).c_str(), stdout);
    std::fputs("\n", stdout);
    std::fputs(scene::format_error_keys(*report).c_str(), stdout);
    return 0;
}

}  // namespace glslrun::cli
