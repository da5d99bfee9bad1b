// The batched interpreter. The IR tree is compiled once into a flat array of
// Steps with resolved operand pointers; running walks the structured control
// flow recursively and masks lanes off (runtime/exec_mask.h).
#include "runtime/interpreter.h"

#include "runtime/traced_interpreter.h"

#include <bit>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "runtime/aligned_words.h"
#include "runtime/fast_kernels.h"

namespace glslrun::rt {

namespace {

// GLSL has no recursion, so call depth is bounded by the program; this only
// guards against a malformed shader that calls itself.
constexpr int kMaxCallDepth = 1024;

struct Range {
    uint32_t begin = 0, end = 0;
};

// The interpreter over register words W (interp_kernels.h): one copy of the
// control-flow code serves the fp32 modes (uint32_t) and Reference (uint64_t).
// kTraced instantiates it a second time with calls to a TraceHook
// (runtime/traced_interpreter.h); the untraced core has no trace code at all.
template <class W, bool kTraced = false>
struct Core {
    size_t reg_count;  // the shader itself is not kept: Steps hold everything
    RunLimits limits;
    // Counts the iterations of all loops of one run together, so nested
    // loops cannot multiply the cap into an effective hang.
    uint64_t loop_iterations_left = 0;
    // Instructions of the blocks entered in this run; the cancel flag is
    // polled when the count passes a multiple of kCancelPoll.
    uint64_t instructions_left = 0, next_cancel_poll = 0;
    static constexpr uint64_t kCancelPoll = RunLimits::kCancelPoll;
    // The draw's budget, and the instructions of this run already given to it.
    BudgetShare share;
    uint64_t reported = 0;
    // One extra register of zeros backs operands that an op does not read.
    AlignedWords<W> file;
    Machine<W> machine;
    std::vector<Step<W>> steps;
    std::vector<Range> functions;
    Range main;
    RunError error;
    uint32_t current = 0;  // traced only: the Step of the If or Loop being entered
    bool failed = false;
    int call_depth = 0;
    bool avx2 = cpu_has_avx2();
    Precision precision;
    uint32_t fast_ops;
    // Traced only: the hook, and the IR node of every Step.
    TraceHook* hook = nullptr;
    std::vector<const ir::Node*> nodes;

    struct Reader final : LaneReader {
        Core* core;
        explicit Reader(Core* c) : core(c) {}
        LaneValue read(ir::Reg r, int lane) const override {
            ir::Kind kind = r < core->kinds.size() ? core->kinds[r] : ir::Kind::I32;
            W word = core->reg(r)[lane];
            LaneValue v{kind, 0, 0, sizeof(W) != sizeof(uint32_t)};
            if (kind != ir::Kind::F32) v.i = int32_t(uint32_t(word));
            else if constexpr (sizeof(W) == sizeof(uint32_t)) v.f = std::bit_cast<float>(word);
            else v.f = std::bit_cast<double>(word);
            return v;
        }
    };
    std::vector<ir::Kind> kinds;  // traced only: of every register
    Reader reader{this};

    Core(const ir::Shader& s, const uint32_t* uniforms, const RunLimits& limits, const GLState::TextureUnit* textures,
         Precision precision, uint32_t fast_ops = kAllFastOps, TraceHook* trace_hook = nullptr)
        : reg_count(s.regs.size()), limits(limits), share(limits.draw), file((s.regs.size() + 1) * kLanes),
          precision(precision), fast_ops(fast_ops), hook(trace_hook) {
        if constexpr (kTraced) kinds = s.regs;
        machine.regs = file.data;
        machine.uniforms = uniforms;
        machine.textures = textures;
        for (const ir::Function& f : s.functions) functions.push_back(compile_block(f.body));
        main = compile_block(s.body);
        run_prologue(compile_block(s.prologue));
    }

    // Uniform code (ir/hoist.cpp), once for all lanes: instructions only,
    // so it cannot fail. Its results stay in W words (doubles in Reference).
    void run_prologue(Range prologue) {
        std::optional<ir::FlushDenormals> ftz;
        if (flushes_denormals()) ftz.emplace();
        machine.mask.reset(kAllLanes);
        instructions_left = UINT64_MAX;  // straight-line code: its size bounds it
        run_block(prologue.begin, prologue.end);
    }

    // The fp32 modes flush denormals (ir/scalar_ops.h); Reference does not.
    static constexpr bool flushes_denormals() { return sizeof(W) == sizeof(uint32_t); }

    Kernel<W> kernel(ir::Op op) const {
        if constexpr (sizeof(W) == sizeof(uint32_t)) return kernel_for(op, avx2, precision, fast_ops);
        else return kernel_for(op);
    }

