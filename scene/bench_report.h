// Frame timings of `glslrun --bench N` and `glref --bench N` as `key value`
// lines, one format for both, so that scripts (bench/side_by_side.py) read
// glslrun's and Mesa's numbers the same way. Times are milliseconds.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace glslrun::scene {

struct BenchReport {
    std::string renderer;  // "glslrun", or Mesa's GL_RENDERER
    int width = 0, height = 0;
    std::string threads;   // as asked for: a count, or "auto"
    std::string precision;  // glslrun's --precision; empty for Mesa (not printed)
    std::string backend;    // glslrun's backend (interp, jit); empty for Mesa (not printed)
    double compile_s = 0;     // building the program (Mesa: glCompileShader + glLinkProgram)
    double first_draw_s = 0;  // the first frame (llvmpipe compiles its shaders there)
    std::vector<double> frame_s;  // the N frames after the first
    // The same frames' process CPU time (all threads): barely moved by a
    // neighbour's load, unlike wall time, on a shared machine.
    std::vector<double> frame_cpu_s;
    // Per stage ("vertex", ...), one time per frame after the first; printed as their median.
    std::vector<std::pair<std::string, std::vector<double>>> stage_s;
    // Printed as they are (e.g. "output": the PNG, written once).
    std::vector<std::pair<std::string, double>> once_s;
    // Counts per frame (vertices, triangles, fragments).
    std::vector<std::pair<std::string, unsigned long long>> counts;
};

double median(std::vector<double> values);  // 0 when empty
double process_cpu_seconds();  // CLOCK_PROCESS_CPUTIME_ID: every thread of this process

// "key value" lines: renderer, size, threads, precision and backend (if any), frames, compile_ms,
// first_draw_ms, first_frame_ms, median_ms, min_ms, fps, cpu_median_ms,
// then <stage>_ms (medians), the once-only times and the counts.
std::string format_bench(const BenchReport& report);

}  // namespace glslrun::scene
