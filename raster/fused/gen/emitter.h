// The fused pipeline's code generator (raster/fused/pipeline.h), shared by
// emit.cpp (the depth tests, the inputs and the module) and outputs.cpp
// (the per-fragment operations and writes). Internal to raster/fused/gen/.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <llvm/IR/IRBuilder.h>

#include "raster/fragments.h"
#include "raster/fused/pipeline.h"

namespace glslrun::raster::fused {

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

// The LLVM IR of one State's fragment functions, into one module.
class PipelineEmitter {
public:
    // The functions are named glslrun_quad_depth, glslrun_square_depth,
    // glslrun_inputs and glslrun_outputs (the module's code has a JITDylib
    // of its own: runtime/jit/engine.h).
    PipelineEmitter(llvm::LLVMContext& context, llvm::Module& module, const State& state)
        : module_(module), b_(context), key_(state), ops_(state.ops) {
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
    // Values of a quad's lanes, or of two or four quads' (width_ 8, 16).
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
    // One quad at (x[0], y[0]), or two or four of one primitive (width_ 8, 16).
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
    struct StencilOutcome {
        llvm::Value* value;   // the stencil values to store
        llvm::Value* passes;  // both tests passed
    };
    StencilOutcome stencil_outcome(const StencilFace& face, llvm::Value* stored, llvm::Value* depth_passes);
    llvm::Value* square_rows(const StencilFace* face, llvm::Value* prim, llvm::Value* ox, llvm::Value* oy,
                             llvm::Value* pixels);
    llvm::Value* pixel_index(llvm::Value* x, llvm::Value* y, llvm::Value* width);
    using QuadBody = std::function<void(llvm::Value* index, const Quad& q)>;
    using PairTest = std::function<llvm::Value*(llvm::Value* index, llvm::Value* next)>;
    void for_each_quad(llvm::Value* batch, const QuadBody& body, const PairTest& pairable = nullptr,
                       const std::function<void(llvm::Value* prim)>& first = nullptr);
    // Element `index` (i32) of the QuadBatch array at `offset`, of `type`.
    llvm::Value* batch_field(llvm::Value* batch, size_t offset, llvm::Type* type, llvm::Value* index) {
        return b_.CreateLoad(type, b_.CreateInBoundsGEP(type, at(batch, offset), b_.CreateZExt(index, i64_)));
    }
    // define_inputs()'s registers and its last primitive's NaN test.
    struct InputsState {
        std::vector<llvm::Value*> regs;
        llvm::AllocaInst *last_prim, *last_nan;
        llvm::Value* nan = nullptr;  // the step's primitive has NaN inputs (i1)
    };
    void store_inputs(const InputsState& state, llvm::Value* index, const Quad& q);
    llvm::Value* primitive_nan(const InputsState& state, llvm::Value* prim);
    // A quad's depth and colour values to store.
    struct QuadValues {
        llvm::Value* z;
        std::array<llvm::Value*, 4> rgba;
        llvm::Value* alpha;  // colour 0's alpha as the shader wrote it (0: not written)
    };
    QuadValues quad_values(const Quad& q, const std::vector<llvm::Value*>& regs, llvm::Value* index);
    void write_float_lanes(const Quad& q, const QuadValues& v, llvm::Value* lanes, llvm::Value* buffer);
    llvm::Value* alpha_passes(const QuadValues& v);
    void write_rgba8_quad(const Quad& q, const QuadValues& v, llvm::Value* lanes, llvm::Value* buffer,
                          llvm::Value* packed = nullptr);
    std::array<llvm::Value*, 4> color_values(const std::vector<llvm::Value*>& regs, size_t first, uint32_t channels,
                                             llvm::Value* index);
    void read_modify_write_quad(const Quad& q, const QuadValues& v, llvm::Value* live, llvm::Value* lower_slot,
                                llvm::Value* upper_slot, llvm::Value* lower_mask, llvm::Value* upper_mask);
    llvm::Value* pack_rgba8(const std::array<llvm::Value*, 4>& rgba);
    llvm::Value* stored_byte(llvm::Value* c);
    std::array<llvm::Value*, 4> convert_batch(const std::vector<llvm::Value*>& regs, size_t first, uint32_t channels,
                                              bool pack);
    void load_target(llvm::Value* target) {
        target_.depth = b_.CreateLoad(ptr_, at(target, offsetof(Target, depth)));
        target_.stencil = b_.CreateLoad(ptr_, at(target, offsetof(Target, stencil)));
        for (size_t b = 0; b < target_.color.size(); ++b)
            target_.color[b] = b_.CreateLoad(ptr_, at(target, offsetof(Target, color) + b * sizeof(void*)));
        target_.width = load_i(target, offsetof(Target, width));
        target_.height = load_i(target, offsetof(Target, height));
    }

    llvm::Module& module_;
    llvm::IRBuilder<> b_;
    const State& key_;
    const FragmentState& ops_;
    llvm::Type *i8_, *i32_, *i64_, *f32_, *ptr_;
    llvm::FixedVectorType* v4f_;
    // Per function being defined.
    llvm::Function* fn_ = nullptr;
    struct {
        llvm::Value *depth, *stencil, *width, *height;
        std::array<llvm::Value*, kMaxDrawBuffers> color;
    } target_{};
    llvm::AllocaInst* written_ = nullptr;
    bool strict_ = false;  // add() and mul() order NaNs
    unsigned width_ = 4;   // lanes per vector: one quad, or two or four in the inputs' runs
};

}  // namespace glslrun::raster::fused
