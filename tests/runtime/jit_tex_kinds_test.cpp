// The JIT's 1D, 3D and cube colour lookups and 2D depth comparisons, which
// call the batched sampler's kernel for the texture's state from generated
// code (runtime/jit/tex_direct.cpp, BoundKernel), against the interpreter's
// `tex` kernel (Precise, and Fast with and without its GPU filtering) and
// against the lane sampler (sample_complete_lane()), which shares no code
// with the kernels: the interpreter runs the same kernels, so comparing the
// two backends alone could not see a kernel's error. Every filter and wrap
// of each target (those whose state has no kernel, or whose level of detail
// matters, fall back to the call-out), every comparison function and depth
// mode, odd sizes and base level 1, RGBA8 and float texels; spread lanes
// (NaN, infinite, huge and denormal coordinates) and close ones (as the
// rasterizer packs a magnified image's), partial masks, lanes that skip
// their lookups, lanes of another unit or of none, an incomplete texture;
// the derivative rows stored where a unit's texture may read them and
// left alone where none does.
// 2D colour lookups too: the one-pass samplers' fallback, and mipmapped
// states in every filter and wrap pair (their kernel, BoundKernel's Mip2D,
// in Precise and Fast without its GPU filtering; the call-out under it, or
// where magnification and minification filter a level differently) against
// the lane sampler with each quad's first lane's derivatives (the
// interpreter's rows), with a bias too, and each lane's own where the
// program gives the gradients; jit_tex_direct_test.cpp has the one-pass
// sweep.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "ir/scalar_ops.h"
#include "runtime/backend_factory.h"
#include "runtime/jit/context.h"
#include "runtime/interp_kernels.h"
#include "runtime/sampling.h"
#include "runtime/sampling_rules.h"
#include "tests/runtime/ir_builder.h"
#include "tests/runtime/jit_tex_modes.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

constexpr int kUnit = 2;        // the state under test
constexpr int kOtherUnit = 5;   // a NEAREST REPEAT texture of the target
constexpr int kIncomplete = 7;  // mipmap filters, no mipmaps: (0, 0, 0, 1)

// The lookups of one kind: a target, and whether it compares depths.
struct LookupKind {
    TextureTarget target;
    bool shadow;
    const char* name;
};

struct State {
    TextureFilter filter;
    TextureWrap wrap[3];
    CompareFunc func;
    DepthTextureMode mode;
    int size[3];
    int base_level;
    TextureFormat format;
    // Magnification's filter within a level unlike minification's (a
    // mipmapped state the mipmapped 2D kernel does not take).
    bool mag_other = false;
};

// A mipmapped state's magnification filter: NEAREST or LINEAR as its
// minification filters a level, the other where `other`.
TextureFilter mag_of(TextureFilter filter, bool other) {
    if (!rt::is_mipmap_filter(filter)) return filter;
    return rt::sampling::linear_within_level(filter) != other ? TextureFilter::Linear : TextureFilter::Nearest;
}

std::shared_ptr<const Texture> texture(const LookupKind& kind, const State& st, bool mipmaps, uint32_t seed) {
    std::mt19937 rng(seed);
    const bool depth = kind.shadow;
    std::uniform_real_distribution<float> value(depth ? -0.1f : -2.0f, depth ? 1.1f : 2.0f);
    const int w = st.size[0];
    const int h = kind.target == TextureTarget::Tex1D ? 1 : kind.target == TextureTarget::Cube ? w : st.size[1];
    const int d = kind.target == TextureTarget::Tex3D ? st.size[2] : 1;
    std::vector<TextureImage> faces;
    for (int f = 0; f < (kind.target == TextureTarget::Cube ? 6 : 1); ++f) {
        TextureImage img{w, h, d, {}};
        for (int k = 0; k < w * h * d; ++k) img.texels.push_back({value(rng), value(rng), value(rng), value(rng)});
        faces.push_back(std::move(img));
    }
    Result<Texture> t = Texture::create(kind.target, std::move(faces), depth ? TextureFormat::Depth : st.format);
    REQUIRE(t.ok());
    if (mipmaps) t->generate_mipmaps();
    SamplerState& s = t->sampler;
    s.min_filter = st.filter;
    s.mag_filter = mag_of(st.filter, st.mag_other);
    s.wrap_s = st.wrap[0];
    s.wrap_t = st.wrap[1];
    s.wrap_r = st.wrap[2];
    s.base_level = st.base_level;
    s.border_color = {0.25f, 1.5f, -0.5f, 0.75f};  // clamped to [0, 1] by the sampler
    s.compare = depth;
    s.compare_func = st.func;
    s.depth_mode = st.mode;
    return std::make_shared<const Texture>(std::move(*t));
}

