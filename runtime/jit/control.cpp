// The JIT's functions, blocks and execution masks: the interpreter's
// run_block / run_if / run_loop / run_call (runtime/interpreter.cpp) and
// ExecMask (runtime/exec_mask.h), written out as LLVM IR. Masks are i64 lane
// bits, as there; LLVM keeps them in registers (mem2reg).
//
// Where the interpreter skips code, so does the generated code, at the same
// points: a block is left as soon as no lane is active (at its start and
// after each control-flow node), so instructions run exactly where the
// interpreter runs them, and loop iterations are counted alike.
#include "runtime/jit/codegen.h"

#include <bit>
#include <cmath>

#include "ir/assigned.h"
#include "ir/flow.h"

#include <llvm/IR/Function.h>

namespace glslrun::rt::jit {

Emitter::Emitter(llvm::LLVMContext& context, llvm::Module& module, const ir::Shader& shader, Precision precision,
                 uint32_t fast_ops, bool avx2, std::vector<CallOut>& call_outs)
    : ctx_(context), module_(module), b_(context), shader_(shader), precision_(precision), fast_ops_(fast_ops),
      avx2_(avx2), call_outs_(call_outs) {
    i1_ = llvm::Type::getInt1Ty(ctx_);
    i32_ = llvm::Type::getInt32Ty(ctx_);
    i64_ = llvm::Type::getInt64Ty(ctx_);
    f32_ = llvm::Type::getFloatTy(ctx_);
    vi32_ = llvm::FixedVectorType::get(i32_, kLanes);
    vf32_ = llvm::FixedVectorType::get(f32_, kLanes);
    ptr_ = llvm::PointerType::get(ctx_, 0);
    mask_int_ = llvm::Type::getIntNTy(ctx_, kLanes);
}

llvm::BasicBlock* Emitter::new_block(const char* name) { return llvm::BasicBlock::Create(ctx_, name, fn_); }

llvm::Value* Emitter::load_mask(llvm::AllocaInst* slot) { return b_.CreateLoad(i64_, slot); }
void Emitter::store_mask(llvm::AllocaInst* slot, llvm::Value* v) { b_.CreateStore(v, slot); }

// ExecMask::remaining: entry & alive & ~brk & ~cont & ~ret.
llvm::Value* Emitter::remaining(llvm::Value* entry) {
    llvm::Value* left = b_.CreateOr(b_.CreateOr(load_mask(brk_), load_mask(cont_)), load_mask(ret_));
    return b_.CreateAnd(b_.CreateAnd(entry, load_mask(alive_)), b_.CreateNot(left));
}

void Emitter::branch_unless_active(llvm::BasicBlock* exit) {
    llvm::BasicBlock* next = new_block("active");
    b_.CreateCondBr(b_.CreateICmpNE(load_mask(exec_), b_.getInt64(0)), next, exit);
    b_.SetInsertPoint(next);
}

void Emitter::find_constants() {
    using namespace ir::flow;
    std::vector<int> writes(shader_.regs.size());
    auto count = [&](ir::Reg r) {
        if (r < writes.size()) writes[r] += 2;  // a binding's, too, is a write from outside
    };
    for (const auto* list : {&shader_.inputs, &shader_.outputs})
        for (const ir::Binding& b : *list)
            for (uint32_t i = 0; i < b.count; ++i) count(b.first + i);
    auto written = [&](const ir::Node& n) {
        if (n.kind == ir::NodeKind::Instr) for_each_write(n.instr, count);
    };
    walk(shader_.body, written);
    for (const ir::Function& f : shader_.functions) walk(f.body, written);
    constants_.assign(shader_.regs.size(), std::nullopt);
    walk(shader_.prologue, [&](const ir::Node& n) {
        if (n.kind == ir::NodeKind::Instr)
            for_each_write(n.instr, [&](ir::Reg r) {
                if (r < writes.size()) ++writes[r];
            });
    });
    // LLVM folds x * 1, x / 1, x - 0 and -0 - x to x or -x, which under
    // DAZ the CPU does not (a denormal x gives 0), nor for a signalling NaN
    // (quieted); it picks a NaN operand's NaN as it likes. Such floats stay
    // in the register file.
    auto foldable = [](ir::Kind kind, uint32_t word) {
        const float v = std::bit_cast<float>(word);
        return kind != ir::Kind::F32 || (std::isnormal(v) && std::fabs(v) != 1.0f);
    };
    for (const ir::Node& n : shader_.prologue)  // its top level runs for every lane
        if (n.kind == ir::NodeKind::Instr && n.instr.op == ir::Op::konst && n.instr.dst < constants_.size() &&
            foldable(shader_.regs[n.instr.dst], n.instr.imm[0]))
            constants_[n.instr.dst] = n.instr.imm[0];
    for (size_t r = 0; r < writes.size(); ++r)
        if (writes[r] != 1) constants_[r].reset();
}

namespace {
constexpr int32_t kNobody = -1, kShared = -2;
// What a call passes to its function and gets back (i64 fields of an
// alloca): the caller's exec mask on entry, the lanes alive, the loop
// iterations left and the budget's credit; the last three come back.
enum CallFrame : uint64_t { kFrameExec, kFrameAlive, kFrameLoopLeft, kFrameCredit, kFrameFields };
}  // namespace

void Emitter::find_owners() {
    using namespace ir::flow;
    owner_.assign(shader_.regs.size(), kNobody);
    auto claim = [&](ir::Reg r, int32_t unit) {
        if (r < owner_.size()) owner_[r] = owner_[r] == kNobody || owner_[r] == unit ? unit : kShared;
    };
    auto shared = [&](ir::Reg r) { claim(r, kShared); };
    for (const auto* list : {&shader_.inputs, &shader_.outputs})
        for (const ir::Binding& b : *list)
            for (uint32_t i = 0; i < b.count; ++i) shared(b.first + i);
    auto refs = [&](int32_t unit) {
        return [&claim, unit](const ir::Node& n) {
            auto mine = [&](ir::Reg r) { claim(r, unit); };
            for_each_read(n, mine);
            if (n.kind != ir::NodeKind::Instr) return;
            for_each_write(n.instr, mine);
            // Indexed arrays: gathers and scatters reach them through the
            // register file; a derivative reads its operand's other lanes too.
            if (reads_range(n.instr.op) || writes_range(n.instr.op))
                for_each_in_range(n.instr, [&](ir::Reg r) { claim(r, kShared); });
            if (ir::has(n.instr.op, ir::OpProp::CrossLane)) claim(n.instr.src[0], kShared);
        };
    };
    walk(shader_.prologue, refs(kShared));
    // A register that some lane may read before writing it sees what an
    // earlier run or call left in the register file: it stays there.
    const std::vector<bool> unset = ir::maybe_read_unset(shader_);
    for (size_t r = 0; r < unset.size() && r < owner_.size(); ++r)
        if (unset[r]) owner_[r] = kShared;
    walk(shader_.body, refs(0));
    for (size_t f = 0; f < shader_.functions.size(); ++f) walk(shader_.functions[f].body, refs(int32_t(f) + 1));
}

void Emitter::make_locals(int32_t unit) {
    locals_.clear();
    constants_.clear();
    if (unit < 0) return;  // the prologue writes the constants
    if (owner_.empty()) find_owners();
    find_constants();
    locals_.resize(shader_.regs.size());
    for (size_t r = 0; r < owner_.size(); ++r) {
        if (owner_[r] != unit) continue;
        // Starting from the register file's value: what a lane reads
        // before the body writes it is what the interpreter would read.
        llvm::Value* initial = load_reg(ir::Reg(r));
        locals_[r] = b_.CreateAlloca(vi32_, nullptr, "r" + std::to_string(r));
        b_.CreateStore(initial, locals_[r]);
    }
}

// The function's masks, as a call frame leaves them (ExecMask::call_begin):
// brk, cont and ret empty.
void Emitter::open_masks(llvm::Value* exec, llvm::Value* alive, llvm::Value* loop_left) {
    exec_ = b_.CreateAlloca(i64_, nullptr, "exec");
    alive_ = b_.CreateAlloca(i64_, nullptr, "alive");
    brk_ = b_.CreateAlloca(i64_, nullptr, "brk");
    cont_ = b_.CreateAlloca(i64_, nullptr, "cont");
    ret_ = b_.CreateAlloca(i64_, nullptr, "ret");
    loop_left_ = b_.CreateAlloca(i64_, nullptr, "loop_left");
    call_frame_ = b_.CreateAlloca(llvm::ArrayType::get(i64_, kFrameFields), nullptr, "call_frame");
    store_mask(exec_, exec);
    store_mask(alive_, alive);
    for (llvm::AllocaInst* m : {brk_, cont_, ret_}) store_mask(m, b_.getInt64(0));
    b_.CreateStore(loop_left, loop_left_);
}

void Emitter::define(const std::string& name, const ir::Block& block) {
    auto* type = llvm::FunctionType::get(i32_, {ptr_, ptr_, ptr_, i64_}, false);
    fn_ = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, module_);
    start_function();
    // The prologue runs once for all lanes (the executor passes kAllLanes,
    // as the interpreter's run_prologue): a constant mask, so LLVM drops its
    // writes' blends under the mask (a third of a vertex shader's code was them).
    llvm::Value* live = fn_->getArg(3);
    if (&block == &shader_.prologue) live = b_.getInt64(kAllLanes);

