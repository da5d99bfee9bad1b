// Texture lookups of a whole batch at once: the `tex` kernel's lanes that
// read one texture go through each step of the lookup together (coordinates
// and cube faces, the level of detail, the mipmap levels, the texel indices
// of each axis), in lane loops that the compiler vectorises, 8 lanes at a
// time under AVX2. Where every lane reads one image with one filter (no
// mipmaps, not a cube map: 1D, 2D, 3D and rectangles alike) the level and
// face steps are skipped and the image's sizes are constants. Linear blends
// that cannot meet the border or a depth comparison fetch 4 lanes at a time
// (8 under AVX2), the texels transposed into channels; the others lane by
// lane, four channels in one register. Under AVX2, a colour texture's
// NEAREST or LINEAR lookup of one 2D image (or rectangle), any wrap, goes
// eight lanes at a time from the coordinates to the result in registers,
// one kernel per texture state (sampling_direct.h), and so does a mipmapped
// 2D one whose filter within a level is one kind (sampling_mip2d.h, the
// level of detail and both levels in registers); cube maps (a pass per
// face and level a group of eight lanes reads) and shadow maps go eight
// lanes at a time too (sampling_batch_cube.h, _shadow.h). Every
// value comes from the same functions as sample_complete_lane()'s
// (runtime/sampling_rules.h), so both give the same bits;
// tests/runtime/sampling_batch_test.cpp compares them.
#pragma once
#include "runtime/backend.h"
#include "runtime/sampling.h"

namespace glslrun::rt {

// A `tex` instruction's operands for every lane of a batch, as floats: one
// array of kLanes per component. Components the lookup does not have point
// at zeros (the coordinate's unused ones, the derivatives of an explicit
// LOD); `ref` and `lod` may be null where the lookup has none.
struct BatchLookup {
    const float* coord[3] = {};
    const float* ddx[3] = {};
    const float* ddy[3] = {};
    const float* ref = nullptr;
    const float* lod = nullptr;  // the explicit LOD, or the bias
    bool implicit = true, bias = false;
    // Every quad's derivatives are its first lane's (lanes 4q..4q+3 read
    // lane 4q's; the others' rows hold anything): the tex kernel's Precise
    // lookups, for a sampler that reads them so (batch_reads_quad_leaders()).
    bool quad_derivatives = false;
};

// Whether sample_batch(texture, ..., avx2) reads each quad's derivatives
// from its first lane alone where BatchLookup::quad_derivatives says they
// are that lane's (the others' need every lane's rows filled).
bool batch_reads_quad_leaders(const Texture& texture, bool avx2);

// Whether sample_batch() takes lookups of this (complete) texture; the
// others go through sample_complete_lane(). Decided here only.
bool batch_samples(const Texture& texture);

// sample_complete_lane() of every lane in `lanes` (a complete texture that
// batch_samples() takes): lane i's channel c into out[c][i]. The other lanes'
// entries are left as they are. `avx2`: the AVX2 build of the lane loops
// (the same bits as the baseline one).
void sample_batch(const Texture& texture, const BatchLookup& lookup, LaneMask lanes, float (*out)[kLanes], bool avx2);

// A lookup kernel chosen once for a texture's state (its filter, wraps and
// comparison are the kernel's template arguments): sample_batch()'s
// result for the lanes of `lanes` into out[c][i], the other lanes' entries
// left as they are. The JIT's generated lookups call one straight
// (runtime/jit/tex_direct.cpp) with no selection per lookup.
using BatchKernel = void (*)(const Texture& texture, const BatchLookup& lookup, LaneMask lanes,
                             float (*out)[kLanes]);

// The eight-lane cube map kernel (sampling_batch_cube.h) of a complete
// texture that it takes (a colour cube map, LINEAR within every level,
// wraps that keep every texel in the image), else null. Only for a CPU
// with AVX2; it reads the lookup's derivatives where lod_matters().
BatchKernel cube_kernel(const Texture& texture);

}  // namespace glslrun::rt
