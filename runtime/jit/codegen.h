// The emitter of one shader's LLVM IR (runtime/jit/jit.h): control.cpp
// writes the functions, blocks and masks, alu.cpp the instructions.
#pragma once
#include <optional>
#include <vector>
#include <string>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

#include "ir/ir.h"
#include "runtime/jit/charges.h"
#include "runtime/jit/context.h"

namespace glslrun::rt::jit {

// How an op writes its destination, as the interpreter's kernel does:
// Honours ir::Instr::unmasked (the table's Alu ops, mov, konst, sel,
// uniform: every lane when set) or Blends under the mask always (ddx, ddy).
enum class WriteMode { Honours, Blends };

class Emitter {
public:
    // Kernels for the call-outs are picked for (precision, fast_ops, avx2);
    // their records go to `call_outs`, in the order of the indices the
    // generated code passes to run_call_out.
    Emitter(llvm::LLVMContext& context, llvm::Module& module, const ir::Shader& shader, Precision precision,
            uint32_t fast_ops, bool avx2, std::vector<CallOut>& call_outs);

    // Defines `name`, a ShaderFn running `block` (the main body, or the
    // prologue) as the interpreter's run() does: the run's call frame
    // changes nothing that anyone reads after it.
    void define(const std::string& name, const ir::Block& block);
    // Defines the functions that the Call nodes emitted so far call (and
    // those they call): after define().
    void define_functions();

private:
    // --- control.cpp: masks are i64 lane bits kept in allocas
    llvm::Value* load_mask(llvm::AllocaInst* slot);
    void store_mask(llvm::AllocaInst* slot, llvm::Value* v);
    llvm::Value* remaining(llvm::Value* entry);
    void branch_unless_active(llvm::BasicBlock* exit);
    void emit_block(const ir::Block& block, llvm::BasicBlock* exit);
    // False when the node ends the block for every lane (break, ...).
    bool emit_node(const ir::Node& node, llvm::BasicBlock* exit);
    void emit_if(const ir::Node& node);
    void emit_loop(const ir::Node& node);
    void emit_call(const ir::Block& body);
    void emit_function_call(uint32_t callee);
    llvm::Function* function(uint32_t callee);
    void define_function(uint32_t callee);
    void start_function();
    void emit_failure(Failure failure, int line);
    void begin_budget(llvm::Value* credit);
    void open_masks(llvm::Value* exec, llvm::Value* alive, llvm::Value* loop_left);
    void end_budget();
    void charge(uint64_t instructions);
    llvm::BasicBlock* new_block(const char* name);

    // --- alu.cpp: one instruction
    void emit_instr(const ir::Instr& in);
    bool emit_native(const ir::Instr& in, llvm::Value** result);
    llvm::Value* emit_float_op(ir::Op op, llvm::Value* a, llvm::Value* b, llvm::Value* c);
    llvm::Value* first_operand_op(bool multiply, llvm::Value* a, llvm::Value* b, llvm::Value* c = nullptr);
    llvm::Value* fused_multiply_add(llvm::Value* a, llvm::Value* b, llvm::Value* c);
    llvm::Value* join_parts(std::vector<llvm::Value*> parts);
    static bool non_nan_constant(llvm::Value* v);  // a float vector constant without NaNs
    static bool at_most_one_nan(llvm::Value* a, llvm::Value* b);  // a, b cannot be two different NaNs
    llvm::Constant* exact_reciprocal(llvm::Value* b);
    llvm::Value* emit_int_op(ir::Op op, llvm::Value* a, llvm::Value* b);
    llvm::Value* emit_compare(ir::Op op, llvm::Value* a, llvm::Value* b);
    llvm::Value* emit_conversion(ir::Op op, llvm::Value* a);
    llvm::Value* emit_derivative(ir::Op op, llvm::Value* a);
    llvm::Value* element_index(const ir::Instr& in);  // kLanes x i32
    llvm::Value* register_lanes(llvm::Value* regs);     // kLanes x ptr
    void emit_precise_pow(const ir::Instr& in);
    void emit_call_out(const ir::Instr& in);
    // tex_direct.cpp: a 2D or rectangle lookup that calls its unit's
    // one-pass sampler where it has one; false where the op is not one.
    bool emit_tex_direct(const ir::Instr& in);
    llvm::Value* reg_ptr(ir::Reg r);   // its local, or file_ptr(r)
    llvm::Value* file_ptr(ir::Reg r);  // in the register file
    llvm::Value* load_reg(ir::Reg r);  // kLanes x i32
    llvm::Value* load_float(ir::Reg r);
    void write_reg(ir::Reg r, llvm::Value* words, WriteMode mode, bool unmasked);
    llvm::Value* exec_lanes();  // kLanes x i1 of the exec mask
    llvm::Value* ftz(llvm::Value* v);
    llvm::Value* as_bool(llvm::Value* words);  // kLanes x i1: word != 0
    llvm::Value* from_bool(llvm::Value* lanes);  // kLanes x i32: 0 or 1
    llvm::Value* splat_f(float v);
    llvm::Value* splat_i(uint32_t v);
    llvm::Value* call_intrinsic(unsigned id, std::initializer_list<llvm::Value*> args);

