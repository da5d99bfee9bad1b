// The fused fragment pipeline's code (raster/fused/pipeline.h): LLVM IR
// for the early depth test of a quad or of an 8x8 square, the shader inputs
// of a batch and the per-fragment writes, computing what raster/fragments.cpp's
// C++ path computes, operation for operation. A quad's four lanes are one
// 4-wide vector; the writes go in lane order, as two quads of a batch may
// cover the same pixel (a quad's own four pixels are distinct).
#include <algorithm>
#include <array>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/BLAKE3.h>

#include "raster/fused/gen/emitter.h"
#include "runtime/jit/cached_shader.h"
#include "runtime/jit/engine.h"

namespace glslrun::raster::fused {

llvm::Function* PipelineEmitter::begin(const char* name, llvm::Type* result, llvm::ArrayRef<llvm::Type*> params) {
    auto* type = llvm::FunctionType::get(result, params, false);
    fn_ = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, module_);
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    b_.SetInsertPoint(llvm::BasicBlock::Create(b_.getContext(), "entry", fn_));
    return fn_;
}

llvm::Value* PipelineEmitter::if_then(llvm::Value* condition, llvm::Value* otherwise,
                                      const std::function<llvm::Value*()>& then) {
    llvm::BasicBlock* taken = llvm::BasicBlock::Create(b_.getContext(), "then", fn_);
    llvm::BasicBlock* next = llvm::BasicBlock::Create(b_.getContext(), "next", fn_);
    llvm::BasicBlock* from = b_.GetInsertBlock();
    b_.CreateCondBr(condition, taken, next);
    b_.SetInsertPoint(taken);
    llvm::Value* value = then();
    llvm::BasicBlock* end = b_.GetInsertBlock();
    b_.CreateBr(next);
    b_.SetInsertPoint(next);
    llvm::PHINode* merged = b_.CreatePHI(otherwise->getType(), 2);
    merged->addIncoming(otherwise, from);
    merged->addIncoming(value, end);
    return merged;
}

PipelineEmitter::Quad PipelineEmitter::quad(llvm::Value* prim, llvm::ArrayRef<llvm::Value*> x,
                                            llvm::ArrayRef<llvm::Value*> y) {
    auto per_quad = [&](llvm::ArrayRef<llvm::Value*> v) {
        llvm::Value* lanes = llvm::PoisonValue::get(llvm::FixedVectorType::get(i32_, width_));
        for (unsigned i = 0; i < width_; ++i) lanes = b_.CreateInsertElement(lanes, v[i / 4], uint64_t(i));
        return lanes;
    };
    Quad q{prim, nullptr, nullptr, nullptr, nullptr};
    q.px = b_.CreateAdd(per_quad(x), lanes_i(kDx));
    q.py = b_.CreateAdd(per_quad(y), lanes_i(kDy));
    q.fx = b_.CreateSIToFP(b_.CreateSub(q.px, splat(load_i(prim, kOx))), vf());
    q.fy = b_.CreateSIToFP(b_.CreateSub(q.py, splat(load_i(prim, kOy))), vf());
    return q;
}

// c + a * x + b * y, as FragmentStage evaluates a Plane (plane_at). Strict:
// x and y are never NaN, so a * x and b * y have one NaN operand at most,
// and c's NaN is a scalar test.
llvm::Value* PipelineEmitter::plane(const Quad& q, uint64_t offset) {
    llvm::Value* a = load_f(q.prim, offset);
    llvm::Value* b = load_f(q.prim, offset + 4);
    llvm::Value* c = load_f(q.prim, offset + 8);
    llvm::Value* ax = b_.CreateFMul(splat(a), q.fx);
    if (!strict_) return b_.CreateFAdd(b_.CreateFAdd(splat(c), ax), b_.CreateFMul(splat(b), q.fy));
    llvm::Value* cax = b_.CreateSelect(is_nan(c), splat(b_.CreateFAdd(c, c)), b_.CreateFAdd(splat(c), ax));
    return a_nan_first(cax, b_.CreateFAdd(cax, b_.CreateFMul(splat(b), q.fy)));
}

