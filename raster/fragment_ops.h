// The per-fragment operations after the fragment shader (GL 2.1 §4.1), in
// GL's order: alpha test, stencil test, depth test, then per colour buffer
// blending, logic op and colour mask. (The scissor test cuts the draw's
// rectangle before rasterization: draw.cpp.) Each runs over the lanes of one
// batch in lane order, so two quads of a batch that cover one pixel see each
// other's writes as GL's sequential order says; the fragment stage calls
// them one after the other, and a JIT's fused fragment function can call or
// inline the same functions.
#pragma once
#include <array>
#include <cstdint>

#include "glslrun/glslrun.h"
#include "runtime/interpreter.h"

namespace glslrun {
// Field by field (FragmentState's comparison).
inline bool operator==(const StencilFace& a, const StencilFace& b) {
    return a.func == b.func && a.ref == b.ref && a.value_mask == b.value_mask && a.write_mask == b.write_mask &&
           a.fail == b.fail && a.depth_fail == b.depth_fail && a.depth_pass == b.depth_pass;
}
inline bool operator==(const BlendState& a, const BlendState& b) {
    return a.src_rgb == b.src_rgb && a.dst_rgb == b.dst_rgb && a.src_alpha == b.src_alpha &&
           a.dst_alpha == b.dst_alpha && a.equation_rgb == b.equation_rgb && a.equation_alpha == b.equation_alpha &&
           a.color == b.color;
}
}  // namespace glslrun

namespace glslrun::raster {

using Lanes = std::array<float, rt::kLanes>;

using U8x4 = std::array<uint32_t, 4>;
using Unorm8 = std::array<uint8_t, 4>;

// Blending with the draw's factors and equations picked once (resolve_blend),
// so that no pixel switches over them: `pixel8` blends one pixel of an RGBA8
// buffer as blend_unorm8() does, `pixel_float` one of a float buffer as
// blend() does, bit for bit. The common glBlendFunc pairs get a function of
// their own; the others call the picked factor and equation functions.
struct ResolvedBlend {
    using Pixel8 = Unorm8 (*)(const ResolvedBlend&, const Unorm8& src, const Unorm8& dst);
    using Factor8 = U8x4 (*)(const U8x4& s, const U8x4& d, const U8x4& c);
    using Combine8 = uint32_t (*)(uint32_t s, uint32_t sf, uint32_t d, uint32_t df);
    Pixel8 pixel8 = nullptr;
    Factor8 src_rgb = nullptr, dst_rgb = nullptr, src_alpha = nullptr, dst_alpha = nullptr;
    Combine8 rgb = nullptr, alpha = nullptr;
    U8x4 constant8{};  // the blend colour as bytes
    BlendState state;
};
ResolvedBlend resolve_blend(const BlendState& s, ColorRounding rounding = ColorRounding::Nearest);

// The per-fragment state of a draw as the operations read it (GL's values
// clamped and masked), compared whole: the fused pipeline's key
// (raster/fused/state.h) holds all of it, so that a field added here is
// refused by the generated path (fused::fusable) until that path takes it.
struct FragmentState {
    bool alpha_test = false;
    CompareFunc alpha_func = CompareFunc::Always;
    float alpha_ref = 0;     // clamped to [0, 1] with RGBA8 buffers; compared as is with float buffers
    bool stencil_test = false;
    std::array<StencilFace, 2> stencil;  // front, back
    bool depth_test = false, depth_write = true;
    CompareFunc depth_func = CompareFunc::Less;
    bool blend = false, logic_op = false, float_color = false;
    ColorRounding rounding = ColorRounding::Nearest;  // the framebuffer's, for RGBA8 stores
    bool half_float = false;  // float stores truncated to binary16 (Framebuffer::half_float)
    BlendState blend_state;  // its colour clamped to [0, 1] with RGBA8 buffers
    LogicOp logic = LogicOp::Copy;
    std::array<bool, 4> color_mask{true, true, true, true};
    int draw_buffers = 1;  // colour buffers written (gl_FragData[i] to buffer i)
    bool operator==(const FragmentState&) const = default;
};

// The state of the operations, resolved once per draw from GLState.
struct FragmentOps : FragmentState {
    FragmentOps(const GLState& gl, const Framebuffer& fb);
    // Only the depth test (or none) and plain colour stores into one buffer:
    // the fragment stage's fast path, which needs none of the functions below.
    bool plain = true;
    float alpha_ref8 = 0;    // the byte RGBA8 storage would make of alpha_ref, as a float
    ResolvedBlend resolved_blend;
};

// Where the lanes of a batch are: window position, depth, facing.
struct LanePixels {
    const int* x;
    const int* y;
    const float* z;
    rt::LaneMask back;  // lanes of back-facing polygons (their stencil state is [1])
};

// GL 2.1 §4.1.4: the lanes of `mask` whose alpha passes glAlphaFunc.
// `compared`, when given, gets the alpha of each lane of `mask` as the test
// compared it with the reference (ops.alpha_ref or ops.alpha_ref8).
rt::LaneMask alpha_test(const FragmentOps& ops, const Lanes& alpha, rt::LaneMask mask, Lanes* compared = nullptr);

// §4.1.5 and §4.1.6: the stencil test, then the depth test, of each lane of
// `mask` in lane order, with their stencil and depth buffer updates; returns
// the lanes that pass both. `stencil_failed`, when given, gets the lanes
// that failed the stencil test (the others of `mask` not returned failed
// the depth test).
rt::LaneMask stencil_depth_test(const FragmentOps& ops, Framebuffer& fb, const LanePixels& px, rt::LaneMask mask,
                                rt::LaneMask* stencil_failed = nullptr);

// §4.1.8 to §4.2.2: blending, logic op, colour mask and the store of the
// lanes of `mask` into colour buffer `buffer` (RGBA8 storage rounds to n/255).
void write_color(const FragmentOps& ops, Framebuffer& fb, int buffer, const LanePixels& px,
                 const std::array<Lanes, 4>& rgba, rt::LaneMask mask);

// One pixel's blend (§4.1.8) into a float buffer: `src` the fragment's
// colour, `dst` the buffer's.
glm::vec4 blend(const BlendState& s, glm::vec4 src, glm::vec4 dst);
// One RGBA8 pixel's channels.
// The same into an RGBA8 buffer, in 8-bit fixed point as GPUs' blend units
// and llvmpipe compute it: the source, factors and constant are n/255 values
// and each product is rounded to n/255 before the equation (saturating)
// combines them. Float arithmetic rounded once at the end differed from
// Mesa by 2/255 on 1.6% of a blended scene (subtractions of rounded terms).
// With ColorRounding::Gpu the products are exact and only the result is
// rounded, to the nearest byte (combine8_gpu in fragment_ops.cpp).
Unorm8 blend_unorm8(const BlendState& s, const Unorm8& src, const Unorm8& dst,
                    ColorRounding rounding = ColorRounding::Nearest);
// One 8-bit channel's logic op (§4.1.10).
uint32_t logic_op(LogicOp op, uint32_t src, uint32_t dst);
// A stencil value after `op` (§4.1.5), before the write mask.
uint32_t stencil_op(StencilOp op, uint32_t value, int ref);

}  // namespace glslrun::raster
