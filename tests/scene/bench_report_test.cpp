// The `key value` lines of --bench (scene/bench_report.h), which
// bench/side_by_side.py parses for glslrun and glref alike.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "tests/scene/key_lines.h"
#include "scene/bench_report.h"

using namespace glslrun::scene;

TEST_CASE("median of odd and even counts, unsorted", "[scene][bench]") {
    CHECK(median({}) == 0);
    CHECK(median({3.0}) == 3.0);
    CHECK(median({5.0, 1.0, 3.0}) == 3.0);
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5);
}

TEST_CASE("the bench report's keys and values", "[scene][bench]") {
    BenchReport r;
    r.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.width = 640;
    r.height = 480;
    r.threads = "auto";
    r.compile_s = 0.002;
    r.first_draw_s = 0.030;
    r.frame_s = {0.010, 0.030, 0.020, 0.040};
    r.frame_cpu_s = {0.009, 0.008, 0.007};
    r.stage_s = {{"vertex", {0.001, 0.003, 0.002}}};
    r.once_s = {{"output", 0.005}};
    r.counts = {{"triangles", 6400}};
    auto v = scene_test::parse_key_lines(format_bench(r));
    CHECK(v["renderer"] == "llvmpipe (LLVM 15.0.6, 256 bits)");
    CHECK(v["size"] == "640x480");
    CHECK(v["threads"] == "auto");
    CHECK(v["frames"] == "4");
    CHECK(v["compile_ms"] == "2.000");
    CHECK(v["first_draw_ms"] == "30.000");
    CHECK(v["first_frame_ms"] == "32.000");
    CHECK(v["median_ms"] == "25.000");
    CHECK(v["min_ms"] == "10.000");
    CHECK(v["fps"] == "40.00");  // 4 frames in 0.1 s
    CHECK(v["cpu_median_ms"] == "8.000");
    CHECK(v["vertex_ms"] == "2.000");
    CHECK(v["output_ms"] == "5.000");
    CHECK(v["triangles"] == "6400");
    CHECK(v.size() == 14);
}
