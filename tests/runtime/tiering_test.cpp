// Backend::Auto's policy (runtime/backend_cache.h), the process's compile
// queue (runtime/compile_queue.h) and the JIT's compile-cost bound
// (runtime/jit/jit.h): a short render compiles nothing, a long one compiles
// in the background and keeps the faster backend, nothing waits for a
// compile it will not use, and large programs stay on the interpreter.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
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
#include "runtime/jit/jit.h"
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
    auto plan_compile = [](const ir::Shader& s, bool quick) { return rt::plan_jit(s, quick); };
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
    // The second tier recompiles the quick ones with every optimization, and only those.
    CHECK(plan_compile(raytrace, false).optimisable);
    CHECK(plan_compile(spot_vertex, false).optimisable);
    CHECK_FALSE(plan_compile(spot, false).optimisable);
    CHECK_FALSE(plan_compile(raytrace, true).optimisable);  // ExecOptions::jit_quick_codegen
    CHECK(rt::plan_jit(raytrace, false, true).take);
    CHECK_FALSE(rt::plan_jit(raytrace, false, true).quick);
    CHECK(rt::plan_jit(raytrace, false, true).nanos > plan_compile(raytrace, false).nanos);
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

// The JIT's second tier (runtime/backend_cache.h): a hot stage's code
// compiled again with every code-generation optimization, in the
// background, and swapped in for its next executors.
namespace {

rt::BackendCache::Key vertex_key() {
    rt::BackendCache::Key key = key_for(rt::Runner::Jit);
    key.stage = ir::Stage::Vertex;  // always quick in the first tier: the second makes other code
    return key;
}

ir::Shader small_vertex_shader() {
    ir::Shader shader = small_shader();
    shader.stage = ir::Stage::Vertex;
    return shader;
}

// Runs one batch on a new executor of `cache`'s (Backend::Jit) and returns
// the lanes it added to the second tier's count once it went.
uint64_t hot_lanes_of_one_run(rt::BackendCache& cache, const ir::Shader& shader) {
    rt::BackendCache::Meter& meter = cache.meter(ir::Stage::Vertex);
    const uint64_t before = meter.hot_lanes.load() + meter.lanes[1].load();
    {
        auto e = cache.jit_executor(shader, vertex_key(), {});
        CHECK(e->runner() == rt::Runner::Jit);
        check_runs(*e);
    }
    return meter.hot_lanes.load() + meter.lanes[1].load() - before;
}

}  // namespace

TEST_CASE("the second tier: a hot stage is compiled again in the background and swapped in", "[runtime][tiering]") {
    if (!jit_available()) return;
    wait_for_queue();
    const ir::Shader shader = small_vertex_shader();
    auto cache = std::make_shared<rt::BackendCache>();
    rt::BackendCache::Meter& meter = cache->meter(ir::Stage::Vertex);
    // The first tier's code serves and is counted.
    CHECK(hot_lanes_of_one_run(*cache, shader) == uint64_t(rt::kLanes));
    REQUIRE(meter.optimise_nanos != rt::BackendCache::Meter::kUnknown);
    REQUIRE(meter.optimise_nanos > 0);
    CHECK_FALSE(meter.optimise_queued);
    CHECK(cache->jit_compiles().compiled == 1);
    CHECK(cache->jit_compiles().optimised == 0);
    // Not hot yet: a batch's time is far less than the compile's.
    CHECK(hot_lanes_of_one_run(*cache, shader) == uint64_t(rt::kLanes));
    CHECK_FALSE(meter.optimise_queued);
    // The compile expected from the first tier's, measured, where the plan's estimate is more.
    CHECK(meter.optimise_measured);
    CHECK(meter.optimise_nanos <= uint64_t(cache->jit_compile_seconds() * 1e9 / rt::jit::kQuickCodegenShare) + 1);
    CHECK(meter.optimise_nanos <= rt::plan_jit(shader, false, true).nanos);
    // Hot: the timed part's cost per lane times the untimed lanes reaches LLVM's expected time.
    meter.nanos[1] = 1000;
    meter.lanes[1] = 1;
    meter.hot_lanes = meter.optimise_nanos / 1000;
    CHECK(hot_lanes_of_one_run(*cache, shader) == 0);  // the first tier while it compiles, no longer counted
    CHECK(meter.optimise_queued);
    wait_for_queue();
    CHECK(cache->jit_compiles().compiled == 2);
    CHECK(cache->jit_compiles().optimised == 1);
    CHECK(cache->optimise_seconds() > 0);
    // The second tier's code now, no longer counted; the same results (check_runs).
    CHECK(hot_lanes_of_one_run(*cache, shader) == 0);
    CHECK(cache->jit_compiles().compiled == 2);
}

