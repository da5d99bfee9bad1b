// Rules glslang 12 accepts but GLSL 1.10/1.20 (as Mesa enforces them) do not,
// each found by a piglit compiler test that must fail to compile
// (tests/frontend/unit_checks_test.cpp tests them).
#include "frontend/unit_checks.h"

#include <map>

#include <fmt/format.h>

#include "frontend/declaration_checks.h"
#include "frontend/source_rewrite.h"

namespace glslrun::frontend {
namespace {

namespace gl = glslang;

constexpr int kMaxTextureCoords = 8;  // matches resources() in glslang_driver.cpp

bool is_output_param(gl::TStorageQualifier q) { return q == gl::EvqOut || q == gl::EvqInOut; }

// The variable an l-value writes to, through indices, fields and swizzles.
gl::TIntermSymbol* written_symbol(gl::TIntermTyped* n) {
    while (n) {
        if (gl::TIntermSymbol* s = n->getAsSymbolNode()) return s;
        gl::TIntermBinary* b = n->getAsBinaryNode();
        if (!b) return nullptr;
        gl::TOperator op = b->getOp();
        if (op != gl::EOpIndexDirect && op != gl::EOpIndexIndirect && op != gl::EOpIndexDirectStruct &&
            op != gl::EOpVectorSwizzle)
            return nullptr;
        n = b->getLeft();
    }
    return nullptr;
}

bool is_assignment(gl::TOperator op) { return op >= gl::EOpAssign && op <= gl::EOpRightShiftAssign; }

class RuleChecker : public gl::TIntermTraverser {
public:
    RuleChecker(gl::TIntermediate& unit, const std::string& file, std::vector<Diagnostic>& out)
        : unit_(unit), file_(file), out_(out) {}

    void finish() {
        if (frag_color_line_ && frag_data_line_)
            error(std::max(frag_color_line_, frag_data_line_),
                  "fragment shader writes to both 'gl_FragColor' and 'gl_FragData'");
    }

    bool visitAggregate(gl::TVisit, gl::TIntermAggregate* n) override {
        if (n->getOp() == gl::EOpFunction) check_function(n);
        if (n->getOp() == gl::EOpFunctionCall) {
            note_operand(n, n->getType());
            const gl::TQualifierList& quals = n->getQualifierList();
            const gl::TIntermSequence& args = n->getSequence();
            for (size_t i = 0; i < args.size() && i < quals.size(); ++i)
                if (is_output_param(quals[i]) && args[i]->getAsTyped())
                    note_write(written_symbol(args[i]->getAsTyped()), args[i]->getLoc().line);
        }
        return true;
    }

    void visitSymbol(gl::TIntermSymbol* n) override { note_operand(n, n->getType()); }

    bool visitBinary(gl::TVisit, gl::TIntermBinary* n) override {
        if (is_assignment(n->getOp())) note_write(written_symbol(n->getLeft()), n->getLoc().line);
        if (n->getOp() == gl::EOpIndexDirect) check_constant_index(n);
        return true;
    }

    // GLSL 1.10 §5.2: [] is the only operator on arrays, so ?: cannot
    // choose between arrays (1.20 allows it; glslang allows it in 1.10).
    bool visitSelection(gl::TVisit, gl::TIntermSelection* n) override {
        if (n->getType().isArray() && unit_.getVersion() < 120)
            error(n->getLoc().line, "'?:' : the operands cannot be arrays in GLSL 1.10");
        return true;
    }

    bool visitUnary(gl::TVisit, gl::TIntermUnary* n) override {
        gl::TOperator op = n->getOp();
        if (op == gl::EOpPostIncrement || op == gl::EOpPostDecrement || op == gl::EOpPreIncrement ||
            op == gl::EOpPreDecrement)
            note_write(written_symbol(n->getOperand()), n->getLoc().line);
        return true;
    }

private:
    void error(int line, const std::string& message) { out_.push_back(Diagnostic{file_, line, message, false}); }

