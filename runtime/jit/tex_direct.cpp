// A 2D or rectangle `tex` lookup in generated code. The call-out (the
// interpreter's `tex` kernel, runtime/tex_kernel.cpp, run through
// run_call_out) decodes the operand block, groups the lanes by unit, checks
// the texture's completeness and picks a sampler at every lookup: with the
// register-file traffic around it, a fifth of a nine-tap post-process frame
// (perf). Here the generated code copies the units and the operand block
// into its stack frame and calls run_tex(), which, where every lane names
// one unit whose texture has a one-pass sampler (runtime/sampling_direct.h,
// or Fast's runtime/sampling_gpu_direct.h under its GPU filtering; bound
// when the executor is made), calls that sampler with the lookup
// lanes; anything else (another unit per lane, a unit out of range, an
// incomplete texture, a mipmapped or a depth one) runs the call-out's kernel
// over the copies. The sampler is the one the kernel would pick, the
// default results the kernel's (a lane that skips its lookup reads 0), the
// write masked as Machine::write's: the bits are the call-out's
// (tests/runtime/jit_tex_direct_test.cpp). One call and no branch per
// lookup in the generated code: LLVM's time stays the call-out's.
#include "runtime/jit/codegen.h"

#include "runtime/backend.h"
#include "runtime/fast_kernels.h"
#include "runtime/sampling_gpu_direct.h"

namespace glslrun::rt::jit {

namespace {

constexpr unsigned kRegAlign = kLanes * 4 < 64 ? kLanes * 4 : 64;  // as a register's (alu.cpp)

// Whether an op's lookups go to the one-pass sampler where the texture
// allows: 2D and rectangle colour lookups (a shadow lookup's texture is a
// depth one); Fast's GPU arithmetic has its own (bind_gpu_direct()).
bool direct_candidate(const ir::Instr& in) {
    if (in.op != ir::Op::tex) return false;
    const ir::TexInfo info = ir::TexInfo::decode(in.imm[2]);
    return (info.target == ir::TexTarget::T2D || info.target == ir::TexTarget::Rect) && !info.shadow;
}

}  // namespace

void bind_direct_samplers(const GLState::TextureUnit* units, bool gpu, DirectSampler* out) {
    for (size_t i = 0; i < kDirectSlots; ++i) out[i] = {};
    if (!units || !cpu_has_avx2()) return;
    for (uint32_t unit = 0; unit < uint32_t(kMaxTextureUnits); ++unit) {
        const auto& bound = units[unit].bound;
        const Texture* t2d = bound[size_t(ir::TexTarget::T2D)].get();
        out[direct_slot(unit, false)] = gpu ? bind_gpu_direct(t2d) : bind_direct(t2d);
        out[direct_slot(unit, true)] = bind_direct(bound[size_t(ir::TexTarget::Rect)].get());
    }
}

void run_tex(Context* ctx, uint64_t index, uint64_t exec, const uint32_t* units, const uint32_t* operands,
             uint32_t* out) {
    const Step<uint32_t>& call = ctx->call_steps[index];
    const uint32_t unit = units[0];
    uint32_t differ = 0;  // as the kernel's same_unit(): every lane, active or not
    for (int i = 0; i < kLanes; ++i) differ |= units[i] ^ unit;
    if (!differ && unit < uint32_t(kMaxTextureUnits) && ctx->direct) {
        const bool rect = ir::TexInfo::decode(call.imm[2]).target == ir::TexTarget::Rect;
        const DirectSampler& sampler = ctx->direct[direct_slot(unit, rect)];
        if (sampler.run) {
            auto* result = reinterpret_cast<float (*)[kLanes]>(out);
            const LaneMask lookups = exec & ctx->machine.lookups;
            // fill_defaults() of the lanes that skip their lookups (the
            // sampler writes the others): a third of this function when done
            // for every batch.
            if (lookups != kAllLanes)
                for (uint32_t c = 0; c < ir::kTexResults; ++c)
                    for (int i = 0; i < kLanes; ++i) result[c][i] = 0.0f;
            const auto* coord = reinterpret_cast<const float*>(operands);
            sampler.run(sampler, coord, coord + kLanes, lookups, result);
            return;
        }
    }
    Step<uint32_t> step = call;  // over the copies, not the register file
    step.src[0] = units;
    step.src[1] = operands;
    step.dst = out;
    ctx->machine.mask.reset(exec);
    step.fn(step, ctx->machine);
}

bool Emitter::emit_tex_direct(const ir::Instr& in) {
    if (!avx2_ || !direct_candidate(in)) return false;
    call_outs_.push_back({kernel_for(in.op, avx2_, precision_, fast_ops_), in});
    const uint32_t operands = ir::TexInfo::decode(in.imm[2]).operand_count();
    // The copies in the function's stack frame: the registers stay values.
    llvm::IRBuilder<> entry(&fn_->getEntryBlock(), fn_->getEntryBlock().begin());
    auto* words = llvm::ArrayType::get(i32_, kLanes);
    llvm::AllocaInst* units = entry.CreateAlloca(words, nullptr, "tex_units");
    llvm::AllocaInst* block = entry.CreateAlloca(llvm::ArrayType::get(words, operands), nullptr, "tex_operands");
    llvm::AllocaInst* out = entry.CreateAlloca(llvm::ArrayType::get(words, ir::kTexResults), nullptr, "tex_out");
    for (llvm::AllocaInst* a : {units, block, out}) a->setAlignment(llvm::Align(kRegAlign));
    auto row = [&](llvm::Value* base, uint32_t k) {
        return b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), base, uint64_t(k) * kLanes * sizeof(uint32_t));
    };
    b_.CreateAlignedStore(load_reg(in.src[0]), units, llvm::Align(kRegAlign));
    for (uint32_t k = 0; k < operands; ++k)
        b_.CreateAlignedStore(load_reg(in.imm[0] + k), row(block, k), llvm::Align(kRegAlign));
    llvm::Value* run = b_.CreateLoad(ptr_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kTexOffset));
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, i64_, i64_, ptr_, ptr_, ptr_}, false);
    b_.CreateCall(type, run, {ctx_arg_, b_.getInt64(call_outs_.size() - 1), load_mask(exec_), units, block, out});
    for (uint32_t c = 0; c < ir::kTexResults; ++c)  // Machine::write's mask
        write_reg(in.dst + c, b_.CreateAlignedLoad(vi32_, row(out, c), llvm::Align(kRegAlign)), WriteMode::Blends,
                  false);
    return true;
}

}  // namespace glslrun::rt::jit