TEST_CASE("the second tier under auto: only once the JIT is kept, and not for code it would not change",
          "[runtime][tiering]") {
    if (!jit_available()) return;
    wait_for_queue();
    const ir::Shader shader = small_vertex_shader();
    auto cache = std::make_shared<rt::BackendCache>();
    rt::BackendCache::Meter& meter = cache->meter(ir::Stage::Vertex);
    rt::BackendCache::Key jit = vertex_key(), interp = vertex_key();
    interp.runner = rt::Runner::Interp;
    meter.nanos[0] = 1'000'000'000;  // the first tier's compile is due
    CHECK(cache->auto_executor(shader, jit, interp, {})->runner() == rt::Runner::Interp);
    wait_for_queue();
    // Measuring: the JIT's code is timed, and however long it ran, the second tier waits for the choice.
    meter.nanos[1] = 1'000'000;
    meter.lanes[1] = 1;
    meter.hot_lanes = 1'000'000'000;
    CHECK(cache->auto_executor(shader, jit, interp, {})->runner() == rt::Runner::Jit);
    CHECK_FALSE(meter.optimise_queued);
    // The interpreter measured slower per lane: the JIT is kept, and the hot stage's second tier queued.
    meter.nanos[1] = 2'000'000;  // 2 ns per lane against the interpreter's 1e9 over 1 lane
    meter.lanes[1] = 1'000'000;
    meter.lanes[0] = 1;
    meter.nanos[0] = 1'000'000'000;
    meter.hot_lanes = 1'000'000'000'000;
    CHECK(cache->auto_executor(shader, jit, interp, {})->runner() == rt::Runner::Jit);
    CHECK(meter.choice.load() == int(rt::Runner::Jit));
    CHECK(cache->auto_executor(shader, jit, interp, {})->runner() == rt::Runner::Jit);
    CHECK(meter.optimise_queued);
    wait_for_queue();
    CHECK(cache->jit_compiles().optimised == 1);

    // A fragment shader compiled with every optimization in the first tier: no second.
    auto fragment = std::make_shared<rt::BackendCache>();
    rt::BackendCache::Meter& fmeter = fragment->meter(ir::Stage::Fragment);
    const ir::Shader small = small_shader();
    (void)fragment->jit_executor(small, key_for(rt::Runner::Jit), {});
    CHECK(fmeter.optimise_nanos == 0);
    fmeter.nanos[1] = 1'000'000'000;
    fmeter.lanes[1] = 1;
    (void)fragment->jit_executor(small, key_for(rt::Runner::Jit), {});
    CHECK_FALSE(fmeter.optimise_queued);
    CHECK(fragment->jit_compiles().optimised == 0);
}

namespace {

std::string source_file(const std::string& name) { return read_file(GLSLRUN_SOURCE_DIR "/tests/compile_cost/" + name); }

struct TierRender {
    std::vector<float> pixels;
    Program::JitCompiles compiles;
    double optimise_seconds = 0;
};

// The ray tracer (both stages quick in the first tier) over a 24x24 float image, `frames` times.
TierRender render_raytrace(Backend backend, JitTier tier, const std::string& cache_dir = "", int frames = 1) {
    auto program = Program::compile({{"raytrace.vert", source_file("raytrace.vert")}},
                                    {{"raytrace.frag", source_file("raytrace.frag")}});
    REQUIRE(program);
    program->exec.backend = backend;
    program->exec.jit_tier = tier;
    program->exec.threads = 1;
    program->exec.code_cache = !cache_dir.empty();
    program->exec.code_cache_dir = cache_dir;
    const float resolution[2] = {24, 24}, time = 0.75f;
    REQUIRE(program->set_uniform("resolution", Span<const float>(resolution, 2)));
    REQUIRE(program->set_uniform("time", Span<const float>(&time, 1)));
    Framebuffer fb(24, 24, true);
    const std::vector<float> quad = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    const std::vector<float> uv = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
    for (int f = 0; f < frames; ++f)
        REQUIRE(draw(*program, GLState{}, fb, Primitive::Triangles,
                     {{"gl_Vertex", 2, quad}, {"gl_MultiTexCoord0", 2, uv}}, 6));
    auto colors = fb.color_data<float>();
    return {std::vector<float>(colors.begin(), colors.end()), program->jit_compiles(),
            state_of(*program).backends->optimise_seconds()};
}

struct ScratchDir {
    std::string path;
    ScratchDir() {
        char name[] = "/tmp/glslrun-tier-XXXXXX";
        REQUIRE(::mkdtemp(name) != nullptr);
        path = name;
    }
    ~ScratchDir() { std::filesystem::remove_all(path); }
};

}  // namespace

