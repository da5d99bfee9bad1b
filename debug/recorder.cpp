#include "debug/recorder.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

namespace glslrun::debug {

ShaderNames::ShaderNames(const ir::Shader& shader, const ir::Program& program)
    : shader_(shader), program_(program), var_of_(shader.regs.size(), -1), uniform_of_(program.uniform_words, -1) {
    vars_ = shader.variables;
    for (const ir::Binding& b : shader.outputs)
        vars_.push_back(ir::Variable{b.name, "", binding_type(b), b.first, b.count});
    for (size_t v = 0; v < vars_.size(); ++v) {
        const ir::Variable& var = vars_[v];
        for (uint32_t c = 0; c < var.count && var.first + c < var_of_.size(); ++c) var_of_[var.first + c] = int(v);
    }
    for (size_t u = 0; u < program.uniforms.size(); ++u) {
        const ir::Uniform& leaf = program.uniforms[u];
        uint32_t words = leaf.type.components() * leaf.array_size;
        for (uint32_t w = 0; w < words && leaf.slot + w < uniform_of_.size(); ++w) uniform_of_[leaf.slot + w] = int(u);
    }
}

std::string ShaderNames::where(const ir::SourceLoc& loc, bool column) const {
    const std::string& file = loc.source < shader_.sources.size() ? shader_.sources[loc.source] : std::string();
    if (column && loc.column) return fmt::format("{}:{}:{}", file, loc.line, loc.column);
    return fmt::format("{}:{}", file, loc.line);
}

Values read_values(const rt::LaneReader& regs, ir::Reg first, uint32_t count, int lane) {
    Values v;
    for (uint32_t c = 0; c < count; ++c) {
        rt::LaneValue x = regs.read(first + c, lane);
        v.kind = x.kind;
        v.wide = x.wide;
        v.c.push_back(x.kind == ir::Kind::F32 ? x.f : double(x.i));
    }
    return v;
}

NamedValue uniform_value(const ir::Uniform& u, const uint32_t* store) {
    NamedValue out{u.name, type_name(u.type), {u.type.kind, false, {}}};
    if (u.is_array) out.type += fmt::format("[{}]", u.array_size);
    for (uint32_t w = 0; w < u.type.components() * u.array_size; ++w) {
        uint32_t word = store[u.slot + w];
        out.value.c.push_back(u.type.kind == ir::Kind::F32 ? double(std::bit_cast<float>(word))
                                                           : double(int32_t(word)));
    }
    return out;
}

namespace {

bool non_finite(const rt::LaneValue& v) { return v.kind == ir::Kind::F32 && !std::isfinite(v.f); }

// The registers an instruction writes: tex writes four.
bool lookup_op(const ir::Instr& in) { return ir::has(in.op, ir::OpProp::Texture); }
uint32_t results(const ir::Instr& in) { return lookup_op(in) ? ir::kTexResults : 1; }

}  // namespace

std::optional<NanEvent> nan_event(const ShaderNames& names, const ir::Node& n, const rt::LaneReader& regs, int lane) {
    const ir::Instr& in = n.instr;
    if (in.dst == ir::kNoReg || in.type != ir::Kind::F32) return std::nullopt;
    bool bad = false;
    for (uint32_t k = 0; k < results(in); ++k) bad = bad || non_finite(regs.read(in.dst + k, lane));
    if (!bad) return std::nullopt;
    NanEvent e{names.where(n.loc), ir::op_info(in.op).name, {}, read_values(regs, in.dst, results(in), lane), {}};
    const int arity = lookup_op(in) ? 0 : ir::op_info(in.op).arity;
    for (int k = 0; k < arity; ++k) e.operands.push_back(read_values(regs, in.src[k], 1, lane));
    if (const ir::Variable* var = names.variable(in.dst)) e.variable = var->name;
    return e;
}

void NanWatch::instr(const ir::Node& n, rt::LaneMask active, const rt::LaneReader& regs) {
    for (rt::LaneMask bits = active & ~found; bits; bits &= bits - 1) {
        int lane = std::countr_zero(bits);
        if (auto e = nan_event(names_, n, regs, lane)) {
            first[size_t(lane)] = std::move(e);
            found |= rt::LaneMask(1) << lane;
        }
    }
}

LaneRecorder::LaneRecorder(const ShaderNames& names, const uint32_t* uniforms, int lane, size_t max_steps,
                           const GLState::TextureUnit* textures, Precision precision)
    : names_(names), uniforms_(uniforms), lane_(lane), max_steps_(max_steps), textures_(textures),
      rules_(precision == Precision::Reference ? rt::SamplingRules::Spec
             : precision == Precision::Fast    ? rt::SamplingRules::Gpu
                                               : rt::SamplingRules::Common) {}

// A `tex` instruction of the lane, after it ran: its operands (the block
// ir::TexInfo lays out), the sampler's steps again with an observer, and
// the result the shader got.
void LaneRecorder::lookup(const ir::Node& n, const rt::LaneReader& regs) {
    const ir::Instr& in = n.instr;
    TextureLookup t;
    t.info = ir::TexInfo::decode(in.imm[2]);
    t.unit = regs.read(in.src[0], lane_).i;
    for (const ir::Uniform& u : names_.program().uniforms)
        if (u.type.is_sampler)
            for (uint32_t e = 0; e < u.array_size; ++e)
                if (int32_t(uniforms_[u.slot + e]) == t.unit)
                    t.samplers.push_back(u.is_array ? fmt::format("{}[{}]", u.name, e) : u.name);
    auto operand = [&](uint32_t k) { return float(regs.read(ir::Reg(in.imm[0] + k), lane_).f); };
    auto vec = [&](uint32_t first, uint32_t dims) {
        return glm::vec3(operand(first), dims > 1 ? operand(first + 1) : 0.0f, dims > 2 ? operand(first + 2) : 0.0f);
    };
    rt::LaneLookup lk;  // as the `tex` kernel decodes it (runtime/tex_kernel.cpp)
    lk.rules = rules_;
    lk.coord = vec(0, t.info.dims());
    for (uint32_t c = 0; c < t.info.dims(); ++c) t.coord.push_back(lk.coord[int(c)]);
    if (t.info.shadow) t.ref = lk.ref = operand(t.info.ref_at());
    lk.implicit = t.info.lod != ir::TexLod::Explicit;
    lk.bias = t.info.lod == ir::TexLod::ImplicitBias;
    if (t.info.lod != ir::TexLod::Implicit) t.lod = lk.lod = operand(t.info.lod_at());
    if (lk.implicit) {
        const int from = rt::derivative_lane(lane_, rules_, t.info.grad);
        auto derivative = [&](uint32_t first) {
            const uint32_t dims = t.info.grad_dims();
            auto at = [&](uint32_t k) { return float(regs.read(ir::Reg(in.imm[0] + first + k), from).f); };
            return glm::vec3(at(0), dims > 1 ? at(1) : 0.0f, dims > 2 ? at(2) : 0.0f);
        };
        lk.ddx = derivative(t.info.ddx_at());
        lk.ddy = derivative(t.info.ddy_at());
    }
    const Texture* texture = textures_ && t.unit >= 0 && t.unit < kMaxTextureUnits
                                 ? textures_[t.unit].bound[size_t(t.info.target)].get()
                                 : nullptr;
    t.details = rt::explain_lookup(texture, lk);
    for (uint32_t c = 0; c < ir::kTexResults; ++c) t.result[c] = float(regs.read(in.dst + c, lane_).f);
    TraceStep s;
    s.kind = TraceStep::Kind::Lookup;
    s.where = names_.where(n.loc);
    s.source = n.loc.source;
    s.line = uint32_t(n.loc.line);
    s.lookup = uint32_t(trace.lookups.size());
    if (cost() >= max_steps_) return add(std::move(s));  // marks the trace truncated
    trace.lookups.push_back(std::move(t));
    add(std::move(s));
    extra_ += kLookupExtra;
}

void LaneRecorder::add(TraceStep step) {
    if (cost() >= max_steps_) {
        trace.truncated = true;
        return;
    }
    // "file:21" then "file:21  if: ..." says the same twice.
    if (step.kind != TraceStep::Kind::Statement && step.kind != TraceStep::Kind::Assign &&
        step.kind != TraceStep::Kind::Lookup && !trace.steps.empty() &&
        trace.steps.back().kind == TraceStep::Kind::Statement &&
        (step.where == trace.steps.back().where || step.where.starts_with(trace.steps.back().where + ":")))
        trace.steps.pop_back();
    step.depth = depth_;
    trace.steps.push_back(std::move(step));
}

// The variables written since the last statement, with all their components.
void LaneRecorder::flush_assignments() {
    for (const ir::Variable* var : dirty_) {
        TraceStep s;
        s.kind = TraceStep::Kind::Assign;
        // A callee's parameters are written by its caller: "light.i".
        bool foreign = !var->function.empty() && var->function != functions_.back();
        s.name = foreign ? var->function + "." + var->name : var->name;
        s.type = var->type;
        s.value = read_values(*regs_, var->first, var->count, lane_);
        add(std::move(s));
    }
    dirty_.clear();
}

void LaneRecorder::statement(const ir::SourceLoc& loc) {
    if (loc.line <= 0 || (loc.line == last_.line && loc.source == last_.source)) return;
    flush_assignments();
    last_ = loc;
    // A statement over several lines: its first line stands for it.
    if (!trace.steps.empty() && trace.steps.back().kind == TraceStep::Kind::Statement &&
        trace.steps.back().depth == depth_)
        return;
    TraceStep s;
    s.kind = TraceStep::Kind::Statement;
    s.where = names_.where(loc);
    s.source = loc.source;
    s.line = uint32_t(loc.line);
    add(std::move(s));
}

void LaneRecorder::instr(const ir::Node& n, rt::LaneMask active, const rt::LaneReader& regs) {
    // Line 0: the outputs' implicit zeros before main (lower_shader.cpp).
    if (!on(active) || n.loc.line <= 0) return;
    regs_ = &regs;
    statement(n.loc);
    const ir::Instr& in = n.instr;
    if (in.op == ir::Op::uniform || in.op == ir::Op::uniform_ind) {
        uint32_t slot = in.imm[0];
        if (in.op == ir::Op::uniform_ind && in.imm[1] > 0) {  // base + clamp(index, 0, count - 1) * stride
            int32_t index = std::clamp<int32_t>(regs.read(in.src[0], lane_).i, 0, int32_t(in.imm[1]) - 1);
            slot += uint32_t(index) * in.imm[2];
        }
        int u = names_.uniform_at(slot);
        if (u >= 0 && std::find(uniforms_read_.begin(), uniforms_read_.end(), u) == uniforms_read_.end())
            uniforms_read_.push_back(u);
    }
    if (lookup_op(in)) lookup(n, regs);
    ir::Reg written = ir::has(in.op, ir::OpProp::WritesRange) ? in.imm[0] : in.dst;
    if (const ir::Variable* var = names_.variable(written))
        if (std::find(dirty_.begin(), dirty_.end(), var) == dirty_.end()) dirty_.push_back(var);
    if (!trace.first_nan) trace.first_nan = nan_event(names_, n, regs, lane_);
}

void LaneRecorder::branch(const ir::Node& n, rt::LaneMask active, rt::LaneMask taken) {
    if (!on(active)) return;
    if (regs_) flush_assignments();
    TraceStep s;
    s.kind = TraceStep::Kind::Branch;
    s.where = names_.where(n.loc, true);  // the column tells apart the ifs of `a && b` on one line
    s.source = n.loc.source;
    s.line = uint32_t(n.loc.line);
    s.taken = on(taken);
    add(std::move(s));
    last_ = n.loc;  // the branch's line is shown: its statements there need no line of their own
}

void LaneRecorder::loop_iteration(const ir::Node& n, uint64_t iteration, rt::LaneMask active) {
    if (!on(active)) return;
    if (regs_) flush_assignments();
    TraceStep s;
    s.kind = TraceStep::Kind::Loop;
    s.where = names_.where(n.loc);
    s.source = n.loc.source;
    s.line = uint32_t(n.loc.line);
    s.iteration = iteration;
    add(std::move(s));
    last_ = {};
}

void LaneRecorder::jump(const ir::Node& n, rt::LaneMask active) {
    if (n.kind == ir::NodeKind::Call) calls_.push_back(on(active));
    if (!on(active) || n.kind == ir::NodeKind::Scope) return;
    if (regs_) flush_assignments();
    TraceStep s;
    s.kind = n.kind == ir::NodeKind::Call ? TraceStep::Kind::Call : TraceStep::Kind::Jump;
    s.where = names_.where(n.loc);
    s.source = n.loc.source;
    s.line = uint32_t(n.loc.line);
    static constexpr const char* kJumps[] = {"", "", "", "break", "continue", "return", "discard"};
    if (n.kind == ir::NodeKind::Call) {
        const auto& fns = names_.shader().functions;
        s.name = n.callee < fns.size() ? fns[n.callee].name : "?";
    } else {
        s.name = kJumps[size_t(n.kind)];
    }
    if (n.kind == ir::NodeKind::Discard) trace.discarded = true;
    std::string callee = s.name;
    add(std::move(s));
    if (n.kind == ir::NodeKind::Call) {
        ++depth_;
        functions_.push_back(callee);
        last_ = {};
    }
}

void LaneRecorder::leave(const ir::Node& n) {
    if (n.kind != ir::NodeKind::Call || calls_.empty()) return;
    bool ours = calls_.back();
    calls_.pop_back();
    if (!ours) return;
    if (regs_) flush_assignments();
    depth_ = std::max(0, depth_ - 1);
    if (functions_.size() > 1) functions_.pop_back();
    last_ = {};
}

void LaneRecorder::finish(const rt::LaneReader* regs) {
    if (regs) regs_ = regs;
    if (regs_) flush_assignments();
    for (int u : uniforms_read_)
        trace.uniforms.push_back(uniform_value(names_.program().uniforms[size_t(u)], uniforms_));
}

}  // namespace glslrun::debug
