// Interpreter throughput: million fragment-shader invocations per second on one
// core, for the lecture's per-pixel spot-light shader on synthetic inputs.
// Run: glslrun_bench [seconds] [reference|precise|fast]. Whole-frame benchmarks
// live in glslrun itself.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "glslrun/glslrun.h"
#include "ir/ir.h"
#include "runtime/interpreter.h"
#include "runtime/program_state.h"

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The spot scene (scenes/spot.toml), in eye space.
glslrun::GLState spot_scene() {
    glslrun::GLState gl;
    auto& light = gl.lights[0];
    light.ambient = {0.2f, 0.2f, 0.2f, 1};
    light.position = {0.4f, 1.2f, -2.6f, 1};
    light.spot_direction = {-0.1474420f, -0.4423259f, -0.8846517f};
    light.spot_cutoff = 20;
    light.spot_exponent = 12;
    light.constant_attenuation = 1;
    light.linear_attenuation = 0.05f;
    light.quadratic_attenuation = 0.02f;
    gl.front_material = {{0.25f, 0.20f, 0.07f, 1}, {0.75f, 0.61f, 0.23f, 1}, {0.8f, 0.8f, 0.8f, 1}, {0, 0, 0.05f, 1}, 64};
    return gl;
}

// This thread's CPU time: on a shared machine it counts only our own cycles.
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

const glslrun::ir::Binding* find_input(const glslrun::ir::Shader& s, const char* name) {
    for (const auto& b : s.inputs)
        if (b.name == name) return &b;
    return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = argc > 1 ? std::atof(argv[1]) : 2.0;
    std::string dir = GLSLRUN_SHADER_DIR;
    auto prog = glslrun::Program::compile({{"pos_pix.vert", read_file(dir + "/pos_pix.vert")}},
                                          {{"spot_pix_fixed.frag", read_file(dir + "/spot_pix_fixed.frag")}});
    if (!prog) {
        std::fprintf(stderr, "%s", prog.error().str().c_str());
        return 1;
    }
    if (auto st = glslrun::apply_builtin_uniforms(*prog, spot_scene()); !st) {
        std::fprintf(stderr, "%s", st.error().str().c_str());
        return 1;
    }
    const auto& fs = state_of(*prog).ir.fragment;
    namespace rt = glslrun::rt;
    glslrun::Precision precision = glslrun::Precision::Precise;
    if (argc > 2) {
        auto parsed = glslrun::parse_precision(argv[2]);
        if (!parsed) {
            std::fprintf(stderr, "bench: %s\n", parsed.error().str().c_str());
            return 1;
        }
        precision = *parsed;
    }
    rt::Interpreter interp(fs, state_of(*prog).uniforms.data(), 1u << 20, nullptr, precision);
    const auto* normal = find_input(fs, "normal");
    const auto* ec_pos = find_input(fs, "ecPos");
    if (!normal || !ec_pos) {
        std::fprintf(stderr, "bench: shader inputs not found\n");
        return 1;
    }
    // A spread of normals and positions on a unit sphere 5 units away, so
    // lanes take both sides of the shader's branches.
    for (int lane = 0; lane < rt::kLanes; ++lane) {
        float t = float(lane) / rt::kLanes * 6.2831853f;
        float n[3] = {std::cos(t), std::sin(t) * 0.6f, 0.5f};
        for (int c = 0; c < 3; ++c) {
            interp.lanes_f(normal->first + c)[lane] = n[c];
            interp.lanes_f(ec_pos->first + c)[lane] = n[c] + (c == 2 ? -5.0f : 0.0f);
        }
    }
    rt::RunError err;
    uint64_t batches = 0;
    auto start = std::chrono::steady_clock::now();
    double cpu_start = thread_cpu_seconds();
    double elapsed = 0;
    while (elapsed < seconds) {
        for (int i = 0; i < 1000; ++i)
            if (!interp.run(rt::kAllLanes, &err)) {
                std::fprintf(stderr, "bench: %s\n", err.message.c_str());
                return 1;
            }
        batches += 1000;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    double cpu = thread_cpu_seconds() - cpu_start;
    size_t instructions = 0;
    std::function<void(const glslrun::ir::Block&)> count = [&](const glslrun::ir::Block& b) {
        for (const auto& n : b) {
            instructions += n.kind == glslrun::ir::NodeKind::Instr;
            count(n.body);
            count(n.alt);
        }
    };
    count(fs.body);
    double invocations = double(batches) * rt::kLanes;
    std::printf("spot_pix_fixed.frag: %zu IR instructions per batch (+%zu in the per-draw prologue), %d lanes, %s\n",
                instructions, fs.prologue.size(), rt::kLanes, glslrun::precision_name(precision));
    std::printf("%.2f M invocations/s on one core (%.0f invocations in %.2f s)\n", invocations / elapsed / 1e6,
                invocations, elapsed);
    std::printf("%.2f M invocations per CPU-second (%.2f CPU-s; the wall-clock figure suffers from other load)\n",
                invocations / cpu / 1e6, cpu);
    return 0;
}
