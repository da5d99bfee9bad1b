// Backend::Auto's policy (runtime/backend_cache.h), the process's compile
// queue (runtime/compile_queue.h) and the JIT's compile-cost bound
// (runtime/jit/jit.h): a short render compiles nothing, a long one compiles
// in the background and keeps the faster backend, nothing waits for a
// compile it will not use, and large programs stay on the interpreter.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <new>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "glslrun/glslrun.h"
#include "runtime/backend_cache.h"
#include "runtime/compile_queue.h"
#include "runtime/interp_kernels.h"
#include "runtime/program_state.h"
#include "tests/runtime/ir_builder.h"

using namespace glslrun;
using namespace glslrun::test;

namespace {

// out = in * 2 + 1
ir::Shader small_shader() {
    Builder b;
    Reg in = b.reg(Kind::F32), two = b.reg(Kind::F32), one = b.reg(Kind::F32), t = b.reg(Kind::F32),
        out = b.reg(Kind::F32);
    b.set_konst(two, bits(2.0f));
    b.set_konst(one, bits(1.0f));
    b.instr(Op::fmul, Kind::F32, t, {in, two});
    b.instr(Op::fadd, Kind::F32, out, {t, one});
    b.sh.inputs = {{"in", Kind::F32, in, 1}};
    b.sh.outputs = {{"out", Kind::F32, out, 1}};
    return b.sh;
}

rt::BackendCache::Key key_for(rt::Runner runner) {
    return {ir::Stage::Fragment, runner, Precision::Precise, rt::kAllFastOps, rt::cpu_has_avx2(), false};
}

// Runs one batch on `e` and checks its output lanes.
void check_runs(rt::Executor& e) {
    for (int i = 0; i < rt::kLanes; ++i) e.lanes_f(0)[i] = float(i);
    rt::RunError error;
    REQUIRE(e.run(rt::kAllLanes, &error));
    for (int i = 0; i < rt::kLanes; ++i) REQUIRE(e.lanes_f(4)[i] == float(i) * 2 + 1);
}

void wait_for_queue() {
    for (int i = 0; i < 20000 && rt::compiles_pending() > 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    REQUIRE(rt::compiles_pending() == 0);
}

}  // namespace

TEST_CASE("auto: a short render compiles nothing; a long one compiles and keeps the faster", "[runtime][tiering]") {
    if (!jit_available()) return;
    const ir::Shader shader = small_shader();
    const rt::ExecParams params;
    for (bool jit_faster : {true, false}) {
        INFO("the JIT measures " << (jit_faster ? "faster" : "slower"));
        auto cache = std::make_shared<rt::BackendCache>();
        rt::BackendCache::Meter& meter = cache->meter(ir::Stage::Fragment);
        const auto jit = key_for(rt::Runner::Jit), interp = key_for(rt::Runner::Interp);
        {
            auto e = cache->auto_executor(shader, jit, interp, params);
            CHECK(e->runner() == rt::Runner::Interp);
            check_runs(*e);
        }
        // One batch is far less than LLVM's time: nothing was queued.
        CHECK(meter.lanes[0].load() == uint64_t(rt::kLanes));
        CHECK_FALSE(meter.queued.load());
        CHECK(cache->jit_compile_seconds() == 0);
        // Interpreting as long as the compile would take queues it. The interpreter
        // serves meanwhile, unless the compile thread (a small shader) has already
        // finished when the queueing call looks for its code.
        meter.nanos[0] = 1'000'000'000;
        if (cache->auto_executor(shader, jit, interp, params)->runner() == rt::Runner::Jit)
            CHECK(cache->jit_compile_seconds() > 0);  // kept, with its compile time
        CHECK(meter.queued.load());
        wait_for_queue();
        CHECK(cache->jit_compile_seconds() > 0);
        // The JIT's code runs, timed, until it has run long enough to compare.
        {
            auto e = cache->auto_executor(shader, jit, interp, params);
            CHECK(e->runner() == rt::Runner::Jit);
            check_runs(*e);
        }
        CHECK(meter.lanes[1].load() == uint64_t(rt::kLanes));
        CHECK(meter.choice.load() == -1);
        // Per lane: the interpreter 1e9 ns over 16 lanes; the JIT 1/10 or 10x that.
        meter.lanes[1] = meter.lanes[0].load();
        meter.nanos[1] = jit_faster ? 100'000'000 : 10'000'000'000;
        const rt::Runner kept = jit_faster ? rt::Runner::Jit : rt::Runner::Interp;
        for (int draw = 0; draw < 3; ++draw) {
            auto e = cache->auto_executor(shader, jit, interp, params);
            CHECK(e->runner() == kept);
            check_runs(*e);
        }
        CHECK(meter.choice.load() == int(kept));
    }
}

TEST_CASE("a program goes without waiting for its queued compile", "[runtime][tiering]") {
    if (!jit_available()) return;
    const ir::Shader shader = small_shader();
    // Holds the compile thread until released.
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    REQUIRE(rt::submit_compile([released] { released.wait(); }));
    auto cache = std::make_shared<rt::BackendCache>();
    cache->meter(ir::Stage::Fragment).nanos[0] = 1'000'000'000;
    CHECK(cache->auto_executor(shader, key_for(rt::Runner::Jit), key_for(rt::Runner::Interp), {})->runner() ==
          rt::Runner::Interp);
    CHECK(rt::compiles_pending() == 2);
    cache.reset();  // would never return if it waited for the compile behind the held one
    release.set_value();
    wait_for_queue();  // the queued compile found the cache gone
}

TEST_CASE("a job that throws leaves the compile thread running", "[runtime][tiering]") {
    REQUIRE(rt::submit_compile([] { throw std::bad_alloc(); }));
    std::promise<void> ran;
    auto done = ran.get_future();
    REQUIRE(rt::submit_compile([&ran] { ran.set_value(); }));
    CHECK(done.wait_for(std::chrono::seconds(60)) == std::future_status::ready);
    wait_for_queue();
}

namespace {

ir::Program program_ir(const std::string& fragment, const std::string& vertex) {
    auto program = Program::compile({{"a.vert", vertex}}, {{"a.frag", fragment}});
    if (!program.ok()) FAIL(program.error().str());
    return state_of(program.value()).ir;
}
// The fragment shader's IR; `vertex` writes its varyings.
ir::Shader fragment_ir(const std::string& fragment,
                       const std::string& vertex = "varying float v; void main() { v = 1.0; gl_Position = gl_Vertex; }") {
    return program_ir(fragment, vertex).fragment;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    REQUIRE(!text.str().empty());
    return text.str();
}

}  // namespace

TEST_CASE("the JIT's compile-cost bound: large programs stay on the interpreter", "[runtime][tiering]") {
    if (!jit_available()) return;
    auto plan_compile = rt::plan_jit;
    // The lecture's spot light (about 90 ms of LLVM's time measured) is compiled as it was.
    const ir::Shader spot = fragment_ir(read_file(GLSLRUN_SOURCE_DIR "/shaders/spot_pix_fixed.frag"),
                                        read_file(GLSLRUN_SOURCE_DIR "/shaders/spot_pix_fixed.vert"));
    CHECK(plan_compile(spot, false).take);
    CHECK_FALSE(plan_compile(spot, false).quick);
    // Its vertex shader, far colder, without code-generation optimizations.
    const ir::Shader spot_vertex = program_ir(read_file(GLSLRUN_SOURCE_DIR "/shaders/spot_pix_fixed.frag"),
                                              read_file(GLSLRUN_SOURCE_DIR "/shaders/spot_pix_fixed.vert")).vertex;
    CHECK(plan_compile(spot_vertex, false).take);
    CHECK(plan_compile(spot_vertex, false).quick);
    // A ray tracer with structs, inout struct parameters and calls: 2 s of LLVM's time with its
    // calls written out in place; its trace() and shade() compiled once each as functions of
    // their own, about 80 ms (docs/performance.md): taken, without code-generation optimizations.
    const ir::Shader raytrace = fragment_ir(read_file(GLSLRUN_SOURCE_DIR "/tests/compile_cost/raytrace.frag"),
                                            read_file(GLSLRUN_SOURCE_DIR "/tests/compile_cost/raytrace.vert"));
    CHECK(plan_compile(raytrace, false).take);
    CHECK(plan_compile(raytrace, false).quick);
    // 5000 lines of straight-line code.
    std::string straight = "varying float v;\nvoid main() {\n float x = v;\n";
    for (int i = 0; i < 5000; ++i) straight += " x = x * 1.0001 + " + std::to_string(i) + ".0;\n";
    straight += " gl_FragColor = vec4(x);\n}\n";
    CHECK_FALSE(plan_compile(fragment_ir(straight), false).take);
    // A call chain 250 deep (deeper ones are refused by the compiler: docs/limits.md), each link a few
    // instructions: thousands once written out in place.
    std::string chain = "varying float v;\nfloat f0(float x) { return x * 1.5; }\n";
    for (int i = 1; i < 250; ++i)
        chain += "float f" + std::to_string(i) + "(float x) { return f" + std::to_string(i - 1) +
                 "(x) * 1.5 + sin(x) * 0.25 - x * x; }\n";
    chain += "void main() { gl_FragColor = vec4(f249(v)); }\n";
    const ir::Shader deep = fragment_ir(chain);
    CHECK_FALSE(plan_compile(deep, false).take);
    // And the JIT declines them when asked (within the budget, without LLVM).
    const std::vector<uint32_t> uniforms(1 << 16, 0);  // more than either reads
    rt::ExecParams params;
    params.uniforms = uniforms.data();
    for (const ir::Shader* s : {&deep}) {
        const auto start = std::chrono::steady_clock::now();
        CHECK(rt::compile_shader(*s, rt::Runner::Jit, Precision::Precise, rt::kAllFastOps, false)
                  ->instantiate(params)->runner() == rt::Runner::Interp);
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
    }
}

TEST_CASE("a forked child has a compile thread of its own", "[runtime][tiering]") {
    std::promise<void> ran;
    auto done = ran.get_future();
    REQUIRE(rt::submit_compile([&ran] { ran.set_value(); }));  // the parent's thread is started
    REQUIRE(done.wait_for(std::chrono::seconds(60)) == std::future_status::ready);
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        std::promise<void> child_ran;
        auto child_done = child_ran.get_future();
        const bool queued = rt::submit_compile([&child_ran] { child_ran.set_value(); });
        ::_exit(queued && child_done.wait_for(std::chrono::seconds(60)) == std::future_status::ready ? 0 : 1);
    }
    int status = -1;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

namespace {

std::atomic<bool> g_exiting{false};

}  // namespace

// Exit handlers registered after the queue's run before it: a compile still
// running then (loading LLVM, say) raced them and crashed now and then.
// stop_background_compiles() waits for it before main returns.
TEST_CASE("stop_background_compiles: no compile runs once exit begins", "[runtime][tiering]") {
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        std::atomic<bool> started{false};
        rt::submit_compile([&started] {
            started = true;
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            if (g_exiting.load()) ::_exit(3);  // ran on while exit handlers did
        });
        while (!started.load()) std::this_thread::yield();
        std::atexit([] { g_exiting = true; });  // registered after the queue's handler, so run before it
        glslrun::stop_background_compiles();
        const bool dropped = rt::submit_compile([] { ::_exit(4); }) && rt::compiles_pending() == 0;
        std::exit(dropped ? 0 : 5);
    }
    int status = -1;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}

namespace {

size_t thread_count() {
    size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task")) n += entry.is_directory();
    return n;
}

}  // namespace

TEST_CASE("300 programs' background compiles take one thread", "[runtime][tiering]") {
    if (!jit_available()) return;
    const ir::Shader shader = small_shader();
    wait_for_queue();  // an earlier case's background compile would add to the count below
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    REQUIRE(rt::submit_compile([released] { released.wait(); }));  // the thread is started and held
    const size_t threads = thread_count();
    std::vector<std::shared_ptr<rt::BackendCache>> caches;
    for (int i = 0; i < 300; ++i) {
        caches.push_back(std::make_shared<rt::BackendCache>());
        caches.back()->meter(ir::Stage::Fragment).nanos[0] = 1'000'000'000;
        (void)caches.back()->auto_executor(shader, key_for(rt::Runner::Jit), key_for(rt::Runner::Interp), {});
    }
    CHECK(rt::compiles_pending() == 301);
    CHECK(thread_count() == threads);
    caches.clear();  // their queued compiles find them gone
    release.set_value();
    wait_for_queue();
}
