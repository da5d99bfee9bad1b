// The JIT's call-outs: an instruction run by the interpreter's own kernel
// (runtime/interp_kernels.h, fast_kernels.h, tex_kernel.cpp) on the
// executor's register file, under the generated code's exec mask. The
// kernel is the one the interpreter would pick, so the bits are its bits.
#include "runtime/jit/context.h"

namespace glslrun::rt::jit {

void run_call_out(Context* ctx, uint32_t* regs, const CallOut* call, uint64_t exec) {
    const uint32_t zero = ctx->reg_count;
    Step<uint32_t> step = instr_step<uint32_t>(call->instr, call->kernel, [&](ir::Reg r) {
        return regs + size_t(r == ir::kNoReg || r >= zero ? zero : r) * kLanes;
    });
    Machine<uint32_t>& m = ctx->machine;
    m.regs = regs;
    m.mask.reset(exec);
    step.fn(step, m);
}

}  // namespace glslrun::rt::jit
