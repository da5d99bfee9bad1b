// PNG files through libpng: the one place glslrun reads and writes them, for
// the public write_png (Framebuffer) and the scene library's Image functions.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::png {

// Framebuffer row y (0 = bottom, GL's order) as the RGBA8 bytes a PNG
// stores: the row itself for RGBA8 storage, else converted into `scratch`
// (width * 4 bytes).
const uint8_t* framebuffer_row(const Framebuffer& fb, int buffer, int y, uint8_t* scratch);

// Writes a width x height RGBA8 PNG; row(y, scratch) returns image row y
// (0 = top), width * 4 bytes, stored where it is or written into `scratch`.
// One row at a time: a whole image's bytes (1 MB at 512x512) cost more in
// page faults than their conversion.
using RowSource = std::function<const uint8_t*(int y, uint8_t* scratch)>;
Status write_rgba8(const std::string& path, int width, int height, const RowSource& row);

// Where an image file is written before it is renamed to `path`, so that a
// process killed meanwhile never leaves a truncated image there; `path`
// itself where it is not a regular file (/dev/stdout, a FIFO).
std::string staging_path(const std::string& path);

struct Rgba8Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;  // top row first
};
// Any 8-, 16-bit, grey, palette or RGB(A) PNG as RGBA8, without gamma
// correction (16-bit is scaled down). A side beyond max_side is refused
// before anything is allocated; errors name the file.
Result<Rgba8Image> read_rgba8(const std::string& path, int max_side);

}  // namespace glslrun::png
