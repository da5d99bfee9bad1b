// What the text (format_trace.cpp) and the JSON (format_json.cpp) of a trace
// share: the names of outcomes, tests and GL's enums, and the source lines.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "debug/debugger.h"

namespace glslrun::debug::detail {

const char* outcome_key(FragmentTrace::Outcome o);  // "written", "depth_failed", ...
const char* func_name(CompareFunc f);                // "less", as the scene format names it
const char* result_key(FragmentTests::Result r);     // "off", "passed", "failed", "not_reached"
const char* factor_name(BlendFactor f);              // "one_minus_src_alpha"
const char* equation_name(BlendEquation e);          // "func_add"
const char* logic_name(LogicOp op);                  // "xor"

using SourceLines = std::map<std::string, std::vector<std::string>>;
// The trimmed text of a step's line; empty when its source is unknown.
std::string_view line_text(const SourceLines& lines, const InvocationTrace& t, const TraceStep& s);

}  // namespace glslrun::debug::detail
