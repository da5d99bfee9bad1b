#include "scene/text_file.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "glslrun/scene/render.h"
#include "runtime/api_checks.h"

namespace glslrun::scene {

Status check_path(const std::string& path, const char* what) {
    if (Status st = rt::check_path(path); !st)
        return Error(fmt::format("cannot open {}: {}", what, st.error().diagnostics.front().message));
    return Ok{};
}

Status check_regular_file(const std::string& path, const char* what) {
    namespace fs = std::filesystem;
    if (Status st = check_path(path, what); !st) return st;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) return Error(fmt::format("cannot open {}: no such file", what), path);
    if (ec) return Error(fmt::format("cannot open {}: {}", what, ec.message()), path);
    if (fs::is_directory(status)) return Error(fmt::format("cannot read {}: it is a directory", what), path);
    if (!fs::is_regular_file(status)) return Error(fmt::format("cannot read {}: not a regular file", what), path);
    return Ok{};
}

Result<std::string> read_text_file(const std::string& path, const char* what, int64_t max_bytes) {
    namespace fs = std::filesystem;
    if (Status st = check_regular_file(path, what); !st) return st.error();
    std::error_code ec;
    const uintmax_t bytes = fs::file_size(path, ec);
    if (ec) return Error(fmt::format("cannot read {}: {}", what, ec.message()), path);
    if (bytes > uintmax_t(max_bytes))
        return Error(fmt::format("cannot read {}: it is {} bytes, the limit is {} MiB", what, bytes, max_bytes >> 20),
                     path);
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error(fmt::format("cannot open {}: {}", what, std::strerror(errno)), path);
    std::string text(size_t(bytes), '\0');
    in.read(text.data(), std::streamsize(bytes));
    text.resize(size_t(in.gcount()));  // a file that shrank meanwhile
    if (in.bad()) return Error(fmt::format("cannot read {}", what), path);
    return text;
}

std::string shader_stage_of(const std::string& path) {
    auto lower = [](std::string text) {
        for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
        return text;
    };
    std::filesystem::path p(path);
    std::string ext = lower(p.extension().string());
    if (ext == ".glsl") ext = lower(p.stem().extension().string());
    if (ext == ".vert" || ext == ".vs") return "vert";
    if (ext == ".frag" || ext == ".fs") return "frag";
    return {};
}

}  // namespace glslrun::scene
