// check_undefined(): the scene rendered with the programs compiled with
// check_undef instructions (ir/undefined.h), on one thread, with an
// observer that is both the draws' probe (raster/probe.h: which pass, draw
// and pixels a fragment batch holds) and the checks' sink
// (runtime/undef_sink.h: which lanes computed an undefined operation).
#include "glslrun/scene/undefined.h"

#include <algorithm>
#include <bit>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "glslrun/scene/render.h"
#include "ir/undefined.h"
#include "raster/fragments.h"
#include "raster/probe.h"
#include "runtime/program_state.h"
#include "runtime/undef_sink.h"
#include "scene/undefined_values.h"

namespace glslrun::scene {
namespace {

struct PassInfo {
    Program* program = nullptr;
    std::string name, program_name;
    bool to_output = true;
    int height = 0;  // of the framebuffer it draws into
};

// One site's findings so far.
struct Tally {
    uint64_t count = 0;
    UndefinedInvocation first;
    // The batch whose lanes were last counted: a vec3 operation checks each
    // component, and each invocation counts once per batch.
    uint64_t batch = ~0ull;
    rt::LaneMask counted = 0;
};

class UndefProbe final : public raster::DrawProbe, public rt::UndefSink {
public:
    std::vector<PassInfo> passes;
    size_t pass = 0;
    uint32_t draws = 0;  // begin_draw calls so far
    // By (program, vertex stage, site).
    std::map<std::tuple<const Program*, bool, uint32_t>, Tally> tallies;

    void begin_draw(const raster::ProbeDraw&) override { ++draws; }

    void before_run(const raster::ProbeBatch& b) override {
        ++batch_;
        vertex_ = false;
        fragments_ = &b;
    }
    void after_write(const raster::ProbeBatch&, rt::LaneMask, rt::LaneMask, const raster::ProbeTests&) override {
        fragments_ = nullptr;
    }

    void vertex_batch(uint32_t first) override {
        ++batch_;
        vertex_ = true;
        first_vertex_ = first;
        fragments_ = nullptr;
    }

    void undefined(uint32_t site, uint64_t lanes, const double* a, const double* b, const double* c) override {
        if (!vertex_ && !fragments_) return;  // not within a batch: nothing to attribute it to
        if (!vertex_) lanes &= fragments_->covered;  // helper lanes are no invocation
        Tally& t = tallies[{passes[pass].program, vertex_, site}];
        if (t.batch != batch_) t.counted = 0;
        t.batch = batch_;
        const rt::LaneMask fresh = lanes & ~t.counted;
        if (!fresh) return;
        if (t.count == 0) t.first = invocation(std::countr_zero(fresh), site, a, b, c);
        t.count += uint64_t(std::popcount(fresh));
        t.counted |= fresh;
    }

private:
    UndefinedInvocation invocation(int lane, uint32_t site, const double* a, const double* b, const double* c) const {
        const PassInfo& p = passes[pass];
        UndefinedInvocation inv;
        inv.vertex = vertex_;
        inv.draw = vertex_ ? draws : draws - 1;  // begin_draw comes after the draw's vertices
        inv.pass = p.name;
        inv.program = p.program_name;
        inv.in_target = !p.to_output;
        if (vertex_) {
            inv.vertex_index = first_vertex_ + uint32_t(lane);
        } else {
            inv.x = fragments_->x[size_t(lane)];
            inv.y = p.height - 1 - fragments_->y[size_t(lane)];
        }
        const ir::Shader& shader = vertex_ ? state_of(*p.program).ir.vertex : state_of(*p.program).ir.fragment;
        const int n = ir::undef_info(ir::UndefOp(shader.undef_sites[site].op)).operands;
        const double* values[] = {a, b, c};
        for (int k = 0; k < n; ++k) inv.operands.push_back(values[k][lane]);
        return inv;
    }

