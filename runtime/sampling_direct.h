// The batched sampler's one-pass lookups (sampling_direct.cpp): a colour
// texture of one image with one filter, 2D or rectangle, NEAREST or LINEAR,
// any wrap mode, eight lanes at a time under AVX2 from the coordinates to
// the result, with the coordinates, indices and weights in registers and
// no lane array between the steps. The kernel is chosen once per lookup
// from the texture's state (the filter and each axis's wrap rule are
// template arguments). Every value comes from the operations of
// runtime/sampling_rules.h in the same order, so the bits are
// sample_complete_lane()'s; tests/runtime/sampling_batch_test.cpp compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// Whether sample_direct() takes lookups of this (complete) texture: a 2D
// texture or rectangle, colour (not depth), whose every lookup reads one
// image with one filter (no mipmaps; the min and mag filters both NEAREST
// or both LINEAR within the level).
bool direct_samples(const Texture& texture);

// sample_batch()'s result for the lanes of `lanes` of a texture that
// direct_samples() takes, into out[c][i]; the other lanes' entries are
// left as they are. Only for a CPU with AVX2 (cpu_has_avx2()).
void sample_direct(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

// A texture that direct_samples() takes, its kernel chosen once for many
// lookups: the JIT's generated `tex` code calls `run` through this record
// (runtime/jit/tex_direct.cpp) with no operand block and no selection per
// lookup. The texture must stay alive and unchanged while it is used.
struct DirectSampler {
    // sample_direct()'s results for the lanes of `lanes` at (s[i], t[i]).
    using Run = void (*)(const DirectSampler& self, const float* s, const float* t, LaneMask lanes,
                         float (*out)[kLanes]);
    Run run = nullptr;      // null: not a texture of sample_direct(), or no AVX2
    void (*kernel)() = nullptr;  // the state's kernel (sampling_direct.cpp's type)
    const void* texels = nullptr;
    int width = 0, height = 0;
    float border[4] = {};
    bool finite = false;  // every texel finite (RGBA8): no NaN to canonicalise
};

// `texture` (null, incomplete or any other: `run` is then null) bound for DirectSampler::run.
DirectSampler bind_direct(const Texture* texture);

}  // namespace glslrun::rt