    W* reg(ir::Reg r) {
        if (r == ir::kNoReg || r >= reg_count) return file.data + reg_count * kLanes;
        return file.data + size_t(r) * kLanes;
    }

    // Reserves the block's slots first so its Steps are contiguous; nested
    // blocks are appended after it.
    Range compile_block(const ir::Block& block) {
        Range range{uint32_t(steps.size()), uint32_t(steps.size() + block.size())};
        steps.resize(range.end);
        if constexpr (kTraced) nodes.resize(range.end);
        for (size_t i = 0; i < block.size(); ++i) {
            if constexpr (kTraced) nodes[range.begin + i] = &block[i];
            Step<W> step = compile_node(block[i]);
            steps[range.begin + i] = step;
        }
        return range;
    }

    Step<W> compile_node(const ir::Node& n) {
        Step<W> s;
        s.kind = n.kind;
        s.line = n.loc.line;
        switch (n.kind) {
        case ir::NodeKind::Instr:
            s = instr_step<W>(n.instr, kernel(n.instr.op), [this](ir::Reg r) { return reg(r); });
            s.kind = n.kind;
            s.line = n.loc.line;
            break;
        case ir::NodeKind::If: {
            s.cond = reg(n.cond);
            Range body = compile_block(n.body), alt = compile_block(n.alt);
            s.body_begin = body.begin, s.body_end = body.end, s.alt_begin = alt.begin, s.alt_end = alt.end;
            break;
        }
        case ir::NodeKind::Loop:
        case ir::NodeKind::Scope: {
            Range body = compile_block(n.body), alt = compile_block(n.alt);
            s.body_begin = body.begin, s.body_end = body.end, s.alt_begin = alt.begin, s.alt_end = alt.end;
            break;
        }
        case ir::NodeKind::Call: s.callee = n.callee; break;
        default: break;
        }
        return s;
    }

    bool fail(std::string message, int line) {
        if (!failed) error = RunError{std::move(message), line};
        failed = true;
        return false;
    }

    // Four lanes per SSE2 movemask: this runs at every If.
    static LaneMask lanes_true(const W* cond) {
        LaneMask m = 0;
#if defined(__SSE2__)
        if constexpr (sizeof(W) != sizeof(uint32_t)) {  // Reference: speed is secondary
            for (int i = 0; i < kLanes; ++i) m |= LaneMask(cond[i] != 0) << i;
            return m;
        }
        const __m128i zero = _mm_setzero_si128();
        for (int i = 0; i < kLanes; i += 4) {
            __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cond + i));
            int is_zero = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, zero)));
            m |= LaneMask(~is_zero & 0xf) << i;
        }
#else
        for (int i = 0; i < kLanes; ++i) m |= LaneMask(cond[i] != 0) << i;
