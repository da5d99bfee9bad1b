#include "raster/fragments.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "ir/scalar_ops.h"
#include "raster/framebuffer.h"
#include "runtime/backend_factory.h"
#include "runtime/execute.h"
#include "runtime/half_float.h"
#include "runtime/interp_kernels.h"
#include "runtime/program_state.h"

namespace glslrun::raster {

struct FragmentStage::InputPlan {
    using Source = fused::InputSource;
    Source source = Source::Zero;
    const ir::Binding* binding = nullptr;
    uint32_t attr_offset = 0;  // Varying: where in the attribute vector
    bool sprite_coord = false;  // gl_TexCoord[i] of a unit with GL_COORD_REPLACE (point sprites)
};

// Per lane of the batch: the perspective-correct weights of vertices 1 and 2
// (vertex 0's is implied) and the interpolated 1/w.
struct FragmentStage::Weights {
    std::array<float, rt::kLanes> p1, p2, inv_w;
};

namespace {

const ir::Binding* find_binding(const std::vector<ir::Binding>& list, std::initializer_list<const char*> names) {
    for (const char* name : names)
        for (const ir::Binding& b : list)
            if (b.name == name) return &b;
    return nullptr;
}

Plane to_plane(double a, double b, double c) { return {float(a), float(b), float(c)}; }

// a + b and a * b naming a's NaN (quieted) when a is one (ir::a_nan_first),
// whatever order the compiler gives the operands: the fused pipeline
// (raster/fused/gen/emit.cpp) computes the same expressions with the same rule.
QuadF add(QuadF a, QuadF b) { return ir::a_nan_first(a, a + b); }
QuadF mul(QuadF a, QuadF b) { return ir::a_nan_first(a, a * b); }
// A broadcast, which keeps -0 and denormals as they are (0 + v would make
// -0 of both, and flushed, of a negative denormal +0), as the fused
// pipeline's vector splat does.
QuadF splat(float v) { return QuadF{v, v, v, v}; }

// A plane at a quad's pixels, x and y relative to its origin: (c + a x) + b y.
QuadF plane_at(const Plane& p, QuadF x, QuadF y) {
    return add(add(splat(p.c), mul(splat(p.a), x)), mul(splat(p.b), y));
}

// Whole registers are copied, a constant size: lanes past the batch are not
// live, so their values do not matter.
void store_lanes(rt::Executor& in, ir::Kind kind, ir::Reg r, const Lanes& v, int lanes) {
    if (kind == ir::Kind::F32) {
        std::memcpy(in.lanes_f(r), v.data(), sizeof v);
        return;
    }
    for (int lane = 0; lane < lanes; ++lane) exec::set_lane(in, kind, r, lane, v[size_t(lane)]);
}

void load_lanes(rt::Executor& in, ir::Kind kind, ir::Reg r, Lanes& v, int lanes) {
    if (kind == ir::Kind::F32) {
        std::memcpy(v.data(), in.lanes_f(r), sizeof v);
        return;
    }
    for (int lane = 0; lane < lanes; ++lane) v[size_t(lane)] = exec::lane_as_float(in, kind, r, lane);
}

}  // namespace

// Vertex i's barycentric weight as a plane, from the unsnapped window
// positions (in double): coverage uses the positions snapped to the
// subpixel grid, but attributes interpolated over the snapped triangle are
// off by the snap (1/512 pixel) over the triangle's size, up to 1e-4 of a
// texture coordinate's range on small triangles; llvmpipe sets up its
// attribute planes from the float positions too. False where those
// positions make no triangle.
bool set_weight_planes(FsPrimitive& prim) {
    std::array<glm::dvec2, 3> p;
    const glm::dvec2 origin(prim.ox + 0.5, prim.oy + 0.5);
    for (int i = 0; i < 3; ++i) p[size_t(i)] = glm::dvec2(prim.v[size_t(i)].win) - origin;
    const double area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (!(std::fabs(area2) > 0.0) || !std::isfinite(area2)) return false;
    for (size_t i = 0; i < 3; ++i) {
        const glm::dvec2 &pj = p[(i + 1) % 3], &pk = p[(i + 2) % 3];
        prim.weight[i] = to_plane((pj.y - pk.y) / area2, (pk.x - pj.x) / area2, (pj.x * pk.y - pk.x * pj.y) / area2);
    }
    return true;
}

void set_triangle_planes(FsPrimitive& prim, const TriangleSetup& t, bool snapped) {
    prim.ox = t.bbox.x0;
    prim.oy = t.bbox.y0;
    const bool weights_set = !snapped && set_weight_planes(prim);
    // Depth (and the weights when snapped or where the float positions are degenerate): the
    // edge functions over twice the area, exact at the origin (integers)
    // and with per-pixel steps of kSubpixelOne.
    std::array<int64_t, 3> e = edge_values(t, prim.ox, prim.oy);
    const double inv_area2 = 1.0 / double(t.area2);
    double za = 0, zb = 0, zc = 0;
    for (int i = 0; i < 3; ++i) {
        double a = double(t.ea[i]) * double(kSubpixelOne) * inv_area2;
        double b = double(t.eb[i]) * double(kSubpixelOne) * inv_area2;
        double c = double(e[i]) * inv_area2;
        if (!weights_set) prim.weight[i] = to_plane(a, b, c);
        za += a * prim.v[i].z;
        zb += b * prim.v[i].z;
        zc += c * prim.v[i].z;
    }
    prim.z = to_plane(za, zb, zc);
}

void set_line_planes(FsPrimitive& prim) {
    prim.v[2] = prim.v[1];
    glm::dvec2 a = prim.v[0].win, d = glm::dvec2(prim.v[1].win) - a;
    int major = std::fabs(d.x) >= std::fabs(d.y) ? 0 : 1;
    prim.ox = pixel_floor(prim.v[0].win.x);
    prim.oy = pixel_floor(prim.v[0].win.y);
    if (!(d[major] != 0.0)) return set_point_planes(prim);  // no pixels
    // t: the pixel centre projected onto the major axis, 0 at v0 and 1 at v1.
    glm::dvec2 centre(prim.ox + 0.5, prim.oy + 0.5);
    double step = 1.0 / d[major], t0 = (centre[major] - a[major]) * step;
    double ta = major == 0 ? step : 0.0, tb = major == 1 ? step : 0.0;
    prim.weight = {to_plane(-ta, -tb, 1.0 - t0), to_plane(ta, tb, t0), Plane{}};
    double dz = double(prim.v[1].z) - prim.v[0].z;
    prim.z = to_plane(ta * dz, tb * dz, prim.v[0].z + t0 * dz);
}

void set_point_planes(FsPrimitive& prim) {
    prim.v[1] = prim.v[2] = prim.v[0];
    prim.weight = {Plane{0, 0, 1}, Plane{}, Plane{}};
    prim.z = Plane{0, 0, prim.v[0].z};
}

FragmentStage::FragmentStage(const Program& program, const GLState& gl, Framebuffer& fb, rt::DrawBudget* budget)
    : program_(program), gl_(gl), fb_(fb), ops_(gl, fb) {
    const Program::State& st = state_of(program);
    const ir::Shader& fs = st.ir.fragment;
    interp_ = rt::make_executor(program, ir::Stage::Fragment, gl.texture_units.data(), budget);
    for (size_t i = 0; i < fs.inputs.size(); ++i) {
        const ir::Binding& b = fs.inputs[i];
        InputPlan plan{InputPlan::Source::Zero, &b, 0};
        for (int unit = 0; unit < 8 && gl.point_sprite; ++unit)
            if ((gl.coord_replace >> unit) & 1u && b.name == "gl_TexCoord[" + std::to_string(unit) + "]")
                plan.sprite_coord = true;
        if (b.name == "gl_FragCoord") plan.source = InputPlan::Source::FragCoord;
        else if (b.name == "gl_FrontFacing") plan.source = InputPlan::Source::FrontFacing;
        else if (b.name == "gl_PointCoord") plan.source = InputPlan::Source::PointCoord;
        for (const ir::VaryingLink& link : st.ir.varyings) {
            if (link.fs_input != i || plan.source != InputPlan::Source::Zero) continue;
            if (link.vs_output < 0 && link.vs_back_output < 0) continue;
            plan.source = InputPlan::Source::Varying;
            plan.attr_offset = attr_count_;
            varyings_.push_back({attr_count_, b.count, link.vs_output, link.vs_back_output, link.is_color});
            attr_count_ += b.count;
        }
        inputs_.push_back(plan);
    }
    // gl_FragColor goes to every draw buffer; gl_FragData[i] to buffer i.
    const ir::Binding* frag_color = find_binding(fs.outputs, {"gl_FragColor"});
    for (int i = 0; i < gl.draw_buffers && i < kMaxDrawBuffers; ++i) {
        std::string element = "gl_FragData[" + std::to_string(i) + "]";
        color_out_[size_t(i)] = frag_color ? frag_color : find_binding(fs.outputs, {element.c_str()});
    }
    depth_out_ = find_binding(fs.outputs, {"gl_FragDepth"});
    // Without discard, gl_FragDepth and the alpha test (which a fragment
    // must survive to reach the stencil test, whose depth-fail update
    // depends on it) the stencil and depth tests cannot depend on the
    // shader, so they run before shading and cull hidden quads and those
    // the stencil rejects (a mirror's room drawn around its mark: a fifth of
    // the fragments shaded, perf). Their updates of a pixel stay in
    // submission order, and the colour writes after shading in lane order.
    // The shader debugger sees every fragment shaded: the late tests give the
    // same image (the same tests in the same order), only with more shading.
    probe_ = st.probe;
    if (probe_) probe_tests_ = std::make_unique<ProbeTests>();
    early_depth_ = (gl.depth_test || gl.stencil_test) && !fs.uses_discard && !depth_out_ && !gl.alpha_test && !probe_;
    // After the early tests a shader whose colours no buffer takes (every
    // channel masked, or no colour output) has nothing left to do: its
    // fragments are counted as written and not shaded (a mirror's stencil
    // mark, a depth-only pass).
    bool colour_written = false;
    for (int b = 0; b < ops_.draw_buffers && b < kMaxDrawBuffers; ++b) colour_written |= color_out_[size_t(b)] != nullptr;
    colour_written &= ops_.color_mask != std::array<bool, 4>{false, false, false, false};
    tests_only_ = early_depth_ && !colour_written;
    // The debugger shows every lane's values, helpers' lookups too.
    skip_helper_lookups_ = !fs.helper_lookups_matter && !probe_;
    pipeline_ = fused_pipeline();
}

// The fused path's state: the draw's per-fragment operations, the shader's
// inputs and outputs (with the registers the functions fill and read).
fused::State FragmentStage::fused_state() {
    fused::State state;
    state.ops = ops_;
    state.probe = probe_ != nullptr;
    input_regs_.clear();
    output_regs_.clear();
    for (const InputPlan& p : inputs_) {
        const ir::Binding& b = *p.binding;
        for (uint32_t c = 0; c < b.count; ++c) {
            uint32_t index = p.source == InputPlan::Source::Varying ? p.attr_offset + c : c;
            state.inputs.push_back({p.source, index, b.kind, p.sprite_coord, uint8_t(c)});
            input_regs_.push_back(interp_->lanes(b.first + c));
        }
    }
    if (const ir::Binding* color = color_out_[0]) {
        state.float_outputs &= color->kind == ir::Kind::F32;
        state.color_channels = std::min<uint32_t>(4, color->count);
        for (uint32_t k = 0; k < state.color_channels; ++k) output_regs_.push_back(interp_->lanes(color->first + k));
    }
    if (depth_out_) {
        state.float_outputs &= depth_out_->kind == ir::Kind::F32;
        state.depth_output = true;
        output_regs_.push_back(interp_->lanes(depth_out_->first));
    }
    for (int b = 1; b < ops_.draw_buffers; ++b) {
        const ir::Binding* color = color_out_[size_t(b)];
        if (!color) continue;
        state.float_outputs &= color->kind == ir::Kind::F32;
        state.more_channels[size_t(b)] = uint8_t(std::min<uint32_t>(4, color->count));
        for (uint32_t k = 0; k < state.more_channels[size_t(b)]; ++k)
            output_regs_.push_back(interp_->lanes(color->first + k));
    }
    state.early_depth = early_depth_;
    state.avx2 = rt::cpu_has_avx2();
    return state;
}

// The fused pipeline where the shader runs JIT-compiled and
// fused::fusable() takes the draw's state. Null otherwise, until the
// program has shaded enough fragments to pay for it
// (fused::kPipelineAfterFragments), and under Backend::Auto until its
// background compile is done.
const fused::Pipeline* FragmentStage::fused_pipeline() {
    if (interp_->runner() != rt::Runner::Jit) return nullptr;
    const fused::State state = fused_state();
    target_.depth = fb_.depth.data();
    target_.stencil = fb_.stencil.data();
    for (int b = 0; b < ops_.draw_buffers; ++b)
        target_.color[size_t(b)] = ops_.float_color ? static_cast<void*>(fb_.color_data<float>(b).data())
                                                    : static_cast<void*>(fb_.color_data<uint8_t>(b).data());
    target_.width = fb_.width;
    target_.height = fb_.height;
    return state_of(program_).pipelines->get(state, program_.exec.backend == Backend::Jit, program_.exec);
}

void FragmentStage::prefetch(const Rect& r) const {
    constexpr size_t kLine = 64;
    const bool depth = ops_.depth_test, color = color_out_[0] != nullptr;
    const size_t color_bytes = fb_.float_color() ? 4 * sizeof(float) : 4;
    for (int y = r.y0; y < r.y1; ++y) {
        const size_t first = size_t(y) * size_t(fb_.width) + size_t(r.x0), pixels = size_t(r.x1 - r.x0);
        if (depth)
            for (size_t i = 0; i < pixels * sizeof(float); i += kLine)
                __builtin_prefetch(reinterpret_cast<const char*>(&fb_.depth[first]) + i, 1);
        const char* row = fb_.float_color() ? reinterpret_cast<const char*>(fb_.color_row<float>(0, y))
                                            : reinterpret_cast<const char*>(fb_.color_row<uint8_t>(0, y));
        if (color)
            for (size_t i = 0; i < pixels * color_bytes; i += kLine) __builtin_prefetch(row + size_t(r.x0) * color_bytes + i, 1);
        // A tile's row of stencil bytes is one line or two (the stencil test's
        // loads waited on them: perf, a mirror's frame).
        if (ops_.stencil_test)
            for (size_t i = 0; i < pixels; i += kLine) __builtin_prefetch(&fb_.stencil[first] + i, 1);
    }
}

ProbeBatch FragmentStage::probe_batch(rt::LaneMask covered) {
    return ProbeBatch{*interp_, quads_ * 4, lane_x_, lane_y_, lane_z_, quad_prim_.data(), covered};
}

FragmentStage::Walk::Walk(FragmentStage& stage) : stage_(stage) {
    if (stage_.interp_->hold_denormal_mode(true)) flushed_.emplace();
}

FragmentStage::Walk::~Walk() {
    flushed_.reset();
    stage_.interp_->hold_denormal_mode(false);
}

FragmentStage::~FragmentStage() { state_of(program_).pipelines->count_unfused(shaded_ - fused_); }

void FragmentStage::gather(const float* vs_vertex, const std::vector<uint32_t>& vs_offset, bool back,
                           float* dst) const {
    for (const VaryingSlot& s : varyings_) {
        int source = back && s.is_color && s.vs_back_output >= 0 ? s.vs_back_output : s.vs_output;
        if (source < 0) source = s.vs_back_output;
        const float* src = vs_vertex + vs_offset[size_t(source)];
        for (uint32_t c = 0; c < s.count; ++c) {
            float v = src[c];
            // GL 2.1 clamps colour varyings to [0,1] (GL_CLAMP_VERTEX_COLOR default TRUE).
            dst[s.offset + c] = s.is_color ? (v > 0.0f ? std::min(v, 1.0f) : 0.0f) : v;
        }
    }
}

void FragmentStage::copy_colors(const float* from, float* to) const {
    for (const VaryingSlot& s : varyings_)
        if (s.is_color) std::copy(from + s.offset, from + s.offset + s.count, to + s.offset);
}

// The depth test of the lanes `mask` of the quad at lane `base`, with the
// depths z (of the batch's lanes); returns those that pass.
template <bool kWrite>
unsigned FragmentStage::depth_test_quad(int base, const float* z_lanes, unsigned mask) {
    const int x = lane_x_[base], y = lane_y_[base];
    const QuadF z = load_quad(z_lanes + base);
    if (x + 1 < fb_.width && y + 1 < fb_.height) {
        // The whole quad is in the framebuffer: one vector test. Its four
        // pixels are distinct, so the lanes' order does not matter.
        float* at = &fb_.depth[size_t(y) * size_t(fb_.width) + size_t(x)];
        QuadF stored = gather_quad(at, size_t(fb_.width));
        QuadI passes = depth_passes(ops_.depth_func, z, stored) & lanes_of(mask);
        if (kWrite) scatter_quad(at, size_t(fb_.width), passes ? z : stored);
        return mask_of(passes);
    }
    // The function read once (stores to the depth buffer would otherwise
    // make the compiler reload it per lane).
    const GLState::DepthFunc func = ops_.depth_func;
    for (unsigned bits = mask; bits; bits &= bits - 1) {
        int i = std::countr_zero(bits), lane = base + i;
        float& stored = fb_.depth[size_t(lane_y_[lane]) * fb_.width + lane_x_[lane]];
        // Stored either way, so that the outcome needs no branch.
        bool passes = depth_passes(func, z_lanes[lane], stored);
        if (kWrite) stored = passes ? z_lanes[lane] : stored;
        mask &= ~(unsigned(!passes) << i);
    }
    return mask;
}

// The early stencil and depth tests of the quad at lane `base` (its
// positions and depths stored), with their buffer updates.
unsigned FragmentStage::early_tests_quad(const FsPrimitive& prim, int base, unsigned mask) {
    if (ops_.stencil_test) {
        const LanePixels px{lane_x_.data(), lane_y_.data(), lane_z_.data(), prim.front ? 0 : rt::LaneMask(0xF) << base};
        return unsigned(stencil_depth_test(ops_, fb_, px, rt::LaneMask(mask) << base) >> base);
    }
    return ops_.depth_write ? depth_test_quad<true>(base, lane_z_.data(), mask)
                            : depth_test_quad<false>(base, lane_z_.data(), mask);
}

void FragmentStage::add_quad(const FsPrimitive& prim, int x, int y, unsigned mask) {
    if (error_) return;
    int base = quads_ * 4;
    if (pipeline_) {
        if (early_depth_) mask = pipeline_->quad_depth(&prim, x, y, mask, &target_);
        if (tests_only_) written_ += uint64_t(std::popcount(mask));
        if (!mask || tests_only_) return;
        batch_.prim[quads_] = &prim;
        batch_.x[quads_] = x;
        batch_.y[quads_] = y;
        covered_ |= rt::LaneMask(mask) << base;
        if (++quads_ == rt::kLanes / 4) flush();
        return;
    }
    store_quad(&lane_x_[base], x + kQuadDxI);
    store_quad(&lane_y_[base], y + kQuadDyI);
    const QuadF px = float(x - prim.ox) + kQuadDxF, py = float(y - prim.oy) + kQuadDyF;
    const QuadF z = clamp01(plane_at(prim.z, px, py));
    store_quad(&lane_z_[base], z);
    if (early_depth_) mask = early_tests_quad(prim, base, mask);
    if (tests_only_) written_ += uint64_t(std::popcount(mask));
    if (!mask || tests_only_) return;
    quad_prim_[size_t(quads_)] = &prim;
    covered_ |= rt::LaneMask(mask) << base;
    if (++quads_ == rt::kLanes / 4) flush();
}

void FragmentStage::add_quads(const FsPrimitive& prim, uint64_t pixels, uint64_t part, int ox, int oy) {
    if (!pipeline_) {
        visit_quads(pixels, part, ox, oy, [&](int x, int y, unsigned mask) { add_quad(prim, x, y, mask); });
        return;
    }
    if (error_) return;
    // The parts' edges are even (triangle.h), so the part's pixels are its
    // quads' pixels. The early tests write only depth and stencil: testing
    // all of them before the batches they fill are shaded changes nothing.
    if (early_depth_) pixels = pipeline_->square_depth(&prim, ox, oy, pixels & part, &target_);
    if (tests_only_) {
        written_ += uint64_t(std::popcount(pixels & part));
        return;
    }
    visit_quads(pixels, part, ox, oy, [&](int x, int y, unsigned mask) {
        if (error_) return;
        batch_.prim[quads_] = &prim;
        batch_.x[quads_] = x;
        batch_.y[quads_] = y;
        covered_ |= rt::LaneMask(mask) << (quads_ * 4);
        if (++quads_ == rt::kLanes / 4) flush();
    });
}

void FragmentStage::compute_weights(Weights& w) const {
    for (int q = 0; q < quads_; ++q) {
        const FsPrimitive& p = *quad_prim_[size_t(q)];
        const int base = q * 4;
        const QuadF x = float(lane_x_[base] - p.ox) + kQuadDxF, y = float(lane_y_[base] - p.oy) + kQuadDyF;
        const QuadF l0 = plane_at(p.weight[0], x, y), l1 = plane_at(p.weight[1], x, y), l2 = plane_at(p.weight[2], x, y);
        const QuadF w1 = mul(l1, splat(p.v[1].inv_w)), w2 = mul(l2, splat(p.v[2].inv_w));
        const QuadF inv_w = add(add(mul(l0, splat(p.v[0].inv_w)), w1), w2);
        // 1 / 0 in the lanes that do not use it: no trap, nothing reads the flags.
        const QuadI finite = inv_w != 0.0f;
        const QuadF r = 1.0f / inv_w;
        store_quad(&w.inv_w[size_t(base)], inv_w);
        store_quad(&w.p1[size_t(base)], finite ? mul(w1, r) : l1);
        store_quad(&w.p2[size_t(base)], finite ? mul(w2, r) : l2);
    }
}

// Component `attr` of the attribute vectors, perspective correct, into the
// batch's lanes.
void FragmentStage::interpolate(uint32_t attr, const Weights& w, float* v) const {
    for (int q = 0; q < quads_; ++q) {
        const FsPrimitive& prim = *quad_prim_[size_t(q)];
        float a0 = prim.v[0].attrs[attr];
        float d1 = prim.v[1].attrs[attr] - a0, d2 = prim.v[2].attrs[attr] - a0;
        const size_t base = size_t(q) * 4;
        store_quad(v + base, add(add(splat(a0), mul(load_quad(&w.p1[base]), splat(d1))),
                                 mul(load_quad(&w.p2[base]), splat(d2))));
    }
}

// Component c of gl_FragCoord, gl_FrontFacing or gl_PointCoord (0 for inputs
// no varying feeds).
void FragmentStage::builtin_input(fused::InputSource source, uint32_t c, const Weights& w, Lanes& v) const {
    using Source = InputPlan::Source;
    for (int q = 0; q < quads_; ++q) {
        const FsPrimitive& prim = *quad_prim_[size_t(q)];
        for (int lane = q * 4; lane < q * 4 + 4; ++lane) {
            float fx = float(lane_x_[lane]) + 0.5f, fy = float(lane_y_[lane]) + 0.5f, value = 0;
            switch (source) {
            case Source::FragCoord: {
                const float coord[4] = {fx, fy, lane_z_[lane], w.inv_w[lane]};
                value = c < 4 ? coord[c] : 0.0f;
                break;
            }
            case Source::FrontFacing: value = prim.front ? 1.0f : 0.0f; break;
            case Source::PointCoord:
                if (prim.count != 1) break;
                value = std::fma(prim.point_coord_step[int(c & 1)], float(c == 0 ? lane_x_[lane] : lane_y_[lane]),
                                 prim.point_coord_origin[int(c & 1)]);
                break;
            default: break;
            }
            v[size_t(lane)] = value;
        }
    }
}

// GL_COORD_REPLACE: on points, component c of gl_TexCoord[i] is that of
// (gl_PointCoord, 0, 1); other primitives keep their values.
void FragmentStage::replace_sprite_coord(uint32_t c, const Weights& w, Lanes& v) const {
    Lanes coord{};
    if (c < 2) builtin_input(InputPlan::Source::PointCoord, c, w, coord);
    for (int q = 0; q < quads_; ++q) {
        if (quad_prim_[size_t(q)]->count != 1) continue;
        for (int lane = q * 4; lane < q * 4 + 4; ++lane) v[size_t(lane)] = c < 2 ? coord[size_t(lane)] : c == 3 ? 1.0f : 0.0f;
    }
}

void FragmentStage::fill_inputs(const Weights& w) {
    Lanes v{};
    for (const InputPlan& p : inputs_) {
        const ir::Binding& b = *p.binding;
        for (uint32_t c = 0; c < b.count; ++c) {
            // Float varyings straight into the executor's register.
            if (p.source == InputPlan::Source::Varying && b.kind == ir::Kind::F32 && !p.sprite_coord) {
                interpolate(p.attr_offset + c, w, interp_->lanes_f(b.first + c));
                continue;
            }
            if (p.source == InputPlan::Source::Varying) interpolate(p.attr_offset + c, w, v.data());
            else builtin_input(p.source, c, w, v);
            if (p.sprite_coord) replace_sprite_coord(c, w, v);
            store_lanes(*interp_, b.kind, b.first + c, v, quads_ * 4);
        }
    }
}

void FragmentStage::flush() {
    if (quads_ == 0) return;
    int lanes = quads_ * 4;
    if (pipeline_) {
        batch_.quads = quads_;
        pipeline_->inputs(&batch_, input_regs_.data());
    } else {
        Weights w;
        compute_weights(w);
        fill_inputs(w);
    }
    rt::LaneMask live = lanes == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << lanes) - 1;
    if (skip_helper_lookups_) interp_->skip_lookups(live & ~covered_);
    rt::RunError run_error;
    if (probe_) [[unlikely]]
        probe_->before_run(probe_batch(covered_));
    bool ok = interp_->run(live, &run_error);
    rt::LaneMask covered = covered_;
    covered_ = 0;
    if (!ok) {
        quads_ = 0;
        error_ = exec::run_error(state_of(program_), ir::Stage::Fragment, run_error);
        return;
    }
    if (pipeline_) {
        rt::LaneMask written = pipeline_->outputs(&batch_, output_regs_.data(), interp_->alive() & covered, &target_);
        shaded_ += uint64_t(std::popcount(covered));
        fused_ += uint64_t(std::popcount(covered));
        written_ += uint64_t(std::popcount(written));
    } else if (probe_) [[unlikely]]
        probe_->after_write(probe_batch(covered), interp_->alive() & covered, write_outputs<true>(covered),
                            *probe_tests_);
    else
        write_outputs<false>(covered);
    quads_ = 0;
}

