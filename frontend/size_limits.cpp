#include "frontend/size_limits.h"

#include <set>

#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

class SizeChecker : public gl::TIntermTraverser {
public:
    SizeChecker(const std::string& file, std::vector<Diagnostic>& out) : file_(file), out_(out) {}

    void visitSymbol(gl::TIntermSymbol* s) override {
        if (!seen_.insert(s->getId()).second) return;
        uint64_t n = components_of(s->getType());
        if (n <= kMaxVariableComponents) return;
        out_.push_back(Diagnostic{file_, s->getLoc().line,
                                  fmt::format("'{}' : {} components is more than glslrun's limit of {} per variable",
                                              s->getName().c_str(), n, kMaxVariableComponents),
                                  false});
    }

private:
    const std::string& file_;
    std::vector<Diagnostic>& out_;
    std::set<long long> seen_;
};

}  // namespace

void check_size_limits(gl::TIntermediate& unit, const std::string& file, std::vector<Diagnostic>& out) {
    if (!unit.getTreeRoot()) return;
    SizeChecker checker(file, out);
    unit.getTreeRoot()->traverse(&checker);
}

}  // namespace glslrun::frontend
