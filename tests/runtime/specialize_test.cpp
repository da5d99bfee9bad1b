// Specialization on uniforms (ir/specialize.cpp): a uniform condition's dead
// branch goes and uniform code folds, except the ops that Precision::Fast
// approximates; the JIT's code of the specialized shader computes the
// interpreter's bits of the unspecialized one.
#include <catch2/catch.hpp>

#include "ir/passes.h"
#include "runtime/backend_factory.h"
#include "runtime/interp_kernels.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

size_t count_ops(const ir::Block& block, Op op) {
    size_t n = 0;
    for (const ir::Node& node : block) {
        n += node.kind == NodeKind::Instr && node.instr.op == op;
        n += count_ops(node.body, op) + count_ops(node.alt, op);
    }
    return n;
}

size_t count_ifs(const ir::Block& block) {
    size_t n = 0;
    for (const ir::Node& node : block) n += (node.kind == NodeKind::If) + count_ifs(node.body) + count_ifs(node.alt);
    return n;
}

}  // namespace

TEST_CASE("specialization folds uniform code and dead branches, with the same bits", "[runtime][specialize]") {
    // x = u0 ? y * exp(u1) : sin(y); out = x + u1
    Builder b;
    Reg y = b.reg(Kind::F32), x = b.reg(Kind::F32), out = b.reg(Kind::F32);
    Reg c = b.reg(Kind::Bool), u1 = b.reg(Kind::F32), e = b.reg(Kind::F32);
    b.instr(Op::uniform, Kind::Bool, c, {}, {0});
    b.instr(Op::uniform, Kind::F32, u1, {}, {1});
    b.if_(c, [&] {
        b.instr(Op::fexp, Kind::F32, e, {u1});
        b.instr(Op::fmul, Kind::F32, x, {y, e});
    }, [&] { b.instr(Op::fsin, Kind::F32, x, {y}); });
    b.instr(Op::fadd, Kind::F32, out, {x, u1});
    b.sh.inputs = {{"y", Kind::F32, y, 1}};
    b.sh.outputs = {{"out", Kind::F32, out, 1}};
    const std::vector<uint32_t> uniforms = {1, bits(0.75f)};
    REQUIRE(ir::uniform_words_read(b.sh) == std::vector<uint32_t>{0, 1});

    for (Precision precision : {Precision::Precise, Precision::Fast}) {
        INFO(precision_name(precision));
        ir::Shader specialized = b.sh;
        const uint32_t approximated = precision == Precision::Fast ? uint32_t(rt::kAllFastOps) : 0u;
        REQUIRE(ir::specialize(specialized, uniforms, approximated) == "");
        CHECK(count_ifs(specialized.body) == 0);
        CHECK(count_ops(specialized.body, Op::fsin) == 0);
        CHECK(count_ops(specialized.body, Op::uniform) + count_ops(specialized.prologue, Op::uniform) == 0);
        // Fast computes exp with its own kernel at run time: not folded.
        CHECK(count_ops(specialized.body, Op::fexp) + count_ops(specialized.prologue, Op::fexp) ==
              (precision == Precision::Fast ? 1u : 0u));

        rt::ExecParams params{uniforms.data(), 10, nullptr, precision, rt::kAllFastOps};
        const bool avx2 = rt::cpu_has_avx2();
        auto interp = rt::compile_shader(b.sh, rt::Runner::Interp, precision, params.fast_ops, avx2);
        auto jit = rt::compile_shader(specialized, rt::Runner::Jit, precision, params.fast_ops, avx2);
        auto a = interp->instantiate(params), j = jit->instantiate(params);
        for (int lane = 0; lane < rt::kLanes; ++lane)
            a->lanes_f(y)[lane] = j->lanes_f(y)[lane] = float(lane) * 0.37f - 2.0f;
        REQUIRE(a->run(rt::kAllLanes, nullptr));
        REQUIRE(j->run(rt::kAllLanes, nullptr));
        for (int lane = 0; lane < rt::kLanes; ++lane) CHECK(a->lanes(out)[lane] == j->lanes(out)[lane]);
    }
}
