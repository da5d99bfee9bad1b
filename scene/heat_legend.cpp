// The heat maps' legend as an image (heat_legend.png beside them): the
// colour ramp with its ULP values, and the marker colours, labelled with
// stb_easy_font's quads (Debian's libstb-dev) filled into the pixels.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "glslrun/scene/float_error.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace glslrun::scene {
namespace {

constexpr int kWidth = 560, kHeight = 150, kScale = 2;
constexpr int kBarLeft = 20, kBarTop = 40, kBarWidth = 480, kBarHeight = 28;

// stb_easy_font's vertices: x, y, z as floats, then 4 bytes of colour.
struct FontVertex {
    float x, y, z;
    unsigned char rgba[4];
};

void fill(Image& image, int x0, int y0, int x1, int y1, const std::array<uint8_t, 3>& rgb) {
    for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) {
            uint8_t* p = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
            p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
        }
}

void text(Image& image, int x, int y, const std::string& s) {
    std::vector<FontVertex> quads(s.size() * 70);  // stb: at most ~60 quads per character
    std::string copy = s;
    int n = stb_easy_font_print(0, 0, copy.data(), nullptr, quads.data(), int(quads.size() * sizeof(FontVertex)));
    for (int q = 0; q < n; ++q) {
        const FontVertex* v = &quads[size_t(q) * 4];
        int x0 = int(std::lround(v[0].x)), y0 = int(std::lround(v[0].y));
        int x1 = int(std::lround(v[2].x)), y1 = int(std::lround(v[2].y));
        fill(image, x + std::min(x0, x1) * kScale, y + std::min(y0, y1) * kScale, x + std::max(x0, x1) * kScale,
             y + std::max(y0, y1) * kScale, {255, 255, 255});
    }
}

// A small square of `ulp`'s colour with its label.
void swatch(ImageError& e, int x, int y, uint64_t ulp) {
    for (int j = y; j < y + 16; ++j)
        for (int i = x; i < x + 16; ++i) e.pixel_ulp[size_t(j) * size_t(e.width) + size_t(i)] = ulp;
}

}  // namespace

Image heat_map_legend_image() {
    ImageError e;
    e.width = kWidth;
    e.height = kHeight;
    e.pixel_ulp.assign(size_t(kWidth) * kHeight, kBackground);
    // The ramp: 1 ULP at the left to 2^24 at the right, on heat_map()'s log2 scale.
    for (int i = 0; i < kBarWidth; ++i) {
        auto ulp = uint64_t(std::llround(std::exp2(24.0 * i / (kBarWidth - 1))));
        for (int j = kBarTop; j < kBarTop + kBarHeight; ++j) e.pixel_ulp[size_t(j) * kWidth + size_t(kBarLeft + i)] = ulp;
    }
    const int row = kBarTop + kBarHeight + 40;
    swatch(e, kBarLeft, row, 0);
    swatch(e, kBarLeft + 130, row, kCoverageMismatch);
    swatch(e, kBarLeft + 350, row, kNanUlp);
    Image image = heat_map(e);
    text(image, kBarLeft, 10, "ULP error per pixel (largest channel), log2 scale");
    const char* ticks[] = {"1", "64", "4096", "2^18", "2^24+"};
    for (int t = 0; t < 5; ++t)
        text(image, kBarLeft + t * (kBarWidth - 1) / 4 - (t == 4 ? 40 : 0), kBarTop + kBarHeight + 6, ticks[t]);
    text(image, kBarLeft + 22, row + 2, "exact");
    text(image, kBarLeft + 152, row + 2, "one image only");
    text(image, kBarLeft + 372, row + 2, "NaN in one image");
    text(image, kBarLeft, row + 26, "grey: no fragment in either image");
    return image;
}

}  // namespace glslrun::scene
