#include "raster/framebuffer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

namespace {

Status check_color_buffers(int count) {
    if (count >= 1 && count <= kMaxDrawBuffers) return Ok{};
    return Error(fmt::format("a framebuffer of {} colour buffers is not allowed: 1..{} (GL_MAX_DRAW_BUFFERS)", count,
                             kMaxDrawBuffers));
}

}  // namespace

Framebuffer::Framebuffer(int w, int h, bool float_target, int color_buffers) : float_color_(float_target) {
    if (!check_framebuffer_size(w, h) || !check_color_buffers(color_buffers)) return;
    width = w;
    height = h;
    const size_t pixels = size_t(w) * size_t(h), buffers = size_t(color_buffers);
    if (float_color_) float_colors_.assign(buffers, std::vector<float>(pixels * 4, 0.0f));
    else rgba8_colors_.assign(buffers, std::vector<uint8_t>(pixels * 4, 0));
    depth.assign(pixels, 1.0f);
    stencil.assign(pixels, 0);
}

Result<Framebuffer> Framebuffer::create(int w, int h, bool float_target, int color_buffers) {
    if (Status st = check_framebuffer_size(w, h); !st) return st.error();
    if (Status st = check_color_buffers(color_buffers); !st) return st.error();
    try {
        return Framebuffer(w, h, float_target, color_buffers);
    } catch (const std::bad_alloc&) {
        return Error(fmt::format("out of memory for a {}x{} framebuffer", w, h));
    }
}

namespace {

// Fills from this size on use x86's string store (fill_repeated).
constexpr size_t kStringStoreBytes = 4096;

// Fills `bytes` bytes at dst with `pattern` repeated: 16 bytes of whole
// elements (pixels, depths) whose size divides 16, so that a tail is a
// prefix of it. Clears are memory bound; whole 16-byte stores keep them so.
void fill_repeated(void* dst, size_t bytes, const std::array<uint8_t, 16>& pattern) {
    auto* p = static_cast<uint8_t*>(dst);
    size_t i = 0;
#if defined(__SSE2__)
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pattern.data()));
#if defined(__x86_64__)
    // Large fills of an 8-byte pattern (RGBA8 colour, depth): the string
    // store writes whole cache lines without reading them first (1080p
    // spot frame under the JIT: 6.32 -> 6.07 ms CPU, docs/performance.md).
    uint64_t halves[2];
    std::memcpy(halves, pattern.data(), 16);
    if (bytes >= kStringStoreBytes && halves[0] == halves[1]) {
        size_t words = bytes / 8;
        void* at = p;
        asm volatile("rep stosq" : "+D"(at), "+c"(words) : "a"(halves[0]) : "memory");
        i = bytes / 8 * 8;
    }
#endif
    for (; i + 16 <= bytes; i += 16) _mm_storeu_si128(reinterpret_cast<__m128i*>(p + i), v);
#else
    for (; i + 16 <= bytes; i += 16) std::memcpy(p + i, pattern.data(), 16);
#endif
    std::memcpy(p + i, pattern.data(), bytes - i);
}

template <class T>
std::array<uint8_t, 16> repeated(const T* element, size_t count) {
    static_assert(16 % sizeof(T) == 0);
    std::array<uint8_t, 16> out;
    for (size_t i = 0; i < 16; i += count * sizeof(T)) std::memcpy(&out[i], element, count * sizeof(T));
    return out;
}

size_t color_pixel_bytes(const Framebuffer& fb) { return fb.float_color() ? 4 * sizeof(float) : 4; }

void* color_at(Framebuffer& fb, int buffer, int x, int y) {
    size_t offset = (size_t(y) * size_t(fb.width) + size_t(x)) * 4;
    if (fb.float_color()) return fb.color_data<float>(buffer).data() + offset;
    return fb.color_data<uint8_t>(buffer).data() + offset;
}

}  // namespace

// The whole storage, whatever its size (draw() rejects a mismatch with width x height).
void Framebuffer::clear_color(glm::vec4 c) {
    const std::array<uint8_t, 16> pattern = raster::stored_clear(*this, ClearValues{c, {}, {}}).color_pattern;
    for (auto& buffer : float_colors_) fill_repeated(buffer.data(), buffer.size() * sizeof(float), pattern);
    for (auto& buffer : rgba8_colors_) fill_repeated(buffer.data(), buffer.size(), pattern);
}

