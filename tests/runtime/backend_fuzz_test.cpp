// Differential fuzzing of the backends: random shaders (every op of the
// table but tex, random structured control flow with break, continue,
// return, discard and loops that may hit the iteration cap) run on the
// interpreter and on the JIT, in Precise and Fast, for the baseline and the
// AVX2 code (and LLVM's quick code generation in Precise), half of them under an instruction budget that some batches
// exhaust; every register of every lane, the alive mask and the run's error
// must be bit-identical. Inputs mix ordinary values with the special
// ones (signed zeros, denormals, infinities, NaNs, integer extremes).
//
// Nothing may differ, NaNs included: + and * say which of two NaN operands
// they return (ir::a_nan_first), so the compilers' operand order cannot
// show (tests/runtime/nan_operands_test.cpp checks that op by op).
//
// GLSLRUN_FUZZ_PROGRAMS (default 64) sets how many programs; each runs
// four batches; GLSLRUN_FUZZ_PROGRAM=N runs program N alone and cuts it down
// to the first top-level nodes that differ.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <limits>
#include <random>

#include "ir/alu_eval.h"
#include "ir/passes.h"
#include "runtime/backend.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

constexpr int kBatches = 4;
constexpr uint64_t kLoopCap = 40;

struct Fuzzer {
    std::mt19937 rng;
    Builder b;
    std::vector<Reg> f, i, bo;  // registers by kind
    int loop_depth = 0, scope_depth = 0;

    explicit Fuzzer(uint32_t seed) : rng(seed) {
        for (int k = 0; k < 20; ++k) f.push_back(b.reg(Kind::F32));
        for (int k = 0; k < 8; ++k) i.push_back(b.reg(Kind::I32));
        for (int k = 0; k < 8; ++k) bo.push_back(b.reg(Kind::Bool));
    }
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
        else {
            do op = Op(pick(int(Op::Count_)));
            while (ir::op_info(op).kind != ir::OpKind::Alu);
        }
        const ir::OpInfo& info = ir::op_info(op);
        Kind type = op == Op::ddx || op == Op::ddy ? Kind::F32 : any_kind();
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
        n.instr.unmasked = pick(10) == 0 && op != Op::store_ind;
        b.push(std::move(n));
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
            } else if (depth > 0 && roll < 15) {
                ++scope_depth;
                b.scope([&] { block(depth - 1, 1 + pick(5)); });
                --scope_depth;
            } else if (roll < 18) {
                NodeKind leave = loop_depth > 0 && pick(2) ? (pick(2) ? NodeKind::Break : NodeKind::Continue)
                                 : scope_depth > 0 && pick(2) ? NodeKind::Return
                                                              : NodeKind::Discard;
                b.if_(of(Kind::Bool), [&] { b.leaf(leave); });
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

// Runs `shader` on `executor` for each batch; returns what it left.
std::string run_all(rt::Executor& e, const ir::Shader& shader, const std::vector<Batch>& batches,
                    std::vector<uint32_t>* out) {
    std::string log;
    for (const Batch& batch : batches) {
        for (size_t r = 0; r < shader.regs.size(); ++r)
            std::copy_n(batch.words.begin() + long(r * rt::kLanes), rt::kLanes, e.lanes(Reg(r)));
        rt::RunError error;
        bool ok = e.run(batch.live, &error);
        log += ok ? "ok;" : error.message + "@" + std::to_string(error.line) + ";";
        out->push_back(uint32_t(e.alive()));
        out->push_back(uint32_t(e.alive() >> 32));
        for (size_t r = 0; r < shader.regs.size(); ++r) out->insert(out->end(), e.lanes(Reg(r)), e.lanes(Reg(r)) + rt::kLanes);
    }
    return log;
}

// The first word where the backends differ on `shader` (size when none).
size_t first_difference(const ir::Shader& shader, const std::vector<uint32_t>& uniforms, const std::vector<Batch>& batches,
                        uint64_t max_instructions, Precision precision, bool avx2, bool quick, std::string* logs,
                        uint32_t* words) {
    rt::ExecParams params{uniforms.data(), kLoopCap, nullptr, precision, rt::kAllFastOps};
    params.limits.max_instructions = max_instructions;
    auto interp = rt::compile_shader(shader, Backend::Interp, precision, params.fast_ops, avx2);
    auto jit = rt::compile_shader(shader, Backend::Jit, precision, params.fast_ops, avx2, nullptr, quick);
    auto a = interp->instantiate(params);
    auto b = jit->instantiate(params);
    REQUIRE(b->backend() == Backend::Jit);
    std::vector<uint32_t> words_a, words_b;
    logs[0] = run_all(*a, shader, batches, &words_a);
    logs[1] = run_all(*b, shader, batches, &words_b);
    size_t first = 0;
    while (first < words_a.size() && words_a[first] == words_b[first]) ++first;
    if (first < words_a.size()) words[0] = words_a[first], words[1] = words_b[first];
    return first == words_a.size() ? std::string::npos : first;
}

}  // namespace