    llvm::LLVMContext& ctx_;
    llvm::Module& module_;
    llvm::IRBuilder<> b_;
    const ir::Shader& shader_;
    Precision precision_;
    uint32_t fast_ops_;
    bool avx2_;
    std::vector<CallOut>& call_outs_;

    llvm::Type* i1_;
    llvm::Type* i32_;
    llvm::Type* i64_;
    llvm::Type* f32_;
    llvm::FixedVectorType* vi32_;
    llvm::FixedVectorType* vf32_;
    llvm::Type* ptr_;
    llvm::Type* mask_int_;  // iN, N = kLanes

    // Per function being defined.
    llvm::Function* fn_ = nullptr;
    llvm::Value* ctx_arg_ = nullptr;
    llvm::Value* regs_ = nullptr;
    llvm::Value* uniforms_ = nullptr;
    // The registers that only the function being defined reads and writes
    // (not the bindings, the prologue's, indexed arrays, nor those of other
    // functions): an alloca each, which SROA turns into values, so that they
    // are never stored (call-outs and calls excepted); null for those kept
    // in the register file. A "unit" is the main body (0) or functions[f]
    // (f + 1), each one LLVM function; the prologue has no locals.
    std::vector<llvm::AllocaInst*> locals_;
    std::vector<int32_t> owner_;  // per register: its unit, or kShared
    void find_owners();
    void make_locals(int32_t unit);
    // The LLVM function of each ir::Function (null until called), and those
    // declared but not yet defined.
    std::vector<llvm::Function*> functions_;
    std::vector<uint32_t> undefined_;
    // Per function being defined: a call's frame (CallFrame, control.cpp).
    llvm::AllocaInst* call_frame_ = nullptr;
    // The main body's reads of a prologue `konst` that nothing else writes:
    // its value, which LLVM sees (a division by a power of two becomes a
    // multiplication, alu.cpp) instead of a load from the register file.
    std::vector<std::optional<uint32_t>> constants_;
    void find_constants();
    llvm::AllocaInst* exec_ = nullptr;
    llvm::AllocaInst* alive_ = nullptr;
    llvm::AllocaInst* brk_ = nullptr;
    llvm::AllocaInst* cont_ = nullptr;
    llvm::AllocaInst* ret_ = nullptr;
    llvm::AllocaInst* loop_left_ = nullptr;
    llvm::AllocaInst* credit_ = nullptr;
    llvm::AllocaInst* budget_failure_ = nullptr;
    llvm::BasicBlock* over_budget_ = nullptr;  // where charge()'s failures return
    Charges charges_{shader_};  // which blocks' charges an enclosing block's entry makes
};

}  // namespace glslrun::rt::jit
