#include "output_guard.h"

#include <sys/stat.h>

#include <fmt/format.h>

#include "scene/text_file.h"

namespace glslrun::cli {

void InputFiles::add(const std::string& path) {
    struct stat st{};
    // stat, not lstat: a symbolic link given as input protects its target.
    if (path.find('\0') != std::string::npos || ::stat(path.c_str(), &st) != 0) return;
    inputs_.push_back({st.st_dev, st.st_ino, path});
}

void InputFiles::add_scene(const scene::Scene& scene) {
    add(scene.path);
    for (const std::string& file : scene.files) add(file);
    for (const scene::Pass& pass : scene.passes) {
        for (const ShaderSource& s : pass.vertex) add(s.name);
        for (const ShaderSource& s : pass.fragment) add(s.name);
    }
}

Status InputFiles::check_output(const std::string& path, const char* what) const {
    if (Status st = scene::check_path(path, what); !st) return st;
    struct stat st{};
    if (::stat(path.c_str(), &st) != 0) return Ok{};  // a new file
    for (const Id& in : inputs_)
        if (in.device == st.st_dev && in.inode == st.st_ino)
            return Error(fmt::format("{} '{}' is an input ({}{}): glslrun never writes over its inputs; give "
                                     "another name",
                                     what, path, in.path == path ? "the same file" : "the same file as ",
                                     in.path == path ? "" : "'" + in.path + "'"));
    return Ok{};
}

}  // namespace glslrun::cli
