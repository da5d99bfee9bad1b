// Differential fuzzing of the backends: random shaders (every op of the
// table, texture lookups included, random structured control flow with
// break, continue, return, discard and loops that may hit the iteration cap)
// run on the interpreter and on the JIT, in Precise and Fast, for the
// baseline and the AVX2 code (and LLVM's quick code generation in Precise),
// half of them under an instruction budget that some batches exhaust; every
// register of every lane, the alive mask and the run's error must be
// bit-identical. Inputs mix ordinary values with the special ones (signed
// zeros, denormals, infinities, NaNs, integer extremes).
//
// Texture lookups are GLSL 1.10/1.20's: texture1D/2D/3D/Cube, their Proj
// forms (but Cube's), shadow1D/2D; in fragment shaders with implicit level
// of detail (derivatives of the coordinates) or a bias, in vertex shaders
// (a third of the programs) with an explicit lod. They sample small
// textures of every target, filter, wrap mode and format, on units that the
// sampler uniforms name (some unbound or out of range).
//
// A quarter of the programs also run specialized on their uniforms
// (ir/specialize.cpp, as ExecOptions::jit_specialize_after does): on both
// backends, which must agree on every register, and against the
// unspecialized interpreter, which they must match on the shader's outputs
// (the registers that specialization must keep; it may drop or hoist writes
// to the others).
//
// Nothing may differ, NaNs included: + and * say which of two NaN operands
// they return (ir::a_nan_first), so the compilers' operand order cannot
// show (tests/runtime/nan_operands_test.cpp checks that op by op).
//
// GLSLRUN_FUZZ_PROGRAMS (default 64) sets how many programs; each runs
// four batches; GLSLRUN_FUZZ_PROGRAM=N runs program N alone and cuts it down
// to the first top-level nodes that differ.
#include <catch2/catch.hpp>

#include <array>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <sstream>

#include "ir/alu_eval.h"
#include "ir/flow.h"
#include "ir/passes.h"
#include "runtime/backend_factory.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

constexpr int kBatches = 4;
constexpr uint64_t kLoopCap = 40;
// The uniform store: words 0..15 hold values, 16..19 the sampler uniforms' units.
constexpr uint32_t kUniformWords = 32, kSamplerWords = 16, kSamplers = 4;

struct Fuzzer {
    std::mt19937 rng;
    Builder b;
    std::vector<Reg> f, i, bo;  // registers by kind: the program's variables
    int loop_depth = 0, scope_depth = 0;
    // Functions that Call nodes may call (each calls only earlier ones), and
    // whether one is being made: its instructions have no random `unmasked`
    // flags (regalloc sets only true ones: the lanes it leaves out are dead,
    // as the JIT's functions assume of their own registers' other lanes).
    std::vector<uint32_t> functions;
    bool in_function = false;
    // A program to specialize reads uniforms more often (more code to fold)
    // and has no random `unmasked` flags: regalloc sets only true ones (no
    // lane reads what the register held), on which specialization relies.
    bool specializing = false;

    Fuzzer(uint32_t seed, ir::Stage stage) : rng(seed), b(stage) {
        for (int k = 0; k < 20; ++k) f.push_back(b.reg(Kind::F32));
        for (int k = 0; k < 8; ++k) i.push_back(b.reg(Kind::I32));
        for (int k = 0; k < 8; ++k) bo.push_back(b.reg(Kind::Bool));
        // The variables are inputs; the first half of each kind are also outputs.
        for (const std::vector<Reg>* regs : {&f, &i, &bo})
            for (size_t k = 0; k < regs->size(); ++k) {
                Reg r = (*regs)[k];
                b.input("in", r);
                if (k < regs->size() / 2) b.output("out", r);
            }
    }
    bool fragment() const { return b.sh.stage == ir::Stage::Fragment; }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
    Reg any(const std::vector<Reg>& regs) { return regs[size_t(pick(int(regs.size())))]; }
    Reg of(Kind k) { return any(k == Kind::F32 ? f : k == Kind::I32 ? i : bo); }
    Kind kind_of(ir::TypeClass c, Kind type) {
        return c == ir::TypeClass::F ? Kind::F32 : c == ir::TypeClass::I ? Kind::I32
                                                  : c == ir::TypeClass::B ? Kind::Bool : type;
    }
    Kind any_kind() { return Kind(pick(3)); }

