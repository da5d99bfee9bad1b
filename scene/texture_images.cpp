// Texture images: files through stb_image (header-only from Debian's
// libstb-dev, compiled here with PNG and JPEG only), and procedural patterns.
#include "glslrun/scene/texture_images.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "scene/text_file.h"

// Static functions, so another stb_image in the same program cannot clash;
// only the two formats the scene format documents; no stdio (the file is
// read here, with our own size limit and error messages). stb's dimension
// limit stays its default: a lower one would make stbi_info fail with
// "unknown image type" instead of letting image_size() say what is wrong.
// The user messages ("Corrupt PNG") name the format; the terse ones may hold
// a chunk type's bytes, NUL included, in a buffer shared by all threads.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>

namespace glslrun::scene {

namespace {

Result<std::vector<unsigned char>> read_file(const std::string& path) {
    if (Status st = check_regular_file(path, "the image"); !st) return st.error();
    std::error_code ec;
    auto bytes = std::filesystem::file_size(path, ec);
    if (ec) return Error(fmt::format("cannot read the image '{}': {}", path, ec.message()));
    if (int64_t(bytes) > kMaxTextureFileBytes)
        return Error(fmt::format("the image '{}' is {} bytes; image files are limited to {} MiB", path, bytes,
                                 kMaxTextureFileBytes >> 20));
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error(fmt::format("cannot open the image '{}': {}", path, std::strerror(errno)));
    std::vector<unsigned char> data(static_cast<size_t>(bytes));
    in.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size()));
    if (in.gcount() != std::streamsize(data.size())) return Error(fmt::format("cannot read the image '{}'", path));
    return data;
}

enum class Format { Png, Jpeg, Other };

// By the file's signature: stbi_info's own failure reason is always "unknown
// image type" (its last attempt), which would hide what is wrong.
Format sniff(const std::vector<unsigned char>& d) {
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (d.size() >= 8 && std::equal(png, png + 8, d.begin())) return Format::Png;
    if (d.size() >= 3 && d[0] == 0xff && d[1] == 0xd8 && d[2] == 0xff) return Format::Jpeg;
    return Format::Other;
}

uint32_t big_endian(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

Status check_size(const std::string& path, int64_t w, int64_t h) {
    if (w < 1 || h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
        return Error(fmt::format("the image '{}' is {}x{}: textures are 1..{} texels per side (GL_MAX_TEXTURE_SIZE)",
                                 path, w, h, kMaxTextureSize));
    if (w * h > kMaxTextureTexels)
        return Error(fmt::format("the image '{}' is {}x{} = {} texels; a texture may hold at most {}", path, w, h,
                                 w * h, kMaxTextureTexels));
    return Ok{};
}

// Width and height from the header alone; nothing is decoded yet. A PNG's
// IHDR is read here first, because stb refuses a huge one without saying so.
Result<std::pair<int, int>> image_size(const std::string& path, const std::vector<unsigned char>& data) {
    Format format = sniff(data);
    if (format == Format::Other)
        return Error(fmt::format("'{}' is {}neither a PNG nor a JPEG file (the formats textures are read from)",
                                 path, data.empty() ? "empty: " : ""));
    const char* name = format == Format::Png ? "PNG" : "JPEG";
    if (format == Format::Png && data.size() >= 24 && std::equal(data.begin() + 12, data.begin() + 16, "IHDR"))
        if (Status st = check_size(path, big_endian(&data[16]), big_endian(&data[20])); !st) return st.error();
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data.data(), int(data.size()), &w, &h, &channels))
        return Error(fmt::format("'{}' is not a {} image that can be read: its header is corrupt", path, name));
    if (Status st = check_size(path, w, h); !st) return st.error();
    return std::pair{w, h};
}

}  // namespace