SamplerState st_sampler(const State& st) {
    SamplerState s;
    s.min_filter = st.filter;
    s.mag_filter = mag_of(st.filter, st.mag_other);
    return s;
}

float special(std::mt19937& rng) {
    static constexpr float kSpecial[] = {std::numeric_limits<float>::quiet_NaN(),
                                         std::numeric_limits<float>::infinity(),
                                         -std::numeric_limits<float>::infinity(),
                                         1e30f, -1e30f, 16777216.0f, -16777217.0f, 8388609.5f,
                                         1e-40f, -0.0f, 0.0f, 1.0f, 0.5f, -0.5f};
    return kSpecial[rng() % (sizeof kSpecial / sizeof kSpecial[0])];
}

// A spread coordinate: inside, around and far outside the image, and the special values.
float spread(std::mt19937& rng) {
    if (rng() % 8 == 0) return special(rng);
    return std::uniform_real_distribution<float>(-2.5f, 3.5f)(rng);
}

struct Shader {
    Builder b;
    Reg coord[3], ref, lod, unit, unit_lane, cond, result, explicit_result;
    Reg block;  // the implicit lookup's operand block
    ir::TexInfo implicit;
    // A 2D colour kind's lookup with the program's gradients (each lane's
    // own, as texture2DGradARB's: no quad shares them); 0: none.
    Reg grad_result = 0;
    // Its implicit lookup with a bias (lod's), and that lookup's operand block.
    Reg bias_result = 0, bias_block = 0;
    ir::TexInfo bias;
};

