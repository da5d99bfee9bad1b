// A 2D or rectangle `tex` lookup in generated code. The call-out (the
// interpreter's `tex` kernel, runtime/tex_kernel.cpp) decodes the operand
// block, groups the lanes by unit, checks the texture's completeness and
// picks a sampler at every lookup: a fifth of a nine-tap post-process
// frame, as much as the JIT's own code for the shader (perf). Here the
// generated code tests that every lane names one unit and that the unit's
// texture has a one-pass sampler (runtime/sampling_direct.h), bound when
// the executor is made, and calls it with the coordinates and the lookup
// lanes; anything else (another unit per lane, a unit out of range, an
// incomplete texture, a mipmapped or a depth one) takes the call-out. The
// sampler is the one the kernel would pick, the default results the
// kernel's (a lane that skips its lookup reads 0), the write masked as
// Machine::write's: the bits are the call-out's
// (tests/runtime/jit_tex_direct_test.cpp).
#include "runtime/jit/codegen.h"

#include "runtime/backend.h"

namespace glslrun::rt::jit {

namespace {

// Whether an op's lookups go through sample_lanes()'s common rules to the
// one-pass sampler where the texture allows: 2D and rectangle colour
// lookups (a shadow lookup's texture is a depth one) outside Fast's GPU
// arithmetic.
bool direct_candidate(const ir::Instr& in, Precision precision, uint32_t fast_ops) {
    if (in.op != ir::Op::tex) return false;
    if (precision == Precision::Fast && (fast_ops & kFastTexture)) return false;
    const ir::TexInfo info = ir::TexInfo::decode(in.imm[2]);
    return (info.target == ir::TexTarget::T2D || info.target == ir::TexTarget::Rect) && !info.shadow;
}

}  // namespace

void bind_direct_samplers(const GLState::TextureUnit* units, DirectSampler* out) {
    for (size_t i = 0; i < kDirectSlots; ++i) out[i] = {};
    if (!units || !cpu_has_avx2()) return;
    for (uint32_t unit = 0; unit < uint32_t(kMaxTextureUnits); ++unit) {
        const auto& bound = units[unit].bound;
        out[direct_slot(unit, false)] = bind_direct(bound[size_t(ir::TexTarget::T2D)].get());
        out[direct_slot(unit, true)] = bind_direct(bound[size_t(ir::TexTarget::Rect)].get());
    }
}

bool Emitter::emit_tex_direct(const ir::Instr& in) {
    if (!avx2_ || !direct_candidate(in, precision_, fast_ops_)) return false;
    const bool rect = ir::TexInfo::decode(in.imm[2]).target == ir::TexTarget::Rect;
    llvm::BasicBlock* has_unit = new_block("tex_unit");
    llvm::BasicBlock* direct = new_block("tex_direct");
    llvm::BasicBlock* call_out = new_block("tex_call_out");
    llvm::BasicBlock* done = new_block("tex_done");

    // Every lane's unit is lane 0's (as the kernel's same_unit()), and a unit.
    llvm::Value* units = load_reg(in.src[0]);
    llvm::Value* unit = b_.CreateExtractElement(units, uint64_t(0));
    llvm::Value* same = b_.CreateICmpEQ(units, b_.CreateVectorSplat(kLanes, unit));
    llvm::Value* all_same = b_.CreateICmpEQ(b_.CreateBitCast(same, mask_int_), llvm::Constant::getAllOnesValue(mask_int_));
    llvm::Value* in_range = b_.CreateICmpULT(unit, b_.getInt32(uint32_t(kMaxTextureUnits)));
    b_.CreateCondBr(b_.CreateAnd(all_same, in_range), has_unit, call_out);

    // Its sampler: Context::direct[direct_slot(unit, rect)].run, null where none.
    b_.SetInsertPoint(has_unit);
    llvm::Value* table = b_.CreateLoad(ptr_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kDirectOffset));
    llvm::Value* slot_index = b_.CreateAdd(b_.CreateMul(b_.CreateZExt(unit, i64_), b_.getInt64(2)), b_.getInt64(rect));
    llvm::Value* slot = b_.CreateInBoundsGEP(
        b_.getInt8Ty(), table, b_.CreateMul(slot_index, b_.getInt64(sizeof(DirectSampler))));
    static_assert(offsetof(DirectSampler, run) == 0);
    llvm::Value* run = b_.CreateLoad(ptr_, slot);
    b_.CreateCondBr(b_.CreateIsNotNull(run), direct, call_out);

    b_.SetInsertPoint(direct);
    llvm::Value* lookups = b_.CreateAnd(
        load_mask(exec_), b_.CreateLoad(i64_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kLookupsOffset)));
    if constexpr (kLanes < 64) lookups = b_.CreateAnd(lookups, b_.getInt64(kAllLanes));
    // The coordinates and the results in the function's stack frame, not in
    // the register file; the lanes not looked up read 0 (fill_defaults()).
    llvm::IRBuilder<> entry(&fn_->getEntryBlock(), fn_->getEntryBlock().begin());
    auto* coord_type = llvm::ArrayType::get(f32_, kLanes);
    llvm::AllocaInst* s = entry.CreateAlloca(coord_type, nullptr, "tex_s");
    llvm::AllocaInst* t = entry.CreateAlloca(coord_type, nullptr, "tex_t");
    llvm::AllocaInst* out = entry.CreateAlloca(llvm::ArrayType::get(coord_type, ir::kTexResults), nullptr, "tex_out");
    for (llvm::AllocaInst* a : {s, t, out}) a->setAlignment(llvm::Align(64));
    const uint32_t block = in.imm[0];
    b_.CreateAlignedStore(load_float(block), s, llvm::Align(64));
    b_.CreateAlignedStore(load_float(block + 1), t, llvm::Align(64));
    auto channel = [&](uint32_t c) {
        return b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), out, uint64_t(c) * kLanes * sizeof(float));
    };
    for (uint32_t c = 0; c < ir::kTexResults; ++c) b_.CreateAlignedStore(splat_f(0.0f), channel(c), llvm::Align(64));
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, ptr_, i64_, ptr_}, false);
    b_.CreateCall(type, run, {slot, s, t, lookups, out});
    for (uint32_t c = 0; c < ir::kTexResults; ++c) {
        llvm::Value* v = b_.CreateAlignedLoad(vf32_, channel(c), llvm::Align(64));
        write_reg(in.dst + c, b_.CreateBitCast(v, vi32_), WriteMode::Blends, false);  // Machine::write's mask
    }
    b_.CreateBr(done);

    b_.SetInsertPoint(call_out);
    emit_call_out(in);
    b_.CreateBr(done);
    b_.SetInsertPoint(done);
    return true;
}

}  // namespace glslrun::rt::jit