// Component values of colour buffer `buffer`'s output over the batch.
void FragmentStage::load_color(int buffer, std::array<Lanes, 4>& rgba) const {
    const ir::Binding* out = color_out_[size_t(buffer)];
    rgba = {};
    uint32_t channels = std::min<uint32_t>(4, out->count);
    for (uint32_t k = 0; k < channels; ++k) load_lanes(*interp_, out->kind, out->first + k, rgba[k], quads_ * 4);
}

// The per-fragment operations over the batch (late depth test or none,
// then colour writes), in lane order: two quads of the batch may cover the
// same pixel.
// kProbed: returns the lanes written (alive, and passing the tests), for
// the probe; without it, 0 (no work for it per lane on the fast path).
template <bool kProbed>
rt::LaneMask FragmentStage::write_outputs(rt::LaneMask covered) {
    rt::Executor& in = *interp_;
    shaded_ += uint64_t(std::popcount(covered));
    rt::LaneMask alive = in.alive() & covered;
    Lanes z = lane_z_;
    if (depth_out_) {
        load_lanes(in, depth_out_->kind, depth_out_->first, z, quads_ * 4);
        for (float& d : z) d = d > 0.0f ? std::min(d, 1.0f) : 0.0f;  // NaN -> 0
    }
    if constexpr (kProbed) {
        ProbeTests& t = *probe_tests_;
        t = ProbeTests{};
        t.z = z;
        t.alpha_ref = ops_.float_color ? ops_.alpha_ref : ops_.alpha_ref8;
        t.alpha_bytes = !ops_.float_color;
        return write_watched(covered, alive, z);
    }
    if (ops_.plain) return write_plain<false>(alive, z);
    write_with_ops(alive, z, nullptr);
    return 0;
}