// Two lookups of one kind: an implicit one (derivatives of the
// coordinates) whose unit is a uniform's, under an if, and an explicit-LOD
// one whose unit is each lane's own.
std::unique_ptr<Shader> make_shader(const LookupKind& kind) {
    auto sh = std::make_unique<Shader>();
    Builder& b = sh->b;
    for (Reg& c : sh->coord) c = b.reg(Kind::F32);
    sh->ref = b.reg(Kind::F32);
    sh->lod = b.reg(Kind::F32);
    sh->unit_lane = b.reg(Kind::I32);
    sh->cond = b.reg(Kind::Bool);
    for (Reg r : {sh->coord[0], sh->coord[1], sh->coord[2], sh->ref, sh->lod, sh->unit_lane, sh->cond})
        b.input("in", r);
    sh->unit = b.reg(Kind::I32);
    b.instr(Op::uniform, Kind::I32, sh->unit, {}, {0});
    ir::TexInfo implicit;
    implicit.target = ir::TexTarget(kind.target);
    implicit.shadow = kind.shadow;
    const uint32_t dims = implicit.dims();
    const auto block_of = [&](const ir::TexInfo& info) {
        const Reg block = b.range(Kind::F32, info.operand_count());
        for (uint32_t k = 0; k < dims; ++k) b.mov(block + k, sh->coord[k]);
        if (info.shadow) b.mov(block + info.ref_at(), sh->ref);
        if (info.lod != ir::TexLod::Implicit) b.mov(block + info.lod_at(), sh->lod);
        if (info.lod != ir::TexLod::Explicit)
            for (uint32_t k = 0; k < info.grad_dims(); ++k) {
                b.instr(Op::ddx, Kind::F32, block + info.ddx_at() + k, {sh->coord[k]});
                b.instr(Op::ddy, Kind::F32, block + info.ddy_at() + k, {sh->coord[k]});
            }
        return block;
    };
    const Reg block = block_of(implicit);
    sh->block = block;
    sh->implicit = implicit;
    sh->result = b.range(Kind::F32, ir::kTexResults);
    b.if_(sh->cond, [&] {
        b.instr(Op::tex, Kind::F32, sh->result, {sh->unit}, {block, implicit.operand_count(), implicit.encode()});
    });
    ir::TexInfo explicit_lod = implicit;
    explicit_lod.lod = ir::TexLod::Explicit;
    const Reg explicit_block = block_of(explicit_lod);
    sh->explicit_result = b.range(Kind::F32, ir::kTexResults);
    b.instr(Op::tex, Kind::F32, sh->explicit_result, {sh->unit_lane},
            {explicit_block, explicit_lod.operand_count(), explicit_lod.encode()});
    for (uint32_t c = 0; c < ir::kTexResults; ++c) {
        b.output("r", sh->result + c);
        b.output("e", sh->explicit_result + c);
    }
    if (kind.target == TextureTarget::Tex2D && !kind.shadow) {
        ir::TexInfo grad = implicit;
        grad.grad = true;
        const Reg block = b.range(Kind::F32, grad.operand_count());
        for (uint32_t k = 0; k < dims; ++k) b.mov(block + k, sh->coord[k]);
        const Reg rows[] = {sh->ref, sh->lod, sh->lod, sh->ref};  // (ref, lod) and (lod, ref): every lane its own
        for (uint32_t k = 0; k < 4; ++k) b.mov(block + grad.ddx_at() + k, rows[k]);
        sh->grad_result = b.range(Kind::F32, ir::kTexResults);
        b.instr(Op::tex, Kind::F32, sh->grad_result, {sh->unit}, {block, grad.operand_count(), grad.encode()});
        for (uint32_t c = 0; c < ir::kTexResults; ++c) b.output("g", sh->grad_result + c);
        sh->bias = implicit;
        sh->bias.lod = ir::TexLod::ImplicitBias;
        sh->bias_block = block_of(sh->bias);
        sh->bias_result = b.range(Kind::F32, ir::kTexResults);
        b.instr(Op::tex, Kind::F32, sh->bias_result, {sh->unit},
                {sh->bias_block, sh->bias.operand_count(), sh->bias.encode()});
        for (uint32_t c = 0; c < ir::kTexResults; ++c) b.output("b", sh->bias_result + c);
    }
    return sh;
}

// `lod_free`: kIncomplete left unbound, so that no unit's texture reads
// derivatives where kUnit's does not (the generated code then stores none).
std::array<GLState::TextureUnit, kMaxTextureUnits> units_of(const LookupKind& kind, const State& st, uint32_t seed,
                                                            bool lod_free) {
    using enum TextureWrap;
    std::array<GLState::TextureUnit, kMaxTextureUnits> units{};
    auto bind = [&](int unit, std::shared_ptr<const Texture> t) {
        units[size_t(unit)].bound[size_t(t->target())] = std::move(t);
    };
    bind(kUnit, texture(kind, st, true, seed));
    const State other{TextureFilter::Nearest, {Repeat, Repeat, Repeat}, CompareFunc::Less, DepthTextureMode::Luminance,
                      {3, 2, 2}, 0, TextureFormat::RGBA8};
    bind(kOtherUnit, texture(kind, other, false, 7u));
    State incomplete = other;
    incomplete.filter = TextureFilter::LinearMipmapLinear;
    incomplete.size[0] = incomplete.size[1] = incomplete.size[2] = 4;
    if (!lod_free) bind(kIncomplete, texture(kind, incomplete, false, 9u));
    return units;
}

