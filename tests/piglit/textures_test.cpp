// shader_runner's texture commands: parsing, the textures piglit's helpers
// build, texparameter, and texture tests end to end.
#include <catch2/catch.hpp>

#include "tests/piglit/command_helpers.h"
#include "tools/glslrun/piglit_exec.h"
#include "tools/glslrun/piglit_textures.h"

using namespace glslrun::piglit;
using glslrun::CompareFunc;
using glslrun::DepthTextureMode;
using glslrun::GLState;
using glslrun::TextureFilter;
using glslrun::TextureFormat;
using glslrun::TextureTarget;
using glslrun::TextureWrap;

namespace {

const glm::vec4 kRed{1, 0, 0, 1}, kGreen{0, 1, 0, 1}, kBlue{0, 0, 1, 1}, kWhite{1, 1, 1, 1};

glm::vec4 texel(const glslrun::TextureImage& img, int x, int y, int z = 0) {
    return img.texels[size_t(x + img.width * (y + img.height * z))];
}

glslrun::Texture made(const TextureCommand& c) {
    auto t = make_texture(c);
    if (!t) FAIL(t.error().str());
    return std::move(*t);
}

std::string make_error(const TextureCommand& c) {
    auto t = make_texture(c);
    if (t) FAIL("make_texture succeeded, but should not");
    return t.error().str();
}

TestResult run(const std::string& text) { return run_shader_test(text, ".", RunOptions{}); }

const std::string kTexturedRect = R"([require]
GLSL >= 1.10

[vertex shader]
varying vec2 tc;
void main() { gl_Position = gl_Vertex; tc = gl_MultiTexCoord0.xy; }

[fragment shader]
uniform sampler2D tex;
varying vec2 tc;
void main() { gl_FragColor = texture2D(tex, tc); }

[test]
)";

}  // namespace

// ------------------------------------------------------------------ parsing ---
TEST_CASE("texture command syntax", "[piglit][textures]") {
    TextureCommand t = cmd<TextureCommand>("texture rgbw 1 (8, 4)");
    CHECK(t.kind == TextureCommand::Kind::Rgbw);
    CHECK(t.unit == 1);
    CHECK(t.width == 8);
    CHECK(t.height == 4);
    CHECK(t.format.empty());
    CHECK_FALSE(t.float_format);

    t = cmd<TextureCommand>("texture rgbw 0 (16,16) GL_RGBA32F");
    CHECK(t.format == "GL_RGBA32F");
    CHECK(t.float_format);
    CHECK(cmd<TextureCommand>("texture rgbw 0 ( 2 , 2 ) GL_RGBA8").float_format == false);

    CHECK(cmd<TextureCommand>("texture rgbw 1D 3").kind == TextureCommand::Kind::Rgbw1D);
    t = cmd<TextureCommand>("texture rgbw 3D 2");
    CHECK(t.kind == TextureCommand::Kind::Rgbw3D);
    CHECK(t.unit == 2);

    t = cmd<TextureCommand>("texture checkerboard 1 0 (8, 8) (0.0, 0.0, 0.0, 0.0) (1.0, 0.5, 0.25, 1)");
    CHECK(t.kind == TextureCommand::Kind::Checkerboard);
    CHECK(t.unit == 1);
    CHECK(t.level == 0);
    CHECK(t.black == std::array<float, 4>{0, 0, 0, 0});
    CHECK(t.white == std::array<float, 4>{1, 0.5f, 0.25f, 1});

    t = cmd<TextureCommand>("texture shadow1D 0 (32)");
    CHECK(t.kind == TextureCommand::Kind::Shadow1D);
    CHECK(t.width == 32);
    CHECK(t.height == 1);
    t = cmd<TextureCommand>("texture shadow2D 3 (32, 16)");
    CHECK(t.kind == TextureCommand::Kind::Shadow2D);
    CHECK(t.unit == 3);
    CHECK(t.height == 16);
    t = cmd<TextureCommand>("texture shadowRect 2 (32, 16)");
    CHECK(t.kind == TextureCommand::Kind::ShadowRect);
    CHECK(t.unit == 2);
    CHECK(t.height == 16);
    CHECK(cmd<TexParameter>("texparameter Rect compare_func never").target == TexParameter::Target::Rect);
}

