// Which vector ISA the CPU offers beyond AVX2 (runtime/interp_kernels.h's
// cpu_has_avx2()), for the code that picks a variant at run time.
#pragma once
#include <cstdlib>

namespace glslrun::rt {

// AVX-512 F, BW, DQ and VL, unless GLSLRUN_NO_AVX512=1: the JIT's 512-bit
// code (runtime/jit/engine.h) and the rasterizer's block coverage
// (raster/triangle.cpp). Either way the same bits.
inline bool cpu_has_avx512() {
#if defined(__x86_64__) && defined(__GNUC__)
    static const bool on = [] {
        const char* off = std::getenv("GLSLRUN_NO_AVX512");
        if (off && off[0] == '1') return false;
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
               __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
    }();
    return on;
#else
    return false;
#endif
}

}  // namespace glslrun::rt
