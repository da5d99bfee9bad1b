#include "batch_command.h"

#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "glslrun/scene/render.h"
#include "image_output.h"
#include "output_guard.h"
#include "progress.h"
#include "render_command.h"
#include "runtime/program_state.h"
#include "scene/text_file.h"

namespace glslrun::cli {

std::optional<std::vector<std::string>> split_job_line(std::string_view line, std::string& why) {
    std::vector<std::string> fields;
    std::string field;
    bool in_field = false;
    for (size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        if (c == '\0') {
            why = "a NUL byte in the line (paths cannot hold one)";
            return std::nullopt;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            if (in_field) fields.push_back(std::move(field));
            field.clear();
            in_field = false;
        } else if (c == '#' && !in_field) {
            break;
        } else if (c == '\'' || c == '"') {
            size_t end = i + 1;
            for (; end < line.size() && line[end] != c; ++end) {
                if (line[end] == '\0') {
                    why = "a NUL byte in the line (paths cannot hold one)";
                    return std::nullopt;
                }
                if (c == '"' && line[end] == '\\' && end + 1 < line.size() &&
                    (line[end + 1] == '"' || line[end + 1] == '\\'))
                    ++end;
                field += line[end];
            }
            if (end == line.size()) {
                why = fmt::format("the quote {} opened in column {} is not closed", c, i + 1);
                return std::nullopt;
            }
            i = end;
            in_field = true;
        } else if (c == '\\' && i + 1 < line.size()) {
            field += line[++i];
            if (field.back() == '\0') {
                why = "a NUL byte in the line (paths cannot hold one)";
                return std::nullopt;
            }
            in_field = true;
        } else {
            field += c;
            in_field = true;
        }
    }
    if (in_field) fields.push_back(std::move(field));
    return fields;
}

namespace {

struct Job {
    int line = 0;
    std::string vertex, fragment, scene, output;
};

struct ParsedJobs {
    std::vector<Job> jobs;
    std::vector<std::string> errors;  // "JOBS:line: error: ..." for malformed lines
};

// A line's fields as a job, or why they are not one: `VERT FRAG SCENE
// OUTPUT` by position, or with a stage left out (GL's fixed function) the
// shaders that remain, each by its name's stage.
std::string job_fields(const std::vector<std::string>& fields, Job& job) {
    constexpr const char* kForm =
        "a job is `[VERT] [FRAG] SCENE OUTPUT` (2 to 4 fields, quoted where they hold a blank; a shader left out "
        "is GL's fixed function)";
    if (fields.size() < 2 || fields.size() > 4) return fmt::format("{}; this line has {}", kForm, fields.size());
    const size_t shaders = fields.size() - 2;
    job.scene = fields[shaders];
    job.output = fields[shaders + 1];
    if (!job.scene.ends_with(".toml"))
        return fmt::format("{}; '{}', the field before the output, is not a scene file (.toml)", kForm, job.scene);
    if (Status st = check_image_name(job.output); !st) return st.error().diagnostics.front().message;
    if (shaders == 2) {
        job.vertex = fields[0];
        job.fragment = fields[1];
    } else if (shaders == 1) {
        const std::string stage = scene::shader_stage_of(fields[0]);
        if (stage.empty())
            return fmt::format("'{}': a job of one shader takes its stage from the name (.vert, .frag, "
                               "a.vert.glsl); give both shaders, VERT FRAG, to name them by position",
                               fields[0]);
        (stage == "vert" ? job.vertex : job.fragment) = fields[0];
    }
    return {};
}

ParsedJobs parse_jobs(const std::string& path, const std::string& text) {
    ParsedJobs out;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::string why;
        auto fields = split_job_line(line, why);
        if (fields && fields->empty()) continue;  // blank or comment
        Job job{number, {}, {}, {}, {}};
        if (fields && why.empty()) why = job_fields(*fields, job);
        if (!why.empty()) {
            out.errors.push_back(Error(why, path, number).str());
            continue;
        }
        out.jobs.push_back(std::move(job));
    }
    return out;
}

// A program compiled once for every job that names the same two files,
// with the uniform values it had then: each job starts from those, so no
// job sees another's uniforms.
struct CachedProgram {
    Result<Program> program;
    std::vector<uint32_t> initial_uniforms;
};

class ProgramCache {
public:
    Result<Program*> get(const Job& job) {
        auto key = std::pair{job.vertex, job.fragment};
        auto it = cache_.find(key);
        if (it == cache_.end()) {
            auto paths = [](const std::string& p) { return p.empty() ? std::vector<std::string>{} : std::vector{p}; };
            auto compiled = job.vertex.empty() && job.fragment.empty()
                                ? scene::unused_main_program()
                                : scene::compile_files(paths(job.vertex), paths(job.fragment));
            std::vector<uint32_t> initial;
            if (compiled) initial = state_of(*compiled).uniforms;
            // Braces: clang 14 (the sanitizer build) has no aggregate init from parentheses.
            auto cached = std::make_unique<CachedProgram>(CachedProgram{std::move(compiled), std::move(initial)});
            it = cache_.emplace(key, std::move(cached)).first;
        }
        CachedProgram& c = *it->second;
        if (!c.program) return c.program.error();
        state_of(*c.program).uniforms = c.initial_uniforms;
        return &*c.program;
    }
    size_t compiled() const { return cache_.size(); }

private:
    std::map<std::pair<std::string, std::string>, std::unique_ptr<CachedProgram>> cache_;
};

Status run_job(const Job& job, const ExecOptions& exec, ProgramCache& programs, const InputFiles& all_inputs) {
    auto scene = scene::load_scene(job.scene);
    if (!scene) return scene.error();
    // No shaders: every draw in GL's fixed function, as `glslrun scene.toml` draws it.
    if (job.vertex.empty() && job.fragment.empty()) {
        if (std::string w = scene::fixed_function_warning(*scene); !w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
        scene::use_fixed_function(*scene);
    }
    InputFiles inputs = all_inputs;
    inputs.add_scene(*scene);
    if (Status st = inputs.check_output(job.output, "the output"); !st) return st;
    auto program = programs.get(job);
    if (!program) return program.error();
    (*program)->exec = exec;
    // Legal but likely unintended, printed as when rendering one scene.
    for (const Diagnostic& w : scene->warnings) std::fprintf(stderr, "%s\n", w.str().c_str());
    auto drawn = scene::ScenePrograms::compile(**program, *scene);
    if (!drawn) return drawn.error();
    for (const Diagnostic& w : drawn->warnings()) std::fprintf(stderr, "%s\n", w.str().c_str());
    auto fb = Framebuffer::create(scene->width, scene->height, false, scene::color_buffers(*scene));
    if (!fb) return fb.error();
    if (auto stats = scene::render_scene(*drawn, *scene, *fb); !stats) return stats.error();
    return write_image(scene::read_framebuffer(*fb), job.output);
}

}  // namespace

int run_batch_command(const std::string& jobs_path, const ExecOptions& exec) {
    auto text = scene::read_text_file(jobs_path, "job file");
    if (!text) {
        std::fputs(text.error().str().c_str(), stderr);
        return 2;
    }
    ParsedJobs parsed = parse_jobs(jobs_path, *text);
    for (const std::string& e : parsed.errors) std::fputs(e.c_str(), stderr);
    if (parsed.jobs.empty() && parsed.errors.empty()) {
        std::fputs(Error("no jobs in the file", jobs_path).str().c_str(), stderr);
        return 2;
    }
    // No job's output may replace the job file or any job's shader or scene.
    InputFiles inputs;
    inputs.add(jobs_path);
    for (const Job& job : parsed.jobs)
        for (const std::string* p : {&job.vertex, &job.fragment, &job.scene})
            if (!p->empty()) inputs.add(*p);
    ProgramCache programs;
    size_t failed = 0;
    {
        Progress progress("jobs", parsed.jobs.size());
        for (const Job& job : parsed.jobs) {
            Status st = run_job(job, exec, programs, inputs);
            if (!st) {
                ++failed;
                progress.print(fmt::format("{}:{}: error: job failed:\n{}", jobs_path, job.line, st.error().str()));
            }
            progress.step(!st);
        }
    }
    std::printf("%zu jobs, %zu rendered, %zu failed, %zu malformed line%s; %zu program%s compiled\n",
                parsed.jobs.size(), parsed.jobs.size() - failed, failed, parsed.errors.size(),
                parsed.errors.size() == 1 ? "" : "s", programs.compiled(), programs.compiled() == 1 ? "" : "s");
    return failed || !parsed.errors.empty() ? 1 : 0;
}

}  // namespace glslrun::cli