#endif
        return m;
    }

    // Runs steps [begin, end) under the current mask; false on a run error.
    // Instructions never change the mask, so only control flow re-checks it.
    bool run_block(uint32_t begin, uint32_t end) {
        ExecMask& mask = machine.mask;
        if (!mask.any()) return true;
        if (!charge(end - begin)) return false;
        for (uint32_t i = begin; i < end; ++i) {
            const Step<W>& s = steps[i];
            // Instructions dominate: a predictable branch, not the switch's jump table.
            if (s.kind == ir::NodeKind::Instr) [[likely]] {
                s.fn(s, machine);
                if constexpr (kTraced) hook->instr(*nodes[i], mask.active(), reader);
                continue;
            }
            if constexpr (kTraced) {
                if (s.kind != ir::NodeKind::If && s.kind != ir::NodeKind::Loop) hook->jump(*nodes[i], mask.active());
                current = i;
            }
            switch (s.kind) {
            case ir::NodeKind::Instr: break;
            case ir::NodeKind::If:
                if (!run_if(s)) return false;
                break;
            case ir::NodeKind::Loop:
                if (!run_loop(s)) return false;
                break;
            case ir::NodeKind::Break: mask.do_break(); break;
            case ir::NodeKind::Continue: mask.do_continue(); break;
            case ir::NodeKind::Return: mask.do_return(); break;
            case ir::NodeKind::Discard: mask.do_discard(); break;
            case ir::NodeKind::Call:
                if (s.callee >= functions.size()) return fail("call to a missing function", s.line);
                if (!run_call(functions[s.callee].begin, functions[s.callee].end, s.line)) return false;
                break;
            case ir::NodeKind::Scope:
                if (!run_call(s.body_begin, s.body_end, s.line)) return false;
                break;
            }
            if constexpr (kTraced)
                if (s.kind == ir::NodeKind::Call || s.kind == ir::NodeKind::Scope) hook->leave(*nodes[i]);
            if (!mask.any()) return true;
        }
        return true;
    }

    bool charge(uint64_t instructions) {
        if (instructions > instructions_left)
            return fail(limits.instructions_message(), 0);
        instructions_left -= instructions;
        if ((limits.cancel || share.active()) && instructions_left < next_cancel_poll) {
            next_cancel_poll = instructions_left > kCancelPoll ? instructions_left - kCancelPoll : 0;
            if (limits.cancel && limits.cancel->load(std::memory_order_relaxed))
                return fail(RunLimits::kCancelledMessage, 0);
            return report();
        }
        return true;
    }

    // Gives the draw's budget what this run charged since the last report.
    bool report() {
        if (!share.active()) return true;
        const uint64_t used = limits.max_instructions - instructions_left;
        DrawBudget::Stop stop = share.charge(used - reported);
        reported = used;
        return stop == DrawBudget::Stop::None || fail(share.message(stop), 0);
    }

    // A branch whose mask is empty is skipped entirely.
    bool run_if(const Step<W>& s) {
        ExecMask& mask = machine.mask;
        if constexpr (kTraced) hook->branch(*nodes[current], mask.active(), lanes_true(s.cond) & mask.active());
        ExecMask::IfFrame frame = mask.if_push(lanes_true(s.cond));
        if (mask.any() && !run_block(s.body_begin, s.body_end)) return false;
        mask.if_else(frame);
        if (mask.any() && !run_block(s.alt_begin, s.alt_end)) return false;
        mask.if_pop(frame);
        return true;
    }

    bool run_loop(const Step<W>& s) {
        ExecMask& mask = machine.mask;
        ExecMask::LoopFrame frame = mask.loop_begin();
        [[maybe_unused]] const ir::Node* node = nullptr;
        if constexpr (kTraced) node = nodes[current];
        for ([[maybe_unused]] uint64_t iteration = 0;; ++iteration) {
            if constexpr (kTraced) hook->loop_iteration(*node, iteration, mask.active());
            if (loop_iterations_left-- == 0)
                return fail(limits.loop_cap_message(), s.line);
            if (!run_block(s.body_begin, s.body_end)) return false;
            mask.loop_continue_block(frame);
            if (mask.any() && !run_block(s.alt_begin, s.alt_end)) return false;
            if (!mask.loop_iteration_end(frame)) break;
        }
        mask.loop_end(frame);
        return true;
    }

    bool run_call(uint32_t begin, uint32_t end, int line) {
        if (++call_depth > kMaxCallDepth) return fail("call depth exceeded (recursion?)", line);
        ExecMask& mask = machine.mask;
        ExecMask::CallFrame frame = mask.call_begin();
        bool ok = run_block(begin, end);
        mask.call_end(frame);
        --call_depth;
        return ok;
    }

    bool run(LaneMask live) {
        failed = false;
        call_depth = 0;
        loop_iterations_left = limits.max_loop_iterations;
        instructions_left = limits.max_instructions;
        next_cancel_poll = instructions_left > kCancelPoll ? instructions_left - kCancelPoll : 0;
        reported = 0;
        error = {};
        machine.mask.reset(live & kAllLanes);
        ExecMask::CallFrame frame = machine.mask.call_begin();
        bool ok = run_block(main.begin, main.end);
        machine.mask.call_end(frame);
        bool within = report();  // after a failure too: the draw's total counts it
        return ok && within;
    }
};

}  // namespace

// What Interpreter forwards to: Narrow (fp32 words) or Wide (Reference).
class Engine {
public:
    virtual ~Engine() = default;
    virtual uint32_t* lanes(ir::Reg r) = 0;
    virtual bool run(LaneMask live, RunError* error) = 0;
    virtual LaneMask alive() const = 0;
    virtual void skip_lookups(LaneMask lanes) = 0;
    virtual void watch_undefined(UndefSink* sink) = 0;
    // Executor::hold_denormal_mode; Reference's runs keep denormals.
    virtual bool hold_denormal_mode(bool) { return false; }
};

