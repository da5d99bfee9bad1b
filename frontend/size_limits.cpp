#include "frontend/size_limits.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

class SizeChecker : public gl::TIntermTraverser {
public:
    SizeChecker(const std::string& file, uint64_t& stage_components, std::vector<Diagnostic>& out)
        : file_(file), stage_components_(stage_components), out_(out) {}

    void visitSymbol(gl::TIntermSymbol* s) override {
        if (!seen_.insert(s->getId()).second) return;
        uint64_t n = components_of(s->getType());
        bool was_within = stage_components_ <= kMaxStageComponents;
        stage_components_ = std::min(stage_components_ + n, kMaxStageComponents + 1);
        if (n <= kMaxVariableComponents) {
            if (was_within && stage_components_ > kMaxStageComponents)
                out_.push_back(Diagnostic{file_, s->getLoc().line,
                                          fmt::format("'{}' : the stage's variables hold more than {} components "
                                                      "together, glslrun's limit (docs/limits.md)",
                                                      s->getName().c_str(), kMaxStageComponents),
                                          false});
            return;
        }
        out_.push_back(Diagnostic{file_, s->getLoc().line,
                                  fmt::format("'{}' : {} components is more than glslrun's limit of {} per variable",
                                              s->getName().c_str(), n, kMaxVariableComponents),
                                  false});
    }

private:
    const std::string& file_;
    uint64_t& stage_components_;
    std::vector<Diagnostic>& out_;
    std::set<long long> seen_;
};

}  // namespace

void check_size_limits(gl::TIntermediate& unit, const std::string& file, uint64_t& stage_components,
                       std::vector<Diagnostic>& out) {
    if (!unit.getTreeRoot()) return;
    SizeChecker checker(file, stage_components, out);
    unit.getTreeRoot()->traverse(&checker);
}

}  // namespace glslrun::frontend
