#include "scene/bench_report.h"

#include <time.h>

#include <algorithm>
#include <numeric>

#include <fmt/format.h>

namespace glslrun::scene {

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : (values[mid - 1] + values[mid]) / 2;
}

double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

std::string format_bench(const BenchReport& r) {
    std::string out;
    auto line = [&](const std::string& key, const std::string& value) { out += fmt::format("{:<16} {}\n", key, value); };
    auto ms = [&](const std::string& key, double seconds) { line(key + "_ms", fmt::format("{:.3f}", seconds * 1e3)); };
    line("renderer", r.renderer);
    line("size", fmt::format("{}x{}", r.width, r.height));
    line("threads", r.threads);
    if (!r.precision.empty()) line("precision", r.precision);
    if (!r.backend.empty()) line("backend", r.backend);
    line("frames", std::to_string(r.frame_s.size()));
    ms("compile", r.compile_s);
    ms("first_draw", r.first_draw_s);
    ms("first_frame", r.compile_s + r.first_draw_s);
    ms("median", median(r.frame_s));
    ms("min", r.frame_s.empty() ? 0 : *std::min_element(r.frame_s.begin(), r.frame_s.end()));
    // Throughput over all frames after the first, as a frames/s counter would show it.
    double total = std::accumulate(r.frame_s.begin(), r.frame_s.end(), 0.0);
    line("fps", fmt::format("{:.2f}", total > 0 ? double(r.frame_s.size()) / total : 0.0));
    ms("cpu_median", median(r.frame_cpu_s));
    for (const auto& [stage, seconds] : r.stage_s) ms(stage, median(seconds));
    for (const auto& [what, seconds] : r.once_s) ms(what, seconds);
    for (const auto& [what, count] : r.counts) line(what, std::to_string(count));
    return out;
}

}  // namespace glslrun::scene