// Whether the quad's primitive has a NaN among the values the inputs are
// interpolated from (or infinities that sum to one: then the strict code
// runs where the plain code would do).
llvm::Value* PipelineEmitter::nan_inputs(const Quad& q) {
    std::vector<llvm::Value*> terms;
    for (uint32_t k = 0; k < 9; ++k) terms.push_back(load_f(q.prim, kWeights + 4 * k));
    for (int i = 0; i < 3; ++i) terms.push_back(b_.CreateLoad(f32_, vertex(q, i, kVertexInvW)));
    for (const Input& in : key_.inputs)
        if (in.source == InputSource::Varying)
            for (llvm::Value* a : attributes(q, in.index)) terms.push_back(a);
    while (terms.size() > 1) {  // a tree of sums: NaN when any term is
        std::vector<llvm::Value*> sums;
        for (size_t i = 0; i + 1 < terms.size(); i += 2) sums.push_back(b_.CreateFAdd(terms[i], terms[i + 1]));
        if (terms.size() % 2) sums.push_back(terms.back());
        terms = std::move(sums);
    }
    return is_nan(terms[0]);
}

std::array<llvm::Value*, 3> PipelineEmitter::attributes(const Quad& q, uint32_t index) {
    std::array<llvm::Value*, 3> a;
    for (int i = 0; i < 3; ++i)
        a[size_t(i)] = load_f(b_.CreateLoad(ptr_, vertex(q, i, kVertexAttrs)), uint64_t(index) * 4);
    return a;
}

// raster::clamp01: maxss then minss, NaN and -0 kept.
llvm::Value* PipelineEmitter::clamp01(llvm::Value* v) {
    llvm::Value* zero = llvm::ConstantFP::get(v->getType(), 0.0);
    llvm::Value* one = llvm::ConstantFP::get(v->getType(), 1.0);
    llvm::Value* low = b_.CreateSelect(b_.CreateFCmpOGT(zero, v), zero, v);
    return b_.CreateSelect(b_.CreateFCmpOLT(one, low), one, low);
}

// FragmentStage::compute_weights.
PipelineEmitter::Weights PipelineEmitter::weights(const Quad& q) {
    llvm::Value* l[3];
    for (int k = 0; k < 3; ++k) l[k] = plane(q, kWeights + 12u * uint32_t(k));
    auto inv_w_of = [&](int i) { return splat(b_.CreateLoad(f32_, vertex(q, i, kVertexInvW))); };
    llvm::Value* w1 = mul(l[1], inv_w_of(1));
    llvm::Value* w2 = mul(l[2], inv_w_of(2));
    llvm::Value* inv_w = add(add(mul(l[0], inv_w_of(0)), w1), w2);
    llvm::Value* nonzero = b_.CreateFCmpUNE(inv_w, splat_f(0.0f));
    llvm::Value* r = b_.CreateSelect(nonzero, b_.CreateFDiv(splat_f(1.0f), inv_w), splat_f(0.0f));
    return {b_.CreateSelect(nonzero, mul(w1, r), l[1]), b_.CreateSelect(nonzero, mul(w2, r), l[2]), inv_w};
}

// One input register's four lanes (FragmentStage::interpolate and builtin_input).
llvm::Value* PipelineEmitter::input(const Input& in, const Quad& q, const Weights& w) {
    if (in.sprite_coord) {
        // FragmentStage::replace_sprite_coord: on points, (gl_PointCoord, 0, 1).
        Input plain = in;
        plain.sprite_coord = false;
        llvm::Value* value = input(plain, q, w);
        llvm::Value* is_point = b_.CreateICmpEQ(load_i(q.prim, kCount), b_.getInt32(1));
        llvm::Value* sprite = in.component < 2 ? input({InputSource::PointCoord, in.component, ir::Kind::F32}, q, w)
                                               : splat_f(in.component == 3 ? 1.0f : 0.0f);
        return b_.CreateSelect(is_point, sprite, value);
    }
    switch (in.source) {
    case InputSource::Varying: {
        std::array<llvm::Value*, 3> a = attributes(q, in.index);
        llvm::Value* d1 = splat(b_.CreateFSub(a[1], a[0]));
        llvm::Value* d2 = splat(b_.CreateFSub(a[2], a[0]));
        return add(add(splat(a[0]), mul(w.p1, d1)), mul(w.p2, d2));
    }
    case InputSource::FragCoord:
        switch (in.index) {
        case 0: return b_.CreateFAdd(b_.CreateSIToFP(q.px, vf()), splat_f(0.5f));
        case 1: return b_.CreateFAdd(b_.CreateSIToFP(q.py, vf()), splat_f(0.5f));
        case 2: return quad_depth(q);
        default: return w.inv_w;
        }
    case InputSource::FrontFacing: {
        llvm::Value* front = b_.CreateICmpNE(b_.CreateLoad(i8_, at(q.prim, kFront)), b_.getInt8(0));
        llvm::Value* word = in.kind == ir::Kind::Bool ? b_.CreateZExt(front, i32_)
                                       : b_.CreateSelect(front, llvm::ConstantFP::get(f32_, 1.0),
                                                         llvm::ConstantFP::get(f32_, 0.0));
        return splat(word);
    }
    case InputSource::PointCoord: {
        llvm::Value* is_point = b_.CreateICmpEQ(load_i(q.prim, kCount), b_.getInt32(1));
        // fma(step, pixel, origin), one rounding (raster/fragments.h).
        const uint32_t component = in.index == 0 ? 0 : 4;
        llvm::Value* step = splat(load_f(q.prim, kPointCoordStep + component));
        llvm::Value* origin = splat(load_f(q.prim, kPointCoordOrigin + component));
        llvm::Value* pixel = b_.CreateSIToFP(in.index == 0 ? q.px : q.py, vf());
        llvm::Value* value = b_.CreateIntrinsic(llvm::Intrinsic::fma, {vf()}, {step, pixel, origin});
        return b_.CreateSelect(is_point, value, splat_f(0.0f));
    }
    case InputSource::Zero: break;
    }
    return splat_f(0.0f);
}

