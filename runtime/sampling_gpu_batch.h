// Fast's texture lookups (the GPU's rules, runtime/sampling_gpu.h) for a
// whole batch at once: the level of detail, the levels and the texel indices
// in lane loops, then each lane's 16-bit blends with sampling_gpu.h's own
// functions, so the bits are sample_complete_lane()'s under
// SamplingRules::Gpu (tests/runtime/sampling_gpu_batch_test.cpp compares
// them over random coordinates, derivatives, wraps and filters).
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// Whether sample_gpu_batch() takes lookups of this complete texture under
// SamplingRules::Gpu: RGBA8 1D, 2D and cube-map textures (sampling_gpu.h's
// filtered() ones but arrays, which keep the per-lane path).
bool gpu_batch_samples(const Texture& texture);

// sample_complete_lane() with SamplingRules::Gpu for every lane in `lanes`:
// lane i's channel c into out[c][i], the other lanes' entries left as they
// are. The implicit LOD takes each quad's first lane's derivatives (lanes
// 4q..4q+3 are a 2x2 quad), as the per-lane path does. `avx2`: the AVX2
// build of the lane loops (the same bits).
void sample_gpu_batch(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes],
                      bool avx2);

// lambda_base of every lane of a cube-map lookup with an implicit LOD, as
// the GPU's rules take it: rho on the face the lane's direction selects,
// from its quad's first lane's derivatives, through gpu::lambda_of_rho().
void gpu_cube_lambdas(const Texture& texture, const BatchLookup& lookup, float* lambda);

}  // namespace glslrun::rt
