// PNG output through libpng. The framebuffer's row 0 is the bottom (GL), an
// image's row 0 is the top, so rows are written in reverse.
#include <cstdio>
#include <memory>
#include <vector>

#include <png.h>

#include "glslrun/glslrun.h"
#include "raster/framebuffer.h"

namespace glslrun {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

std::vector<png_byte> to_rgba8(const Framebuffer& fb) {
    std::vector<png_byte> bytes(size_t(fb.width) * fb.height * 4);
    for (int y = 0; y < fb.height; ++y) {
        const float* src = &fb.color[size_t(fb.height - 1 - y) * fb.width * 4];
        png_byte* dst = &bytes[size_t(y) * fb.width * 4];
        for (int i = 0; i < fb.width * 4; ++i)
            dst[i] = png_byte(raster::quantize_unorm8(src[i]) * 255.0f + 0.5f);
    }
    return bytes;
}

}  // namespace

Status write_png(const Framebuffer& fb, const std::string& path) {
    if (fb.width <= 0 || fb.height <= 0) return Error("cannot write an empty framebuffer as PNG");
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
    if (!file) return Error("cannot open '" + path + "' for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return Error("libpng: out of memory");
    }
    std::vector<png_byte> bytes = to_rgba8(fb);
    std::vector<png_bytep> rows(fb.height);
    for (int y = 0; y < fb.height; ++y) rows[y] = &bytes[size_t(y) * fb.width * 4];
    // libpng reports errors by longjmp; nothing with a destructor is created below.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return Error("libpng failed writing '" + path + "'");
    }
    png_init_io(png, file.get());
    png_set_IHDR(png, info, png_uint_32(fb.width), png_uint_32(fb.height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Speed over size: the default level costs more than a whole 512x512 frame.
    png_set_compression_level(png, 1);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(file.get()) != 0) return Error("cannot write '" + path + "'");
    return Ok{};
}

}  // namespace glslrun
