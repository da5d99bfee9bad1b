// Texture sampling as GL 2.1 §3.8.8–3.8.14 defines it, one lane at a time:
// level-of-detail selection, magnification/minification, mipmap choice,
// wrap modes and the border, nearest/linear filtering, cube-face selection,
// depth comparison and DEPTH_TEXTURE_MODE. The interpreter's `tex` kernel
// decodes an instruction's operands and samples the lanes of one texture
// together (sampling_batch.h), or one by one with sample_complete_lane().
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "glslrun/glslrun.h"

namespace glslrun::rt {

using TextureUnits = std::array<GLState::TextureUnit, kMaxTextureUnits>;

// Where GL 2.1 leaves a lookup's arithmetic to the implementation, which
// answer it takes (docs/semantics.md, "Texture filtering and level of detail").
enum class SamplingRules : uint8_t {
    Spec,    // Precision::Reference: §3.8.8's formulas exactly, c = 1/2 for the min/mag switch-over
    Common,  // Precision::Precise: exact arithmetic, and c = 0 as llvmpipe and NVIDIA's driver switch
    Gpu,     // Precision::Fast: NVIDIA's filter weights, level of detail and 16-bit filter results
};

// The lane whose derivatives an implicit level of detail reads. llvmpipe and
// NVIDIA's driver take one pair per 2x2 quad (lanes 4q..4q+3): its first
// lane's, the lower row's d/dx and the left column's d/dy (tools/gpu_probes'
// lod.frag band 4; llvmpipe's quad LOD), so Precise and Fast do too; the
// spec's rules (Reference) take each fragment's own, and so does every mode
// for derivatives the program gives (`given`: texture*GradARB).
inline int derivative_lane(int lane, SamplingRules rules, bool given) {
    return rules == SamplingRules::Spec || given ? lane : lane & ~3;
}

// The implicit level of detail, log2(rho) of §3.8.8 (before any bias or
// clamp), from the derivatives of the (already projected) coordinates over
// the screen. Only the components of the texture's dimensionality are read.
// For a cube map, `coord` is the direction and the derivatives are projected
// onto the face it selects.
float implicit_lod(const Texture& texture, const glm::vec3& coord, const glm::vec3& ddx, const glm::vec3& ddy);

// One texture lookup. `coord` is (s, t, r) as far as the target uses them
// (cube: the direction); `ref` is the depth-comparison reference, used when
// the texture is a depth texture with compare on; `lod` is lambda_base: the
// implicit LOD plus the shader's bias, or the explicit Lod argument. The
// texture object's own lod_bias, min/max_lod and base/max_level apply here.
// An incomplete texture gives (0, 0, 0, 1).
glm::vec4 sample_texture(const Texture& texture, const glm::vec3& coord, float ref, float lod,
                         SamplingRules rules = SamplingRules::Common);
// What a shader's lookup gives one lane: the coordinate, the reference, and
// either the LOD (explicit) or the derivatives with an optional bias.
struct LaneLookup {
    glm::vec3 coord{0.0f}, ddx{0.0f}, ddy{0.0f};
    float ref = 0.0f;
    float lod = 0.0f;  // the explicit LOD, or the bias
    bool implicit = true, bias = false;
    SamplingRules rules = SamplingRules::Common;
};

// implicit_lod() (where the lookup has no explicit LOD) and sample_texture()
// of a texture known to be complete (Texture::complete() walks the mipmap
// chains: the `tex` kernel asks once per texture and batch), into rgba.
// One call does all: called one by one, the helpers' small vectors went
// back through memory and the loads stalled on the stores (perf).
void sample_complete_lane(const Texture& texture, const LaneLookup& lookup, float* rgba);

// One lookup as the sampler made it, for the shader debugger's trace: the
// same rules as sample_complete_lane() (sampling_rules.h) with an observer
// on their steps, so the result has the same bits.
struct LookupTexel {
    int level = 0;
    int i = 0, j = 0, k = 0;  // texel coordinates in the level; -1: the border
    glm::vec4 value{0.0f};     // as filtered: a depth texture's comparison result when compare is on
};
struct LookupLevel {
    int level = 0, width = 0, height = 0, depth = 0;
    bool linear = false;  // LINEAR within the level, else NEAREST
};
struct LookupDetails {
    bool complete = false;  // incomplete (or nothing bound): (0, 0, 0, 1), nothing sampled
    int face = -1;          // cube maps: the face (0..5: +X, -X, +Y, -Y, +Z, -Z)
    glm::vec3 face_coord{0.0f};  // cube maps: (s, t) on the face
    // lambda_base of §3.8.8 from the derivatives (implicit LOD: NaN where
    // the lookup has an explicit one), and lambda after the shader's bias
    // (or the explicit LOD), the texture's bias and the LOD clamps, as the
    // filter used it. Where neither mipmaps nor a mag/min switch make the
    // LOD matter the sampler skips computing it: `lod_used` false, and
    // lambda is then only the biases'.
    float lod_implicit = 0.0f, lambda = 0.0f;
    bool lod_used = true, magnified = false;
    std::vector<LookupLevel> levels;
    std::vector<LookupTexel> texels;
    glm::vec4 result{0.0f, 0.0f, 0.0f, 1.0f};
};
LookupDetails explain_lookup(const Texture* texture, const LaneLookup& lookup);
// Whether lookups of `texture` under `rules` go through sample_complete_lane()
// rather than sample_batch(), whose lane loops follow SamplingRules::Common.
bool lanes_only(const Texture& texture, SamplingRules rules);

// sample_complete_lane() of a complete rectangle texture (TextureTarget::Rect:
// unnormalized coordinates, one level, clamping wraps; sampling_rect.cpp).
void sample_rect_lane(const Texture& texture, const LaneLookup& lookup, float* rgba);

}  // namespace glslrun::rt
