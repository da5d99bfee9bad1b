// The interpreter's `tex` kernel: decodes the operand block that the frontend
// laid out (ir::TexInfo) and samples every active lane.
//
//   uniform sampler2D tex;            // unit from the uniform, per lane
//   gl_FragColor = texture2DProj(tex, gl_TexCoord[0]);
//
// reaches here as coord = (s/q, t/q), ddx/ddy of those, and no bias. A unit
// out of range, or no texture bound to the sampler's target on that unit,
// samples as (0, 0, 0, 1): GL 2.1 §3.8.10's result for an incomplete texture.
#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>

#include "runtime/interp_kernels.h"
#include "runtime/sampling_batch.h"
#include "runtime/sampling_gpu3d.h"
#include "runtime/sampling_gpu_batch.h"
#include "runtime/sampling_gpu_direct.h"
#include "runtime/sampling_rules.h"

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
LaneLookup lane_lookup(const ir::TexInfo& info, const Operands<W>& ops, int lane, SamplingRules rules) {
    const uint32_t dims = info.dims();
    LaneLookup lk;
    lk.rules = rules;
    lk.coord = ops.vec(0, dims, lane);
    if (info.shadow) lk.ref = ops.at(info.ref_at(), lane);
    lk.implicit = info.lod != ir::TexLod::Explicit;
    lk.bias = info.lod == ir::TexLod::ImplicitBias;
    if (info.lod != ir::TexLod::Implicit) lk.lod = ops.at(info.lod_at(), lane);
    if (lk.implicit) {
        const int from = derivative_lane(lane, rules, info.grad);
        lk.ddx = ops.vec(info.ddx_at(), info.grad_dims(), from);
        lk.ddy = ops.vec(info.ddy_at(), info.grad_dims(), from);
    }
    return lk;
}

// The operands as float arrays for sample_batch(): the register block
// itself in the fp32 modes, a rounded copy of the operands in Reference mode.
template <class W>
struct FloatOperands {
    static constexpr uint32_t kMax = 12;  // 3 + ref + lod + 3 + 3, and a spare
    alignas(32) float copy[std::is_same_v<FloatOf<W>, float> ? 1 : kMax][kLanes];
    alignas(32) static constexpr float zeros[kLanes] = {};
    const float* base = nullptr;

    FloatOperands(const ir::TexInfo& info, const FloatOf<W>* block) {
        if constexpr (std::is_same_v<FloatOf<W>, float>) {
            (void)info;
            base = block;
        } else {
            const uint32_t n = std::min(info.operand_count(), kMax);
            for (uint32_t k = 0; k < n; ++k)
                for (int i = 0; i < kLanes; ++i) copy[k][i] = float(block[size_t(k) * kLanes + size_t(i)]);
            base = copy[0];
        }
    }
    const float* at(uint32_t k) const { return base + size_t(k) * kLanes; }
    // Component c of the vector operand at `first` with `dims` components.
    const float* component(uint32_t first, uint32_t dims, uint32_t c) const { return c < dims ? at(first + c) : zeros; }

    BatchLookup lookup(const ir::TexInfo& info) const {
        BatchLookup lk;
        const uint32_t dims = info.dims();
        lk.implicit = info.lod != ir::TexLod::Explicit;
        lk.bias = info.lod == ir::TexLod::ImplicitBias;
        for (uint32_t c = 0; c < 3; ++c) {
            lk.coord[c] = component(0, dims, c);
            lk.ddx[c] = lk.implicit ? component(info.ddx_at(), info.grad_dims(), c) : zeros;
            lk.ddy[c] = lk.implicit ? component(info.ddy_at(), info.grad_dims(), c) : zeros;
        }
        if (info.shadow) lk.ref = at(info.ref_at());
        if (info.lod != ir::TexLod::Implicit) lk.lod = at(info.lod_at());
        return lk;
    }
};

