// The batched sampler's depth comparisons of a shadow map (sampler2DShadow:
// shadow2D, shadow2DProj, one lookup or each tap of a PCF kernel), eight
// lanes at a time under AVX2 from the coordinates to the result in
// registers: a 2D depth texture with the comparison on, one image and one
// filter (no level-of-detail decision), wraps that keep every texel in the
// image (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE; CLAMP under NEAREST). Every value
// comes from the operations of sampling_rules.h in the same order, so the
// bits are sample_complete_lane()'s; tests/runtime/sampling_batch_test.cpp
// compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// The kernel of a complete texture that these lookups take, else null;
// it reads the lookups' `ref`. Only for a CPU with AVX2 (cpu_has_avx2()).
BatchKernel shadow8_kernel(const Texture& texture);

// Whether sample_shadow8() takes these lookups of this (complete) texture.
bool shadow8_samples(const Texture& texture, const BatchLookup& lookup);

// sample_batch()'s result for the lanes of `lanes`, into out[c][i]; the
// other lanes' entries are left as they are. Only where shadow8_samples()
// and cpu_has_avx2().
void sample_shadow8(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

}  // namespace glslrun::rt