// raster::depth_passes with `func`, on scalars or vectors.
llvm::Value* PipelineEmitter::compare(CompareFunc func, llvm::Value* incoming, llvm::Value* stored) {
    llvm::Type* result = llvm::CmpInst::makeCmpResultType(incoming->getType());
    switch (func) {
    case CompareFunc::Never: return llvm::Constant::getNullValue(result);
    case CompareFunc::Less: return b_.CreateFCmpOLT(incoming, stored);
    case CompareFunc::Equal: return b_.CreateFCmpOEQ(incoming, stored);
    case CompareFunc::Lequal: return b_.CreateFCmpOLE(incoming, stored);
    case CompareFunc::Greater: return b_.CreateFCmpOGT(incoming, stored);
    case CompareFunc::Notequal: return b_.CreateFCmpUNE(incoming, stored);
    case CompareFunc::Gequal: return b_.CreateFCmpOGE(incoming, stored);
    case CompareFunc::Always: break;
    }
    return llvm::Constant::getAllOnesValue(result);
}

llvm::Value* PipelineEmitter::pixel_index(llvm::Value* x, llvm::Value* y, llvm::Value* width) {
    return b_.CreateAdd(b_.CreateMul(b_.CreateSExt(y, i64_), b_.CreateSExt(width, i64_)), b_.CreateSExt(x, i64_));
}

// quad_depth(prim, x, y, mask, target): FragmentStage::early_tests_quad,
// the stencil and depth tests where the stencil test is on.
void PipelineEmitter::define_quad_depth() {
    begin("glslrun_quad_depth", i32_, {ptr_, i32_, i32_, i32_, ptr_});
    llvm::Value* target = fn_->getArg(4);
    Quad q = quad(fn_->getArg(0), fn_->getArg(1), fn_->getArg(2));
    llvm::Value* z = quad_depth(q);
    load_target(target);
    b_.CreateRet(ops_.stencil_test ? stencil_depth_lanes(q, z, fn_->getArg(3)) : depth_test_lanes(q, z, fn_->getArg(3)));
}

// The depth test (and write) of the lanes of a quad in `mask` (i32, bit i:
// lane i), in lane order, depths `z`; returns those that pass.
llvm::Value* PipelineEmitter::depth_test_lanes(const Quad& q, llvm::Value* z, llvm::Value* mask) {
    for (int i = 0; i < 4; ++i) {
        llvm::Value* lane = b_.CreateICmpNE(b_.CreateAnd(mask, b_.getInt32(1u << i)), b_.getInt32(0));
        mask = if_then(lane, mask, [&] {
            llvm::Value* px = b_.CreateExtractElement(q.px, uint64_t(i));
            llvm::Value* py = b_.CreateExtractElement(q.py, uint64_t(i));
            llvm::Value* slot = b_.CreateInBoundsGEP(f32_, target_.depth, pixel_index(px, py, target_.width));
            llvm::Value* stored = b_.CreateLoad(f32_, slot);
            llvm::Value* zi = b_.CreateExtractElement(z, uint64_t(i));
            llvm::Value* passes = depth_passes(zi, stored);
            if (ops_.depth_write) b_.CreateStore(b_.CreateSelect(passes, zi, stored), slot);
            llvm::Value* failed = b_.CreateShl(b_.CreateZExt(b_.CreateNot(passes), i32_), uint64_t(i));
            return b_.CreateAnd(mask, b_.CreateNot(failed));
        });
    }
    return mask;
}