    uint32_t special_word(Kind k) {
        static const float floats[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 3.0f, 1e-40f, -1e-42f, 1.17549435e-38f,
                                       std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                                       std::numeric_limits<float>::quiet_NaN(), 2147483648.0f, -2147483904.0f,
                                       1e30f, 0.1f, 100.0f, -7.5f};
        static const int32_t ints[] = {0, 1, -1, 2, 7, -8, 31, std::numeric_limits<int32_t>::min(),
                                       std::numeric_limits<int32_t>::max()};
        if (k == Kind::Bool) return uint32_t(pick(8) == 0 ? 2 : pick(2));
        if (k == Kind::I32) return pick(2) ? uint32_t(ints[pick(9)]) : uint32_t(pick(200) - 100);
        if (pick(3) == 0) return bits(floats[pick(18)]);
        return bits(std::uniform_real_distribution<float>(-10.0f, 10.0f)(rng));
    }

    void instr() {
        int roll = pick(100);
        if (specializing && pick(6) == 0) roll = 15;  // a uniform read
        Op op;
        if (roll < 6) op = Op::konst;
        else if (roll < 10) op = Op::mov;
        else if (roll < 14) op = Op::sel;
        else if (roll < 17) op = Op::uniform;
        else if (roll < 19) op = Op::ddx;
        else if (roll < 21) op = Op::ddy;
        else if (roll < 23) op = Op::load_ind;
        else if (roll < 25) op = Op::store_ind;
        else if (roll < 27) op = Op::uniform_ind;
        else if (roll < 30) return tex();
        else {
            do op = Op(pick(int(Op::Count_)));
            while (ir::op_info(op).kind != ir::OpKind::Alu);
        }
        if (!fragment() && (op == Op::ddx || op == Op::ddy)) op = Op::mov;  // derivatives are fragment-only
        const ir::OpInfo& info = ir::op_info(op);
        // load_ind reads a range of the float variables.
        Kind type = op == Op::ddx || op == Op::ddy || op == Op::load_ind ? Kind::F32 : any_kind();
        Kind result = Builder::result_kind(op, type);
        Reg dst = op == Op::store_ind ? ir::kNoReg : of(result);
        std::vector<Reg> src;
        std::vector<uint32_t> imm;
        switch (op) {
        case Op::konst: imm = {special_word(type)}; break;
        case Op::sel: src = {of(Kind::Bool), of(type), of(type)}; break;
        case Op::uniform: imm = {uint32_t(pick(16))}; break;
        case Op::uniform_ind: src = {of(Kind::I32)}; imm = {uint32_t(pick(8)), 4, uint32_t(1 + pick(2))}; break;
        case Op::load_ind: src = {of(Kind::I32)}; imm = {f[size_t(pick(12))], 4, uint32_t(1 + pick(2))}; break;
        case Op::store_ind:
            type = Kind::F32;
            src = {of(Kind::I32), of(Kind::F32)};
            imm = {f[size_t(pick(12))], 4, uint32_t(1 + pick(2))};
            break;
        default:
            for (int k = 0; k < info.arity; ++k) src.push_back(of(kind_of(info.operand, type)));
        }
        ir::Node n;
        n.instr.op = op;
        n.instr.type = op == Op::store_ind ? Kind::F32 : result;
        n.instr.dst = dst;
        for (size_t k = 0; k < src.size(); ++k) n.instr.src[k] = src[k];
        for (size_t k = 0; k < imm.size(); ++k) n.instr.imm[k] = imm[k];
        n.instr.unmasked = pick(10) == 0 && op != Op::store_ind && !specializing && !in_function;
        b.push(std::move(n));
    }

