#include "glslrun/scene/float_error.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "raster/framebuffer.h"

namespace glslrun::scene {

namespace {

// The float's position on a line where consecutive floats are consecutive
// integers and both zeros are 0.
int64_t ordered(float f) {
    uint32_t bits = std::bit_cast<uint32_t>(f);
    int64_t magnitude = int64_t(bits & 0x7fffffffu);
    return bits & 0x80000000u ? -magnitude : magnitude;
}

}  // namespace

uint64_t ulp_distance(float a, float b) {
    bool nan_a = std::isnan(a), nan_b = std::isnan(b);
    if (nan_a || nan_b) return nan_a == nan_b ? 0 : kNanUlp;
    int64_t d = ordered(a) - ordered(b);
    return uint64_t(d < 0 ? -d : d);
}

// The expression of raster/png.cpp and read_framebuffer(), byte for byte.
int to_unorm8(float v) { return raster::to_unorm8(v); }

uint64_t ChannelError::add(float reference, float actual) {
    ++compared;
    uint64_t ulp = ulp_distance(reference, actual);
    max_ulp = std::max(max_ulp, ulp);
    if (ulp == kNanUlp) {
        ++nan_mismatches;
        return ulp;
    }
    sum_ulp += double(ulp);
    // Inf - Inf of the same sign is NaN, but the values are equal.
    double abs = ulp == 0 ? 0.0 : std::fabs(double(reference) - double(actual));
    max_abs = std::max(max_abs, abs);
    return ulp;
}

int ChannelError::add_8bit(float reference, float actual) {
    ++compared_8bit;
    int diff = std::abs(to_unorm8(reference) - to_unorm8(actual));
    max_8bit = std::max(max_8bit, diff);
    sum_8bit += diff;
    return diff;
}

void ChannelError::merge(const ChannelError& o) {
    compared += o.compared;
    nan_mismatches += o.nan_mismatches;
    max_ulp = std::max(max_ulp, o.max_ulp);
    sum_ulp += o.sum_ulp;
    max_abs = std::max(max_abs, o.max_abs);
    compared_8bit += o.compared_8bit;
    max_8bit = std::max(max_8bit, o.max_8bit);
    sum_8bit += o.sum_8bit;
}

double ChannelError::mean_ulp() const {
    uint64_t n = compared - nan_mismatches;
    return n ? sum_ulp / double(n) : 0.0;
}

double ChannelError::mean_8bit() const { return compared_8bit ? sum_8bit / double(compared_8bit) : 0.0; }

ChannelError ImageError::total() const {
    ChannelError all;
    for (int c = 0; c < channels; ++c) all.merge(channel[size_t(c)]);
    return all;
}

namespace {

std::vector<float> pixel_values(const FloatImage& image, size_t pixel) {
    auto first = image.values.begin() + std::ptrdiff_t(pixel * size_t(image.channels));
    return {first, first + image.channels};
}

void note_worst(WorstPlace& place, const FloatImage& reference, const FloatImage& actual, size_t pixel,
                uint64_t ulp, int diff_8bit) {
    place.found = true;
    place.x = int(pixel % size_t(reference.width));
    place.y = reference.height - 1 - int(pixel / size_t(reference.width));
    place.ulp = ulp;
    place.diff_8bit = diff_8bit;
    place.reference = pixel_values(reference, pixel);
    place.actual = pixel_values(actual, pixel);
}

// One pixel's contribution; `image_index` is its index with the top row first.
void compare_pixel(ImageError& e, const FloatImage& reference, const FloatImage& actual, size_t pixel,
                   size_t image_index) {
    bool in_ref = reference.covered[pixel] != 0, in_actual = actual.covered[pixel] != 0;
    if (!in_ref && !in_actual) {
        e.pixel_ulp[image_index] = kBackground;
        return;
    }
    const float* r = &reference.values[pixel * size_t(e.channels)];
    const float* a = &actual.values[pixel * size_t(e.channels)];
    uint64_t ulp = 0;
    int diff = 0;
    for (int c = 0; c < e.channels; ++c) {
        ChannelError& ch = e.channel[size_t(c)];
        if (in_ref && in_actual) ulp = std::max(ulp, ch.add(r[c], a[c]));
        if (e.quantized) diff = std::max(diff, ch.add_8bit(r[c], a[c]));
    }
    e.differing_8bit += diff > 0;
    if (in_ref && in_actual) {
        ++e.covered_both;
        e.pixel_ulp[image_index] = ulp;
        // The first pixel in scan order (top row first) among equals.
        if (!e.worst_ulp.found || ulp > e.worst_ulp.ulp) note_worst(e.worst_ulp, reference, actual, pixel, ulp, diff);
    } else {
        ++e.covered_one;
        e.pixel_ulp[image_index] = kCoverageMismatch;
    }
    if (e.quantized && (!e.worst_8bit.found || diff > e.worst_8bit.diff_8bit))
        note_worst(e.worst_8bit, reference, actual, pixel, in_ref && in_actual ? ulp : kCoverageMismatch, diff);
}

Status check_image(const FloatImage& image, const char* which) {
    size_t pixels = size_t(image.width) * size_t(image.height);
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
        image.values.size() != pixels * size_t(image.channels) || image.covered.size() != pixels)
        return Error(fmt::format("error report: the {} image is malformed ({}x{}, {} channels, {} values, "
                                 "{} coverage flags)", which, image.width, image.height, image.channels,
                                 image.values.size(), image.covered.size()));
    return Ok{};
}

}  // namespace

