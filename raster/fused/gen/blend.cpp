// Blending and the colour mask as generated vector code (raster/fused/gen/blend.h).
#include "raster/fused/gen/blend.h"

#include <functional>

#include "raster/framebuffer.h"

namespace glslrun::raster::fused {

namespace {

// How a blend factor is made in one arithmetic (8-bit fixed point or
// float): 0, 1, 1 - x, the blend colour's channel k and 1 minus it, min.
struct FactorTerms {
    llvm::Value *zero, *one;
    std::function<llvm::Value*(llvm::Value*)> inv;
    std::function<llvm::Value*(size_t)> color, inv_color;
    std::function<llvm::Value*(llvm::Value*, llvm::Value*)> min;
};

// GL 2.1 Table 4.1's factor `f` for channel k (3: alpha).
llvm::Value* factor_of(BlendFactor f, size_t k, const std::array<llvm::Value*, 4>& src,
                       const std::array<llvm::Value*, 4>& dst, const FactorTerms& t) {
    switch (f) {
    case BlendFactor::Zero: return t.zero;
    case BlendFactor::One: return t.one;
    case BlendFactor::SrcColor: return src[k];
    case BlendFactor::OneMinusSrcColor: return t.inv(src[k]);
    case BlendFactor::DstColor: return dst[k];
    case BlendFactor::OneMinusDstColor: return t.inv(dst[k]);
    case BlendFactor::SrcAlpha: return src[3];
    case BlendFactor::OneMinusSrcAlpha: return t.inv(src[3]);
    case BlendFactor::DstAlpha: return dst[3];
    case BlendFactor::OneMinusDstAlpha: return t.inv(dst[3]);
    case BlendFactor::ConstantColor: return t.color(k);
    case BlendFactor::OneMinusConstantColor: return t.inv_color(k);
    case BlendFactor::ConstantAlpha: return t.color(3);
    case BlendFactor::OneMinusConstantAlpha: return t.inv_color(3);
    case BlendFactor::SrcAlphaSaturate: return k == 3 ? t.one : t.min(src[3], t.inv(dst[3]));
    }
    return t.zero;
}

}  // namespace

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
    const FactorTerms terms{constant(0), constant(255), inv, [&](size_t k) { return constant(constant8[k]); },
                            [&](size_t k) { return constant(255u - constant8[k]); }, umin};
    auto factor = [&](BlendFactor f, size_t k) { return factor_of(f, k, src, dst, terms); };
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
    // rounded to the nearest byte, (c + 127) / 255.
    constexpr uint32_t kOne = 255 * 255;
    auto stored = [&](llvm::Value* c) { return builder.CreateUDiv(builder.CreateAdd(c, constant(127)), constant(255)); };
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

std::array<llvm::Value*, 4> emit_blend_float(llvm::IRBuilder<>& b, const FragmentState& o,
                                             const std::array<llvm::Value*, 4>& src,
                                             const std::array<llvm::Value*, 4>& dst) {
    const BlendState& s = o.blend_state;
    auto constant = [&](float v) { return llvm::ConstantFP::get(b.getFloatTy(), v); };
    // ir::a_nan_first(a, r), as raster's combine() names NaNs.
    auto nan_first = [&](llvm::Value* a, llvm::Value* r) { return b.CreateSelect(b.CreateFCmpUNO(a, a), b.CreateFAdd(a, a), r); };
    auto inv = [&](llvm::Value* x) { return b.CreateFSub(constant(1.0f), x); };
    auto min = [&](llvm::Value* x, llvm::Value* y) { return b.CreateSelect(b.CreateFCmpOLT(y, x), y, x); };  // std::min
    auto max = [&](llvm::Value* x, llvm::Value* y) { return b.CreateSelect(b.CreateFCmpOLT(x, y), y, x); };  // std::max
    // raster's factor() for channel k (3: alpha).
    const FactorTerms terms{constant(0.0f), constant(1.0f), inv, [&](size_t k) { return constant(s.color[int(k)]); },
                            [&](size_t k) { return constant(1.0f - s.color[int(k)]); }, min};
    auto factor = [&](BlendFactor f, size_t k) { return factor_of(f, k, src, dst, terms); };
    std::array<llvm::Value*, 4> out;
    for (size_t k = 0; k < 4; ++k) {
        const bool alpha = k == 3;
        const BlendEquation eq = alpha ? s.equation_alpha : s.equation_rgb;
        llvm::Value* a = src[k];
        a = nan_first(a, b.CreateFMul(a, factor(alpha ? s.src_alpha : s.src_rgb, k)));
        llvm::Value* d = dst[k];
        d = nan_first(d, b.CreateFMul(d, factor(alpha ? s.dst_alpha : s.dst_rgb, k)));
        switch (eq) {
        case BlendEquation::Add: out[k] = nan_first(a, b.CreateFAdd(a, d)); break;
        case BlendEquation::Subtract: out[k] = nan_first(a, b.CreateFSub(a, d)); break;
        case BlendEquation::ReverseSubtract: out[k] = nan_first(d, b.CreateFSub(d, a)); break;
        case BlendEquation::Min: out[k] = min(src[k], dst[k]); break;
        case BlendEquation::Max: out[k] = max(src[k], dst[k]); break;
        }
    }
    return out;
}

}  // namespace glslrun::raster::fused
