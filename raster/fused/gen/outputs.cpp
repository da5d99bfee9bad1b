// The fused pipeline's outputs function (raster/fused/gen/emitter.h): after
// the shader, raster/fragment_ops.cpp's operations in GL's order, quad by
// quad in lane order: the alpha test, the stencil and depth tests with
// their buffer updates, then the colour writes into each draw buffer.
#include <algorithm>
#include <array>
#include <vector>

#include "raster/framebuffer.h"
#include "raster/fused/gen/blend.h"
#include "raster/fused/gen/emitter.h"

namespace glslrun::raster::fused {

// raster::stencil_op on i32 values (0 to 255): a scalar, or a vector of them.
llvm::Value* PipelineEmitter::stencil_op(StencilOp op, llvm::Value* v, int ref) {
    constexpr uint32_t kMax = (1u << kStencilBits) - 1;
    auto k = [&](uint32_t c) { return llvm::ConstantInt::get(v->getType(), c); };
    switch (op) {
    case StencilOp::Keep: return v;
    case StencilOp::Zero: return k(0);
    case StencilOp::Replace: return k(uint32_t(std::clamp(ref, 0, int(kMax))));
    case StencilOp::Incr: {
        llvm::Value* up = b_.CreateAdd(v, k(1));
        return b_.CreateSelect(b_.CreateICmpULT(up, k(kMax)), up, k(kMax));
    }
    case StencilOp::Decr: return b_.CreateSelect(b_.CreateICmpUGT(v, k(0)), b_.CreateSub(v, k(1)), k(0));
    case StencilOp::Invert: return b_.CreateAnd(b_.CreateNot(v), k(kMax));
    case StencilOp::IncrWrap: return b_.CreateAnd(b_.CreateAdd(v, k(1)), k(kMax));
    case StencilOp::DecrWrap: return b_.CreateAnd(b_.CreateSub(v, k(1)), k(kMax));
    }
    return v;
}

// The stencil test's outcome on `stored` (i32 values, scalar or vector),
// the depth test's (`depth_passes`, i1 of the same shape), and the new
// stencil values through the write mask (raster::stencil_depth_one).
PipelineEmitter::StencilOutcome PipelineEmitter::stencil_outcome(const StencilFace& face, llvm::Value* stored,
                                                                 llvm::Value* depth_passes) {
    llvm::Type* t = stored->getType();
    auto k = [&](uint32_t c) { return llvm::ConstantInt::get(t, c); };
    auto updated = [&](StencilOp op) {
        llvm::Value* v = stencil_op(op, stored, face.ref);
        return b_.CreateOr(b_.CreateAnd(stored, k(~face.write_mask)), b_.CreateAnd(v, k(face.write_mask)));
    };
    // Bytes compare exactly as floats: raster compares them with depth_passes.
    const uint32_t ref = uint32_t(std::clamp(face.ref, 0, int((1u << kStencilBits) - 1)));
    llvm::Type* ft = t->isVectorTy() ? llvm::VectorType::get(f32_, llvm::cast<llvm::VectorType>(t)) : f32_;
    llvm::Value* passes = compare(face.func, llvm::ConstantFP::get(ft, float(ref & face.value_mask)),
                                  b_.CreateUIToFP(b_.CreateAnd(stored, k(face.value_mask)), ft));
    StencilOutcome out;
    out.value = b_.CreateSelect(passes, b_.CreateSelect(depth_passes, updated(face.depth_pass), updated(face.depth_fail)),
                                updated(face.fail));
    out.passes = b_.CreateAnd(passes, depth_passes);
    return out;
}

// The stencil and depth tests of lane i (raster::stencil_depth_test's
// stencil_depth_one with `face`), if it is in `mask` (i32, bit i: lane i),
// with their buffer updates; returns `mask` less the lane where it fails.
llvm::Value* PipelineEmitter::stencil_depth_lane(const StencilFace& face, const Quad& q, int i, llvm::Value* z,
                                                 llvm::Value* mask) {
    llvm::Value* lane = b_.CreateICmpNE(b_.CreateAnd(mask, b_.getInt32(1u << i)), b_.getInt32(0));
    return if_then(lane, mask, [&] {
        llvm::Value* pixel = pixel_index(b_.CreateExtractElement(q.px, uint64_t(i)),
                                         b_.CreateExtractElement(q.py, uint64_t(i)), target_.width);
        llvm::Value* slot = b_.CreateInBoundsGEP(i8_, target_.stencil, pixel);
        llvm::Value* stored = b_.CreateZExt(b_.CreateLoad(i8_, slot), i32_);
        llvm::Value* depth_passes_here = b_.getTrue();
        llvm::Value* depth_slot = nullptr;
        llvm::Value* zi = b_.CreateExtractElement(z, uint64_t(i));
        if (ops_.depth_test) {
            depth_slot = b_.CreateInBoundsGEP(f32_, target_.depth, pixel);
            depth_passes_here = depth_passes(zi, b_.CreateLoad(f32_, depth_slot));
        }
        const StencilOutcome o = stencil_outcome(face, stored, depth_passes_here);
        b_.CreateStore(b_.CreateTrunc(o.value, i8_), slot);
        if (ops_.depth_test && ops_.depth_write) {
            llvm::Value* old = b_.CreateLoad(f32_, depth_slot);
            b_.CreateStore(b_.CreateSelect(o.passes, zi, old), depth_slot);
        }
        llvm::Value* failed = b_.CreateShl(b_.CreateZExt(b_.CreateNot(o.passes), i32_), uint64_t(i));
        return b_.CreateAnd(mask, b_.CreateNot(failed));
    });
}

// The stencil and depth tests of a quad's lanes in lane order, with the
// front or back face's state as its primitive faces.
llvm::Value* PipelineEmitter::stencil_depth_lanes(const Quad& q, llvm::Value* z, llvm::Value* mask) {
    auto lanes = [&](const StencilFace& face) {
        llvm::Value* m = mask;
        for (int i = 0; i < 4; ++i) m = stencil_depth_lane(face, q, i, z, m);
        return m;
    };
    if (ops_.stencil[0] == ops_.stencil[1]) return lanes(ops_.stencil[0]);
    llvm::Value* front = b_.CreateICmpNE(b_.CreateLoad(i8_, at(q.prim, kFront)), b_.getInt8(0));
    llvm::BasicBlock* back_block = llvm::BasicBlock::Create(b_.getContext(), "back_face", fn_);
    llvm::BasicBlock* front_block = llvm::BasicBlock::Create(b_.getContext(), "front_face", fn_);
    llvm::BasicBlock* tested = llvm::BasicBlock::Create(b_.getContext(), "stencil_tested", fn_);
    b_.CreateCondBr(front, front_block, back_block);
    b_.SetInsertPoint(front_block);
    llvm::Value* front_mask = lanes(ops_.stencil[0]);
    llvm::BasicBlock* front_end = b_.GetInsertBlock();
    b_.CreateBr(tested);
    b_.SetInsertPoint(back_block);
    llvm::Value* back_mask = lanes(ops_.stencil[1]);
    llvm::BasicBlock* back_end = b_.GetInsertBlock();
    b_.CreateBr(tested);
    b_.SetInsertPoint(tested);
    llvm::PHINode* merged = b_.CreatePHI(i32_, 2);
    merged->addIncoming(front_mask, front_end);
    merged->addIncoming(back_mask, back_end);
    return merged;
}

// The float colour of a quad's lanes in `lanes` (i32, bit i: lane i):
// blended where the draw blends, the channels of the colour mask (raster's
// write_float).
void PipelineEmitter::write_float_lanes(const Quad& q, const QuadValues& v, llvm::Value* lanes,
                                        llvm::Value* buffer) {
    const bool all = ops_.color_mask == std::array<bool, 4>{true, true, true, true};
    for (int i = 0; i < 4; ++i) {
        llvm::BasicBlock* write = llvm::BasicBlock::Create(b_.getContext(), "write", fn_);
        llvm::BasicBlock* next = llvm::BasicBlock::Create(b_.getContext(), "next", fn_);
        b_.CreateCondBr(b_.CreateICmpNE(b_.CreateAnd(lanes, b_.getInt32(1u << i)), b_.getInt32(0)), write, next);
        b_.SetInsertPoint(write);
        llvm::Value* pixel = pixel_index(b_.CreateExtractElement(q.px, uint64_t(i)),
                                         b_.CreateExtractElement(q.py, uint64_t(i)), target_.width);
        llvm::Value* dst = b_.CreateInBoundsGEP(f32_, buffer, b_.CreateShl(pixel, 2));
        std::array<llvm::Value*, 4> out;
        for (unsigned k = 0; k < 4; ++k) out[k] = b_.CreateExtractElement(v.rgba[k], uint64_t(i));
        if (ops_.blend) {
            std::array<llvm::Value*, 4> stored;
            for (unsigned k = 0; k < 4; ++k) stored[k] = b_.CreateLoad(f32_, b_.CreateConstInBoundsGEP1_64(f32_, dst, k));
            out = emit_blend_float(b_, ops_, out, stored);
        }
        if (all) {
            llvm::Value* texel = llvm::PoisonValue::get(v4f_);
            for (unsigned k = 0; k < 4; ++k) texel = b_.CreateInsertElement(texel, out[k], uint64_t(k));
            b_.CreateAlignedStore(texel, dst, llvm::Align(4));
        } else {
            for (unsigned k = 0; k < 4; ++k)
                if (ops_.color_mask[k]) b_.CreateStore(out[k], b_.CreateConstInBoundsGEP1_64(f32_, dst, k));
        }
        b_.CreateBr(next);
        b_.SetInsertPoint(next);
    }
}

// The alpha test (raster::alpha_test) of a quad's lanes: a mask (i32, bit
// i: lane i) of those that pass. RGBA8 storage compares the bytes alpha
// and the reference would be stored as.
llvm::Value* PipelineEmitter::alpha_passes(const QuadValues& v) {
    llvm::Value* a = v.alpha;
    float ref = ops_.alpha_ref;
    if (!ops_.float_color) {
        constexpr float kRound = 8388608.0f;
        a = b_.CreateSelect(b_.CreateFCmpOGT(a, splat_f(0.0f)), a, splat_f(0.0f));
        a = b_.CreateSelect(b_.CreateFCmpOLT(a, splat_f(1.0f)), a, splat_f(1.0f));
        a = b_.CreateFSub(b_.CreateFAdd(b_.CreateFMul(a, splat_f(255.0f)), splat_f(kRound)), splat_f(kRound));
        ref = unorm8_steps(ref);
    }
    llvm::Value* passes = compare(ops_.alpha_func, a, splat_f(ref));
    return b_.CreateZExt(b_.CreateBitCast(passes, b_.getIntNTy(4)), i32_);
}

// A quad's live lanes into RGBA8 storage: the lanes' pixels are distinct, two rows of two, so two
// masked stores of two pixels each write the same bytes. No branch on the
// lanes: a quad's live lanes vary, and branches on them mispredicted (perf).
// `lanes`: i32, bit i: lane i. `packed`: the quad's words, where the
// batch's were packed ahead (else null: packed here).
void PipelineEmitter::write_rgba8_quad(const Quad& q, const QuadValues& v, llvm::Value* lanes, llvm::Value* buffer,
                                       llvm::Value* packed) {
    auto* v4i = llvm::FixedVectorType::get(i32_, 4);
    llvm::Value* live = b_.CreateICmpNE(b_.CreateAnd(b_.CreateVectorSplat(4, lanes),
                                                     llvm::ConstantDataVector::get(b_.getContext(), llvm::ArrayRef<uint32_t>{1, 2, 4, 8})),
                                        llvm::Constant::getNullValue(v4i));
    llvm::Value* pixel = pixel_index(b_.CreateExtractElement(q.px, uint64_t(0)),
                                     b_.CreateExtractElement(q.py, uint64_t(0)), target_.width);
    llvm::Value* above = b_.CreateAdd(pixel, b_.CreateSExt(target_.width, i64_));
    // Four-lane stores whose last two lanes are off (they may lie past the buffer).
    llvm::Value* off = b_.getFalse();
    auto row = [&](int first) {
        llvm::Value* lo = b_.CreateExtractElement(live, uint64_t(first));
        llvm::Value* hi = b_.CreateExtractElement(live, uint64_t(first + 1));
        llvm::Value* mask = llvm::PoisonValue::get(llvm::FixedVectorType::get(b_.getInt1Ty(), 4));
        for (unsigned i = 0; i < 4; ++i) mask = b_.CreateInsertElement(mask, i == 0 ? lo : i == 1 ? hi : off, uint64_t(i));
        return mask;
    };
    llvm::Value* lower_slot = b_.CreateGEP(i32_, buffer, pixel);
    llvm::Value* upper_slot = b_.CreateGEP(i32_, buffer, above);
    if (reads_color(key_)) return read_modify_write_quad(q, v, live, lower_slot, upper_slot, row(0), row(2));
    llvm::Value* words = packed ? packed : pack_rgba8(v.rgba);
    llvm::Value* lower = b_.CreateShuffleVector(words, llvm::ArrayRef<int>{0, 1, 0, 1});
    llvm::Value* upper = b_.CreateShuffleVector(words, llvm::ArrayRef<int>{2, 3, 2, 3});
    b_.CreateMaskedStore(lower, lower_slot, llvm::Align(4), row(0));
    b_.CreateMaskedStore(upper, upper_slot, llvm::Align(4), row(2));
}

// Lanes of channel values (0 to 255) as RGBA8 words (a quad's, or a batch's).
llvm::Value* PipelineEmitter::pack_rgba8(const std::array<llvm::Value*, 4>& rgba) {
    llvm::Type* vi = rgba[0]->getType();
    llvm::Value* words = llvm::Constant::getNullValue(vi);
    for (unsigned k = 0; k < 4; ++k) {
        llvm::Value* byte = b_.CreateAnd(rgba[k], llvm::ConstantInt::get(vi, 255));
        words = b_.CreateOr(words, b_.CreateShl(byte, llvm::ConstantInt::get(vi, 8 * k)));
    }
    return words;
}

// write_rgba8_quad() with blending or a colour mask: the buffer's bytes of
// the quad are read, combined with the fragments' (emit_blend_and_mask) and
// written back in the live lanes. A quad inside the buffer reads and writes
// its two rows as plain 8-byte words: a masked load of four pixels after the
// previous quad's masked store over the same 16 bytes (two of them its
// pixels) waited for that store (perf: half of the blending function). At
// the buffer's right and top edges its lanes may lie outside, and the row's
// other pixel in another tile: masked loads and stores there.
void PipelineEmitter::read_modify_write_quad(const Quad& q, const QuadValues& v, llvm::Value* live,
                                             llvm::Value* lower_slot, llvm::Value* upper_slot,
                                             llvm::Value* lower_mask, llvm::Value* upper_mask) {
    auto* v2i = llvm::FixedVectorType::get(i32_, 2);
    auto* v4i = llvm::FixedVectorType::get(i32_, 4);
    auto combined = [&](llvm::Value* stored) {
        std::array<llvm::Value*, 4> dst;
        for (unsigned k = 0; k < 4; ++k)
            dst[k] = b_.CreateAnd(b_.CreateLShr(stored, llvm::ConstantInt::get(v4i, 8 * k)), llvm::ConstantInt::get(v4i, 255));
        return b_.CreateSelect(live, pack_rgba8(emit_blend_and_mask(b_, ops_, v.rgba, dst)), stored);
    };
    llvm::Value* x = b_.CreateExtractElement(q.px, uint64_t(0));
    llvm::Value* y = b_.CreateExtractElement(q.py, uint64_t(0));
    llvm::Value* inside = b_.CreateAnd(b_.CreateICmpSLT(b_.CreateAdd(x, b_.getInt32(1)), target_.width),
                                       b_.CreateICmpSLT(b_.CreateAdd(y, b_.getInt32(1)), target_.height));
    llvm::BasicBlock* whole = llvm::BasicBlock::Create(b_.getContext(), "whole_quad", fn_);
    llvm::BasicBlock* edge = llvm::BasicBlock::Create(b_.getContext(), "edge_quad", fn_);
    llvm::BasicBlock* done = llvm::BasicBlock::Create(b_.getContext(), "quad_written", fn_);
    b_.CreateCondBr(inside, whole, edge);
    b_.SetInsertPoint(whole);
    {
        llvm::Value* below = b_.CreateAlignedLoad(v2i, lower_slot, llvm::Align(4));
        llvm::Value* top = b_.CreateAlignedLoad(v2i, upper_slot, llvm::Align(4));
        llvm::Value* words = combined(b_.CreateShuffleVector(below, top, llvm::ArrayRef<int>{0, 1, 2, 3}));
        b_.CreateAlignedStore(b_.CreateShuffleVector(words, llvm::ArrayRef<int>{0, 1}), lower_slot, llvm::Align(4));
        b_.CreateAlignedStore(b_.CreateShuffleVector(words, llvm::ArrayRef<int>{2, 3}), upper_slot, llvm::Align(4));
        b_.CreateBr(done);
    }
    b_.SetInsertPoint(edge);
    {
        llvm::Value* zero = llvm::Constant::getNullValue(v4i);
        llvm::Value* below = b_.CreateMaskedLoad(v4i, lower_slot, llvm::Align(4), lower_mask, zero);
        llvm::Value* top = b_.CreateMaskedLoad(v4i, upper_slot, llvm::Align(4), upper_mask, zero);
        llvm::Value* words = combined(b_.CreateShuffleVector(below, top, llvm::ArrayRef<int>{0, 1, 4, 5}));
        b_.CreateMaskedStore(b_.CreateShuffleVector(words, llvm::ArrayRef<int>{0, 1, 0, 1}), lower_slot, llvm::Align(4),
                             lower_mask);
        b_.CreateMaskedStore(b_.CreateShuffleVector(words, llvm::ArrayRef<int>{2, 3, 2, 3}), upper_slot, llvm::Align(4),
                             upper_mask);
        b_.CreateBr(done);
    }
    b_.SetInsertPoint(done);
}

// A quad's depth (gl_FragDepth clamped to [0, 1], NaN -> 0, or the plane's)
// and colour as stored (RGBA8: raster::to_unorm8's steps, as 32-bit integers).
PipelineEmitter::QuadValues PipelineEmitter::quad_values(const Quad& q, const std::vector<llvm::Value*>& regs,
                                                         llvm::Value* index) {
    auto lanes = [&](uint32_t r) {
        return b_.CreateAlignedLoad(v4f_, b_.CreateInBoundsGEP(i32_, regs[r], b_.CreateShl(index, 2)), llvm::Align(16));
    };
    QuadValues v;
    if (key_.depth_output) {
        llvm::Value* d = lanes(key_.color_channels);
        llvm::Value* upper = b_.CreateSelect(b_.CreateFCmpOLT(splat_f(1.0f), d), splat_f(1.0f), d);
        v.z = b_.CreateSelect(b_.CreateFCmpOGT(d, splat_f(0.0f)), upper, splat_f(0.0f));
    } else {
        v.z = quad_depth(q);
    }
    v.rgba = color_values(regs, 0, key_.color_channels, index);
    v.alpha = key_.color_channels > 3 ? lanes(3) : splat_f(0.0f);
    return v;
}

// The colour of a quad as stored, from the `channels` registers of `regs`
// from `first` on (missing channels 0).
std::array<llvm::Value*, 4> PipelineEmitter::color_values(const std::vector<llvm::Value*>& regs, size_t first,
                                                          uint32_t channels, llvm::Value* index) {
    std::array<llvm::Value*, 4> rgba;
    for (uint32_t k = 0; k < 4; ++k) {
        llvm::Value* c = splat_f(0.0f);
        if (k < channels)
            c = b_.CreateAlignedLoad(v4f_, b_.CreateInBoundsGEP(i32_, regs[first + k], b_.CreateShl(index, 2)),
                                     llvm::Align(16));
        rgba[k] = ops_.float_color ? c : stored_byte(c);
    }
    return rgba;
}

// A channel's RGBA8 byte as a 32-bit integer: raster::to_unorm8's steps, or
// raster::gpu_unorm8's with ColorRounding::Gpu (of a quad's lanes, or a batch's).
llvm::Value* PipelineEmitter::stored_byte(llvm::Value* c) {
    llvm::Type* vi = llvm::VectorType::getInteger(llvm::cast<llvm::VectorType>(c->getType()));
    auto f = [&](float v) { return llvm::ConstantFP::get(c->getType(), v); };
    c = b_.CreateSelect(b_.CreateFCmpOGT(c, f(0.0f)), c, f(0.0f));
    c = b_.CreateSelect(b_.CreateFCmpOLT(c, f(1.0f)), c, f(1.0f));
    if (ops_.rounding == ColorRounding::Gpu) {
        llvm::Value* t = b_.CreateFPToSI(b_.CreateFMul(c, f(4096.0f)), vi);
        llvm::Value* sum = b_.CreateAdd(b_.CreateMul(t, llvm::ConstantInt::get(vi, 510)), llvm::ConstantInt::get(vi, 4095));
        return b_.CreateAShr(sum, llvm::ConstantInt::get(vi, 13));
    }
    constexpr float kRound = 8388608.0f;
    llvm::Value* rounded = b_.CreateFAdd(b_.CreateFMul(c, f(255.0f)), f(kRound));
    return b_.CreateFPToSI(b_.CreateFSub(rounded, f(kRound)), vi);
}

// The RGBA8 bytes of every lane of the batch for the colour buffer whose
// outputs are the `channels` registers of `regs` from `first` on, into
// slots of kLanes words: one conversion of whole registers (16 lanes a
// 512-bit vector) instead of one per quad. With `pack`, one slot of the
// lanes' RGBA8 words ([0]); else one slot per channel. Lanes past the
// batch's quads are converted too, never stored.
std::array<llvm::Value*, 4> PipelineEmitter::convert_batch(const std::vector<llvm::Value*>& regs, size_t first,
                                                           uint32_t channels, bool pack) {
    auto* batch_f = llvm::FixedVectorType::get(f32_, kLanes);
    std::array<llvm::Value*, 4> bytes;
    for (uint32_t k = 0; k < 4; ++k) {
        llvm::Value* c = llvm::ConstantFP::get(batch_f, 0.0);
        if (k < channels) c = b_.CreateAlignedLoad(batch_f, regs[first + k], llvm::Align(16));
        bytes[k] = stored_byte(c);
    }
    auto slot_of = [&](llvm::Value* words) -> llvm::Value* {
        llvm::AllocaInst* slot = b_.CreateAlloca(llvm::ArrayType::get(i32_, kLanes));
        slot->setAlignment(llvm::Align(64));
        b_.CreateAlignedStore(words, slot, llvm::Align(64));
        return slot;
    };
    if (pack) return {slot_of(pack_rgba8(bytes)), nullptr, nullptr, nullptr};
    std::array<llvm::Value*, 4> slots;
    for (size_t k = 0; k < 4; ++k) slots[k] = slot_of(bytes[k]);
    return slots;
}

// outputs(batch, regs, alive, target): FragmentStage::write_outputs, quad
// by quad in lane order: the alpha test, the late depth test and write, then
// the colour write. A quad's depth tests before its colour write: the
// buffers are apart, and its pixels distinct.
void PipelineEmitter::define_outputs() {
    begin("glslrun_outputs", i64_, {ptr_, ptr_, i64_, ptr_});
    std::vector<llvm::Value*> regs;
    uint32_t reg_count = key_.color_channels + (key_.depth_output ? 1 : 0);
    for (uint8_t c : key_.more_channels) reg_count += c;
    for (uint32_t i = 0; i < reg_count; ++i) regs.push_back(b_.CreateLoad(ptr_, at(fn_->getArg(1), uint64_t(i) * 8)));
    load_target(fn_->getArg(3));
    written_ = b_.CreateAlloca(i64_);
    b_.CreateStore(b_.getInt64(0), written_);
    const bool late_depth = ops_.depth_test && !key_.early_depth;
    const bool late_stencil = ops_.stencil_test && !key_.early_depth;
    const bool rgba8 = !ops_.float_color && writes_color(key_);
    // RGBA8 colours are converted for the whole batch before the quads'
    // writes; where every live lane's colour is stored as the shader made it
    // (no test after the shader, nothing read back), packed into words too.
    const bool packed = rgba8 && !late_depth && !ops_.alpha_test && !late_stencil && !reads_color(key_);
    std::array<std::array<llvm::Value*, 4>, kMaxDrawBuffers> converted{};
    for (size_t b = 0, first = key_.color_channels + (key_.depth_output ? 1 : 0); rgba8 && b < converted.size(); ++b) {
        const uint32_t channels = b == 0 ? key_.color_channels : key_.more_channels[b];
        if (channels == 0) continue;
        converted[b] = convert_batch(regs, b == 0 ? 0 : first, channels, packed);
        if (b > 0) first += channels;
    }
    auto quad_words = [&](llvm::Value* slot, llvm::Value* index) -> llvm::Value* {
        return b_.CreateAlignedLoad(llvm::FixedVectorType::get(i32_, 4),
                                    b_.CreateInBoundsGEP(i32_, slot, b_.CreateShl(index, 2)), llvm::Align(16));
    };
    for_each_quad(fn_->getArg(0), [&](llvm::Value* index, const Quad& q) {
        llvm::Value* shift = b_.CreateShl(index, 2);
        llvm::Value* lanes = b_.CreateTrunc(b_.CreateAnd(b_.CreateLShr(fn_->getArg(2), shift), b_.getInt64(0xF)), i32_);
        // RGBA8 quads without a late depth test: every quad, its dead lanes
        // masked, no branch; the others only where a lane lives.
        llvm::BasicBlock* next = nullptr;
        if (late_depth || !rgba8) {
            llvm::BasicBlock* body = llvm::BasicBlock::Create(b_.getContext(), "alive", fn_);
            next = llvm::BasicBlock::Create(b_.getContext(), "next_quad", fn_);
            b_.CreateCondBr(b_.CreateICmpNE(lanes, b_.getInt32(0)), body, next);
            b_.SetInsertPoint(body);
        }
        QuadValues v = quad_values(q, regs, index);
        if (ops_.alpha_test) lanes = b_.CreateAnd(lanes, alpha_passes(v));
        if (late_stencil) lanes = stencil_depth_lanes(q, v.z, lanes);
        else if (late_depth) lanes = depth_test_lanes(q, v.z, lanes);
        b_.CreateStore(b_.CreateOr(b_.CreateLoad(i64_, written_), b_.CreateShl(b_.CreateZExt(lanes, i64_), shift)),
                       written_);
        // Each colour buffer in turn (raster::write_color's order).
        size_t first = key_.color_channels + (key_.depth_output ? 1 : 0);
        for (size_t b = 0; b < key_.more_channels.size(); ++b) {
            const uint32_t channels = b == 0 ? key_.color_channels : key_.more_channels[b];
            if (channels == 0) continue;
            QuadValues colour = v;
            llvm::Value* words = nullptr;
            if (!rgba8 && b > 0) colour.rgba = color_values(regs, first, channels, index);
            else if (packed) words = quad_words(converted[b][0], index);
            else if (rgba8)
                for (size_t k = 0; k < 4; ++k) colour.rgba[k] = quad_words(converted[b][k], index);
            if (b > 0) first += channels;
            if (rgba8) write_rgba8_quad(q, colour, lanes, target_.color[b], words);
            else write_float_lanes(q, colour, lanes, target_.color[b]);
        }
        if (next) {
            b_.CreateBr(next);
            b_.SetInsertPoint(next);
        }
    });
    b_.CreateRet(b_.CreateLoad(i64_, written_));
}

}  // namespace glslrun::raster::fused
