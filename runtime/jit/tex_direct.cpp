// A `tex` lookup in generated code. The call-out (the interpreter's `tex`
// kernel, runtime/tex_kernel.cpp, run through run_call_out) decodes the
// operand block, groups the lanes by unit, checks the texture's
// completeness and picks a sampler at every lookup: with the register-file
// traffic around it, a fifth of a nine-tap post-process frame and a tenth
// of a four-tap shadow-map one (perf). Here the generated code stores the
// units and the operand block as a call-out does and calls run_tex(),
// which, where every lane names one unit whose texture has a sampler bound
// when the executor was made, calls it with the lookup lanes: a 2D or
// rectangle colour lookup the one-pass sampler (runtime/sampling_direct.h,
// or Fast's runtime/sampling_gpu_direct.h under its GPU filtering); a 1D,
// 3D or cube colour lookup or a 2D depth comparison the batched sampler's
// kernel for the texture's state (BoundKernel: sampling_direct1d.h,
// sampling_direct3d.h, sampling_batch_cube.h, sampling_shadow8.h), and a
// mipmapped 2D colour lookup in Precise sampling_mip2d.h's kernel with the
// derivative rows, each quad's first lane's (as the tex kernel's share
// step gives them). Anything else (another unit per lane, a unit out of
// range, an incomplete texture, a state with no such kernel, another one
// whose level of detail matters) runs the call-out's kernel. The sampler is the one the kernel
// would pick, the default results the kernel's (a lane that skips its
// lookup reads 0), the write masked as Machine::write's: the bits are the
// call-out's (tests/runtime/jit_tex_direct_test.cpp,
// jit_tex_kinds_test.cpp). One call per lookup in the generated code, and
// one branch where it has derivative rows: they are stored only where a
// texture of the executor may read them (tex_derivatives(); a NEAREST or
// LINEAR shadow map never does).
#include "runtime/jit/codegen.h"

#include "runtime/backend.h"
#include "runtime/fast_kernels.h"
#include "runtime/sampling_direct1d.h"
#include "runtime/sampling_direct3d.h"
#include "runtime/sampling_gpu3d.h"
#include "runtime/sampling_gpu_direct.h"
#include "runtime/sampling_mip2d.h"
#include "runtime/sampling_rules.h"
#include "runtime/sampling_shadow8.h"