TEST_CASE("texparameter syntax", "[piglit][textures]") {
    TexParameter p = cmd<TexParameter>("texparameter 2D compare_func greater");
    CHECK(p.target == TexParameter::Target::Tex2D);
    CHECK(p.name == TexParameter::Name::CompareFunc);
    CHECK(p.value == "greater");
    p = cmd<TexParameter>("texparameter 1D depth_mode intensity");
    CHECK(p.target == TexParameter::Target::Tex1D);
    CHECK(p.name == TexParameter::Name::DepthMode);
    CHECK(cmd<TexParameter>("texparameter 3D min linear_mipmap_nearest").name == TexParameter::Name::Min);
    CHECK(cmd<TexParameter>("texparameter Cube mag linear").target == TexParameter::Target::Cube);
    CHECK(cmd<TexParameter>("texparameter 2D wrap_t clamp_to_border").name == TexParameter::Name::WrapT);
    CHECK(cmd<TexParameter>("texparameter 2D lod_bias -1.5").numbers[0] == -1.5f);
    CHECK(cmd<TexParameter>("texparameter 2D max_level 3").numbers[0] == 3);
    p = cmd<TexParameter>("texparameter 2D border_color 0.5 0 1 1");
    CHECK(p.numbers == std::array<float, 4>{0.5f, 0, 1, 1});
}

TEST_CASE("malformed texture commands are parse errors", "[piglit][textures][malformed]") {
    CHECK(parse_error("texture rgbw 0 8, 8") == "bad texture rgbw command \"texture rgbw 0 8, 8\"");
    parse_error("texture rgbw 0 (8)");
    parse_error("texture rgbw (8, 8)");
    parse_error("texture rgbw 0 (8, 8.5)");
    parse_error("texture rgbw 0 (99999999999, 8)");  // does not fit an int
    parse_error("texture checkerboard 0 0 (8, 8) (0, 0, 0, 0)");
    parse_error("texture checkerboard 0 0 (8, 8) (0, 0, 0) (1, 1, 1, 1)");
    parse_error("texture shadow1D 0");
    parse_error("texture shadow2D 0 (32)");
    parse_error("texture rgbw 3D");
    CHECK(parse_error("texparameter 4D min nearest").find("bad texture target \"4D\"") == 0);
    CHECK(parse_error("texparameter 2D compare_func bigger") == "bad compare_func \"bigger\"");
    CHECK(parse_error("texparameter 2D mag nearest_mipmap_nearest") == "bad mag \"nearest_mipmap_nearest\"");
    CHECK(parse_error("texparameter 2D wrap_q repeat") == "unknown texture parameter \"wrap_q\"");
    parse_error("texparameter 2D border_color 1 0 0");
    parse_error("texparameter 2D max_level many");
    parse_error("texparameter");
}

TEST_CASE("texture variants that need GL 3 or extensions skip", "[piglit][textures]") {
    CHECK(cmd<Unsupported>("texture rgbw 0 (8, 8) GL_RGBA8UI").reason ==
          "texture format GL_RGBA8UI is not supported");
    cmd<Unsupported>("texture integer 0 (8, 8) (0, 0) GL_RGBA8I");
    cmd<Unsupported>("texparameter CubeArray compare_func greater");
    cmd<Unsupported>("texparameter 2D swizzle_r green");
    cmd<Unsupported>("texparameter 2D depth_mode red");
    cmd<Unsupported>("texcoord 0 (0, 0, 0, 1)");
}