// Lane i's position on one axis of a magnified image, as the rasterizer
// packs lanes (quad i / 4 at (2 (q % 4), 2 (q / 4)) of an 8x4 block, the
// lane at (i & 1, i >> 1 & 1) in it): `step` a pixel from `origin`.
float close_coordinate(int lane, int axis, float origin, float step) {
    const int q = lane / 4;
    const int pixel = axis == 0 ? 2 * (q % 4) + (lane & 1) : axis == 1 ? 2 * (q / 4) + ((lane >> 1) & 1) : q % 3;
    return origin + (float(pixel) + 0.5f) * step;
}

// The lane sampler's words for a lookup of `texture`, in the backends'
// floating-point mode (denormals flushed: a reference of 1e-40 is 0).
// `lod`: the explicit LOD (the bias where `bias`); `ddx`, `ddy`: the implicit one's derivatives (null: none read).
std::array<uint32_t, 4> lane_sample(const Texture& texture, const float* coord, float ref, rt::SamplingRules rules,
                                    const float* lod = nullptr, const float* ddx = nullptr,
                                    const float* ddy = nullptr, bool bias = false) {
    ir::FlushDenormals ftz;
    rt::LaneLookup lane;
    lane.rules = rules;
    lane.coord = {coord[0], coord[1], coord[2]};
    lane.ref = ref;
    lane.implicit = !lod || bias;
    lane.bias = bias;
    if (lod) lane.lod = *lod;
    if (ddx) lane.ddx = {ddx[0], ddx[1], 0.0f};
    if (ddy) lane.ddy = {ddy[0], ddy[1], 0.0f};
    float rgba[4];
    rt::sample_complete_lane(texture, lane, rgba);
    return {bits(rgba[0]), bits(rgba[1]), bits(rgba[2]), bits(rgba[3])};
}

struct Lanes {
    std::vector<float> coord[3], ref;
};

// Round 0-1 spread lanes (1: the if taken by two lanes of three), 2 a
// partial live mask, 3 lanes that skip their lookups, 4-5 mixed units per
// lane (some out of range), 6-7 close lanes (a cube's: directions near a
// face's corner; a shadow map's: references near the texels' depths).
Lanes lanes_of(const LookupKind& kind, const State& st, int round, std::mt19937& rng) {
    Lanes l;
    for (auto& c : l.coord) c.resize(rt::kLanes);
    l.ref.resize(rt::kLanes);
    const bool close = round >= 6;
    float origin[3], step[3];
    for (int a = 0; a < 3; ++a) {
        origin[a] = std::uniform_real_distribution<float>(-0.3f, 1.3f)(rng);
        step[a] = (round == 6 ? 0.3f : 0.6f) / float(st.size[a]);
    }
    if (kind.target == TextureTarget::Cube) {  // a major axis of +-1, the others near a corner
        const int major = int(rng() % 3);
        origin[major] = rng() % 2 ? 1.0f : -1.0f;
        step[major] = 0.0f;
        for (int a = 0; a < 3; ++a)
            if (a != major) origin[a] = std::uniform_real_distribution<float>(-1.05f, 0.9f)(rng);
    }
    const float ref_origin = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    for (int lane = 0; lane < rt::kLanes; ++lane) {
        for (int a = 0; a < 3; ++a)
            l.coord[a][size_t(lane)] = close ? close_coordinate(lane, a, origin[a], step[a]) : spread(rng);
        l.ref[size_t(lane)] = close ? ref_origin + 0.01f * float(lane % 5) : rng() % 8 ? spread(rng) * 0.4f : special(rng);
    }
    return l;
}

