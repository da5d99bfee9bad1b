// A small helper to build IR by hand in tests (runtime and ir passes), and to
// run it over the kLanes lanes of the interpreter.
#pragma once
#include <bit>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

#include "ir/ir.h"
#include "runtime/interpreter.h"

namespace glslrun::test {

using ir::Kind;
using ir::NodeKind;
using ir::Op;
using ir::Reg;

inline uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }
inline uint32_t bits(int32_t i) { return static_cast<uint32_t>(i); }
inline float as_float(uint32_t w) { return std::bit_cast<float>(w); }

struct Builder {
    ir::Shader sh;
    ir::Block* cur = &sh.body;
    int line = 1;

    explicit Builder(ir::Stage stage = ir::Stage::Fragment) { sh.stage = stage; }

    Reg reg(Kind k) {
        sh.regs.push_back(k);
        return Reg(sh.regs.size() - 1);
    }
    // `count` consecutive registers of one kind; returns the first.
    Reg range(Kind k, uint32_t count) {
        Reg first = Reg(sh.regs.size());
        for (uint32_t i = 0; i < count; ++i) sh.regs.push_back(k);
        return first;
    }

    ir::Node& push(ir::Node n) {
        n.loc.line = line++;
        cur->push_back(std::move(n));
        return cur->back();
    }
    void instr(Op op, Kind type, Reg dst, std::initializer_list<Reg> src, std::initializer_list<uint32_t> imm = {}) {
        ir::Node n;
        n.instr.op = op;
        n.instr.type = type;
        n.instr.dst = dst;
        int k = 0;
        for (Reg r : src) n.instr.src[k++] = r;
        k = 0;
        for (uint32_t v : imm) n.instr.imm[k++] = v;
        push(std::move(n));
    }

    Reg konst(Kind k, uint32_t raw) {
        Reg d = reg(k);
        instr(Op::konst, k, d, {}, {raw});
        return d;
    }
    Reg kf(float f) { return konst(Kind::F32, bits(f)); }
    Reg ki(int32_t i) { return konst(Kind::I32, bits(i)); }
    Reg kb(bool b) { return konst(Kind::Bool, b ? 1u : 0u); }
    void set_konst(Reg dst, uint32_t raw) { instr(Op::konst, sh.regs[dst], dst, {}, {raw}); }

    static Kind result_kind(Op op, Kind type) {
        switch (ir::op_info(op).result) {
        case ir::TypeClass::F: return Kind::F32;
        case ir::TypeClass::I: return Kind::I32;
        case ir::TypeClass::B: return Kind::Bool;
        default: return type;
        }
    }
    // A fresh destination for an Alu op.
    Reg alu(Op op, std::initializer_list<Reg> src) {
        Kind k = result_kind(op, Kind::F32);
        Reg d = reg(k);
        instr(op, k, d, src);
        return d;
    }
    void alu_to(Reg dst, Op op, std::initializer_list<Reg> src) { instr(op, sh.regs[dst], dst, src); }
    void mov(Reg dst, Reg src) { instr(Op::mov, sh.regs[dst], dst, {src}); }

    void nested(ir::Node n, const std::function<void()>& body, const std::function<void()>& alt) {
        n.loc.line = line++;
        ir::Block* saved = cur;
        cur = &n.body;
        if (body) body();
        cur = &n.alt;
        if (alt) alt();
        cur = saved;
        cur->push_back(std::move(n));
    }
    void if_(Reg cond, const std::function<void()>& then, const std::function<void()>& otherwise = {}) {
        ir::Node n;
        n.kind = NodeKind::If;
        n.cond = cond;
        nested(std::move(n), then, otherwise);
    }
    void loop(const std::function<void()>& body, const std::function<void()>& cont = {}) {
        ir::Node n;
        n.kind = NodeKind::Loop;
        nested(std::move(n), body, cont);
    }
    void scope(const std::function<void()>& body) {
        ir::Node n;
        n.kind = NodeKind::Scope;
        nested(std::move(n), body, {});
    }
    void leaf(NodeKind k) {
        ir::Node n;
        n.kind = k;
        push(std::move(n));
    }
    void brk() { leaf(NodeKind::Break); }
    void cont() { leaf(NodeKind::Continue); }
    void ret() { leaf(NodeKind::Return); }
    void discard() { leaf(NodeKind::Discard); }
    void call(uint32_t callee) {
        ir::Node n;
        n.kind = NodeKind::Call;
        n.callee = callee;
        push(std::move(n));
    }
    uint32_t function(const char* name, const std::function<void()>& body) {
        sh.functions.push_back({name, {}});
        uint32_t index = uint32_t(sh.functions.size() - 1);
        ir::Block block;
        ir::Block* saved = cur;
        cur = &block;
        body();
        cur = saved;
        sh.functions[index].body = std::move(block);
        return index;
    }

    void output(const char* name, Reg r) { sh.outputs.push_back({name, sh.regs[r], r, 1}); }
    void input(const char* name, Reg r) { sh.inputs.push_back({name, sh.regs[r], r, 1}); }
};

// Runs a shader with per-lane inputs; returns per-lane words of the watched registers.
struct Runner {
    const ir::Shader& shader;
    std::vector<uint32_t> uniforms;
    uint64_t max_iterations = 1u << 16;
    std::unique_ptr<rt::Interpreter> it;

    explicit Runner(const ir::Shader& s, std::vector<uint32_t> u = {}) : shader(s), uniforms(std::move(u)) {
        if (uniforms.empty()) uniforms.push_back(0);
        it = std::make_unique<rt::Interpreter>(shader, uniforms.data(), max_iterations);
    }
    void set(Reg r, const std::function<uint32_t(int)>& lane_value) {
        for (int i = 0; i < rt::kLanes; ++i) it->lanes(r)[i] = lane_value(i);
    }
    void setf(Reg r, const std::function<float(int)>& lane_value) {
        for (int i = 0; i < rt::kLanes; ++i) it->lanes(r)[i] = bits(lane_value(i));
    }
    bool run(rt::LaneMask live = rt::kAllLanes, rt::RunError* error = nullptr) {
        rt::RunError e;
        return it->run(live, error ? error : &e);
    }
    uint32_t at(Reg r, int lane) { return it->lanes(r)[lane]; }
    float f(Reg r, int lane) { return as_float(at(r, lane)); }
    int32_t i(Reg r, int lane) { return int32_t(at(r, lane)); }
};

}  // namespace glslrun::test
