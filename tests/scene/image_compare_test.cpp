// Image reading and comparison (scene/image_compare.h): the measure the
// reference tests and `glslrun --compare` rely on.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "glslrun/scene/image_compare.h"

using namespace glslrun;
using namespace glslrun::scene;

namespace {

std::string temp_path(const std::string& name) {
    return "/tmp/glslrun_image_compare_" + std::to_string(getpid()) + "_" + name;
}

Image solid(int w, int h, Rgba8 c) {
    Image img{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 4)};
    for (size_t p = 0; p < img.rgba.size(); p += 4)
        for (size_t k = 0; k < 4; ++k) img.rgba[p + k] = c[k];
    return img;
}

uint8_t* at(Image& img, int x, int y) { return &img.rgba[(size_t(y) * size_t(img.width) + size_t(x)) * 4]; }

// ---- hand-made PNG files, so that formats libpng must convert and broken
// headers can be tested without writing them through libpng itself.
uint32_t crc32(const std::string& bytes) {
    uint32_t crc = 0xffffffffu;
    for (unsigned char b : bytes) {
        crc ^= b;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
}

void chunk(std::string& png, const std::string& type, const std::string& data) {
    put32(png, uint32_t(data.size()));
    std::string body = type + data;
    png += body;
    put32(png, crc32(body));
}

// zlib stream with one stored (uncompressed) deflate block.
std::string zlib_stored(const std::string& raw) {
    std::string z = "\x78\x01";
    z += '\x01';
    z += char(raw.size() & 0xff);
    z += char(raw.size() >> 8);
    z += char(~raw.size() & 0xff);
    z += char((~raw.size() >> 8) & 0xff);
    z += raw;
    uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    put32(z, (b << 16) | a);
    return z;
}

// `scanlines` already carries each row's filter byte (0).
std::string make_png(uint32_t w, uint32_t h, int depth, int color_type, const std::string& scanlines,
                     const std::string& plte = {}) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string ihdr;
    put32(ihdr, w);
    put32(ihdr, h);
    ihdr += char(depth);
    ihdr += char(color_type);
    ihdr += std::string(3, '\0');  // deflate, adaptive filters, no interlace
    chunk(png, "IHDR", ihdr);
    if (!plte.empty()) chunk(png, "PLTE", plte);
    chunk(png, "IDAT", zlib_stored(scanlines));
    chunk(png, "IEND", "");
    return png;
}

