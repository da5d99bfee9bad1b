// The work of one draw() or run_* call as a whole (ExecOptions): its
// instructions, all batches and worker threads together, the cancel flag and
// the deadline. A budget per batch alone let a two-line shader with a loop
// just under the caps run for tens of minutes at 512x512 (4096 batches,
// each within its budget).
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

#include "glslrun/glslrun.h"

namespace glslrun::rt {

// Every executor of a draw reports the instructions it charged here, in
// shares of at least RunLimits::kCancelPoll (BudgetShare), and the draw
// checks the total once its workers are done (over()): whether a draw fails
// depends on its total alone, which its batches fix, not on the threads.
class DrawBudget {
public:
    enum class Stop : uint8_t { None, Instructions, RenderInstructions, Cancelled, TimeLimit };
    // The draw's limit is the smaller of its own budget and what is left of
    // its render's (ExecOptions::render_instructions); the destructor adds
    // the draw's instructions to the render's count.
    explicit DrawBudget(const ExecOptions& exec);
    ~DrawBudget();
    DrawBudget(const DrawBudget&) = delete;
    DrawBudget& operator=(const DrawBudget&) = delete;
    // Adds instructions charged; says whether the draw must stop: past its
    // instructions, cancelled or past the deadline (both polled here).
    Stop add(uint64_t instructions);
    // After the workers, with every share reported: the total's verdict.
    Stop over() const { return used() > max_ ? past_max() : Stop::None; }
    uint64_t used() const { return used_.load(std::memory_order_relaxed); }
    std::string message(Stop stop) const;
    static constexpr const char* kTimeLimitMessage =
        "the time limit ran out (ExecOptions::deadline): the draw stopped unfinished";

private:
    Stop past_max() const { return render_binds_ ? Stop::RenderInstructions : Stop::Instructions; }

    std::atomic<uint64_t> used_{0};
    uint64_t max_;
    uint64_t render_max_;
    std::atomic<uint64_t>* render_;
    bool render_binds_ = false;  // what is left of the render's budget is below the draw's
    const std::atomic<bool>* cancel_;
    std::chrono::steady_clock::time_point deadline_;
};

// One executor's part of a DrawBudget: instructions gather here and go to
// the budget in shares of kCancelPoll (an atomic add per 64K instructions,
// not per batch); what is left goes when the executor does.
class BudgetShare {
public:
    explicit BudgetShare(DrawBudget* draw) : draw_(draw) {}
    BudgetShare(const BudgetShare&) = delete;
    BudgetShare& operator=(const BudgetShare&) = delete;
    ~BudgetShare() {
        if (draw_ && pending_) draw_->add(pending_);
    }
    bool active() const { return draw_ != nullptr; }
    DrawBudget::Stop charge(uint64_t instructions);
    std::string message(DrawBudget::Stop stop) const { return draw_->message(stop); }

private:
    DrawBudget* draw_;
    uint64_t pending_ = 0;
};

}  // namespace glslrun::rt