    // A lookup as lower_texture.cpp emits it: the operand block filled by
    // moves (projected coordinates divided by q), derivatives of the
    // coordinates for an implicit lod, the unit from a sampler uniform (or,
    // now and then, any int), and the results read back into variables.
    void tex() {
        ir::TexInfo info;
        info.target = ir::TexTarget(pick(7));
        // shadow1D, shadow2D, shadow2DRect, shadow1DArray, shadow2DArray
        info.shadow = (info.target <= ir::TexTarget::T2D || info.target >= ir::TexTarget::Rect) && pick(3) == 0;
        // texture2DGradARB & co. (either stage): an implicit LOD from given gradients, not ddx/ddy.
        const bool grad = !info.arrayed() && pick(5) == 0;
        info.lod = grad ? ir::TexLod::Implicit
                   : !fragment() ? ir::TexLod::Explicit
                   : pick(3) == 0 ? ir::TexLod::ImplicitBias : ir::TexLod::Implicit;
        const bool proj = info.target != ir::TexTarget::Cube && !info.arrayed() && pick(3) == 0;
        const Reg q = of(Kind::F32);
        auto coordinate = [&] {
            if (!proj) return of(Kind::F32);
            Reg r = b.reg(Kind::F32);
            b.instr(Op::fdiv, Kind::F32, r, {of(Kind::F32), q});
            return r;
        };
        std::vector<Reg> operands;
        for (uint32_t d = 0; d < info.dims(); ++d) operands.push_back(coordinate());
        if (info.shadow) operands.push_back(coordinate());
        if (info.lod != ir::TexLod::Implicit) operands.push_back(of(Kind::F32));  // lod or bias
        if (info.lod != ir::TexLod::Explicit)
            for (Op d : {Op::ddx, Op::ddy})
                for (uint32_t k = 0; k < info.grad_dims(); ++k) {
                    if (grad) {
                        operands.push_back(of(Kind::F32));
                        continue;
                    }
                    Reg r = b.reg(Kind::F32);
                    b.instr(d, Kind::F32, r, {operands[k]});
                    operands.push_back(r);
                }
        const Reg block = b.range(Kind::F32, uint32_t(operands.size()));
        for (size_t k = 0; k < operands.size(); ++k) b.mov(block + Reg(k), operands[k]);
        Reg unit = of(Kind::I32);
        if (pick(6)) {
            unit = b.reg(Kind::I32);
            b.instr(Op::uniform, Kind::I32, unit, {}, {kSamplerWords + uint32_t(pick(kSamplers))});
        }
        const Reg result = b.range(Kind::F32, ir::kTexResults);
        b.instr(Op::tex, Kind::F32, result, {unit}, {block, uint32_t(operands.size()), info.encode()});
        for (uint32_t c = 0; c < ir::kTexResults; ++c)
            if (pick(2)) b.mov(of(Kind::F32), result + c);
    }

    // `count` functions with temporaries of their own (private registers,
    // some read before any write), returns, discards, loops and calls of the
    // earlier ones: the JIT compiles each once and calls it.
    void make_functions(int count) {
        for (int k = 0; k < count; ++k) {
            const size_t floats = f.size(), ints = i.size();
            for (int t = 0; t < 4; ++t) f.push_back(b.reg(Kind::F32));
            i.push_back(b.reg(Kind::I32));
            in_function = true;
            ++scope_depth;
            functions.push_back(b.function("fn", [&] { block(2, 4 + pick(10)); }));
            --scope_depth;
            in_function = false;
            f.resize(floats);
            i.resize(ints);
        }
    }

    void block(int depth, int length) {
        for (int k = 0; k < length; ++k) {
            int roll = pick(100);
            if (depth > 0 && roll < 8) {
                b.if_(of(Kind::Bool), [&] { block(depth - 1, 1 + pick(5)); },
                      pick(2) ? std::function<void()>([&] { block(depth - 1, 1 + pick(4)); }) : nullptr);
            } else if (depth > 0 && roll < 12) {
                ++loop_depth;
                Reg counter = any(i);
                b.loop([&] {
                    // Leaves when a counter passes a bound, or by a random break.
                    Reg stop = any(bo);
                    b.instr(Op::igt, Kind::Bool, stop, {counter, b.ki(pick(6))});
                    b.if_(stop, [&] { b.brk(); });
                    block(depth - 1, 1 + pick(5));
                }, [&] { b.instr(Op::iadd, Kind::I32, counter, {counter, b.ki(1)}); });
                --loop_depth;
            } else if (depth > 0 && roll < 18 && !functions.empty() && pick(2) == 0) {
                b.call(functions[size_t(pick(int(functions.size())))]);
            } else if (depth > 0 && roll < 15) {
                // An inlined function: break and continue cannot leave it.
                const int loops_outside = loop_depth;
                ++scope_depth, loop_depth = 0;
                b.scope([&] { block(depth - 1, 1 + pick(5)); });
                --scope_depth, loop_depth = loops_outside;
            } else if (roll < 18) {
                NodeKind leave = loop_depth > 0 && pick(2) ? (pick(2) ? NodeKind::Break : NodeKind::Continue)
                                 : scope_depth > 0 && pick(2) ? NodeKind::Return
                                                              : NodeKind::Discard;
                if (leave == NodeKind::Discard && !fragment()) instr();
                else b.if_(of(Kind::Bool), [&] { b.leaf(leave); });
            } else {
                instr();
            }
        }
    }
};

