// The fused pipeline's key and its one eligibility rule (raster/fused/state.h).
#include "raster/fused/state.h"

#include <type_traits>

namespace glslrun::raster::fused {

namespace {

// A field added to these structs must be added to state_key() (and, where
// the generated code implements it, to forget_known_fields()): these sizes
// say when one was.
#define GLSLRUN_FUSED_SIZE(T, n) \
    static_assert(sizeof(T) == n, #T " changed: add its new field to state_key() and, once generated, forget_known_fields()")
GLSLRUN_FUSED_SIZE(FragmentState, 96);
GLSLRUN_FUSED_SIZE(StencilFace, 20);
GLSLRUN_FUSED_SIZE(BlendState, 24);
GLSLRUN_FUSED_SIZE(Input, 12);
GLSLRUN_FUSED_SIZE(State, 144);
#undef GLSLRUN_FUSED_SIZE

class KeyBytes {
public:
    template <class T>
    void add(const T& v) {
        static_assert((std::is_trivially_copyable_v<T> && std::has_unique_object_representations_v<T>) ||
                      std::is_floating_point_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void add(bool v) { bytes_.push_back(v ? '\1' : '\0'); }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

// The fields with no effect on the operations (a disabled test's function)
// take their defaults, so that states that draw alike share code.
FragmentState canonical(FragmentState o) {
    const FragmentState none;
    if (!o.alpha_test) o.alpha_func = none.alpha_func, o.alpha_ref = none.alpha_ref;
    if (!o.stencil_test) o.stencil = none.stencil;
    if (!o.depth_test) o.depth_func = none.depth_func, o.depth_write = none.depth_write;
    if (!o.blend) o.blend_state = none.blend_state;
    if (!o.logic_op) o.logic = none.logic;
    return o;
}

}  // namespace

std::string state_key(const State& state) {
    KeyBytes k;
    const FragmentState o = canonical(state.ops);
    k.add(o.alpha_test), k.add(o.alpha_func), k.add(o.alpha_ref);
    k.add(o.stencil_test);
    for (const StencilFace& f : o.stencil) {
        k.add(f.func), k.add(f.ref), k.add(f.value_mask), k.add(f.write_mask);
        k.add(f.fail), k.add(f.depth_fail), k.add(f.depth_pass);
    }
    k.add(o.depth_test), k.add(o.depth_write), k.add(o.depth_func);
    k.add(o.blend), k.add(o.logic_op), k.add(o.float_color), k.add(o.rounding), k.add(o.half_float);
    const BlendState& b = o.blend_state;
    k.add(b.src_rgb), k.add(b.dst_rgb), k.add(b.src_alpha), k.add(b.dst_alpha);
    k.add(b.equation_rgb), k.add(b.equation_alpha);
    for (int c = 0; c < 4; ++c) k.add(b.color[c]);
    k.add(o.logic);
    for (bool m : o.color_mask) k.add(m);
    k.add(o.draw_buffers);
    k.add(uint32_t(state.inputs.size()));
    for (const Input& in : state.inputs) k.add(in.source), k.add(in.index), k.add(in.kind), k.add(in.sprite_coord), k.add(in.component);
    k.add(state.color_channels);
    for (uint8_t c : state.more_channels) k.add(c);
    k.add(state.float_outputs), k.add(state.depth_output), k.add(state.early_depth);
    k.add(state.probe), k.add(state.avx2);
    return k.take();
}

State inputs_only(const State& s) {
    State only;
    only.inputs = s.inputs;
    only.avx2 = s.avx2;
    return only;
}

void forget_known_fields(State& s) {
    const State none;
    FragmentState& o = s.ops;
    o = canonical(o);
    // The stencil test, both faces, every function and operation.
    o.stencil_test = none.ops.stencil_test, o.stencil = none.ops.stencil;
    // The alpha test, either storage.
    o.alpha_test = none.ops.alpha_test, o.alpha_func = none.ops.alpha_func, o.alpha_ref = none.ops.alpha_ref;
    // The colour mask and blending, either storage; the logic op (RGBA8:
    // FragmentOps has none with float storage); the depth test early or late.
    o.color_mask = none.ops.color_mask;
    o.logic_op = none.ops.logic_op, o.logic = none.ops.logic;
    o.blend = none.ops.blend, o.blend_state = none.ops.blend_state;
    // The inputs: float registers, gl_FrontFacing's bool, or zeros; point
    // sprites' coordinates.
    bool inputs_known = true;
    for (const Input& in : s.inputs)
        inputs_known &= in.kind == ir::Kind::F32 || in.source == InputSource::Zero ||
                        (in.kind == ir::Kind::Bool && in.source == InputSource::FrontFacing);
    if (inputs_known) s.inputs = none.inputs;
    s.color_channels = none.color_channels;
    // Several draw buffers, each with the same operations.
    o.draw_buffers = none.ops.draw_buffers;
    s.more_channels = none.more_channels;
    s.depth_output = none.depth_output;
    s.early_depth = none.early_depth;
    s.avx2 = none.avx2;
    // The depth test, any function, with or without writes; both storages and roundings.
    o.depth_test = none.ops.depth_test, o.depth_write = none.ops.depth_write, o.depth_func = none.ops.depth_func;
    o.float_color = none.ops.float_color, o.rounding = none.ops.rounding;
}

bool fusable(const State& s) { return only_known_fields(s); }

}  // namespace glslrun::raster::fused
