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
#include <string>
#include <utility>
#include <vector>

#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Verifier.h>

#include "raster/fragments.h"
#include "raster/framebuffer.h"
#include "raster/fused/gen/blend.h"
#include "runtime/jit/engine.h"

namespace glslrun::raster::fused {

namespace {

using rt::jit::Engine;
using rt::jit::EngineCode;

// Where FsPrimitive's fields are (raster/fragments.h), read as raw bytes.
static_assert(std::is_standard_layout_v<FsPrimitive> && std::is_standard_layout_v<FsVertex> &&
              sizeof(Plane) == 3 * sizeof(float) && sizeof(FsPrimitive::front) == 1 &&
              sizeof(FsPrimitive::ox) == 4 && sizeof(FsPrimitive::count) == 4 &&
              sizeof(FsVertex::attrs) == sizeof(void*) && sizeof(FsPrimitive::weight) == 9 * sizeof(float));
constexpr uint64_t kVertices = offsetof(FsPrimitive, v), kVertexSize = sizeof(FsVertex);
constexpr uint64_t kVertexInvW = offsetof(FsVertex, inv_w), kVertexAttrs = offsetof(FsVertex, attrs);
constexpr uint64_t kWeights = offsetof(FsPrimitive, weight), kDepth = offsetof(FsPrimitive, z);
constexpr uint64_t kOx = offsetof(FsPrimitive, ox), kOy = offsetof(FsPrimitive, oy);
constexpr uint64_t kFront = offsetof(FsPrimitive, front), kCount = offsetof(FsPrimitive, count);
constexpr uint64_t kPointCoordOrigin = offsetof(FsPrimitive, point_coord_origin);
constexpr uint64_t kPointCoordStep = offsetof(FsPrimitive, point_coord_step);

// Quad lane i is pixel (x + kDx[i], y + kDy[i]) (runtime/backend.h).
constexpr int kDx[4] = {0, 1, 0, 1};
constexpr int kDy[4] = {0, 0, 1, 1};

class PipelineEmitter {
public:
    // The functions are named glslrun_quad_depth, glslrun_inputs and
    // glslrun_outputs, followed by `suffix`.
    PipelineEmitter(llvm::LLVMContext& context, llvm::Module& module, const State& state, std::string suffix)
        : module_(module), b_(context), key_(state), ops_(state.ops), suffix_(std::move(suffix)) {
        i8_ = b_.getInt8Ty();
        i32_ = b_.getInt32Ty();
        i64_ = b_.getInt64Ty();
        f32_ = b_.getFloatTy();
        v4f_ = llvm::FixedVectorType::get(f32_, 4);
        ptr_ = llvm::PointerType::getUnqual(context);
    }

    void define_quad_depth();
    void define_square_depth();
    void define_inputs();
    void define_outputs();

private:
    // Where a quad's lanes are: pixel coordinates, and their offsets from
    // the primitive's origin as floats.
    struct Quad {
        llvm::Value *prim, *px, *py, *fx, *fy;
    };
    // Perspective-correct weights of vertices 1 and 2, and 1/w.
    struct Weights {
        llvm::Value *p1, *p2, *inv_w;
    };