struct Batch {
    std::vector<uint32_t> words;  // every register's lanes
    rt::LaneMask live;
};

// Textures of every target, filter, wrap mode and format on units 0..4; unit
// 5 has none. Texels are fixed pseudo-random values (outside [0, 1] in the
// float formats).
std::array<GLState::TextureUnit, kMaxTextureUnits> make_textures() {
    std::mt19937 rng(0x7e47u);
    auto image = [&](int w, int h, int d, float lo, float hi) {
        TextureImage img{w, h, d, {}};
        std::uniform_real_distribution<float> value(lo, hi);
        for (int k = 0; k < w * h * d; ++k) img.texels.push_back({value(rng), value(rng), value(rng), value(rng)});
        return img;
    };
    auto make = [](TextureTarget target, std::vector<TextureImage> faces, TextureFormat format, auto&& set) {
        Result<Texture> t = Texture::create(target, std::move(faces), format);
        REQUIRE(t.ok());
        set(*t);
        return std::make_shared<const Texture>(std::move(*t));
    };
    std::array<GLState::TextureUnit, kMaxTextureUnits> units{};
    auto bind = [&](int unit, std::shared_ptr<const Texture> t) { units[size_t(unit)].bound[size_t(t->target())] = t; };
    bind(0, make(TextureTarget::Tex2D, {image(4, 4, 1, 0, 1)}, TextureFormat::RGBA8, [](Texture& t) {
        t.generate_mipmaps();  // trilinear, repeat
        t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    }));
    bind(1, make(TextureTarget::Tex2D, {image(4, 2, 1, 0, 1)}, TextureFormat::Depth, [](Texture& t) {
        t.sampler.compare = true;  // shadow2D
        t.sampler.min_filter = TextureFilter::Linear;
        t.sampler.mag_filter = TextureFilter::Nearest;
        t.sampler.wrap_s = t.sampler.wrap_t = TextureWrap::ClampToEdge;
    }));
    bind(1, make(TextureTarget::Tex1D, {image(4, 1, 1, 0, 1)}, TextureFormat::Depth, [](Texture& t) {
        t.generate_mipmaps();  // shadow1D, alpha result, mipmapped
        t.sampler.compare = true;
        t.sampler.compare_func = CompareFunc::Greater;
        t.sampler.depth_mode = DepthTextureMode::Alpha;
        t.sampler.min_filter = TextureFilter::NearestMipmapNearest;
    }));
    bind(2, make(TextureTarget::Cube, std::vector<TextureImage>(6, image(2, 2, 1, -2, 3)), TextureFormat::RGBA32F,
                 [](Texture& t) {
                     t.sampler.min_filter = TextureFilter::Nearest;
                     t.sampler.wrap_s = t.sampler.wrap_t = TextureWrap::ClampToEdge;
                     t.sampler.lod_bias = 0.5f;
                 }));
    bind(2, make(TextureTarget::Tex2D, {image(3, 5, 1, 0, 1)}, TextureFormat::RGBA8, [](Texture& t) {
        t.sampler.min_filter = t.sampler.mag_filter = TextureFilter::Nearest;  // not a power of two, GL_CLAMP
        t.sampler.wrap_s = t.sampler.wrap_t = TextureWrap::Clamp;
    }));
    bind(3, make(TextureTarget::Tex3D, {image(2, 2, 2, 0, 1)}, TextureFormat::RGBA8, [](Texture& t) {
        t.generate_mipmaps();
        t.sampler.min_filter = TextureFilter::LinearMipmapNearest;
        t.sampler.wrap_s = t.sampler.wrap_t = t.sampler.wrap_r = TextureWrap::MirroredRepeat;
    }));
    bind(0, make(TextureTarget::Rect, {image(5, 3, 1, 0, 1)}, TextureFormat::RGBA8, [](Texture& t) {
        t.sampler.wrap_s = TextureWrap::ClampToBorder;  // texture2DRect: linear, the border on s
        t.sampler.wrap_t = TextureWrap::Clamp;
        t.sampler.border_color = {0.5f, 0.25f, 1.0f, 0.0f};
    }));
    bind(1, make(TextureTarget::Rect, {image(4, 6, 1, 0, 1)}, TextureFormat::Depth, [](Texture& t) {
        t.sampler.compare = true;  // shadow2DRect, nearest when minified
        t.sampler.min_filter = TextureFilter::Nearest;
        t.sampler.depth_mode = DepthTextureMode::Intensity;
    }));
    bind(4, make(TextureTarget::Rect, {image(7, 2, 1, -1, 2)}, TextureFormat::RGBA32F, [](Texture& t) {
        t.sampler.mag_filter = TextureFilter::Nearest;  // linear when minified, a LOD bias
        t.sampler.lod_bias = -0.5f;
    }));
    bind(5, make(TextureTarget::Tex2DArray, {image(4, 2, 3, 0, 1)}, TextureFormat::RGBA8, [](Texture& t) {
        t.generate_mipmaps();  // texture2DArray: trilinear within a layer
        t.sampler.min_filter = TextureFilter::LinearMipmapLinear;
    }));
    bind(5, make(TextureTarget::Tex1DArray, {image(4, 3, 1, 0, 1)}, TextureFormat::Depth, [](Texture& t) {
        t.sampler.compare = true;  // shadow1DArray, linear, clamped
        t.sampler.min_filter = TextureFilter::Linear;
        t.sampler.wrap_s = TextureWrap::ClampToEdge;
    }));
    bind(4, make(TextureTarget::Tex1D, {image(8, 1, 1, -1, 2)}, TextureFormat::RGBA32F, [](Texture& t) {
        t.generate_mipmaps();  // border colour, a clamped lod range from level 1
        t.sampler.min_filter = TextureFilter::NearestMipmapLinear;
        t.sampler.wrap_s = TextureWrap::ClampToBorder;
        t.sampler.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
        t.sampler.min_lod = 0.5f, t.sampler.max_lod = 2.0f, t.sampler.base_level = 1;
    }));
    return units;
}

