// Fast's 1D, 2D and cube-map lookups in registers (sampling_gpu_direct.cpp):
// an RGBA8 1D or 2D texture under the GPU's rules (sampling_gpu.h), mipmapped
// or not, any wrap, or a cube map whose wraps keep the indices in the face,
// eight lanes at a time under AVX2 from the coordinates to the
// result: each quad's lambda, each lane's level(s), the indices, 8-bit
// weights and 16-bit blends in registers, one kernel per texture state.
// Every value comes from sampling_gpu.h's operations, so the bits are
// sample_complete_lane()'s under SamplingRules::Gpu and sample_gpu_batch()'s
// (tests/runtime/sampling_gpu_batch_test.cpp compares both with the
// per-lane path). The batched path (sampling_gpu_batch.h) keeps the mixed
// filters and the cube maps clamped to the border.
#pragma once
#include "runtime/sampling_direct.h"

namespace glslrun::rt {

// Whether sample_gpu_direct() takes lookups of this complete texture: a
// texture that gpu_batch_samples() takes (1D, 2D or a cube map whose wraps
// are REPEAT, MIRRORED_REPEAT or CLAMP_TO_EDGE, or NEAREST's CLAMP), whose filter within a level
// is the same on both sides of the switch-over (LINEAR_MIPMAP_* with
// LINEAR magnification, NEAREST_MIPMAP_* with NEAREST, or one filter
// without mipmaps). Only for a CPU with AVX2 (cpu_has_avx2(), which the
// caller asks once: it reads the environment).
bool gpu_direct_samples(const Texture& texture);

// sample_gpu_batch()'s results for the lanes of `lanes` of a texture that
// gpu_direct_samples() takes, into out[c][i]; the other lanes' entries are
// left as they are. The implicit LOD takes each quad's first lane's
// derivatives (lanes 4q..4q+3 are a 2x2 quad).
void sample_gpu_direct(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes]);

// Fast's one-pass sampler of a 2D texture for the JIT's generated `tex`
// code (as bind_direct() is Precise's): the GPU's rules for a texture
// without mipmaps that gpu_direct_samples() takes, bind_direct()'s for a
// texture outside the GPU's rules (float texels: the tex kernel samples
// those by the Common rules under Fast too), `run` null otherwise
// (mipmaps, mixed filters, incomplete, no AVX2).
DirectSampler bind_gpu_direct(const Texture* texture);

}  // namespace glslrun::rt
