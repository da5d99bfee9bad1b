// CompileOptions::check_undefined: reads of a variable that no write has
// reached in this invocation (GLSL 1.20 §4.3: such variables "enter main()
// with undefined values"; §7.2: reading gl_FragColor before writing it
// "results in an undefined value"). The static analysis (ir/assigned.h)
// finds the variables' registers that some lane may read before writing;
// each of those gets a shadow i32 register, 0 at the body's start and 1
// after every write (a store_ind marks its whole array: it may have written
// any element), and a check_undef (ir/undefined.h, UndefOp::Unwritten)
// before every read, so only a read that a run really reaches unwritten is
// reported. Runs on the frontend's IR, where the registers are still the
// variables' (Shader::variables), before inlining.
#include <vector>

#include "ir/assigned.h"
#include "ir/flow.h"
#include "ir/passes.h"
#include "ir/undefined.h"

namespace glslrun::ir {
namespace {

struct Instrumenter {
    Shader& shader;
    std::vector<Reg> shadow;  // by register: its shadow, or kNoReg

    Node instr_node(const Instr& in, const SourceLoc& loc) {
        Node n;
        n.kind = NodeKind::Instr;
        n.instr = in;
        n.loc = loc;
        return n;
    }

    Node set_shadow(Reg s, uint32_t value, const SourceLoc& loc) {
        Instr in;
        in.op = Op::konst;
        in.type = Kind::I32;
        in.dst = s;
        in.imm[0] = value;
        return instr_node(in, loc);
    }

    Node check(Reg s, const SourceLoc& loc) {
        UndefSite site;
        site.op = uint8_t(UndefOp::Unwritten);
        site.loc = loc;
        shader.undef_sites.push_back(site);
        Instr in;
        in.op = Op::check_undef;
        in.type = Kind::I32;
        in.src[0] = in.src[1] = in.src[2] = s;
        in.imm[0] = uint32_t(UndefOp::Unwritten);
        in.imm[1] = uint32_t(shader.undef_sites.size() - 1);
        return instr_node(in, loc);
    }

    Reg shadow_of(Reg r) const { return r < shadow.size() ? shadow[r] : kNoReg; }

    void block(Block& b) {
        Block out;
        out.reserve(b.size());
        for (Node& n : b) {
            // Operands and If conditions; load_ind's range is left out: its
            // element is known only at run time.
            if (n.kind == NodeKind::If) {
                if (Reg s = shadow_of(n.cond); s != kNoReg) out.push_back(check(s, n.loc));
            } else if (n.kind == NodeKind::Instr) {
                flow::for_each_operand(n.instr, [&](Reg r) {
                    if (Reg s = shadow_of(r); s != kNoReg) out.push_back(check(s, n.loc));
                });
            }
            block(n.body);
            block(n.alt);
            const SourceLoc loc = n.loc;
            const bool is_instr = n.kind == NodeKind::Instr;
            const Instr in = n.instr;
            out.push_back(std::move(n));
            if (is_instr)
                flow::for_each_write(in, [&](Reg r) {
                    if (Reg s = shadow_of(r); s != kNoReg) out.push_back(set_shadow(s, 1, loc));
                });
        }
        b = std::move(out);
    }
};

}  // namespace

void check_unwritten_reads(Shader& shader) {
    const std::vector<bool> maybe = maybe_read_unset(shader);
    std::vector<bool> input(shader.regs.size(), false);  // written by the caller before the run
    for (const Binding& b : shader.inputs)
        for (uint32_t k = 0; k < b.count; ++k)
            if (b.first + k < input.size()) input[b.first + k] = true;
    Instrumenter ins{shader, std::vector<Reg>(shader.regs.size(), kNoReg)};
    std::vector<Node> init;
    for (const Variable& v : shader.variables)
        for (uint32_t k = 0; k < v.count; ++k) {
            const Reg r = v.first + k;
            if (r >= maybe.size() || !maybe[r] || input[r] || ins.shadow[r] != kNoReg) continue;
            ins.shadow[r] = Reg(shader.regs.size());
            shader.regs.push_back(Kind::I32);
            init.push_back(ins.set_shadow(ins.shadow[r], 0, {}));
        }
    if (init.empty()) return;
    ins.block(shader.body);
    for (Function& f : shader.functions) ins.block(f.body);
    shader.body.insert(shader.body.begin(), init.begin(), init.end());
}

}  // namespace glslrun::ir
