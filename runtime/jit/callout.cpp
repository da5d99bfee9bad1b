// The JIT's call-outs: an instruction run by the interpreter's own kernel
// (runtime/interp_kernels.h, fast_kernels.h, tex_kernel.cpp) on the
// executor's register file, under the generated code's exec mask. The
// kernel is the one the interpreter would pick, so the bits are its bits.
#include "runtime/jit/context.h"

#include <algorithm>

namespace glslrun::rt::jit {

Step<uint32_t> call_out_step(const CallOut& call, uint32_t* regs, uint32_t reg_count) {
    return instr_step<uint32_t>(call.instr, call.kernel, [&](ir::Reg r) {
        return regs + size_t(r == ir::kNoReg || r >= reg_count ? reg_count : r) * kLanes;
    });
}

void run_call_out(Context* ctx, [[maybe_unused]] uint32_t* regs, uint64_t index, uint64_t exec) {
    const Step<uint32_t>& step = ctx->call_steps[index];
    Machine<uint32_t>& m = ctx->machine;  // m.regs == regs
    m.mask.reset(exec);
    step.fn(step, m);
}

namespace {
uint64_t poll_below(uint64_t left) {
    return left > RunLimits::kCancelPoll ? left - RunLimits::kCancelPoll : 0;
}
}  // namespace

void Context::start_budget(uint64_t max_instructions, const std::atomic<bool>* flag, BudgetShare* draw) {
    cancel = flag;
    share = draw;
    run_instructions = max_instructions;
    reported = 0;
    stop = DrawBudget::Stop::None;
    next_cancel_poll = flag || draw ? poll_below(max_instructions) : 0;
    credit = max_instructions - next_cancel_poll;
}

bool Context::report(uint64_t left) {
    if (!share) return true;
    // After a failure `left` may be stale (the generated code stores it only on a normal return).
    const uint64_t used = std::max(run_instructions - left, reported);
    const DrawBudget::Stop now = share->charge(used - reported);
    reported = used;
    if (now == DrawBudget::Stop::None) return true;
    stop = now;  // kept for the message: a later report (after the run) does not clear it
    return false;
}

// Interpreter's charge(), from credit = left - next_cancel_poll.
int32_t charge_slowly(Context* ctx, uint64_t credit, uint64_t instructions) {
    uint64_t left = ctx->next_cancel_poll + credit;
    if (instructions > left) return int32_t(Failure::Instructions);
    left -= instructions;
    if ((ctx->cancel || ctx->share) && left < ctx->next_cancel_poll) {
        ctx->next_cancel_poll = poll_below(left);
        if (ctx->cancel && ctx->cancel->load(std::memory_order_relaxed)) return int32_t(Failure::Cancelled);
        if (!ctx->report(left)) return int32_t(Failure::DrawBudget);
    }
    ctx->credit = left - ctx->next_cancel_poll;
    return int32_t(Failure::None);
}

}  // namespace glslrun::rt::jit
