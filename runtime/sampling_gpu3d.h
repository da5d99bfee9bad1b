// Fast's batched 3D lookups (sampling_gpu3d.cpp): NVIDIA's trilinear rule
// (sampling_gpu.h's linear_sum(): the planes z0 and z1 weigh 256 - wz and
// wz, each split among its 2x2 texels by level_weights(), one sum of the
// eight 16-bit texels rounded once) for an RGBA8 3D texture of one image
// with one filter (no mipmaps; the min and mag filters both NEAREST or both
// LINEAR within the level) whose wraps keep every texel in the image
// (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE), eight lanes at a time under
// AVX2. Every weight and sum is an integer below 2^24, so the bits are
// sample_complete_lane()'s under SamplingRules::Gpu in any order;
// tests/runtime/sampling_gpu3d_test.cpp compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// Whether sample_gpu3d() takes lookups of this complete texture under SamplingRules::Gpu.
bool gpu3d_samples(const Texture& texture);

// sample_gpu3d()'s kernel for the texture's state (the generated code binds
// it per texture unit); null where gpu3d_samples() is false.
BatchKernel gpu3d_kernel(const Texture& texture);

// sample_complete_lane() with SamplingRules::Gpu for the lanes of `lanes`
// of a texture that gpu3d_samples() takes, into out[c][i]; the other lanes'
// entries are left as they are. Only for a CPU with AVX2 (cpu_has_avx2()).
void sample_gpu3d(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

}  // namespace glslrun::rt