    // GLSL 1.10 §6.1: no array parameters that are out or inout (1.20 allows
    // them). §4.1.7: samplers only as uniforms or in parameters, so neither a
    // struct holding one.
    void check_function(gl::TIntermAggregate* def) {
        std::string name = def->getName().c_str();
        name = name.substr(0, name.find('('));
        if (def->getType().containsSampler())
            error(def->getLoc().line, fmt::format("'{}' : function cannot return a sampler or a structure containing one", name));
        const gl::TIntermSequence& seq = def->getSequence();
        if (seq.empty() || !seq[0]->getAsAggregate()) return;
        for (TIntermNode* p : seq[0]->getAsAggregate()->getSequence()) {
            gl::TIntermSymbol* sym = p->getAsSymbolNode();
            if (!sym) continue;
            const gl::TType& t = sym->getType();
            if (!is_output_param(t.getQualifier().storage)) continue;
            std::string pname = sym->getName().c_str();
            if (t.isArray() && unit_.getVersion() < 120)
                error(sym->getLoc().line,
                      fmt::format("'{}' : array parameters cannot be out or inout in GLSL 1.10", pname));
            if (t.containsSampler())
                error(sym->getLoc().line,
                      fmt::format("'{}' : a sampler or a structure containing one cannot be an out or inout parameter", pname));
        }
    }

    // Constant indices must be inside the array; glslang misses it when the
    // array is sized after the access (an implicit size redeclared smaller),
    // and for gl_TexCoord, which may only be sized up to gl_MaxTextureCoords.
    void check_constant_index(gl::TIntermBinary* n) {
        const gl::TType& t = n->getLeft()->getType();
        gl::TIntermConstantUnion* c = n->getRight()->getAsConstantUnion();
        if (!t.isArray() || !c || c->getConstArray().size() < 1) return;
        int index = c->getConstArray()[0].getIConst();
        gl::TIntermSymbol* sym = n->getLeft()->getAsSymbolNode();
        int limit = t.isUnsizedArray() ? -1 : t.getOuterArraySize();
        if (sym && sym->getName() == "gl_TexCoord") limit = kMaxTextureCoords;
        if (limit >= 0 && index >= limit)
            error(n->getLoc().line, fmt::format("array index {} out of range: '{}' has {} elements", index,
                                                sym ? sym->getName().c_str() : "array", limit));
    }

    void note_write(gl::TIntermSymbol* sym, int line) {
        if (!sym || unit_.getStage() != EShLangFragment) return;
        if (sym->getName() == "gl_FragColor" && !frag_color_line_) frag_color_line_ = line;
        if (sym->getName() == "gl_FragData" && !frag_data_line_) frag_data_line_ = line;
    }

public:
    // Typed nodes that a unary `+` may apply to, by source position.
    std::map<std::pair<int, int>, const gl::TType*> operand_types;

private:
    void note_operand(TIntermNode* n, const gl::TType& type) {
        const gl::TSourceLoc& loc = n->getLoc();
        operand_types.emplace(std::make_pair(loc.line, loc.column), &type);
    }

    gl::TIntermediate& unit_;
    const std::string& file_;
    std::vector<Diagnostic>& out_;
    int frag_color_line_ = 0, frag_data_line_ = 0;
};

// glslang drops a unary `+` without checking its operand: find the operand
// by its position (glslang's columns are 1-based; ours are 0-based).
void check_unary_plus(const RuleChecker& checker, const std::string& text, const std::string& file,
                      std::vector<Diagnostic>& out) {
    for (const UnaryPlusOperand& op : unary_plus_operands(text)) {
        for (int col : {op.pos.column + 1, op.pos.column}) {
            auto it = checker.operand_types.find({op.pos.line, col});
            if (it == checker.operand_types.end()) continue;
            const gl::TType& t = *it->second;
            if (t.isArray() || t.getBasicType() == gl::EbtVoid || t.isStruct())
                out.push_back(Diagnostic{file, op.pos.line,
                                         fmt::format("'+' : wrong operand type: unary '+' takes a scalar, vector or "
                                                     "matrix, not {}",
                                                     t.isArray() ? "an array" : t.isStruct() ? "a structure" : "void"),
                                         false});
            break;
        }
    }
}

}  // namespace

void check_unit_rules(glslang::TIntermediate& unit, const std::string& text, const std::string& file,
                      std::vector<Diagnostic>& out) {
    TIntermNode* root = unit.getTreeRoot();
    if (!root) return;
    RuleChecker checker(unit, file, out);
    root->traverse(&checker);
    checker.finish();
    check_unary_plus(checker, text, file, out);
    check_declarations(unit, text, file, out);
    // glslang takes the first component of a vector array size (or index).
    for (int line : stringification_lines(text))
        out.push_back(Diagnostic{file, line, "'#' : the stringification operator is not supported in GLSL", false});
    for (const DirectiveProblem& d : directive_problems(text)) out.push_back(Diagnostic{file, d.line, d.message, false});
    for (const TokenPos& p : vector_constructor_subscripts(text))
        out.push_back(Diagnostic{file, p.line, "array size or index must be a scalar integer expression", false});
}

}  // namespace glslrun::frontend
