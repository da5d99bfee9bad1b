// Running a program's vertex shader over attribute arrays, shared by
// run_vertices() and draw(). Internal to the library.
#pragma once
#include <cstdint>
#include <vector>

#include "glslrun/glslrun.h"
#include "runtime/backend.h"
#include "runtime/program_state.h"

namespace glslrun::exec {

// Every vertex-shader output of every vertex, as floats (ints and bools converted).
struct VertexOutputs {
    std::vector<uint32_t> offset;  // per ir vertex output: first float within a vertex
    uint32_t stride = 0;           // floats per vertex
    std::vector<float> data;       // count * stride
    const float* vertex(uint32_t i) const { return data.data() + size_t(i) * stride; }
};

// Runs the vertex shader on vertices [0, count). Attributes the arrays lack
// take `current`'s values (gl_Color, gl_SecondaryColor, gl_Normal) or (0,0,0,1).
// `out` is overwritten; its storage is reused (draw() keeps it between draws).
Status shade_vertices(const Program& program, const std::vector<VertexAttrib>& attribs, uint32_t count,
                      const GLState& current, VertexOutputs& out);

// The words (one per component, in the register's kind) that vertex
// `element` gives each of `shader`'s inputs, in shader.inputs' order, as
// shade_vertices fills them (the shader debugger replays one vertex).
Result<std::vector<std::vector<uint32_t>>> vertex_input_words(const ir::Shader& shader,
                                                               const std::vector<VertexAttrib>& attribs,
                                                               uint32_t count, const GLState& current,
                                                               uint32_t element);

// The offset of each of `shader`'s outputs in a vertex of VertexOutputs, and
// in *stride the floats of a vertex.
std::vector<uint32_t> output_offsets(const ir::Shader& shader, uint32_t* stride);

// An interpreter failure (loop cap) as a user-facing error.
Error run_error(const Program::State& state, ir::Stage stage, const rt::RunError& error);

// Reads lane `lane` of register r as a float (ints and bools converted).
float lane_as_float(rt::Executor& interp, ir::Kind kind, ir::Reg r, int lane);
// Writes a float into lane `lane` of register r in the register's kind.
void set_lane(rt::Executor& interp, ir::Kind kind, ir::Reg r, int lane, float value);

}  // namespace glslrun::exec