// square_depth(prim, ox, oy, pixels, target): define_quad_depth's tests on
// the pixels of an 8x8 square, a row of eight at a time. The pixels are
// distinct, so their order does not matter; the masked loads and stores
// touch only the pixels in `pixels`. With the stencil test, the primitive's
// face picks the stencil state (one face for the whole square).
void PipelineEmitter::define_square_depth() {
    begin("glslrun_square_depth", i64_, {ptr_, i32_, i32_, i64_, ptr_});
    llvm::Value* prim = fn_->getArg(0);
    llvm::Value *ox = fn_->getArg(1), *oy = fn_->getArg(2), *pixels = fn_->getArg(3);
    load_target(fn_->getArg(4));
    if (!ops_.stencil_test) return void(b_.CreateRet(square_rows(nullptr, prim, ox, oy, pixels)));
    if (ops_.stencil[0] == ops_.stencil[1]) return void(b_.CreateRet(square_rows(&ops_.stencil[0], prim, ox, oy, pixels)));
    llvm::Value* front = b_.CreateICmpNE(b_.CreateLoad(i8_, at(prim, kFront)), b_.getInt8(0));
    llvm::BasicBlock* front_block = llvm::BasicBlock::Create(b_.getContext(), "front_face", fn_);
    llvm::BasicBlock* back_block = llvm::BasicBlock::Create(b_.getContext(), "back_face", fn_);
    b_.CreateCondBr(front, front_block, back_block);
    b_.SetInsertPoint(front_block);
    b_.CreateRet(square_rows(&ops_.stencil[0], prim, ox, oy, pixels));
    b_.SetInsertPoint(back_block);
    b_.CreateRet(square_rows(&ops_.stencil[1], prim, ox, oy, pixels));
}

// The pixels of the square that pass the depth test, or with `face` the
// stencil and depth tests, with their buffer updates.
llvm::Value* PipelineEmitter::square_rows(const StencilFace* face, llvm::Value* prim, llvm::Value* ox, llvm::Value* oy,
                                          llvm::Value* pixels) {
    auto* v8f = llvm::FixedVectorType::get(f32_, 8);
    auto* v8i = llvm::FixedVectorType::get(i32_, 8);
    auto* v8b = llvm::FixedVectorType::get(i8_, 8);
    llvm::Value* columns = llvm::ConstantDataVector::get(b_.getContext(), llvm::ArrayRef<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7});
    llvm::Value* bits = llvm::ConstantDataVector::get(b_.getContext(),
                                                      llvm::ArrayRef<uint32_t>{1, 2, 4, 8, 16, 32, 64, 128});
    // The plane's terms as Quad and plane() take them, eight lanes wide.
    llvm::Value* fx = b_.CreateSIToFP(
        b_.CreateAdd(b_.CreateVectorSplat(8, b_.CreateSub(ox, load_i(prim, kOx))), columns), v8f);
    llvm::Value* prim_oy = load_i(prim, kOy);
    llvm::Value* a = b_.CreateVectorSplat(8, load_f(prim, kDepth));
    llvm::Value* b = b_.CreateVectorSplat(8, load_f(prim, kDepth + 4));
    llvm::Value* c = load_f(prim, kDepth + 8);
    llvm::Value* cax = b_.CreateSelect(is_nan(c), b_.CreateVectorSplat(8, b_.CreateFAdd(c, c)),
                                       b_.CreateFAdd(b_.CreateVectorSplat(8, c), b_.CreateFMul(a, fx)));
    // Every row, empty ones too: a branch per row on its pixels mispredicted
    // (perf), and a masked load or store of no lane touches no memory.
    llvm::Value* passing = b_.getInt64(0);
    for (int row = 0; row < 8; ++row) {
        llvm::Value* row_bits = b_.CreateTrunc(b_.CreateLShr(pixels, uint64_t(8 * row)), i8_);
        llvm::Value* y = b_.CreateAdd(oy, b_.getInt32(uint32_t(row)));
        llvm::Value* fy = b_.CreateVectorSplat(8, b_.CreateSIToFP(b_.CreateSub(y, prim_oy), f32_));
        llvm::Value* z = clamp01(b_.CreateSelect(is_nan(cax), cax, b_.CreateFAdd(cax, b_.CreateFMul(b, fy))));
        llvm::Value* in = b_.CreateICmpNE(b_.CreateAnd(b_.CreateVectorSplat(8, b_.CreateZExt(row_bits, i32_)), bits),
                                          llvm::Constant::getNullValue(v8i));
        // Not inbounds: the lanes outside `pixels` may lie outside the buffer.
        llvm::Value* pixel = pixel_index(ox, y, target_.width);
        llvm::Value* slot = b_.CreateGEP(f32_, target_.depth, pixel);
        llvm::Value* passes = llvm::Constant::getAllOnesValue(in->getType());
        if (ops_.depth_test) {
            llvm::Value* stored = b_.CreateMaskedLoad(v8f, slot, llvm::Align(4), in, llvm::ConstantFP::get(v8f, 0.0));
            passes = depth_passes(z, stored);
            if (!passes->getType()->isVectorTy()) passes = b_.CreateVectorSplat(8, passes);
        }
        if (face) {
            llvm::Value* stencil_slot = b_.CreateGEP(i8_, target_.stencil, pixel);
            llvm::Value* stored = b_.CreateZExt(
                b_.CreateMaskedLoad(v8b, stencil_slot, llvm::Align(1), in, llvm::Constant::getNullValue(v8b)), v8i);
            const StencilOutcome o = stencil_outcome(*face, stored, passes);
            b_.CreateMaskedStore(b_.CreateTrunc(o.value, v8b), stencil_slot, llvm::Align(1), in);
            passes = o.passes;
        }
        passes = b_.CreateAnd(passes, in);
        if (ops_.depth_test && ops_.depth_write) b_.CreateMaskedStore(z, slot, llvm::Align(4), passes);
        llvm::Value* passed = b_.CreateZExt(b_.CreateBitCast(passes, i8_), i64_);
        passing = b_.CreateOr(passing, b_.CreateShl(passed, uint64_t(8 * row)));
    }
    return passing;
}

