// Which uniform leaves the optimized program really reads. glslang keeps a
// whole built-in array such as gl_LightSource[8] when a shader names element
// 0; deriving and uploading the other seven is wasted work per draw.
#include <algorithm>

#include "ir/passes.h"

namespace glslrun::ir {
namespace {

void mark_words(const Block& block, std::vector<bool>& read) {
    auto mark = [&](uint64_t first, uint64_t count) {
        for (uint64_t w = first; w < std::min<uint64_t>(first + count, read.size()); ++w) read[w] = true;
    };
    for (const Node& n : block) {
        if (n.kind == NodeKind::Instr && n.instr.op == Op::uniform) mark(n.instr.imm[0], 1);
        // uniforms[imm0 + clamp(i, 0, imm1 - 1) * imm2]: any element may be read.
        if (n.kind == NodeKind::Instr && n.instr.op == Op::uniform_ind && n.instr.imm[1] > 0)
            mark(n.instr.imm[0], uint64_t(n.instr.imm[1] - 1) * n.instr.imm[2] + 1);
        mark_words(n.body, read);
        mark_words(n.alt, read);
    }
}

}  // namespace

void mark_read_uniforms(Program& program) {
    std::vector<bool> read(program.uniform_words, false);
    for (const Shader* shader : {&program.vertex, &program.fragment}) {
        mark_words(shader->prologue, read);
        mark_words(shader->body, read);
        for (const Function& f : shader->functions) mark_words(f.body, read);
    }
    for (Uniform& u : program.uniforms) {
        uint32_t words = u.type.components() * u.array_size;
        u.read = std::any_of(read.begin() + std::min<size_t>(u.slot, read.size()),
                             read.begin() + std::min<size_t>(u.slot + words, read.size()),
                             [](bool b) { return b; });
    }
}

}  // namespace glslrun::ir