    b_.SetInsertPoint(new_block("entry"));
    make_locals(&block == &shader_.body ? 0 : kNobody);
    live = b_.CreateAnd(live, b_.getInt64(kAllLanes));
    // ExecMask::reset(live), then the run's call frame (call_begin).
    open_masks(live, live, b_.CreateLoad(i64_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kMaxLoopOffset)));
    begin_budget(b_.CreateLoad(i64_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kCreditOffset)));
    llvm::BasicBlock* done = new_block("done");
    emit_block(block, done);
    b_.CreateBr(done);
    b_.SetInsertPoint(done);
    b_.CreateStore(load_mask(alive_), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kAliveOffset));
    // The credit left, from which the executor reports the run's instructions to the draw's budget.
    b_.CreateStore(b_.CreateLoad(i64_, credit_), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kCreditOffset));
    b_.CreateRet(b_.getInt32(int32_t(Failure::None)));
    end_budget();
}

// The attributes and arguments every generated function shares: (ctx, regs,
// uniforms, and a last one of its own).
void Emitter::start_function() {
    // The executor runs with FTZ and DAZ set (ir::FlushDenormals): tell LLVM,
    // so that what it folds matches what the CPU computes.
    fn_->addFnAttr("denormal-fp-math", "preserve-sign,preserve-sign");
    fn_->addFnAttr("denormal-fp-math-f32", "preserve-sign,preserve-sign");
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    ctx_arg_ = fn_->getArg(0);
    regs_ = fn_->getArg(1);
    uniforms_ = fn_->getArg(2);
    fn_->addParamAttr(1, llvm::Attribute::NoAlias);
    fn_->addParamAttr(2, llvm::Attribute::NoAlias);
}

