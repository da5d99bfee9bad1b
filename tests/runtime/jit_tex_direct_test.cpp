// The JIT's 2D and rectangle lookups that call the unit's one-pass sampler
// from generated code (runtime/jit/tex_direct.cpp) against the
// interpreter's `tex` kernel (Precise, and Fast with and without its GPU
// filtering): every filter and wrap pair of both targets,
// odd sizes, RGBA8 and float texels, NaN, infinite, huge and denormal
// coordinates, partial masks, lanes that skip their lookups, lanes of
// another unit or of none, an incomplete texture; every result word compared.
// Both run the same one-pass kernels, so batches of close lanes (a magnified
// image's, as the rasterizer packs them) are also compared with the lane
// sampler, which shares no code with them; mipmapped 2D textures' too
// (the call-out's kernel reads each quad's derivatives from its first lane).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "runtime/backend_factory.h"
#include "runtime/interp_kernels.h"
#include "runtime/sampling.h"
#include "runtime/sampling_rules.h"
#include "tests/runtime/ir_builder.h"
#include "tests/runtime/jit_tex_modes.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

constexpr int kUnit = 3;        // the state under test, 2D and rectangle
constexpr int kOtherUnit = 6;   // a nearest REPEAT texture of each target
constexpr int kIncomplete = 9;  // mipmap filters, no mipmaps: (0, 0, 0, 1)

std::shared_ptr<const Texture> texture(TextureTarget target, int w, int h, TextureFormat format, TextureFilter filter,
                                       TextureWrap ws, TextureWrap wt, uint32_t seed, bool mipmaps = false) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(format == TextureFormat::RGBA8 ? 0.0f : -2.0f, 2.0f);
    TextureImage img{w, h, 1, {}};
    for (int k = 0; k < w * h; ++k) img.texels.push_back({value(rng), value(rng), value(rng), value(rng)});
    Result<Texture> t = Texture::create(target, {std::move(img)}, format);
    REQUIRE(t.ok());
    t->sampler.min_filter = t->sampler.mag_filter = filter;
    if (mipmaps) {  // the mipmapped 2D kernel: the same filter within a level for both
        t->generate_mipmaps();
        t->sampler.mag_filter = rt::sampling::linear_within_level(filter) ? TextureFilter::Linear : TextureFilter::Nearest;
    }
    t->sampler.wrap_s = ws;
    t->sampler.wrap_t = wt;
    t->sampler.border_color = {0.25f, 1.5f, -0.5f, 0.75f};  // clamped to [0, 1] by the sampler
    return std::make_shared<const Texture>(std::move(*t));
}

// A coordinate on an axis of `size` (1 when normalized): inside, around and far
// outside the image, and the special values.
float coordinate(std::mt19937& rng, float size) {
    static constexpr float kSpecial[] = {std::numeric_limits<float>::quiet_NaN(),
                                         std::numeric_limits<float>::infinity(),
                                         -std::numeric_limits<float>::infinity(),
                                         1e30f, -1e30f, 16777216.0f, -16777217.0f, 8388609.5f,
                                         1e-40f, -0.0f, 0.0f, 1.0f, 0.5f, -0.5f};
    const int pick = int(rng() % 8);
    if (pick == 0) return kSpecial[rng() % (sizeof kSpecial / sizeof kSpecial[0])];
    std::uniform_real_distribution<float> near(-2.5f * size, 3.5f * size);
    return near(rng);
}

struct Shader {
    Builder b;
    Reg s, t, lod, unit, unit_lane, cond, block, explicit_block, result, explicit_result;
};

