#include "image_output.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <vector>

#include <fmt/format.h>

#include "raster/png.h"

// Static functions, so another stb_image_write in the program cannot clash;
// no stdio: the bytes are written here, through a temporary file.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

namespace glslrun::cli {
namespace {

// Quality 95: visually lossless for rendered images, a fifth of the PNG's size.
constexpr int kJpegQuality = 95;

void append(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    bytes->insert(bytes->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
}

Status write_bytes(const std::vector<unsigned char>& bytes, const std::string& path) {
    const std::string staging = png::staging_path(path);
    std::FILE* file = std::fopen(staging.c_str(), "wb");
    if (!file) return Error("cannot open '" + path + "' for writing");
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    ok = std::fclose(file) == 0 && ok;
    if (staging == path) return ok ? Status(Ok{}) : Status(Error("cannot write '" + path + "'"));
    if (ok && std::rename(staging.c_str(), path.c_str()) != 0) {
        std::remove(staging.c_str());
        return Error("cannot write '" + path + "': renaming its temporary file failed");
    }
    if (!ok) {
        std::remove(staging.c_str());
        return Error("cannot write '" + path + "'");
    }
    return Ok{};
}

}  // namespace

std::optional<ImageFormat> image_format_of(const std::string& path) {
    if (path == "-") return ImageFormat::Png;
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    if (ext == ".bmp") return ImageFormat::Bmp;
    if (ext == ".tga") return ImageFormat::Tga;
    return std::nullopt;
}

Status write_image(const scene::Image& image, const std::string& path) {
    auto format = image_format_of(path);
    if (!format) return Error(fmt::format("cannot write '{}': not a .png, .jpg, .bmp or .tga name", path));
    if (*format == ImageFormat::Png) return scene::write_png(image, path);
    std::vector<unsigned char> bytes;
    const int w = image.width, h = image.height;
    int ok = 0;
    // JPEG and BMP drop alpha (JPEG has none; stb writes BMP as 24-bit RGB);
    // TGA keeps it.
    switch (*format) {
    case ImageFormat::Jpeg: ok = stbi_write_jpg_to_func(append, &bytes, w, h, 4, image.rgba.data(), kJpegQuality); break;
    case ImageFormat::Bmp: ok = stbi_write_bmp_to_func(append, &bytes, w, h, 4, image.rgba.data()); break;
    case ImageFormat::Tga: ok = stbi_write_tga_to_func(append, &bytes, w, h, 4, image.rgba.data()); break;
    case ImageFormat::Png: break;
    }
    if (!ok || bytes.empty()) return Error(fmt::format("cannot encode '{}'", path));
    return write_bytes(bytes, path);
}

Status write_image(const Framebuffer& fb, int buffer, const std::string& path) {
    auto format = image_format_of(path);
    // PNG straight from the framebuffer's rows, with no copy of the image.
    if (format == ImageFormat::Png) return write_png(fb, path, buffer);
    return write_image(scene::read_framebuffer(fb, buffer), path);
}

}  // namespace glslrun::cli
