// The IR verifier. It runs after every pass when CompileOptions::verify_ir or
// the environment's GLSLRUN_VERIFY=1 asks for it (every ctest test sets it),
// so a pass that breaks an invariant is named at once instead of showing up
// later as a wrong pixel.
#include <string>

#include <fmt/format.h>

#include "ir/passes.h"
#include "ir/undefined.h"

namespace glslrun::ir {
namespace {

struct Verifier {
    const Shader& shader;
    std::string error;

    bool fail(const Node& n, const std::string& what) {
        if (error.empty()) error = fmt::format("line {}: {}", n.loc.line, what);
        return false;
    }
    bool reg_ok(Reg r) const { return r != kNoReg && r < shader.regs.size(); }
    bool range_ok(uint32_t base, uint32_t count, uint32_t stride) const {
        if (count == 0 || stride == 0) return false;
        uint64_t last = uint64_t(base) + uint64_t(count - 1) * stride;
        return last < shader.regs.size();
    }

    // Checks one register against an operand/result class of the table.
    bool class_ok(TypeClass c, Reg r, Kind instr_type) const {
        Kind k = shader.regs[r];
        switch (c) {
        case TypeClass::F: return k == Kind::F32;
        case TypeClass::I: return k == Kind::I32;
        case TypeClass::B: return k == Kind::Bool;
        case TypeClass::T: return k == instr_type;
        case TypeClass::X: return true;
        }
        return false;
    }

    bool instr(const Node& n) {
        const Instr& in = n.instr;
        if (size_t(in.op) >= size_t(Op::Count_)) return fail(n, "bad opcode");
        const OpInfo& info = op_info(in.op);
        for (int i = 0; i < info.arity; ++i) {
            if (!reg_ok(in.src[i])) return fail(n, fmt::format("{}: operand {} out of range", info.name, i));
            if (info.kind == OpKind::Alu && !class_ok(info.operand, in.src[i], in.type))
                return fail(n, fmt::format("{}: operand {} has kind {}", info.name, i, kind_name(shader.regs[in.src[i]])));
        }
        for (int i = info.arity; i < 3; ++i)
            if (in.src[i] != kNoReg) return fail(n, fmt::format("{}: extra operand {}", info.name, i));
        if (in.op == Op::check_undef) return check_undef(n);
        if (in.op == Op::store_ind) {
            if (in.dst != kNoReg) return fail(n, "store_ind has a destination");
            if (shader.regs[in.src[0]] != Kind::I32) return fail(n, "store_ind index is not i32");
            if (shader.regs[in.src[1]] != in.type) return fail(n, "store_ind value kind differs from its type");
            if (!range_ok(in.imm[0], in.imm[1], in.imm[2])) return fail(n, "store_ind range out of bounds");
            for (uint32_t e = 0; e < in.imm[1]; ++e)
                if (shader.regs[in.imm[0] + e * in.imm[2]] != in.type) return fail(n, "store_ind range kind mismatch");
            return true;
        }
        if (!reg_ok(in.dst)) return fail(n, fmt::format("{}: destination out of range", info.name));
        if (!class_ok(info.result == TypeClass::X ? TypeClass::T : info.result, in.dst, in.type) ||
            shader.regs[in.dst] != in.type)
            return fail(n, fmt::format("{}: destination %{} is {}, instruction type {}", info.name, in.dst,
                                       kind_name(shader.regs[in.dst]), kind_name(in.type)));
        switch (in.op) {
        case Op::mov:
            if (shader.regs[in.src[0]] != in.type) return fail(n, "mov between kinds");
            break;
        case Op::sel:
            if (shader.regs[in.src[0]] != Kind::Bool) return fail(n, "sel condition is not bool");
            if (shader.regs[in.src[1]] != in.type || shader.regs[in.src[2]] != in.type)
                return fail(n, "sel operands differ from its type");
            break;
        case Op::uniform_ind:
        case Op::load_ind:
            if (shader.regs[in.src[0]] != Kind::I32) return fail(n, "index is not i32");
            if (in.imm[1] == 0 || in.imm[2] == 0) return fail(n, "empty indexed range");
            if (in.op == Op::load_ind) {
                if (!range_ok(in.imm[0], in.imm[1], in.imm[2])) return fail(n, "load_ind range out of bounds");
                for (uint32_t e = 0; e < in.imm[1]; ++e)
                    if (shader.regs[in.imm[0] + e * in.imm[2]] != in.type)
                        return fail(n, "load_ind range kind mismatch");
            }
            break;
        case Op::ddx:
        case Op::ddy:
            if (shader.stage != Stage::Fragment) return fail(n, "derivative outside a fragment shader");
            break;
        case Op::tex: return tex(n);
        default: break;
        }
        return true;
    }

