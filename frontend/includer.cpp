#include "frontend/includer.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

namespace glslrun::frontend {

namespace fs = std::filesystem;

FileIncluder::FileIncluder(std::string unit_file, std::vector<std::string> dirs,
                           std::function<std::string(std::string)> prepare, size_t& bytes_left)
    : unit_file_(std::move(unit_file)), dirs_(std::move(dirs)), prepare_(std::move(prepare)), bytes_left_(bytes_left) {}

FileIncluder::IncludeResult* FileIncluder::includeLocal(const char* header, const char* includer, size_t depth) {
    return find(header, includer ? includer : "", depth, true);
}

FileIncluder::IncludeResult* FileIncluder::includeSystem(const char* header, const char* includer, size_t depth) {
    return find(header, includer ? includer : "", depth, false);
}

void FileIncluder::releaseInclude(IncludeResult* result) {
    if (!result) return;
    for (auto it = texts_.begin(); it != texts_.end(); ++it)
        if (it->data() == result->headerData) {
            texts_.erase(it);
            break;
        }
    delete result;
}

FileIncluder::IncludeResult* FileIncluder::failure(std::string why) {
    texts_.push_back(std::move(why));
    return new IncludeResult("", texts_.back().data(), texts_.back().size(), nullptr);
}

FileIncluder::IncludeResult* FileIncluder::find(const std::string& header, const std::string& includer, size_t depth,
                                                bool local) {
    // glslang asks for a quoted name locally first and then as a system
    // one: the local search is done as part of the one below.
    if (local) return nullptr;
    if (depth > kMaxIncludeDepth)
        return failure(fmt::format("#include nests more than {} deep (a file that includes itself?), glslrun's "
                                   "limit",
                                   kMaxIncludeDepth));
    std::vector<std::string> places;
    // The unit's own string has no name in glslang: its includer is the unit's file.
    const std::string from = includer.empty() ? unit_file_ : includer;
    if (!fs::path(header).is_absolute()) places.push_back(fs::path(from).parent_path().string());
    for (const std::string& d : dirs_) places.push_back(d);
    std::error_code ec;
    for (const std::string& dir : places) {
        fs::path candidate = dir.empty() ? fs::path(header) : fs::path(dir) / header;
        if (fs::exists(candidate, ec)) return read(candidate.lexically_normal().string());
    }
    std::string searched;
    for (const std::string& dir : places) searched += (searched.empty() ? "" : ", ") + (dir.empty() ? "." : dir);
    return failure(fmt::format("'{}' is in none of {} (-I DIR adds a directory)", header, searched));
}

FileIncluder::IncludeResult* FileIncluder::read(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return failure(fmt::format("'{}' is not a regular file", path));
    const uintmax_t size = fs::file_size(path, ec);
    if (ec || size > bytes_left_)
        return failure(fmt::format("'{}' would take the stage's sources past glslrun's limit of 1 MiB together", path));
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) return failure(fmt::format("cannot read '{}'", path));
    bytes_left_ -= size_t(size);
    texts_.push_back(prepare_(text.str()));
    return new IncludeResult(path, texts_.back().data(), texts_.back().size(), nullptr);
}

}  // namespace glslrun::frontend