// What one backend leaves: the runs' errors, and per batch the alive mask
// and every register's lanes.
struct Outcome {
    std::string log;
    std::vector<uint32_t> words;
};

Outcome run_all(rt::Executor& e, const ir::Shader& shader, const std::vector<Batch>& batches) {
    // Each batch sets every register but those of the prologue (a
    // specialization's hoisted code), which it computed once for all lanes.
    std::vector<bool> set(shader.regs.size(), true);
    for (const ir::Node& n : shader.prologue) ir::flow::for_each_write(n.instr, [&](Reg r) { set[r] = false; });
    Outcome out;
    for (const Batch& batch : batches) {
        for (size_t r = 0; r < shader.regs.size(); ++r)
            if (set[r]) std::copy_n(batch.words.begin() + long(r * rt::kLanes), rt::kLanes, e.lanes(Reg(r)));
        rt::RunError error;
        bool ok = e.run(batch.live, &error);
        out.log += ok ? "ok;" : error.message + "@" + std::to_string(error.line) + ";";
        out.words.push_back(uint32_t(e.alive()));
        out.words.push_back(uint32_t(e.alive() >> 32));
        for (size_t r = 0; r < shader.regs.size(); ++r)
            out.words.insert(out.words.end(), e.lanes(Reg(r)), e.lanes(Reg(r)) + rt::kLanes);
    }
    return out;
}

struct Config {
    Precision precision;
    bool avx2, quick;
    uint64_t max_instructions;
    const GLState::TextureUnit* textures;
};

Outcome run_on(const ir::Shader& shader, rt::Runner runner, const std::vector<uint32_t>& uniforms,
               const std::vector<Batch>& batches, const Config& c) {
    rt::ExecParams params{uniforms.data(), kLoopCap, c.textures, c.precision, rt::kAllFastOps};
    params.limits.max_instructions = c.max_instructions;
    auto code = rt::compile_shader(shader, runner, c.precision, params.fast_ops, c.avx2, nullptr,
                                   runner == rt::Runner::Jit && c.quick);
    auto e = code->instantiate(params);
    REQUIRE(e->runner() == runner);
    return run_all(*e, shader, batches);
}

