// The shader debugger's results: what one invocation did, line by line
// (glslrun trace), and where a NaN or infinity first appeared (--find-nan).
// docs/debugging.md shows them at work.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ir/ir.h"
#include "runtime/sampling.h"

namespace glslrun::debug {

// The components of a value, exact: floats as fp32 (double in Reference,
// `wide`), ints and bools (0/1) as integers.
struct Values {
    ir::Kind kind = ir::Kind::F32;
    bool wide = false;
    std::vector<double> c;
};

struct NamedValue {
    std::string name;
    std::string type;  // GLSL type ("vec3", "mat4"); decides how matrices print
    Values value;
};

struct TraceStep {
    enum class Kind : uint8_t {
        Statement,  // a statement runs: `where`
        Assign,     // `name` (a variable) now holds `value` (every component)
        Branch,     // an if at `where`: `taken`
        Loop,       // a loop at `where` starts iteration `iteration` (0, 1, ...)
        Jump,       // `name`: break, continue, return or discard
        Call,       // `name`: a call of that function starts; depth + 1 until it returns
        Lookup,     // a texture lookup at `where`: InvocationTrace::lookups[lookup]
    };
    Kind kind = Kind::Statement;
    int depth = 0;      // call depth
    std::string where;  // "file:line"
    uint32_t source = 0, line = 0;  // the same: an index into InvocationTrace::files, and the line
    std::string name;
    std::string type;
    Values value;
    bool taken = false;
    uint64_t iteration = 0;
    uint32_t lookup = 0;
};

// A texture lookup of the traced lane, as the sampler made it.
struct TextureLookup {
    int unit = 0;
    std::vector<std::string> samplers;  // the sampler uniforms that hold this unit
    ir::TexInfo info;                   // target, shadow, and how the LOD comes
    // The operands: the coordinates (projective lookups divided by q
    // already), the depth reference, and the explicit LOD or the bias.
    std::vector<float> coord;
    float ref = 0, lod = 0;
    rt::LookupDetails details;  // what the sampler computed and fetched
    std::array<float, 4> result{};  // the lookup's value in the shader's registers
};

// The first NaN or infinity of an invocation: the instruction that made it.
struct NanEvent {
    std::string where;
    std::string op;  // the IR operation, e.g. "fdiv"
    std::vector<Values> operands;
    Values result;
    std::string variable;  // the variable it was written to, if any
};

struct InvocationTrace {
    std::vector<NamedValue> inputs;    // shader inputs (varyings, gl_FragCoord, attributes)
    std::vector<NamedValue> uniforms;  // every uniform read, in first-read order
    std::vector<std::string> files;  // the shader's source names, for TraceStep::source
    std::vector<TraceStep> steps;
    std::vector<TextureLookup> lookups;  // of the Lookup steps
    std::vector<NamedValue> outputs;
    std::optional<NanEvent> first_nan;
    bool discarded = false;
    bool truncated = false;  // more steps than recorded (kMaxSteps, kMaxTraceSteps), or the run stopped early
    std::string stopped;     // why the run stopped early (a limit of debug.exec, its cancel flag), if it did
    static constexpr size_t kMaxSteps = 200000;
    // A texture lookup counts as three steps (LaneRecorder::cost).
    // All invocations of one trace together (a step takes about 225 bytes):
    // 20 fragments at a pixel, each a long loop, took 900 MB without it.
    static constexpr size_t kMaxTraceSteps = 1000000;
};

// "float", "vec3", "mat4", "bvec2", "sampler" for a uniform's type.
std::string type_name(const ir::ValueType& t);
// "float", "vec3", "ivec2", "bool" for a binding's registers.
std::string binding_type(const ir::Binding& b);
// "0.5", "vec3(1, 0, 0.25)", "mat2(vec2(1, 0), vec2(0, 1))"; matrices as
// GLSL's constructor takes them, by columns (for one-line messages).
std::string format_value(const Values& v, const std::string& type);
// Columns and rows of a "matN" / "matCxR" type (GLSL stores a matrix's
// components column by column); {1, count} for anything else.
std::pair<int, int> matrix_shape(const std::string& type, size_t count);
// A matrix on several lines, one row per line: how --stats and the trace
// show matrices. Not a matrix: format_value's one line.
std::vector<std::string> format_matrix_rows(const Values& v, const std::string& type);

}  // namespace glslrun::debug
