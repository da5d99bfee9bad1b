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

ParsedJobs parse_jobs(const std::string& path, const std::string& text) {
    ParsedJobs out;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::string why;
        auto fields = split_job_line(line, why);
        if (fields && fields->empty()) continue;  // blank or comment
        if (fields && fields->size() != 4)
            why = fmt::format("a job is `VERT FRAG SCENE OUTPUT` (4 fields, quoted where they hold a blank); "
                              "this line has {}", fields->size());
        if (fields && why.empty())
            if (Status st = check_image_name((*fields)[3]); !st) why = st.error().diagnostics.front().message;
        if (!why.empty()) {
            out.errors.push_back(Error(why, path, number).str());
            continue;
        }
        out.jobs.push_back({number, (*fields)[0], (*fields)[1], (*fields)[2], (*fields)[3]});
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
            auto compiled = scene::compile_files({job.vertex}, {job.fragment});
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
    InputFiles inputs = all_inputs;
    inputs.add_scene(*scene);
    if (Status st = inputs.check_output(job.output, "the output"); !st) return st;
    auto program = programs.get(job);
    if (!program) return program.error();
    (*program)->exec = exec;
    auto image = scene::render_image(**program, *scene);
    if (!image) return image.error();
    return write_image(*image, job.output);
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
        for (const std::string* p : {&job.vertex, &job.fragment, &job.scene}) inputs.add(*p);
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