std::vector<Reg> output_registers(const ir::Shader& shader) {
    std::vector<Reg> regs;
    for (const ir::Binding& b : shader.outputs)
        for (uint32_t k = 0; k < b.count; ++k) regs.push_back(b.first + k);
    return regs;
}

// `o` (every register) cut down to the outputs of `shader`.
Outcome outputs_of(const Outcome& o, const ir::Shader& shader) {
    const size_t per_batch = 2 + shader.regs.size() * rt::kLanes;
    Outcome out{o.log, {}};
    for (size_t batch = 0; batch < o.words.size() / per_batch; ++batch) {
        auto at = o.words.begin() + long(batch * per_batch);
        out.words.insert(out.words.end(), at, at + 2);
        for (Reg r : output_registers(shader))
            out.words.insert(out.words.end(), at + long(2 + r * rt::kLanes), at + long(2 + (r + 1) * rt::kLanes));
    }
    return out;
}

// The specialization of `shader` on `uniforms` (ExecOptions::jit_specialize_after's).
ir::Shader specialized(const ir::Shader& shader, const std::vector<uint32_t>& uniforms, Precision precision) {
    ir::Shader s = shader;
    const std::string error = ir::specialize(s, uniforms, precision == Precision::Fast ? uint32_t(rt::kAllFastOps) : 0u);
    INFO(error);
    REQUIRE(error.empty());
    return s;
}

// The first difference of one program in one configuration, on the outputs
// (what a caller may read after a run: the JIT keeps the body's other
// registers out of the register file): the JIT against the interpreter;
// specialized, the JIT's code of the specialization against the
// interpreter's, and the interpreter's against its unspecialized run.
std::string first_difference(const ir::Shader& shader, bool specialize, const std::vector<uint32_t>& uniforms,
                             const std::vector<Batch>& batches, const Config& c, std::string* log) {
    auto differ = [&](const char* what, const Outcome& a, const Outcome& b, const ir::Shader& sh, bool outputs) {
        if (a.log != b.log) return std::string(what) + ": the runs end differently: " + a.log + " vs " + b.log;
        size_t first = 0;
        while (first < a.words.size() && a.words[first] == b.words[first]) ++first;
        if (first == a.words.size()) return std::string();
        std::vector<Reg> regs = output_registers(sh);
        if (!outputs) {
            regs.resize(sh.regs.size());
            for (size_t r = 0; r < regs.size(); ++r) regs[r] = Reg(r);
        }
        const size_t per_batch = 2 + regs.size() * rt::kLanes, word = first % per_batch;
        std::ostringstream out;
        out << what << ": batch " << first / per_batch << ", "
            << (word < 2 ? std::string("alive mask")
                         : "register %" + std::to_string(regs[(word - 2) / rt::kLanes]) + " lane " +
                               std::to_string((word - 2) % rt::kLanes))
            << ": " << std::hex << a.words[first] << " vs " << b.words[first];
        return out.str();
    };
    const Outcome interp = run_on(shader, rt::Runner::Interp, uniforms, batches, c);
    *log = interp.log;
    std::string d = differ("interpreter vs JIT", outputs_of(interp, shader),
                           outputs_of(run_on(shader, rt::Runner::Jit, uniforms, batches, c), shader), shader, true);
    if (!d.empty() || !specialize) return d;
    const ir::Shader s = specialized(shader, uniforms, c.precision);
    const Outcome s_interp = run_on(s, rt::Runner::Interp, uniforms, batches, c);
    d = differ("specialized interpreter vs specialized JIT", outputs_of(s_interp, s),
               outputs_of(run_on(s, rt::Runner::Jit, uniforms, batches, c), s), s, true);
    if (!d.empty()) return d;
    return differ("interpreter vs specialized interpreter, outputs", outputs_of(interp, shader),
                  outputs_of(s_interp, s), shader, true);
}

// Alone, a program is cut down to the top-level node after which the
// backends differ: "" when the whole program agrees.
template <class Differs>
std::string cut_down(ir::Shader& shader, const std::vector<Batch>& batches, Differs&& differs) {
    ir::Block body = shader.body;
    std::string where;
    for (size_t n = 1; n <= body.size(); ++n) {
        shader.body.assign(body.begin(), body.begin() + long(n));
        if (!differs(shader)) continue;
        where = "\nthe first " + std::to_string(n) + " nodes differ:\n" + ir::print(shader) + "unmasked:";
        std::function<void(const ir::Block&)> list = [&](const ir::Block& block) {
            for (const ir::Node& node : block) {
                if (node.kind == NodeKind::Instr && node.instr.unmasked) where += " %" + std::to_string(node.instr.dst);
                list(node.body), list(node.alt);
            }
        };
        list(shader.body);
        for (const Batch& batch : batches) where += "\nlive " + std::to_string(batch.live);
        break;
    }
    shader.body = body;
    return where;
}

}  // namespace

