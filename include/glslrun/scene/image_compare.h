// RGBA8 images and their comparison: `glslrun --compare`, tools/glref and the
// reference tests (glslrun against Mesa) all measure differences the same way.
//
// An Image's row 0 is the TOP row, as in PNG files and image viewers; GL's
// buffers (glslrun::Framebuffer, glReadPixels) start at the bottom, so the
// functions that take them flip the rows.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::scene {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4 bytes, top row first
    const uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

using Rgba8 = std::array<uint8_t, 4>;

// Any 8-, 16-bit, grey, palette or RGB(A) PNG, converted to RGBA8 without
// gamma correction (the stored values as they are; 16-bit is scaled down).
// Missing, corrupt, truncated and oversized files (> kMaxImageSide per side,
// refused before anything is allocated) are errors naming the file.
Result<Image> read_png(const std::string& path);
Status write_png(const Image& image, const std::string& path);

// The framebuffer's colours quantised exactly as glslrun::write_png does, so
// an in-memory comparison sees the bytes the PNG file would hold.
Image read_framebuffer(const Framebuffer& fb);
// Rows as glReadPixels returns them (bottom row first, tightly packed RGBA8).
Result<Image> image_from_bottom_up(int width, int height, std::span<const uint8_t> rgba);
// A colour as an RGBA8 buffer stores it (glClearColor's value after the clear).
Rgba8 to_rgba8(glm::vec4 color);

struct CompareOptions {
    int tolerance = 1;  // per channel, 0..255: a pixel "differs" when some channel is off by more
    // The pass rule: at least this fraction of the covered pixels are within tolerance.
    double min_fraction_within = 0.999;
    // Pixels equal to it in both images are background, not "covered". Without
    // it every pixel counts as covered.
    std::optional<Rgba8> clear_color;
};

struct CompareStats {
    int width = 0, height = 0;
    std::array<int, 4> max_diff{};      // per channel R, G, B, A
    std::array<double, 4> mean_diff{};  // per channel, over all pixels
    uint64_t pixels = 0;
    uint64_t differing = 0;  // pixels with some channel off by more than the tolerance
    uint64_t covered = 0;    // pixels that differ from the clear colour in either image
    int worst_x = -1, worst_y = -1;  // a pixel with the largest channel difference (top-left origin)
    int tolerance = 0;
    double min_fraction_within = 0;
    bool passed = false;
    int max_channel_diff() const;
    double differing_percent() const;           // of all pixels
    double covered_within_fraction() const;     // of covered pixels within tolerance; 1 when none are covered
    std::string summary() const;                // one line for people
};

// `reference` against `actual`. Different sizes are an error naming both;
// so is a tolerance outside 0..255 or a fraction outside 0..1.
Result<CompareStats> compare_images(const Image& reference, const Image& actual, const CompareOptions& options);

// The reference in dimmed grey, with each pixel that differs by more than
// `tolerance` in red, brighter for larger differences. Sizes must match.
Result<Image> diff_image(const Image& reference, const Image& actual, int tolerance);

}  // namespace glslrun::scene