// Emits body(index, quads) for the batch's quads in order, a loop: quads
// `index` to `index + 3` together (width_ 16, the first one's primitive)
// where the code is AVX-512's and pairable(index, k) holds for the three
// others, else `index` and `index + 1` (width_ 8) where pairable(index,
// index + 1) holds, else quad `index` alone (width_ 4). first(prim), where
// given, is emitted at the start of each step, for quad `index`'s primitive.
void PipelineEmitter::for_each_quad(llvm::Value* batch, const QuadBody& body, const PairTest& pairable,
                                    const std::function<void(llvm::Value* prim)>& first) {
    llvm::Value* quads = load_i(batch, offsetof(QuadBatch, quads));
    llvm::BasicBlock* entry = b_.GetInsertBlock();
    llvm::BasicBlock* loop = llvm::BasicBlock::Create(b_.getContext(), "quad", fn_);
    llvm::BasicBlock* done = llvm::BasicBlock::Create(b_.getContext(), "done", fn_);
    b_.CreateCondBr(b_.CreateICmpSGT(quads, b_.getInt32(0)), loop, done);
    b_.SetInsertPoint(loop);
    llvm::PHINode* index = b_.CreatePHI(i32_, 2);
    index->addIncoming(b_.getInt32(0), entry);
    auto plus = [&](int k) { return b_.CreateAdd(index, b_.getInt32(k)); };
    llvm::Value* next = plus(1);
    auto x = [&](llvm::Value* i) { return batch_field(batch, offsetof(QuadBatch, x), i32_, i); };
    auto y = [&](llvm::Value* i) { return batch_field(batch, offsetof(QuadBatch, y), i32_, i); };
    llvm::Value* prim = batch_field(batch, offsetof(QuadBatch, prim), ptr_, index);
    if (first) first(prim);
    llvm::BasicBlock* step_start = b_.GetInsertBlock();  // `loop`, or where first() left off
    llvm::Value* step = b_.getInt32(1);
    if (pairable) {
        llvm::BasicBlock* after = llvm::BasicBlock::Create(b_.getContext(), "after_quads", fn_);
        llvm::PHINode* taken = llvm::PHINode::Create(i32_, 3, "taken", after);
        // Quads index .. index + n - 1 at width_ 4n, then to `after`.
        auto run = [&](int n, const char* name) {
            llvm::BasicBlock* block = llvm::BasicBlock::Create(b_.getContext(), name, fn_);
            b_.SetInsertPoint(block);
            std::vector<llvm::Value*> xs, ys;
            for (int k = 0; k < n; ++k) {
                xs.push_back(x(k ? plus(k) : index));
                ys.push_back(y(k ? plus(k) : index));
            }
            width_ = unsigned(4 * n);
            body(b_.CreateZExt(index, i64_), quad(prim, xs, ys));
            width_ = 4;
            taken->addIncoming(b_.getInt32(n), b_.GetInsertBlock());
            b_.CreateBr(after);
            return block;
        };
        llvm::BasicBlock* single = run(1, "single");
        llvm::BasicBlock* pair = run(2, "pair");
        llvm::BasicBlock* pair_or_four = pair;
        if (key_.avx2 && rt::jit::avx512()) {
            // Four quads of one primitive: a 512-bit register per value.
            llvm::BasicBlock* four = run(4, "four");
            pair_or_four = llvm::BasicBlock::Create(b_.getContext(), "test_four", fn_);
            b_.SetInsertPoint(pair_or_four);
            llvm::BasicBlock* test_rest = llvm::BasicBlock::Create(b_.getContext(), "test_rest", fn_);
            b_.CreateCondBr(b_.CreateICmpSLT(plus(3), quads), test_rest, pair);
            b_.SetInsertPoint(test_rest);
            b_.CreateCondBr(b_.CreateAnd(pairable(index, plus(2)), pairable(index, plus(3))), four, pair);
        }
        llvm::BasicBlock* test_pair = llvm::BasicBlock::Create(b_.getContext(), "test_pair", fn_);
        b_.SetInsertPoint(step_start);
        b_.CreateCondBr(b_.CreateICmpSLT(next, quads), test_pair, single);
        b_.SetInsertPoint(test_pair);
        b_.CreateCondBr(pairable(index, next), pair_or_four, single);
        b_.SetInsertPoint(after);
        step = taken;
    } else {
        body(b_.CreateZExt(index, i64_), quad(prim, {x(index)}, {y(index)}));
    }
    llvm::Value* following = b_.CreateAdd(index, step);
    index->addIncoming(following, b_.GetInsertBlock());
    b_.CreateCondBr(b_.CreateICmpSLT(following, quads), loop, done);
    b_.SetInsertPoint(done);
}

