// Blending and the colour mask as generated vector code (raster/fused/gen/blend.h).
#include "raster/fused/gen/blend.h"

#include "raster/framebuffer.h"

namespace glslrun::raster::fused {

std::array<llvm::Value*, 4> emit_blend_and_mask(llvm::IRBuilder<>& builder, const FragmentState& o,
                                                const std::array<llvm::Value*, 4>& src,
                                                const std::array<llvm::Value*, 4>& dst) {
    auto* v4i = llvm::FixedVectorType::get(builder.getInt32Ty(), 4);
    const bool gpu_rounding = o.rounding == ColorRounding::Gpu;
    const BlendState& s = o.blend_state;
    // The blend colour as the bytes resolve_blend makes of it.
    std::array<uint32_t, 4> constant8;
    for (size_t k = 0; k < 4; ++k) constant8[k] = to_unorm8(s.color[int(k)], o.rounding);
    auto constant = [&](uint32_t c) { return llvm::ConstantInt::get(v4i, c); };
    auto inv = [&](llvm::Value* x) { return builder.CreateSub(constant(255), x); };
    auto umin = [&](llvm::Value* x, llvm::Value* y) { return builder.CreateSelect(builder.CreateICmpULT(x, y), x, y); };
    auto umax = [&](llvm::Value* x, llvm::Value* y) { return builder.CreateSelect(builder.CreateICmpUGT(x, y), x, y); };
    // Table 4.1's factor for channel k (3: alpha) in 8-bit fixed point.
    auto factor = [&](BlendFactor f, size_t k) -> llvm::Value* {
        switch (f) {
        case BlendFactor::Zero: return constant(0);
        case BlendFactor::One: return constant(255);
        case BlendFactor::SrcColor: return src[k];
        case BlendFactor::OneMinusSrcColor: return inv(src[k]);
        case BlendFactor::DstColor: return dst[k];
        case BlendFactor::OneMinusDstColor: return inv(dst[k]);
        case BlendFactor::SrcAlpha: return src[3];
        case BlendFactor::OneMinusSrcAlpha: return inv(src[3]);
        case BlendFactor::DstAlpha: return dst[3];
        case BlendFactor::OneMinusDstAlpha: return inv(dst[3]);
        case BlendFactor::ConstantColor: return constant(constant8[k]);
        case BlendFactor::OneMinusConstantColor: return constant(255u - constant8[k]);
        case BlendFactor::ConstantAlpha: return constant(constant8[3]);
        case BlendFactor::OneMinusConstantAlpha: return constant(255u - constant8[3]);
        case BlendFactor::SrcAlphaSaturate: return k == 3 ? constant(255) : umin(src[3], inv(dst[3]));
        }
        return constant(0);
    };
    // raster::logic_op (§4.1.10) on bytes; the caller keeps the low 8 bits.
    auto logic = [&](LogicOp op, llvm::Value* s8, llvm::Value* d8) -> llvm::Value* {
        auto no = [&](llvm::Value* x) { return builder.CreateNot(x); };
        switch (op) {
        case LogicOp::Clear: return constant(0);
        case LogicOp::And: return builder.CreateAnd(s8, d8);
        case LogicOp::AndReverse: return builder.CreateAnd(s8, no(d8));
        case LogicOp::Copy: return s8;
        case LogicOp::AndInverted: return builder.CreateAnd(no(s8), d8);
        case LogicOp::Noop: return d8;
        case LogicOp::Xor: return builder.CreateXor(s8, d8);
        case LogicOp::Or: return builder.CreateOr(s8, d8);
        case LogicOp::Nor: return no(builder.CreateOr(s8, d8));
        case LogicOp::Equiv: return no(builder.CreateXor(s8, d8));
        case LogicOp::Invert: return no(d8);
        case LogicOp::OrReverse: return builder.CreateOr(s8, no(d8));
        case LogicOp::CopyInverted: return no(s8);
        case LogicOp::OrInverted: return builder.CreateOr(no(s8), d8);
        case LogicOp::Nand: return no(builder.CreateAnd(s8, d8));
        case LogicOp::Set: return constant(255);
        }
        return s8;
    };
    // mul_unorm8's (x * f * 2 + 255) / 510, the product rounded to n/255, as
    // (t + (t >> 8)) >> 8 with t = x * f + 128: equal for every x and f in
    // [0, 255] (tests/fused/fused_pipeline.cpp checks), and shifts, not a
    // division. With the GPU's rounding the product stays exact.
    auto product = [&](llvm::Value* x, llvm::Value* f) -> llvm::Value* {
        if (gpu_rounding) return builder.CreateMul(x, f);
        llvm::Value* t = builder.CreateAdd(builder.CreateMul(x, f), constant(128));
        return builder.CreateLShr(builder.CreateAdd(t, builder.CreateLShr(t, constant(8))), constant(8));
    };
    // raster's combine8_gpu: exact products (units of 1/65025), the result
    // stored by the GPU's rule, floor(c * 4096 / 65025) then (510 t + 4095) >> 13.
    constexpr uint32_t kOne = 255 * 255;
    auto stored = [&](llvm::Value* c) {
        llvm::Value* t = builder.CreateUDiv(builder.CreateMul(c, constant(4096)), constant(kOne));
        return builder.CreateLShr(builder.CreateAdd(builder.CreateMul(t, constant(510)), constant(4095)), constant(13));
    };
    const uint32_t one = gpu_rounding ? kOne : 255;
    std::array<llvm::Value*, 4> out;
    for (size_t k = 0; k < 4; ++k) {
        out[k] = src[k];
        if (o.logic_op) {
            out[k] = builder.CreateAnd(logic(o.logic, src[k], dst[k]), constant(255));
        } else if (o.blend) {
            const bool alpha = k == 3;
            const BlendEquation eq = alpha ? s.equation_alpha : s.equation_rgb;
            llvm::Value* a = product(src[k], factor(alpha ? s.src_alpha : s.src_rgb, k));
            llvm::Value* b = product(dst[k], factor(alpha ? s.dst_alpha : s.dst_rgb, k));
            switch (eq) {
            case BlendEquation::Add: out[k] = umin(builder.CreateAdd(a, b), constant(one)); break;
            case BlendEquation::Subtract: out[k] = builder.CreateSelect(builder.CreateICmpUGT(a, b), builder.CreateSub(a, b), constant(0)); break;
            case BlendEquation::ReverseSubtract: out[k] = builder.CreateSelect(builder.CreateICmpUGT(b, a), builder.CreateSub(b, a), constant(0)); break;
            case BlendEquation::Min: out[k] = umin(src[k], dst[k]); break;
            case BlendEquation::Max: out[k] = umax(src[k], dst[k]); break;
            }
            if (gpu_rounding && eq != BlendEquation::Min && eq != BlendEquation::Max) out[k] = stored(out[k]);
        }
        if (!o.color_mask[k]) out[k] = dst[k];
    }
    return out;
}

}  // namespace glslrun::raster::fused
