// The batched sampler's one-pass 3D lookups (sampling_direct3d.cpp): a
// colour 3D texture of one image with one filter (no mipmaps; the min and
// mag filters both NEAREST or both LINEAR within the level) whose wraps
// keep every texel in the image (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE,
// and CLAMP under NEAREST), eight lanes at a time under AVX2 from the
// coordinates to the result in registers, one kernel per texture state.
// Every value comes from the operations of sampling_rules.h in the same
// order, so the bits are sample_complete_lane()'s;
// tests/runtime/sampling_batch_test.cpp compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// Whether sample_direct3d() takes lookups of this (complete) texture.
bool direct3d_samples(const Texture& texture);

// The kernel of a texture that direct3d_samples() takes, else null. Only
// for a CPU with AVX2 (cpu_has_avx2()).
BatchKernel direct3d_kernel(const Texture& texture);

// sample_batch()'s result for the lanes of `lanes` of a texture that
// direct3d_samples() takes, into out[c][i]; the other lanes' entries are
// left as they are. Only for a CPU with AVX2 (cpu_has_avx2()).
void sample_direct3d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

}  // namespace glslrun::rt
