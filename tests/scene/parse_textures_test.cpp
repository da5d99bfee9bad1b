// The scene parser: [textures.N]. Procedural texels are checked texel by
// texel; image files are written by the test itself (stb_image_write) into a
// temporary directory, so no binary file is committed.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <fmt/format.h>

#include "parse_helpers.h"
#include "glslrun/scene/render.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

using namespace scene_test;
using glslrun::CompareFunc;
using glslrun::DepthTextureMode;
using glslrun::Texture;
using glslrun::TextureFilter;
using glslrun::TextureFormat;
using glslrun::TextureImage;
using glslrun::TextureTarget;
using glslrun::TextureWrap;
using glslrun::scene::TextureChannels;
namespace fs = std::filesystem;

namespace {

const Texture& texture(const Scene& s, int unit) {
    for (const auto& t : s.textures)
        if (t.unit == unit) return *t.texture;
    FAIL("no texture on unit " << unit);
    return *s.textures.front().texture;
}

glm::vec4 texel(const TextureImage& image, int i, int j, int k = 0) {
    return image.texels[size_t(i + image.width * (j + image.height * k))];
}

glm::vec4 texel(const Texture& t, int i, int j, int k = 0) { return texel(t.levels(0)[0], i, j, k); }

// A directory of test images, removed at the end of the test.
struct TempDir {
    fs::path path = fs::temp_directory_path() / ("glslrun_scene_textures_" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
    // parse_scene as if the scene file were in this directory.
    glslrun::Result<Scene> parse(std::string_view toml) const {
        return glslrun::scene::parse_scene(toml, file("scene.toml"));
    }
};

// 2x2 RGBA in file order (top row first): red, green / blue, white.
const unsigned char kQuadrants[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

uint32_t crc32(const std::string& bytes) {
    uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

std::string big_endian(uint32_t v) {
    return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A PNG signature and IHDR chunk claiming width x height, and nothing else:
// a reader that allocated before checking the header would try gigabytes.
std::string png_header_only(uint32_t width, uint32_t height) {
    std::string ihdr = "IHDR" + big_endian(width) + big_endian(height) + std::string("\x08\x06\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(crc32(ihdr));
}

}  // namespace

TEST_CASE("no [textures]: nothing is bound", "[scene][textures]") {
    Scene s = parse_ok("");
    CHECK(s.textures.empty());
    CHECK(s.warnings.empty());
}

TEST_CASE("a checkerboard with GL's default sampling state", "[scene][textures]") {
    Scene s = parse_ok("[textures.0]\ncheckerboard = { size = [4, 2], square_size = 1 }\n");
    REQUIRE(s.textures.size() == 1);
    CHECK(s.textures[0].unit == 0);
    CHECK(s.textures[0].where.line == 1);
    CHECK_FALSE(s.textures[0].generate_mipmap);
    const Texture& t = texture(s, 0);
    CHECK(t.target() == TextureTarget::Tex2D);
    CHECK(t.format() == TextureFormat::RGBA8);
    REQUIRE(t.levels(0).size() == 1);
    CHECK(t.levels(0)[0].width == 4);
    CHECK(t.levels(0)[0].height == 2);
    check_vec(texel(t, 0, 0), {0, 0, 0, 1});  // colors[0] at t = 0, s = 0
    check_vec(texel(t, 1, 0), {1, 1, 1, 1});
    check_vec(texel(t, 0, 1), {1, 1, 1, 1});
    check_vec(texel(t, 3, 1), {0, 0, 0, 1});
    const glslrun::SamplerState& st = t.sampler;
    CHECK(st.min_filter == TextureFilter::NearestMipmapLinear);
    CHECK(st.mag_filter == TextureFilter::Linear);
    CHECK(st.wrap_s == TextureWrap::Repeat);
    CHECK(st.wrap_t == TextureWrap::Repeat);
    CHECK(st.wrap_r == TextureWrap::Repeat);
    check_vec(st.border_color, {0, 0, 0, 0});
    CHECK(st.min_lod == -1000);
    CHECK(st.max_lod == 1000);
    CHECK(st.lod_bias == 0);
    CHECK(st.base_level == 0);
    CHECK(st.max_level == 1000);
    CHECK_FALSE(st.compare);
    // GL's default min filter wants mipmaps: the texture is incomplete, and said so.
    REQUIRE(s.warnings.size() == 1);
    CHECK(s.warnings[0].warning);
    CHECK(s.warnings[0].line == 1);
    CHECK_THAT(s.warnings[0].message, Catch::Contains("texture unit 0 is incomplete"));
    CHECK_THAT(s.warnings[0].message, Catch::Contains("generate_mipmap = true"));
}

TEST_CASE("checkerboard squares, colours and greys", "[scene][textures]") {
    Scene s = parse_ok(R"([textures.3]
min_filter = "nearest"
checkerboard = { size = [8, 8], colors = [[1, 0, 0], 0.5] }
[textures.4]
min_filter = "linear"
checkerboard = { size = [6, 4], square_size = [3, 1], colors = [[0, 0, 1, 0.5], [0, 1, 0]] }
)");
    CHECK(s.warnings.empty());
    const Texture& a = texture(s, 3);  // default squares: a side / 8 = 1 texel
    check_vec(texel(a, 0, 0), {1, 0, 0, 1});
    check_vec(texel(a, 1, 0), {128 / 255.0, 128 / 255.0, 128 / 255.0, 1});  // GL_RGBA8 rounds to k/255
    const Texture& b = texture(s, 4);
    check_vec(texel(b, 2, 0), {0, 0, 1, 128 / 255.0});
    check_vec(texel(b, 3, 0), {0, 1, 0, 1});
    check_vec(texel(b, 3, 1), {0, 0, 1, 128 / 255.0});
}

TEST_CASE("every sampling key is one glTexParameter", "[scene][textures]") {
    Scene s = parse_ok(R"([textures.1]
levels = [{ solid = { size = [4, 4], color = 1 } }, { solid = { size = [2, 2], color = 1 } },
          { solid = { size = [1, 1], color = 1 } }]
min_filter = "linear_mipmap_nearest"
mag_filter = "nearest"
wrap_s = "clamp_to_edge"
wrap_t = "mirrored_repeat"
wrap_r = "clamp_to_border"
border_color = [0.25, 0.5, 0.75]
min_lod = -2.5
max_lod = 4
lod_bias = 0.5
base_level = 1
max_level = 3
[textures.2]
internal_format = "depth_component"
solid = { size = [2, 2], color = 0.25 }
min_filter = "nearest"
wrap_s = "clamp"
compare_mode = "compare_r_to_texture"
compare_func = "gequal"
depth_texture_mode = "alpha"
)");
    const glslrun::SamplerState& a = texture(s, 1).sampler;
    CHECK(a.min_filter == TextureFilter::LinearMipmapNearest);
    CHECK(a.mag_filter == TextureFilter::Nearest);
    CHECK(a.wrap_s == TextureWrap::ClampToEdge);
    CHECK(a.wrap_t == TextureWrap::MirroredRepeat);
    CHECK(a.wrap_r == TextureWrap::ClampToBorder);
    check_vec(a.border_color, {0.25, 0.5, 0.75, 1});
    CHECK(a.min_lod == -2.5f);
    CHECK(a.max_lod == 4.0f);
    CHECK(a.lod_bias == 0.5f);
    CHECK(a.base_level == 1);
    CHECK(a.max_level == 3);
    CHECK_FALSE(s.textures[0].generate_mipmap);
    const Texture& d = texture(s, 2);
    CHECK(d.depth());
    CHECK(texel(d, 1, 1).r == 0.25f);  // a depth texture keeps its depth in .r
    CHECK(d.sampler.wrap_s == TextureWrap::Clamp);
    CHECK(d.sampler.compare);
    CHECK(d.sampler.compare_func == CompareFunc::Gequal);
    CHECK(d.sampler.depth_mode == DepthTextureMode::Alpha);
    CHECK(s.warnings.empty());
}

TEST_CASE("generate_mipmap builds every level down to 1x1", "[scene][textures]") {
    Scene s = parse_ok("[textures.0]\ngenerate_mipmap = true\nrgbw = { size = [8, 4] }\n");
    const Texture& t = texture(s, 0);
    REQUIRE(t.levels(0).size() == 4);  // 8x4, 4x2, 2x1, 1x1
    CHECK(t.levels(0)[3].width == 1);
    CHECK(t.levels(0)[3].height == 1);
    CHECK(s.warnings.empty());  // complete with GL's default min filter
}

TEST_CASE("generate_mipmap starts at base_level, as in GL", "[scene][textures]") {
    Scene s = parse_ok("[textures.0]\ngenerate_mipmap = true\nbase_level = 1\nrgbw = { size = [4, 4] }\n");
    CHECK(texture(s, 0).levels(0).size() == 1);  // GL_GENERATE_MIPMAP needs a level_base image
    REQUIRE(s.warnings.size() == 1);
    CHECK_THAT(s.warnings[0].message, Catch::Contains("base_level = 1 has no image"));
}

TEST_CASE("levels: an explicit mipmap chain, level 0 first", "[scene][textures]") {
    Scene s = parse_ok(R"([textures.0]
min_filter = "nearest_mipmap_nearest"
levels = [
  { solid = { size = [4, 4], color = [1, 0, 0] } },
  { solid = { size = [2, 2], color = [0, 1, 0] } },
  { solid = { size = [1, 1], color = [0, 0, 1] } },
]
)");
    const Texture& t = texture(s, 0);
    REQUIRE(t.levels(0).size() == 3);
    check_vec(texel(t.levels(0)[1], 1, 1), {0, 1, 0, 1});
    check_vec(texel(t.levels(0)[2], 0, 0), {0, 0, 1, 1});
    CHECK_FALSE(s.textures[0].generate_mipmap);
    CHECK(s.warnings.empty());
}

TEST_CASE("rgbw is piglit's texture in 1, 2 and 3 dimensions", "[scene][textures]") {
    Scene s = parse_ok(R"([textures.0]
rgbw = { size = [4, 4] }
[textures.1]
rgbw = { size = [2, 2], alpha = true }
[textures.2]
target = "1d"
rgbw = { size = [8] }
[textures.3]
target = "3d"
rgbw = { size = [2, 2, 2] }
)");
    const Texture& t = texture(s, 0);
    check_vec(texel(t, 0, 0), {1, 0, 0, 1});  // s < 1/2, t < 1/2
    check_vec(texel(t, 3, 1), {0, 1, 0, 1});
    check_vec(texel(t, 1, 2), {0, 0, 1, 1});
    check_vec(texel(t, 2, 3), {1, 1, 1, 1});
    const Texture& a = texture(s, 1);
    CHECK(texel(a, 0, 0).a == 0.0f);
    CHECK(texel(a, 1, 0).a == Approx(64 / 255.0));
    CHECK(texel(a, 0, 1).a == Approx(128 / 255.0));
    CHECK(texel(a, 1, 1).a == 1.0f);
    const Texture& one = texture(s, 2);
    CHECK(one.target() == TextureTarget::Tex1D);
    check_vec(texel(one, 1, 0), {1, 0, 0, 1});
    check_vec(texel(one, 2, 0), {0, 1, 0, 1});
    check_vec(texel(one, 5, 0), {0, 0, 1, 1});
    check_vec(texel(one, 7, 0), {1, 1, 1, 1});
    const Texture& three = texture(s, 3);
    CHECK(three.target() == TextureTarget::Tex3D);
    check_vec(texel(three, 1, 1, 0), {1, 1, 1, 1});
    check_vec(texel(three, 0, 0, 1), {1, 1, 0, 1});
    check_vec(texel(three, 1, 1, 1), {0, 0, 0, 1});
}

TEST_CASE("cube maps: one pattern for every face, or six faces", "[scene][textures]") {
    Scene s = parse_ok(R"([textures.0]
target = "cube_map"
checkerboard = { size = [4, 4] }
[textures.1]
faces = [
  { solid = { size = [2, 2], color = [1, 0, 0] } },
  { solid = { size = [2, 2], color = [0, 1, 1] } },
  { solid = { size = [2, 2], color = [0, 1, 0] } },
  { solid = { size = [2, 2], color = [1, 0, 1] } },
  { rgbw = { size = [2, 2] } },
  { checkerboard = { size = [2, 2] } },
]
)");
    const Texture& a = texture(s, 0);
    CHECK(a.target() == TextureTarget::Cube);
    CHECK(a.faces() == 6);
    const Texture& b = texture(s, 1);  // the target follows from `faces`
    CHECK(b.target() == TextureTarget::Cube);
    REQUIRE(b.faces() == 6);
    check_vec(texel(b.levels(1)[0], 0, 0), {0, 1, 1, 1});
    check_vec(texel(b.levels(4)[0], 1, 1), {1, 1, 1, 1});
}

TEST_CASE("image files: PNG and JPEG, relative to the scene, flipped upright", "[scene][textures]") {
    TempDir dir;
    REQUIRE(stbi_write_png(dir.file("quad.png").c_str(), 2, 2, 4, kQuadrants, 8));
    const unsigned char grey[2] = {0, 51};
    REQUIRE(stbi_write_png(dir.file("grey.png").c_str(), 2, 1, 1, grey, 2));
    std::vector<unsigned char> orange(16 * 16 * 3);
    for (size_t i = 0; i < orange.size(); i += 3) orange[i] = 255, orange[i + 1] = 128, orange[i + 2] = 0;
    REQUIRE(stbi_write_jpg(dir.file("orange.jpg").c_str(), 16, 16, 3, orange.data(), 95));
    auto r = dir.parse(R"([textures.0]
image = "quad.png"
[textures.1]
target = "1d"
image = "grey.png"
[textures.2]
image = "orange.jpg"
[textures.3]
faces = ["quad.png", "quad.png", "quad.png", "quad.png", "quad.png", "quad.png"]
)");
    INFO((r ? std::string() : r.error().str()));
    REQUIRE(r);
    // The file's bottom row is t = 0: the picture stands upright with t up.
    const Texture& t = texture(*r, 0);
    check_vec(texel(t, 0, 0), {0, 0, 1, 1});
    check_vec(texel(t, 1, 0), {1, 1, 1, 128 / 255.0});
    check_vec(texel(t, 0, 1), {1, 0, 0, 1});
    check_vec(texel(texture(*r, 1), 1, 0), {0.2, 0.2, 0.2, 1});  // grey is (L, L, L, 1)
    glm::vec4 o = texel(texture(*r, 2), 8, 8);
    CHECK(o.r == Approx(1.0).margin(0.02));
    CHECK(o.g == Approx(128 / 255.0).margin(0.02));
    CHECK(o.b == Approx(0.0).margin(0.02));
    // Cube faces keep the file's top row at t = 0, GL's cube map face layout.
    check_vec(texel(texture(*r, 3).levels(5)[0], 0, 0), {1, 0, 0, 1});
}

TEST_CASE("bad image files are errors at the scene's line", "[scene][textures]") {
    TempDir dir;
    REQUIRE(stbi_write_png(dir.file("quad.png").c_str(), 2, 2, 4, kQuadrants, 8));
    REQUIRE(stbi_write_png(dir.file("wide.png").c_str(), 4, 1, 4, kQuadrants, 16));
    std::string good = read_bytes(dir.file("quad.png"));
    write_bytes(dir.file("truncated.png"), good.substr(0, good.size() / 2 + 8));
    write_bytes(dir.file("garbage.png"), "this is not an image at all");
    write_bytes(dir.file("empty.png"), "");
    write_bytes(dir.file("picture.gif"), std::string("GIF89a\x02\x00\x02\x00\x00\x00\x00;", 14));
    write_bytes(dir.file("huge.png"), png_header_only(20000, 20000));
    write_bytes(dir.file("many.png"), png_header_only(16384, 16384));
    write_bytes(dir.file("header.png"), good.substr(0, 20));
    // An IDAT chunk (at byte 33, after the signature and IHDR) whose length
    // passes 2^31: stb fails without a reason, and reported its JPEG test's.
    std::string long_idat = good;
    REQUIRE(long_idat.substr(37, 4) == "IDAT");
    long_idat[33] = '\xec';
    write_bytes(dir.file("long_idat.png"), long_idat);
    write_bytes(dir.file("chunk.png"), good.substr(0, 37) + std::string("\0DAT", 4) + good.substr(41));
    struct Case {
        std::string toml;
        std::string message, detail;
    };
    const std::vector<Case> cases = {
        {"image = \"none.png\"", "'textures.0.image': cannot use the image", "cannot open the image: no such file"},
        // A NUL cut the path short at the C library, and quad.png was loaded instead.
        {"image = \"quad.png\\u0000.txt\"", "cannot use the image", "quad.png' holds a NUL byte"},
        {"image = \"truncated.png\"", "cannot use the image", "cannot decode the image"},
        {"image = \"long_idat.png\"", "cannot use the image", "long_idat.png': Corrupt PNG"},
        {"image = \"chunk.png\"", "cannot use the image", "chunk.png': PNG not supported: unknown PNG chunk type"},
        {"image = \"garbage.png\"", "cannot use the image", "is neither a PNG nor a JPEG file"},
        {"image = \"empty.png\"", "cannot use the image", "is empty: neither a PNG nor a JPEG file"},
        {"image = \"picture.gif\"", "cannot use the image", "is neither a PNG nor a JPEG file"},
        {"image = \"header.png\"", "cannot use the image", "is not a PNG image that can be read: its header is corrupt"},
        {"image = \"huge.png\"", "cannot use the image", "is 20000x20000: textures are 1..16384 texels per side"},
        {"image = \"many.png\"", "cannot use the image", "a texture may hold at most 16777216"},
        {"image = \".\"", "cannot use the image", "cannot read the image"},
        {"target = \"1d\"\nimage = \"quad.png\"", "is 2x2: a 1d texture needs an image 1 texel high", ""},
        {"target = \"3d\"\nimage = \"quad.png\"", "3d textures take checkerboard, rgbw or solid", ""},
        {"faces = [\"quad.png\", \"quad.png\", \"quad.png\", \"quad.png\", \"quad.png\", \"wide.png\"]",
         "[textures.0]", ""},
    };
    for (const Case& c : cases) {
        INFO(c.toml);
        auto r = dir.parse("# textures\n[textures.0]\n" + c.toml + "\n");
        REQUIRE_FALSE(r);
        const auto& ds = r.error().diagnostics;
        INFO(r.error().str());
        CHECK(ds[0].file == dir.file("scene.toml"));
        CHECK(ds[0].line >= 3);
        CHECK_THAT(ds[0].message, Catch::Contains(c.message));
        if (!c.detail.empty()) {
            REQUIRE(ds.size() >= 2);
            CHECK_THAT(ds[1].message, Catch::Contains(c.detail));
        }
    }
}

// Issue #17: each texture was bounded, not the scene: 16 units of 4096x4096
// took 4.5 GB. Eight of 2048x2048 are the limit; one texel more is refused.
TEST_CASE("a scene's textures hold at most kMaxSceneTexels together", "[scene][textures][errors]") {
    std::string toml;
    for (int unit = 0; unit < 8; ++unit)
        toml += fmt::format("[textures.{}]\nsolid = {{ size = [2048, 2048], color = [1, 1, 1] }}\n", unit);
    CHECK(parse_ok(toml).textures.size() == 8);
    toml += "[textures.8]\nsolid = { size = [1, 1], color = [1, 1, 1] }\n";
    check_error(toml, 17, "the textures up to [textures.8] hold 33554433 texels in all, mipmaps included; a scene "
                          "may hold at most 33554432");
}

TEST_CASE("texture keys: unknown names, types and ranges", "[scene][textures][errors]") {
    const char* solid = "solid = { size = [1, 1], color = [1, 1, 1] }\n";
    auto with = [&](const std::string& line) { return std::string("[textures.0]\n") + solid + line + "\n"; };
    check_error(with("min_filer = \"linear\""), 3, "unknown key 'min_filer' in [textures.0]; did you mean 'min_filter'?");
    check_error(with("wrap_s = \"clamp_to_edges\""), 3, "did you mean 'clamp_to_edge'?");
    check_error(with("min_filter = \"liner\""), 3, "'textures.0.min_filter' = \"liner\" is not allowed; did you mean 'linear'?");
    check_error(with("mag_filter = \"linear_mipmap_linear\""), 3, "valid values: nearest, linear");
    check_error(with("target = \"cube\""), 3, "valid values: 1d, 2d, 3d, cube_map, rectangle");
    check_error(with("internal_format = \"depth\""), 3, "'textures.0.internal_format' = \"depth\" is not allowed");
    check_error(with("border_color = [0, 0, 2]"), 3, "'textures.0.border_color' must be in [0, 1] (GL_TEXTURE_BORDER_COLOR); got 2");
    check_error(with("base_level = -1"), 3, "'textures.0.base_level' must be in [0, 2147483647]; got -1");
    check_error(with("max_level = 1.5"), 3, "'textures.0.max_level' must be an integer");
    check_error(with("lod_bias = \"big\""), 3, "'textures.0.lod_bias' must be a number");
    check_error(with("min_lod = nan"), 3, "must be a finite number");
    check_error(with("generate_mipmap = 1"), 3, "'textures.0.generate_mipmap' must be true or false");
    check_error(with("compare_mode = \"compare_r_to_texture\""), 3,
                "'textures.0.compare_mode' applies to depth textures only");
    check_error(with("target = \"2d\"\nfaces = []"), 4,
                "'textures.0.faces' is for target = \"cube_map\" (this is \"2d\")");
    check_error("[textures.16]\nrgbw = { size = [2, 2] }\n", 1, "texture units are 0..15");
    check_error("[textures.x]\n", 1, "texture units are 0..15");
    check_error("textures = 3\n", 1, "'textures' must be a table");
    check_error("[texture.0]\n", 1, "did you mean 'textures'?");
}

TEST_CASE("a rectangle texture: GL's state for rectangles, and what GL refuses for one", "[scene][textures]") {
    Scene s = parse_ok("[textures.2]\ntarget = \"rectangle\"\ncheckerboard = { size = [6, 3], square_size = 1 }\n");
    const Texture& t = texture(s, 2);
    CHECK(t.target() == TextureTarget::Rect);
    CHECK(t.levels(0)[0].width == 6);
    CHECK(t.levels(0)[0].height == 3);
    CHECK(t.sampler.min_filter == TextureFilter::Linear);  // complete without mipmaps
    CHECK(t.sampler.wrap_s == TextureWrap::ClampToEdge);
    CHECK(t.complete());
    CHECK(s.warnings.empty());
    Scene depth = parse_ok("[textures.0]\ntarget = \"rectangle\"\ninternal_format = \"depth_component\"\n"
                           "solid = { size = [3, 2], color = 0.5 }\ncompare_mode = \"compare_r_to_texture\"\n");
    CHECK(texture(depth, 0).sampler.compare);
    auto rect = [](const std::string& line) {
        return "[textures.0]\ntarget = \"rectangle\"\nrgbw = { size = [4, 2] }\n" + line + "\n";
    };
    check_error(rect("wrap_s = \"repeat\""), 4, "'textures.0.wrap_s' of a rectangle texture is \"clamp\"");
    check_error(rect("wrap_t = \"mirrored_repeat\""), 4, "GL refuses \"mirrored_repeat\"");
    check_error(rect("min_filter = \"linear_mipmap_linear\""), 4, "is \"nearest\" or \"linear\" (it has no mipmaps)");
    check_error(rect("generate_mipmap = true"), 4, "'textures.0.generate_mipmap': a rectangle texture has no mipmaps");
    check_error(rect("base_level = 1"), 4, "'textures.0.base_level' of a rectangle texture is 0");
    check_error("[textures.0]\ntarget = \"rectangle\"\nrgbw = { size = [4] }\n", 3, "[width, height]");
}

TEST_CASE("array textures: one image per layer, stacked; what they refuse", "[scene][textures][array]") {
    Scene s = parse_ok("[textures.1]\ntarget = \"2d_array\"\nmin_filter = \"nearest\"\nlayers = [\n"
                       "  { solid = { size = [2, 2], color = [1, 0, 0] } },\n"
                       "  { checkerboard = { size = [2, 2], square_size = 1 } },\n"
                       "  { rgbw = { size = [2, 2] } },\n]\n");
    const Texture& t = texture(s, 1);
    CHECK(t.target() == TextureTarget::Tex2DArray);
    const TextureImage& img = t.levels(0)[0];
    CHECK((img.width == 2 && img.height == 2 && img.depth == 3));
    CHECK(texel(img, 1, 1, 0) == glm::vec4(1, 0, 0, 1));
    CHECK(texel(img, 0, 0, 1) == glm::vec4(0, 0, 0, 1));  // the checkerboard's first colour, bottom left
    CHECK(texel(img, 1, 1, 1) == glm::vec4(0, 0, 0, 1));
    CHECK(texel(img, 0, 0, 2) == glm::vec4(1, 0, 0, 1));  // rgbw: red bottom left
    CHECK(t.complete());
    Scene one = parse_ok("[textures.0]\ntarget = \"1d_array\"\ngenerate_mipmap = true\n"
                         "layers = [ { rgbw = { size = [4] } }, { solid = { size = [4], color = 0.5 } } ]\n");
    const Texture& o = texture(one, 0);
    CHECK(o.target() == TextureTarget::Tex1DArray);
    CHECK((o.levels(0)[0].width == 4 && o.levels(0)[0].height == 2));
    REQUIRE(o.levels(0).size() == 3);
    CHECK(o.levels(0)[2].height == 2);  // the layers stay at every level
    CHECK(o.complete());
    check_error("[textures.0]\ntarget = \"2d_array\"\nrgbw = { size = [2, 2] }\n", 3,
                "an array texture takes its images from 'layers'");
    check_error("[textures.0]\ntarget = \"2d_array\"\nmin_filter = \"linear\"\n", 1, "needs 'layers'");
    check_error("[textures.0]\nlayers = [ { rgbw = { size = [2, 2] } } ]\n", 2,
                "'textures.0.layers' is for target = \"1d_array\" or \"2d_array\"");
    check_error("[textures.0]\ntarget = \"2d_array\"\nlayers = [ { rgbw = { size = [2, 2] } }, "
                "{ rgbw = { size = [4, 2] } } ]\n", 3, "every layer has one size");
    check_error("[textures.0]\ntarget = \"1d_array\"\nlayers = [ { rgbw = { size = [2, 2] } } ]\n", 3, "[width]");
    check_error("[textures.0]\ntarget = \"2d_array\"\nlayers = []\n", 3, "must have 1 to 2048 elements");
}

TEST_CASE("texture sources: one of them, of the right size", "[scene][textures][errors]") {
    check_error("[textures.0]\nmin_filter = \"linear\"\n", 1, "[textures.0] needs a source of texels");
    check_error("[textures.0]\nrgbw = { size = [2, 2] }\nsolid = { size = [1, 1], color = 1 }\n", 3,
                "has both 'rgbw' and 'solid'");
    check_error("[textures.0]\nrgbw = { size = [2, 2, 2] }\n", 2,
                "'textures.0.rgbw.size' must be [width, height] for a 2d texture (got an array of 3 values)");
    check_error("[textures.0]\ntarget = \"3d\"\nrgbw = { size = [2, 2] }\n", 3, "[width, height, depth]");
    check_error("[textures.0]\nrgbw = { alpha = true }\n", 2, "[textures.0.rgbw] needs 'size'");
    check_error("[textures.0]\nrgbw = { size = [0, 2] }\n", 2, "'textures.0.rgbw.size[0]' must be in [1, 16384]; got 0");
    check_error("[textures.0]\nrgbw = { size = [16385, 2] }\n", 2, "must be in [1, 16384]");
    check_error("[textures.0]\ntarget = \"3d\"\nrgbw = { size = [2, 2, 4096] }\n", 3, "must be in [1, 2048]");
    check_error("[textures.0]\nrgbw = { size = [16384, 16384] }\n", 2, "is 268435456 texels; a texture may hold at most 16777216");
    check_error("[textures.0]\nrgbw = { size = [2, 2], colour = 1 }\n", 2, "unknown key 'colour' in [textures.0.rgbw]");
    check_error("[textures.0]\nsolid = { size = [1, 1], color = [2, 0, 0] }\n", 2,
                "'textures.0.solid.color' must be in [0, 1]: rgba8 stores no other values");
    check_error("[textures.0]\nsolid = { size = [1, 1], color = [1, 0] }\n", 2, "must be an array of 3 or 4 numbers");
    check_error("[textures.0]\ncheckerboard = { size = [4, 4], colors = [1] }\n", 2, "must be two colours");
    check_error("[textures.0]\ncheckerboard = { size = [4, 4], square_size = 0 }\n", 2, "square_size' must be in [1, 16384]");
    check_error("[textures.0]\ncheckerboard = { size = [4, 4], square_size = [1, 2, 3] }\n", 2, "must be an integer or 2 integers");
    check_error("[textures.0]\nfaces = [\"a.png\"]\n", 2, "'textures.0.faces' must have 6 elements (got 1)");
    check_error("[textures.0]\nfaces = [1, 2, 3, 4, 5, 6]\n", 2, "'textures.0.faces[0]' must be a table");
    check_error("[textures.0]\nfaces = [{}, {}, {}, {}, {}, {}]\n", 2, "[textures.0.faces[0]] needs one of image");
    check_error("[textures.0]\ntarget = \"cube_map\"\nlevels = [{ rgbw = { size = [2, 2] } }]\n", 3,
                "a cube_map takes 'faces'");
    check_error("[textures.0]\ngenerate_mipmap = true\nlevels = [{ rgbw = { size = [2, 2] } }]\n", 3,
                "has both 'levels' and generate_mipmap = true");
    check_error("[textures.0]\nlevels = []\n", 2, "must have 1 to 32 elements (got 0)");
    check_error("[textures.0]\nimage = 3\n", 2, "'textures.0.image' must be a file name (got the integer 3)");
    check_error("[textures.0]\ntarget = \"cube_map\"\nsolid = { size = [2048, 2048], color = 1 }\n", 3,
                "[textures.0] holds 25165824 texels in all; a texture may hold at most 16777216");
    check_error("[textures.0]\nlevels = [{ solid = { size = [4096, 4096], color = 1 } },\n"
                "  { solid = { size = [16, 16], color = 1 } }]\n", 3, "holds 16777472 texels in all");
    check_error("[textures.0]\ntarget = \"3d\"\ninternal_format = \"depth_component\"\n"
                "solid = { size = [2, 2, 2], color = 1 }\n", 4, "[textures.0]: a depth texture is 1D, 2D or a rectangle");
    check_error("[textures.0]\ntarget = \"cube_map\"\nsolid = { size = [4, 2], color = 1 }\n", 3,
                "[textures.0]: cube map face +X: cube map faces are square");
}

TEST_CASE("a float texture keeps values outside [0, 1]", "[scene][textures]") {
    Scene s = parse_ok("[textures.0]\ninternal_format = \"rgba32f\"\nmin_filter = \"nearest\"\n"
                       "solid = { size = [1, 1], color = [2, -1, 0.3] }\n");
    const Texture& t = texture(s, 0);
    CHECK(t.format() == TextureFormat::RGBA32F);
    check_vec(texel(t, 0, 0), {2, -1, 0.3, 1});
}

TEST_CASE("float formats of fewer channels keep theirs and read GL's values for the rest", "[scene][textures]") {
    const char* kSource = "min_filter = \"nearest\"\nsolid = { size = [1, 1], color = [2.5, 0.6, 0.9, 0.45] }\n";
    const std::pair<const char*, glm::vec4> kCases[] = {
        {"rgb32f", {2.5f, 0.6f, 0.9f, 1}},   {"rg32f", {2.5f, 0.6f, 0, 1}},
        {"r32f", {2.5f, 0, 0, 1}},           {"luminance32f", {2.5f, 2.5f, 2.5f, 1}},
        {"intensity32f", glm::vec4(2.5f)},    {"luminance_alpha32f", {2.5f, 2.5f, 2.5f, 0.45f}},
        {"alpha32f", {0, 0, 0, 0.45f}},
    };
    for (const auto& [name, expected] : kCases) {
        INFO(name);
        Scene s = parse_ok(std::string("[textures.0]\ninternal_format = \"") + name + "\"\n" + kSource);
        CHECK(texture(s, 0).format() == TextureFormat::RGBA32F);
        CHECK(texel(texture(s, 0), 0, 0) == expected);
        CHECK(s.textures[0].channels != TextureChannels::Rgba);
    }
    // The 16f forms store halves of what they keep: 0.6 to 0.60009765625.
    Scene half = parse_ok(std::string("[textures.0]\ninternal_format = \"rg16f\"\n") + kSource);
    CHECK(texture(half, 0).format() == TextureFormat::RGBA16F);
    CHECK(texel(texture(half, 0), 0, 0).g == 0.60009765625f);
}

TEST_CASE("render_scene binds every [textures.N]; sampler uniforms pick the unit", "[scene][textures]") {
    Scene s = parse_ok(R"([output]
size = [4, 4]
[textures.2]
min_filter = "nearest"
solid = { size = [1, 1], color = [0.2, 0.4, 0.6] }
[textures.5]
target = "cube_map"
min_filter = "nearest"
solid = { size = [1, 1], color = [1, 0.6, 0.2] }
[uniforms]
decal = 2
cube = 5
[[objects]]
mesh = "quad"
)");
    const char* vs = "void main() { gl_Position = gl_Vertex; }";
    const char* fs = "uniform sampler2D decal; uniform samplerCube cube;\n"
                     "void main() { gl_FragColor = texture2D(decal, vec2(0.5)) + 0.25 * textureCube(cube, vec3(1.0)); }";
    auto program = glslrun::Program::compile({{"v.vert", vs}}, {{"f.frag", fs}});
    INFO((program ? std::string() : program.error().str()));
    REQUIRE(program);
    glslrun::Framebuffer fb(4, 4);
    auto stats = glslrun::scene::render_scene(*program, s, fb);
    INFO((stats ? std::string() : stats.error().str()));
    REQUIRE(stats);
    check_vec(fb.pixel(1, 1), {0.2 + 0.25, 0.4 + 0.15, 0.6 + 0.05, 1}, 1.0 / 255);
}

TEST_CASE("a uniform given the wrong number of values names its declaration, at the scene's line", "[scene]") {
    const char* fs = "uniform vec3 color; uniform vec2 points[3];\n"
                     "void main() { gl_FragColor = vec4(color + points[2].xyx, 1.0); }";
    auto program = glslrun::Program::compile({{"v.vert", "void main() { gl_Position = gl_Vertex; }"}},
                                             {{"f.frag", fs}});
    REQUIRE(program);
    glslrun::Status st = glslrun::scene::apply_uniforms(*program, parse_ok("[uniforms]\ncolor = 1.0\n").uniforms);
    REQUIRE_FALSE(st);
    CHECK(st.error().diagnostics[0].line == 2);
    CHECK_THAT(st.error().diagnostics[0].message, Catch::EndsWith("(the program declares 'uniform vec3 color')"));
    st = glslrun::scene::apply_uniforms(*program, parse_ok("[uniforms]\npoints = [1, 2, 3]\n").uniforms);
    REQUIRE_FALSE(st);
    CHECK_THAT(st.error().diagnostics[0].message, Catch::EndsWith("(the program declares 'uniform vec2 points[3]')"));
}

TEST_CASE("a sampler uniform takes an integer, at the scene's line", "[scene][textures]") {
    Scene s = parse_ok("[uniforms]\ntex = 0.0\n");
    const char* fs = "uniform sampler2D tex; void main() { gl_FragColor = texture2D(tex, vec2(0.5)); }";
    auto program = glslrun::Program::compile({{"v.vert", "void main() { gl_Position = gl_Vertex; }"}},
                                             {{"f.frag", fs}});
    REQUIRE(program);
    glslrun::Status st = glslrun::scene::apply_uniforms(*program, s.uniforms);
    REQUIRE_FALSE(st);
    CHECK(st.error().diagnostics[0].line == 2);
    CHECK_THAT(st.error().diagnostics[0].message, Catch::Contains("its value is a texture unit, an integer"));
}
