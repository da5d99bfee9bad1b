// The plugin's one exported symbol (runtime/jit_plugin.h): the host finds
// the JIT's entry points through it, and only if both were built together.
#include <cstring>

#include "raster/fused/pipeline.h"
#include "runtime/jit/jit.h"
#include "runtime/jit_plugin.h"

extern "C" __attribute__((visibility("default"))) const glslrun::rt::JitEntryPoints* glslrun_jit_entry_points(
    const char* build_key) {
    static const glslrun::rt::JitEntryPoints points{&glslrun::rt::jit::compile, &glslrun::raster::fused::compile};
    return build_key && std::strcmp(build_key, GLSLRUN_JIT_BUILD_KEY) == 0 ? &points : nullptr;
}