// The pixel of lane `lane` as the framebuffer holds it now.
void FragmentStage::snapshot(int lane, ProbePixel& p) const {
    const size_t pixel = size_t(lane_y_[size_t(lane)]) * size_t(fb_.width) + size_t(lane_x_[size_t(lane)]);
    p.buffers = std::min(fb_.color_buffers(), kMaxDrawBuffers);
    for (int b = 0; b < p.buffers; ++b)
        for (size_t k = 0; k < 4; ++k)
            p.color[size_t(b)][k] = fb_.float_color() ? fb_.color_data<float>(b)[pixel * 4 + k]
                                                      : float(fb_.color_data<uint8_t>(b)[pixel * 4 + k]);
    p.depth = pixel < fb_.depth.size() ? fb_.depth[pixel] : 0.0f;
    p.stencil = pixel < fb_.stencil.size() ? fb_.stencil[pixel] : uint8_t(0);
}

// With a probe: the lanes it watches one at a time, each between snapshots
// of its pixel, after the others (which touch other pixels only: the same
// image). Returns the lanes written.
rt::LaneMask FragmentStage::write_watched(rt::LaneMask covered, rt::LaneMask alive, const Lanes& z) {
    ProbeTests& t = *probe_tests_;
    auto write = [&](rt::LaneMask lanes) {
        return ops_.plain ? write_plain<true>(lanes, z) : write_with_ops(lanes, z, &t);
    };
    t.watched = probe_->watched(probe_batch(covered)) & covered;
    rt::LaneMask written = write(alive & ~t.watched);
    for (rt::LaneMask bits = t.watched; bits; bits &= bits - 1) {
        const int lane = std::countr_zero(bits);
        snapshot(lane, t.before[size_t(lane)]);
        if (alive & (rt::LaneMask(1) << lane)) written |= write(alive & (rt::LaneMask(1) << lane));
        snapshot(lane, t.after[size_t(lane)]);
    }
    return written;
}

