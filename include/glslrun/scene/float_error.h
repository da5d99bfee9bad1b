// Error statistics of one set of float values against a reference set: the
// numbers `glslrun --error-report` prints (docs/precision.md, "Error report").
//
// ULP distance. Floats are mapped to integers in value order: the bits of a
// non-negative float as they are, those of a negative one negated
// (-(bits & 0x7fffffff)). The distance is the difference of the two integers:
// the number of representable floats one has to step over to get from one
// value to the other.
//   - +0 and -0 are the same point: distance 0.
//   - Denormals are ordinary steps (FLT_TRUE_MIN is 1 ULP from 0).
//   - +Inf is one step past FLT_MAX; Inf against Inf of the same sign is 0.
//   - Across a sign change the distance counts every float through zero, so
//     -1e-30 against +1e-30 is about 2 * 0x0DA24260 ULP; the absolute error
//     and the 8-bit difference say whether that matters.
//   - NaN against NaN (any payload) is 0; NaN against a number is kNanUlp,
//     larger than any distance between two numbers (at most 0xFF000000,
//     -Inf to +Inf). Such pairs count in `nan_mismatches` and in the maximum,
//     not in the mean.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "glslrun/scene/image_compare.h"

namespace glslrun::scene {

inline constexpr uint64_t kNanUlp = uint64_t(1) << 32;

uint64_t ulp_distance(float a, float b);

// Where a float channel lands in an RGBA8 buffer: raster::to_unorm8's
// rounding, as an integer 0..255.
int to_unorm8(float v);

// The errors of one channel (or of one varying over its components).
struct ChannelError {
    uint64_t compared = 0;        // value pairs seen by add()
    uint64_t nan_mismatches = 0;  // NaN in exactly one of the two
    uint64_t max_ulp = 0;
    double sum_ulp = 0;           // over pairs without a NaN mismatch
    double max_abs = 0;           // |a - b| without NaN mismatches; Inf where an Inf is unmatched
    uint64_t compared_8bit = 0;   // value pairs seen by add_8bit()
    int max_8bit = 0;
    double sum_8bit = 0;

    uint64_t add(float reference, float actual);  // returns the pair's ULP distance
    int add_8bit(float reference, float actual);  // returns the pair's 8-bit difference
    void merge(const ChannelError& other);
    double mean_ulp() const;   // 0 when nothing was compared
    double mean_8bit() const;
};

// A value of the worst place found so far: a pixel (x, y) or a vertex (y is
// the object, x the vertex), with the values of both sides.
struct WorstPlace {
    bool found = false;
    int x = -1, y = -1;
    uint64_t ulp = 0;
    int diff_8bit = 0;
    std::vector<float> reference, actual;
};

// `channels` floats per pixel, row 0 at the bottom (GL's order), and per
// pixel whether a fragment was written there. Where none was, `values` hold
// what the buffer holds there (the clear colour or depth).
struct FloatImage {
    int width = 0, height = 0, channels = 4;
    std::vector<float> values;
    std::vector<uint8_t> covered;
};

// Per-pixel markers of ImageError::pixel_ulp besides ULP distances.
inline constexpr uint64_t kBackground = ~uint64_t(0);            // covered in neither image
inline constexpr uint64_t kCoverageMismatch = ~uint64_t(0) - 1;  // covered in one image only

// One shader output stored per pixel (a colour, or depth), against the reference.
struct ImageError {
    std::string name;  // "gl_FragColor", "depth"
    int width = 0, height = 0, channels = 4;
    bool quantized = true;  // an RGBA8 colour: 8-bit statistics too
    // ULP statistics over pixels covered in both images; 8-bit statistics
    // over pixels covered in either (elsewhere both hold the clear colour).
    std::array<ChannelError, 4> channel;
    uint64_t covered_both = 0, covered_one = 0;
    uint64_t differing_8bit = 0;  // pixels with some channel off in 8 bits
    // Pixel positions have the top-left origin of image files (row 0 = the
    // top); GL's window y is height - 1 - y.
    WorstPlace worst_ulp, worst_8bit;
    std::vector<uint64_t> pixel_ulp;  // top row first; max over channels, or a marker
    ChannelError total() const;       // all channels together
};

// `actual` against `reference`: sizes and channel counts must match.
Result<ImageError> compare_float_images(const std::string& name, const FloatImage& reference,
                                        const FloatImage& actual, bool quantized);

// One RGB colour per pixel of error.pixel_ulp on a log2 scale (heat_map_legend() says which).
Image heat_map(const ImageError& error);
std::string heat_map_legend();
// The legend as an image: the ramp with its ULP values and the marker colours, labelled.
Image heat_map_legend_image();

}  // namespace glslrun::scene
