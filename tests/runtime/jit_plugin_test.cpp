// The JIT plugin (runtime/jit_plugin.h) in a build that has one: it loads,
// or every test that compares the JIT with the interpreter would skip.
#include <catch2/catch.hpp>

#include "glslrun/glslrun.h"
#include "runtime/jit_plugin.h"

TEST_CASE("jit plugin: a build with the JIT loads its plugin") {
#ifdef GLSLRUN_TEST_JIT_BUILT
    INFO(glslrun::rt::jit_plugin_error());
    CHECK(glslrun::rt::jit_plugin_present());
    REQUIRE(glslrun::jit_available());
    CHECK(glslrun::rt::jit_plugin()->compile != nullptr);
    CHECK(glslrun::rt::jit_plugin_error().empty());
    CHECK(glslrun::effective_backend(glslrun::Backend::Auto, glslrun::Precision::Precise) == glslrun::Backend::Jit);
#else
    CHECK_FALSE(glslrun::jit_available());
    CHECK(glslrun::effective_backend(glslrun::Backend::Jit, glslrun::Precision::Precise) == glslrun::Backend::Interp);
#endif
    CHECK(glslrun::effective_backend(glslrun::Backend::Auto, glslrun::Precision::Reference) ==
          glslrun::Backend::Interp);
}