std::string save(const std::string& name, const std::string& bytes) {
    std::string path = temp_path(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

bool mentions(const Error& e, const std::string& what) { return e.str().find(what) != std::string::npos; }

}  // namespace

TEST_CASE("write_png and read_png round-trip RGBA8 exactly", "[compare]") {
    Image img{7, 3, std::vector<uint8_t>(7 * 3 * 4)};
    for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = uint8_t((i * 37 + 11) % 256);
    std::string path = temp_path("roundtrip.png");
    REQUIRE(write_png(img, path));
    auto back = read_png(path);
    REQUIRE(back);
    CHECK(back->width == 7);
    CHECK(back->height == 3);
    CHECK(back->rgba == img.rgba);
    std::remove(path.c_str());
}

TEST_CASE("read_framebuffer gives the bytes glslrun::write_png stores", "[compare]") {
    Framebuffer fb(5, 2, /*float_color=*/true);
    const float values[] = {-1.0f, 0.0f, 0.5f, 1.0f / 255.0f, 0.49f / 255.0f, 0.51f / 255.0f, 0.999f, 1.0f, 2.0f, NAN};
    std::span<float> color = fb.color_data<float>();
    for (size_t i = 0; i < color.size(); ++i) color[i] = values[i % 10];
    std::string path = temp_path("fb.png");
    REQUIRE(glslrun::write_png(fb, path));
    auto file = read_png(path);
    REQUIRE(file);
    Image mem = read_framebuffer(fb);
    CHECK(mem.rgba == file->rgba);
    // Row 0 of an Image is the framebuffer's top row.
    CHECK(mem.pixel(0, 0)[0] == uint8_t(std::lround(std::clamp(fb.pixel(0, 1).r, 0.0f, 1.0f) * 255)));
    std::remove(path.c_str());
}

TEST_CASE("read_png converts grey, 16-bit and palette images to RGBA8", "[compare]") {
    SECTION("8-bit grey") {
        auto img = read_png(save("grey.png", make_png(2, 1, 8, 0, std::string("\0\x10\xf0", 3))));
        REQUIRE(img);
        CHECK(img->rgba == std::vector<uint8_t>{0x10, 0x10, 0x10, 255, 0xf0, 0xf0, 0xf0, 255});
    }
    SECTION("16-bit RGB is rounded to 8 bits") {
        std::string row("\0\x12\x34\xff\xff\x00\x00", 7);
        auto img = read_png(save("rgb16.png", make_png(1, 1, 16, 2, row)));
        REQUIRE(img);
        CHECK(img->rgba == std::vector<uint8_t>{0x12, 0xff, 0x00, 255});
    }
    SECTION("palette") {
        std::string plte("\x01\x02\x03\xaa\xbb\xcc", 6);
        auto img = read_png(save("pal.png", make_png(2, 1, 8, 3, std::string("\0\x01\x00", 3), plte)));
        REQUIRE(img);
        CHECK(img->rgba == std::vector<uint8_t>{0xaa, 0xbb, 0xcc, 255, 1, 2, 3, 255});
    }
}

TEST_CASE("read_png refuses missing, corrupt and oversized files without crashing", "[compare]") {
    SECTION("missing") {
        auto img = read_png("/nonexistent/dir/none.png");
        REQUIRE(!img);
        CHECK(mentions(img.error(), "/nonexistent/dir/none.png"));
    }
    SECTION("not a PNG") {
        auto img = read_png(save("text.png", "hello, this is not an image"));
        REQUIRE(!img);
        CHECK(mentions(img.error(), "cannot read"));
    }
    SECTION("truncated image data") {
        std::string png = make_png(64, 64, 8, 6, std::string(64 * (1 + 64 * 4), '\x20'));
        auto img = read_png(save("cut.png", png.substr(0, png.size() / 2)));
        REQUIRE(!img);
    }
    SECTION("corrupt CRC") {
        std::string png = make_png(1, 1, 8, 2, std::string("\0\1\2\3", 4));
        png[29] ^= 0x55;  // inside IHDR's CRC
        REQUIRE(!read_png(save("crc.png", png)));
    }
    SECTION("a 20000 x 20000 header is refused before allocating") {
        auto img = read_png(save("huge.png", make_png(20000, 20000, 8, 6, std::string(1, '\0'))));
        REQUIRE(!img);
        CHECK(mentions(img.error(), "20000x20000"));
        CHECK(mentions(img.error(), "16384"));
    }
}

TEST_CASE("compare_images measures per-channel and per-pixel differences", "[compare]") {
    Image ref = solid(100, 10, {10, 20, 30, 255});
    Image act = ref;
    at(act, 3, 4)[1] = 22;  // G off by 2
    at(act, 7, 8)[0] = 9;   // R off by 1: within tolerance 1
    auto s = compare_images(ref, act, {});
    REQUIRE(s);
    CHECK(s->max_diff == std::array<int, 4>{1, 2, 0, 0});
    CHECK(s->mean_diff[1] == Approx(2.0 / 1000.0));
    CHECK(s->differing == 1);
    CHECK(s->differing_percent() == Approx(0.1));
    CHECK(s->covered == 1000);  // no clear colour: everything is covered
    CHECK(s->worst_x == 3);
    CHECK(s->worst_y == 4);
    CHECK(s->passed);  // 999 of 1000 is 99.9%
    at(act, 50, 5)[2] = 0;
    s = compare_images(ref, act, {});
    REQUIRE(s);
    CHECK(s->max_diff[2] == 30);
    CHECK(!s->passed);
    CHECK(s->summary().find("FAIL") != std::string::npos);
}

TEST_CASE("covered pixels are those differing from the clear colour in either image", "[compare]") {
    Rgba8 clear{0, 0, 0, 255};
    Image ref = solid(10, 10, clear), act = ref;
    at(ref, 1, 1)[0] = 200;  // only in the reference
    at(act, 2, 2)[1] = 200;  // only in the other
    at(ref, 3, 3)[2] = 100;  // in both, slightly different
    at(act, 3, 3)[2] = 101;
    CompareOptions o;
    o.clear_color = clear;
    auto s = compare_images(ref, act, o);
    REQUIRE(s);
    CHECK(s->covered == 3);
    CHECK(s->differing == 2);
    CHECK(s->covered_within_fraction() == Approx(1.0 / 3.0));
    CHECK(!s->passed);
    o.tolerance = 255;
    s = compare_images(ref, act, o);
    REQUIRE(s);
    CHECK(s->passed);
    CHECK(s->covered_within_fraction() == 1.0);
}

TEST_CASE("compare_images refuses mismatched sizes and bad options", "[compare]") {
    auto s = compare_images(solid(4, 3, {}), solid(3, 4, {}), {});
    REQUIRE(!s);
    CHECK(mentions(s.error(), "4x3"));
    CHECK(mentions(s.error(), "3x4"));
    CompareOptions o;
    o.tolerance = 256;
    CHECK(!compare_images(solid(1, 1, {}), solid(1, 1, {}), o));
    o.tolerance = 1;
    o.min_fraction_within = 1.5;
    CHECK(!compare_images(solid(1, 1, {}), solid(1, 1, {}), o));
    Image broken{2, 2, std::vector<uint8_t>(3)};
    CHECK(!compare_images(broken, broken, {}));
}

TEST_CASE("the diff image marks differing pixels in red over a grey reference", "[compare]") {
    Image ref = solid(3, 1, {255, 255, 255, 255}), act = ref;
    at(act, 1, 0)[0] = 253;  // off by 2
    at(act, 2, 0)[0] = 0;    // off by 255
    auto d = diff_image(ref, act, 1);
    REQUIRE(d);
    const uint8_t* same = d->pixel(0, 0);
    CHECK(same[0] == same[1]);
    CHECK(same[1] == same[2]);
    CHECK(same[0] < 150);  // dimmed, so that red shows against white
    CHECK(d->pixel(1, 0)[0] > 150);
    CHECK(d->pixel(1, 0)[1] == 0);
    CHECK(d->pixel(2, 0)[0] == 255);
    CHECK(d->pixel(2, 0)[0] > d->pixel(1, 0)[0]);
    CHECK(!diff_image(ref, solid(2, 1, {}), 1));
    CHECK(!diff_image(ref, act, -1));
}

TEST_CASE("bottom-up rows (glReadPixels) are flipped, colours quantised like a clear", "[compare]") {
    std::vector<uint8_t> gl_rows = {1, 1, 1, 1, 2, 2, 2, 2};  // 1x2: bottom row first
    auto img = image_from_bottom_up(1, 2, gl_rows);
    REQUIRE(img);
    CHECK(img->pixel(0, 0)[0] == 2);
    CHECK(img->pixel(0, 1)[0] == 1);
    CHECK(!image_from_bottom_up(2, 2, gl_rows));
    CHECK(to_rgba8({0, 0.5f, 1, 2}) == Rgba8{0, 128, 255, 255});
    CHECK(to_rgba8({-1, 1.0f / 255.0f, 0.2f, 0.0f}) == Rgba8{0, 1, 51, 0});
}
