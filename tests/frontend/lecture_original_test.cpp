// The lecture's shaders as printed on its slides (shaders/lecture-original/):
// each typo must be reported at its own line with a message a student can act
// on. The corrected programs (shaders/) must all compile.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "frontend/compile.h"

namespace {

using namespace glslrun;

std::string read_file(const std::string& relative) {
    std::ifstream in(std::string(GLSLRUN_SOURCE_DIR) + "/" + relative);
    REQUIRE(in.good());
    std::stringstream buf;
    buf << in.rdbuf();
    return buf.str();
}

// Compiles `path` with a corrected partner for the other stage.
std::string first_error(const std::string& path) {
    ShaderSource shader{path, read_file(path)};
    ShaderSource partner = path.ends_with(".vert") ? ShaderSource{"partner.frag", "void main() { gl_FragColor = gl_Color; }\n"}
                                                   : ShaderSource{"partner.vert", read_file("shaders/pos_pix.vert")};
    bool is_vs = path.ends_with(".vert");
    auto r = frontend::compile_program(is_vs ? std::vector{shader} : std::vector{partner},
                                       is_vs ? std::vector{partner} : std::vector{shader}, {});
    REQUIRE_FALSE(r.ok());
    return r.error().str();
}

struct Typo {
    const char* file;
    int line;
    std::vector<const char*> phrases;  // all must appear in the first error
};

}  // namespace

TEST_CASE("each typo of the lecture's slides is reported at its line, with a hint", "[lecture]") {
    const std::vector<Typo> typos = {
        {"colors.vert", 5, {"'glColor' : undeclared identifier", "gl_FrontColor", "gl_Color"}},
        {"dir_vert_global.vert", 16, {"'emissive'", "did you mean 'emission'?"}},
        {"pos_pix.frag", 17, {"'FrontMaterial' : undeclared identifier", "did you mean 'gl_FrontMaterial'?"}},
        {"pos_pix_att_snippet.frag", 13, {"int / float", "1.0"}},
        {"dir_vert_specular_snippet.vert", 18, {"float > int", "0.0"}},
        {"spot_pix_fixed.frag", 31, {"float != int", "0.0"}},
    };
    for (const Typo& t : typos) {
        std::string path = std::string("shaders/lecture-original/") + t.file;
        std::string err = first_error(path);
        INFO(err);
        std::string first_line = err.substr(0, err.find('\n'));
        CHECK_THAT(first_line, Catch::StartsWith(fmt::format("{}:{}: error: ", path, t.line)));
        for (const char* phrase : t.phrases) CHECK_THAT(first_line, Catch::Contains(phrase));
    }
}

TEST_CASE("the missing ';' is reported at the line that lacks it, not the next", "[lecture]") {
    std::string err = first_error("shaders/lecture-original/pos_pix.frag");
    INFO(err);
    CHECK_THAT(err, Catch::Contains("pos_pix.frag:20: error: missing ';' at the end of this line"));
}

TEST_CASE("every corrected lecture program compiles and links", "[lecture]") {
    const char* programs[] = {"minimal", "colors", "matamb", "dir_vert_diffuse", "dir_vert_global", "dir_vert",
                              "dir_pix", "pos_pix", "spot_pix_oops", "spot_pix_fixed"};
    for (const char* p : programs) {
        std::string vs = fmt::format("shaders/{}.vert", p), fs = fmt::format("shaders/{}.frag", p);
        auto r = frontend::compile_program({{vs, read_file(vs)}}, {{fs, read_file(fs)}}, {});
        INFO(p << ": " << (r ? std::string() : r.error().str()));
        CHECK(r.ok());
    }
}