    llvm::Function* begin(const char* name, llvm::Type* result, llvm::ArrayRef<llvm::Type*> params);
    llvm::Value* at(llvm::Value* base, uint64_t offset) { return b_.CreateConstInBoundsGEP1_64(i8_, base, offset); }
    llvm::Value* load_f(llvm::Value* base, uint64_t offset) { return b_.CreateLoad(f32_, at(base, offset)); }
    llvm::Value* load_i(llvm::Value* base, uint64_t offset) { return b_.CreateLoad(i32_, at(base, offset)); }
    // Values of a quad's lanes, or of two quads' (width_ 8).
    llvm::FixedVectorType* vf() { return llvm::FixedVectorType::get(f32_, width_); }
    llvm::Value* splat(llvm::Value* v) { return b_.CreateVectorSplat(width_, v); }
    llvm::Value* lanes_i(const int (&v)[4]) {
        std::vector<uint32_t> lanes;
        for (unsigned i = 0; i < width_; ++i) lanes.push_back(uint32_t(v[i % 4]));
        return llvm::ConstantDataVector::get(b_.getContext(), lanes);
    }
    llvm::Value* splat_f(float v) { return llvm::ConstantFP::get(vf(), v); }
    // a + b and a * b returning a's NaN (quieted) when a is one (as
    // ir::a_nan_first and raster/fragments.cpp's add() and mul()). Without strict_, plain: exact where every NaN is
    // the CPU's default NaN (made by the arithmetic, none in the inputs).
    llvm::Value* a_nan_first(llvm::Value* a, llvm::Value* r) {
        return b_.CreateSelect(b_.CreateFCmpUNO(a, a), b_.CreateFAdd(a, a), r);
    }
    llvm::Value* add(llvm::Value* a, llvm::Value* b) {
        return strict_ ? a_nan_first(a, b_.CreateFAdd(a, b)) : b_.CreateFAdd(a, b);
    }
    llvm::Value* mul(llvm::Value* a, llvm::Value* b) {
        return strict_ ? a_nan_first(a, b_.CreateFMul(a, b)) : b_.CreateFMul(a, b);
    }
    llvm::Value* is_nan(llvm::Value* v) { return b_.CreateFCmpUNO(v, v); }
    // then()'s value where `condition` holds, else `otherwise`: a branch and a phi.
    llvm::Value* if_then(llvm::Value* condition, llvm::Value* otherwise, const std::function<llvm::Value*()>& then);
    // One quad at (x[0], y[0]), or two of one primitive (width_ 8).
    Quad quad(llvm::Value* prim, llvm::ArrayRef<llvm::Value*> x, llvm::ArrayRef<llvm::Value*> y);
    llvm::Value* plane(const Quad& q, uint64_t offset);
    llvm::Value* clamp01(llvm::Value* v);
    // The window depth: its plane is not among nan_inputs(), so always strict.
    llvm::Value* quad_depth(const Quad& q) {
        const bool strict = std::exchange(strict_, true);
        llvm::Value* z = clamp01(plane(q, kDepth));
        strict_ = strict;
        return z;
    }
    Weights weights(const Quad& q);
    llvm::Value* vertex(const Quad& q, int i, uint64_t field) {
        return at(q.prim, kVertices + uint64_t(i) * kVertexSize + field);
    }
    llvm::Value* input(const Input& in, const Quad& q, const Weights& w);
    llvm::Value* nan_inputs(const Quad& q);
    std::array<llvm::Value*, 3> attributes(const Quad& q, uint32_t index);  // of vertices 0, 1, 2
    llvm::Value* compare(CompareFunc func, llvm::Value* incoming, llvm::Value* stored);
    llvm::Value* depth_passes(llvm::Value* incoming, llvm::Value* stored) {
        return compare(ops_.depth_func, incoming, stored);
    }
    llvm::Value* depth_test_lanes(const Quad& q, llvm::Value* z, llvm::Value* mask);
    llvm::Value* stencil_depth_lanes(const Quad& q, llvm::Value* z, llvm::Value* mask);
    llvm::Value* stencil_depth_lane(const StencilFace& face, const Quad& q, int i, llvm::Value* z, llvm::Value* mask);
    llvm::Value* stencil_op(StencilOp op, llvm::Value* value, int ref);
    llvm::Value* pixel_index(llvm::Value* x, llvm::Value* y, llvm::Value* width);
    using QuadBody = std::function<void(llvm::Value* index, const Quad& q)>;
    using PairTest = std::function<llvm::Value*(llvm::Value* index, llvm::Value* next)>;
    void for_each_quad(llvm::Value* batch, const QuadBody& body, const PairTest& pairable = nullptr);
    // Element `index` (i32) of the QuadBatch array at `offset`, of `type`.
    llvm::Value* batch_field(llvm::Value* batch, size_t offset, llvm::Type* type, llvm::Value* index) {
        return b_.CreateLoad(type, b_.CreateInBoundsGEP(type, at(batch, offset), b_.CreateZExt(index, i64_)));
    }
    // define_inputs()'s registers and its last primitive's NaN test.
    struct InputsState {
        std::vector<llvm::Value*> regs;
        llvm::AllocaInst *last_prim, *last_nan;
    };
    void store_inputs(const InputsState& state, llvm::Value* index, const Quad& q);
    // A quad's depth and colour values to store.
    struct QuadValues {
        llvm::Value* z;
        std::array<llvm::Value*, 4> rgba;
        llvm::Value* alpha;  // colour 0's alpha as the shader wrote it (0: not written)
    };
    QuadValues quad_values(const Quad& q, const std::vector<llvm::Value*>& regs, llvm::Value* index);
    void write_float_lanes(const Quad& q, const QuadValues& v, llvm::Value* lanes);
    llvm::Value* alpha_passes(const QuadValues& v);
    void write_rgba8_quad(const Quad& q, const QuadValues& v, llvm::Value* lanes);
    void read_modify_write_quad(const Quad& q, const QuadValues& v, llvm::Value* live, llvm::Value* lower_slot,
                                llvm::Value* upper_slot, llvm::Value* lower_mask, llvm::Value* upper_mask);
    llvm::Value* pack_rgba8(const std::array<llvm::Value*, 4>& rgba);
    llvm::Value* stored_byte(llvm::Value* c);
    void load_target(llvm::Value* target) {
        target_.depth = b_.CreateLoad(ptr_, at(target, offsetof(Target, depth)));
        target_.stencil = b_.CreateLoad(ptr_, at(target, offsetof(Target, stencil)));
        target_.color = b_.CreateLoad(ptr_, at(target, offsetof(Target, color)));
        target_.width = load_i(target, offsetof(Target, width));
        target_.height = load_i(target, offsetof(Target, height));
    }

