// Runs one piglit test with the glslrun library: shader_runner semantics for
// .shader_test, glslparsertest semantics for .vert/.frag.
#pragma once
#include <cstdint>
#include <string>

#include "piglit_parse.h"
#include "piglit_suite.h"

namespace glslrun::piglit {

struct RunOptions {
    double time_limit_s = 120;  // checked between commands; loop caps stop runaway shaders
    uint64_t max_loop_iterations = 0;  // 0: the library's default
    Precision precision = Precision::Precise;
    Backend backend = Backend::Auto;
    Capabilities caps;
    // When it becomes true, a running draw stops (ExecOptions::cancel): the
    // wall-clock limit of `glslrun test --no-isolate`.
    const std::atomic<bool>* cancel = nullptr;
    // The test file's name in compile diagnostics, which cite its own lines;
    // "" names the section instead ("[fragment shader]:3" within the section).
    std::string file;
};

// Dispatches on the extension; never throws for bad input (it becomes a fail).
TestResult run_test_file(const std::string& path, const RunOptions& options);

// `dir` resolves [... shader file] sections.
TestResult run_shader_test(const std::string& text, const std::string& dir, const RunOptions& options);
// `ext` is the file's extension (".vert", ".frag", ...); `name` appears in diagnostics.
TestResult run_parser_test(const std::string& text, const std::string& ext, const std::string& name,
                           const RunOptions& options);

// Compiles a small program per GLSL version the suite uses, so that glslang's
// built-in symbol tables (built once per process on first use, per version and
// stage, and read-only afterwards) exist before run_isolated forks: each
// test's child inherits them instead of building them again. With `backend`
// Jit it also draws one pixel through the JIT: LLVM's one-time set-up (its
// engine, and about 10 ms of first-compile work) is then inherited too. Not
// with Auto, whose short tests never compile: a parent with LLVM loaded made
// every fork dearer (the suite took 30% more CPU than with Interp).
void warm_up_compiler(Backend backend);

}  // namespace glslrun::piglit