TEST_CASE("array textures (EXT_texture_array): piglit_array_texture's layers and the depth ramps",
          "[piglit][textures]") {
    auto one = cmd<TextureCommand>("texture rgbw 1DArray 2 (8, 3)");
    CHECK((one.kind == TextureCommand::Kind::Rgbw1DArray && one.unit == 2 && one.width == 8 && one.layers == 3));
    auto two = cmd<TextureCommand>("texture shadow2DArray 0 (4, 2, 5)");
    CHECK((two.kind == TextureCommand::Kind::Shadow2DArray && two.width == 4 && two.height == 2 && two.layers == 5));
    CHECK(cmd<TexParameter>("texparameter 1DArray min linear").target == TexParameter::Target::Tex1DArray);
    parse_error("texture rgbw 2DArray 0 (8, 8)");
    parse_error("texture shadow1DArray 0 (8)");
    // Layer l is colour l mod 4 of red, green, blue, white; a 1D array's layers are its rows.
    auto t = make_texture(one);
    REQUIRE(t);
    CHECK(t->target() == TextureTarget::Tex1DArray);
    const glslrun::TextureImage& img = t->levels(0)[0];
    CHECK((img.width == 8 && img.height == 3 && img.depth == 1));
    CHECK(texel(img, 5, 1) == kGreen);
    CHECK(texel(img, 0, 2) == kBlue);
    CHECK(t->sampler.min_filter == TextureFilter::Nearest);
    auto d = make_texture(two);
    REQUIRE(d);
    CHECK((d->target() == TextureTarget::Tex2DArray && d->depth() && d->sampler.compare));
    CHECK(d->levels(0)[0].depth == 5);
    CHECK(texel(d->levels(0)[0], 3, 1, 4).r == 1.0f);  // layer 4, x = 3: the ramp's end
    CHECK(texel(d->levels(0)[0], 0, 1, 4).r == 0.0f);
}

// ------------------------------------------------------------------- images ---
TEST_CASE("rgbw image: red, green at the bottom, blue, white at the top", "[piglit][textures]") {
    auto img = rgbw_image(8, 4);
    REQUIRE(img.texels.size() == 32);
    CHECK(texel(img, 0, 0) == kRed);
    CHECK(texel(img, 3, 1) == kRed);
    CHECK(texel(img, 4, 0) == kGreen);
    CHECK(texel(img, 7, 1) == kGreen);
    CHECK(texel(img, 0, 2) == kBlue);
    CHECK(texel(img, 3, 3) == kBlue);
    CHECK(texel(img, 4, 2) == kWhite);
    CHECK(texel(img, 7, 3) == kWhite);
    // Odd sizes: the middle column/row belongs to the right/top half (x < w/2).
    auto odd = rgbw_image(3, 1);
    CHECK(texel(odd, 0, 0) == kBlue);  // h / 2 == 0: every row is a top row
    CHECK(texel(odd, 1, 0) == kWhite);
}

TEST_CASE("fixed rgbw 1D and 3D images", "[piglit][textures]") {
    auto one = rgbw_1d_image();
    CHECK(one.width == 4);
    CHECK(one.texels == std::vector<glm::vec4>{kRed, kGreen, kBlue, kWhite});
    auto three = rgbw_3d_image();
    CHECK(three.depth == 2);
    CHECK(texel(three, 0, 0, 0) == kRed);
    CHECK(texel(three, 1, 1, 0) == kWhite);
    CHECK(texel(three, 0, 0, 1) == glm::vec4(1, 1, 0, 1));
    CHECK(texel(three, 1, 1, 1) == glm::vec4(0, 0, 0, 1));
}

TEST_CASE("checkerboard image: w/2 x h/2 tiles, the first colour bottom-left", "[piglit][textures]") {
    glm::vec4 b{0, 0, 0, 0}, w{0, 1, 0, 0};
    auto img = checkerboard_image(8, 8, b, w);
    CHECK(texel(img, 0, 0) == b);
    CHECK(texel(img, 3, 3) == b);
    CHECK(texel(img, 4, 0) == w);
    CHECK(texel(img, 0, 4) == w);
    CHECK(texel(img, 7, 7) == b);
    auto odd = checkerboard_image(5, 2, b, w);  // tiles 2x1; column 4 starts a third tile
    CHECK(texel(odd, 4, 0) == b);
    CHECK(texel(odd, 2, 0) == w);
    CHECK(texel(odd, 2, 1) == b);
}

TEST_CASE("depth ramp: x / (w - 1) on every row", "[piglit][textures]") {
    auto img = depth_ramp_image(5, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 5; ++x) CHECK(texel(img, x, y).r == float(x) / 4.0f);
    CHECK(depth_ramp_image(1, 1).texels[0].r == 0.0f);  // piglit's 0/0
}