// The batched sampler's derivatives as derivative_lane() picks them: each
// quad's first lane's for all four, copied into `rows`.
void share_quad_derivatives(BatchLookup& lk, float (&rows)[6][kLanes]) {
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < kLanes; ++i) {
            rows[c][i] = lk.ddx[c][i & ~3];
            rows[3 + c][i] = lk.ddy[c][i & ~3];
        }
        lk.ddx[c] = rows[c];
        lk.ddy[c] = rows[3 + c];
    }
}

// The lanes of `lanes` whose unit is the same as lane `first`'s.
template <class W>
LaneMask same_unit(const W* units, LaneMask lanes, int first) {
    // Usually every lane holds the uniform's one unit: one vectorised test.
    W differ = 0;
    for (int i = 0; i < kLanes; ++i) differ |= units[i] ^ units[first];
    if (!differ) return lanes;
    LaneMask same = 0;
    for (int i = 0; i < kLanes; ++i) same |= LaneMask(units[i] == units[first]) << i;
    return same & lanes;
}

// (0, 0, 0, 1) in every lane, (0, 0, 0, 0) where `lookups` skips the lane;
// the bit tests as in Machine::write (the loops vectorise).
void fill_defaults(float (*out)[kLanes], LaneMask lookups) {
    for (int i = 0; i < kLanes; ++i) {
        out[0][i] = out[1][i] = out[2][i] = 0.0f;
        out[3][i] = 1.0f;
    }
    if (lookups == kAllLanes) return;
    for (int base = 0; base < kLanes; base += 32) {
        const uint32_t bits = uint32_t(lookups >> base);
        const int n = kLanes - base < 32 ? kLanes - base : 32;
        for (int i = 0; i < n; ++i) out[3][base + i] = (bits & kLaneBit[size_t(i)]) ? 1.0f : 0.0f;
    }
}

bool use_avx2() {
    static const bool avx2 = cpu_has_avx2();  // the CPU and the environment do not change
    return avx2;
}

// Whether the result registers share no word with the operand block or the units.
template <class W>
bool apart(const Step<W>& s, const ir::TexInfo& info) {
    const auto disjoint = [](const W* a, size_t na, const W* b, size_t nb) {
        const auto ia = reinterpret_cast<uintptr_t>(a), ib = reinterpret_cast<uintptr_t>(b);
        return ia + na * sizeof(W) <= ib || ib + nb * sizeof(W) <= ia;
    };
    const size_t results = size_t(ir::kTexResults) * kLanes;
    return disjoint(s.dst, results, s.src[1], size_t(info.operand_count()) * kLanes) &&
           disjoint(s.dst, results, s.src[0], kLanes);
}