    bool check_undef(const Node& n) {
        const Instr& in = n.instr;
        if (in.dst != kNoReg) return fail(n, "check_undef has a destination");
        if (in.imm[0] >= uint32_t(UndefOp::Count_)) return fail(n, "check_undef: bad UndefOp");
        if (in.imm[1] >= shader.undef_sites.size()) return fail(n, "check_undef: no such site");
        if (in.type != Kind::F32 && in.type != Kind::I32) return fail(n, "check_undef: operands are not f32 or i32");
        for (Reg r : in.src)
            if (shader.regs[r] != in.type) return fail(n, "check_undef: operand kind differs from its type");
        return true;
    }

    bool tex(const Node& n) {
        const Instr& in = n.instr;
        const TexInfo t = TexInfo::decode(in.imm[2]);
        if (in.imm[2] != t.encode() || int(t.lod) > int(TexLod::ImplicitBias) || int(t.target) > int(TexTarget::A2D))
            return fail(n, "tex: bad TexInfo");
        if (shader.regs[in.src[0]] != Kind::I32) return fail(n, "tex: unit is not i32");
        if (in.type != Kind::F32) return fail(n, "tex: result is not f32");
        if (in.imm[1] != t.operand_count()) return fail(n, "tex: operand count differs from its TexInfo");
        // An implicit LOD outside a fragment shader is texture*GradARB's (its
        // operands are the given gradients, not ddx/ddy of the coordinates).
        if (!range_ok(in.imm[0], in.imm[1], 1) || !range_ok(in.dst, kTexResults, 1))
            return fail(n, "tex: register block out of bounds");
        for (uint32_t k = 0; k < in.imm[1]; ++k)
            if (shader.regs[in.imm[0] + k] != Kind::F32) return fail(n, "tex: operand is not f32");
        for (uint32_t k = 0; k < kTexResults; ++k)
            if (shader.regs[in.dst + k] != Kind::F32) return fail(n, "tex: result is not f32");
        return true;
    }

    bool block(const Block& b, int loops, int returnable) {
        for (const Node& n : b)
            if (!node(n, loops, returnable)) return false;
        return true;
    }

    bool node(const Node& n, int loops, int returnable) {
        switch (n.kind) {
        case NodeKind::Instr: return instr(n);
        case NodeKind::If:
            if (!reg_ok(n.cond) || shader.regs[n.cond] != Kind::Bool) return fail(n, "if condition is not a bool register");
            return block(n.body, loops, returnable) && block(n.alt, loops, returnable);
        case NodeKind::Loop: return block(n.body, loops + 1, returnable) && block(n.alt, loops + 1, returnable);
        case NodeKind::Break:
        case NodeKind::Continue:
            return loops > 0 ? true : fail(n, "break/continue outside a loop");
        case NodeKind::Return: return returnable > 0 ? true : fail(n, "return outside a function or scope");
        case NodeKind::Discard:
            return shader.stage == Stage::Fragment ? true : fail(n, "discard outside a fragment shader");
        case NodeKind::Call:
            return n.callee < shader.functions.size() ? true : fail(n, "call to a missing function");
        case NodeKind::Scope: return block(n.body, 0, returnable + 1);
        }
        return fail(n, "bad node kind");
    }

    void bindings(const std::vector<Binding>& list) {
        for (const Binding& b : list) {
            if (!error.empty()) return;
            if (b.count == 0 || !range_ok(b.first, b.count, 1)) {
                error = fmt::format("binding {} out of range", b.name);
                return;
            }
            for (uint32_t i = 0; i < b.count; ++i)
                if (shader.regs[b.first + i] != b.kind) error = fmt::format("binding {} kind mismatch", b.name);
        }
    }
};

}  // namespace

std::string verify(const Shader& shader) {
    Verifier v{shader, {}};
    v.bindings(shader.inputs);
    v.bindings(shader.outputs);
    // A function body may return; loops do not extend into callees.
    for (size_t i = 0; i < shader.functions.size() && v.error.empty(); ++i)
        if (!v.block(shader.functions[i].body, 0, 1))
            v.error = fmt::format("function {}: {}", shader.functions[i].name, v.error);
    // The prologue runs once for all lanes: instructions only.
    for (size_t i = 0; i < shader.prologue.size() && v.error.empty(); ++i) {
        const Node& n = shader.prologue[i];
        if (n.kind == NodeKind::Instr) v.instr(n);
        else v.fail(n, "control flow in the prologue");
    }
    if (v.error.empty()) v.block(shader.body, 0, 1);
    return v.error;
}

}  // namespace glslrun::ir
