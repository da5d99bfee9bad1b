// What the generated code of one executor and its call-outs share. The
// generated function reads and writes these fields by their offsets.
#pragma once
#include <cstddef>
#include <atomic>
#include <cstdint>
#include <vector>

#include "runtime/backend.h"
#include "runtime/interp_kernels.h"
#include "runtime/sampling_batch.h"
#include "runtime/sampling_direct.h"
#include "runtime/sampling_rules.h"

namespace glslrun::rt::jit {

// Why a run stopped early (the generated function's return value).
// DrawBudget: the draw's budget as a whole stopped it (Context::stop says why).
enum class Failure : int32_t { None = 0, LoopCap = 1, MissingFunction = 2, Instructions = 3, Cancelled = 4,
                               DrawBudget = 5 };

// A unit's texture of one kind and the batched sampler's kernel for its
// state (sampling_batch.h), which the generated `tex` code calls where
// its lanes' unit has one: run(*texture, ...).
struct BoundKernel {
    BatchKernel run = nullptr;
    const Texture* texture = nullptr;
};

struct Context {
    uint64_t max_loop_iterations = 0;  // read at entry
    // The work budget, as the interpreter's (runtime/interpreter.cpp):
    // instructions charged per block entered, and the cancel flag (may be
    // null) polled whenever the count passes `next_cancel_poll`. The
    // generated code keeps only `credit`, the instructions it may charge
    // before either event (left - next_cancel_poll), read at entry; beyond
    // it, charge_slowly() does the interpreter's bookkeeping.
    uint64_t credit = 0;
    uint64_t next_cancel_poll = 0;
    const std::atomic<bool>* cancel = nullptr;
    // The draw's budget (may be null), reported to at the polls and after
    // the run (the generated code stores `credit` back when it returns).
    BudgetShare* share = nullptr;
    uint64_t run_instructions = 0, reported = 0;  // the run's budget, and what of it was reported
    DrawBudget::Stop stop = DrawBudget::Stop::None;
    // Starts a run of `max_instructions` (RunLimits::kCancelPoll below it: the first poll).
    void start_budget(uint64_t max_instructions, const std::atomic<bool>* flag, BudgetShare* draw = nullptr);
    // Reports the instructions charged since the last report to `share`;
    // false (and `stop` set) when the draw must stop.
    bool report(uint64_t left);
    uint64_t alive = 0;                // written at exit: the lanes that did not discard
    int32_t error_line = 0;            // with a Failure
    // The call-outs run the interpreter's kernels over this machine (its
    // mask set per call), each with its Step built once per executor over
    // the executor's register file (call_steps[i] for the i-th CallOut).
    Machine<uint32_t> machine;
    const Step<uint32_t>* call_steps = nullptr;
    // The one-pass samplers of the bound textures (tex_direct.cpp), two per
    // unit (direct_slot()), which the generated `tex` code calls where its
    // lanes' unit has one; null: none.
    const DirectSampler* direct = nullptr;
    // The kernels of the bound 1D, 3D, cube and 2D depth-comparing textures
    // (bind_kernels()), per unit and kind (kernel_slot()); null: none.
    const BoundKernel* kernels = nullptr;
    // Per call-out, a `tex` one's coordinates and reference in the register
    // file (tex_lookups()), which a BoundKernel reads: made once per
    // executor, not per lookup.
    const BatchLookup* lookups = nullptr;
    // What the generated `tex` code calls
    // (run_tex, tex_direct.cpp), loaded from here: the code cache's code
    // holds no address.
    void (*tex)(Context* ctx, uint64_t index, uint64_t exec, const uint32_t* units, const uint32_t* operands,
                uint32_t* out) = nullptr;
    // Per call-out, whether a run_tex lookup's derivative rows go to the
    // register file (tex_derivatives()): 0 where no bound texture of its
    // target reads them, so the generated code neither stores them nor
    // (LLVM sinking them) computes them.
    const uint8_t* derivatives = nullptr;
};

inline constexpr size_t kMaxLoopOffset = offsetof(Context, max_loop_iterations);
inline constexpr size_t kCreditOffset = offsetof(Context, credit);
inline constexpr size_t kAliveOffset = offsetof(Context, alive);
inline constexpr size_t kErrorLineOffset = offsetof(Context, error_line);
inline constexpr size_t kTexOffset = offsetof(Context, tex);
inline constexpr size_t kDerivativesOffset = offsetof(Context, derivatives);

// Context::direct's entry of a unit's 2D texture (rect false) or rectangle.
constexpr size_t direct_slot(uint32_t unit, bool rect) { return size_t(unit) * 2 + (rect ? 1 : 0); }
inline constexpr size_t kDirectSlots = direct_slot(kMaxTextureUnits, false);

// The lookups that BoundKernel takes: 1D, 3D and cube colour lookups, 2D
// depth comparisons (shadow2D, shadow2DProj), and 2D colour lookups of a
// mipmapped texture (where the unit's one-pass sampler has none).
enum class KernelKind : uint8_t { T1D, T3D, Cube, Shadow2D, Mip2D, Count };
constexpr size_t kernel_slot(uint32_t unit, KernelKind kind) {
    return size_t(unit) * size_t(KernelKind::Count) + size_t(kind);
}
inline constexpr size_t kKernelSlots = kernel_slot(kMaxTextureUnits, KernelKind::T1D);

// A lookup's KernelKind; Count where none is bound for it.
inline KernelKind kernel_kind(const ir::TexInfo& info) {
    using enum ir::TexTarget;
    if (info.shadow) return info.target == T2D ? KernelKind::Shadow2D : KernelKind::Count;
    switch (info.target) {
    case T1D: return KernelKind::T1D;
    case T2D: return KernelKind::Mip2D;
    case T3D: return KernelKind::T3D;
    case Cube: return KernelKind::Cube;
    default: return KernelKind::Count;
    }
}

// Whether a 2D or rectangle colour lookup (the one-pass samplers'; a
// shadow lookup's texture is a depth one).
inline bool one_pass_lookup(const ir::TexInfo& info) {
    return (info.target == ir::TexTarget::T2D || info.target == ir::TexTarget::Rect) && !info.shadow;
}

// Whether the generated code of `in` calls run_tex (its lookups may go to
// a unit's one-pass sampler or BoundKernel), not the plain call-out;
// decided before the textures are known. Under Fast's GPU filtering
// (`gpu`), RGBA8 1D, 3D and cube textures (nearly all) are its own paths'
// and bind no kernel, which the call-out reaches with less around it (toon
// in Fast against main's build, interleaved at load 10: 3 to 4% slower
// through run_tex, 0 to 2% through the call-out); its depth textures take
// the shadow-map kernels.
inline bool tex_runs_direct(const ir::Instr& in, bool gpu) {
    if (in.op != ir::Op::tex) return false;
    const ir::TexInfo info = ir::TexInfo::decode(in.imm[2]);
    const KernelKind kind = kernel_kind(info);
    if (gpu && (kind == KernelKind::T1D || kind == KernelKind::T3D || kind == KernelKind::Cube)) return false;
    return one_pass_lookup(info) || kind != KernelKind::Count;
}

// Whether bind_kernels() binds sample_mip2d() for a unit's 2D texture `t`
// (may be null): complete, mipmapped, colour, and one that the tex kernel
// samples with it (sample_batch()'s pick, reading each quad's first lane's
// derivatives), not under Fast's GPU filtering (`gpu`), which takes its own.
inline bool binds_mip2d(const Texture* t, bool gpu) {
    return !gpu && t && t->complete() && !t->depth() && batch_samples(*t) && sampling::lod_matters(t->sampler) &&
           batch_reads_quad_leaders(*t, true);
}

// The units' kernels into out[kKernelSlots]: each kind's texture whose
// state has an eight-lane kernel that reads no derivatives (no level of
// detail decision), complete, that the tex kernel samples with those
// kernels (under `gpu`, Fast's GPU filtering, those it does not filter);
// and, not under `gpu`, a complete mipmapped 2D colour texture that the
// tex kernel samples with sample_mip2d() (it reads the derivative rows,
// each quad's first lane's where Context::lookups says so); all null where
// `units` is null or the CPU lacks AVX2.
void bind_kernels(const GLState::TextureUnit* units, bool gpu, BoundKernel* out);

// The units' one-pass samplers into out[kDirectSlots] (all null where
// `units` is null or the CPU lacks AVX2); `gpu`: Fast's GPU filtering
// (the tex kernel's SamplingRules::Gpu).
void bind_direct_samplers(const GLState::TextureUnit* units, bool gpu, DirectSampler* out);

// The `index`-th call-out, a `tex`, on the lanes of `exec`: its unit's
// one-pass sampler or kernel where every lane names one unit that has one,
// else the call-out's kernel, over its registers (`units`, the operand
// block: the register file's) into `out` (kTexResults x kLanes words, of which the
// lanes of `exec` are written).
void run_tex(Context* ctx, uint64_t index, uint64_t exec, const uint32_t* units, const uint32_t* operands,
             uint32_t* out);

// One instruction that the generated code runs with an interpreter kernel.
struct CallOut {
    Kernel<uint32_t> kernel;
    ir::Instr instr;
};

// The BatchLookup of each `tex` call-out among `calls` (its Step in
// `steps`) over the register file: its coordinates and reference; a 2D
// colour lookup's also its derivative rows, LOD or bias and, where the tex
// kernel gives a quad its first lane's derivatives (an implicit LOD from
// no gradients of the program's), quad_derivatives.
std::vector<BatchLookup> tex_lookups(const std::vector<CallOut>& calls, const std::vector<Step<uint32_t>>& steps);

// Per call-out among `calls`, 1 where a `tex` with derivative rows may
// have them read: some unit's texture of its target (`units`; null: all
// count) is one whose sampling may take a level of detail (a mipmap or
// min/mag decision) or one that Fast's GPU filtering takes (`gpu`). The
// operand blocks are pinned registers (ir/regalloc.cpp) that only their
// lookup reads, and the textures are the executor's for its lifetime: a
// row never stored is a row never read.
std::vector<uint8_t> tex_derivatives(const std::vector<CallOut>& calls, const GLState::TextureUnit* units, bool gpu);

// The generated functions: a batch (`live` lanes), and the prologue (all
// lanes, before any batch). `regs` is the executor's register file.
using ShaderFn = int32_t (*)(Context* ctx, uint32_t* regs, const uint32_t* uniforms, uint64_t live);

// The Step of `call` over the register file `regs` of `reg_count` registers
// (register reg_count is the zero register).
Step<uint32_t> call_out_step(const CallOut& call, uint32_t* regs, uint32_t reg_count);

// The names by which generated code calls run_call_out and charge_slowly
// (defined in each Engine's LLJIT): never their addresses, which differ from
// process to process, so that the code cache's machine code can be loaded
// by another process.
inline constexpr const char* kRunCallOutSymbol = "glslrun_run_call_out";
inline constexpr const char* kChargeSlowlySymbol = "glslrun_charge_slowly";

// Runs the `index`-th call-out's kernel on the lanes in `exec` (a plain C++
// function whose address the generated code holds). `regs`, the register
// file that the call-out's Step points into, is passed so that LLVM knows
// the call reads and writes it (the generated function's `regs` is noalias).
void run_call_out(Context* ctx, uint32_t* regs, uint64_t index, uint64_t exec);

// Charges `instructions` with only `credit` left before an event: returns
// the Failure (Instructions, Cancelled or None) and sets ctx->credit anew.
int32_t charge_slowly(Context* ctx, uint64_t credit, uint64_t instructions);

}  // namespace glslrun::rt::jit
