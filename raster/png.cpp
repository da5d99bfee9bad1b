// PNG reading and writing through libpng. The framebuffer's row 0 is the
// bottom (GL), an image's row 0 is the top, so framebuffer rows are written in
// reverse.
#include "raster/png.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>
#include <memory>
#include <vector>

#include <fmt/format.h>
#include <png.h>

#include "raster/framebuffer.h"

namespace glslrun::png {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

// ------------------------------------------------------------ reading ---
// libpng reports errors by calling this and expecting it not to return; the
// message is kept for our Error.
struct PngErrorSink {
    char message[256] = {};
};

void on_png_error(png_structp png, png_const_charp msg) {
    auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
    std::snprintf(sink->message, sizeof sink->message, "%s", msg);
    png_longjmp(png, 1);
}

// Warnings concern ancillary chunks (bad gamma, text); the pixels are fine.
void on_png_warning(png_structp, png_const_charp) {}

// Owns libpng's read structures so that every exit path frees them.
struct PngReader {
    PngErrorSink sink;
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngReader() {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &sink, on_png_error, on_png_warning);
        if (png) info = png_create_info_struct(png);
    }
    ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
};

// The three steps below each set their own longjmp target and create nothing
// with a destructor after it: a libpng error unwinds no C++ object.
bool png_read_header(png_structp png, png_infop info, std::FILE* file) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_read_info(png, info);
    return true;
}

// Whatever the file's format, libpng hands out RGBA8 rows; no gamma
// transform is requested, so 8-bit values come back exactly as stored.
bool png_request_rgba8(png_structp png, png_infop info) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_byte color = png_get_color_type(png, info);
    png_byte depth = png_get_bit_depth(png, info);
    bool has_trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (has_trns) png_set_tRNS_to_alpha(png);
    if (depth == 16) png_set_scale_16(png);  // rounds, where strip_16 would truncate
    if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    if (!(color & PNG_COLOR_MASK_ALPHA) && !has_trns) png_set_filler(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return true;
}

bool png_read_rows(png_structp png, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

Error png_failure(const std::string& path, const PngReader& r) {
    return Error(fmt::format("cannot read '{}' as PNG: {}", path, r.sink.message[0] ? r.sink.message : "libpng failed"));
}

}  // namespace

const uint8_t* framebuffer_row(const Framebuffer& fb, int buffer, int y, uint8_t* scratch) {
    if (!fb.float_color()) return fb.color_row<uint8_t>(buffer, y);
    const float* src = fb.color_row<float>(buffer, y);
    for (size_t i = 0; i < size_t(fb.width) * 4; ++i) scratch[i] = raster::to_unorm8(src[i]);
    return scratch;
}

// Unique per process and thread.
std::string staging_path(const std::string& path) {
    std::error_code ec;
    auto type = std::filesystem::status(path, ec).type();
    if (type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found) return path;
    return fmt::format("{}.partial-{}-{:x}", path, getpid(), std::hash<std::thread::id>{}(std::this_thread::get_id()));
}

namespace {

Status write_rgba8_to(std::FILE* file, const std::string& path, int width, int height, const RowSource& row_of) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return Error("libpng: out of memory");
    }
    std::vector<png_byte> row(size_t(width) * 4);
    // libpng reports errors by longjmp; nothing with a destructor is created below.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return Error("libpng failed writing '" + path + "'");
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // Speed over size: the default level costs more than a whole 512x512 frame,
    // and libpng's adaptive filter choice is half of what remains (512x512 spot:
    // 5.5 ms of CPU) for 3% smaller files than the SUB filter alone.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, row_of(y, row.data()));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fflush(file) != 0) return Error("cannot write '" + path + "'");
    return Ok{};
}

}  // namespace

Status write_rgba8(const std::string& path, int width, int height, const RowSource& row_of) {
    if (width <= 0 || height <= 0) return Error("cannot write an empty image as PNG");
    if (path.empty()) return Error("cannot write a PNG to an empty path");
    if (path == "-") return write_rgba8_to(stdout, "standard output", width, height, row_of);  // stays open
    const std::string staging = staging_path(path);
    std::FILE* file = std::fopen(staging.c_str(), "wb");
    if (!file) return Error("cannot open '" + path + "' for writing");
    Status written = write_rgba8_to(file, path, width, height, row_of);
    bool closed = std::fclose(file) == 0;
    if (written && !closed) written = Error("cannot write '" + path + "'");
    if (staging == path) return written;
    if (written && std::rename(staging.c_str(), path.c_str()) != 0)
        written = Error("cannot write '" + path + "': renaming its temporary file failed");
    if (!written) std::remove(staging.c_str());
    return written;
}

Result<Rgba8Image> read_rgba8(const std::string& path, int max_side) {
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return Error(fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
    PngReader r;
    if (!r.info) return Error("libpng: out of memory");
    if (!png_read_header(r.png, r.info, file.get())) return png_failure(path, r);
    png_uint_32 w = png_get_image_width(r.png, r.info), h = png_get_image_height(r.png, r.info);
    if (w == 0 || h == 0 || w > png_uint_32(max_side) || h > png_uint_32(max_side))
        return Error(fmt::format("'{}' is {}x{}: images must be 1..{} pixels per side", path, w, h, max_side));
    // zlib inflates at most ~1032:1, so a file far smaller than its rows'
    // least compressed size is truncated: refused before the rows are allocated.
    std::error_code ec;
    uintmax_t file_bytes = std::filesystem::file_size(path, ec);
    uint64_t least_raw = uint64_t(h) * ((uint64_t(w) + 7) / 8 + 1);
    if (!ec && least_raw / 1032 > file_bytes + 1024)
        return Error(fmt::format("'{}' claims {}x{} pixels, more than its {} bytes can hold: it is truncated or corrupt",
                                 path, w, h, file_bytes));
    if (!png_request_rgba8(r.png, r.info)) return png_failure(path, r);
    if (png_get_rowbytes(r.png, r.info) != size_t(w) * 4)
        return Error(fmt::format("'{}': libpng could not convert the image to RGBA8", path));
    Rgba8Image image{int(w), int(h), std::vector<uint8_t>(size_t(w) * h * 4)};
    std::vector<png_bytep> rows(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = &image.rgba[size_t(y) * w * 4];
    if (!png_read_rows(r.png, rows.data())) return png_failure(path, r);
    return image;
}

}  // namespace glslrun::png

namespace glslrun {

Status write_png(const Framebuffer& fb, const std::string& path, int buffer) {
    if (fb.width <= 0 || fb.height <= 0) return Error("cannot write an empty framebuffer as PNG");
    if (buffer < 0 || buffer >= fb.color_buffers())
        return Error("the framebuffer has no colour buffer " + std::to_string(buffer));
    return png::write_rgba8(path, fb.width, fb.height,
                            [&](int y, uint8_t* scratch) { return png::framebuffer_row(fb, buffer, fb.height - 1 - y, scratch); });
}

}  // namespace glslrun
