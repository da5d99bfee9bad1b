#include "raster/fragment_ops.h"

#include <algorithm>
#include <array>
#include <bit>
#include <utility>

#include "ir/scalar_ops.h"
#include "raster/framebuffer.h"
#include "runtime/half_float.h"

namespace glslrun::raster {

namespace {

constexpr uint32_t kStencilMax = (1u << kStencilBits) - 1;

// GL 2.1 Table 4.1: the factor of one operand (RGB, then alpha in .a).
glm::vec4 factor(BlendFactor f, glm::vec4 src, glm::vec4 dst, glm::vec4 constant) {
    switch (f) {
    case BlendFactor::Zero: return glm::vec4(0.0f);
    case BlendFactor::One: return glm::vec4(1.0f);
    case BlendFactor::SrcColor: return src;
    case BlendFactor::OneMinusSrcColor: return 1.0f - src;
    case BlendFactor::DstColor: return dst;
    case BlendFactor::OneMinusDstColor: return 1.0f - dst;
    case BlendFactor::SrcAlpha: return glm::vec4(src.a);
    case BlendFactor::OneMinusSrcAlpha: return glm::vec4(1.0f - src.a);
    case BlendFactor::DstAlpha: return glm::vec4(dst.a);
    case BlendFactor::OneMinusDstAlpha: return glm::vec4(1.0f - dst.a);
    case BlendFactor::ConstantColor: return constant;
    case BlendFactor::OneMinusConstantColor: return 1.0f - constant;
    case BlendFactor::ConstantAlpha: return glm::vec4(constant.a);
    case BlendFactor::OneMinusConstantAlpha: return glm::vec4(1.0f - constant.a);
    case BlendFactor::SrcAlphaSaturate: {
        float f = std::min(src.a, 1.0f - dst.a);
        return {f, f, f, 1.0f};
    }
    }
    return glm::vec4(0.0f);
}

// Each product and sum names its first operand's NaN where that is one
// (ir::a_nan_first): with two NaNs, which one x86 returns follows the
// compiler's operand order, and the fused pipeline's generated blending
// (raster/fused/gen/blend.cpp) must give the same bits.
float combine(BlendEquation eq, float s, float sf, float d, float df) {
    const float a = ir::a_nan_first(s, s * sf), b = ir::a_nan_first(d, d * df);
    switch (eq) {
    case BlendEquation::Add: return ir::a_nan_first(a, a + b);
    case BlendEquation::Subtract: return ir::a_nan_first(a, a - b);
    case BlendEquation::ReverseSubtract: return ir::a_nan_first(b, b - a);
    case BlendEquation::Min: return std::min(s, d);  // factors unused (§4.1.8)
    case BlendEquation::Max: return std::max(s, d);
    }
    return s;
}

// a * b / 255 rounded to the nearest integer, for a and b in 0..255.
uint32_t mul_unorm8(uint32_t a, uint32_t b) { return (a * b * 2 + 255) / 510; }

// Table 4.1's factor of one operand in 8-bit fixed point (RGB, then alpha in [3]).
std::array<uint32_t, 4> factor8(BlendFactor f, const std::array<uint32_t, 4>& s, const std::array<uint32_t, 4>& d,
                                const std::array<uint32_t, 4>& c) {
    auto all = [](uint32_t v) { return std::array<uint32_t, 4>{v, v, v, v}; };
    auto inv = [](std::array<uint32_t, 4> v) {
        for (uint32_t& x : v) x = 255 - x;
        return v;
    };
    switch (f) {
    case BlendFactor::Zero: return all(0);
    case BlendFactor::One: return all(255);
    case BlendFactor::SrcColor: return s;
    case BlendFactor::OneMinusSrcColor: return inv(s);
    case BlendFactor::DstColor: return d;
    case BlendFactor::OneMinusDstColor: return inv(d);
    case BlendFactor::SrcAlpha: return all(s[3]);
    case BlendFactor::OneMinusSrcAlpha: return all(255 - s[3]);
    case BlendFactor::DstAlpha: return all(d[3]);
    case BlendFactor::OneMinusDstAlpha: return all(255 - d[3]);
    case BlendFactor::ConstantColor: return c;
    case BlendFactor::OneMinusConstantColor: return inv(c);
    case BlendFactor::ConstantAlpha: return all(c[3]);
    case BlendFactor::OneMinusConstantAlpha: return all(255 - c[3]);
    case BlendFactor::SrcAlphaSaturate: {
        uint32_t v = std::min(s[3], 255 - d[3]);
        return {v, v, v, 255};
    }
    }
    return all(0);
}

uint32_t combine8(BlendEquation eq, uint32_t s, uint32_t sf, uint32_t d, uint32_t df) {
    int a = int(mul_unorm8(s, sf)), b = int(mul_unorm8(d, df));
    switch (eq) {
    case BlendEquation::Add: return uint32_t(std::min(a + b, 255));
    case BlendEquation::Subtract: return uint32_t(std::max(a - b, 0));
    case BlendEquation::ReverseSubtract: return uint32_t(std::max(b - a, 0));
    case BlendEquation::Min: return std::min(s, d);
    case BlendEquation::Max: return std::max(s, d);
    }
    return s;
}

// ColorRounding::Gpu's blending, as NVIDIA's driver blends into RGBA8: the
// source is stored as a byte first (gpu_unorm8), then the bytes and factors
// combine exactly (products in units of 1/65025), and the result, clamped to
// [0, 1], is rounded to the nearest byte (c / 255 is never a tie): not by
// gpu_unorm8's truncating rule, which gives one less on 3% of the blends.
// tools/gpu_probes/blendover.frag measured it: all 4,194,304 channels of
// SRC_ALPHA, ONE_MINUS_SRC_ALPHA over random bytes (docs/precision.md, "The
// GPU's colour conversion"); bench/corpus/volume blends 48 slices so.
uint32_t combine8_gpu(BlendEquation eq, uint32_t s, uint32_t sf, uint32_t d, uint32_t df) {
    constexpr uint32_t kOne = 255 * 255;
    const uint32_t a = s * sf, b = d * df;
    uint32_t c = 0;
    switch (eq) {
    case BlendEquation::Add: c = std::min(a + b, kOne); break;
    case BlendEquation::Subtract: c = a > b ? a - b : 0; break;
    case BlendEquation::ReverseSubtract: c = b > a ? b - a : 0; break;
    case BlendEquation::Min: return std::min(s, d);  // stored bytes: the rule gives them back
    case BlendEquation::Max: return std::max(s, d);
    }
    return (c + 127) / 255;
}

// One function per factor and equation: the switch folds away at compile time.
template <BlendFactor F>
U8x4 factor8_of(const U8x4& s, const U8x4& d, const U8x4& c) { return factor8(F, s, d, c); }
template <BlendEquation E>
uint32_t combine8_of(uint32_t s, uint32_t sf, uint32_t d, uint32_t df) { return combine8(E, s, sf, d, df); }
template <BlendEquation E>
uint32_t combine8_gpu_of(uint32_t s, uint32_t sf, uint32_t d, uint32_t df) { return combine8_gpu(E, s, sf, d, df); }

template <size_t... I>
constexpr std::array<ResolvedBlend::Factor8, sizeof...(I)> factor8_table(std::index_sequence<I...>) {
    return {&factor8_of<BlendFactor(I)>...};
}
template <size_t... I>
constexpr std::array<ResolvedBlend::Combine8, sizeof...(I)> combine8_table(std::index_sequence<I...>) {
    return {&combine8_of<BlendEquation(I)>...};
}
template <size_t... I>
constexpr std::array<ResolvedBlend::Combine8, sizeof...(I)> combine8_gpu_table(std::index_sequence<I...>) {
    return {&combine8_gpu_of<BlendEquation(I)>...};
}
constexpr auto kFactor8 = factor8_table(std::make_index_sequence<size_t(BlendFactor::SrcAlphaSaturate) + 1>());
constexpr auto kCombine8 = combine8_table(std::make_index_sequence<size_t(BlendEquation::Max) + 1>());
constexpr auto kCombine8Gpu = combine8_gpu_table(std::make_index_sequence<size_t(BlendEquation::Max) + 1>());

U8x4 widen(const Unorm8& v) { return {v[0], v[1], v[2], v[3]}; }

// blend_unorm8 through the picked functions.
Unorm8 blend8_picked(const ResolvedBlend& b, const Unorm8& src, const Unorm8& dst) {
    const U8x4 s8 = widen(src), d8 = widen(dst), &c8 = b.constant8;
    U8x4 sf = b.src_rgb(s8, d8, c8), df = b.dst_rgb(s8, d8, c8);
    uint32_t sfa = b.src_alpha(s8, d8, c8)[3], dfa = b.dst_alpha(s8, d8, c8)[3];
    Unorm8 out;
    for (size_t k = 0; k < 3; ++k) out[k] = uint8_t(b.rgb(s8[k], sf[k], d8[k], df[k]));
    out[3] = uint8_t(b.alpha(s8[3], sfa, d8[3], dfa));
    return out;
}

// glBlendFunc(S, D) with one equation E for all channels, inlined whole.
template <BlendFactor S, BlendFactor D, BlendEquation E>
Unorm8 blend8_same(const ResolvedBlend& b, const Unorm8& src, const Unorm8& dst) {
    const U8x4 s8 = widen(src), d8 = widen(dst);
    U8x4 sf = factor8(S, s8, d8, b.constant8), df = factor8(D, s8, d8, b.constant8);
    Unorm8 out;
    for (size_t k = 0; k < 4; ++k) out[k] = uint8_t(combine8(E, s8[k], sf[k], d8[k], df[k]));
    return out;
}

size_t pixel_index(const LanePixels& px, int lane, int width) {
    return size_t(px.y[lane]) * size_t(width) + size_t(px.x[lane]);
}

// The stencil test and update of one fragment (§4.1.5, §4.1.6); true when
// it passes both tests; `stencil_failed` says which one it failed.
bool stencil_depth_one(const FragmentOps& ops, const StencilFace& face, uint8_t& stencil, float z, float& depth,
                       bool& stencil_failed) {
    auto update = [&](StencilOp op) {
        if (!ops.stencil_test) return;
        uint32_t v = stencil_op(op, stencil, face.ref);
        stencil = uint8_t((stencil & ~face.write_mask) | (v & face.write_mask));
    };
    if (ops.stencil_test) {
        uint32_t ref = uint32_t(std::clamp(face.ref, 0, int(kStencilMax)));
        // 8-bit values are exact as floats: the depth test's comparison serves.
        if (!depth_passes(face.func, float(ref & face.value_mask), float(stencil & face.value_mask))) {
            update(face.fail);
            stencil_failed = true;
            return false;
        }
    }
    if (ops.depth_test && !depth_passes(ops.depth_func, z, depth)) {
        update(face.depth_fail);
        return false;
    }
    update(face.depth_pass);
    if (ops.depth_test && ops.depth_write) depth = z;
    return true;
}

}  // namespace

// ARB_color_buffer_float's CLAMP_FRAGMENT_COLOR is FIXED_ONLY in a GL 2.1
// context: the fragment's colour, the alpha test's reference and the blend
// colour are clamped to [0, 1] for RGBA8 buffers and kept as they are for
// float ones (Mesa picks AlphaRef or AlphaRefUnclamped, BlendColor or
// BlendColorUnclamped, by the same rule).
FragmentOps::FragmentOps(const GLState& gl, const Framebuffer& fb) {
    float_color = fb.float_color();
    half_float = float_color && fb.half_float;
    alpha_test = gl.alpha_test;
    alpha_func = gl.alpha_func;
    alpha_ref = float_color ? gl.alpha_ref : std::clamp(gl.alpha_ref, 0.0f, 1.0f);
    alpha_ref8 = unorm8_steps(alpha_ref);
    stencil_test = gl.stencil_test;
    stencil = gl.stencil;
    depth_test = gl.depth_test;
    depth_write = gl.depth_mask;
    depth_func = gl.depth_func;
    blend = gl.blend;
    logic_op = gl.color_logic_op && !float_color;
    rounding = fb.rounding;
    blend_state = gl.blend_state;
    logic = gl.logic_op;
    color_mask = gl.color_mask;
    draw_buffers = gl.draw_buffers;
    if (!float_color) blend_state.color = glm::clamp(blend_state.color, 0.0f, 1.0f);
    resolved_blend = resolve_blend(blend_state, rounding);
    for (StencilFace& f : stencil) f.value_mask &= kStencilMax, f.write_mask &= kStencilMax;
    bool all_channels = color_mask == std::array<bool, 4>{true, true, true, true};
    plain = !alpha_test && !stencil_test && !blend && !logic_op && all_channels && draw_buffers == 1 &&
            (depth_write || !depth_test);
}

ResolvedBlend resolve_blend(const BlendState& s, ColorRounding rounding) {
    ResolvedBlend b;
    b.state = s;
    for (size_t k = 0; k < 4; ++k) b.constant8[k] = to_unorm8(s.color[int(k)], rounding);
    b.src_rgb = kFactor8[size_t(s.src_rgb)];
    b.dst_rgb = kFactor8[size_t(s.dst_rgb)];
    b.src_alpha = kFactor8[size_t(s.src_alpha)];
    b.dst_alpha = kFactor8[size_t(s.dst_alpha)];
    const auto& combine = rounding == ColorRounding::Gpu ? kCombine8Gpu : kCombine8;
    b.rgb = combine[size_t(s.equation_rgb)];
    b.alpha = combine[size_t(s.equation_alpha)];
    b.pixel8 = &blend8_picked;
    if (rounding == ColorRounding::Gpu) return b;  // the functions below round as Nearest
    // SrcAlphaSaturate's alpha factor is 1, not its RGB's: not a "same" pair.
    bool same = s.src_rgb == s.src_alpha && s.dst_rgb == s.dst_alpha && s.equation_rgb == s.equation_alpha &&
                s.src_rgb != BlendFactor::SrcAlphaSaturate && s.equation_rgb == BlendEquation::Add;
    if (!same) return b;
    using F = BlendFactor;
    constexpr auto kAdd = BlendEquation::Add;
    if (s.src_rgb == F::SrcAlpha && s.dst_rgb == F::OneMinusSrcAlpha) b.pixel8 = &blend8_same<F::SrcAlpha, F::OneMinusSrcAlpha, kAdd>;
    if (s.src_rgb == F::One && s.dst_rgb == F::One) b.pixel8 = &blend8_same<F::One, F::One, kAdd>;
    if (s.src_rgb == F::One && s.dst_rgb == F::OneMinusSrcAlpha) b.pixel8 = &blend8_same<F::One, F::OneMinusSrcAlpha, kAdd>;
    if (s.src_rgb == F::SrcAlpha && s.dst_rgb == F::One) b.pixel8 = &blend8_same<F::SrcAlpha, F::One, kAdd>;
    if (s.src_rgb == F::DstColor && s.dst_rgb == F::Zero) b.pixel8 = &blend8_same<F::DstColor, F::Zero, kAdd>;
    return b;
}

uint32_t stencil_op(StencilOp op, uint32_t value, int ref) {
    switch (op) {
    case StencilOp::Keep: return value;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return uint32_t(std::clamp(ref, 0, int(kStencilMax)));
    case StencilOp::Incr: return std::min(value + 1, kStencilMax);
    case StencilOp::Decr: return value > 0 ? value - 1 : 0;
    case StencilOp::Invert: return ~value & kStencilMax;
    case StencilOp::IncrWrap: return (value + 1) & kStencilMax;
    case StencilOp::DecrWrap: return (value - 1) & kStencilMax;
    }
    return value;
}

uint32_t logic_op(LogicOp op, uint32_t s, uint32_t d) {
    uint32_t r = 0;
    switch (op) {
    case LogicOp::Clear: r = 0; break;
    case LogicOp::And: r = s & d; break;
    case LogicOp::AndReverse: r = s & ~d; break;
    case LogicOp::Copy: r = s; break;
    case LogicOp::AndInverted: r = ~s & d; break;
    case LogicOp::Noop: r = d; break;
    case LogicOp::Xor: r = s ^ d; break;
    case LogicOp::Or: r = s | d; break;
    case LogicOp::Nor: r = ~(s | d); break;
    case LogicOp::Equiv: r = ~(s ^ d); break;
    case LogicOp::Invert: r = ~d; break;
    case LogicOp::OrReverse: r = s | ~d; break;
    case LogicOp::CopyInverted: r = ~s; break;
    case LogicOp::OrInverted: r = ~s | d; break;
    case LogicOp::Nand: r = ~(s & d); break;
    case LogicOp::Set: r = ~0u; break;
    }
    return r & 0xFFu;
}

glm::vec4 blend(const BlendState& s, glm::vec4 src, glm::vec4 dst) {
    glm::vec4 sf = factor(s.src_rgb, src, dst, s.color), df = factor(s.dst_rgb, src, dst, s.color);
    float sfa = factor(s.src_alpha, src, dst, s.color).a, dfa = factor(s.dst_alpha, src, dst, s.color).a;
    glm::vec4 out;
    for (int k = 0; k < 3; ++k) out[k] = combine(s.equation_rgb, src[k], sf[k], dst[k], df[k]);
    out.a = combine(s.equation_alpha, src.a, sfa, dst.a, dfa);
    return out;
}

Unorm8 blend_unorm8(const BlendState& s, const Unorm8& src, const Unorm8& dst, ColorRounding rounding) {
    const std::array<uint32_t, 4> s8{src[0], src[1], src[2], src[3]}, d8{dst[0], dst[1], dst[2], dst[3]};
    std::array<uint32_t, 4> c8;
    for (size_t k = 0; k < 4; ++k) c8[k] = to_unorm8(s.color[int(k)], rounding);
    std::array<uint32_t, 4> sf = factor8(s.src_rgb, s8, d8, c8), df = factor8(s.dst_rgb, s8, d8, c8);
    uint32_t sfa = factor8(s.src_alpha, s8, d8, c8)[3], dfa = factor8(s.dst_alpha, s8, d8, c8)[3];
    Unorm8 out;
    auto combine = rounding == ColorRounding::Gpu ? &combine8_gpu : &combine8;
    for (size_t k = 0; k < 3; ++k) out[k] = uint8_t(combine(s.equation_rgb, s8[k], sf[k], d8[k], df[k]));
    out[3] = uint8_t(combine(s.equation_alpha, s8[3], sfa, d8[3], dfa));
    return out;
}

rt::LaneMask alpha_test(const FragmentOps& ops, const Lanes& alpha, rt::LaneMask mask, Lanes* compared) {
    for (rt::LaneMask bits = mask; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        // §4.1.4 compares in the colour buffer's precision: with RGBA8 storage,
        // the bytes that alpha and the reference would be stored as (llvmpipe
        // too, so that 128/255 passes EQUAL 0.5 and 0.1005 fails GREATER 0.1).
        // Float buffers compare the shader's value as is.
        float a = ops.float_color ? alpha[size_t(lane)] : unorm8_steps(alpha[size_t(lane)]);
        bool passes = depth_passes(ops.alpha_func, a, ops.float_color ? ops.alpha_ref : ops.alpha_ref8);
        if (compared) (*compared)[size_t(lane)] = a;
        if (!passes) mask &= ~(rt::LaneMask(1) << lane);
    }
    return mask;
}

rt::LaneMask stencil_depth_test(const FragmentOps& ops, Framebuffer& fb, const LanePixels& px, rt::LaneMask mask,
                                rt::LaneMask* stencil_failed) {
    for (rt::LaneMask bits = mask; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        size_t pixel = pixel_index(px, lane, fb.width);
        const StencilFace& face = ops.stencil[(px.back >> lane) & 1u];
        bool stencil_fail = false;
        if (!stencil_depth_one(ops, face, fb.stencil[pixel], px.z[lane], fb.depth[pixel], stencil_fail))
            mask &= ~(rt::LaneMask(1) << lane);
        if (stencil_fail && stencil_failed) *stencil_failed |= rt::LaneMask(1) << lane;
    }
    return mask;
}

namespace {

void write_float(const FragmentOps& ops, float* buffer, int width, const LanePixels& px,
                 const std::array<Lanes, 4>& rgba, rt::LaneMask mask) {
    for (rt::LaneMask bits = mask; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        float* dst = &buffer[pixel_index(px, lane, width) * 4];
        glm::vec4 s{rgba[0][size_t(lane)], rgba[1][size_t(lane)], rgba[2][size_t(lane)], rgba[3][size_t(lane)]};
        glm::vec4 out = ops.blend ? blend(ops.blend_state, s, glm::vec4{dst[0], dst[1], dst[2], dst[3]}) : s;
        for (int k = 0; k < 4; ++k)
            if (ops.color_mask[size_t(k)]) dst[k] = ops.half_float ? rt::truncate_to_half(out[k]) : out[k];
    }
}

// The shader's colour is clamped to [0, 1] and rounded to bytes first
// (§3.11.6, §4.1.8): blending and the logic op work on the bytes.
void write_unorm8(const FragmentOps& ops, uint8_t* buffer, int width, const LanePixels& px,
                  const std::array<Lanes, 4>& rgba, rt::LaneMask mask) {
    for (rt::LaneMask bits = mask; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        uint8_t* dst = &buffer[pixel_index(px, lane, width) * 4];
        const Unorm8 d{dst[0], dst[1], dst[2], dst[3]};
        Unorm8 out;
        for (size_t k = 0; k < 4; ++k) out[k] = to_unorm8(rgba[k][size_t(lane)], ops.rounding);
        if (ops.logic_op) {
            for (size_t k = 0; k < 4; ++k) out[k] = uint8_t(logic_op(ops.logic, out[k], d[k]));
        } else if (ops.blend) {
            out = ops.resolved_blend.pixel8(ops.resolved_blend, out, d);
        }
        for (size_t k = 0; k < 4; ++k)
            if (ops.color_mask[k]) dst[k] = out[k];
    }
}

}  // namespace

void write_color(const FragmentOps& ops, Framebuffer& fb, int buffer, const LanePixels& px,
                 const std::array<Lanes, 4>& rgba, rt::LaneMask mask) {
    if (ops.float_color) write_float(ops, fb.color_data<float>(buffer).data(), fb.width, px, rgba, mask);
    else write_unorm8(ops, fb.color_data<uint8_t>(buffer).data(), fb.width, px, rgba, mask);
}

}  // namespace glslrun::raster