// Two lookups of one target: an implicit one (derivatives of the
// coordinates) whose unit is a uniform's, under an if, and an explicit-LOD
// one whose unit is each lane's own.
std::unique_ptr<Shader> make_shader(ir::TexTarget target) {
    auto sh = std::make_unique<Shader>();
    Builder& b = sh->b;
    sh->s = b.reg(Kind::F32);
    sh->t = b.reg(Kind::F32);
    sh->lod = b.reg(Kind::F32);
    sh->unit_lane = b.reg(Kind::I32);
    sh->cond = b.reg(Kind::Bool);
    for (Reg r : {sh->s, sh->t, sh->lod, sh->unit_lane, sh->cond}) b.input("in", r);
    sh->unit = b.reg(Kind::I32);
    b.instr(Op::uniform, Kind::I32, sh->unit, {}, {0});
    ir::TexInfo implicit;
    implicit.target = target;
    sh->block = b.range(Kind::F32, implicit.operand_count());
    b.mov(sh->block, sh->s);
    b.mov(sh->block + 1, sh->t);
    b.instr(Op::ddx, Kind::F32, sh->block + 2, {sh->s});
    b.instr(Op::ddx, Kind::F32, sh->block + 3, {sh->t});
    b.instr(Op::ddy, Kind::F32, sh->block + 4, {sh->s});
    b.instr(Op::ddy, Kind::F32, sh->block + 5, {sh->t});
    sh->result = b.range(Kind::F32, ir::kTexResults);
    b.if_(sh->cond, [&] {
        b.instr(Op::tex, Kind::F32, sh->result, {sh->unit}, {sh->block, implicit.operand_count(), implicit.encode()});
    });
    ir::TexInfo explicit_lod = implicit;
    explicit_lod.lod = ir::TexLod::Explicit;
    sh->explicit_block = b.range(Kind::F32, explicit_lod.operand_count());
    b.mov(sh->explicit_block, sh->t);  // the coordinates swapped: s from t
    b.mov(sh->explicit_block + 1, sh->s);
    b.mov(sh->explicit_block + 2, sh->lod);
    sh->explicit_result = b.range(Kind::F32, ir::kTexResults);
    b.instr(Op::tex, Kind::F32, sh->explicit_result, {sh->unit_lane},
            {sh->explicit_block, explicit_lod.operand_count(), explicit_lod.encode()});
    for (uint32_t c = 0; c < ir::kTexResults; ++c) {
        b.output("r", sh->result + c);
        b.output("e", sh->explicit_result + c);
    }
    return sh;
}

using Mode = TexMode;

struct Case {
    Mode mode;
    bool rect;
    TextureFilter filter;
    TextureWrap ws, wt;
    int w, h;
    TextureFormat format;
    uint32_t seed;
};

// The units of one case: its state on kUnit, and the other units' textures.
std::array<GLState::TextureUnit, kMaxTextureUnits> units_of(const Case& c) {
    using enum TextureWrap;
    const TextureTarget target = c.rect ? TextureTarget::Rect : TextureTarget::Tex2D;
    std::array<GLState::TextureUnit, kMaxTextureUnits> units{};
    auto bind = [&](int unit, std::shared_ptr<const Texture> t) {
        units[size_t(unit)].bound[size_t(t->target())] = std::move(t);
    };
    bind(kUnit, texture(target, c.w, c.h, c.format, c.filter, c.ws, c.wt, c.seed,
                        rt::is_mipmap_filter(c.filter)));
    bind(kOtherUnit, texture(target, 3, 2, TextureFormat::RGBA8, TextureFilter::Nearest, Repeat, Repeat, 7u));
    if (!c.rect)  // a rectangle has no mipmap filter: none bound on its unit
        bind(kIncomplete, texture(target, 4, 4, TextureFormat::RGBA8, TextureFilter::LinearMipmapLinear, Repeat,
                                  Repeat, 9u));
    return units;
}

// Lane i's coordinate on one axis of a magnified image, as the rasterizer
// packs lanes (quad i / 4 at (2 (q % 4), 2 (q / 4)) of an 8x4 block, the
// lane at (i & 1, i >> 1 & 1) in it): each pixel `scale` texels from
// `origin`; divided by `size` where normalized.
float close_coordinate(int lane, int axis, float origin, float scale, float size) {
    const int q = lane / 4;
    const int pixel = axis == 0 ? 2 * (q % 4) + (lane & 1) : 2 * (q / 4) + ((lane >> 1) & 1);
    return (origin + (float(pixel) + 0.5f) * scale) / size;
}

