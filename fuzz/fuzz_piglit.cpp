// libFuzzer target: the piglit file parsers (.shader_test sections and
// commands, glslparsertest's [config] block).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tools/glslrun/piglit_parse.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    namespace pg = glslrun::piglit;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto test = pg::parse_shader_test(text);
    if (pg::parsed_ok(test)) {
        const auto& t = std::get<pg::ShaderTest>(test);
        (void)pg::skip_reason(t);
        for (const auto& section : t.shaders) (void)pg::effective_source(section.text, t.require);
    }
    (void)pg::parse_parser_test(text);
    return 0;
}