TEST_CASE("backends agree bit for bit on random shaders", "[runtime][backend][fuzz]") {
    if (!jit_available()) SUCCEED("built without the JIT");
    int programs = 64;
    if (const char* n = std::getenv("GLSLRUN_FUZZ_PROGRAMS")) programs = std::atoi(n);
    int first_program = 0;
    if (const char* one = std::getenv("GLSLRUN_FUZZ_PROGRAM")) first_program = std::atoi(one), programs = 1;
    const bool avx2 = rt::cpu_has_avx2();
    const auto textures = make_textures();
    int compared = 0, over_budget = 0, specialized_runs = 0, vertex = 0;
    for (int p = first_program; p < first_program + programs && jit_available(); ++p) {
        const ir::Stage stage = p % 3 == 2 ? ir::Stage::Vertex : ir::Stage::Fragment;
        const bool specialize = p % 4 == 2;
        Fuzzer fz(0x5eed0000u + uint32_t(p), stage);
        fz.specializing = specialize;
        if (p % 3 == 1) fz.make_functions(1 + fz.pick(3));
        fz.block(3, 30);
        ir::Shader& shader = fz.b.sh;
        INFO("program " << p);
        REQUIRE(ir::verify(shader) == "");
        vertex += stage == ir::Stage::Vertex;
        // Every other program has a small instruction budget, which some
        // batches exhaust; specialization changes the count, so a quarter
        // of the others run specialized.
        const uint64_t max_instructions = p % 2 ? uint64_t(20 + fz.pick(400)) : ExecOptions{}.max_instructions;
        std::vector<uint32_t> uniforms(kUniformWords);
        for (uint32_t& u : uniforms) u = fz.special_word(fz.any_kind());
        for (uint32_t k = 0; k < kSamplers; ++k) {
            static const int32_t units[] = {0, 1, 2, 3, 4, 5, -1, kMaxTextureUnits};
            uniforms[kSamplerWords + k] = uint32_t(units[fz.pick(fz.pick(4) ? 6 : 8)]);
        }
        std::vector<Batch> batches(kBatches);
        for (Batch& batch : batches) {
            for (size_t r = 0; r < shader.regs.size(); ++r)
                for (int lane = 0; lane < rt::kLanes; ++lane) batch.words.push_back(fz.special_word(shader.regs[r]));
            batch.live = fz.pick(4) == 0 ? rt::kAllLanes >> (4 * (1 + fz.pick(rt::kLanes / 4 - 1))) : rt::kAllLanes;
        }
        for (Precision precision : {Precision::Precise, Precision::Fast})
            for (int config = 0; config < 3; ++config) {
                // Baseline, AVX2, and (Precise only) quick code generation for this CPU.
                const bool isa = config == 1 || (config == 2 && avx2), quick = config == 2;
                if ((config == 1 && !avx2) || (quick && precision != Precision::Precise)) continue;
                INFO(precision_name(precision) << (isa ? ", avx2" : ", baseline") << (quick ? ", quick codegen" : ""));
                const Config c{precision, isa, quick, max_instructions, textures.data()};
                std::string log;
                const std::string difference = first_difference(shader, specialize, uniforms, batches, c, &log);
                if (!difference.empty()) {
                    std::string where;
                    if (programs == 1)
                        where = cut_down(shader, batches, [&](const ir::Shader& sh) {
                            std::string l;
                            return !first_difference(sh, specialize, uniforms, batches, c, &l).empty();
                        });
                    FAIL(difference << where);
                }
                over_budget += log.find("instructions in one batch") != std::string::npos;
                ++compared;
                specialized_runs += specialize;
            }
    }
    WARN(compared << " program runs compared (" << specialized_runs << " also specialized; " << vertex
                  << " vertex programs), " << over_budget << " stopped by the instruction budget");
    CHECK((compared > 0 || !jit_available()));
}
