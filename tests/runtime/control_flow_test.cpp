// Structured control flow under divergence: if/else, loops with break and
// continue, return from scopes and calls, discard, the iteration cap.
#include <catch2/catch.hpp>

#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;
using rt::kLanes;

TEST_CASE("divergent nested if/else", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), y = b.reg(Kind::I32);
    Reg three = b.ki(3), ten = b.ki(10), one = b.ki(1);
    Reg gt3 = b.alu(Op::igt, {x, three});
    b.if_(
        gt3,
        [&] {
            Reg lt10 = b.alu(Op::ilt, {x, ten});
            b.if_(lt10, [&] { b.alu_to(y, Op::imul, {x, ten}); }, [&] { b.alu_to(y, Op::ineg, {x}); });
        },
        [&] { b.alu_to(y, Op::iadd, {x, one}); });
    Runner r(b.sh);
    r.set(x, [](int i) { return bits(int32_t(i)); });
    REQUIRE(r.run());
    for (int i = 0; i < kLanes; ++i) CHECK(r.i(y, i) == (i > 3 ? (i < 10 ? i * 10 : -i) : i + 1));
}

// for (i = 0; ; i++) { if (i >= n) break; if (i == 2) continue;
//   for (j = 0; ; j++) { if (j >= 3) break; if ((i + j) % 2 == 1) continue; sum += i * j; }
//   if (i == 6 && n > 10) break; sum += 100; }
static int32_t nested_loops_reference(int32_t n) {
    int32_t sum = 0;
    for (int32_t i = 0;; i++) {
        if (i >= n) break;
        if (i == 2) continue;
        for (int32_t j = 0;; j++) {
            if (j >= 3) break;
            if ((i + j) % 2 == 1) continue;
            sum += i * j;
        }
        if (i == 6 && n > 10) break;
        sum += 100;
    }
    return sum;
}

TEST_CASE("nested loops with break and continue under divergence", "[runtime][cf]") {
    Builder b;
    Reg n = b.reg(Kind::I32), sum = b.reg(Kind::I32), i = b.reg(Kind::I32), j = b.reg(Kind::I32);
    Reg k0 = b.ki(0), k1 = b.ki(1), k2 = b.ki(2), k3 = b.ki(3), k6 = b.ki(6), k10 = b.ki(10), k100 = b.ki(100);
    b.mov(sum, k0);
    b.mov(i, k0);
    b.loop(
        [&] {
            b.if_(b.alu(Op::ige, {i, n}), [&] { b.brk(); });
            b.if_(b.alu(Op::ieq, {i, k2}), [&] { b.cont(); });
            b.mov(j, k0);
            b.loop(
                [&] {
                    b.if_(b.alu(Op::ige, {j, k3}), [&] { b.brk(); });
                    Reg odd = b.alu(Op::ieq, {b.alu(Op::imod, {b.alu(Op::iadd, {i, j}), k2}), k1});
                    b.if_(odd, [&] { b.cont(); });
                    b.alu_to(sum, Op::iadd, {sum, b.alu(Op::imul, {i, j})});
                },
                [&] { b.alu_to(j, Op::iadd, {j, k1}); });
            Reg stop = b.alu(Op::band, {b.alu(Op::ieq, {i, k6}), b.alu(Op::igt, {n, k10})});
            b.if_(stop, [&] { b.brk(); });
            b.alu_to(sum, Op::iadd, {sum, k100});
        },
        [&] { b.alu_to(i, Op::iadd, {i, k1}); });
    Runner r(b.sh);
    r.set(n, [](int l) { return bits(int32_t(l)); });
    REQUIRE(r.run());
    for (int l = 0; l < kLanes; ++l) {
        INFO("lane " << l);
        CHECK(r.i(sum, l) == nested_loops_reference(l));
    }
}

TEST_CASE("return ends the innermost scope only", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), y = b.reg(Kind::I32), z = b.reg(Kind::I32), i = b.reg(Kind::I32);
    Reg k1 = b.ki(1), k2 = b.ki(2), k3 = b.ki(3), k10 = b.ki(10), k0 = b.ki(0);
    b.scope([&] {
        b.if_(b.alu(Op::igt, {x, k3}), [&] {
            b.mov(y, k1);
            b.ret();
        });
        b.mov(y, k2);
        // a return from inside a loop leaves both the loop and the scope
        b.mov(i, k0);
        b.loop([&] {
            b.if_(b.alu(Op::ige, {i, x}), [&] { b.ret(); });
            b.alu_to(i, Op::iadd, {i, k1});
        });
        b.mov(y, k3);  // never reached: every lane returns from the loop
    });
    b.alu_to(z, Op::iadd, {y, k10});
    Runner r(b.sh);
    r.set(x, [](int l) { return bits(int32_t(l)); });
    REQUIRE(r.run());
    for (int l = 0; l < kLanes; ++l) {
        CHECK(r.i(y, l) == (l > 3 ? 1 : 2));
        CHECK(r.i(z, l) == (l > 3 ? 11 : 12));
        CHECK(r.i(i, l) == (l > 3 ? 0 : l));
    }
}

