// Program::State: what a compiled Program owns, and state_of(), the way in for
// glslrun's own code (the runtime, the rasterizer, the scene library's error
// report, the tools, tests and benchmarks). Not a public header.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"

namespace glslrun {
namespace raster { class DrawProbe; }
namespace rt { class BackendCache; class UndefSink; }
namespace raster::fused { class Cache; }

struct Program::State {
    ir::Program ir;
    std::vector<uint32_t> uniforms;  // ir.uniform_words words, GL default 0
    std::string vertex_name, fragment_name;  // first source of each stage, for run-time errors
    // A program compiled without one of its stages keeps its sources: the
    // scene library links them again with the fixed-function stage it
    // generates from each draw's GL state (scene/ffp_*.cpp). Empty for a
    // program of both stages, except one linked with a generated stage
    // (named ffp::kVertexStageName...): the shader debugger's twin reads them.
    std::vector<ShaderSource> vertex_sources, fragment_sources;
    // The options it was compiled with: the programs a scene's passes name,
    // the generated fixed-function stages' links and the debugger's twins
    // compile with the same -D and -I.
    CompileOptions options;
    // draw()'s working memory, reused by the next draw: a raster::DrawScratch
    // (raster/scratch.h) made at the first draw. The runtime does not know the
    // rasterizer's types; shared_ptr<void> still deletes it as what it is.
    std::shared_ptr<void> draw_scratch;
    // rt::FastOps bits: the op classes Precision::Fast approximates. All of
    // them, except in the error report's ablation (scene/error_report.cpp).
    uint32_t fast_ops = ~0u;
    // Set while a draw or set_uniform runs (ProgramUse).
    std::atomic<bool> busy{false};
    // Draws and uniform updates so far (ProgramUse): tells one draw's
    // executors from the next draw's (the specialization policy).
    uint64_t uses = 0;
    // The shader debugger's observer of draws (raster/probe.h); null when not debugging.
    raster::DrawProbe* probe = nullptr;
    // Where check_undef instructions report (runtime/undef_sink.h); null when
    // not checking (the program then has none).
    rt::UndefSink* undef = nullptr;
    // The shaders compiled by the backends (runtime/backend_cache.h), made
    // with the State; shared_ptr for the same reason as draw_scratch.
    std::shared_ptr<rt::BackendCache> backends;
    // The fused fragment pipelines (raster/fused/pipeline.h), by draw state.
    std::shared_ptr<raster::fused::Cache> pipelines;
};

inline Program::State& state_of(Program& program) { return *program.state_; }
inline const Program::State& state_of(const Program& program) { return *program.state_; }

// Claims a Program for one draw or uniform update. A moved-from Program, or
// one that another thread is using, gives an Error instead of a data race.
class ProgramUse {
public:
    explicit ProgramUse(Program& program);
    ~ProgramUse();
    ProgramUse(const ProgramUse&) = delete;
    ProgramUse& operator=(const ProgramUse&) = delete;
    const Status& status() const { return status_; }
private:
    Program::State* claimed_ = nullptr;
    Status status_ = Ok{};
};
// The Error for a moved-from Program (the calls that only read it).
Status check_valid(const Program& program);

}  // namespace glslrun