// A mipmapped 2D lookup of lane `lane` (of kUnit in both lookups): the
// implicit one from its quad's first lane's derivative rows (the
// interpreter's words), the explicit one at its LOD, by the lane sampler.
void check_mip2d(const Shader& sh, rt::Executor& interp, rt::Executor& jit, const Texture& tex, const Lanes& l,
                 int lane) {
    const float coord[3] = {l.coord[0][size_t(lane)], l.coord[1][size_t(lane)], 0.0f};
    const auto row = [&](Reg block, uint32_t k) { return std::bit_cast<float>(interp.lanes(block + k)[lane & ~3]); };
    const float ddx[2] = {row(sh.block, sh.implicit.ddx_at()), row(sh.block, sh.implicit.ddx_at() + 1)};
    const float ddy[2] = {row(sh.block, sh.implicit.ddy_at()), row(sh.block, sh.implicit.ddy_at() + 1)};
    const float bias_dx[2] = {row(sh.bias_block, sh.bias.ddx_at()), row(sh.bias_block, sh.bias.ddx_at() + 1)};
    const float bias_dy[2] = {row(sh.bias_block, sh.bias.ddy_at()), row(sh.bias_block, sh.bias.ddy_at() + 1)};
    const std::array<uint32_t, 4> want = lane_sample(tex, coord, 0.0f, rt::SamplingRules::Common, nullptr, ddx, ddy);
    const float lod = float(lane % 3) - 1.0f;
    const std::array<uint32_t, 4> want_explicit = lane_sample(tex, coord, 0.0f, rt::SamplingRules::Common, &lod);
    const float ref = l.ref[size_t(lane)];
    const float gx[2] = {ref, lod}, gy[2] = {lod, ref};
    const std::array<uint32_t, 4> want_grad = lane_sample(tex, coord, 0.0f, rt::SamplingRules::Common, nullptr, gx, gy);
    const std::array<uint32_t, 4> want_bias =
        lane_sample(tex, coord, 0.0f, rt::SamplingRules::Common, &lod, bias_dx, bias_dy, true);
    for (uint32_t k = 0; k < ir::kTexResults; ++k) {
        INFO("mipmapped channel " << k << " ddx " << ddx[0] << "," << ddx[1] << " ddy " << ddy[0] << "," << ddy[1]);
        REQUIRE(jit.lanes(sh.result + k)[lane] == want[k]);
        REQUIRE(jit.lanes(sh.explicit_result + k)[lane] == want_explicit[k]);
        REQUIRE(jit.lanes(sh.grad_result + k)[lane] == want_grad[k]);
        REQUIRE(jit.lanes(sh.bias_result + k)[lane] == want_bias[k]);
    }
}