// inputs(batch, regs): FragmentStage::fill_inputs. Two or four quads of
// one primitive (the common case: a batch's quads come several from one
// triangle) are interpolated together, 8 or 16 lanes a vector: the same
// operations per lane, a half or a quarter of the instructions.
void PipelineEmitter::define_inputs() {
    begin("glslrun_inputs", b_.getVoidTy(), {ptr_, ptr_});
    llvm::Value* batch = fn_->getArg(0);
    std::vector<llvm::Value*> regs;
    for (size_t i = 0; i < key_.inputs.size(); ++i) regs.push_back(b_.CreateLoad(ptr_, at(fn_->getArg(1), i * 8)));
    // The last quad's primitive and whether it has NaN inputs: the test
    // loads all its interpolated values. Slots in the entry block, which
    // SROA turns into registers.
    InputsState state{regs, b_.CreateAlloca(ptr_), b_.CreateAlloca(b_.getInt1Ty()), nullptr};
    b_.CreateStore(llvm::ConstantPointerNull::get(llvm::PointerType::getUnqual(b_.getContext())), state.last_prim);
    b_.CreateStore(b_.getFalse(), state.last_nan);
    // Quads run together only where their primitive has no NaN inputs:
    // the strict version is emitted for single quads only (a copy per width
    // cost LLVM a fifth more time on a program of several pipelines). The
    // test is emitted once, at the start of each step (once per use, its
    // four copies were a fifth of the function's LLVM time).
    auto test_nan = [&](llvm::Value* prim) { state.nan = primitive_nan(state, prim); };
    auto same_primitive = [&](llvm::Value* index, llvm::Value* next) {
        llvm::Value* prim = batch_field(batch, offsetof(QuadBatch, prim), ptr_, index);
        llvm::Value* same = b_.CreateICmpEQ(prim, batch_field(batch, offsetof(QuadBatch, prim), ptr_, next));
        return b_.CreateAnd(same, b_.CreateNot(state.nan));
    };
    for_each_quad(batch, [&](llvm::Value* index, const Quad& q) { store_inputs(state, index, q); }, same_primitive,
                  test_nan);
    b_.CreateRetVoid();
}

