#include "runtime/budget.h"

#include <fmt/format.h>

#include "runtime/backend.h"

namespace glslrun {

void ExecOptions::set_time_limit(double seconds) {
    using Clock = std::chrono::steady_clock;
    deadline = Clock::time_point::max();
    if (seconds > 0 && seconds <= 1e9)
        deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace glslrun

namespace glslrun::rt {

std::string RunLimits::loop_cap_message() const {
    return fmt::format("loop exceeded {} iterations", max_loop_iterations);
}

std::string RunLimits::instructions_message() const {
    return fmt::format("the shader executed more than {} instructions in one batch (calls that multiply, or a loop "
                       "too long)",
                       max_instructions);
}

DrawBudget::DrawBudget(const ExecOptions& exec)
    : max_(exec.max_draw_instructions),
      render_max_(exec.max_render_instructions),
      render_(exec.render_instructions),
      cancel_(exec.cancel),
      deadline_(exec.deadline) {
    if (!render_) return;
    const uint64_t before = render_->load(std::memory_order_relaxed);
    const uint64_t left = before < render_max_ ? render_max_ - before : 0;
    if (left < max_) {
        max_ = left;
        render_binds_ = true;
    }
}

DrawBudget::~DrawBudget() {
    if (render_) render_->fetch_add(used(), std::memory_order_relaxed);
}

DrawBudget::Stop DrawBudget::add(uint64_t instructions) {
    uint64_t before = used_.fetch_add(instructions, std::memory_order_relaxed);
    if (before + instructions > max_ || before + instructions < before) return past_max();
    if (cancel_ && cancel_->load(std::memory_order_relaxed)) return Stop::Cancelled;
    if (deadline_ != std::chrono::steady_clock::time_point::max() && std::chrono::steady_clock::now() >= deadline_)
        return Stop::TimeLimit;
    return Stop::None;
}

std::string DrawBudget::message(Stop stop) const {
    switch (stop) {
    case Stop::None: break;
    case Stop::Instructions:
        return fmt::format("the draw executed more than {} instructions, its batches together "
                           "(ExecOptions::max_draw_instructions): loops or calls too long for its pixels",
                           max_);
    case Stop::RenderInstructions:
        return fmt::format("the render executed more than {} instructions, its draws together "
                           "(ExecOptions::max_render_instructions, glslrun --max-instructions): loops or calls "
                           "too long for its draws and frames",
                           render_max_);
    case Stop::Cancelled: return RunLimits::kCancelledMessage;
    case Stop::TimeLimit: return kTimeLimitMessage;
    }
    return {};
}

DrawBudget::Stop BudgetShare::charge(uint64_t instructions) {
    pending_ += instructions;
    if (!draw_ || pending_ < RunLimits::kCancelPoll) return DrawBudget::Stop::None;
    uint64_t share = pending_;
    pending_ = 0;
    return draw_->add(share);
}

}  // namespace glslrun::rt