void compare(const LookupKind& kind, const Shader& sh, const rt::CompiledShader& interp, const rt::CompiledShader& jit,
             const TexMode& mode, const State& st, uint32_t seed) {
    // Half the states whose lookups take no level of detail have no unit
    // that does: the JIT's derivative rows are then never stored.
    const bool lod_free = !rt::sampling::lod_matters(st_sampler(st)) && seed % 2 == 1;
    const auto units = units_of(kind, st, seed, lod_free);
    // Under Fast's GPU filtering, RGBA8 textures (kOtherUnit's) may read
    // them, and its 1D, 3D and cube lookups call out; its depth maps do not.
    const bool stored_none = lod_free && (!mode.gpu() || kind.shadow);
    const uint32_t uniforms[] = {uint32_t(kUnit)};
    const rt::ExecParams params{uniforms, 10, units.data(), mode.precision, mode.fast_ops};
    auto ia = interp.instantiate(params), ja = jit.instantiate(params);
    const Texture& tex = *units[size_t(kUnit)].bound[size_t(kind.target)];
    // The lane sampler's rules are Precise's (Fast's GPU filtering has its own).
    // The lane sampler under the mode's rules, where they are Precise's:
    // Fast's GPU filtering of the textures it takes is its own paths' (and
    // its quads' levels of detail), as is a level-of-detail decision (the
    // quads' derivatives).
    const rt::SamplingRules rules = mode.gpu() ? rt::SamplingRules::Gpu : rt::SamplingRules::Common;
    const bool oracle = tex.complete() && !rt::lanes_only(tex, rules) && !rt::sampling::lod_matters(tex.sampler);
    // A mipmapped 2D colour texture that filters a level alike on both
    // sides: the mipmapped kernel's, bound outside Fast's GPU filtering
    // (which takes it: then the call-out), and the lane sampler's words
    // from each quad's first lane's derivatives (Precise's one LOD a quad).
    const bool mip2d = kind.target == TextureTarget::Tex2D && !kind.shadow && tex.complete() &&
                       rt::is_mipmap_filter(st.filter) && !st.mag_other;
    {
        INFO(kind.name << " filter " << int(st.filter) << " mag_other " << st.mag_other << " gpu " << mode.gpu());
        REQUIRE(rt::jit::binds_mip2d(units[size_t(kUnit)].bound[size_t(TextureTarget::Tex2D)].get(), mode.gpu()) ==
                (mip2d && !mode.gpu()));
        for (int other : {kOtherUnit, kIncomplete})
            REQUIRE(!rt::jit::binds_mip2d(units[size_t(other)].bound[size_t(TextureTarget::Tex2D)].get(), false));
    }
    const bool mip_oracle = mip2d && !mode.gpu();
    std::mt19937 rng(seed * 977u);
    for (int round = 0; round < 8; ++round) {
        const rt::LaneMask live = round == 2 ? rt::LaneMask(0x5a5a5a5a5a5a5a5aull) & rt::kAllLanes : rt::kAllLanes;
        const rt::LaneMask skipped = round == 3 ? rt::LaneMask(0x0f0f0f0f0f0f0f0full) & rt::kAllLanes : 0;
        const Lanes l = lanes_of(kind, st, round, rng);
        const auto cond = [&](int lane) { return round == 1 ? lane % 3 != 0 : true; };
        for (rt::Executor* e : {ia.get(), ja.get()}) {
            e->skip_lookups(skipped);
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                const int mixed[] = {kUnit, kOtherUnit, kIncomplete, -1, 40};
                const int unit = round == 4 || round == 5 ? mixed[(lane + round) % 5] : kUnit;
                for (int a = 0; a < 3; ++a) e->lanes(sh.coord[a])[lane] = bits(l.coord[a][size_t(lane)]);
                e->lanes(sh.ref)[lane] = bits(l.ref[size_t(lane)]);
                e->lanes(sh.lod)[lane] = bits(float(lane % 3) - 1.0f);
                e->lanes(sh.unit_lane)[lane] = bits(round == 5 && lane ? kOtherUnit : unit);
                e->lanes(sh.cond)[lane] = cond(lane);
                for (uint32_t k = sh.implicit.ddx_at(); k < sh.implicit.operand_count(); ++k)
                    e->lanes(sh.block + k)[lane] = 0xdeadbeefu;
                for (uint32_t k = 0; k < ir::kTexResults; ++k) {
                    e->lanes(sh.result + k)[lane] = 0xdeadbeefu;
                    e->lanes(sh.explicit_result + k)[lane] = 0xdeadbeefu;
                    if (sh.grad_result) e->lanes(sh.grad_result + k)[lane] = 0xdeadbeefu;
                    if (sh.bias_result) e->lanes(sh.bias_result + k)[lane] = 0xdeadbeefu;
                }
            }
        }
        REQUIRE(ia->run(live, nullptr));
        REQUIRE(ja->run(live, nullptr));
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            INFO(kind.name << " precision " << int(mode.precision) << " fast_ops " << mode.fast_ops << " filter "
                 << int(st.filter) << " wrap " << int(st.wrap[0]) << "," << int(st.wrap[1]) << "," << int(st.wrap[2])
                 << " func " << int(st.func) << " mode " << int(st.mode) << " " << st.size[0] << "x" << st.size[1]
                 << "x" << st.size[2] << " base " << st.base_level << " round " << round << " lane " << lane
                 << " coord " << l.coord[0][size_t(lane)] << "," << l.coord[1][size_t(lane)] << ","
                 << l.coord[2][size_t(lane)] << " ref " << l.ref[size_t(lane)]);
            for (const ir::Binding& out : sh.b.sh.outputs) {
                INFO("register " << out.first);
                REQUIRE(ia->lanes(out.first)[lane] == ja->lanes(out.first)[lane]);
            }
            // The derivative rows: the interpreter's words where a texture
            // may read them, else never stored (the JIT's generated code
            // took the shortcut; on a CPU without AVX2 it calls out).
            for (uint32_t k = sh.implicit.ddx_at(); k < sh.implicit.operand_count(); ++k) {
                INFO("derivative row " << k);
                if (stored_none) REQUIRE(ja->lanes(sh.block + k)[lane] == 0xdeadbeefu);
                else REQUIRE(ja->lanes(sh.block + k)[lane] == ia->lanes(sh.block + k)[lane]);
            }
            // The lanes that looked up kUnit's texture: the lane sampler's words.
            const bool looked = ((live >> lane) & 1) && !((skipped >> lane) & 1) && cond(lane) && round != 4 &&
                                round != 5;
            if (mip_oracle && looked) check_mip2d(sh, *ia, *ja, tex, l, lane);
            if (!oracle || !looked) continue;
            const float coord[3] = {l.coord[0][size_t(lane)], l.coord[1][size_t(lane)], l.coord[2][size_t(lane)]};
            const std::array<uint32_t, 4> want = lane_sample(tex, coord, l.ref[size_t(lane)], rules);
            for (uint32_t k = 0; k < ir::kTexResults; ++k) {
                INFO("channel " << k);
                REQUIRE(ja->lanes(sh.result + k)[lane] == want[k]);
            }
        }
    }
}