Result<TextureImage> read_texture_image(const std::string& path, bool bottom_up) {
    auto data = read_file(path);
    if (!data) return data.error();
    auto size = image_size(path, *data);
    if (!size) return size.error();
    int w = 0, h = 0, channels = 0;
    // stb tries JPEG before PNG, and a few of its PNG failures (an IDAT
    // length past 2^31) set no reason: the JPEG test's "Corrupt JPEG" would
    // be reported for a PNG. So the reason is cleared first (this file
    // compiles stb, whose reason is a thread-local of this file).
    stbi__g_failure_reason = nullptr;
    // Four channels requested: stb expands grey to (L, L, L) and adds alpha 255.
    stbi_uc* pixels = stbi_load_from_memory(data->data(), int(data->size()), &w, &h, &channels, 4);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        return Error(fmt::format("cannot decode the image '{}': {}", path,
                                 reason ? reason : sniff(*data) == Format::Png ? "Corrupt PNG" : "Corrupt JPEG"));
    }
    // A header that lied about the size would index past the decoded pixels.
    if (std::pair{w, h} != *size) {
        stbi_image_free(pixels);
        return Error(fmt::format("the image '{}' decodes to another size than its header states", path));
    }
    TextureImage image{w, h, 1, std::vector<glm::vec4>(size_t(w) * size_t(h))};
    for (int y = 0; y < h; ++y) {
        const stbi_uc* row = pixels + size_t(y) * size_t(w) * 4;
        size_t j = size_t(bottom_up ? h - 1 - y : y);
        for (int x = 0; x < w; ++x) {
            const stbi_uc* p = row + size_t(x) * 4;
            image.texels[j * size_t(w) + size_t(x)] = glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
        }
    }
    stbi_image_free(pixels);
    return image;
}

namespace {

template <class ColorAt>
TextureImage generate(Size3 size, ColorAt color_at) {
    TextureImage image{size[0], size[1], size[2], {}};
    image.texels.reserve(size_t(size[0]) * size_t(size[1]) * size_t(size[2]));
    for (int k = 0; k < size[2]; ++k)
        for (int j = 0; j < size[1]; ++j)
            for (int i = 0; i < size[0]; ++i) image.texels.push_back(color_at(i, j, k));
    return image;
}

// Which half of `n` texels index i lies in: piglit's `i < n / 2`, so a side
// of 1 texel is all in the upper half.
int half(int i, int n) { return i < n / 2 ? 0 : 1; }

}  // namespace

TextureImage checkerboard_image(Size3 size, Size3 square_size, const std::array<glm::vec4, 2>& colors) {
    return generate(size, [&](int i, int j, int k) {
        int parity = (i / square_size[0] + j / square_size[1] + k / square_size[2]) % 2;
        return colors[size_t(parity)];
    });
}

TextureImage rgbw_image(Size3 size, int dimensions, bool alpha) {
    const glm::vec4 red{1, 0, 0, alpha ? 0.0f : 1.0f}, green{0, 1, 0, alpha ? 64 / 255.0f : 1.0f};
    const glm::vec4 blue{0, 0, 1, alpha ? 128 / 255.0f : 1.0f}, white{1, 1, 1, 1};
    if (dimensions == 1) {
        const std::array<glm::vec4, 4> quarters{red, green, blue, white};
        return generate(size, [&](int i, int, int) { return quarters[size_t(i * 4 / size[0])]; });
    }
    if (dimensions == 2) {
        const std::array<glm::vec4, 4> quadrants{red, green, blue, white};
        return generate(size, [&](int i, int j, int) {
            return quadrants[size_t(half(i, size[0]) + 2 * half(j, size[1]))];
        });
    }
    const std::array<glm::vec4, 8> octants{red,       green, blue, white, {1, 1, 0, 1}, {1, 0, 1, 1},
                                           {0, 1, 1, 1}, {0, 0, 0, 1}};
    return generate(size, [&](int i, int j, int k) {
        return octants[size_t(half(i, size[0]) + 2 * half(j, size[1]) + 4 * half(k, size[2]))];
    });
}

TextureImage solid_image(Size3 size, glm::vec4 color) {
    return generate(size, [&](int, int, int) { return color; });
}

}  // namespace glslrun::scene
