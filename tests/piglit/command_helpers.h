// Parsing one [test] command line in the piglit tests: the parsed command of
// the expected kind, or the parse error; anything else fails the test.
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <string_view>

#include "tools/glslrun/piglit_parse.h"

namespace glslrun::piglit {

template <class T>
T cmd(std::string_view line) {
    auto p = parse_command(line);
    if (!parsed_ok(p)) FAIL("parse error for \"" << line << "\": " << std::get<ParseError>(p).message);
    const CommandData& d = std::get<CommandData>(p);
    if (!std::holds_alternative<T>(d)) FAIL("\"" << line << "\" parsed to alternative " << d.index());
    return std::get<T>(d);
}

inline std::string parse_error(std::string_view line) {
    auto p = parse_command(line);
    if (parsed_ok(p)) FAIL("\"" << line << "\" parsed, but should not");
    return std::get<ParseError>(p).message;
}

inline bool is_error(std::string_view line) { return !parsed_ok(parse_command(line)); }

}  // namespace glslrun::piglit