void sweep(const LookupKind& kind, const std::vector<State>& states) {
    auto sh = make_shader(kind);
    for (const TexMode& mode : kTexModes) {
        auto interp = rt::compile_shader(sh->b.sh, rt::Runner::Interp, mode.precision, mode.fast_ops, true);
        auto jit = rt::compile_shader(sh->b.sh, rt::Runner::Jit, mode.precision, mode.fast_ops, true);
        REQUIRE(jit);
        uint32_t seed = 0;
        for (const State& st : states) compare(kind, *sh, *interp, *jit, mode, st, ++seed);
    }
}

// Every filter kind and wrap on each axis the target has (the others
// REPEAT); sizes, formats and base levels cycled.
std::vector<State> states_of(const LookupKind& kind) {
    using enum TextureWrap;
    const TextureWrap wraps[] = {Repeat, MirroredRepeat, ClampToEdge, Clamp, ClampToBorder};
    const int sizes[][3] = {{5, 3, 4}, {1, 1, 1}, {7, 1, 3}, {1, 6, 2}, {13, 11, 5}, {4, 4, 1}, {9, 6, 7}};
    const int axes = kind.target == TextureTarget::Tex1D ? 1 : kind.target == TextureTarget::Tex3D ? 3 : 2;
    // A 2D colour texture's mipmapped states (the mipmapped kernel's) in
    // every filter and wrap pair; the other kinds' (the call-out's) once
    // per wrap on s.
    const bool mip2d = kind.target == TextureTarget::Tex2D && !kind.shadow;
    std::vector<TextureFilter> filters = {TextureFilter::Nearest, TextureFilter::Linear,
                                          TextureFilter::LinearMipmapLinear};
    if (mip2d)
        filters.insert(filters.end(), {TextureFilter::LinearMipmapNearest, TextureFilter::NearestMipmapLinear,
                                       TextureFilter::NearestMipmapNearest});
    std::vector<State> states;
    uint32_t n = 0;
    for (const TextureFilter filter : filters)
        for (int w = 0; w < 125; ++w) {
            const TextureWrap ws = wraps[w % 5], wt = axes > 1 ? wraps[w / 5 % 5] : Repeat;
            const TextureWrap wr = axes > 2 ? wraps[w / 25] : Repeat;
            if ((axes < 2 && w >= 5) || (axes < 3 && w >= 25)) break;
            if (rt::is_mipmap_filter(filter) && !mip2d && w >= 5) break;
            ++n;
            const int* size = sizes[n % 7];
            State st{filter, {ws, wt, wr}, CompareFunc(n % 8), DepthTextureMode(n % 3), {size[0], size[1], size[2]},
                     int(n % 4 == 3), n % 3 == 2 ? TextureFormat::RGBA32F : TextureFormat::RGBA8,
                     rt::is_mipmap_filter(filter) && w % 7 == 3};
            states.push_back(st);
            if (kind.shadow)  // every comparison function with this state's filter and wraps
                for (int f = 1; f < 8; ++f) {
                    st.func = CompareFunc((n + uint32_t(f)) % 8);
                    st.mode = DepthTextureMode((n + uint32_t(f)) % 3);
                    states.push_back(st);
                }
        }
    return states;
}

}  // namespace