llvm::Function* Emitter::function(uint32_t callee) {
    if (functions_.empty()) functions_.resize(shader_.functions.size());
    if (!functions_[callee]) {
        auto* type = llvm::FunctionType::get(i32_, {ptr_, ptr_, ptr_, ptr_}, false);
        functions_[callee] = llvm::Function::Create(type, llvm::Function::InternalLinkage,
                                                    "glslrun_fn" + std::to_string(callee), module_);
        undefined_.push_back(callee);
    }
    return functions_[callee];
}

void Emitter::define_functions() {
    while (!undefined_.empty()) {
        const uint32_t f = undefined_.back();
        undefined_.pop_back();
        define_function(f);
    }
}

// functions[callee] as an LLVM function of its own, run as run_call runs it:
// its call frame's masks (the caller's brk, cont and ret do not reach it),
// the caller's alive lanes, loop count and credit in and out through the
// frame; a failure returns its code, which the caller returns too.
void Emitter::define_function(uint32_t callee) {
    fn_ = functions_[callee];
    start_function();
    fn_->addParamAttr(3, llvm::Attribute::NoAlias);
    fn_->addParamAttr(3, llvm::Attribute::NoCapture);
    llvm::Value* frame = fn_->getArg(3);
    auto field = [&](uint64_t i) { return b_.CreateConstInBoundsGEP1_64(i64_, frame, i); };
    b_.SetInsertPoint(new_block("entry"));
    make_locals(int32_t(callee) + 1);
    open_masks(b_.CreateLoad(i64_, field(kFrameExec)), b_.CreateLoad(i64_, field(kFrameAlive)),
               b_.CreateLoad(i64_, field(kFrameLoopLeft)));
    begin_budget(b_.CreateLoad(i64_, field(kFrameCredit)));
    llvm::BasicBlock* done = new_block("done");
    emit_block(shader_.functions[callee].body, done);
    b_.CreateBr(done);
    b_.SetInsertPoint(done);
    b_.CreateStore(load_mask(alive_), field(kFrameAlive));
    b_.CreateStore(b_.CreateLoad(i64_, loop_left_), field(kFrameLoopLeft));
    b_.CreateStore(b_.CreateLoad(i64_, credit_), field(kFrameCredit));
    b_.CreateRet(b_.getInt32(int32_t(Failure::None)));
    end_budget();
}

