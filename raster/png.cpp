// PNG output through libpng. The framebuffer's row 0 is the bottom (GL), an
// image's row 0 is the top, so rows are written in reverse.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <png.h>

#include "glslrun/glslrun.h"
#include "raster/framebuffer.h"

namespace glslrun {

namespace {

// Framebuffer row y (bottom first) as RGBA8 bytes.
void to_rgba8(const Framebuffer& fb, int y, png_byte* dst) {
    const float* src = &fb.color[size_t(y) * fb.width * 4];
    for (int i = 0; i < fb.width * 4; ++i) dst[i] = png_byte(raster::quantize_unorm8(src[i]) * 255.0f + 0.5f);
}

// Where the image is written before it is renamed to `path`, so that a
// process killed meanwhile never leaves a truncated PNG there. Unique per
// process and thread; `path` itself where it is not a regular file
// (/dev/stdout, a FIFO) and cannot be replaced.
std::string staging_path(const std::string& path) {
    std::error_code ec;
    auto type = std::filesystem::status(path, ec).type();
    if (type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found) return path;
    return fmt::format("{}.partial-{}-{:x}", path, getpid(), std::hash<std::thread::id>{}(std::this_thread::get_id()));
}

Status write_png_file(const Framebuffer& fb, const std::string& path, std::FILE* out);

}  // namespace

Status write_png(const Framebuffer& fb, const std::string& path) {
    if (fb.width <= 0 || fb.height <= 0) return Error("cannot write an empty framebuffer as PNG");
    if (path.empty()) return Error("cannot write a PNG to an empty path");
    const std::string staging = staging_path(path);
    std::FILE* file = std::fopen(staging.c_str(), "wb");
    if (!file) return Error("cannot open '" + path + "' for writing");
    Status written = write_png_file(fb, path, file);
    bool closed = std::fclose(file) == 0;
    if (written && !closed) written = Error("cannot write '" + path + "'");
    if (staging == path) return written;
    if (written && std::rename(staging.c_str(), path.c_str()) != 0)
        written = Error("cannot write '" + path + "': renaming its temporary file failed");
    if (!written) std::remove(staging.c_str());
    return written;
}

namespace {

Status write_png_file(const Framebuffer& fb, const std::string& path, std::FILE* file) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return Error("libpng: out of memory");
    }
    // One row at a time: a whole image's bytes (1 MB at 512x512) cost more
    // in page faults than their conversion (perf, docs/performance.md).
    std::vector<png_byte> row(size_t(fb.width) * 4);
    // libpng reports errors by longjmp; nothing with a destructor is created below.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return Error("libpng failed writing '" + path + "'");
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(fb.width), png_uint_32(fb.height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Speed over size: the default level costs more than a whole 512x512 frame,
    // and libpng's adaptive filter choice is half of what remains (512x512 spot:
    // 5.5 ms of CPU) for 3% smaller files than the SUB filter alone.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    for (int y = fb.height - 1; y >= 0; --y) {
        to_rgba8(fb, y, row.data());
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(file) != 0) return Error("cannot write '" + path + "'");
    return Ok{};
}

}  // namespace

}  // namespace glslrun