// Whether `prim` has NaN inputs (nan_inputs()), tested only where it is
// not the last primitive tested.
llvm::Value* PipelineEmitter::primitive_nan(const InputsState& state, llvm::Value* prim) {
    llvm::BasicBlock* test = llvm::BasicBlock::Create(b_.getContext(), "nan_test", fn_);
    llvm::BasicBlock* tested = llvm::BasicBlock::Create(b_.getContext(), "nan_tested", fn_);
    b_.CreateCondBr(b_.CreateICmpEQ(prim, b_.CreateLoad(ptr_, state.last_prim)), tested, test);
    b_.SetInsertPoint(test);
    b_.CreateStore(nan_inputs(Quad{prim, nullptr, nullptr, nullptr, nullptr}), state.last_nan);
    b_.CreateStore(prim, state.last_prim);
    b_.CreateBr(tested);
    b_.SetInsertPoint(tested);
    return b_.CreateLoad(b_.getInt1Ty(), state.last_nan);
}

// The inputs of quad `index` (and the next one or three, width_ 8 or 16,
// whose primitive has no NaN inputs: plain): by the primitive's NaN test
// (state.nan), the plain or the strict version.
void PipelineEmitter::store_inputs(const InputsState& state, llvm::Value* index, const Quad& q) {
    llvm::BasicBlock* stored = llvm::BasicBlock::Create(b_.getContext(), "stored", fn_);
    llvm::BasicBlock* plain = llvm::BasicBlock::Create(b_.getContext(), "plain", fn_);
    std::vector<llvm::BasicBlock*> versions{plain};
    if (width_ == 4) {
        // Two versions: the one that orders NaNs (add, mul) runs only for
        // primitives with NaNs in their inputs.
        llvm::BasicBlock* strict = llvm::BasicBlock::Create(b_.getContext(), "strict", fn_);
        b_.CreateCondBr(state.nan, strict, plain);
        versions.push_back(strict);
    } else {
        b_.CreateBr(plain);
    }
    for (llvm::BasicBlock* block : versions) {
        b_.SetInsertPoint(block);
        strict_ = block != plain;
        // All values before the first store: the stores could alias the
        // primitive for all LLVM knows, which would reload its fields.
        Weights w = weights(q);
        std::vector<llvm::Value*> values;
        for (const Input& in : key_.inputs) values.push_back(input(in, q, w));
        for (size_t i = 0; i < values.size(); ++i)
            b_.CreateAlignedStore(values[i], b_.CreateInBoundsGEP(i32_, state.regs[i], b_.CreateShl(index, 2)),
                                  llvm::Align(16));
        b_.CreateBr(stored);
    }
    strict_ = false;
    b_.SetInsertPoint(stored);
}

