#include "batch_command.h"

#include <unistd.h>

#include <cstdio>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "render_command.h"
#include "scene/text_file.h"

namespace glslrun::cli {
namespace {

struct Job {
    int line = 0;
    std::string vertex, fragment, scene, output;
};

Result<std::vector<Job>> parse_jobs(const std::string& path, const std::string& text) {
    std::vector<Job> jobs;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream fields(line.substr(0, line.find('#')));
        Job job{number, {}, {}, {}, {}};
        std::string extra;
        if (!(fields >> job.vertex)) continue;  // blank or comment
        if (!(fields >> job.fragment >> job.scene >> job.output) || fields >> extra)
            return Error("a job is `VERT FRAG SCENE OUTPUT.png`", path, number);
        if (Status st = check_png_name(job.output); !st)
            return Error(st.error().diagnostics.front().message, path, number);
        jobs.push_back(std::move(job));
    }
    if (jobs.empty()) return Error("no jobs in the file", path);
    return jobs;
}

Status run_job(const Job& job, const ExecOptions& exec) {
    auto scene = scene::load_scene(job.scene);
    if (!scene) return scene.error();
    auto program = scene::compile_files({job.vertex}, {job.fragment});
    if (!program) return program.error();
    program->exec = exec;
    auto image = scene::render_image(*program, *scene);
    if (!image) return image.error();
    return scene::write_png(*image, job.output);
}

// "[#####.....]  12/40 jobs, 1 failed", redrawn in place on a terminal.
void draw_progress(size_t done, size_t total, size_t failed) {
    constexpr size_t kWidth = 30;
    size_t filled = total ? done * kWidth / total : kWidth;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r[%s] %zu/%zu jobs%s", bar.c_str(), done, total,
                 failed ? fmt::format(", {} failed", failed).c_str() : "");
    std::fflush(stderr);
}

}  // namespace

int run_batch_command(const std::string& jobs_path, const ExecOptions& exec) {
    auto text = scene::read_text_file(jobs_path, "job file");
    if (!text) {
        std::fputs(text.error().str().c_str(), stderr);
        return 2;
    }
    auto jobs = parse_jobs(jobs_path, *text);
    if (!jobs) {
        std::fputs(jobs.error().str().c_str(), stderr);
        return 2;
    }
    const bool terminal = isatty(fileno(stderr));
    size_t failed = 0;
    for (size_t i = 0; i < jobs->size(); ++i) {
        const Job& job = (*jobs)[i];
        if (Status st = run_job(job, exec); !st) {
            ++failed;
            if (terminal) std::fputc('\n', stderr);
            std::fprintf(stderr, "%s:%d: error: job failed:\n%s", jobs_path.c_str(), job.line, st.error().str().c_str());
        }
        if (terminal) draw_progress(i + 1, jobs->size(), failed);
    }
    if (terminal) std::fputc('\n', stderr);
    std::printf("%zu jobs, %zu rendered, %zu failed\n", jobs->size(), jobs->size() - failed, failed);
    return failed ? 1 : 0;
}

}  // namespace glslrun::cli
