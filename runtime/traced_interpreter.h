// The interpreter with a hook: the same Steps, kernels and execution masks as
// rt::Interpreter (so the same bits), plus calls to a TraceHook after every
// instruction and at every control-flow decision. A separate instantiation
// of the interpreter's core: the untraced one has no hook and no branch for
// it (runtime/interpreter.cpp). Used by debug/ (trace, --find-nan).
#pragma once
#include <cstdint>
#include <memory>

#include "runtime/interpreter.h"

namespace glslrun::rt {

// One lane's value of a register. Floats are exact: fp32 in Precise and Fast,
// double in Reference (`wide`).
struct LaneValue {
    ir::Kind kind = ir::Kind::F32;
    double f = 0;       // F32
    int32_t i = 0;      // I32, and Bool as 0/1
    bool wide = false;  // Reference: f is the register's double
};

class LaneReader {
public:
    virtual LaneValue read(ir::Reg r, int lane) const = 0;

protected:
    ~LaneReader() = default;
};

// `active`: the lanes the node runs for (an If's lanes before it splits).
class TraceHook {
public:
    virtual ~TraceHook() = default;
    // After an instruction ran (it wrote its destination in `active`).
    virtual void instr(const ir::Node& n, LaneMask active, const LaneReader& regs) = 0;
    // An If: `taken` are the active lanes whose condition holds.
    virtual void branch(const ir::Node& n, LaneMask active, LaneMask taken) = 0;
    // A Loop starts iteration `iteration` (0, 1, ...) with `active` lanes.
    virtual void loop_iteration(const ir::Node& n, uint64_t iteration, LaneMask active) = 0;
    // Break, Continue, Return, Discard, Call and Scope nodes as they run.
    virtual void jump(const ir::Node& n, LaneMask active) = 0;
    // A Call or Scope finished.
    virtual void leave(const ir::Node& n) = 0;
};

class TracedEngine;

class TracedInterpreter {
public:
    // As rt::Interpreter, under the same limits (loop cap, instruction
    // budget, cancel flag); `hook` must outlive the interpreter, and so must
    // `shader` (the hook is given its nodes).
    TracedInterpreter(const ir::Shader& shader, const uint32_t* uniforms, const RunLimits& limits,
                      const GLState::TextureUnit* textures, Precision precision, uint32_t fast_ops, TraceHook& hook);
    ~TracedInterpreter();
    uint32_t* lanes(ir::Reg r);
    bool run(LaneMask live, RunError* error);
    LaneMask alive() const;

private:
    std::unique_ptr<TracedEngine> engine_;
};

}  // namespace glslrun::rt
