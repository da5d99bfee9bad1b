// Parsing of piglit's test formats: shader_runner's .shader_test scripts and
// glslparsertest's .vert/.frag files with a [config] block. Pure text
// processing: no file I/O beyond what the caller passes in, and nothing from
// the glslrun library, so the parser can be unit-tested on its own.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frontend/source_rewrite.h"  // kExtraExtensions: a constant, no code
#include "glslrun/glslrun.h"

namespace glslrun::piglit {

struct ParseError {
    int line = 0;  // 0: not tied to a line
    std::string message;
    std::string str() const;  // "line N: message"
};

template <class T>
using Parsed = std::variant<T, ParseError>;

template <class T>
bool parsed_ok(const Parsed<T>& p) { return p.index() == 0; }

// ------------------------------------------------------------ sections ---
enum class ShaderStage { Vertex, Fragment };

struct ShaderSection {
    ShaderStage stage = ShaderStage::Vertex;
    std::string label;       // "[vertex shader]", used in diagnostics
    std::string text;        // the section's lines, as written
    std::string file;        // [... shader file]: the file to load instead of text
    int first_line = 0;      // file line of the section's first text line
};

// What the [require] section asks for, and what it could not express.
struct Requirements {
    int glsl_version = 0;      // 110, 120, ...; 0 when missing
    bool glsl_es = false;
    int gl_version = 0;        // 20, 21, ...; 0 when missing
    bool gl_es = false;
    int width = 250, height = 250;
    std::vector<std::string> extensions;        // required ("GL_ARB_foo")
    std::vector<std::string> absent_extensions; // "!GL_ARB_foo"
    struct Limit { std::string name; std::string op; long value = 0; };
    std::vector<Limit> limits;  // GL_MAX_VARYING_COMPONENTS >= 52, ...
};

// What glslrun can do; requirements are judged against this.
struct Capabilities {
    int max_glsl_version = 120;
    int max_gl_version = 21;
    long max_varying_components = 64;
    long max_fragment_uniform_components = 16384;
    long max_vertex_uniform_components = 16384;
    long max_vertex_attribs = 16;
    long max_clip_planes = 6;
    // The extensions a test may require, or require to be absent (frontend/source_rewrite.h).
    std::vector<std::string> extensions = [] {
        std::vector<std::string> all{frontend::kExtraExtensions.begin(), frontend::kExtraExtensions.end()};
        all.insert(all.end(), frontend::kDefaultExtensions.begin(), frontend::kDefaultExtensions.end());
        all.insert(all.end(), frontend::kOptionalExtensions.begin(), frontend::kOptionalExtensions.end());
        return all;
    }();
    bool has_extension(const std::string& name) const {
        return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
    }
};

// ------------------------------------------------------------ commands ---
struct ClearColor { std::array<float, 4> rgba{}; };
struct ClearDepth { float depth = 1; };
struct Clear {};
struct DrawRect {
    bool ortho = false;  // x y w h in window coordinates
    bool tex = false;
    std::array<float, 4> rect{};
    std::array<float, 4> tex_rect{};
};
struct DrawArrays { std::string mode; int first = 0; int count = 0; };
struct Ortho { std::optional<std::array<float, 4>> lrbt; };  // none: the window
struct Frustum { std::array<float, 6> lrbtnf{}; };
struct SetUniform {
    std::string type;  // "vec4", "mat3x2", "int", ...
    std::string name;  // "a", "a[2]", "s.f"
    bool integer = false;           // ints holds the values, else floats
    std::vector<float> floats;
    std::vector<int32_t> ints;
};
struct Probe {
    enum class Region { Pixel, Rect, All } region = Region::Pixel;
    bool relative = false;  // coordinates are fractions of the window
    bool rgba = false;      // else rgb
    bool warn = false;      // a mismatch gives a warning, not a failure
    std::array<float, 4> rect{};   // x y (w h)
    std::array<float, 4> color{};
};
struct ProbeDepth { int x = 0, y = 0; float depth = 0; };
struct LinkCheck { bool expect_success = true; };
struct Enable { std::string cap; bool on = true; };
struct DepthFunc { glslrun::CompareFunc func = glslrun::CompareFunc::Less; };  // glDepthFunc
struct ClipPlane { int index = 0; std::array<double, 4> plane{}; };
struct ShadeModel { bool flat = false; };
struct CurrentColor { std::array<float, 4> rgba{}; };
struct Light { int index = 0; std::string param; std::vector<float> values; };
struct Tolerance { std::array<float, 4> tol{}; };
// "texture rgbw|checkerboard|shadow1D|shadow2D ...": shader_runner makes a new
// texture on `unit`, binds it there and leaves that unit active.
struct TextureCommand {
    enum class Kind { Rgbw, Rgbw1D, Rgbw3D, Miptree, Checkerboard, Shadow1D, Shadow2D, ShadowRect, Rgbw1DArray,
                      Rgbw2DArray, Shadow1DArray, Shadow2DArray } kind = Kind::Rgbw;
    int unit = 0;
    int level = 0;                 // checkerboard: the mip level it writes
    int width = 1, height = 1;     // rgbw/checkerboard/shadow (1D: height 1)
    int layers = 1;                // the array textures (EXT_texture_array)
    std::string format;            // rgbw: the internal format named after the size, "" = GL_RGBA
    bool float_format = false;     // that format stores floats (GL_RGBA32F, ...), else 8-bit unorm
    std::array<float, 4> black{}, white{};  // checkerboard colours
};
// "texparameter <target> <name> <value>": glTexParameter on the texture bound
// to <target> of the active unit.
struct TexParameter {
    enum class Target { Tex1D, Tex2D, Tex3D, Cube, Rect, Tex1DArray, Tex2DArray } target = Target::Tex2D;
    enum class Name { CompareFunc, DepthMode, Min, Mag, WrapS, WrapT, WrapR, LodBias, MaxLevel,
                      BaseLevel, BorderColor } name = Name::CompareFunc;
    std::string value;             // enum values as written ("greater", "linear_mipmap_nearest")
    std::array<float, 4> numbers{};  // lod_bias, max/base_level: [0]; border_color: all four
};
struct Ignored {};                           // hint, ...
struct Unsupported { std::string reason; };  // makes the test skip

using CommandData = std::variant<ClearColor, ClearDepth, Clear, DrawRect, DrawArrays, Ortho,
                                 Frustum, SetUniform, Probe, ProbeDepth, LinkCheck, Enable,
                                 DepthFunc, ClipPlane, ShadeModel, CurrentColor, Light, Tolerance,
                                 TextureCommand, TexParameter, Ignored, Unsupported>;
struct Command {
    int line = 0;
    CommandData data;
};

// [vertex data]: one column per attribute component group.
struct VertexColumn {
    std::string name;  // GLSL attribute name ("vertex", "gl_Vertex", ...)
    std::string type;  // float, int, uint
    uint32_t components = 1;
};
struct VertexData {
    std::vector<VertexColumn> columns;
    std::vector<std::vector<float>> per_column;  // components floats per row
    uint32_t rows = 0;
    int first_line = 0;
};

struct ShaderTest {
    Requirements require;
    bool has_require = false;
    std::vector<ShaderSection> shaders;
    std::optional<VertexData> vertex_data;
    bool has_test_section = false;
    std::vector<Command> commands;
    std::optional<std::string> skip_reason;  // an unsupported section, ...
};

Parsed<ShaderTest> parse_shader_test(std::string_view text);

// Why the test cannot run here, judged from [require] and the commands; none if it can.
std::optional<std::string> skip_reason(const ShaderTest& test, const Capabilities& caps = {});

// The text handed to the compiler: piglit prepends "#version N" (from
// "GLSL >= N") to any shader that does not contain "#version ".
std::string effective_source(const std::string& text, const Requirements& require);

// The pass-through vertex shader of [vertex shader passthrough].
std::string passthrough_vertex_shader();

// Parses one command line of [test] (without its newline). Empty lines and
// '#' comments give Ignored.
Parsed<CommandData> parse_command(std::string_view line);

// -------------------------------------------------------- glslparsertest ---
struct ParserTest {
    bool expect_pass = true;
    int glsl_version = 110;      // 110, 120, ...
    bool glsl_es = false;
    bool check_link = false;
    std::vector<std::string> extensions;
};
// Reads the "[config]" ... "[end config]" block (in // or /* */ comments).
Parsed<ParserTest> parse_parser_test(std::string_view text);

// ------------------------------------------------------------ helpers ---
// strtod-like number lists: "1.0 -2 0x3f800000" (0x...: the bits of a float,
// as piglit's parse_floats). Stops at the first thing that is not a number.
std::vector<float> parse_float_list(std::string_view s, size_t* consumed = nullptr);
std::vector<int32_t> parse_int_list(std::string_view s, size_t* consumed = nullptr);
std::string_view trim(std::string_view s);

}  // namespace glslrun::piglit