// A Call: the function's code is emitted once and called here. Only
// registers in the register file pass between the two (find_owners).
void Emitter::emit_function_call(uint32_t callee) {
    llvm::Function* target = function(callee);
    llvm::Value* entry = load_mask(exec_);
    auto field = [&](uint64_t i) { return b_.CreateConstInBoundsGEP2_64(call_frame_->getAllocatedType(), call_frame_, 0, i); };
    b_.CreateStore(entry, field(kFrameExec));
    b_.CreateStore(load_mask(alive_), field(kFrameAlive));
    b_.CreateStore(b_.CreateLoad(i64_, loop_left_), field(kFrameLoopLeft));
    b_.CreateStore(b_.CreateLoad(i64_, credit_), field(kFrameCredit));
    llvm::Value* failure = b_.CreateCall(target, {ctx_arg_, regs_, uniforms_, call_frame_});
    store_mask(alive_, b_.CreateLoad(i64_, field(kFrameAlive)));
    b_.CreateStore(b_.CreateLoad(i64_, field(kFrameLoopLeft)), loop_left_);
    b_.CreateStore(b_.CreateLoad(i64_, field(kFrameCredit)), credit_);
    llvm::BasicBlock* failed = new_block("call_failed");
    llvm::BasicBlock* returned = new_block("call_returned");
    b_.CreateCondBr(b_.CreateICmpNE(failure, b_.getInt32(0)), failed, returned);
    b_.SetInsertPoint(failed);
    b_.CreateRet(failure);  // the function stored alive and the line (emit_failure, end_budget)
    b_.SetInsertPoint(returned);
    store_mask(exec_, remaining(entry));  // ExecMask::call_end
}

// The run's budget (Context::credit), and the block that its failures
// (an Instructions or Cancelled code in budget_failure_) return from.
void Emitter::begin_budget(llvm::Value* credit) {
    credit_ = b_.CreateAlloca(i64_, nullptr, "credit");
    budget_failure_ = b_.CreateAlloca(i32_, nullptr, "budget_failure");
    b_.CreateStore(credit, credit_);
    over_budget_ = new_block("over_budget");
}

