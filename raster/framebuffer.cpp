#include "raster/framebuffer.h"

#include <algorithm>
#include <cmath>

namespace glslrun {

Framebuffer::Framebuffer(int w, int h, bool float_target)
    : width(std::max(w, 0)), height(std::max(h, 0)), float_color(float_target),
      color(size_t(width) * height * 4, 0.0f), depth(size_t(width) * height, 1.0f) {}

void Framebuffer::clear_color(glm::vec4 c) {
    if (!float_color)
        for (int i = 0; i < 4; ++i) c[i] = raster::quantize_unorm8(c[i]);
    for (size_t i = 0; i < color.size(); i += 4)
        for (int k = 0; k < 4; ++k) color[i + k] = c[k];
}

void Framebuffer::clear_depth(float d) {
    float v = std::isnan(d) ? 0.0f : std::clamp(d, 0.0f, 1.0f);
    std::fill(depth.begin(), depth.end(), v);
}

glm::vec4 Framebuffer::pixel(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return glm::vec4(0.0f);
    const float* p = &color[(size_t(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

namespace raster {

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c) {
    float* p = &fb.color[(size_t(y) * fb.width + x) * 4];
    for (int k = 0; k < 4; ++k) p[k] = fb.float_color ? c[k] : quantize_unorm8(c[k]);
}

}  // namespace raster
}  // namespace glslrun
