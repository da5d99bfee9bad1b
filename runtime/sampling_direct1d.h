// The batched sampler's one-pass 1D lookups (sampling_direct1d.cpp): a
// colour 1D texture of one image with one filter (no mipmaps; the min and
// mag filters both NEAREST or both LINEAR within the level), any wrap,
// eight lanes at a time under AVX2 from the coordinate to the result in
// registers, one kernel per texture state. Before this, 1D lookups went
// through the batched sampler's lane arrays (the indices, then the texels
// lane by lane). Every value comes from the operations of sampling_rules.h
// in the same order, so the bits are sample_complete_lane()'s;
// tests/runtime/jit_tex_kinds_test.cpp compares.
#pragma once
#include "runtime/sampling_batch.h"

namespace glslrun::rt {

// The kernel of a complete texture that these lookups take, else null.
// Only for a CPU with AVX2 (cpu_has_avx2()).
BatchKernel direct1d_kernel(const Texture& texture);

}  // namespace glslrun::rt