TEST_CASE("backends agree bit for bit on random shaders", "[runtime][backend][fuzz]") {
    if (!jit_available()) SUCCEED("built without the JIT");
    int programs = 64;
    if (const char* n = std::getenv("GLSLRUN_FUZZ_PROGRAMS")) programs = std::atoi(n);
    int first_program = 0;
    if (const char* one = std::getenv("GLSLRUN_FUZZ_PROGRAM")) first_program = std::atoi(one), programs = 1;
    const bool avx2 = rt::cpu_has_avx2();
    int compared = 0, over_budget = 0;
    for (int p = first_program; p < first_program + programs && jit_available(); ++p) {
        Fuzzer fz(0x5eed0000u + uint32_t(p));
        fz.block(3, 30);
        ir::Shader& shader = fz.b.sh;
        // Every other program has a small instruction budget, which some batches exhaust.
        const uint64_t max_instructions = p % 2 ? uint64_t(20 + fz.pick(400)) : ExecOptions{}.max_instructions;
        std::vector<uint32_t> uniforms(32);
        for (uint32_t& u : uniforms) u = fz.special_word(fz.any_kind());
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
                INFO("program " << p << ", " << precision_name(precision) << (isa ? ", avx2" : ", baseline")
                                << (quick ? ", quick codegen" : ""));
                std::string logs[2];
                uint32_t words[2];
                size_t first = first_difference(shader, uniforms, batches, max_instructions, precision, isa, quick, logs, words);
                REQUIRE(logs[0] == logs[1]);
                over_budget += logs[0].find("instructions in one batch") != std::string::npos;
                if (first != std::string::npos) {
                    // Alone, the program is cut down to the top-level node after which the backends differ.
                    std::string where;
                    if (programs == 1) {
                        ir::Block body = shader.body;
                        for (size_t n = 1; n <= body.size(); ++n) {
                            shader.body.assign(body.begin(), body.begin() + long(n));
                            if (first_difference(shader, uniforms, batches, max_instructions, precision, isa, quick, logs, words) != std::string::npos) {
                                where = "\nthe first " + std::to_string(n) + " nodes differ:\n" + ir::print(shader);
                                where += "unmasked:";
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
                        }
                        shader.body = body;
                    }
                    const size_t per_batch = 2 + shader.regs.size() * rt::kLanes, word = first % per_batch;
                    FAIL("batch " << first / per_batch << ", "
                                  << (word < 2 ? std::string("alive mask")
                                               : "register %" + std::to_string((word - 2) / rt::kLanes) + " lane " +
                                                     std::to_string((word - 2) % rt::kLanes))
                                  << ": interpreter " << std::hex << words[0] << ", JIT " << words[1] << std::dec << where);
                }
                ++compared;
            }
    }
    WARN(compared << " program runs compared, " << over_budget << " stopped by the instruction budget");
    CHECK((compared > 0 || !jit_available()));
}
