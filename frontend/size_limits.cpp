#include "frontend/size_limits.h"

#include <algorithm>
#include <set>
#include <unordered_set>

#include <fmt/format.h>

#include "frontend/lower.h"

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

class SizeChecker : public gl::TIntermTraverser {
public:
    SizeChecker(const std::string& file, StageTotals& stage, std::vector<Diagnostic>& out)
        : file_(file), stage_(stage), out_(out) {}

    bool visitAggregate(gl::TVisit, gl::TIntermAggregate* n) override {
        if (n->getOp() == gl::EOpFunction) caller_ = n->getName().c_str();
        if (n->getOp() != gl::EOpFunctionCall || !calls_.insert(caller_ + '\n' + n->getName().c_str()).second)
            return true;
        if (++stage_.calls == kMaxStageCalls + 1)
            out_.push_back(Diagnostic{file_, n->getLoc().line,
                                      fmt::format("'{}' : the stage makes more than {} distinct calls (caller and "
                                                  "callee pairs), glslrun's limit (docs/limits.md)",
                                                  std::string(n->getName().c_str()).substr(0, n->getName().find('(')),
                                                  kMaxStageCalls),
                                      false});
        return true;
    }

    void visitSymbol(gl::TIntermSymbol* s) override {
        if (!seen_.insert(s->getId()).second) return;
        uint64_t n = components_of(s->getType());
        bool was_within = stage_.components <= kMaxStageComponents;
        stage_.components = std::min(stage_.components + n, kMaxStageComponents + 1);
        if (n <= kMaxVariableComponents) {
            if (was_within && stage_.components > kMaxStageComponents)
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
    StageTotals& stage_;
    std::vector<Diagnostic>& out_;
    std::set<long long> seen_;
    std::string caller_;
    std::unordered_set<std::string> calls_;
};

}  // namespace

void check_size_limits(gl::TIntermediate& unit, const std::string& file, StageTotals& stage,
                       std::vector<Diagnostic>& out) {
    if (!unit.getTreeRoot()) return;
    SizeChecker checker(file, stage, out);
    unit.getTreeRoot()->traverse(&checker);
}

}  // namespace glslrun::frontend
