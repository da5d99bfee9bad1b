// Image files the command line writes: PNG (lossless, the default) through
// libpng, and JPEG, BMP and TGA through stb_image_write, chosen by the name.
#pragma once
#include <optional>
#include <string>

#include "glslrun/glslrun.h"
#include "glslrun/scene/image_compare.h"

namespace glslrun::cli {

enum class ImageFormat { Png, Jpeg, Bmp, Tga };

// By the name's ending, in any case (.png, .jpg/.jpeg, .bmp, .tga); "-"
// (standard output) is PNG; nullopt for any other name.
std::optional<ImageFormat> image_format_of(const std::string& path);

// Writes colour buffer `buffer` in the format its name asks for. Like PNGs,
// the other formats go through a temporary file renamed into place.
Status write_image(const Framebuffer& fb, int buffer, const std::string& path);
Status write_image(const scene::Image& image, const std::string& path);

}  // namespace glslrun::cli
