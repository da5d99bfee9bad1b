// `#include "name"` and `#include <name>` (GL_GOOGLE_include_directive, as
// glslangValidator reads them with -I DIR). Internal to frontend/.
#pragma once
#include <functional>
#include <list>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>

namespace glslrun::frontend {

// Included files nest at most this deep: a file that includes itself ends
// here with a message instead of growing until the source limit.
constexpr size_t kMaxIncludeDepth = 32;

// Finds an included file ("name" or <name>) beside the file that includes
// it, then in each of `dirs` in order. What it reads goes through
// `prepare` (the rewrites a unit's own text gets) and counts toward
// `bytes_left`, the stage's source limit (kMaxSourceBytes): a file that
// cannot be read, or one past the limit, ends the compile with glslang's
// "#include" error at the directive's line, our reason in it.
class FileIncluder : public glslang::TShader::Includer {
public:
    FileIncluder(std::string unit_file, std::vector<std::string> dirs, std::function<std::string(std::string)> prepare,
                 size_t& bytes_left);
    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
    void releaseInclude(IncludeResult* result) override;

private:
    IncludeResult* find(const std::string& header, const std::string& includer, size_t depth, bool local);
    IncludeResult* failure(std::string why);
    IncludeResult* read(const std::string& path);

    std::string unit_file_;
    std::vector<std::string> dirs_;
    std::function<std::string(std::string)> prepare_;
    size_t& bytes_left_;
    std::list<std::string> texts_;  // the results' text, alive until released (glslang keeps pointers)
};

}  // namespace glslrun::frontend
