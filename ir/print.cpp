// The IR printer: the debugging tool (glslrun --dump-ir) and the basis of the
// golden tests, so its output is stable and complete.
#include <array>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "ir/passes.h"
#include "ir/undefined.h"

namespace glslrun::ir {
namespace {

std::string reg_name(Reg r) { return r == kNoReg ? std::string("_") : fmt::format("%{}", r); }

std::string konst_text(Kind kind, uint32_t bits) {
    switch (kind) {
    case Kind::F32: {
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return fmt::format("{}", f);
    }
    case Kind::I32: return fmt::format("{}", int32_t(bits));
    case Kind::Bool: return bits ? "true" : "false";
    }
    return "?";
}

std::string instr_text(const Instr& in) {
    const OpInfo& info = op_info(in.op);
    std::string s;
    if (in.dst != kNoReg) s += fmt::format("{}:{} = ", reg_name(in.dst), kind_name(in.type));
    s += info.name;
    switch (in.op) {
    case Op::konst: return s + " " + konst_text(in.type, in.imm[0]);
    case Op::uniform: return s + fmt::format(" u{}", in.imm[0]);
    case Op::uniform_ind:
        return s + fmt::format(" u{}[{} of {}, stride {}]", in.imm[0], reg_name(in.src[0]), in.imm[1], in.imm[2]);
    case Op::load_ind:
        return s + fmt::format(" %{}[{} of {}, stride {}]", in.imm[0], reg_name(in.src[0]), in.imm[1], in.imm[2]);
    case Op::store_ind:
        return s + fmt::format(":{} %{}[{} of {}, stride {}] = {}", kind_name(in.type), in.imm[0],
                               reg_name(in.src[0]), in.imm[1], in.imm[2], reg_name(in.src[1]));
    case Op::check_undef:
        return s + fmt::format(":{} {} ({}, {}, {}) site {}", kind_name(in.type),
                               undef_info(UndefOp(in.imm[0] % uint32_t(UndefOp::Count_))).name, reg_name(in.src[0]),
                               reg_name(in.src[1]), reg_name(in.src[2]), in.imm[1]);
    case Op::tex: {
        // By TexTarget: a target added there without a name here does not compile.
        static constexpr std::array<const char*, size_t(TexTarget::A2D) + 1> targets = {
            "1d", "2d", "3d", "cube", "rect", "1darray", "2darray"};
        static_assert(targets.back() != nullptr);
        static const char* const lods[] = {"lod", "implicit", "bias"};
        const TexInfo t = TexInfo::decode(in.imm[2]);
        return s + fmt::format(".{}{}.{} unit {}, %{}..%{} (result %{}..%{})", targets[int(t.target)],
                               t.shadow ? ".shadow" : "", lods[int(t.lod)], reg_name(in.src[0]), in.imm[0],
                               in.imm[0] + in.imm[1] - 1, in.dst, in.dst + kTexResults - 1);
    }
    default: break;
    }
    for (int i = 0; i < info.arity; ++i) s += (i ? ", " : " ") + reg_name(in.src[i]);
    return s;
}

// " ; 12:5" (source 0) or " ; s1:12" (another source of the stage): where
// the node comes from; nothing for nodes without a line.
std::string loc_text(const SourceLoc& loc) {
    if (loc.line <= 0) return {};
    std::string source = loc.source ? fmt::format("s{}:", loc.source) : std::string();
    std::string column = loc.column ? fmt::format(":{}", loc.column) : std::string();
    return fmt::format(" ; {}{}{}", source, loc.line, column);
}

void print_block(std::string& out, const Block& block, int depth);

void print_node(std::string& out, const Node& n, int depth) {
    std::string pad(size_t(depth) * 2, ' ');
    std::string at = loc_text(n.loc) + "\n";
    switch (n.kind) {
    case NodeKind::Instr: out += pad + instr_text(n.instr) + at; return;
    case NodeKind::Break: out += pad + "break" + at; return;
    case NodeKind::Continue: out += pad + "continue" + at; return;
    case NodeKind::Return: out += pad + "return" + at; return;
    case NodeKind::Discard: out += pad + "discard" + at; return;
    case NodeKind::Call: out += pad + fmt::format("call @{}", n.callee) + at; return;
    case NodeKind::If:
        out += pad + fmt::format("if {} {{", reg_name(n.cond)) + at;
        print_block(out, n.body, depth + 1);
        if (!n.alt.empty()) {
            out += pad + "} else {\n";
            print_block(out, n.alt, depth + 1);
        }
        out += pad + "}\n";
        return;
    case NodeKind::Loop:
        out += pad + "loop {" + at;
        print_block(out, n.body, depth + 1);
        if (!n.alt.empty()) {
            out += pad + "} continue {\n";
            print_block(out, n.alt, depth + 1);
        }
        out += pad + "}\n";
        return;
    case NodeKind::Scope:
        out += pad + "scope {" + at;
        print_block(out, n.body, depth + 1);
        out += pad + "}\n";
        return;
    }
}

void print_block(std::string& out, const Block& block, int depth) {
    for (const Node& n : block) print_node(out, n, depth);
}

void print_bindings(std::string& out, const char* what, const std::vector<Binding>& bindings) {
    for (const Binding& b : bindings)
        out += fmt::format("{} {}:{} = %{}..%{}\n", what, b.name, kind_name(b.kind), b.first,
                           b.first + b.count - 1);
}

}  // namespace

std::string print(const Shader& shader) {
    std::string out = shader.stage == Stage::Vertex ? "vertex shader\n" : "fragment shader\n";
    out += fmt::format("registers {}\n", shader.regs.size());
    for (size_t i = 0; i < shader.sources.size(); ++i) out += fmt::format("source s{} {}\n", i, shader.sources[i]);
    print_bindings(out, "in", shader.inputs);
    print_bindings(out, "out", shader.outputs);
    for (size_t i = 0; i < shader.functions.size(); ++i) {
        out += fmt::format("function @{} {} {{\n", i, shader.functions[i].name);
        print_block(out, shader.functions[i].body, 1);
        out += "}\n";
    }
    if (!shader.prologue.empty()) {
        out += "prologue {\n";
        print_block(out, shader.prologue, 1);
        out += "}\n";
    }
    out += "main {\n";
    print_block(out, shader.body, 1);
    out += "}\n";
    return out;
}

std::string print(const Program& program) {
    std::string out;
    for (const Uniform& u : program.uniforms)
        out += fmt::format("uniform u{} {}{}: {}{}x{}\n", u.slot, u.name,
                           u.is_array ? fmt::format("[{}]", u.array_size) : "",
                           u.type.is_sampler ? "sampler " : kind_name(u.type.kind), int(u.type.cols),
                           int(u.type.rows));
    out += print(program.vertex);
    out += print(program.fragment);
    return out;
}

}  // namespace glslrun::ir
