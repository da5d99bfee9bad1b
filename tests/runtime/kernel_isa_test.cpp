// The AVX2 kernels (picked at run time) against the baseline x86-64 ones:
// every Alu op and the lane-wise Special ops must give the same bits on every
// lane, for special values (NaN, infinities, signed zeros, denormals, integer
// extremes) and under full and partial masks. One freedom is allowed: when
// both operands are NaN, x86 returns the first one's payload, and GCC may swap
// the operands of a commutative op in either version; GLSL 1.20 cannot
// observe a NaN's payload or sign, so a float result only has to be NaN too.
#include <catch2/catch.hpp>

#include <bit>
#include <limits>
#include <vector>

#include "ir/alu_eval.h"
#include "runtime/fast_kernels.h"

using namespace glslrun;
using rt::kLanes;

namespace {

// Raw words that stress the float and integer paths; lanes and operands get
// different rotations so every pairing of specials occurs somewhere.
uint32_t word(int operand, int lane, int round) {
    static const uint32_t special[] = {
        0x00000000u, 0x80000000u, 0x3f800000u, 0xbf800000u, 0x7f800000u, 0xff800000u, 0x7fc00000u,
        0xffc00001u, 0x00000001u, 0x807fffffu, 0x7f7fffffu, 0x4effffffu, 0xcf000000u, 0x3effffffu,
        0x40490fdbu, 0xc2c80000u, 0x00000007u, 0xfffffff9u, 0x7fffffffu, 0x80000001u, 0x00000002u,
        0x3f000000u, 0x41200000u, 0xbfc00000u};
    constexpr int n = sizeof special / sizeof special[0];
    return special[(lane * (operand + 1) + operand * 7 + round * 5) % n];
}

struct Case {
    std::vector<uint32_t> file = std::vector<uint32_t>(5 * kLanes);  // dst, a, b, c, uniforms
    rt::Step<uint32_t> step;
    rt::Machine<uint32_t> machine;

    Case(int round, rt::LaneMask mask) {
        for (int lane = 0; lane < kLanes; ++lane) {
            file[lane] = 0x12345678u + lane;  // inactive lanes must keep this
            for (int k = 0; k < 3; ++k) file[(k + 1) * kLanes + lane] = word(k, lane, round);
            file[4 * kLanes + lane] = word(3, lane, round);
        }
        step.dst = &file[0];
        for (int k = 0; k < 3; ++k) step.src[k] = &file[(k + 1) * kLanes];
        step.imm[0] = uint32_t(round) % kLanes;  // konst value / uniform word
        step.value = step.imm[0];
        machine.regs = file.data();
        machine.uniforms = &file[4 * kLanes];
        machine.mask.reset(mask);
    }
    std::vector<uint32_t> run(rt::Kernel<uint32_t> k) {
        ir::FlushDenormals ftz;
        k(step, machine);
        return std::vector<uint32_t>(file.begin(), file.begin() + kLanes);
    }
};

bool same_result(ir::Op op, uint32_t expected, uint32_t actual) {
    auto is_nan = [](uint32_t w) { return (w & 0x7f800000u) == 0x7f800000u && (w & 0x007fffffu) != 0; };
    bool float_result = ir::op_info(op).result == ir::TypeClass::F;
    return expected == actual || (float_result && is_nan(expected) && is_nan(actual));
}

bool lane_wise(ir::Op op) {
    return ir::alu::is_alu(op) || op == ir::Op::mov || op == ir::Op::konst || op == ir::Op::sel ||
           op == ir::Op::uniform || op == ir::Op::ddx || op == ir::Op::ddy;
}

// The baseline and AVX2 kernels of `op` under three masks and six rounds of
// operands; returns the cases compared.
int compare_isas(ir::Op op, Precision precision) {
    const rt::LaneMask masks[] = {rt::kAllLanes, rt::LaneMask(0x5a5a5a5a5a5a5a5aull) & rt::kAllLanes, 1};
    int checked = 0;
    for (rt::LaneMask mask : masks)
        for (int round = 0; round < 6; ++round) {
            INFO(ir::op_info(op).name << " round " << round << " mask " << mask << " " << precision_name(precision));
            Case base(round, mask), avx(round, mask);
            std::vector<uint32_t> expected = base.run(rt::kernel_for(op, false, precision));
            std::vector<uint32_t> actual = avx.run(rt::kernel_for(op, true, precision));
            REQUIRE(rt::kernel_for(op, true, precision) != rt::kernel_for(op, false, precision));
            for (int lane = 0; lane < kLanes; ++lane) {
                INFO("lane " << lane << ": " << expected[lane] << " against " << actual[lane]);
                CHECK(same_result(op, expected[lane], actual[lane]));
                if (!((mask >> lane) & 1)) CHECK(actual[lane] == 0x12345678u + uint32_t(lane));
            }
            ++checked;
        }
    return checked;
}

}  // namespace

TEST_CASE("AVX2 kernels compute the same bits as the baseline kernels") {
    if (!rt::cpu_has_avx2()) {
        WARN("no AVX2 on this CPU: only the baseline kernels exist here");
        return;
    }
    int checked = 0;
    // Fast mode's kernels (runtime/fast_kernels.h) must be as portable.
    for (Precision precision : {Precision::Precise, Precision::Fast})
        for (int o = 0; o < int(ir::Op::Count_); ++o)
            if (lane_wise(ir::Op(o))) checked += compare_isas(ir::Op(o), precision);
    CHECK(checked > 600);
}
