// One shader compiled for the interpreter and for the JIT, each with an
// executor: the tests that compare the two backends lane by lane.
#pragma once
#include <memory>

#include <catch2/catch.hpp>

#include "ir/ir.h"
#include "runtime/backend_factory.h"

namespace glslrun::test {

struct BackendPair {
    std::unique_ptr<rt::CompiledShader> interp_code, jit_code;  // the executors' code: kept alive
    std::unique_ptr<rt::Executor> interp, jit;
};

inline BackendPair both_backends(const ir::Shader& shader, Precision precision, const rt::ExecParams& params,
                                 bool avx2) {
    BackendPair p;
    p.interp_code = rt::compile_shader(shader, rt::Runner::Interp, precision, params.fast_ops, avx2);
    p.jit_code = rt::compile_shader(shader, rt::Runner::Jit, precision, params.fast_ops, avx2);
    REQUIRE(p.interp_code);
    REQUIRE(p.jit_code);
    p.interp = p.interp_code->instantiate(params);
    p.jit = p.jit_code->instantiate(params);
    return p;
}

}  // namespace glslrun::test
