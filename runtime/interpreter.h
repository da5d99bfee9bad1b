// The batched IR interpreter: runs one ir::Shader over kLanes invocations at
// once, structure of arrays. Each instruction loops over the lanes, so the
// dispatch cost is paid once per instruction per batch, not per invocation.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "runtime/backend.h"

namespace glslrun::rt {

class Engine;  // runtime/interpreter.cpp: the interpreter for one register word size

class Interpreter final : public Executor {
public:
    // `uniforms` must stay alive while the interpreter runs; it is the
    // program's uniform store (one 32-bit word per component). Its values
    // must not change during the interpreter's life: the shader's prologue
    // (uniform-only code) runs once, here. `textures` (kMaxTextureUnits
    // units, may be null: nothing bound) must stay alive too.
    // `precision` (glslrun.h): Precise and Fast run fp32 registers, Fast with
    // approximate kernels for a few ops; Reference runs double registers.
    // `fast_ops` (FastOps bits): the classes Fast approximates; the others
    // keep their Precise kernels.
    Interpreter(const ir::Shader& shader, const uint32_t* uniforms, const RunLimits& limits,
                const GLState::TextureUnit* textures = nullptr, Precision precision = Precision::Precise,
                uint32_t fast_ops = kAllFastOps);
    Interpreter(const ir::Shader& shader, const ExecParams& p)
        : Interpreter(shader, p.uniforms, p.limits, p.textures, p.precision, p.fast_ops) {}
    ~Interpreter() override;

    // In Reference mode the shader works on doubles behind these words: the
    // inputs (ir::Shader::inputs) are read from them at run() and the outputs
    // (ir::Shader::outputs) rounded back to float into them after it; other
    // registers are not exchanged.
    uint32_t* lanes(ir::Reg r) override;
    bool run(LaneMask live, RunError* error) override;
    LaneMask alive() const override;
    void skip_lookups(LaneMask lanes) override;
    Runner runner() const override { return Runner::Interp; }
    void watch_undefined(UndefSink* sink) override;
    bool hold_denormal_mode(bool held) override;

private:
    std::unique_ptr<Engine> engine_;
};

}  // namespace glslrun::rt