// The fast path: at most a depth test with writes, and plain stores into one buffer.
template <bool kProbed>
rt::LaneMask FragmentStage::write_plain(rt::LaneMask alive, const Lanes& z) {
    std::array<Lanes, 4> rgba{};
    if (color_out_[0]) load_color(0, rgba);
    const bool late_depth = ops_.depth_test && !early_depth_;  // with depth writes (ops_.plain)
    rt::LaneMask written = 0;
    // Quad by quad in lane order: two quads of the batch may cover one pixel.
    for (int base = 0; base < quads_ * 4; base += 4) {
        unsigned mask = unsigned(alive >> base) & 0xFu;
        if constexpr (kProbed) {
            for (unsigned bits = late_depth ? mask : 0; bits; bits &= bits - 1) {
                int lane = base + std::countr_zero(bits);
                probe_tests_->stored_depth[size_t(lane)] =
                    fb_.depth[size_t(lane_y_[lane]) * size_t(fb_.width) + size_t(lane_x_[lane])];
            }
        }
        const unsigned tested = mask;
        if (late_depth && mask) mask = depth_test_quad<true>(base, z.data(), mask);
        if constexpr (kProbed) probe_tests_->depth_failed |= rt::LaneMask(tested & ~mask) << base;
        if (!mask) continue;
        written |= rt::LaneMask(mask) << base;
        if (color_out_[0]) store_color_quad(base, rgba, mask);
    }
    written_ += uint64_t(std::popcount(written));
    return kProbed ? written : 0;
}

