// The batched sampler's mipmapped 2D lookups (sampling_mip2d.cpp): a
// colour 2D texture with mipmaps whose filter within a level is the same on
// both sides of §3.8.9 (LINEAR_MIPMAP_* with LINEAR magnification, or
// NEAREST_MIPMAP_* with NEAREST), any wrap, eight lanes at a time under
// AVX2 from the coordinates and derivatives to the result: the level of
// detail, the levels, each level's indices and blends and the mix of the
// two levels in registers, one kernel per texture state. Every value comes
// from the operations of sampling_rules.h in the same order, so the bits
// are sample_complete_lane()'s; tests/runtime/sampling_batch_test.cpp compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// Whether sample_mip2d() takes lookups of this (complete) texture.
bool mip2d_samples(const Texture& texture);

// sample_batch()'s result for the lanes of `lanes` of a texture that
// mip2d_samples() takes, into out[c][i]; the other lanes' entries are left
// as they are. Only for a CPU with AVX2 (cpu_has_avx2()).
void sample_mip2d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

}  // namespace glslrun::rt
