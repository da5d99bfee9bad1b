// `key value` lines (--bench, --error-report) as a map, for the tests of
// their formats: each line must have a value, and each key appear once.
#pragma once
#include <map>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

namespace scene_test {

inline std::map<std::string, std::string> parse_key_lines(const std::string& text) {
    std::map<std::string, std::string> values;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        size_t space = line.find(' ');
        REQUIRE(space != std::string::npos);
        std::string key = line.substr(0, space);
        REQUIRE(values.count(key) == 0);
        values[key] = line.substr(line.find_first_not_of(' ', space));
    }
    return values;
}

}  // namespace scene_test