void Emitter::end_budget() {
    b_.SetInsertPoint(over_budget_);
    b_.CreateStore(load_mask(alive_), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kAliveOffset));
    b_.CreateStore(b_.getInt32(0), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kErrorLineOffset));
    b_.CreateRet(b_.CreateLoad(i32_, budget_failure_));
}

// The interpreter's charge() as a block of `instructions` nodes is entered:
// within the credit a subtraction; beyond it, charge_slowly().
void Emitter::charge(uint64_t instructions) {
    llvm::Value* credit = b_.CreateLoad(i64_, credit_);
    b_.CreateStore(b_.CreateSub(credit, b_.getInt64(instructions)), credit_);
    llvm::BasicBlock* slow = new_block("charge_slowly");
    llvm::BasicBlock* charged = new_block("charged");
    b_.CreateCondBr(b_.CreateICmpUGT(b_.getInt64(instructions), credit), slow, charged);
    b_.SetInsertPoint(slow);
    auto* type = llvm::FunctionType::get(i32_, {ptr_, i64_, i64_}, false);
    llvm::FunctionCallee callee = module_.getOrInsertFunction(kChargeSlowlySymbol, type);
    llvm::Value* failure = b_.CreateCall(callee, {ctx_arg_, credit, b_.getInt64(instructions)});
    b_.CreateStore(failure, budget_failure_);
    b_.CreateStore(b_.CreateLoad(i64_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kCreditOffset)), credit_);
    b_.CreateCondBr(b_.CreateICmpNE(failure, b_.getInt32(0)), over_budget_, charged);
    b_.SetInsertPoint(charged);
}

// Leaves the block on `exit` when no lane is active, as run_block does,
// and charges it there (with the blocks that entering it enters: Charges).
void Emitter::emit_block(const ir::Block& block, llvm::BasicBlock* exit) {
    branch_unless_active(exit);
    if (!block.empty() && !charges_.charged(block)) charge(charges_.on_entry(block));
    for (const ir::Node& node : block) {
        if (!emit_node(node, exit)) {
            b_.CreateBr(exit);
            b_.SetInsertPoint(new_block("dead"));  // the rest of the block never runs
            return;
        }
        if (node.kind != ir::NodeKind::Instr) branch_unless_active(exit);
    }
}

bool Emitter::emit_node(const ir::Node& node, llvm::BasicBlock* exit) {
    auto leave = [&](llvm::AllocaInst* into) {
        llvm::Value* exec = load_mask(exec_);
        if (into == alive_) store_mask(alive_, b_.CreateAnd(load_mask(alive_), b_.CreateNot(exec)));
        else store_mask(into, b_.CreateOr(load_mask(into), exec));
        store_mask(exec_, b_.getInt64(0));
        return false;
    };
    switch (node.kind) {
    case ir::NodeKind::Instr: emit_instr(node.instr); return true;
    case ir::NodeKind::If: emit_if(node); return true;
    case ir::NodeKind::Loop: emit_loop(node); return true;
    case ir::NodeKind::Break: return leave(brk_);
    case ir::NodeKind::Continue: return leave(cont_);
    case ir::NodeKind::Return: return leave(ret_);
    case ir::NodeKind::Discard: return leave(alive_);
    case ir::NodeKind::Call:
        if (node.callee >= shader_.functions.size()) {
            emit_failure(Failure::MissingFunction, node.loc.line);
            return true;
        }
        emit_function_call(node.callee);
        return true;
    case ir::NodeKind::Scope: emit_call(node.body); return true;
    }
    return true;
}

