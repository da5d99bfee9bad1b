#include "raster/framebuffer.h"

#include <algorithm>
#include <cmath>
#include <new>

#include <fmt/format.h>

namespace glslrun {

Status check_framebuffer_size(int w, int h) {
    if (w >= 1 && h >= 1 && w <= kMaxFramebufferSide && h <= kMaxFramebufferSide &&
        int64_t(w) * h <= kMaxFramebufferPixels)
        return Ok{};
    return Error(fmt::format("a {}x{} framebuffer is not allowed: each side must be 1..{} and the pixels at most {}M",
                             w, h, kMaxFramebufferSide, kMaxFramebufferPixels >> 20));
}

Framebuffer::Framebuffer(int w, int h, bool float_target, int color_buffers) : float_color(float_target) {
    if (!check_framebuffer_size(w, h)) return;
    width = w;
    height = h;
    color.assign(size_t(w) * size_t(h) * 4, 0.0f);
    more_colors.assign(size_t(std::clamp(color_buffers, 1, kMaxDrawBuffers) - 1), color);
    depth.assign(size_t(w) * size_t(h), 1.0f);
    stencil.assign(size_t(w) * size_t(h), 0);
}

Result<Framebuffer> Framebuffer::create(int w, int h, bool float_target, int color_buffers) {
    if (Status st = check_framebuffer_size(w, h); !st) return st.error();
    try {
        return Framebuffer(w, h, float_target, color_buffers);
    } catch (const std::bad_alloc&) {
        return Error(fmt::format("out of memory for a {}x{} framebuffer", w, h));
    }
}

namespace {

void fill_pixels(float* p, size_t pixels, glm::vec4 c) {
    for (size_t i = 0; i < pixels; ++i, p += 4)
        for (int k = 0; k < 4; ++k) p[k] = c[k];
}

}  // namespace

// The whole storage, whatever its size (draw() rejects a mismatch with width x height).
void Framebuffer::clear_color(glm::vec4 c) {
    glm::vec4 stored = raster::stored_clear(*this, ClearValues{c, std::nullopt, std::nullopt}).c;
    for (int i = 0; i < color_buffers(); ++i) fill_pixels(color_buffer(i).data(), color_buffer(i).size() / 4, stored);
}

void Framebuffer::clear_depth(float d) {
    std::fill(depth.begin(), depth.end(), raster::stored_clear(*this, ClearValues{std::nullopt, d, std::nullopt}).d);
}

void Framebuffer::clear_stencil(int s) {
    std::fill(stencil.begin(), stencil.end(), raster::stored_clear(*this, ClearValues{std::nullopt, std::nullopt, s}).s);
}

glm::vec4 Framebuffer::pixel(int x, int y, int buffer) const {
    if (x < 0 || y < 0 || x >= width || y >= height || buffer < 0 || buffer >= color_buffers()) return glm::vec4(0.0f);
    const float* p = &color_buffer(buffer)[(size_t(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

namespace raster {

StoredClear stored_clear(const Framebuffer& fb, const ClearValues& clear) {
    StoredClear out;
    out.color = clear.color.has_value();
    out.depth = clear.depth.has_value();
    out.stencil = clear.stencil.has_value();
    if (clear.stencil) out.s = uint8_t(*clear.stencil & ((1 << kStencilBits) - 1));
    if (clear.color) {
        out.c = *clear.color;
        if (!fb.float_color)
            for (int i = 0; i < 4; ++i) out.c[i] = quantize_unorm8(out.c[i]);
    }
    if (clear.depth) out.d = std::isnan(*clear.depth) ? 0.0f : std::clamp(*clear.depth, 0.0f, 1.0f);
    return out;
}

bool storage_matches(const Framebuffer& fb) {
    const size_t pixels = size_t(fb.width) * size_t(fb.height);
    if (fb.depth.size() != pixels || fb.stencil.size() != pixels || fb.color_buffers() > kMaxDrawBuffers) return false;
    for (int i = 0; i < fb.color_buffers(); ++i)
        if (fb.color_buffer(i).size() != pixels * 4) return false;
    return true;
}

void clear_rect(Framebuffer& fb, const StoredClear& clear, int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y) {
        size_t row = size_t(y) * size_t(fb.width);
        for (int b = 0; clear.color && b < fb.color_buffers(); ++b)
            fill_pixels(&fb.color_buffer(b)[(row + size_t(x0)) * 4], size_t(x1 - x0), clear.c);
        if (clear.depth) std::fill(&fb.depth[row + size_t(x0)], &fb.depth[row + size_t(x1)], clear.d);
        if (clear.stencil) std::fill(&fb.stencil[row + size_t(x0)], &fb.stencil[row + size_t(x1)], clear.s);
    }
}

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c) {
    float* p = &fb.color[(size_t(y) * fb.width + x) * 4];
    for (int k = 0; k < 4; ++k) p[k] = fb.float_color ? c[k] : quantize_unorm8(c[k]);
}

}  // namespace raster
}  // namespace glslrun