namespace {

using rt::jit::Engine;
using rt::jit::EngineCode;

// A pipeline's code in the process's LLJIT (engine.h), removed with it:
// the depth tests and the outputs of its state; its inputs function, shared
// with the program's other states (InputsCode).
class CompiledPipeline final : public Pipeline {
public:
    EngineCode code;
};

class CompiledInputs final : public InputsCode {
public:
    EngineCode code;
};

// The code cache's key of `part` of `state`'s pipeline: the engine's salt
// (glslrun's build, LLVM, the target) and the state's bytes (state_key),
// tagged apart from the shaders' keys (runtime/jit/cached_shader.cpp).
std::optional<rt::CodeKey> part_key(const Engine& engine, const char* part, const State& state) {
    if (engine.cache_salt.empty()) return std::nullopt;
    const std::string bytes = engine.cache_salt + "\nfused " + part + "\n" + state_key(state);
    return llvm::BLAKE3::hash(llvm::arrayRefFromStringRef(bytes));
}

// Finds a part's functions in its linked code; false where one is missing.
bool find_functions(CompiledPipeline& code, bool early_depth) {
    if (early_depth) {
        code.quad_depth = reinterpret_cast<Pipeline::QuadDepthFn>(code.code.lookup("glslrun_quad_depth"));
        code.square_depth = reinterpret_cast<Pipeline::SquareDepthFn>(code.code.lookup("glslrun_square_depth"));
    }
    code.outputs = reinterpret_cast<Pipeline::OutputsFn>(code.code.lookup("glslrun_outputs"));
    return code.outputs && (!early_depth || (code.quad_depth && code.square_depth));
}

bool find_functions(CompiledInputs& code, bool) {
    code.inputs = reinterpret_cast<InputsCode::InputsFn>(code.code.lookup("glslrun_inputs"));
    return code.inputs;
}

// One part of `state`'s functions (those `define` emits): from the code
// cache (`disk`, may be null) where it has them and they link, else made by
// LLVM and stored there; `loaded` is cleared where LLVM made them. Null
// where LLVM failed, or with `load_only` where the cache has no such part.
template <class Code>
std::unique_ptr<Code> make_part(Engine& engine, const rt::DiskCache* disk, const char* part, const State& state,
                                const std::function<void(PipelineEmitter&)>& define, bool& loaded,
                                bool load_only) {
    std::optional<rt::CodeKey> key;
    if (disk) key = part_key(engine, part, state);
    std::optional<std::string> payload;
    if (key) payload = disk->load(*key);
    std::optional<rt::jit::CachedShader> cached;
    if (payload) cached = rt::jit::parse_cached_shader(*payload, Precision::Precise, 0, state.avx2);
    if (cached && cached->call_outs.empty()) {
        auto code = std::make_unique<Code>();  // before the lock: its destructor takes it
        std::lock_guard hold(engine.lock);
        if (code->code.add_object(engine, std::move(cached->object)) && find_functions(*code, state.early_depth))
            return code;
    }
    if (load_only) return nullptr;
    loaded = false;
    auto code = std::make_unique<Code>();
    std::lock_guard hold(engine.lock);
    Engine::NewModule made = engine.new_module(part);
    {
        PipelineEmitter emitter(*made.context, *made.module, state);
        define(emitter);
    }
    if (llvm::verifyModule(*made.module, &llvm::errs())) return nullptr;
    rt::jit::optimise(*made.module, *engine.machine);
    const std::vector<rt::jit::CallOut> none;
    std::optional<rt::jit::ShaderCacheWriter> writer;
    if (key) writer.emplace(*disk, *key, none);
    std::unique_ptr<llvm::MemoryBuffer> object =
        rt::jit::compile_object(engine, *made.module, writer ? &*writer : nullptr);
    if (!object || !code->code.add_object(engine, std::move(object)) || !find_functions(*code, state.early_depth))
        return nullptr;
    return code;
}

}  // namespace

// As a shader's (runtime/jit/module.cpp): the code cache is read before any
// LLVM work and written by the compile; an entry is a cached shader without
// call-outs (rt::jit::CachedShader), one per part: the inputs function (keyed
// by inputs_only(state)), and the depth tests and outputs (by the state).
std::unique_ptr<Pipeline> compile(const State& key, PipelineCompile* compile) {
    const double start = rt::jit::thread_cpu_seconds();
    if (!fusable(key)) return nullptr;
    Engine* engine = Engine::of(key.avx2, false);
    if (!engine) return nullptr;
    std::optional<rt::DiskCache> disk;
    if (compile && compile->cache && !compile->cache->dir.empty() && !engine->cache_salt.empty())
        disk.emplace(*compile->cache);
    const rt::DiskCache* cache = disk ? &*disk : nullptr;
    const bool load_only = compile && compile->load_only;
    if (load_only && !cache) return nullptr;
    bool loaded = true;
    std::shared_ptr<const InputsCode> inputs = compile ? compile->inputs : nullptr;
    if (!inputs)
        inputs = make_part<CompiledInputs>(*engine, cache, "inputs", inputs_only(key),
                                           [](PipelineEmitter& e) { e.define_inputs(); }, loaded, load_only);
    if (!inputs) return nullptr;
    std::unique_ptr<CompiledPipeline> code =
        make_part<CompiledPipeline>(*engine, cache, "pipeline", key, [&](PipelineEmitter& e) {
            if (key.early_depth) {
                e.define_quad_depth();
                e.define_square_depth();
            }
            e.define_outputs();
        }, loaded, load_only);
    if (!code) return nullptr;
    code->inputs = inputs->inputs;
    code->shared_inputs = inputs;
    if (compile) {
        compile->inputs = std::move(inputs);
        compile->seconds = rt::jit::thread_cpu_seconds() - start;
        compile->loaded = loaded;
    }
    return code;
}

}  // namespace glslrun::raster::fused
