// GLSL 1.10 §8.7 texture lookups into the `tex` instruction. The frontend does
// everything that is plain arithmetic, so the runtime only samples:
//
//   texture2DProj(s, v4)      coord = v4.xy / v4.w
//   shadow1D(s, v3)           coord = v3.x, ref = v3.z (the r coordinate)
//   shadow2DProj(s, v4)       coord = v4.xy / v4.w, ref = v4.z / v4.w
//   texture2D(s, c, bias)     in a fragment shader: ddx(c), ddy(c), bias
//   texture2DLod(s, c, lod)   lod given; also any lookup in a vertex shader
//                             (lod 0: vertex shaders have no derivatives)
//   texture2DRect(s, c)       as texture2D, target Rect: the sampler takes
//                             c unnormalized (runtime/sampling_rect.cpp)
//   texture2DArray(s, v3)     (EXT_texture_array) coord = v3.xy, layer v3.z;
//                             derivatives of v3.xy only (the sampler picks
//                             the layer); shadow2DArray's ref is v4.w
//   texture2DGradARB(s, c, dx, dy)   (ARB_shader_texture_lod) as texture2D
//                             with dx, dy in place of the screen derivatives,
//                             in either stage; the Proj forms divide c by q
//                             and take dx, dy as they are (the extension's
//                             "already projected" gradients)
//
// Derivatives are taken of the projected coordinates, as §3.8.8 computes
// rho from s/q and t/q.
#include <algorithm>

#include "frontend/lower.h"

namespace glslrun::frontend {

using ir::Kind;
using ir::Op;
using ir::Reg;

namespace {

bool sampler_target(const gl::TSampler& s, ir::TexTarget* target) {
    if (s.isArrayed()) {
        *target = s.dim == gl::Esd1D ? ir::TexTarget::A1D : ir::TexTarget::A2D;
        return s.dim == gl::Esd1D || s.dim == gl::Esd2D;
    }
    switch (s.dim) {
    case gl::Esd1D: *target = ir::TexTarget::T1D; return true;
    case gl::Esd2D: *target = ir::TexTarget::T2D; return true;
    case gl::Esd3D: *target = ir::TexTarget::T3D; return true;
    case gl::EsdCube: *target = ir::TexTarget::Cube; return true;
    case gl::EsdRect: *target = ir::TexTarget::Rect; return true;
    default: return false;
    }
}

}  // namespace

Value StageLowering::texture(gl::TIntermAggregate* n) {
    const gl::TIntermSequence& seq = n->getSequence();
    const gl::TOperator op = n->getOp();
    const bool proj = op == gl::EOpTextureProj || op == gl::EOpTextureProjLod || op == gl::EOpTextureProjGrad;
    const bool explicit_lod = op == gl::EOpTextureLod || op == gl::EOpTextureProjLod;
    const bool grad = op == gl::EOpTextureGrad || op == gl::EOpTextureProjGrad;
    if (seq.size() < (grad ? 4u : 2u) || (op != gl::EOpTexture && !proj && !explicit_lod && !grad))
        return fail(n, "this texture function is not part of GLSL 1.10/1.20");
    const gl::TType& sampler_type = seq[0]->getAsTyped()->getType();
    ir::TexInfo info;
    if (sampler_type.getBasicType() != gl::EbtSampler || !sampler_target(sampler_type.getSampler(), &info.target) ||
        (info.arrayed() && (proj || grad)))
        return fail(n, "only sampler1D/2D/3D/Cube/2DRect, sampler1D/2D/2DRectShadow and the 1D/2D array samplers "
                       "are supported");
    info.shadow = sampler_type.getSampler().isShadow();
    info.grad = grad;
    const bool has_extra = !grad && seq.size() > 2;  // bias, or the explicit lod
    const bool implicit = grad || (stage_ == ir::Stage::Fragment && !explicit_lod);
    info.lod = !implicit ? ir::TexLod::Explicit : has_extra ? ir::TexLod::ImplicitBias : ir::TexLod::Implicit;

    std::vector<Value> args;
    for (TIntermNode* c : seq) args.push_back(expr(c->getAsTyped()));
    set_line(n);
    const Reg unit = args[0].regs.at(0);
    const Value& coord = args[1];
    const uint32_t dims = info.dims();
    // The shadow reference: r of (s, t, r) (shadow1D's too), an array's after its layer.
    const uint32_t ref = std::max<uint32_t>(dims, 2);
    const size_t needed = std::max<size_t>(dims, info.shadow ? ref + 1 : 0) + (proj ? 1 : 0);
    if (coord.regs.size() < needed) return fail(n, "texture coordinate has too few components");

    // The projected coordinates, then the reference depth.
    Reg q = proj ? coord.regs.back() : ir::kNoReg;
    auto projected = [&](Reg r) { return proj ? alu(Op::fdiv, Kind::F32, r, q) : r; };
    std::vector<Reg> s;
    for (uint32_t d = 0; d < dims; ++d) s.push_back(projected(coord.regs[d]));
    std::vector<Reg> block_values = s;
    if (info.shadow) block_values.push_back(projected(coord.regs[ref]));
    if (info.lod == ir::TexLod::Explicit) block_values.push_back(has_extra ? args[2].regs.at(0) : konst_f(0.0f));
    if (info.lod == ir::TexLod::ImplicitBias) block_values.push_back(args[2].regs.at(0));
    if (grad) {
        for (const Value* d : {&args[2], &args[3]}) {
            if (d->regs.size() < dims) return fail(n, "texture gradient has too few components");
            for (uint32_t k = 0; k < dims; ++k) block_values.push_back(d->regs[k]);
        }
    } else if (implicit) {
        shader.uses_derivatives = true;
        for (Op d : {Op::ddx, Op::ddy})
            for (uint32_t k = 0; k < info.grad_dims(); ++k) block_values.push_back(alu(d, Kind::F32, s[k]));
    }

    const Reg block = new_range(std::vector<Kind>(block_values.size(), Kind::F32));
    for (size_t k = 0; k < block_values.size(); ++k) mov_to(block + Reg(k), block_values[k]);
    ir::Instr in;
    in.op = Op::tex;
    in.type = Kind::F32;
    in.dst = new_range(std::vector<Kind>(ir::kTexResults, Kind::F32));
    in.src[0] = unit;
    in.imm[0] = block;
    in.imm[1] = uint32_t(block_values.size());
    in.imm[2] = info.encode();
    emit(in);
    Value result;
    for (uint32_t c = 0; c < ir::kTexResults; ++c) result.regs.push_back(in.dst + c);
    return result;
}

}  // namespace glslrun::frontend
