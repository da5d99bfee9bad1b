// Program::State: what a compiled Program owns. Shared by runtime/program.cpp,
// runtime/gl_state.cpp, runtime/execute.cpp and raster/draw.cpp.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "ir/ir.h"

namespace glslrun {
namespace raster { struct DrawScratch; }
namespace rt { class BackendCache; }

struct Program::State {
    ir::Program ir;
    std::vector<uint32_t> uniforms;  // ir.uniform_words words, GL default 0
    std::string vertex_name, fragment_name;  // first source of each stage, for run-time errors
    // draw()'s working memory, reused by the next draw (raster/scratch.h);
    // made at the first draw. shared_ptr: its deleter works with the type
    // incomplete here.
    std::shared_ptr<raster::DrawScratch> draw_scratch;
    // rt::FastOps bits: the op classes Precision::Fast approximates. All of
    // them, except in the error report's ablation (tools/scene/error_report.cpp).
    uint32_t fast_ops = ~0u;
    // The shaders compiled by the backends (runtime/backend_cache.h), made
    // with the State; shared_ptr for the same reason as draw_scratch.
    std::shared_ptr<rt::BackendCache> backends;
};

}  // namespace glslrun