// ExecMask::if_push / if_else / if_pop around the two blocks.
void Emitter::emit_if(const ir::Node& node) {
    llvm::Value* entry = load_mask(exec_);
    llvm::Value* words = load_reg(node.cond);
    llvm::Value* cond = b_.CreateZExt(b_.CreateBitCast(as_bool(words), mask_int_), i64_);
    store_mask(exec_, b_.CreateAnd(entry, cond));
    llvm::BasicBlock* then_done = new_block("then_done");
    emit_block(node.body, then_done);
    b_.CreateBr(then_done);
    b_.SetInsertPoint(then_done);
    store_mask(exec_, remaining(b_.CreateAnd(entry, b_.CreateNot(cond))));
    llvm::BasicBlock* else_done = new_block("else_done");
    emit_block(node.alt, else_done);
    b_.CreateBr(else_done);
    b_.SetInsertPoint(else_done);
    store_mask(exec_, remaining(entry));
}

// ExecMask's loop frame; the iteration cap counts every iteration of every
// loop of the run, checked before each iteration as run_loop does.
void Emitter::emit_loop(const ir::Node& node) {
    llvm::Value* entry = load_mask(exec_);
    llvm::Value* saved_brk = load_mask(brk_);
    llvm::Value* saved_cont = load_mask(cont_);
    store_mask(brk_, b_.getInt64(0));
    store_mask(cont_, b_.getInt64(0));
    llvm::BasicBlock* header = new_block("loop");
    llvm::BasicBlock* capped = new_block("loop_capped");
    llvm::BasicBlock* body = new_block("loop_body");
    llvm::BasicBlock* body_done = new_block("loop_body_done");
    llvm::BasicBlock* alt_done = new_block("loop_continue_done");
    llvm::BasicBlock* end = new_block("loop_end");
    b_.CreateBr(header);

    b_.SetInsertPoint(header);
    llvm::Value* left = b_.CreateLoad(i64_, loop_left_);
    b_.CreateStore(b_.CreateSub(left, b_.getInt64(1)), loop_left_);
    b_.CreateCondBr(b_.CreateICmpEQ(left, b_.getInt64(0)), capped, body);
    b_.SetInsertPoint(capped);
    emit_failure(Failure::LoopCap, node.loc.line);
    b_.CreateUnreachable();

    b_.SetInsertPoint(body);
    emit_block(node.body, body_done);
    b_.CreateBr(body_done);
    b_.SetInsertPoint(body_done);
    store_mask(cont_, b_.getInt64(0));
    store_mask(exec_, remaining(entry));
    emit_block(node.alt, alt_done);
    b_.CreateBr(alt_done);
    b_.SetInsertPoint(alt_done);
    store_mask(cont_, b_.getInt64(0));
    llvm::Value* again = remaining(entry);
    store_mask(exec_, again);
    b_.CreateCondBr(b_.CreateICmpNE(again, b_.getInt64(0)), header, end);

    b_.SetInsertPoint(end);
    store_mask(brk_, saved_brk);
    store_mask(cont_, saved_cont);
    store_mask(exec_, remaining(entry));
}

// An inlined function's scope: Return ends it for the lanes that return
// (ExecMask::call_begin / call_end).
void Emitter::emit_call(const ir::Block& body) {
    llvm::Value* entry = load_mask(exec_);
    llvm::Value* saved[3] = {load_mask(brk_), load_mask(cont_), load_mask(ret_)};
    for (llvm::AllocaInst* m : {brk_, cont_, ret_}) store_mask(m, b_.getInt64(0));
    llvm::BasicBlock* done = new_block("call_done");
    emit_block(body, done);
    b_.CreateBr(done);
    b_.SetInsertPoint(done);
    store_mask(brk_, saved[0]);
    store_mask(cont_, saved[1]);
    store_mask(ret_, saved[2]);
    store_mask(exec_, remaining(entry));
}

// Returns from the function with `failure` (alive() as the interpreter
// leaves it); the insertion point is left in
// a fresh block that nothing reaches.
void Emitter::emit_failure(Failure failure, int line) {
    b_.CreateStore(load_mask(alive_), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kAliveOffset));
    b_.CreateStore(b_.getInt32(line), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kErrorLineOffset));
    b_.CreateRet(b_.getInt32(int32_t(failure)));
    b_.SetInsertPoint(new_block("after_failure"));
}

}  // namespace glslrun::rt::jit