// The lane sampler's words for the implicit lookup of kUnit at (s, t)
// with derivatives (ddx, ddy) (a mipmapped texture's: its quad's first lane's).
std::array<uint32_t, 4> lane_sample(const Texture& texture, float s, float t, glm::vec2 ddx, glm::vec2 ddy) {
    rt::LaneLookup lane;
    lane.coord = {s, t, 0.0f};
    lane.ddx = {ddx, 0.0f};
    lane.ddy = {ddy, 0.0f};
    float rgba[4];
    if (texture.target() == TextureTarget::Rect) rt::sample_rect_lane(texture, lane, rgba);
    else rt::sample_complete_lane(texture, lane, rgba);
    return {bits(rgba[0]), bits(rgba[1]), bits(rgba[2]), bits(rgba[3])};
}

// Both backends over one case, eight rounds: 0-1 whole batches (1: the if
// taken by two lanes of three); 2 a partial live mask (whole quads where mipmapped); 3 helper lanes that
// skip their lookups; 4-5 mixed units per lane (some out of range); 6-7
// close lanes (0.3 and 0.6 texels a pixel; a mipmapped texture's 0.3 and
// 2.7, minified), Precise's also against the lane sampler.
void compare(const Shader& sh, const rt::CompiledShader& interp, const rt::CompiledShader& jit, const Case& c) {
    const auto units = units_of(c);
    const uint32_t uniforms[] = {uint32_t(kUnit)};
    const rt::ExecParams params{uniforms, 10, units.data(), c.mode.precision, c.mode.fast_ops};
    auto ia = interp.instantiate(params), ja = jit.instantiate(params);
    std::mt19937 rng(c.seed * 977u);
    const float scale_s = c.rect ? float(c.w) : 1.0f, scale_t = c.rect ? float(c.h) : 1.0f;
    for (int round = 0; round < 8; ++round) {
        // A mipmapped texture's partial mask keeps quads whole: a quad's LOD
        // is its first lane's, whose derivative registers the two backends
        // leave differently where that lane is not live.
        const uint64_t partial = rt::is_mipmap_filter(c.filter) ? 0x0ff00ff00ff00ff0ull : 0x5a5a5a5a5a5a5a5aull;
        const rt::LaneMask live = round == 2 ? rt::LaneMask(partial) & rt::kAllLanes : rt::kAllLanes;
        const rt::LaneMask skipped = round == 3 ? rt::LaneMask(0x0f0f0f0f0f0f0f0full) & rt::kAllLanes : 0;
        std::vector<float> s(rt::kLanes), t(rt::kLanes);
        const bool close = round >= 6;
        const float origin_s = std::uniform_real_distribution<float>(-2.0f, float(c.w) + 2.0f)(rng);
        const float origin_t = std::uniform_real_distribution<float>(-2.0f, float(c.h) + 2.0f)(rng);
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            const float texels = round == 6 ? 0.3f : (rt::is_mipmap_filter(c.filter) ? 2.7f : 0.6f);
            s[size_t(lane)] = close ? close_coordinate(lane, 0, origin_s, texels, c.rect ? 1.0f : float(c.w))
                                    : coordinate(rng, scale_s);
            t[size_t(lane)] = close ? close_coordinate(lane, 1, origin_t, texels, c.rect ? 1.0f : float(c.h))
                                    : coordinate(rng, scale_t);
        }
        for (rt::Executor* e : {ia.get(), ja.get()}) {
            e->skip_lookups(skipped);
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                const int mixed[] = {kUnit, kOtherUnit, kIncomplete, -1, 40};
                const int unit = round < 4 || close ? kUnit : mixed[(lane + round) % 5];
                e->lanes(sh.s)[lane] = bits(s[size_t(lane)]);
                e->lanes(sh.t)[lane] = bits(t[size_t(lane)]);
                e->lanes(sh.lod)[lane] = bits(float(lane % 3) - 1.0f);
                e->lanes(sh.unit_lane)[lane] = bits(round == 5 && lane ? kOtherUnit : unit);
                e->lanes(sh.cond)[lane] = round == 1 ? (lane % 3 != 0) : 1;
                for (uint32_t k = 0; k < ir::kTexResults; ++k) {
                    e->lanes(sh.result + k)[lane] = 0xdeadbeefu;
                    e->lanes(sh.explicit_result + k)[lane] = 0xdeadbeefu;
                }
            }
        }
        REQUIRE(ia->run(live, nullptr));
        REQUIRE(ja->run(live, nullptr));
        for (const ir::Binding& out : sh.b.sh.outputs)
            for (int lane = 0; lane < rt::kLanes; ++lane) {
                INFO((c.rect ? "rect" : "2D") << " precision " << int(c.mode.precision) << " fast_ops "
                     << c.mode.fast_ops << " filter " << int(c.filter) << " wrap " << int(c.ws) << "," << int(c.wt)
                     << " " << c.w << "x" << c.h << " round " << round << " lane " << lane << " s "
                     << s[size_t(lane)] << " t " << t[size_t(lane)] << " register " << out.first);
                REQUIRE(ia->lanes(out.first)[lane] == ja->lanes(out.first)[lane]);
            }
        const Texture& tex = *units[size_t(kUnit)].bound[size_t(c.rect ? TextureTarget::Rect : TextureTarget::Tex2D)];
        if (!close || c.mode.precision != Precision::Precise || !tex.complete()) continue;  // incomplete: (0, 0, 0, 1)
        for (int lane = 0; lane < rt::kLanes; ++lane) {
            const auto derivative = [&](uint32_t k) { return ia->lanes_f(sh.block + k)[lane & ~3]; };
            const std::array<uint32_t, 4> want = lane_sample(tex, s[size_t(lane)], t[size_t(lane)],
                                                             {derivative(2), derivative(3)}, {derivative(4), derivative(5)});
            for (uint32_t k = 0; k < ir::kTexResults; ++k) {
                INFO((c.rect ? "rect" : "2D") << " filter " << int(c.filter) << " wrap " << int(c.ws) << ","
                     << int(c.wt) << " " << c.w << "x" << c.h << " round " << round << " lane " << lane << " s "
                     << s[size_t(lane)] << " t " << t[size_t(lane)] << " channel " << k);
                REQUIRE(ja->lanes(sh.result + k)[lane] == want[k]);
            }
        }
    }
}

}  // namespace

