// Trace hooks (runtime/traced_interpreter.h) that turn a traced run into
// debug/trace.h's records: LaneRecorder follows one lane statement by
// statement; NanWatch notes the first NaN or infinity of every lane.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "debug/trace.h"
#include "runtime/sampling.h"
#include "runtime/traced_interpreter.h"

namespace glslrun::debug {

// What the hooks need to name things: registers to variables, words of the
// uniform store to uniforms, nodes to file:line.
class ShaderNames {
public:
    ShaderNames(const ir::Shader& shader, const ir::Program& program);
    // "file:line", with ":column" when asked and known.
    std::string where(const ir::SourceLoc& loc, bool column = false) const;
    // The variable (or shader output) register r belongs to, or null.
    const ir::Variable* variable(ir::Reg r) const {
        return r < var_of_.size() && var_of_[r] >= 0 ? &vars_[size_t(var_of_[r])] : nullptr;
    }
    // The uniform leaf holding word `slot` of the store, or -1.
    int uniform_at(uint32_t slot) const { return slot < uniform_of_.size() ? uniform_of_[slot] : -1; }
    const ir::Shader& shader() const { return shader_; }
    const ir::Program& program() const { return program_; }

private:
    const ir::Shader& shader_;
    const ir::Program& program_;
    std::vector<ir::Variable> vars_;  // the shader's variables and its outputs
    std::vector<int> var_of_, uniform_of_;
};

// A register's values in one lane (`count` registers from `first`).
Values read_values(const rt::LaneReader& regs, ir::Reg first, uint32_t count, int lane);
// The uniform leaf's values (all elements) from the store.
NamedValue uniform_value(const ir::Uniform& u, const uint32_t* store);

class LaneRecorder final : public rt::TraceHook {
public:
    // `uniforms`: the store the run reads (for the values of the uniforms read);
    // at most `max_steps` steps are kept.
    // `textures`: the units the run samples (the lookups' details), by the
    // precision mode's rules (rt::SamplingRules, as the `tex` kernel picks them).
    LaneRecorder(const ShaderNames& names, const uint32_t* uniforms, int lane,
                 size_t max_steps = InvocationTrace::kMaxSteps, const GLState::TextureUnit* textures = nullptr,
                 Precision precision = Precision::Precise);
    void instr(const ir::Node& n, rt::LaneMask active, const rt::LaneReader& regs) override;
    void branch(const ir::Node& n, rt::LaneMask active, rt::LaneMask taken) override;
    void loop_iteration(const ir::Node& n, uint64_t iteration, rt::LaneMask active) override;
    void jump(const ir::Node& n, rt::LaneMask active) override;
    void leave(const ir::Node& n) override;
    // Ends the trace: the last assignments, the uniforms read.
    void finish(const rt::LaneReader* regs);
    // The steps recorded, a texture lookup counting as 1 + kLookupExtra
    // (its texels take about three steps' memory): what the step limits count.
    size_t cost() const { return trace.steps.size() + extra_; }
    static constexpr size_t kLookupExtra = 2;
    InvocationTrace trace;

private:
    bool on(rt::LaneMask active) const { return (active >> lane_) & 1; }
    void add(TraceStep step);
    void flush_assignments();
    void statement(const ir::SourceLoc& loc);
    void lookup(const ir::Node& n, const rt::LaneReader& regs);

    const ShaderNames& names_;
    const uint32_t* uniforms_;
    int lane_;
    size_t max_steps_;
    const GLState::TextureUnit* textures_;
    rt::SamplingRules rules_;
    size_t extra_ = 0;
    int depth_ = 0;
    ir::SourceLoc last_{};
    std::vector<const ir::Variable*> dirty_;
    const rt::LaneReader* regs_ = nullptr;
    std::vector<int> uniforms_read_;
    std::vector<bool> calls_;                     // per Call being run: whether the lane entered it
    std::vector<std::string> functions_{"main"};  // the lane's call stack
};

// The first NaN or infinity that each lane computes (any float result).
class NanWatch final : public rt::TraceHook {
public:
    explicit NanWatch(const ShaderNames& names) : names_(names) {}
    void instr(const ir::Node& n, rt::LaneMask active, const rt::LaneReader& regs) override;
    void branch(const ir::Node&, rt::LaneMask, rt::LaneMask) override {}
    void loop_iteration(const ir::Node&, uint64_t, rt::LaneMask) override {}
    void jump(const ir::Node&, rt::LaneMask) override {}
    void leave(const ir::Node&) override {}
    std::array<std::optional<NanEvent>, rt::kLanes> first;
    rt::LaneMask found = 0;

private:
    const ShaderNames& names_;
};

// The NaN event of instruction `n` in `lane` if its result is NaN or infinite.
std::optional<NanEvent> nan_event(const ShaderNames& names, const ir::Node& n, const rt::LaneReader& regs, int lane);

}  // namespace glslrun::debug
