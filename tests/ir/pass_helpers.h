// Helpers for the pass tests: shape queries on the IR and a check that a
// transformed shader computes the same outputs as the original on every lane.
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "ir/flow.h"
#include "ir/passes.h"
#include "tests/runtime/ir_builder.h"

namespace glslrun::test {

inline size_t count_nodes(const ir::Block& b, const std::function<bool(const ir::Node&)>& pred) {
    size_t n = 0;
    ir::flow::walk(b, [&](const ir::Node& node) { n += pred(node) ? 1 : 0; });
    return n;
}
inline size_t count_op(const ir::Shader& s, Op op) {
    size_t n = count_nodes(s.body, [&](const ir::Node& x) { return x.kind == NodeKind::Instr && x.instr.op == op; });
    for (const ir::Function& f : s.functions)
        n += count_nodes(f.body, [&](const ir::Node& x) { return x.kind == NodeKind::Instr && x.instr.op == op; });
    return n;
}
inline size_t count_kind(const ir::Shader& s, NodeKind k) {
    size_t n = count_nodes(s.body, [&](const ir::Node& x) { return x.kind == k; });
    for (const ir::Function& f : s.functions) n += count_nodes(f.body, [&](const ir::Node& x) { return x.kind == k; });
    return n;
}
// The instruction writing `dst` (the last one in pre-order), or nullptr.
inline const ir::Instr* writer_of(const ir::Shader& s, Reg dst) {
    const ir::Instr* found = nullptr;
    ir::flow::walk(s.body, [&](const ir::Node& n) {
        if (n.kind == NodeKind::Instr && n.instr.dst == dst) found = &n.instr;
    });
    return found;
}

// A fresh register bound as an input.
inline Reg input(Builder& b, const char* name, Kind k = Kind::F32) {
    Reg r = b.reg(k);
    b.input(name, r);
    return r;
}

// Per-lane input values by kind: varied, deterministic, and keyed by the
// input's position among the shader's inputs, never by register number (the
// register allocator renumbers registers).
inline uint32_t input_value(Kind k, uint32_t index, int lane) {
    int v = int(index * 5 + uint32_t(lane) * 3) % 13 - 6;
    switch (k) {
    case Kind::F32: return bits(float(v) * 0.37f + 0.11f);
    case Kind::I32: return bits(int32_t(v & 3));
    case Kind::Bool: return uint32_t(v & 1);
    }
    return 0;
}

// Every output of every lane, then the alive mask, after running `s` with
// input_value() inputs.
inline std::vector<uint32_t> run_outputs(const ir::Shader& s, const std::vector<uint32_t>& uniforms = {}) {
    Runner r(s, uniforms);
    uint32_t index = 0;
    for (const ir::Binding& b : s.inputs)
        for (uint32_t c = 0; c < b.count; ++c, ++index)
            r.set(b.first + c, [&, index](int lane) { return input_value(b.kind, index, lane); });
    rt::RunError error;
    bool ok = r.run(rt::kAllLanes, &error);
    INFO("run error: " << error.message);
    REQUIRE(ok);
    std::vector<uint32_t> out;
    for (const ir::Binding& b : s.outputs)
        for (uint32_t c = 0; c < b.count; ++c)
            for (int lane = 0; lane < rt::kLanes; ++lane) out.push_back(r.at(b.first + c, lane));
    for (int lane = 0; lane < rt::kLanes; ++lane) out.push_back(uint32_t((r.it->alive() >> lane) & 1));
    return out;
}

inline std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Applies `pass` to a copy of `s`; checks it verifies and computes the same outputs.
inline ir::Shader check_pass(const ir::Shader& s, const std::function<void(ir::Shader&)>& pass,
                             const std::vector<uint32_t>& uniforms = {}) {
    REQUIRE(ir::verify(s) == "");
    ir::Shader t = s;
    pass(t);
    INFO("after:\n" << ir::print(t));
    REQUIRE(ir::verify(t) == "");
    CHECK(run_outputs(s, uniforms) == run_outputs(t, uniforms));
    return t;
}

}  // namespace glslrun::test
