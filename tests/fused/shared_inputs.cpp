// The fused pipelines of one program share their inputs function: it depends
// on the state's inputs and ISA alone (raster/fused/pipeline.h, InputsCode),
// so a program that draws with several states compiles it once.
#include <catch2/catch.hpp>

#include "glslrun/glslrun.h"
#include "raster/fused/pipeline.h"
#include "tests/fused/states.h"

using namespace glslrun;
using namespace glslrun::raster;

TEST_CASE("a program's fused pipelines share one inputs function", "[fused]") {
    if (!jit_available()) return;  // no pipelines without the JIT
    fused::Cache cache;
    cache.count_unfused(fused::kPipelineAfterFragments);
    ExecOptions options;
    options.code_cache = false;
    const fused::State early = fused_test::plain_state(__builtin_cpu_supports("avx2"));
    fused::State blended = early;  // another state, the same inputs
    blended.ops.blend = true;
    blended.early_depth = false;
    fused::State stencil = early;
    stencil.ops.stencil_test = true;
    stencil.early_depth = false;
    fused::State more_inputs = early;  // other inputs: a function of their own
    more_inputs.inputs.push_back({fused::InputSource::Varying, 1, ir::Kind::F32, false});
    const fused::Pipeline* a = cache.get(early, true, options);
    const fused::Pipeline* b = cache.get(blended, true, options);
    const fused::Pipeline* c = cache.get(stencil, true, options);
    const fused::Pipeline* d = cache.get(more_inputs, true, options);
    REQUIRE((a && b && c && d));
    CHECK(cache.counts().compiled == 4u);
    CHECK(a->shared_inputs == b->shared_inputs);
    CHECK(a->shared_inputs == c->shared_inputs);
    CHECK((a->inputs == b->inputs && a->inputs == c->inputs));
    CHECK((a->outputs != b->outputs && b->outputs != c->outputs));
    CHECK(d->shared_inputs != a->shared_inputs);
    CHECK(d->inputs != a->inputs);
    // The early depth test is the early state's alone.
    CHECK(a->quad_depth != nullptr);
    CHECK(b->quad_depth == nullptr);
}
