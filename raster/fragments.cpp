#include "raster/fragments.h"

#include <algorithm>
#include <chrono>

#include "raster/framebuffer.h"
#include "runtime/execute.h"

namespace glslrun::raster {

struct FragmentStage::InputPlan {
    enum class Source { Varying, FragCoord, FrontFacing, PointCoord, Zero } source = Source::Zero;
    const ir::Binding* binding = nullptr;
    uint32_t attr_offset = 0;  // Varying: where in the attribute vector
};

namespace {

const ir::Binding* find_binding(const std::vector<ir::Binding>& list, std::initializer_list<const char*> names) {
    for (const char* name : names)
        for (const ir::Binding& b : list)
            if (b.name == name) return &b;
    return nullptr;
}

}  // namespace

FragmentStage::FragmentStage(const Program& program, const GLState& gl, Framebuffer& fb, DrawStats& stats)
    : program_(program), gl_(gl), fb_(fb), stats_(stats) {
    const Program::State& st = program.state();
    const ir::Shader& fs = st.ir.fragment;
    interp_ = std::make_unique<rt::Interpreter>(fs, st.uniforms.data(), program.exec.max_loop_iterations,
                                                gl.texture_units.data());
    for (size_t i = 0; i < fs.inputs.size(); ++i) {
        const ir::Binding& b = fs.inputs[i];
        InputPlan plan{InputPlan::Source::Zero, &b, 0};
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
    color_out_ = find_binding(fs.outputs, {"gl_FragColor", "gl_FragData[0]", "gl_FragData"});
    depth_out_ = find_binding(fs.outputs, {"gl_FragDepth"});
}

FragmentStage::~FragmentStage() = default;

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

void FragmentStage::fill_lane(const FsPrimitive& prim, int lane, int x, int y, const glm::dvec3& l) {
    double inv_w = 0, z = 0;
    for (int i = 0; i < prim.count; ++i) {
        inv_w += l[i] * prim.v[i].inv_w;
        z += l[i] * prim.v[i].z;
    }
    double persp[3] = {0, 0, 0};
    for (int i = 0; i < prim.count; ++i) persp[i] = inv_w != 0 ? l[i] * prim.v[i].inv_w / inv_w : l[i];
    lane_x_[lane] = x;
    lane_y_[lane] = y;
    lane_z_[lane] = float(std::clamp(z, 0.0, 1.0));
    rt::Interpreter& in = *interp_;
    for (const InputPlan& p : inputs_) {
        const ir::Binding& b = *p.binding;
        for (uint32_t c = 0; c < b.count; ++c) {
            float value = 0;
            switch (p.source) {
            case InputPlan::Source::Varying: {
                double sum = 0;
                for (int i = 0; i < prim.count; ++i) sum += persp[i] * prim.v[i].attrs[p.attr_offset + c];
                value = float(sum);
                break;
            }
            case InputPlan::Source::FragCoord: {
                const float coord[4] = {float(x) + 0.5f, float(y) + 0.5f, float(z), float(inv_w)};
                value = c < 4 ? coord[c] : 0.0f;
                break;
            }
            case InputPlan::Source::FrontFacing: value = prim.front ? 1.0f : 0.0f; break;
            case InputPlan::Source::PointCoord: {
                if (prim.count != 1) break;
                float s = 0.5f + (float(x) + 0.5f - prim.point_center.x) / prim.point_size;
                float t = 0.5f - (float(y) + 0.5f - prim.point_center.y) / prim.point_size;
                value = c == 0 ? s : t;
                break;
            }
            case InputPlan::Source::Zero: break;
            }
            exec::set_lane(in, b.kind, b.first + c, lane, value);
        }
    }
}

void FragmentStage::add_quad(const FsPrimitive& prim, int x, int y, unsigned mask,
                             const std::array<glm::dvec3, 4>& weights) {
    if (error_) return;
    int base = quads_ * 4;
    for (int i = 0; i < 4; ++i) {
        fill_lane(prim, base + i, x + kQuadDx[i], y + kQuadDy[i], weights[i]);
        if ((mask >> i) & 1u) covered_ |= rt::LaneMask(1) << (base + i);
    }
    if (++quads_ == rt::kLanes / 4) flush();
}

void FragmentStage::flush() {
    if (quads_ == 0) return;
    int lanes = quads_ * 4;
    rt::LaneMask live = lanes == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << lanes) - 1;
    rt::RunError run_error;
    rt::Interpreter& in = *interp_;
    auto start = std::chrono::steady_clock::now();
    bool ok = in.run(live, &run_error);
    stats_.fragment_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    quads_ = 0;
    rt::LaneMask covered = covered_;
    covered_ = 0;
    if (!ok) {
        error_ = exec::run_error(program_.state(), ir::Stage::Fragment, run_error);
        return;
    }
    rt::LaneMask alive = in.alive() & covered;
    for (int lane = 0; lane < lanes; ++lane) {
        if (!((covered >> lane) & 1u)) continue;
        ++stats_.fragments_shaded;
        if (!((alive >> lane) & 1u)) continue;
        int x = lane_x_[lane], y = lane_y_[lane];
        size_t pixel = size_t(y) * fb_.width + x;
        if (gl_.depth_test) {
            float z = lane_z_[lane];
            if (depth_out_) {
                float written = exec::lane_as_float(in, depth_out_->kind, depth_out_->first, lane);
                z = written > 0.0f ? std::min(written, 1.0f) : 0.0f;  // NaN -> 0
            }
            if (!depth_passes(gl_.depth_func, z, fb_.depth[pixel])) continue;
            fb_.depth[pixel] = z;
        }
        ++stats_.fragments_written;
        if (!color_out_) continue;
        glm::vec4 c(0.0f);
        for (uint32_t k = 0; k < std::min<uint32_t>(4, color_out_->count); ++k)
            c[int(k)] = exec::lane_as_float(in, color_out_->kind, color_out_->first + k, lane);
        write_color(fb_, x, y, c);
    }
}

Status FragmentStage::finish() {
    flush();
    if (error_) return *error_;
    return Ok{};
}

}  // namespace glslrun::raster