TEST_CASE("return inside a call and at the top level", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), y = b.reg(Kind::I32), z = b.reg(Kind::I32), w = b.reg(Kind::I32);
    Reg k5 = b.ki(5), k1 = b.ki(1), k8 = b.ki(8), k0 = b.ki(0);
    uint32_t f = b.function("f", [&] {
        b.if_(b.alu(Op::ilt, {x, k5}), [&] { b.ret(); });
        b.alu_to(y, Op::iadd, {y, k1});
    });
    b.mov(y, k0);
    b.call(f);
    b.call(f);
    b.alu_to(z, Op::iadd, {y, k1});
    b.if_(b.alu(Op::ige, {x, k8}), [&] { b.ret(); });
    b.mov(w, k1);
    Runner r(b.sh);
    r.set(x, [](int l) { return bits(int32_t(l)); });
    r.set(w, [](int) { return 9u; });
    REQUIRE(r.run());
    for (int l = 0; l < kLanes; ++l) {
        CHECK(r.i(y, l) == (l < 5 ? 0 : 2));
        CHECK(r.i(z, l) == (l < 5 ? 1 : 3));
        CHECK(r.i(w, l) == (l >= 8 ? 9 : 1));
    }
}

TEST_CASE("discard removes lanes for the rest of the invocation", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), y = b.reg(Kind::I32), i = b.reg(Kind::I32);
    Reg k1 = b.ki(1), k0 = b.ki(0), k3 = b.ki(3), k7 = b.ki(7);
    uint32_t f = b.function("maybe_discard", [&] {
        b.mov(i, k0);
        b.loop([&] {
            b.if_(b.alu(Op::ige, {i, k3}), [&] { b.brk(); });
            b.if_(b.alu(Op::band, {b.alu(Op::ieq, {i, k1}), b.alu(Op::ieq, {b.alu(Op::imod, {x, k3}), k0})}),
                  [&] { b.discard(); });
            b.alu_to(i, Op::iadd, {i, k1});
        });
    });
    b.call(f);
    b.if_(b.alu(Op::ieq, {x, k7}), [&] { b.discard(); });
    b.mov(y, k1);
    Runner r(b.sh);
    r.set(x, [](int l) { return bits(int32_t(l)); });
    rt::LaneMask live = rt::kAllLanes & ~rt::LaneMask(0b100000);  // lane 5 is not live
    REQUIRE(r.run(live));
    rt::LaneMask want = 0;
    for (int l = 0; l < kLanes; ++l) {
        bool discarded = l % 3 == 0 || l == 7;
        bool alive = l != 5 && !discarded;
        if (alive) want |= rt::LaneMask(1) << l;
        CHECK(r.i(y, l) == (alive ? 1 : 0));
        if (l != 5) CHECK(r.i(i, l) == (l % 3 == 0 ? 1 : 3));
    }
    CHECK(r.it->alive() == want);
}

TEST_CASE("a loop past the iteration cap stops the run with an error", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), i = b.reg(Kind::I32);
    Reg k1 = b.ki(1);
    b.line = 42;
    // lanes with x < 0 never leave the loop
    b.loop([&] {
        b.if_(b.alu(Op::ieq, {i, x}), [&] { b.brk(); });
        b.alu_to(i, Op::iadd, {i, k1});
    });
    ir::Shader& sh = b.sh;
    uint32_t store = 0;
    rt::Interpreter it(sh, &store, 100);
    for (int l = 0; l < kLanes; ++l) {
        it.lanes(x)[l] = bits(int32_t(l == 3 ? -1 : 99));  // 100 iterations: allowed
        it.lanes(i)[l] = 0;
    }
    rt::RunError error;
    CHECK_FALSE(it.run(rt::kAllLanes, &error));
    CHECK(error.message == "loop exceeded 100 iterations");
    CHECK(error.line == 42);
    for (int l = 0; l < kLanes; ++l) {
        it.lanes(x)[l] = bits(int32_t(99));
        it.lanes(i)[l] = 0;
    }
    CHECK(it.run(rt::kAllLanes, &error));
    CHECK(int32_t(it.lanes(i)[0]) == 99);
}

TEST_CASE("a never-taken branch around an exponential call tree is skipped", "[runtime][cf]") {
    Builder b;
    Reg x = b.reg(Kind::I32), y = b.reg(Kind::I32);
    Reg k1 = b.ki(1), never = b.kb(false), always = b.kb(true);
    // f63 increments; f_k calls f_{k+1} twice: 2^64 calls if executed.
    std::vector<uint32_t> ids(64);
    ids[63] = b.function("f63", [&] { b.alu_to(y, Op::iadd, {y, k1}); });
    for (int k = 62; k >= 0; --k)
        ids[k] = b.function("f", [&, k] {
            b.call(ids[k + 1]);
            b.call(ids[k + 1]);
        });
    b.if_(never, [&] { b.call(ids[0]); });
    b.if_(always, {}, [&] { b.call(ids[0]); });  // the else side is skipped too
    b.call(ids[55]);  // 2^8 calls do run
    Runner r(b.sh);
    r.set(x, [](int l) { return bits(int32_t(l)); });
    REQUIRE(r.run());
    for (int l = 0; l < kLanes; ++l) CHECK(r.i(y, l) == 256);
}

TEST_CASE("a self-recursive call fails instead of crashing", "[runtime][cf]") {
    Builder b;
    b.function("loop_forever", [&] { b.call(0); });
    b.call(0);
    Runner r(b.sh);
    rt::RunError error;
    CHECK_FALSE(r.run(rt::kAllLanes, &error));
    CHECK(!error.message.empty());
}
