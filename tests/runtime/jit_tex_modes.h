// The precision modes of the JIT's lookup tests (jit_tex_direct_test.cpp,
// jit_tex_kinds_test.cpp): Precise; Fast without its GPU filtering (the
// error report's ablation), which takes Precise's samplers; Fast, whose
// filtered textures take the GPU's rules.
#pragma once
#include <cstdint>

#include "runtime/backend.h"

namespace glslrun::test {

struct TexMode {
    Precision precision;
    uint32_t fast_ops;
    // Whether Fast's GPU filtering samples the textures it takes.
    bool gpu() const { return precision == Precision::Fast && (fast_ops & rt::kFastTexture); }
};

inline constexpr TexMode kTexModes[] = {{Precision::Precise, rt::kAllFastOps},
                                        {Precision::Fast, rt::kAllFastOps & ~uint32_t(rt::kFastTexture)},
                                        {Precision::Fast, rt::kAllFastOps}};

}  // namespace glslrun::test
