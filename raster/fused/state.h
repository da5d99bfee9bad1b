// What a draw's fragment functions depend on (raster/fused/pipeline.h): the
// program's inputs and outputs and the draw's per-fragment state, raster's
// own FragmentState. One function makes the key that code is cached under
// (state_key); one decides whether the generated path takes a state
// (fusable), and it takes only what it knows: it forgets the fields the
// generated code implements and accepts what is left only where it equals a
// default State, so a field added to FragmentState or State that nobody
// teaches the generated path is refused, not ignored (as llvmpipe's
// fragment shader variants key on the whole state).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ir/ir.h"
#include "raster/fragment_ops.h"

namespace glslrun::raster::fused {

// Where a shader input component comes from (the C++ path's InputPlan too).
enum class InputSource : uint8_t { Varying, FragCoord, FrontFacing, PointCoord, Zero };

struct Input {
    InputSource source = InputSource::Zero;
    uint32_t index = 0;  // Varying: the attribute; the built-ins: the component
    ir::Kind kind = ir::Kind::F32;  // the register's
    bool sprite_coord = false;  // gl_TexCoord[i] replaced on points (GL_COORD_REPLACE)
    uint8_t component = 0;      // which of its binding's components (sprite_coord's (s, t, 0, 1))
    bool operator==(const Input&) const = default;
};

struct State {
    FragmentState ops;           // the draw's per-fragment operations
    std::vector<Input> inputs;   // per input register, in the order the fragment stage passes them
    uint32_t color_channels = 0;  // components of colour buffer 0's output (0: none written)
    // Buffers 1 and up of several draw buffers (FragmentState::draw_buffers):
    // their outputs' components ([0] unused; 0: not written).
    std::array<uint8_t, kMaxDrawBuffers> more_channels{};
    bool float_outputs = true;   // the colour and depth outputs are float registers
    bool depth_output = false;   // gl_FragDepth written
    bool early_depth = false;    // the depth and stencil tests run before the shader (FragmentStage)
    bool probe = false;          // the shader debugger watches the draw
    bool avx2 = false;           // the vector ISA the code is made for
    bool operator==(const State&) const = default;
};

// The bytes `s` is cached under: equal for equal states (NaNs by their
// bits), different for different ones.
std::string state_key(const State& s);

// What a pipeline's inputs function depends on: `s`'s inputs and ISA, the
// rest default (raster/fused/pipeline.h, InputsCode).
State inputs_only(const State& s);

// Whether the generated code computes `s`'s bits; otherwise the C++ path
// (raster/fragments.cpp) draws.
bool fusable(const State& s);

// fusable()'s rule on a state of any type made of a State: the fields the
// generated code implements are reset, and what is left must be a default
// `S` (tests/fused prove it refuses a field it does not know).
template <class S>
bool only_known_fields(const S& s);
// Resets the fields of `s` that the generated code implements for it.
void forget_known_fields(State& s);

template <class S>
bool only_known_fields(const S& s) {
    S rest = s;
    forget_known_fields(rest);
    return rest == S{};
}

// With blending, a logic op or a colour mask, an RGBA8 colour write reads
// the buffer first.
inline bool reads_color(const State& s) {
    return s.ops.blend || s.ops.logic_op || s.ops.color_mask != std::array<bool, 4>{true, true, true, true};
}

// Whether any colour buffer is written.
inline bool writes_color(const State& s) {
    bool any = s.color_channels > 0;
    for (uint8_t c : s.more_channels) any |= c > 0;
    return any;
}

}  // namespace glslrun::raster::fused