    llvm::Module& module_;
    llvm::IRBuilder<> b_;
    const State& key_;
    const FragmentState& ops_;
    std::string suffix_;
    llvm::Type *i8_, *i32_, *i64_, *f32_, *ptr_;
    llvm::FixedVectorType* v4f_;
    // Per function being defined.
    llvm::Function* fn_ = nullptr;
    struct {
        llvm::Value *depth, *stencil, *color, *width, *height;
    } target_{};
    llvm::AllocaInst* written_ = nullptr;
    bool strict_ = false;  // add() and mul() order NaNs
    unsigned width_ = 4;   // lanes per vector: one quad, or two in the inputs' pairs
};

llvm::Function* PipelineEmitter::begin(const char* name, llvm::Type* result, llvm::ArrayRef<llvm::Type*> params) {
    auto* type = llvm::FunctionType::get(result, params, false);
    fn_ = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name + suffix_, module_);
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

// quad_depth(prim, x, y, mask, target): FragmentStage::early_depth_test.
void PipelineEmitter::define_quad_depth() {
    begin("glslrun_quad_depth", i32_, {ptr_, i32_, i32_, i32_, ptr_});
    llvm::Value* target = fn_->getArg(4);
    Quad q = quad(fn_->getArg(0), fn_->getArg(1), fn_->getArg(2));
    llvm::Value* z = quad_depth(q);
    load_target(target);
    b_.CreateRet(depth_test_lanes(q, z, fn_->getArg(3)));
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

// square_depth(prim, ox, oy, pixels, target): define_quad_depth's test on
// the pixels of an 8x8 square, a row of eight at a time. The pixels are
// distinct, so their order does not matter; the masked loads and stores
// touch only the pixels in `pixels`.
void PipelineEmitter::define_square_depth() {
    begin("glslrun_square_depth", i64_, {ptr_, i32_, i32_, i64_, ptr_});
    llvm::Value* prim = fn_->getArg(0);
    llvm::Value *ox = fn_->getArg(1), *oy = fn_->getArg(2), *pixels = fn_->getArg(3);
    load_target(fn_->getArg(4));
    auto* v8f = llvm::FixedVectorType::get(f32_, 8);
    auto* v8i = llvm::FixedVectorType::get(i32_, 8);
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
        llvm::Value* slot = b_.CreateGEP(f32_, target_.depth, pixel_index(ox, y, target_.width));
        llvm::Value* stored = b_.CreateMaskedLoad(v8f, slot, llvm::Align(4), in, llvm::ConstantFP::get(v8f, 0.0));
        llvm::Value* passes = depth_passes(z, stored);
        if (!passes->getType()->isVectorTy()) passes = b_.CreateVectorSplat(8, passes);
        passes = b_.CreateAnd(passes, in);
        if (ops_.depth_write) b_.CreateMaskedStore(z, slot, llvm::Align(4), passes);
        llvm::Value* passed = b_.CreateZExt(b_.CreateBitCast(passes, i8_), i64_);
        passing = b_.CreateOr(passing, b_.CreateShl(passed, uint64_t(8 * row)));
    }
    b_.CreateRet(passing);
}

// Emits body(index, quads) for the batch's quads in order, a loop: quads
// `index` and `index + 1` together (width_ 8, the first one's primitive)
// where pairable(index, index + 1) holds, else quad `index` alone (width_ 4).
void PipelineEmitter::for_each_quad(llvm::Value* batch, const QuadBody& body, const PairTest& pairable) {
    llvm::Value* quads = load_i(batch, offsetof(QuadBatch, quads));
    llvm::BasicBlock* entry = b_.GetInsertBlock();
    llvm::BasicBlock* loop = llvm::BasicBlock::Create(b_.getContext(), "quad", fn_);
    llvm::BasicBlock* done = llvm::BasicBlock::Create(b_.getContext(), "done", fn_);
    b_.CreateCondBr(b_.CreateICmpSGT(quads, b_.getInt32(0)), loop, done);
    b_.SetInsertPoint(loop);
    llvm::PHINode* index = b_.CreatePHI(i32_, 2);
    index->addIncoming(b_.getInt32(0), entry);
    llvm::Value* next = b_.CreateAdd(index, b_.getInt32(1));
    auto x = [&](llvm::Value* i) { return batch_field(batch, offsetof(QuadBatch, x), i32_, i); };
    auto y = [&](llvm::Value* i) { return batch_field(batch, offsetof(QuadBatch, y), i32_, i); };
    llvm::Value* prim = batch_field(batch, offsetof(QuadBatch, prim), ptr_, index);
    llvm::Value* step = b_.getInt32(1);
    if (pairable) {
        llvm::BasicBlock* test_pair = llvm::BasicBlock::Create(b_.getContext(), "test_pair", fn_);
        llvm::BasicBlock* pair = llvm::BasicBlock::Create(b_.getContext(), "pair", fn_);
        llvm::BasicBlock* single = llvm::BasicBlock::Create(b_.getContext(), "single", fn_);
        llvm::BasicBlock* after = llvm::BasicBlock::Create(b_.getContext(), "after_quads", fn_);
        b_.CreateCondBr(b_.CreateICmpSLT(next, quads), test_pair, single);
        b_.SetInsertPoint(test_pair);
        b_.CreateCondBr(pairable(index, next), pair, single);
        b_.SetInsertPoint(pair);
        width_ = 8;
        body(b_.CreateZExt(index, i64_), quad(prim, {x(index), x(next)}, {y(index), y(next)}));
        width_ = 4;
        llvm::BasicBlock* pair_end = b_.GetInsertBlock();
        b_.CreateBr(after);
        b_.SetInsertPoint(single);
        body(b_.CreateZExt(index, i64_), quad(prim, {x(index)}, {y(index)}));
        llvm::BasicBlock* single_end = b_.GetInsertBlock();
        b_.CreateBr(after);
        b_.SetInsertPoint(after);
        llvm::PHINode* taken = b_.CreatePHI(i32_, 2);
        taken->addIncoming(b_.getInt32(2), pair_end);
        taken->addIncoming(b_.getInt32(1), single_end);
        step = taken;
    } else {
        body(b_.CreateZExt(index, i64_), quad(prim, {x(index)}, {y(index)}));
    }
    llvm::Value* following = b_.CreateAdd(index, step);
    index->addIncoming(following, b_.GetInsertBlock());
    b_.CreateCondBr(b_.CreateICmpSLT(following, quads), loop, done);
    b_.SetInsertPoint(done);
}

// inputs(batch, regs): FragmentStage::fill_inputs. Two quads of one
// primitive (the common case: a batch's quads come several from one
// triangle) are interpolated together, 8 lanes a vector: the same
// operations per lane, half the instructions.
void PipelineEmitter::define_inputs() {
    begin("glslrun_inputs", b_.getVoidTy(), {ptr_, ptr_});
    llvm::Value* batch = fn_->getArg(0);
    std::vector<llvm::Value*> regs;
    for (size_t i = 0; i < key_.inputs.size(); ++i) regs.push_back(b_.CreateLoad(ptr_, at(fn_->getArg(1), i * 8)));
    // The last quad's primitive and whether it has NaN inputs: the test
    // loads all its interpolated values. Slots in the entry block, which
    // SROA turns into registers.
    InputsState state{regs, b_.CreateAlloca(ptr_), b_.CreateAlloca(b_.getInt1Ty())};
    b_.CreateStore(llvm::ConstantPointerNull::get(llvm::PointerType::getUnqual(b_.getContext())), state.last_prim);
    b_.CreateStore(b_.getFalse(), state.last_nan);
    auto same_primitive = [&](llvm::Value* index, llvm::Value* next) {
        return b_.CreateICmpEQ(batch_field(batch, offsetof(QuadBatch, prim), ptr_, index),
                               batch_field(batch, offsetof(QuadBatch, prim), ptr_, next));
    };
    for_each_quad(batch, [&](llvm::Value* index, const Quad& q) { store_inputs(state, index, q); }, same_primitive);
    b_.CreateRetVoid();
}

// The inputs of quad `index` (and the next, width_ 8): the primitive's NaN
// test unless it is the last quad's, then the plain or the strict version.
void PipelineEmitter::store_inputs(const InputsState& state, llvm::Value* index, const Quad& q) {
    llvm::BasicBlock* test = llvm::BasicBlock::Create(b_.getContext(), "nan_test", fn_);
    llvm::BasicBlock* tested = llvm::BasicBlock::Create(b_.getContext(), "nan_tested", fn_);
    b_.CreateCondBr(b_.CreateICmpEQ(q.prim, b_.CreateLoad(ptr_, state.last_prim)), tested, test);
    b_.SetInsertPoint(test);
    b_.CreateStore(nan_inputs(q), state.last_nan);
    b_.CreateStore(q.prim, state.last_prim);
    b_.CreateBr(tested);
    b_.SetInsertPoint(tested);
    // Two versions: the one that orders NaNs (add, mul) runs only for
    // primitives with NaNs in their inputs.
    llvm::BasicBlock* plain = llvm::BasicBlock::Create(b_.getContext(), "plain", fn_);
    llvm::BasicBlock* strict = llvm::BasicBlock::Create(b_.getContext(), "strict", fn_);
    llvm::BasicBlock* stored = llvm::BasicBlock::Create(b_.getContext(), "stored", fn_);
    b_.CreateCondBr(b_.CreateLoad(b_.getInt1Ty(), state.last_nan), strict, plain);
    for (llvm::BasicBlock* block : {plain, strict}) {
        b_.SetInsertPoint(block);
        strict_ = block == strict;
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

// raster::stencil_op on an i32 value (0 to 255).
llvm::Value* PipelineEmitter::stencil_op(StencilOp op, llvm::Value* v, int ref) {
    constexpr uint32_t kMax = (1u << kStencilBits) - 1;
    switch (op) {
    case StencilOp::Keep: return v;
    case StencilOp::Zero: return b_.getInt32(0);
    case StencilOp::Replace: return b_.getInt32(uint32_t(std::clamp(ref, 0, int(kMax))));
    case StencilOp::Incr: {
        llvm::Value* up = b_.CreateAdd(v, b_.getInt32(1));
        return b_.CreateSelect(b_.CreateICmpULT(up, b_.getInt32(kMax)), up, b_.getInt32(kMax));
    }
    case StencilOp::Decr:
        return b_.CreateSelect(b_.CreateICmpUGT(v, b_.getInt32(0)), b_.CreateSub(v, b_.getInt32(1)), b_.getInt32(0));
    case StencilOp::Invert: return b_.CreateAnd(b_.CreateNot(v), b_.getInt32(kMax));
    case StencilOp::IncrWrap: return b_.CreateAnd(b_.CreateAdd(v, b_.getInt32(1)), b_.getInt32(kMax));
    case StencilOp::DecrWrap: return b_.CreateAnd(b_.CreateSub(v, b_.getInt32(1)), b_.getInt32(kMax));
    }
    return v;
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
        // The new stencil value after `op`, through the write mask.
        auto updated = [&](StencilOp op) {
            llvm::Value* v = stencil_op(op, stored, face.ref);
            return b_.CreateOr(b_.CreateAnd(stored, b_.getInt32(~face.write_mask)),
                               b_.CreateAnd(v, b_.getInt32(face.write_mask)));
        };
        // Bytes compare exactly as floats: raster compares them with depth_passes.
        const uint32_t ref = uint32_t(std::clamp(face.ref, 0, int((1u << kStencilBits) - 1)));
        llvm::Value* stencil_passes =
            compare(face.func, llvm::ConstantFP::get(f32_, float(ref & face.value_mask)),
                    b_.CreateUIToFP(b_.CreateAnd(stored, b_.getInt32(face.value_mask)), f32_));
        llvm::Value* depth_passes_here = b_.getTrue();
        llvm::Value* depth_slot = nullptr;
        llvm::Value* zi = b_.CreateExtractElement(z, uint64_t(i));
        if (ops_.depth_test) {
            depth_slot = b_.CreateInBoundsGEP(f32_, target_.depth, pixel);
            depth_passes_here = depth_passes(zi, b_.CreateLoad(f32_, depth_slot));
        }
        llvm::Value* value = b_.CreateSelect(stencil_passes,
                                             b_.CreateSelect(depth_passes_here, updated(face.depth_pass),
                                                             updated(face.depth_fail)),
                                             updated(face.fail));
        b_.CreateStore(b_.CreateTrunc(value, i8_), slot);
        llvm::Value* passes = b_.CreateAnd(stencil_passes, depth_passes_here);
        if (ops_.depth_test && ops_.depth_write) {
            llvm::Value* old = b_.CreateLoad(f32_, depth_slot);
            b_.CreateStore(b_.CreateSelect(passes, zi, old), depth_slot);
        }
        llvm::Value* failed = b_.CreateShl(b_.CreateZExt(b_.CreateNot(passes), i32_), uint64_t(i));
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

// The float colour of a quad's lanes in `lanes` (i32, bit i: lane i),
// the channels of the colour mask (raster's write_float, unblended).
void PipelineEmitter::write_float_lanes(const Quad& q, const QuadValues& v, llvm::Value* lanes) {
    const bool all = ops_.color_mask == std::array<bool, 4>{true, true, true, true};
    for (int i = 0; i < 4; ++i) {
        llvm::BasicBlock* write = llvm::BasicBlock::Create(b_.getContext(), "write", fn_);
        llvm::BasicBlock* next = llvm::BasicBlock::Create(b_.getContext(), "next", fn_);
        b_.CreateCondBr(b_.CreateICmpNE(b_.CreateAnd(lanes, b_.getInt32(1u << i)), b_.getInt32(0)), write, next);
        b_.SetInsertPoint(write);
        llvm::Value* pixel = pixel_index(b_.CreateExtractElement(q.px, uint64_t(i)),
                                         b_.CreateExtractElement(q.py, uint64_t(i)), target_.width);
        llvm::Value* dst = b_.CreateInBoundsGEP(f32_, target_.color, b_.CreateShl(pixel, 2));
        llvm::Value* texel = llvm::PoisonValue::get(v4f_);
        for (unsigned k = 0; k < 4; ++k) {
            llvm::Value* c = b_.CreateExtractElement(v.rgba[k], uint64_t(i));
            texel = b_.CreateInsertElement(texel, c, uint64_t(k));
            if (!all && ops_.color_mask[k]) b_.CreateStore(c, b_.CreateConstInBoundsGEP1_64(f32_, dst, k));
        }
        if (all) b_.CreateAlignedStore(texel, dst, llvm::Align(4));
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
// `lanes`: i32, bit i: lane i.
void PipelineEmitter::write_rgba8_quad(const Quad& q, const QuadValues& v, llvm::Value* lanes) {
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
    llvm::Value* lower_slot = b_.CreateGEP(i32_, target_.color, pixel);
    llvm::Value* upper_slot = b_.CreateGEP(i32_, target_.color, above);
    if (reads_color(key_)) return read_modify_write_quad(q, v, live, lower_slot, upper_slot, row(0), row(2));
    llvm::Value* words = pack_rgba8(v.rgba);
    llvm::Value* lower = b_.CreateShuffleVector(words, llvm::ArrayRef<int>{0, 1, 0, 1});
    llvm::Value* upper = b_.CreateShuffleVector(words, llvm::ArrayRef<int>{2, 3, 2, 3});
    b_.CreateMaskedStore(lower, lower_slot, llvm::Align(4), row(0));
    b_.CreateMaskedStore(upper, upper_slot, llvm::Align(4), row(2));
}

// Four lanes of channel values (0 to 255) as RGBA8 words.
llvm::Value* PipelineEmitter::pack_rgba8(const std::array<llvm::Value*, 4>& rgba) {
    auto* v4i = llvm::FixedVectorType::get(i32_, 4);
    llvm::Value* words = llvm::Constant::getNullValue(v4i);
    for (unsigned k = 0; k < 4; ++k) {
        llvm::Value* byte = b_.CreateAnd(rgba[k], llvm::ConstantInt::get(v4i, 255));
        words = b_.CreateOr(words, b_.CreateShl(byte, llvm::ConstantInt::get(v4i, 8 * k)));
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
    for (uint32_t k = 0; k < 4; ++k) {
        llvm::Value* c = k < key_.color_channels ? lanes(k) : splat_f(0.0f);
        if (k == 3) v.alpha = c;
        v.rgba[k] = ops_.float_color ? c : stored_byte(c);
    }
    return v;
}

// A channel's RGBA8 byte as a 32-bit integer: raster::to_unorm8's steps, or
// raster::gpu_unorm8's with ColorRounding::Gpu.
llvm::Value* PipelineEmitter::stored_byte(llvm::Value* c) {
    auto* v4i = llvm::FixedVectorType::get(i32_, 4);
    c = b_.CreateSelect(b_.CreateFCmpOGT(c, splat_f(0.0f)), c, splat_f(0.0f));
    c = b_.CreateSelect(b_.CreateFCmpOLT(c, splat_f(1.0f)), c, splat_f(1.0f));
    if (ops_.rounding == ColorRounding::Gpu) {
        llvm::Value* t = b_.CreateFPToSI(b_.CreateFMul(c, splat_f(4096.0f)), v4i);
        llvm::Value* sum = b_.CreateAdd(b_.CreateMul(t, llvm::ConstantInt::get(v4i, 510)), llvm::ConstantInt::get(v4i, 4095));
        return b_.CreateAShr(sum, llvm::ConstantInt::get(v4i, 13));
    }
    constexpr float kRound = 8388608.0f;
    llvm::Value* rounded = b_.CreateFAdd(b_.CreateFMul(c, splat_f(255.0f)), splat_f(kRound));
    return b_.CreateFPToSI(b_.CreateFSub(rounded, splat_f(kRound)), v4i);
}

// outputs(batch, regs, alive, target): FragmentStage::write_outputs, quad
// by quad in lane order: the alpha test, the late depth test and write, then
// the colour write. A quad's depth tests before its colour write: the
// buffers are apart, and its pixels distinct.
void PipelineEmitter::define_outputs() {
    begin("glslrun_outputs", i64_, {ptr_, ptr_, i64_, ptr_});
    std::vector<llvm::Value*> regs;
    for (uint32_t i = 0; i < key_.color_channels + (key_.depth_output ? 1 : 0); ++i)
        regs.push_back(b_.CreateLoad(ptr_, at(fn_->getArg(1), uint64_t(i) * 8)));
    load_target(fn_->getArg(3));
    written_ = b_.CreateAlloca(i64_);
    b_.CreateStore(b_.getInt64(0), written_);
    const bool late_depth = ops_.depth_test && !key_.early_depth;
    const bool rgba8 = !ops_.float_color && key_.color_channels > 0;
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
        if (ops_.stencil_test) lanes = stencil_depth_lanes(q, v.z, lanes);
        else if (late_depth) lanes = depth_test_lanes(q, v.z, lanes);
        b_.CreateStore(b_.CreateOr(b_.CreateLoad(i64_, written_), b_.CreateShl(b_.CreateZExt(lanes, i64_), shift)),
                       written_);
        if (rgba8) write_rgba8_quad(q, v, lanes);
        else if (key_.color_channels > 0) write_float_lanes(q, v, lanes);
        if (next) {
            b_.CreateBr(next);
            b_.SetInsertPoint(next);
        }
    });
    b_.CreateRet(b_.CreateLoad(i64_, written_));
}

// The pipeline's code in the process's LLJIT (engine.h), removed with it.
class CompiledPipeline final : public Pipeline {
public:
    EngineCode code;
};

}  // namespace

std::unique_ptr<Pipeline> compile(const State& key, double* seconds) {
    const double start = rt::jit::thread_cpu_seconds();
    if (!fusable(key)) return nullptr;
    Engine* engine = Engine::of(key.avx2, false);
    if (!engine) return nullptr;
    auto code = std::make_unique<CompiledPipeline>();  // before the lock: its destructor takes it
    std::lock_guard hold(engine->lock);
    Engine::NewModule made = engine->new_module("pipeline");
    {
        PipelineEmitter emitter(*made.context, *made.module, key, made.suffix);
        if (key.early_depth) {
            emitter.define_quad_depth();
            emitter.define_square_depth();
        }
        emitter.define_inputs();
        emitter.define_outputs();
    }
    if (llvm::verifyModule(*made.module, &llvm::errs())) return nullptr;
    rt::jit::optimise(*made.module, *engine->machine);
    if (!code->code.add(*engine, std::move(made))) return nullptr;
    if (key.early_depth) {
        code->quad_depth = reinterpret_cast<Pipeline::QuadDepthFn>(code->code.lookup("glslrun_quad_depth"));
        code->square_depth = reinterpret_cast<Pipeline::SquareDepthFn>(code->code.lookup("glslrun_square_depth"));
    }
    code->inputs = reinterpret_cast<Pipeline::InputsFn>(code->code.lookup("glslrun_inputs"));
    code->outputs = reinterpret_cast<Pipeline::OutputsFn>(code->code.lookup("glslrun_outputs"));
    if (!code->inputs || !code->outputs || (key.early_depth && (!code->quad_depth || !code->square_depth)))
        return nullptr;
    if (seconds) *seconds = rt::jit::thread_cpu_seconds() - start;
    return code;
}

}  // namespace glslrun::raster::fused