TEST_CASE("generated 2D and rectangle lookups give the tex kernel's words", "[runtime][backend][jit_tex]") {
    if (!jit_available() || !rt::cpu_has_avx2()) return;
    using enum TextureWrap;
    const TextureWrap wraps[] = {Repeat, MirroredRepeat, ClampToEdge, Clamp, ClampToBorder};
    const int sizes[][2] = {{5, 3}, {1, 1}, {7, 1}, {1, 6}, {13, 11}, {4, 4}, {9, 6}};
    for (const Mode& mode : kTexModes)
        for (const bool rect : {false, true}) {
            auto sh = make_shader(rect ? ir::TexTarget::Rect : ir::TexTarget::T2D);
            auto interp = rt::compile_shader(sh->b.sh, rt::Runner::Interp, mode.precision, mode.fast_ops, true);
            auto jit = rt::compile_shader(sh->b.sh, rt::Runner::Jit, mode.precision, mode.fast_ops, true);
            REQUIRE(jit);
            uint32_t state = 0;
            for (const TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear,
                                               TextureFilter::LinearMipmapLinear, TextureFilter::NearestMipmapNearest})
                for (const TextureWrap ws : wraps)
                    for (const TextureWrap wt : wraps) {
                        if (rect && rt::is_mipmap_filter(filter)) continue;  // no mipmaps
                        const int* size = sizes[state % 7];
                        const TextureFormat format = state % 3 == 2 ? TextureFormat::RGBA32F : TextureFormat::RGBA8;
                        compare(*sh, *interp, *jit, {mode, rect, filter, ws, wt, size[0], size[1], format, ++state});
                    }
        }
}
