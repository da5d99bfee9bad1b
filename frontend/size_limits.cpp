#include "frontend/size_limits.h"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

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
        if (stage_.calls < kMaxStageCalls)
            stage_.call_sites.push_back({caller_, n->getName().c_str(), file_, n->getLoc().line});
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

// The longest chain of calls from each function, in calls; memoised, and
// a function met again while its own chain is being measured (a cycle)
// counts as a leaf. Iterative: a chain may be thousands deep.
class CallChains {
public:
    explicit CallChains(const std::vector<CallSite>& sites) {
        for (const CallSite& s : sites) callees_[s.caller].push_back(&s);
    }
    // The deepest call out of `function` (null for a leaf) and the chain's length.
    std::pair<const CallSite*, uint64_t> deepest(const std::string& function) {
        if (!done_.count(function)) measure(function);
        return best_[function];
    }

private:
    void measure(const std::string& root) {
        struct Frame { const std::string* function; size_t next; };
        std::vector<Frame> stack{{&root, 0}};
        best_[root] = {nullptr, 0};
        while (!stack.empty()) {
            Frame& f = stack.back();
            auto found = callees_.find(*f.function);
            const size_t count = found == callees_.end() ? 0 : found->second.size();
            if (f.next == count) {
                done_.insert(*f.function);
                stack.pop_back();
                continue;
            }
            const CallSite* call = found->second[f.next++];
            if (!best_.count(call->callee)) {  // first visit: measure it before taking its length
                best_[call->callee] = {nullptr, 0};
                --stack.back().next;
                stack.push_back({&call->callee, 0});
                continue;
            }
            // Measured, or on the stack (a cycle: glslang's link reports it).
            uint64_t length = done_.count(call->callee) ? best_[call->callee].second + 1 : 1;
            auto& mine = best_[*f.function];
            if (length > mine.second) mine = {call, length};
        }
    }

    std::unordered_map<std::string, std::vector<const CallSite*>> callees_;
    std::unordered_map<std::string, std::pair<const CallSite*, uint64_t>> best_;
    std::unordered_set<std::string> done_;
};

std::string plain_name(const std::string& mangled) { return mangled.substr(0, mangled.find('(')); }

}  // namespace

void check_call_chain(const StageTotals& stage, std::vector<Diagnostic>& out) {
    CallChains chains(stage.call_sites);
    auto [call, length] = chains.deepest("main(");
    if (length <= kMaxCallChain) return;
    // Down the longest chain to the call that crosses the limit.
    for (uint64_t depth = 1; depth <= kMaxCallChain; ++depth) call = chains.deepest(call->callee).first;
    out.push_back(Diagnostic{call->file, call->line,
                             fmt::format("'{}' : calls nest {} deep from main, more than glslrun's limit of {} "
                                         "(docs/limits.md)",
                                         plain_name(call->callee), length, kMaxCallChain),
                             false});
}

void check_size_limits(gl::TIntermediate& unit, const std::string& file, StageTotals& stage,
                       std::vector<Diagnostic>& out) {
    if (!unit.getTreeRoot()) return;
    SizeChecker checker(file, stage, out);
    unit.getTreeRoot()->traverse(&checker);
}

}  // namespace glslrun::frontend