Result<ImageError> compare_float_images(const std::string& name, const FloatImage& reference,
                                        const FloatImage& actual, bool quantized) {
    if (Status st = check_image(reference, "reference"); !st) return st.error();
    if (Status st = check_image(actual, "compared"); !st) return st.error();
    if (reference.width != actual.width || reference.height != actual.height ||
        reference.channels != actual.channels)
        return Error(fmt::format("error report: {} is {}x{}x{} in the reference and {}x{}x{} in the other image",
                                 name, reference.width, reference.height, reference.channels, actual.width,
                                 actual.height, actual.channels));
    ImageError e;
    e.name = name;
    e.width = reference.width;
    e.height = reference.height;
    e.channels = reference.channels;
    e.quantized = quantized;
    e.pixel_ulp.assign(size_t(e.width) * size_t(e.height), kBackground);
    // Top row first, so that the worst pixel is the first one a viewer meets.
    for (int y = e.height - 1; y >= 0; --y)
        for (int x = 0; x < e.width; ++x) {
            size_t pixel = size_t(y) * size_t(e.width) + size_t(x);
            compare_pixel(e, reference, actual, pixel, size_t(e.height - 1 - y) * size_t(e.width) + size_t(x));
        }
    return e;
}

// ----------------------------------------------------------------- heat map ---
namespace {

using Rgb = std::array<uint8_t, 3>;

constexpr Rgb kBackgroundColor{48, 48, 48};
constexpr Rgb kExactColor{0, 0, 0};
constexpr Rgb kCoverageColor{255, 255, 255};
constexpr Rgb kNanColor{255, 0, 255};
// log2(ULP) 0, 6, 12, 18, 24 and above: blue, cyan, green, yellow, red.
constexpr double kScaleTop = 24.0;
constexpr std::array<Rgb, 5> kStops{{{0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}}};

Rgb ramp(double log2_ulp) {
    double t = std::clamp(log2_ulp / kScaleTop, 0.0, 1.0) * double(kStops.size() - 1);
    size_t i = std::min(size_t(t), kStops.size() - 2);
    double f = t - double(i);
    Rgb out{};
    for (size_t k = 0; k < 3; ++k)
        out[k] = uint8_t(std::lround(double(kStops[i][k]) * (1 - f) + double(kStops[i + 1][k]) * f));
    return out;
}

Rgb heat_color(uint64_t ulp) {
    if (ulp == kBackground) return kBackgroundColor;
    if (ulp == kCoverageMismatch) return kCoverageColor;
    if (ulp == kNanUlp) return kNanColor;
    if (ulp == 0) return kExactColor;
    return ramp(std::log2(double(ulp)));
}

}  // namespace

Image heat_map(const ImageError& error) {
    Image image{error.width, error.height, std::vector<uint8_t>(error.pixel_ulp.size() * 4)};
    for (size_t i = 0; i < error.pixel_ulp.size(); ++i) {
        Rgb c = heat_color(error.pixel_ulp[i]);
        std::copy(c.begin(), c.end(), image.rgba.begin() + std::ptrdiff_t(i * 4));
        image.rgba[i * 4 + 3] = 255;
    }
    return image;
}

std::string heat_map_legend() {
    return "per pixel the largest ULP error of its channels, log2 scale: black 0 (exact), blue 1, cyan 64, "
           "green 4096, yellow 2^18, red 2^24 ULP or more (colours in between interpolate); white: covered "
           "in one image only; magenta: NaN in one image only; grey: background in both";
}

}  // namespace glslrun::scene