TEST_CASE("the second tier: the same images as the first tier and the interpreter; cached under a key of its own",
          "[runtime][tiering]") {
    if (!jit_available()) return;
    wait_for_queue();
    const TierRender interp = render_raytrace(Backend::Interp, JitTier::Tiered);
    const TierRender first = render_raytrace(Backend::Jit, JitTier::First);
    const TierRender second = render_raytrace(Backend::Jit, JitTier::Optimised);
    CHECK(first.compiles.compiled == 2);
    CHECK(first.compiles.optimised == 0);
    CHECK(second.compiles.compiled == 2);
    CHECK(second.compiles.optimised == 2);
    REQUIRE(interp.pixels.size() == size_t(24 * 24 * 4));
    CHECK(std::memcmp(first.pixels.data(), interp.pixels.data(), interp.pixels.size() * 4) == 0);
    CHECK(std::memcmp(second.pixels.data(), interp.pixels.data(), interp.pixels.size() * 4) == 0);

    // A one-frame render never starts the second tier.
    const TierRender tiered = render_raytrace(Backend::Jit, JitTier::Tiered);
    wait_for_queue();
    CHECK(tiered.compiles.optimised == 0);
    CHECK(tiered.optimise_seconds == 0);

    // The code cache: the first tier's code does not serve the second's key, nor the reverse; a
    // tiered run loads the second tier's code at its first draw where an earlier run made it.
    ScratchDir dir;
    CHECK(render_raytrace(Backend::Jit, JitTier::First, dir.path).compiles.compiled == 2);
    const TierRender optimised = render_raytrace(Backend::Jit, JitTier::Optimised, dir.path);
    CHECK(optimised.compiles.compiled == 2);
    CHECK(optimised.compiles.loaded == 0);
    const TierRender loaded = render_raytrace(Backend::Jit, JitTier::Tiered, dir.path);
    CHECK(loaded.compiles.compiled == 0);
    CHECK(loaded.compiles.loaded == 2);
    CHECK(loaded.compiles.optimised == 2);
    CHECK(std::memcmp(loaded.pixels.data(), interp.pixels.data(), interp.pixels.size() * 4) == 0);
}

TEST_CASE("stop_background_compiles stops a second-tier compile", "[runtime][tiering]") {
    if (!jit_available()) return;
    wait_for_queue();
    const ir::Shader raytrace = fragment_ir(source_file("raytrace.frag"), source_file("raytrace.vert"));
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        auto cache = std::make_shared<rt::BackendCache>();
        rt::BackendCache::Meter& meter = cache->meter(ir::Stage::Fragment);
        const std::vector<uint32_t> uniforms(1 << 12, 0);
        rt::ExecParams params;
        params.uniforms = uniforms.data();
        (void)cache->jit_executor(raytrace, key_for(rt::Runner::Jit), params);  // the first tier, waited for
        meter.nanos[1] = meter.optimise_nanos;
        meter.lanes[1] = 1;
        (void)cache->jit_executor(raytrace, key_for(rt::Runner::Jit), params);  // queues the second
        const bool queued = meter.optimise_queued && rt::compiles_pending() == 1;
        glslrun::stop_background_compiles();  // drops it, or stops it at its next phase
        const bool stopped = rt::compiles_pending() == 0 && cache->jit_compiles().optimised == 0;
        // The first tier's code goes on serving.
        const bool serves = cache->jit_executor(raytrace, key_for(rt::Runner::Jit), params)->runner() == rt::Runner::Jit;
        ::_exit(!queued ? 3 : !stopped ? 4 : !serves ? 5 : 0);
    }
    int status = -1;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}
