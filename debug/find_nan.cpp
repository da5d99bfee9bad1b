// --find-nan: every invocation of the render replayed on the traced
// interpreter with a NanWatch, until one computes a NaN or an infinity.
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>

#include "debug/debugger.h"
#include "debug/recorder.h"
#include "raster/fragments.h"
#include "raster/probe.h"
#include "runtime/execute.h"
#include "runtime/program_state.h"
#include "glslrun/scene/render.h"

namespace glslrun::debug {
namespace {

// Every pass's draws, in draw order; a pass's own program is replayed on its
// debugging twin (PassProbe).
class NanProbe final : public PassProbe {
public:
    explicit NanProbe(bool colour_range) : colour_range_(colour_range) {}

    void begin_draw(const raster::ProbeDraw& d) override {
        enter_draw(d);
        ++draw_;
        uniforms_ = state_of(*current().program).uniforms;
        gl_ = d.gl;
        if (!report.nan && !stopped && !failed) check_vertices(d);
    }

    void before_run(const raster::ProbeBatch& b) override {
        if (report.nan || stopped || failed) return;
        const Program &program = *current().program, &debug = *current().debug;
        const ir::Shader& fs = state_of(debug).ir.fragment;
        ShaderNames names(fs, state_of(debug).ir);
        NanWatch watch(names);
        rt::TracedInterpreter in(fs, uniforms_.data(), rt::RunLimits(debug.exec), gl_.texture_units.data(),
                                 debug.exec.precision, ~0u, watch);
        const ir::Shader& rendered = state_of(program).ir.fragment;
        for (const ir::Binding& to : fs.inputs)
            for (const ir::Binding& from : rendered.inputs)
                if (from.name == to.name)
                    for (uint32_t k = 0; k < to.count && k < from.count; ++k)
                        std::memcpy(in.lanes(to.first + k), b.interp.lanes(from.first + k), rt::kLanes * 4);
        rt::RunError error;
        if (!in.run(b.lanes == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << b.lanes) - 1, &error))
            stopped = exec::run_error(state_of(debug), ir::Stage::Fragment, error);
        if (rt::LaneMask hit = watch.found & b.covered) {
            int lane = std::countr_zero(hit);
            report.nan = fragment_finding(b, lane, std::move(*watch.first[size_t(lane)]));
        }
    }

    void after_write(const raster::ProbeBatch& b, rt::LaneMask alive, rt::LaneMask,
                     const raster::ProbeTests&) override {
        // Colours of the image, not of a render target.
        if (!colour_range_ || report.out_of_range || !current().to_output) return;
        const ir::Shader& fs = state_of(*current().program).ir.fragment;
        for (const ir::Binding& out : fs.outputs) {
            if (out.name != "gl_FragColor" && !out.name.starts_with("gl_FragData")) continue;
            for (rt::LaneMask bits = alive; bits; bits &= bits - 1) {
                int lane = std::countr_zero(bits);
                NanEvent e{"", out.name, {}, {ir::Kind::F32, false, {}}, out.name};
                bool outside = false;
                for (uint32_t k = 0; k < out.count; ++k) {
                    float v = std::bit_cast<float>(b.interp.lanes(out.first + k)[lane]);
                    e.result.c.push_back(v);
                    outside = outside || !(v >= 0.0f && v <= 1.0f);
                }
                if (outside) {
                    report.out_of_range = fragment_finding(b, lane, std::move(e));
                    return;
                }
            }
        }
    }

    NanReport report;
    // A traced run that ran out of a limit of debug.exec, or was cancelled:
    // the invocations after it were not looked at.
    std::optional<Error> stopped;

private:
    NanFinding fragment_finding(const raster::ProbeBatch& b, int lane, NanEvent e) const {
        NanFinding f;
        f.draw = draw_;
        f.primitive = b.quad_prim[lane / 4]->primitive;
        f.pass = current().name;
        f.in_target = !current().to_output;
        f.x = b.x[size_t(lane)];
        f.y = current().height - 1 - b.y[size_t(lane)];
        f.event = std::move(e);
        return f;
    }

    // The draw's vertices in batches, as the render shades them.
    void check_vertices(const raster::ProbeDraw& d) {
        const Program& debug = *current().debug;
        const ir::Shader& vs = state_of(debug).ir.vertex;
        ShaderNames names(vs, state_of(debug).ir);
        for (uint32_t base = 0; base < d.vertex_count && !report.nan && !stopped; base += rt::kLanes) {
            NanWatch watch(names);
            rt::TracedInterpreter in(vs, uniforms_.data(), rt::RunLimits(debug.exec), gl_.texture_units.data(),
                                     debug.exec.precision, ~0u, watch);
            int n = int(std::min<uint32_t>(rt::kLanes, d.vertex_count - base));
            for (int lane = 0; lane < n; ++lane) {
                auto words = exec::vertex_input_words(vs, d.attribs, d.vertex_count, d.gl, base + uint32_t(lane));
                if (!words) return;
                for (size_t i = 0; i < vs.inputs.size(); ++i)
                    for (uint32_t k = 0; k < vs.inputs[i].count; ++k)
                        in.lanes(vs.inputs[i].first + k)[lane] = (*words)[i][k];
            }
            rt::RunError error;
            if (!in.run(n == 64 ? ~rt::LaneMask(0) : (rt::LaneMask(1) << n) - 1, &error))
                stopped = exec::run_error(state_of(debug), ir::Stage::Vertex, error);
            if (watch.found) {
                int lane = std::countr_zero(watch.found);
                NanFinding f;
                f.vertex = true;
                f.draw = draw_;
                f.pass = current().name;
                f.vertex_index = base + uint32_t(lane);
                f.event = std::move(*watch.first[size_t(lane)]);
                report.nan = std::move(f);
            }
        }
    }

    bool colour_range_;
    uint32_t draw_ = ~0u;
    std::vector<uint32_t> uniforms_;
    GLState gl_;
};

}  // namespace

Result<NanReport> find_nan(Program& program, const Program& debug, const scene::Scene& scene, Framebuffer& fb,
                           bool colour_range) {
    NanProbe probe(colour_range);
    if (Status st = render_with_probe(program, debug, "", scene, fb, probe); !st) return st.error();
    if (probe.stopped && !probe.report.nan) return *probe.stopped;
    auto in_stage = [](const std::optional<NanFinding>& f, const GeneratedStage& g) {
        return f && f->event.where.starts_with(g.name + ":");
    };
    for (const GeneratedStage& g : probe.generated)
        if (in_stage(probe.report.nan, g) || in_stage(probe.report.out_of_range, g))
            probe.report.generated.push_back(g);
    return std::move(probe.report);
}

}  // namespace glslrun::debug
