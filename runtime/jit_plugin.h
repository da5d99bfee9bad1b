// The JIT lives in a plugin, libglslrun-jit.so, loaded at the first compile
// that needs it: LLVM is a 100 MB library whose loading (about 400,000
// relocations and its static constructors) cost every process 14 ms of CPU
// before it drew anything, half the README demo's time, even when
// `--backend auto` then ran the interpreter alone. Only the JIT's three entry
// points cross this seam (a shader's code, a fused pipeline's); the plan (how much a compile would cost) is the
// host's own (runtime/jit_plan.cpp), so Auto decides without loading LLVM.
//
// Where the plugin is looked for, in order, from the directory D of the
// binary that holds this code (the glslrun command, libglslrun.so, the
// Python module or a program linked with libglslrun.a): D itself (the build
// tree, a Python wheel), D/glslrun (beside an installed libglslrun.so),
// D/<bin to lib>/glslrun (an installed command, relocatable), then the
// install's and the build tree's absolute paths. A plugin from another build
// is refused (its build key differs) and the next one is tried; with none,
// the interpreter runs instead: the same bits, more slowly. GLSLRUN_JIT_PLUGIN names a file to use instead.
#pragma once
#include <atomic>
#include <memory>
#include <string>

#include "runtime/backend.h"

namespace glslrun::raster::fused {
struct Pipeline;
struct PipelineCompile;
struct State;
}  // namespace glslrun::raster::fused

namespace glslrun::rt {

namespace jit {
struct CompileStats;
}

struct JitEntryPoints {
    // runtime/jit/jit.h's compile and raster/fused/pipeline.h's.
    std::unique_ptr<CompiledShader> (*compile)(const ir::Shader& shader, Precision precision, uint32_t fast_ops,
                                               bool avx2, bool quick_codegen, jit::CompileStats* stats);
    std::unique_ptr<raster::fused::Pipeline> (*compile_pipeline)(const raster::fused::State& state,
                                                                 raster::fused::PipelineCompile* compile);
};

// The plugin's entry points, loaded at the first call (thread-safe; the
// plugin is never unloaded: its code outlives every program). Null where
// glslrun was built without the JIT, or the plugin is missing or refused
// (jit_plugin_error() says why).
const JitEntryPoints* jit_plugin();
std::string jit_plugin_error();
// Whether a plugin file is there, without loading it: what Backend::Auto
// needs to know before its first draw.
bool jit_plugin_present();
// Whether the plugin is loaded already (by a compile, or jit_available()),
// without loading it: Backend::Auto asks the code cache at a stage's first
// draw only then, since loading LLVM (14 ms of CPU) costs a short render
// more than interpreting it.
bool jit_plugin_loaded();

}  // namespace glslrun::rt

// The plugin's one exported symbol: its entry points, or null where
// `build_key` (GLSLRUN_JIT_BUILD_KEY, the host's) is not its own.
extern "C" const glslrun::rt::JitEntryPoints* glslrun_jit_entry_points(const char* build_key);
