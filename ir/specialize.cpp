// Specialization on uniforms: a copy of an optimized shader in which the
// uniform words of one draw are constants. The prologue (uniform code that
// ran once for all lanes) joins the front of the body as unmasked
// instructions, which compute the same words in every lane; then fold sees
// every uniform read as its word and folds what depends on uniforms alone
// (dead branches too), dce drops what is no longer read, and hoist moves
// what is left of the uniform code back into the prologue. Fold evaluates
// the opcode table's expressions, as the kernels do, so the bits are the
// unspecialized shader's; in Precision::Fast the ops that Fast approximates
// are left to the run time's kernels (`approximated`).
#include "ir/passes.h"

namespace glslrun::ir {

namespace {

constexpr int kMaxRounds = 3;

void collect_reads(const Block& block, std::vector<bool>& read) {
    auto mark = [&](uint32_t w) {
        if (w >= read.size()) read.resize(size_t(w) + 1);
        read[w] = true;
    };
    for (const Node& n : block) {
        if (n.kind == NodeKind::Instr && n.instr.op == Op::uniform) mark(n.instr.imm[0]);
        if (n.kind == NodeKind::Instr && n.instr.op == Op::uniform_ind)
            for (uint32_t i = 0; i < n.instr.imm[1]; ++i) mark(n.instr.imm[0] + i * n.instr.imm[2]);
        collect_reads(n.body, read);
        collect_reads(n.alt, read);
    }
}

}  // namespace

std::vector<uint32_t> uniform_words_read(const Shader& shader) {
    std::vector<bool> read;
    collect_reads(shader.prologue, read);
    collect_reads(shader.body, read);
    for (const Function& f : shader.functions) collect_reads(f.body, read);
    std::vector<uint32_t> words;
    for (uint32_t w = 0; w < read.size(); ++w)
        if (read[w]) words.push_back(w);
    return words;
}

std::string specialize(Shader& shader, const std::vector<uint32_t>& uniforms, uint32_t approximated) {
    for (Node& n : shader.prologue) n.instr.unmasked = true;
    shader.body.insert(shader.body.begin(), std::make_move_iterator(shader.prologue.begin()),
                       std::make_move_iterator(shader.prologue.end()));
    shader.prologue.clear();
    const FoldOptions options{&uniforms, approximated};
    std::string error;
    auto check = [&](const char* pass) {
        if (error.empty() && !(error = verify(shader)).empty()) error = std::string("after ") + pass + ": " + error;
        return error.empty();
    };
    for (int round = 0; round < kMaxRounds; ++round) {
        const std::string before = print(shader);
        fold_constants(shader, options);
        if (!check("fold")) return error;
        eliminate_dead_code(shader);
        if (!check("dce")) return error;
        if (print(shader) == before) break;
    }
    hoist_uniform_code(shader);
    if (!check("hoist")) return error;
    eliminate_dead_code(shader);
    check("dce");
    return error;
}

}  // namespace glslrun::ir