// ----------------------------------------------------------------- textures ---
TEST_CASE("texture objects carry shader_runner's sampler state", "[piglit][textures]") {
    TextureCommand c;
    c.width = c.height = 8;
    glslrun::Texture rgbw = made(c);
    CHECK(rgbw.target() == TextureTarget::Tex2D);
    CHECK(rgbw.format() == TextureFormat::RGBA8);
    CHECK(rgbw.levels(0).size() == 1);  // mip = GL_FALSE: no mipmaps
    CHECK(rgbw.sampler.min_filter == TextureFilter::Nearest);
    CHECK(rgbw.sampler.mag_filter == TextureFilter::Nearest);
    CHECK(rgbw.sampler.wrap_s == TextureWrap::ClampToEdge);
    CHECK(rgbw.sampler.wrap_t == TextureWrap::ClampToEdge);
    CHECK_FALSE(rgbw.sampler.compare);

    c.float_format = true;
    CHECK(made(c).format() == TextureFormat::RGBA32F);

    c = {};
    c.kind = TextureCommand::Kind::Checkerboard;
    c.width = c.height = 8;
    c.black = {0.01f, 0, 0, 0};
    glslrun::Texture board = made(c);
    CHECK(board.format() == TextureFormat::RGBA8);
    CHECK(board.sampler.wrap_s == TextureWrap::ClampToBorder);
    CHECK(board.sampler.border_color == kRed);
    CHECK(board.sampler.min_filter == TextureFilter::Nearest);
    // GL_RGBA8 stores 0.01 as 3/255: glsl-fs-lots-of-tex adds 34 of them and expects 0.4.
    CHECK(board.levels(0)[0].texels[0].r == Approx(3.0 / 255.0));

    c = {};
    c.kind = TextureCommand::Kind::Shadow1D;
    c.width = 32;
    glslrun::Texture shadow = made(c);
    CHECK(shadow.target() == TextureTarget::Tex1D);
    CHECK(shadow.depth());
    CHECK(shadow.sampler.compare);
    CHECK(shadow.sampler.compare_func == CompareFunc::Greater);
    CHECK(shadow.sampler.depth_mode == DepthTextureMode::Luminance);
    CHECK(shadow.levels(0)[0].texels[31].r == 1.0f);

    c.kind = TextureCommand::Kind::Rgbw3D;
    glslrun::Texture cube = made(c);
    CHECK(cube.target() == TextureTarget::Tex3D);
    CHECK(cube.sampler.wrap_r == TextureWrap::ClampToEdge);
}

TEST_CASE("bad texture sizes are clear errors, never allocations", "[piglit][textures][malformed]") {
    TextureCommand c;
    c.width = 0;
    c.height = 5;
    CHECK(make_error(c).find("texture size 0x5 is empty") != std::string::npos);
    c.width = -3;
    CHECK(make_error(c).find("is empty") != std::string::npos);
    c.width = c.height = 100000;
    CHECK(make_error(c).find("exceeds the maximum texture size 16384") != std::string::npos);
    c.width = c.height = 16384;  // GL allows it, but it would be 4 GiB of texels here
    CHECK(make_error(c).find("the piglit runner allows at most") != std::string::npos);
    c.kind = TextureCommand::Kind::Checkerboard;
    c.width = 1;
    c.height = 8;
    CHECK(make_error(c).find("at least 2x2") != std::string::npos);
    c.kind = TextureCommand::Kind::Shadow1D;
    c.width = 20000;
    CHECK(make_error(c).find("texture size 20000 exceeds") != std::string::npos);
}