TEST_CASE("generated 1D, 3D, cube and shadow lookups give the lane sampler's words", "[runtime][backend][jit_tex]") {
    if (!jit_available() || !rt::cpu_has_avx2()) return;
    const LookupKind kinds[] = {{TextureTarget::Tex1D, false, "1D"},
                          {TextureTarget::Tex3D, false, "3D"},
                          {TextureTarget::Cube, false, "cube"},
                          {TextureTarget::Tex2D, true, "shadow 2D"},
                          {TextureTarget::Tex2D, false, "2D"}};
    for (const LookupKind& kind : kinds) {
        SECTION(kind.name) { sweep(kind, states_of(kind)); }
    }
}

// Which lookups the generated code sends to run_tex rather than the plain
// call-out (tex_runs_direct(), decided before the textures are known): under
// Fast's GPU filtering, the RGBA8 1D, 3D and cube textures are its own
// paths' (lanes_only()) and bind no kernel, so run_tex would only add its
// test to the call-out. The bits are the same either way (the sweep above).
TEST_CASE("Fast's GPU-filtered kinds keep the plain call-out", "[runtime][jit_tex]") {
    const LookupKind kinds[] = {{TextureTarget::Tex1D, false, "1D"},
                                {TextureTarget::Tex3D, false, "3D"},
                                {TextureTarget::Cube, false, "cube"},
                                {TextureTarget::Tex2D, true, "shadow 2D"},
                                {TextureTarget::Tex2D, false, "2D"}};
    const State rgba8{TextureFilter::Linear, {TextureWrap::Repeat, TextureWrap::Repeat, TextureWrap::Repeat},
                      CompareFunc::Less, DepthTextureMode::Luminance, {4, 4, 4}, 0, TextureFormat::RGBA8};
    for (const LookupKind& kind : kinds) {
        INFO(kind.name);
        ir::TexInfo info;
        info.target = ir::TexTarget(kind.target);
        info.shadow = kind.shadow;
        ir::Instr in;
        in.op = ir::Op::tex;
        in.imm[2] = info.encode();
        const bool filtered = rt::lanes_only(*texture(kind, rgba8, false, 1u), rt::SamplingRules::Gpu);
        // A 2D colour texture's filtered lookups have Fast's own one-pass sampler.
        const bool own_sampler = kind.target == TextureTarget::Tex2D && !kind.shadow;
        CHECK(filtered == !kind.shadow);
        CHECK(rt::jit::tex_runs_direct(in, true) == (own_sampler || !filtered));
        CHECK(rt::jit::tex_runs_direct(in, false));
    }
}
