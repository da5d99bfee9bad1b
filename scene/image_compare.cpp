#include "glslrun/scene/image_compare.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "raster/framebuffer.h"
#include "raster/png.h"
#include "glslrun/scene/scene.h"
#include "scene/text_file.h"

namespace glslrun::scene {

namespace {

// ------------------------------------------------------------- diffing ---
int channel_diff(const uint8_t* a, const uint8_t* b, int c) { return std::abs(int(a[c]) - int(b[c])); }

int pixel_diff(const uint8_t* a, const uint8_t* b) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, channel_diff(a, b, c));
    return worst;
}

bool is_colour(const uint8_t* p, const Rgba8& c) { return std::equal(c.begin(), c.end(), p); }

Status check_same_size(const Image& reference, const Image& actual) {
    if (reference.width == actual.width && reference.height == actual.height) return Ok{};
    return Error(fmt::format("the images differ in size: the reference is {}x{}, the other {}x{}", reference.width,
                             reference.height, actual.width, actual.height));
}

Status check_options(const CompareOptions& o) {
    if (o.tolerance < 0 || o.tolerance > 255) return Error(fmt::format("tolerance {} is not in 0..255", o.tolerance));
    if (!(o.min_fraction_within >= 0.0 && o.min_fraction_within <= 1.0))
        return Error(fmt::format("required fraction {} is not in 0..1", o.min_fraction_within));
    return Ok{};
}

Status check_image(const Image& image, const char* which) {
    if (image.width < 0 || image.height < 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
        return Error(fmt::format("the {} image's {} bytes do not hold {}x{} RGBA8 pixels", which, image.rgba.size(),
                                 image.width, image.height));
    return Ok{};
}

// Adds one pixel pair to the running statistics; returns its largest channel difference.
int accumulate(CompareStats& s, std::array<uint64_t, 4>& sums, const uint8_t* ref, const uint8_t* act,
               const CompareOptions& o) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
        int d = channel_diff(ref, act, c);
        sums[size_t(c)] += uint64_t(d);
        s.max_diff[size_t(c)] = std::max(s.max_diff[size_t(c)], d);
        worst = std::max(worst, d);
    }
    if (worst > o.tolerance) ++s.differing;
    if (!o.clear_color || !is_colour(ref, *o.clear_color) || !is_colour(act, *o.clear_color)) ++s.covered;
    return worst;
}

}  // namespace

// ----------------------------------------------------------- public API ---
Result<Image> read_png(const std::string& path) {
    // A FIFO would block libpng's fopen for ever.
    if (Status st = check_regular_file(path, "the image"); !st) return st.error();
    auto read = png::read_rgba8(path, kMaxImageSide);
    if (!read) return read.error();
    return Image{read->width, read->height, std::move(read->rgba)};
}

Status write_png(const Image& image, const std::string& path) {
    if (Status st = check_path(path, "output"); !st) return st;
    if (Status st = check_image(image, "output"); !st) return st;
    return png::write_rgba8(path, image.width, image.height, [&](int y, uint8_t*) { return image.pixel(0, y); });
}

Image read_framebuffer(const Framebuffer& fb, int buffer) {
    Image image{fb.width, fb.height, std::vector<uint8_t>(size_t(fb.width) * size_t(fb.height) * 4)};
    const size_t row = size_t(fb.width) * 4;
    for (int y = 0; y < fb.height; ++y) {
        // The bytes glslrun::write_png stores.
        uint8_t* dst = &image.rgba[size_t(y) * row];
        const uint8_t* src = png::framebuffer_row(fb, buffer, fb.height - 1 - y, dst);
        if (src != dst) std::copy_n(src, row, dst);
    }
    return image;
}

Result<Image> image_from_bottom_up(int width, int height, std::span<const uint8_t> rgba) {
    if (width < 0 || height < 0 || rgba.size() != size_t(width) * size_t(height) * 4)
        return Error(fmt::format("{} bytes do not hold {}x{} RGBA8 pixels", rgba.size(), width, height));
    Image image{width, height, std::vector<uint8_t>(rgba.size())};
    size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(rgba.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row), row, &image.rgba[size_t(y) * row]);
    return image;
}

