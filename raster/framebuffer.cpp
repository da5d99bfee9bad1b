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

float quantize_unorm8(float v) {
    if (!(v > 0.0f)) return 0.0f;  // also NaN
    if (v >= 1.0f) return 1.0f;
    return std::nearbyint(v * 255.0f) / 255.0f;
}

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c) {
    float* p = &fb.color[(size_t(y) * fb.width + x) * 4];
    for (int k = 0; k < 4; ++k) p[k] = fb.float_color ? c[k] : quantize_unorm8(c[k]);
}

bool depth_passes(GLState::DepthFunc func, float incoming, float stored) {
    using F = GLState::DepthFunc;
    switch (func) {
    case F::Never: return false;
    case F::Less: return incoming < stored;
    case F::Equal: return incoming == stored;
    case F::Lequal: return incoming <= stored;
    case F::Greater: return incoming > stored;
    case F::Notequal: return incoming != stored;
    case F::Gequal: return incoming >= stored;
    case F::Always: return true;
    }
    return false;
}

}  // namespace raster
}  // namespace glslrun