// The plain store of colour buffer 0's lanes `mask` of the quad at lane `base`.
void FragmentStage::store_color_quad(int base, const std::array<Lanes, 4>& rgba, unsigned mask) {
    const size_t width = size_t(fb_.width), pixel = size_t(lane_y_[base]) * width + size_t(lane_x_[base]);
    auto offset = [&](int lane) { return (pixel + size_t(kQuadDx[lane]) + size_t(kQuadDy[lane]) * width) * 4; };
    if (fb_.float_color()) {
        float* buffer = fb_.color_data<float>(0).data();
        for (unsigned bits = mask; bits; bits &= bits - 1) {
            int lane = std::countr_zero(bits);
            for (size_t k = 0; k < 4; ++k) {
                const float c = rgba[k][size_t(base + lane)];
                buffer[offset(lane) + k] = ops_.half_float ? rt::truncate_to_half(c) : c;
            }
        }
        return;
    }
    uint8_t* buffer = fb_.color_data<uint8_t>(0).data();
    const QuadI words = pack_unorm8(load_quad(&rgba[0][size_t(base)]), load_quad(&rgba[1][size_t(base)]),
                                    load_quad(&rgba[2][size_t(base)]), load_quad(&rgba[3][size_t(base)]),
                                    fb_.rounding);
    const auto* word_bytes = reinterpret_cast<const uint8_t*>(&words);
    if (mask == 0xFu) {  // all four pixels exist: two 8-byte stores
        std::memcpy(buffer + offset(0), word_bytes, 8);
        std::memcpy(buffer + offset(2), word_bytes + 8, 8);
        return;
    }
    for (unsigned bits = mask; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        std::memcpy(buffer + offset(lane), word_bytes + 4 * lane, 4);
    }
}

