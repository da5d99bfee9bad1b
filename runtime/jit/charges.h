// The budget's charges, made fewer (runtime/jit/control.cpp). The
// interpreter charges a block's node count as it enters the block
// (run_block); the generated code made the same charge at the same point,
// a subtraction, a compare and a branch to a call, at every inlined
// function's entry (marble: 72 per fragment batch and octave loop, a fifth
// of its frame with LLVM's quick code generation, whose register allocator
// stores every live value at a block's end).
//
// Here the charges of the Scope blocks that every entry of an enclosing
// block reaches are made at once at that block's entry, when nothing
// between the two can fail, change the mask or write a shader output: the
// same total, and a run that runs out of budget in between stops with the
// same error, alive lanes and outputs, only earlier (what else it wrote
// is the JIT's locals, which nobody reads after a run).
#pragma once
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ir/ir.h"

namespace glslrun::rt::jit {

class Charges {
public:
    explicit Charges(const ir::Shader& shader);

    // What entering `block` charges in all: its own nodes, and the blocks
    // of the Scopes that every entry reaches through nodes that pass().
    // Those blocks are then charged() already.
    uint64_t on_entry(const ir::Block& block);
    bool charged(const ir::Block& block) const { return charged_.count(&block) != 0; }

private:
    // Whether, run under a nonzero mask, `node` leaves that mask as it found
    // it, cannot fail but in a charge, and writes no output: an instruction;
    // an If whose blocks hold no break, continue, return, discard, loop or
    // call; a Scope holding no discard, loop or call (its returns end it).
    bool passes(const ir::Node& node);
    bool writes_output(const ir::Instr& instr) const;

    std::vector<bool> output_;  // per register
    std::unordered_map<const ir::Node*, bool> passes_;
    std::unordered_set<const ir::Block*> charged_;
};

}  // namespace glslrun::rt::jit
