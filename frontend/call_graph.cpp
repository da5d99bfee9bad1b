// The call graph corrections (call_graph.h). glslang keeps its call graph in a protected
// member of TIntermediate; a pointer to member taken in a derived class is
// the one legal way to reach it.
#include "frontend/call_graph.h"

#include <map>
#include <set>
#include <string>

#include <glslang/MachineIndependent/localintermediate.h>

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

struct CallGraphAccess : gl::TIntermediate {
    static constexpr auto member = &CallGraphAccess::callGraph;
};

// Callees that a function body calls outside dead branches.
class LiveCalls : public gl::TIntermTraverser {
public:
    std::set<std::string> callees;

    bool visitAggregate(gl::TVisit, gl::TIntermAggregate* n) override {
        if (n->getOp() == gl::EOpFunctionCall) callees.insert(n->getName().c_str());
        return true;
    }
    bool visitSelection(gl::TVisit, gl::TIntermSelection* n) override {
        int branch = constant_branch(*n);
        if (branch < 0) return true;
        if (TIntermNode* live = branch ? n->getTrueBlock() : n->getFalseBlock()) live->traverse(this);
        return false;
    }
};

}  // namespace

int constant_branch(const gl::TIntermSelection& n) {
    const gl::TIntermConstantUnion* c = n.getCondition()->getAsConstantUnion();
    if (!c || c->getConstArray().size() != 1 || c->getBasicType() != gl::EbtBool) return -1;
    return c->getConstArray()[0].getBConst() ? 1 : 0;
}

void prepare_call_graph(gl::TIntermediate& unit) {
    TIntermNode* root = unit.getTreeRoot();
    if (!root || !root->getAsAggregate()) return;
    std::map<std::string, std::set<std::string>> live;  // caller -> callees
    LiveCalls global_initializers;
    for (TIntermNode* child : root->getAsAggregate()->getSequence()) {
        gl::TIntermAggregate* fn = child->getAsAggregate();
        if (fn && fn->getOp() == gl::EOpLinkerObjects) continue;
        if (!fn || fn->getOp() != gl::EOpFunction) {
            child->traverse(&global_initializers);
            continue;
        }
        LiveCalls walk;
        fn->traverse(&walk);
        live[fn->getName().c_str()] = std::move(walk.callees);
    }
    auto& graph = unit.*CallGraphAccess::member;
    graph.remove_if([&](const gl::TCall& call) {
        auto body = live.find(call.caller.c_str());
        return body != live.end() && !body->second.count(call.callee.c_str());
    });
    // Global initializers run before main: what they call is reachable.
    for (const std::string& callee : global_initializers.callees)
        graph.emplace_back(gl::TString(unit.getEntryPointMangledName().c_str()), gl::TString(callee.c_str()));
}

}  // namespace glslrun::frontend
