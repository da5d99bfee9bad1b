// The flat list of IR passes, one file each, named after the pass (QBE style).
// optimize() runs them in order and, with PassOptions::verify, the verifier
// after every pass.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "ir/ir.h"

namespace glslrun::ir {

// ir/verify.cpp: structural checks. Returns "" when the shader is well formed,
// else a description of the first problem (an internal bug, never user error).
std::string verify(const Shader& shader);

// ir/helper_lookups.cpp: whether a helper lane's texture lookup can change
// a fragment's result (a derivative or a branch reads a value computed from
// a lookup); optimize() records it in Shader::helper_lookups_matter.
bool helper_lookups_matter(const Shader& shader);

// ir/print.cpp: the text form used by --dump-ir and the golden tests.
std::string print(const Shader& shader);
std::string print(const Program& program);

// CompileOptions::check_undefined, before optimize(): check_undef before the
// reads of variables that may be read before any write (ir/unwritten_reads.cpp).
void check_unwritten_reads(Shader& shader);

// ir/inline.cpp: replaces Call nodes by Scope nodes holding a renamed copy of
// the callee while the shader grows by less than `budget` nodes; the calls
// beyond the budget, and those to large functions that main reaches more
// than once, stay real calls.
void inline_calls(Shader& shader, uint32_t budget);
// ir/unroll.cpp: a loop of the frontend's shape whose trip count is a
// constant of at most 8 becomes that many copies of its body (the shader
// grows by at most 2000 nodes), so that fold sees its counter as constants.
void unroll_loops(Shader& shader);
// ir/fold.cpp: evaluates Alu instructions whose operands are constants, using
// the opcode table's expressions; folds If on constant conditions. With
// `uniforms` (a specialization, ir/specialize.cpp) `uniform` reads fold to
// those words; ops of the FastClass bits in `approximated` are left alone
// (Precision::Fast computes them with other kernels at run time).
struct FoldOptions {
    const std::vector<uint32_t>* uniforms = nullptr;
    uint32_t approximated = 0;  // bit c - 1 for FastClass c
};
void fold_constants(Shader& shader, const FoldOptions& options = {});
// ir/copyprop.cpp: replaces reads of a register that holds a copy of another
// register (or constant) by the source, within straight-line code.
void propagate_copies(Shader& shader);
// ir/dce.cpp: removes instructions whose results are never read, and empty
// control flow.
void eliminate_dead_code(Shader& shader);

// ir/contract.cpp: the multiply-adds NVIDIA's compiler contracts become
// ffma/ffms/ffnma (one rounding in Precision::Fast, two in the others).
// Before fuse_mad. `display_copies` (the debugger's IR, which keeps every
// variable): a copy of a product into a variable's register that nothing
// reads is no read of the product, so the product contracts as in the
// optimized program, where that store is dead, while the variable still
// shows the rounded product.
void contract_multiply_add(Shader& shader, bool display_copies = false);
// ir/fuse_mad.cpp: an fmul whose only reader is an fadd/fsub in the same
// block becomes part of it (fmad, fmsub, fnmadd: the same two roundings).
void fuse_multiply_add(Shader& shader);
// ir/dead_stores.cpp: removes a write that the same straight-line code
// overwrites before any read.
void eliminate_dead_stores(Shader& shader);
// ir/hoist.cpp: moves instructions that depend only on uniforms and constants
// into Shader::prologue, where they run once per draw instead of per batch.
void hoist_uniform_code(Shader& shader);

// ir/sqrt_divisor.cpp: an fsqrt whose every read is an fdiv's divisor
// becomes fsqrt_divisor and those fdivs fdiv_by_sqrt (the same values,
// except in Fast mode: rsqrt and multiplies). After hoist and dce.
void mark_sqrt_divisors(Shader& shader);

// ir/regalloc.cpp: renumbers registers so that values with disjoint live
// ranges share one; the register file shrinks. Runs last.
void allocate_registers(Shader& shader);

// ir/specialize.cpp: `shader` (optimized) for one uniform store: its
// prologue joins the body, every uniform read of `uniforms` becomes a
// constant, and fold (leaving the `approximated` FastClass bits alone), dce
// and hoist run again, the verifier after each: dead branches go and
// uniform code folds away, with the same bits. "" or the verifier's message.
std::string specialize(Shader& shader, const std::vector<uint32_t>& uniforms, uint32_t approximated);
// The uniform store words that `shader` reads (uniform, uniform_ind): a
// specialization's key.
std::vector<uint32_t> uniform_words_read(const Shader& shader);

// ir/uniform_reads.cpp: sets Uniform::read on the leaves whose words some
// `uniform`/`uniform_ind` instruction of either shader reads (after
// optimization: GL's "active" uniforms, finer grained, per struct member).
void mark_read_uniforms(Program& program);

struct PassOptions {
    bool optimize = true;
    uint32_t inline_budget = 4000;
    bool verify = false;  // the verifier after every pass (CompileOptions::verify_ir)
};
// Runs the pipeline; returns "" or the verifier's message naming the pass.
std::string optimize(Shader& shader, const PassOptions& options);

}  // namespace glslrun::ir