// `rules`: the precision mode's (SamplingRules).
template <class W>
void sample_lanes(const Step<W>& s, Machine<W>& m, SamplingRules rules) {
    using F = FloatOf<W>;
    const ir::TexInfo info = ir::TexInfo::decode(s.imm[2]);
    const Operands<W> ops{reinterpret_cast<const F*>(s.src[1])};
    alignas(64) float local[ir::kTexResults][kLanes];
    float (*out)[kLanes] = local;
    const LaneMask lookups = m.mask.active() & m.lookups;
    // An incomplete texture samples as (0, 0, 0, 1), as nothing bound (GL
    // 2.1 §3.8.10), and so do inactive lanes; lanes that skip their lookups
    // read 0. A whole batch is usually sampled whole: its defaults are
    // filled afterwards, and only where a lane was not sampled.
    const bool whole = lookups == kAllLanes;
    // A whole batch of fp32 words goes straight into the destination
    // registers (Machine::write would copy them whole: a tenth of a
    // nine-tap frame), unless they reuse an operand's register: a lane may
    // read another lane's operands (Fast's quads) after that one's result.
    if constexpr (std::is_same_v<F, float>)
        if (whole && apart(s, info)) out = reinterpret_cast<float (*)[kLanes]>(s.dst);
    if (!whole) fill_defaults(out, m.lookups);
    const FloatOperands<W> floats(info, ops.block);
    BatchLookup batch = floats.lookup(info);
    // The batched sampler reads derivatives only where the texture's level
    // of detail matters (lod_matters()): the quads' copy is made for the
    // first such texture, not for every lookup (a tenth of a 3D-texture
    // frame without mipmaps).
    alignas(32) float quad_derivatives[6][kLanes];
    bool share = batch.implicit && derivative_lane(1, rules, info.grad) == 0;
    // The lanes' unit is almost always one: each unit's lanes are sampled together.
    LaneMask left = lookups, sampled = 0;
    while (left) {
        const int first = std::countr_zero(left);
        const LaneMask lanes = same_unit(s.src[0], left, first);
        left &= ~lanes;
        const Texture* texture = bound_texture(m, s.src[0][first], info.target);
        if (!texture || !texture->complete()) continue;
        sampled |= lanes;
        // The GPU's batch takes one lambda per quad: gradients the program
        // gives (texture*GradARB) are each lane's, on the lane path.
        if (rules == SamplingRules::Gpu && use_avx2() && gpu3d_samples(*texture)) {
            sample_gpu3d(*texture, batch, lanes, out);  // no level of detail: gradients change nothing
            continue;
        }
        if (rules == SamplingRules::Gpu && !info.grad && gpu_batch_samples(*texture)) {
            if (use_avx2() && gpu_direct_samples(*texture)) sample_gpu_direct(*texture, batch, lanes, out);
            else sample_gpu_batch(*texture, batch, lanes, out, use_avx2());
            continue;
        }
        if (!lanes_only(*texture, rules) && batch_samples(*texture)) {
            if (share && sampling::lod_matters(texture->sampler)) {
                // The mipmapped 2D kernel reads each quad's first lane: no copy.
                batch.quad_derivatives = true;
                if (!batch_reads_quad_leaders(*texture, use_avx2())) {
                    share_quad_derivatives(batch, quad_derivatives);
                    share = false;
                }
            }
            sample_batch(*texture, batch, lanes, out, use_avx2());
            continue;
        }
        for (int i = 0; i < kLanes; ++i) {
            if (!((lanes >> i) & 1)) continue;
            float texel[ir::kTexResults];
            if (texture->target() == TextureTarget::Rect)  // unnormalized coordinates: sampling_rect.cpp
                sample_rect_lane(*texture, lane_lookup(info, ops, i, rules), texel);
            else
                sample_complete_lane(*texture, lane_lookup(info, ops, i, rules), texel);
            for (uint32_t c = 0; c < ir::kTexResults; ++c) out[c][i] = texel[c];
        }
    }
    if (whole && sampled != kAllLanes)  // rare: an incomplete texture or none bound
        for (int i = 0; i < kLanes; ++i)
            if (!((sampled >> i) & 1)) {
                out[0][i] = out[1][i] = out[2][i] = 0.0f;
                out[3][i] = 1.0f;
            }
    if (out != local) return;
    for (uint32_t c = 0; c < ir::kTexResults; ++c) {
        W words[kLanes];
        for (int i = 0; i < kLanes; ++i) words[i] = std::bit_cast<W>(F(out[c][i]));
        m.write(s.dst + size_t(c) * kLanes, words);
    }
}

}  // namespace

template <class W>
void tex(const Step<W>& s, Machine<W>& m) {
    // Reference mode (doubles) takes the specification's rules, Precise the common ones.
    sample_lanes(s, m, std::is_same_v<W, uint64_t> ? SamplingRules::Spec : SamplingRules::Common);
}

void tex_gpu(const Step<uint32_t>& s, Machine<uint32_t>& m) { sample_lanes(s, m, SamplingRules::Gpu); }

template void tex<uint32_t>(const Step<uint32_t>&, Machine<uint32_t>&);
template void tex<uint64_t>(const Step<uint64_t>&, Machine<uint64_t>&);

}  // namespace glslrun::rt::kernels
