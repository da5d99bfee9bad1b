// Harness for the GLSL language tests: compile a shader through the public
// API, run it over many lanes with different inputs, and compare every lane
// with a value computed in C++.
//
// Conventions shared by every test file:
// - Vertex tests read the attributes `a`, `b`, `c` (vec4, see in_a/in_b/in_c)
//   and write results to user varyings (floats only, as GLSL 1.10 requires;
//   ints and bools are written as float(x)).
// - kVerts is not a multiple of the interpreter's batch width, so full and
//   partial batches both run.
#pragma once
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glslrun/glslrun.h>

namespace lang {

inline constexpr uint32_t kVerts = 37;  // two full 16-lane batches and a partial one
inline constexpr uint32_t kFrags = 40;  // ten 2x2 quads, the last batch partial

// Per-lane inputs, all different from lane to lane.
glm::vec4 in_a(uint32_t lane);  // mixed signs, |x| < ~4, never exactly 0
glm::vec4 in_b(uint32_t lane);  // strictly positive, in (0.1, 4); b.w < 1
glm::vec4 in_c(uint32_t lane);  // small integers as floats: x,y,w in [-4,4], z in [0,3]

glslrun::VertexAttrib make_attrib(std::string name, uint32_t components, uint32_t count,
                                  const std::function<float(uint32_t lane, uint32_t comp)>& value);
// attributes a, b, c (vec4) for `count` lanes
std::vector<glslrun::VertexAttrib> std_attribs(uint32_t count = kVerts);

// Compiles or FAILs the test with every diagnostic and the source printed.
glslrun::Program compile_or_fail(const std::string& vs, const std::string& fs,
                                 const glslrun::CompileOptions& options = {});
// A vertex shader with a trivial fragment shader (same #version line).
glslrun::Program compile_vs(const std::string& vs);
// A fragment shader with a vertex shader that declares and writes every
// non-built-in input as a varying float/vecN.
glslrun::Program compile_fs(const std::string& fs, const std::vector<glslrun::VertexAttrib>& inputs);

class Outputs {
public:
    Outputs(std::vector<glslrun::ShaderOutput> outputs, uint32_t count);
    // FAILs the test (listing the outputs present) if there is no such output.
    const glslrun::ShaderOutput& get(std::string_view name) const;
    bool has(std::string_view name) const;
    float at(std::string_view name, uint32_t lane, uint32_t comp = 0) const;
    glm::vec4 vec(std::string_view name, uint32_t lane) const;  // missing components read 0
    uint32_t count() const { return count_; }
    std::string names() const;
private:
    std::vector<glslrun::ShaderOutput> outputs_;
    uint32_t count_;
};

// Runs or FAILs with the run error printed.
Outputs run_vs(const glslrun::Program& program, const std::vector<glslrun::VertexAttrib>& attribs,
               uint32_t count = kVerts);
Outputs run_fs(const glslrun::Program& program, const std::vector<glslrun::VertexAttrib>& inputs,
               uint32_t count = kFrags);
// compile_vs + run_vs with std_attribs
Outputs eval_vs(const std::string& vs, uint32_t count = kVerts);
Outputs eval_vs(const std::string& vs, const std::vector<glslrun::VertexAttrib>& attribs, uint32_t count);
Outputs eval_fs(const std::string& fs, const std::vector<glslrun::VertexAttrib>& inputs,
                uint32_t count = kFrags);

// Compares the first `components` components of output `name` with
// expected(lane) on every lane: |got - want| <= tol * max(1, |want|).
// tol == 0 means exact. Reports up to 8 mismatching lanes.
using Expected = std::function<glm::vec4(uint32_t lane)>;
void check_output(const Outputs& outs, std::string_view name, uint32_t components,
                  const Expected& expected, float tol = 0.0f);
// The comparison behind check_output, without asserting; `report` lists the
// first mismatches.
int count_mismatches(const Outputs& outs, std::string_view name, uint32_t components,
                     const Expected& expected, float tol, std::string* report = nullptr);
inline constexpr float kExact = 0.0f;
inline constexpr float kTight = 1e-6f;  // plain arithmetic
inline constexpr float kLoose = 2e-5f;  // transcendental functions
// Any check's tolerance when the suite runs in Reference or Fast mode.
inline constexpr float kModeTolerance = 2e-5f;
// GLSLRUN_LANG_PRECISION (reference|precise|fast; default precise): the mode
// compile_or_fail gives every program.
glslrun::Precision suite_precision();
// GLSLRUN_LANG_BACKEND (interp|jit|auto; default jit where built in): the backend.
glslrun::Backend suite_backend();

// Fragment grid: quad q covers (x,y) (x+1,y) (x,y+1) (x+1,y+1), quads laid
// out 5 per row; this is the pixel position of fragment i.
glm::vec2 frag_xy(uint32_t i);

float b2f(bool b);

}  // namespace lang
