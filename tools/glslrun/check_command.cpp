#include "check_command.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "command_line.h"
#include "glslrun/glslrun.h"
#include "render_command.h"

namespace glslrun::cli {
namespace {

// One file: its stage from the name (or --stage), compiled with no link step.
int check_file(const std::string& path, const std::string& stage, const CompileOptions& options) {
    auto in = classify({path}, stage);
    if (!in) {
        std::fputs(in.error().str().c_str(), stderr);
        return kResultError;
    }
    if (!in->scene.empty() || !in->image.empty()) {
        std::fputs(Error("check takes shaders (.vert, .frag, or .glsl with --stage)", path).str().c_str(), stderr);
        return kToolError;
    }
    const bool vertex = !in->vertex.empty();
    Status st =
        check_shader(vertex ? Stage::Vertex : Stage::Fragment, vertex ? in->vertex[0] : in->fragment[0], options);
    if (st) return 0;
    std::fputs(st.error().str().c_str(), stderr);
    return kResultError;
}

}  // namespace

int check_main(int argc, char** argv) {
    CLI::App app{"Compiles each shader alone (no link, no scene) and prints its diagnostics as file:line: "
                 "error: ...; exit status 0 when every file compiles, 1 when one does not, 2 for a usage error",
                 "glslrun check"};
    std::vector<std::string> files;
    std::string stage;
    app.add_option("files", files, "shader files: .vert/.vs and .frag/.fs, or any name with --stage")->required();
    app.add_option("--stage,-S", stage, "the stage of files whose name does not give it (a.glsl): vert or frag")
        ->check(CLI::IsMember({"vert", "frag"}));
    CompileOptions options;
    add_define_option(app, options.defines);
    add_include_option(app, options.include_dirs);
    if (int rc = parse_command_line(app, argc, argv); rc >= 0) return rc;
    int status = 0;
    for (const std::string& f : files) status = std::max(status, check_file(f, stage, options));
    return status;
}

}  // namespace glslrun::cli
