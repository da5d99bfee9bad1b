// GLSL's undefined operations, found at run time (`glslrun --check-undefined`,
// docs/debugging.md): pow of x < 0, log of x <= 0, division by zero, an array
// index out of range, int overflow, a read of a variable never written, ... The scene is rendered with the
// programs compiled with CompileOptions::check_undefined; every operation
// that GLSL 1.10/1.20 leaves undefined for the operands it gets is counted per
// source position, with the first invocation (draw and tile order) that
// computed it and what each precision mode and NVIDIA's GPU return for it.
// The findings are the same in every precision mode and on both backends,
// except where a mode's own rounding changes an operand.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "glslrun/scene/scene.h"

namespace glslrun::scene {

// The first invocation that computed a finding's operation.
struct UndefinedInvocation {
    bool vertex = false;     // a vertex (else a fragment)
    uint32_t draw = 0;       // the scene's draws counted over every pass, from 0
    uint32_t vertex_index = 0;  // vertices: the draw's vertex
    int x = 0, y = 0;        // fragments: image coordinates, top-left origin
    bool in_target = false;  // the pass draws into a render target: x, y are the target's
    std::string pass;        // the scene pass's name; empty in a scene without passes
    std::string program;     // its shaders: "a.vert + a.frag"
    std::vector<double> operands;  // as the source passes them (pow(x, y): x, y)
};

struct UndefinedFinding {
    std::string op;         // "pow", "float division", "array index", ...
    std::string condition;  // "pow(x, y) with x < 0, or x = 0 and y <= 0"
    bool vertex = false;    // in a vertex shader (else a fragment shader)
    std::string file;       // ShaderSource::name
    // column: where glslang places the call or operator (a token of it, not
    // always the first); 0 where unknown.
    int line = 0, column = 0;
    std::string line_text;  // the source line, trimmed
    uint64_t count = 0;     // invocations that computed it at least once
    UndefinedInvocation first;
    // What glslrun's precision modes return for `first`'s operands, in the
    // order reference, precise, fast (NaN included); `value_note` says what
    // the numbers mean where they are not the operation's result (the
    // element an out-of-range index reads).
    std::array<double, 3> mode_values{};
    std::string value_note;
    // What NVIDIA's OpenGL driver returns for such operands, measured on an
    // H200 (docs/debugging.md), or "" where the measurement did not cover them.
    std::string gpu;
};

struct UndefinedReport {
    std::vector<UndefinedFinding> findings;  // by file, line, column
    uint32_t draws = 0;                      // draws looked at
    std::vector<Diagnostic> warnings;        // the scene's (ScenePrograms::warnings)
};

// Renders `scene` with the programs of `vertex` and `fragment` (and its
// passes' own) compiled with `compile` and checks, on one thread, with
// `exec`'s precision, backend and limits, into `fb` (the same image as
// without checks), and returns what the checks found.
Result<UndefinedReport> check_undefined(const std::vector<ShaderSource>& vertex,
                                        const std::vector<ShaderSource>& fragment, const Scene& scene,
                                        const ExecOptions& exec, Framebuffer& fb, CompileOptions compile = {});
// The same into a framebuffer of the scene's size, thrown away.
Result<UndefinedReport> check_undefined(const std::vector<ShaderSource>& vertex,
                                        const std::vector<ShaderSource>& fragment, const Scene& scene,
                                        const ExecOptions& exec = {}, CompileOptions compile = {});

// The report as the command line prints it: one block per finding, or a
// line saying that nothing was found.
std::string format_undefined(const UndefinedReport& report);

}  // namespace glslrun::scene