namespace glslrun::rt::jit {

// run_tex() runs only where the generated code is AVX2's (emit_tex_direct()):
// built for it, the units' test goes eight lanes at a time.
#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_AVX2 __attribute__((target("avx2")))
#else
#define GLSLRUN_AVX2
#endif

namespace {

constexpr unsigned kRegAlign = kLanes * 4 < 64 ? kLanes * 4 : 64;  // as a register's (alu.cpp)

// fill_defaults() of the lanes that skip their lookups (the sampler writes
// the others): a third of run_tex() when done for every batch.
GLSLRUN_AVX2 void zero_skipped(float (*result)[kLanes], LaneMask lookups) {
    if (lookups == kAllLanes) return;
    for (uint32_t c = 0; c < ir::kTexResults; ++c)
        for (int i = 0; i < kLanes; ++i) result[c][i] = 0.0f;
}

// The lookup through the unit's bound sampler or kernel where it has one
// (true); false where the call-out's kernel must run.
GLSLRUN_AVX2 bool run_bound(const Context& ctx, uint64_t index, const ir::TexInfo& info, uint32_t unit,
                            LaneMask lookups, const float* operands, float (*result)[kLanes]) {
    if (one_pass_lookup(info) && ctx.direct) {
        const DirectSampler& sampler = ctx.direct[direct_slot(unit, info.target == ir::TexTarget::Rect)];
        if (sampler.run) {
            zero_skipped(result, lookups);
            sampler.run(sampler, operands, operands + kLanes, lookups, result);
            return true;
        }
    }
    const KernelKind kind = kernel_kind(info);
    if (kind == KernelKind::Count || !ctx.kernels || !ctx.lookups) return false;
    const BoundKernel& kernel = ctx.kernels[kernel_slot(unit, kind)];
    if (!kernel.run) return false;
    // Its operands: made at each lookup, the record's zero fill was a `rep
    // stos` that the next store waited on (perf: a third of run_tex() in
    // the shadow-map frame).
    zero_skipped(result, lookups);
    kernel.run(*kernel.texture, ctx.lookups[index], lookups, result);
    return true;
}

// A 2D colour lookup's level-of-detail operands as the tex kernel gives
// sample_mip2d() them (FloatOperands::lookup(), and its quads' derivatives
// read from their first lanes where derivative_lane() picks those).
void mip2d_operands(const ir::TexInfo& info, const float* block, BatchLookup& lk) {
    alignas(32) static constexpr float kZeros[kLanes] = {};
    lk.implicit = info.lod != ir::TexLod::Explicit;
    lk.bias = info.lod == ir::TexLod::ImplicitBias;
    if (info.lod != ir::TexLod::Implicit) lk.lod = block + size_t(info.lod_at()) * kLanes;
    for (uint32_t c = 0; c < 3; ++c) {
        const bool row = lk.implicit && c < info.grad_dims();
        lk.ddx[c] = row ? block + size_t(info.ddx_at() + c) * kLanes : kZeros;
        lk.ddy[c] = row ? block + size_t(info.ddy_at() + c) * kLanes : kZeros;
    }
    lk.quad_derivatives = lk.implicit && derivative_lane(1, SamplingRules::Common, info.grad) == 0;
}

}  // namespace

std::vector<BatchLookup> tex_lookups(const std::vector<CallOut>& calls, const std::vector<Step<uint32_t>>& steps) {
    std::vector<BatchLookup> out(calls.size());
    for (size_t i = 0; i < calls.size(); ++i) {
        if (calls[i].instr.op != ir::Op::tex) continue;
        const ir::TexInfo info = ir::TexInfo::decode(calls[i].instr.imm[2]);
        const auto* block = reinterpret_cast<const float*>(steps[i].src[1]);  // the operand block
        for (uint32_t c = 0; c < info.dims() && c < 3; ++c) out[i].coord[c] = block + size_t(c) * kLanes;
        if (info.shadow) out[i].ref = block + size_t(info.ref_at()) * kLanes;
        if (kernel_kind(info) == KernelKind::Mip2D) mip2d_operands(info, block, out[i]);
    }
    return out;
}

std::vector<uint8_t> tex_derivatives(const std::vector<CallOut>& calls, const GLState::TextureUnit* units, bool gpu) {
    const SamplingRules rules = gpu ? SamplingRules::Gpu : SamplingRules::Common;
    std::vector<uint8_t> out(calls.size(), 0);
    for (size_t i = 0; i < calls.size(); ++i) {
        if (calls[i].instr.op != ir::Op::tex) continue;
        const ir::TexInfo info = ir::TexInfo::decode(calls[i].instr.imm[2]);
        if (info.lod == ir::TexLod::Explicit) continue;
        bool read = !units;
        for (uint32_t unit = 0; unit < uint32_t(kMaxTextureUnits) && !read; ++unit) {
            const Texture* t = units[unit].bound[size_t(info.target)].get();
            read = t && (sampling::lod_matters(t->sampler) || lanes_only(*t, rules));
        }
        out[i] = read;
    }
    return out;
}

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

void bind_kernels(const GLState::TextureUnit* units, bool gpu, BoundKernel* out) {
    for (size_t i = 0; i < kKernelSlots; ++i) out[i] = {};
    if (!units || !cpu_has_avx2()) return;
    // The tex kernel's rules: a texture that Fast's GPU filtering takes
    // (lanes_only()) is sampled by its own paths, any other by the batched
    // sampler's kernels, as Precise's.
    const SamplingRules rules = gpu ? SamplingRules::Gpu : SamplingRules::Common;
    for (uint32_t unit = 0; unit < uint32_t(kMaxTextureUnits); ++unit) {
        const auto bind = [&](KernelKind kind, ir::TexTarget target, BatchKernel (*choose)(const Texture&)) {
            const Texture* t = units[unit].bound[size_t(target)].get();
            // run_bound() passes no derivatives: a level-of-detail decision
            // (and a texture that is not complete) keeps the call-out.
            if (!t || !t->complete() || lanes_only(*t, rules) || sampling::lod_matters(t->sampler)) return;
            if (const BatchKernel run = choose(*t)) out[kernel_slot(unit, kind)] = {run, t};
        };
        bind(KernelKind::T1D, ir::TexTarget::T1D, direct1d_kernel);
        // Fast's RGBA8 3D textures take the GPU's rule (lanes_only() for the rest of the sampler).
        const Texture* t3d = units[unit].bound[size_t(ir::TexTarget::T3D)].get();
        if (BatchKernel run = gpu && t3d && t3d->complete() ? gpu3d_kernel(*t3d) : nullptr)
            out[kernel_slot(unit, KernelKind::T3D)] = {run, t3d};
        else
            bind(KernelKind::T3D, ir::TexTarget::T3D, direct3d_kernel);
        bind(KernelKind::Cube, ir::TexTarget::Cube, cube_kernel);
        bind(KernelKind::Shadow2D, ir::TexTarget::T2D, shadow8_kernel);
        // A mipmapped 2D colour texture, as the tex kernel samples it in
        // Precise: sample_batch() picks sample_mip2d() for it, which reads
        // each quad's first lane's derivatives (no copy of them to share).
        const Texture* t2d = units[unit].bound[size_t(ir::TexTarget::T2D)].get();
        if (binds_mip2d(t2d, gpu)) out[kernel_slot(unit, KernelKind::Mip2D)] = {sample_mip2d, t2d};
    }
}

GLSLRUN_AVX2 void run_tex(Context* ctx, uint64_t index, uint64_t exec, const uint32_t* units,
                          const uint32_t* operands, uint32_t* out) {
    const Step<uint32_t>& call = ctx->call_steps[index];
    const uint32_t unit = units[0];
    uint32_t differ = 0;  // as the kernel's same_unit(): every lane, active or not
    for (int i = 0; i < kLanes; ++i) differ |= units[i] ^ unit;
    if (!differ && unit < uint32_t(kMaxTextureUnits) &&
        run_bound(*ctx, index, ir::TexInfo::decode(call.imm[2]), unit, exec & ctx->machine.lookups,
                  reinterpret_cast<const float*>(operands), reinterpret_cast<float (*)[kLanes]>(out)))
        return;
    Step<uint32_t> step = call;  // the results into `out`, not the register file
    step.dst = out;
    ctx->machine.mask.reset(exec);
    step.fn(step, ctx->machine);
}

bool Emitter::emit_tex_direct(const ir::Instr& in) {
    if (!avx2_ || !tex_runs_direct(in, precision_ == Precision::Fast && (fast_ops_ & kFastTexture))) return false;
    call_outs_.push_back({kernel_for(in.op, avx2_, precision_, fast_ops_), in});
    const uint32_t operands = ir::TexInfo::decode(in.imm[2]).operand_count();
    // The unit and the operand block go to the register file, as a
    // call-out's (emit_call_out()): the call-out's kernel may read a lane
    // that the mask leaves off (a quad's derivatives), whose word must be
    // the interpreter's, the last one written there. The results come back
    // through the function's stack frame: the registers stay values.
    auto sync = [&](ir::Reg r) {
        if (r < locals_.size() && locals_[r]) b_.CreateAlignedStore(load_reg(r), file_ptr(r), llvm::Align(kRegAlign));
    };
    sync(in.src[0]);
    const ir::TexInfo info = ir::TexInfo::decode(in.imm[2]);
    const uint32_t rows = info.lod == ir::TexLod::Explicit ? operands : info.ddx_at();
    for (uint32_t k = 0; k < rows; ++k) sync(in.imm[0] + k);
    if (rows < operands) {  // the derivative rows, where this executor's textures may read them
        llvm::Value* flags = b_.CreateLoad(ptr_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_,
                                                                                kDerivativesOffset));
        llvm::Value* flag = b_.CreateLoad(b_.getInt8Ty(), b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), flags,
                                                                                       call_outs_.size() - 1));
        llvm::BasicBlock* store = new_block("tex_derivatives");
        llvm::BasicBlock* after = new_block("tex_call");
        b_.CreateCondBr(b_.CreateICmpNE(flag, b_.getInt8(0)), store, after);
        b_.SetInsertPoint(store);
        for (uint32_t k = rows; k < operands; ++k) sync(in.imm[0] + k);
        b_.CreateBr(after);
        b_.SetInsertPoint(after);
    }
    llvm::IRBuilder<> entry(&fn_->getEntryBlock(), fn_->getEntryBlock().begin());
    auto* words = llvm::ArrayType::get(i32_, kLanes);
    llvm::AllocaInst* out = entry.CreateAlloca(llvm::ArrayType::get(words, ir::kTexResults), nullptr, "tex_out");
    out->setAlignment(llvm::Align(kRegAlign));
    llvm::Value* run = b_.CreateLoad(ptr_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_arg_, kTexOffset));
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, i64_, i64_, ptr_, ptr_, ptr_}, false);
    b_.CreateCall(type, run, {ctx_arg_, b_.getInt64(call_outs_.size() - 1), load_mask(exec_), file_ptr(in.src[0]),
                              file_ptr(in.imm[0]), out});
    for (uint32_t c = 0; c < ir::kTexResults; ++c)  // Machine::write's mask
        write_reg(in.dst + c,
                  b_.CreateAlignedLoad(vi32_, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), out,
                                                                            uint64_t(c) * kLanes * sizeof(uint32_t)),
                                       llvm::Align(kRegAlign)),
                  WriteMode::Blends, false);
    return true;
}

#undef GLSLRUN_AVX2

}  // namespace glslrun::rt::jit