TEST_CASE("texture commands bind on their unit and make it active", "[piglit][textures]") {
    GLState gl;
    TextureState state;
    TextureCommand c;
    c.unit = 3;
    c.width = c.height = 2;
    REQUIRE(run_texture_command(gl, state, c).ok());
    CHECK(state.active_unit == 3);
    CHECK(gl.texture_units[3].bound[size_t(TextureTarget::Tex2D)] != nullptr);
    CHECK(gl.texture_units[0].bound[size_t(TextureTarget::Tex2D)] == nullptr);

    c.unit = 16;
    auto st = run_texture_command(gl, state, c);
    REQUIRE_FALSE(st.ok());
    CHECK(st.error().str().find("texture unit 16 is out of range") != std::string::npos);
    CHECK(state.active_unit == 3);
    c.unit = -1;
    CHECK_FALSE(run_texture_command(gl, state, c).ok());

    // A checkerboard at level 1 has no level 0: incomplete, like no texture at all.
    c = {};
    c.kind = TextureCommand::Kind::Checkerboard;
    c.unit = 3;
    c.level = 1;
    c.width = c.height = 8;
    REQUIRE(run_texture_command(gl, state, c).ok());
    CHECK(gl.texture_units[3].bound[size_t(TextureTarget::Tex2D)] == nullptr);
}

TEST_CASE("texparameter changes the texture of the active unit's target", "[piglit][textures]") {
    GLState gl;
    TextureState state;
    TextureCommand c;
    c.kind = TextureCommand::Kind::Shadow2D;
    c.unit = 1;
    c.width = c.height = 4;
    REQUIRE(run_texture_command(gl, state, c).ok());
    auto before = gl.texture_units[1].bound[size_t(TextureTarget::Tex2D)];

    auto param = [&](std::string_view line) {
        auto st = run_texparameter(gl, state, cmd<TexParameter>(line));
        if (!st) FAIL(st.error().str());
        return gl.texture_units[1].bound[size_t(TextureTarget::Tex2D)]->sampler;
    };
    CHECK(param("texparameter 2D compare_func never").compare_func == CompareFunc::Never);
    CHECK(param("texparameter 2D depth_mode alpha").depth_mode == DepthTextureMode::Alpha);
    CHECK(param("texparameter 2D min linear_mipmap_linear").min_filter == TextureFilter::LinearMipmapLinear);
    CHECK(param("texparameter 2D mag linear").mag_filter == TextureFilter::Linear);
    CHECK(param("texparameter 2D wrap_s repeat").wrap_s == TextureWrap::Repeat);
    CHECK(param("texparameter 2D wrap_r clamp_to_border").wrap_r == TextureWrap::ClampToBorder);
    CHECK(param("texparameter 2D lod_bias 2.5").lod_bias == 2.5f);
    CHECK(param("texparameter 2D base_level 1").base_level == 1);
    CHECK(param("texparameter 2D max_level 2").max_level == 2);
    CHECK(param("texparameter 2D border_color 0 1 0 1").border_color == kGreen);
    // The texture object that was bound is not changed in place (draws share it).
    CHECK(before->sampler.compare_func == CompareFunc::Greater);

    // 1D on unit 1 has no texture: GL changes texture object 0, nothing visible here.
    CHECK(run_texparameter(gl, state, cmd<TexParameter>("texparameter 1D compare_func less")).ok());
    CHECK(gl.texture_units[1].bound[size_t(TextureTarget::Tex1D)] == nullptr);
    auto st = run_texparameter(gl, state, cmd<TexParameter>("texparameter 2D max_level -1"));
    CHECK_FALSE(st.ok());
}