Rgba8 to_rgba8(glm::vec4 color) {
    Rgba8 out{};
    for (int c = 0; c < 4; ++c) out[size_t(c)] = raster::to_unorm8(color[c]);
    return out;
}

int CompareStats::max_channel_diff() const { return *std::max_element(max_diff.begin(), max_diff.end()); }

double CompareStats::differing_percent() const { return pixels ? 100.0 * double(differing) / double(pixels) : 0.0; }

double CompareStats::covered_within_fraction() const {
    // Background pixels equal the clear colour in both images, so every
    // differing pixel is covered.
    return covered ? double(covered - differing) / double(covered) : 1.0;
}

std::string CompareStats::summary() const {
    std::string s = fmt::format("{}x{}: max diff R/G/B/A {}/{}/{}/{}, mean {:.4f}/{:.4f}/{:.4f}/{:.4f}; ", width,
                                height, max_diff[0], max_diff[1], max_diff[2], max_diff[3], mean_diff[0], mean_diff[1],
                                mean_diff[2], mean_diff[3]);
    s += fmt::format("{} of {} pixels ({:.4f}%) differ by more than {}; ", differing, pixels, differing_percent(),
                     tolerance);
    s += fmt::format("{:.4f}% of {} covered pixels within tolerance (need {:.4f}%): {}", 100.0 * covered_within_fraction(),
                     covered, 100.0 * min_fraction_within, passed ? "PASS" : "FAIL");
    if (worst_x >= 0) s += fmt::format("; largest difference at ({}, {}) from the top left", worst_x, worst_y);
    return s;
}

Result<CompareStats> compare_images(const Image& reference, const Image& actual, const CompareOptions& options) {
    for (Status st : {check_options(options), check_image(reference, "reference"), check_image(actual, "other"),
                      check_same_size(reference, actual)})
        if (!st) return st.error();
    CompareStats s;
    s.width = reference.width;
    s.height = reference.height;
    s.pixels = uint64_t(s.width) * uint64_t(s.height);
    s.tolerance = options.tolerance;
    s.min_fraction_within = options.min_fraction_within;
    std::array<uint64_t, 4> sums{};
    int worst = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const uint8_t *ref = reference.pixel(x, y), *act = actual.pixel(x, y);
            int d = accumulate(s, sums, ref, act, options);
            if (d > worst) {
                worst = d;
                s.worst_x = x;
                s.worst_y = y;
            }
        }
    for (size_t c = 0; c < 4; ++c) s.mean_diff[c] = s.pixels ? double(sums[c]) / double(s.pixels) : 0.0;
    s.passed = s.covered_within_fraction() >= options.min_fraction_within;
    return s;
}

Result<Image> diff_image(const Image& reference, const Image& actual, int tolerance) {
    CompareOptions options;
    options.tolerance = tolerance;
    for (Status st : {check_options(options), check_image(reference, "reference"), check_image(actual, "other"),
                      check_same_size(reference, actual)})
        if (!st) return st.error();
    Image out{reference.width, reference.height, std::vector<uint8_t>(reference.rgba.size())};
    for (size_t p = 0; p < out.rgba.size(); p += 4) {
        const uint8_t *ref = &reference.rgba[p], *act = &actual.rgba[p];
        int d = pixel_diff(ref, act);
        uint8_t* o = &out.rgba[p];
        if (d > tolerance) {
            // 1/255 already shows clearly; 64/255 and more are full red.
            o[0] = uint8_t(std::min(255, 150 + d * 105 / 64));
            o[1] = o[2] = 0;
        } else {
            // Dimmed, so that red stands out even against white.
            int luma = (299 * ref[0] + 587 * ref[1] + 114 * ref[2]) / 1000;
            o[0] = o[1] = o[2] = uint8_t(32 + luma * 96 / 255);
        }
        o[3] = 255;
    }
    return out;
}

}  // namespace glslrun::scene