// The stencil and depth tests lane by lane, as stencil_depth_test() runs
// them, recording each lane's stored values before its test, for the probe.
rt::LaneMask FragmentStage::stencil_depth_probed(const LanePixels& px, rt::LaneMask alive, ProbeTests& tests) {
    rt::LaneMask passed = 0;
    for (rt::LaneMask bits = alive; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        size_t pixel = size_t(lane_y_[size_t(lane)]) * size_t(fb_.width) + size_t(lane_x_[size_t(lane)]);
        tests.stored_depth[size_t(lane)] = fb_.depth[pixel];
        tests.stored_stencil[size_t(lane)] = fb_.stencil[pixel];
        rt::LaneMask one = rt::LaneMask(1) << lane, stencil_failed = 0;
        passed |= stencil_depth_test(ops_, fb_, px, one, &stencil_failed);
        tests.stencil_failed |= stencil_failed;
        if (!(passed & one) && !stencil_failed) tests.depth_failed |= one;
    }
    return passed;
}

// The general path; returns the lanes written. `tests`: with a probe.
rt::LaneMask FragmentStage::write_with_ops(rt::LaneMask alive, const Lanes& z, ProbeTests* tests) {
    std::array<Lanes, 4> rgba{};
    rt::LaneMask back = 0;
    for (int q = 0; q < quads_; ++q)
        if (!quad_prim_[size_t(q)]->front) back |= rt::LaneMask(0xF) << (q * 4);
    LanePixels px{lane_x_.data(), lane_y_.data(), z.data(), back};
    if (ops_.alpha_test) {
        // The alpha of colour 0 (GL 2.1 §4.1.4); none written: alpha 0.
        if (color_out_[0]) load_color(0, rgba);
        rt::LaneMask tested = alive;
        alive = alpha_test(ops_, rgba[3], alive, tests ? &tests->alpha : nullptr);
        if (tests) tests->alpha_failed |= tested & ~alive;
    }
    if ((ops_.stencil_test || ops_.depth_test) && !early_depth_)
        alive = tests ? stencil_depth_probed(px, alive, *tests) : stencil_depth_test(ops_, fb_, px, alive);
    written_ += uint64_t(std::popcount(alive));
    for (int b = 0; b < ops_.draw_buffers && alive; ++b) {
        if (!color_out_[size_t(b)]) continue;
        load_color(b, rgba);
        write_color(ops_, fb_, b, px, rgba, alive);
    }
    return alive;
}

}  // namespace glslrun::raster