    uint64_t batch_ = 0;
    bool vertex_ = false;
    uint32_t first_vertex_ = 0;
    const raster::ProbeBatch* fragments_ = nullptr;
};

std::string sources_name(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment) {
    std::string name;
    for (const auto* list : {&vertex, &fragment})
        for (const ShaderSource& s : *list) name += (name.empty() ? "" : " + ") + s.name;
    return name.empty() ? "(fixed function)" : name;
}

// Line `line` (from 1) of the source named `file`, trimmed.
std::string line_text(const std::vector<const std::vector<ShaderSource>*>& lists, const std::string& file, int line) {
    for (const auto* list : lists)
        for (const ShaderSource& s : *list) {
            if (s.name != file) continue;
            size_t at = 0;
            for (int l = 1; l < line && at != std::string::npos; ++l) {
                at = s.text.find('\n', at);
                if (at != std::string::npos) ++at;
            }
            if (at == std::string::npos) return {};
            std::string text = s.text.substr(at, s.text.find('\n', at) - at);
            const size_t first = text.find_first_not_of(" \t\r"), last = text.find_last_not_of(" \t\r");
            return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
        }
    return {};
}

UndefinedReport build_report(const UndefProbe& probe, const std::vector<const std::vector<ShaderSource>*>& lists) {
    UndefinedReport report;
    report.draws = probe.draws;
    for (const auto& [key, tally] : probe.tallies) {
        const auto& [program, vertex, site_index] = key;
        const ir::Shader& shader = vertex ? state_of(*program).ir.vertex : state_of(*program).ir.fragment;
        const ir::UndefSite& site = shader.undef_sites[site_index];
        const auto op = ir::UndefOp(site.op);
        UndefinedFinding f;
        f.op = ir::undef_info(op).name;
        f.condition = ir::undef_info(op).condition;
        f.vertex = vertex;
        f.file = site.loc.source < shader.sources.size() ? shader.sources[site.loc.source] : "";
        f.line = site.loc.line;
        f.column = site.loc.column;
        f.line_text = line_text(lists, f.file, f.line);
        f.count = tally.count;
        f.first = tally.first;
        describe_values(op, site.length, f);
        report.findings.push_back(std::move(f));
    }
    // One finding per source position and op: a site inlined or written
    // twice (two programs sharing a file) adds up.
    std::stable_sort(report.findings.begin(), report.findings.end(), [](const auto& a, const auto& b) {
        return std::tie(a.file, a.line, a.column, a.op, a.vertex) < std::tie(b.file, b.line, b.column, b.op, b.vertex);
    });
    std::vector<UndefinedFinding> merged;
    for (UndefinedFinding& f : report.findings) {
        if (!merged.empty()) {
            UndefinedFinding& m = merged.back();
            if (std::tie(m.file, m.line, m.column, m.op, m.vertex) == std::tie(f.file, f.line, f.column, f.op, f.vertex)) {
                const bool earlier = std::tie(f.first.draw) < std::tie(m.first.draw);
                const uint64_t count = m.count + f.count;
                if (earlier) m = std::move(f);
                m.count = count;
                continue;
            }
        }
        merged.push_back(std::move(f));
    }
    report.findings = std::move(merged);
    return report;
}

// The probe on every pass's program, as the shader debugger attaches its own.
void attach(UndefProbe& probe, ScenePrograms& programs, const Scene& scene, int height,
            const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment) {
    for (size_t i = 0; i < programs.size(); ++i) {
        PassInfo p{&programs.of_pass(i), "", sources_name(vertex, fragment), true, height};
        if (!scene.passes.empty()) {
            const Pass& pass = scene.passes[i];
            p.name = pass.name;
            p.to_output = pass.target < 0;
            if (pass.target >= 0) p.height = scene.targets[size_t(pass.target)].height;
            if (!pass.vertex.empty() || !pass.fragment.empty()) p.program_name = sources_name(pass.vertex, pass.fragment);
        }
        state_of(*p.program).probe = &probe;
        state_of(*p.program).undef = &probe;
        probe.passes.push_back(std::move(p));
    }
    programs.before_pass = [&probe](size_t pass) { probe.pass = pass; };
}

}  // namespace

Result<UndefinedReport> check_undefined(const std::vector<ShaderSource>& vertex,
                                        const std::vector<ShaderSource>& fragment, const Scene& scene,
                                        const ExecOptions& exec, Framebuffer& fb, CompileOptions options) {
    options.check_undefined = true;
    auto main = Program::compile(vertex, fragment, options);
    if (!main) return main.error();
    main->exec = exec;
    main->exec.threads = 1;  // one fragment stage, in tile order (the passes' programs copy it)
    auto programs = ScenePrograms::compile(*main, scene, options);
    if (!programs) return programs.error();
    UndefProbe probe;
    attach(probe, *programs, scene, fb.height, vertex, fragment);
    auto stats = render_scene(*programs, scene, fb);
    for (size_t i = 0; i < programs->size(); ++i) {
        state_of(programs->of_pass(i)).probe = nullptr;
        state_of(programs->of_pass(i)).undef = nullptr;
    }
    if (!stats) return stats.error();
    std::vector<const std::vector<ShaderSource>*> lists{&vertex, &fragment};
    for (const Pass& pass : scene.passes) {
        lists.push_back(&pass.vertex);
        lists.push_back(&pass.fragment);
    }
    UndefinedReport report = build_report(probe, lists);
    report.warnings = programs->warnings();
    return report;
}

Result<UndefinedReport> check_undefined(const std::vector<ShaderSource>& vertex,
                                        const std::vector<ShaderSource>& fragment, const Scene& scene,
                                        const ExecOptions& exec, CompileOptions compile) {
    auto fb = Framebuffer::create(scene.width, scene.height, false, color_buffers(scene));
    if (!fb) return fb.error();
    return check_undefined(vertex, fragment, scene, exec, *fb, std::move(compile));
}

}  // namespace glslrun::scene