namespace {

template <bool kTraced>
class Narrow final : public Engine {
public:
    Narrow(const ir::Shader& s, const uint32_t* uniforms, const RunLimits& limits, const GLState::TextureUnit* textures,
           Precision precision, uint32_t fast_ops, TraceHook* hook = nullptr)
        : core_(s, uniforms, limits, textures, precision, fast_ops, hook) {}
    uint32_t* lanes(ir::Reg r) override { return core_.reg(r); }
    bool run(LaneMask live, RunError* error) override {
        std::optional<ir::FlushDenormals> ftz;
        if (!held_) ftz.emplace();
        bool ok = core_.run(live);
        if (!ok && error) *error = core_.error;
        return ok;
    }
    LaneMask alive() const override { return core_.machine.mask.alive(); }
    void skip_lookups(LaneMask lanes) override { core_.machine.lookups = ~lanes; }
    void watch_undefined(UndefSink* sink) override { core_.machine.undef = sink; }
    bool hold_denormal_mode(bool held) override {
        held_ = held;
        return true;
    }

private:
    Core<uint32_t, kTraced> core_;
    bool held_ = false;  // the caller holds ir::FlushDenormals around run()
};

// Reference mode: the shader runs on doubles; callers exchange 32-bit words
// through `boundary_`, converted only for the shader's inputs and outputs.
template <bool kTraced>
class Wide final : public Engine {
public:
    Wide(const ir::Shader& s, const uint32_t* uniforms, const RunLimits& limits, const GLState::TextureUnit* textures,
         TraceHook* hook = nullptr)
        : core_(s, uniforms, limits, textures, Precision::Reference, kAllFastOps, hook), boundary_((s.regs.size() + 1) * kLanes),
          inputs_(s.inputs), outputs_(s.outputs) {}
    uint32_t* lanes(ir::Reg r) override {
        if (r == ir::kNoReg || r >= core_.reg_count) return boundary_.data + core_.reg_count * kLanes;
        return boundary_.data + size_t(r) * kLanes;
    }
    bool run(LaneMask live, RunError* error) override {
        for (const ir::Binding& b : inputs_)
            for (uint32_t c = 0; c < b.count; ++c) {
                const uint32_t* from = lanes(b.first + c);
                uint64_t* to = core_.reg(b.first + c);
                for (int i = 0; i < kLanes; ++i) to[i] = widen<uint64_t>(b.kind, from[i]);
            }
        bool ok = core_.run(live);
        if (!ok && error) *error = core_.error;
        // Only the lanes that ran: the others keep what the caller left there.
        for (const ir::Binding& b : outputs_)
            for (uint32_t c = 0; c < b.count; ++c) {
                const uint64_t* from = core_.reg(b.first + c);
                uint32_t* to = lanes(b.first + c);
                for (int i = 0; i < kLanes; ++i)
                    if ((live >> i) & 1) to[i] = narrow<uint64_t>(b.kind, from[i]);
            }
        return ok;
    }
    LaneMask alive() const override { return core_.machine.mask.alive(); }
    void skip_lookups(LaneMask lanes) override { core_.machine.lookups = ~lanes; }
    void watch_undefined(UndefSink* sink) override { core_.machine.undef = sink; }

private:
    Core<uint64_t, kTraced> core_;
    AlignedWords<uint32_t> boundary_;
    std::vector<ir::Binding> inputs_, outputs_;
};

}  // namespace

Interpreter::Interpreter(const ir::Shader& shader, const uint32_t* uniforms, const RunLimits& limits,
                         const GLState::TextureUnit* textures, Precision precision, uint32_t fast_ops) {
    if (precision == Precision::Reference)
        engine_ = std::make_unique<Wide<false>>(shader, uniforms, limits, textures);
    else
        engine_ = std::make_unique<Narrow<false>>(shader, uniforms, limits, textures, precision, fast_ops);
}

Interpreter::~Interpreter() = default;

uint32_t* Interpreter::lanes(ir::Reg r) { return engine_->lanes(r); }

bool Interpreter::run(LaneMask live, RunError* error) { return engine_->run(live, error); }

LaneMask Interpreter::alive() const { return engine_->alive(); }

void Interpreter::skip_lookups(LaneMask lanes) { engine_->skip_lookups(lanes); }

void Interpreter::watch_undefined(UndefSink* sink) { engine_->watch_undefined(sink); }

bool Interpreter::hold_denormal_mode(bool held) { return engine_->hold_denormal_mode(held); }

}  // namespace glslrun::rt

namespace glslrun::rt {

class TracedEngine {
public:
    std::unique_ptr<Engine> engine;
};

TracedInterpreter::TracedInterpreter(const ir::Shader& shader, const uint32_t* uniforms, const RunLimits& limits,
                                     const GLState::TextureUnit* textures, Precision precision, uint32_t fast_ops,
                                     TraceHook& hook)
    : engine_(std::make_unique<TracedEngine>()) {
    if (precision == Precision::Reference)
        engine_->engine = std::make_unique<Wide<true>>(shader, uniforms, limits, textures, &hook);
    else
        engine_->engine = std::make_unique<Narrow<true>>(shader, uniforms, limits, textures, precision,
                                                         fast_ops, &hook);
}

TracedInterpreter::~TracedInterpreter() = default;

uint32_t* TracedInterpreter::lanes(ir::Reg r) { return engine_->engine->lanes(r); }

bool TracedInterpreter::run(LaneMask live, RunError* error) { return engine_->engine->run(live, error); }

LaneMask TracedInterpreter::alive() const { return engine_->engine->alive(); }

}  // namespace glslrun::rt
