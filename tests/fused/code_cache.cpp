// A pipeline the code cache holds is taken at a program's first draw, before
// the program has shaded fused::kPipelineAfterFragments fragments: loading
// it costs no LLVM time (raster/fused/pipeline.h). Without it in the cache,
// nothing is compiled before it is due.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>

#include "glslrun/glslrun.h"
#include "raster/fused/pipeline.h"
#include "tests/fused/states.h"

using namespace glslrun;
using namespace glslrun::raster;

namespace {

// A fresh directory, removed with its files at the end of the scope.
struct TempDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("glslrun-fused-cache-" + std::to_string(std::random_device{}()));
    TempDir() { std::filesystem::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

}  // namespace

TEST_CASE("a pipeline in the code cache is taken at the first draw, before it is due", "[fused]") {
    if (!jit_available()) return;  // no pipelines without the JIT
    TempDir dir;
    ExecOptions options;
    options.code_cache_dir = dir.path.string();
    const fused::State state = fused_test::plain_state(__builtin_cpu_supports("avx2"));
    fused::State other = state;  // never compiled: not in the cache
    other.ops.blend = true;
    other.early_depth = false;

    fused::Cache cold;
    CHECK(cold.get(state, true, options) == nullptr);  // not due, and the cache is empty
    CHECK(cold.counts().compiled + cold.counts().loaded == 0u);
    cold.count_unfused(fused::kPipelineAfterFragments);
    REQUIRE(cold.get(state, true, options) != nullptr);
    CHECK(cold.counts().compiled == 1u);

    fused::Cache warm;  // another program of the same shaders, in a later run
    const fused::Pipeline* loaded = warm.get(state, true, options);
    REQUIRE(loaded != nullptr);
    CHECK(loaded->square_depth != nullptr);
    CHECK(warm.get(state, true, options) == loaded);
    CHECK(warm.counts().loaded == 1u);
    CHECK(warm.get(other, true, options) == nullptr);  // nothing compiled before it is due
    CHECK(warm.get(other, true, options) == nullptr);
    CHECK(warm.counts().compiled == 0u);

    ExecOptions no_cache = options;
    no_cache.code_cache = false;
    fused::Cache off;
    CHECK(off.get(state, true, no_cache) == nullptr);
}