void Framebuffer::clear_depth(float d) {
    float stored = raster::stored_clear(*this, ClearValues{std::nullopt, d, std::nullopt}).d;
    fill_repeated(depth.data(), depth.size() * sizeof(float), repeated(&stored, 1));
}

void Framebuffer::clear_stencil(int s) {
    std::fill(stencil.begin(), stencil.end(), raster::stored_clear(*this, ClearValues{std::nullopt, std::nullopt, s}).s);
}

glm::vec4 Framebuffer::pixel(int x, int y, int buffer) const {
    if (x < 0 || y < 0 || x >= width || y >= height || buffer < 0 || buffer >= color_buffers()) return glm::vec4(0.0f);
    size_t offset = (size_t(y) * size_t(width) + size_t(x)) * 4;
    if (float_color_) {
        const float* p = &float_colors_[size_t(buffer)][offset];
        return {p[0], p[1], p[2], p[3]};
    }
    const uint8_t* p = &rgba8_colors_[size_t(buffer)][offset];
    return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
}

namespace raster {

StoredClear stored_clear(const Framebuffer& fb, const ClearValues& clear) {
    StoredClear out;
    out.color = clear.color.has_value();
    out.depth = clear.depth.has_value();
    out.stencil = clear.stencil.has_value();
    if (clear.stencil) out.s = uint8_t(*clear.stencil & ((1 << kStencilBits) - 1));
    if (clear.color) {
        const glm::vec4 c = *clear.color;
        const uint8_t bytes[4] = {to_unorm8(c.r, fb.rounding), to_unorm8(c.g, fb.rounding), to_unorm8(c.b, fb.rounding),
                                 to_unorm8(c.a, fb.rounding)};
        const glm::vec4 stored = stored_float(fb, c);
        out.color_pattern = fb.float_color() ? repeated(&stored[0], 4) : repeated(bytes, 4);
    }
    if (clear.depth) out.d = std::isnan(*clear.depth) ? 0.0f : std::clamp(*clear.depth, 0.0f, 1.0f);
    return out;
}

bool storage_matches(const Framebuffer& fb) {
    const size_t pixels = size_t(fb.width) * size_t(fb.height);
    if (fb.depth.size() != pixels || fb.stencil.size() != pixels || fb.color_buffers() > kMaxDrawBuffers) return false;
    for (int i = 0; i < fb.color_buffers(); ++i) {
        size_t channels = fb.float_color() ? fb.color_data<float>(i).size() : fb.color_data<uint8_t>(i).size();
        if (channels != pixels * 4) return false;
    }
    return true;
}

void clear_rect(Framebuffer& fb, const StoredClear& clear, int x0, int y0, int x1, int y1) {
    const std::array<uint8_t, 16> depth = repeated(&clear.d, 1);
    // Whole rows are one block, filled at once.
    const bool whole_rows = x0 == 0 && x1 == fb.width;
    const size_t pixels = whole_rows ? size_t(x1) * size_t(y1 - y0) : size_t(x1 - x0);
    for (int y = y0; y < (whole_rows ? y0 + 1 : y1); ++y) {
        size_t start = size_t(y) * size_t(fb.width) + size_t(x0);
        for (int b = 0; clear.color && b < fb.color_buffers(); ++b)
            fill_repeated(color_at(fb, b, x0, y), pixels * color_pixel_bytes(fb), clear.color_pattern);
        if (clear.depth) fill_repeated(&fb.depth[start], pixels * sizeof(float), depth);
        if (clear.stencil) std::fill_n(&fb.stencil[start], pixels, clear.s);
    }
}

void write_color(Framebuffer& fb, int x, int y, glm::vec4 c) {
    if (fb.float_color()) {
        c = stored_float(fb, c);
        std::memcpy(color_at(fb, 0, x, y), &c[0], sizeof c);
        return;
    }
    auto* p = static_cast<uint8_t*>(color_at(fb, 0, x, y));
    for (int k = 0; k < 4; ++k) p[k] = to_unorm8(c[k], fb.rounding);
}

}  // namespace raster
}  // namespace glslrun
