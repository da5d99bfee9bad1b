// The interpreter's `tex` kernel: decodes the operand block that the frontend
// laid out (ir::TexInfo) and samples every active lane.
//
//   uniform sampler2D tex;            // unit from the uniform, per lane
//   gl_FragColor = texture2DProj(tex, gl_TexCoord[0]);
//
// reaches here as coord = (s/q, t/q), ddx/ddy of those, and no bias. A unit
// out of range, or no texture bound to the sampler's target on that unit,
// samples as (0, 0, 0, 1): GL 2.1 §3.8.10's result for an incomplete texture.
#include <cstring>

#include "runtime/interp_kernels.h"
#include "runtime/sampling.h"

namespace glslrun::rt::kernels {

namespace {

template <class W>
const Texture* bound_texture(const Machine<W>& m, W unit_word, ir::TexTarget target) {
    if (!m.textures) return nullptr;
    const int32_t unit = static_cast<int32_t>(static_cast<uint32_t>(unit_word));
    if (unit < 0 || unit >= kMaxTextureUnits) return nullptr;
    return m.textures[unit].bound[size_t(target)].get();
}

// The sampler works in float: Reference mode's doubles are rounded here.
template <class W>
struct Operands {
    const FloatOf<W>* block;  // operand k of lane i at block[k * kLanes + i]
    float at(uint32_t k, int lane) const { return float(block[size_t(k) * kLanes + size_t(lane)]); }
    // Built whole: stored component by component (a variable index), the
    // vector was then loaded from memory and stalled (perf).
    glm::vec3 vec(uint32_t first, uint32_t dims, int lane) const {
        return {at(first, lane), dims > 1 ? at(first + 1, lane) : 0.0f, dims > 2 ? at(first + 2, lane) : 0.0f};
    }
};

template <class W>
LaneLookup lane_lookup(const ir::TexInfo& info, const Operands<W>& ops, int lane) {
    const uint32_t dims = info.dims();
    LaneLookup lk;
    lk.coord = ops.vec(0, dims, lane);
    if (info.shadow) lk.ref = ops.at(info.ref_at(), lane);
    lk.implicit = info.lod != ir::TexLod::Explicit;
    lk.bias = info.lod == ir::TexLod::ImplicitBias;
    if (info.lod != ir::TexLod::Implicit) lk.lod = ops.at(info.lod_at(), lane);
    if (lk.implicit) {
        lk.ddx = ops.vec(info.ddx_at(), dims, lane);
        lk.ddy = ops.vec(info.ddy_at(), dims, lane);
    }
    return lk;
}

}  // namespace

template <class W>
void tex(const Step<W>& s, Machine<W>& m) {
    using F = FloatOf<W>;
    const ir::TexInfo info = ir::TexInfo::decode(s.imm[2]);
    const Operands<W> ops{reinterpret_cast<const F*>(s.src[1])};
    const LaneMask active = m.mask.active() & m.lookups;
    alignas(64) F out[ir::kTexResults][kLanes] = {};
    // The lanes' texture is almost always one: its completeness is asked once.
    const Texture* last = nullptr;
    bool last_complete = false;
    for (int i = 0; i < kLanes; ++i) {
        if (!((active >> i) & 1)) continue;
        const Texture* texture = bound_texture(m, s.src[0][i], info.target);
        if (texture && texture != last) {
            last = texture;
            last_complete = texture->complete();
        }
        // An incomplete texture samples as (0, 0, 0, 1), as nothing bound (GL 2.1 §3.8.10).
        const bool samples = texture && last_complete;
        float texel[ir::kTexResults] = {0.0f, 0.0f, 0.0f, 1.0f};
        if (samples) sample_complete_lane(*texture, lane_lookup(info, ops, i), texel);
        for (uint32_t c = 0; c < ir::kTexResults; ++c) out[c][i] = F(texel[c]);
    }
    for (uint32_t c = 0; c < ir::kTexResults; ++c) {
        W words[kLanes];
        std::memcpy(words, out[c], sizeof words);
        m.write(s.dst + size_t(c) * kLanes, words);
    }
}

template void tex<uint32_t>(const Step<uint32_t>&, Machine<uint32_t>&);
template void tex<uint64_t>(const Step<uint64_t>&, Machine<uint64_t>&);

}  // namespace glslrun::rt::kernels