// --------------------------------------------------------------- end to end ---
TEST_CASE("texture rgbw and draw rect tex end to end", "[piglit][textures][exec]") {
    TestResult r = run(kTexturedRect + R"(uniform int tex 0
texture rgbw 0 (8, 8)
draw rect tex -1 -1 2 2 0 0 1 1
relative probe rgba (0.25, 0.25) (1.0, 0.0, 0.0, 1.0)
relative probe rgba (0.75, 0.25) (0.0, 1.0, 0.0, 1.0)
relative probe rgba (0.25, 0.75) (0.0, 0.0, 1.0, 1.0)
relative probe rgba (0.75, 0.75) (1.0, 1.0, 1.0, 1.0)
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("a sampler reads the unit its uniform names", "[piglit][textures][exec]") {
    TestResult r = run(kTexturedRect + R"(uniform int tex 1
texture checkerboard 0 0 (8, 8) (1, 0, 0, 1) (1, 0, 0, 1)
texture checkerboard 1 0 (8, 8) (0, 0, 1, 1) (0, 0, 1, 1)
draw rect tex -1 -1 2 2 0 0 1 1
probe all rgba 0 0 1 1
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("shadow textures and texparameter end to end", "[piglit][textures][exec]") {
    const std::string test = R"([require]
GLSL >= 1.10

[vertex shader]
varying vec4 texcoords;
void main() { gl_Position = gl_Vertex; texcoords = (gl_Vertex + 1.0) / 2.0; }

[fragment shader]
uniform sampler2DShadow tex;
varying vec4 texcoords;
void main() { gl_FragColor = shadow2D(tex, texcoords.xyy); }

[test]
uniform int tex 0
texture shadow2D 0 (32, 32)
)";
    // GL_GREATER: lit where the reference (t) is greater than the depth (s).
    TestResult r = run(test + R"(draw rect -1 -1 2 2
relative probe rgba (0.1, 0.9) (1.0, 1.0, 1.0, 1.0)
relative probe rgba (0.9, 0.1) (0.0, 0.0, 0.0, 1.0)
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
    r = run(test + R"(texparameter 2D depth_mode intensity
texparameter 2D compare_func always
draw rect -1 -1 2 2
probe all rgba 1 1 1 1
texparameter 2D compare_func never
draw rect -1 -1 2 2
probe all rgba 0 0 0 0
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("texture miptree: 8x8 with a colour per level, sampled nearest per level", "[piglit][textures]") {
    auto c = cmd<TextureCommand>("texture miptree 2");
    CHECK(c.kind == TextureCommand::Kind::Miptree);
    CHECK(c.unit == 2);
    auto t = make_texture(c);
    REQUIRE(t);
    REQUIRE(t->levels(0).size() == 4);
    CHECK(t->levels(0)[0].width == 8);
    CHECK(t->levels(0)[3].width == 1);
    CHECK(texel(t->levels(0)[1], 0, 0) == kGreen);
    CHECK(texel(t->levels(0)[3], 0, 0) == kWhite);
    CHECK(t->sampler.min_filter == TextureFilter::NearestMipmapNearest);
    CHECK(t->complete());
}

TEST_CASE("shadowRect and texparameter Rect end to end", "[piglit][textures][exec]") {
    // As piglit's glsl-fs-shadow2DRect tests: texel x of the 32x32 ramp holds
    // x / 31, compared GREATER with the reference t; coordinates in texels.
    const std::string test = R"([require]
GLSL >= 1.10
GL_ARB_texture_rectangle

[vertex shader]
varying vec4 texcoords;
void main() { gl_Position = gl_Vertex; texcoords = (gl_Vertex + 1.0) / 2.0; }

[fragment shader]
uniform sampler2DRectShadow tex;
varying vec4 texcoords;
void main() { gl_FragColor = shadow2DRect(tex, texcoords.xyy * vec3(31.0, 31.0, 1.0)); }

[test]
uniform int tex 0
texture shadowRect 0 (32, 32)
)";
    TestResult r = run(test + R"(draw rect -1 -1 2 2
relative probe rgba (0.1, 0.9) (1.0, 1.0, 1.0, 1.0)
relative probe rgba (0.9, 0.1) (0.0, 0.0, 0.0, 1.0)
texparameter Rect depth_mode alpha
texparameter Rect compare_func always
draw rect -1 -1 2 2
probe all rgba 0 0 0 1
)");
    INFO(r.message);
    CHECK(r.outcome == Outcome::Pass);
}

TEST_CASE("bad texture commands fail with their line", "[piglit][textures][exec]") {
    TestResult r = run(kTexturedRect + "texture rgbw 0 (0, 5)\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message == "line 14: texture size 0x5 is empty: every dimension must be at least 1");
    r = run(kTexturedRect + "texture rgbw 16 (8, 8)\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.find("line 14: texture unit 16 is out of range") == 0);
    r = run(kTexturedRect + "texture rgbw 0 (100000, 100000)\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.find("exceeds the maximum texture size") != std::string::npos);
    r = run(kTexturedRect + "texparameter 2D compare_func bigger\n");
    CHECK(r.outcome == Outcome::Fail);
    CHECK(r.message.find("bad compare_func \"bigger\"") != std::string::npos);
}
