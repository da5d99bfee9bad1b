// The interpreter's instruction kernels: one function per opcode, each a loop
// over the kLanes lanes of a batch. Alu kernels are generated from the opcode
// table (ir/opcodes.def via ir/alu_eval.h); the Special ones are written by
// name. Dispatch happens once per instruction (a function pointer per Step).
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "glslrun/glslrun.h"
#include "ir/alu_eval.h"
#include "runtime/exec_mask.h"

namespace glslrun::rt {

template <class W>
struct Step;
class UndefSink;

// Bit i of a 32-lane mask word: testing against a table (not shifting by the
// lane index) lets the blend vectorize without AVX2's variable shifts.
inline constexpr std::array<uint32_t, 32> kLaneBit = [] {
    std::array<uint32_t, 32> bits{};
    for (int i = 0; i < 32; ++i) bits[size_t(i)] = 1u << i;
    return bits;
}();

// The register word W: uint32_t (fp32 modes), or uint64_t in
// Precision::Reference, where a float register holds a double. The uniform
// store and the interpreter's callers always see 32-bit words; these convert
// one word of kind k across that boundary (exact when widening).
template <class W>
W widen(ir::Kind k, uint32_t w) {
    if constexpr (sizeof(W) == sizeof(uint32_t)) return w;
    else if (k == ir::Kind::F32) return std::bit_cast<W>(double(std::bit_cast<float>(w)));
    else return w;  // i32 in the low half, bools 0/1
}
template <class W>
uint32_t narrow(ir::Kind k, W w) {
    if constexpr (sizeof(W) == sizeof(uint32_t)) return w;
    else if (k == ir::Kind::F32) return std::bit_cast<uint32_t>(float(std::bit_cast<double>(w)));
    else return uint32_t(w);
}
// The float type of a register word.
template <class W>
using FloatOf = typename ir::alu::Word<ir::TypeClass::F, W>::T;

// What a kernel can touch: the register file, the uniform store, the bound
// textures, the mask.
template <class W>
struct Machine {
    W* regs = nullptr;  // register r lane i at regs[r * kLanes + i]
    const uint32_t* uniforms = nullptr;
    const GLState::TextureUnit* textures = nullptr;  // kMaxTextureUnits units, or none at all
    ExecMask mask;
    // The lanes whose texture lookups are run; the others read 0
    // (Executor::skip_lookups).
    LaneMask lookups = kAllLanes;
    // Where check_undef reports (Executor::watch_undefined); null: nowhere.
    UndefSink* undef = nullptr;

    // Masked register write: inactive lanes keep their old value.
    void write(W* __restrict dst, const W* __restrict value) {
        const LaneMask active = mask.active();
        if (active == kAllLanes) {
            std::memcpy(dst, value, sizeof(W) * kLanes);
            return;
        }
        for (int base = 0; base < kLanes; base += 32) {
            const uint32_t bits = uint32_t(active >> base);
            const int n = kLanes - base < 32 ? kLanes - base : 32;
            for (int i = 0; i < n; ++i) {
                const W pick = W(0) - W((bits & kLaneBit[size_t(i)]) != 0);
                dst[base + i] = (value[base + i] & pick) | (dst[base + i] & ~pick);
            }
        }
    }
};

template <class W>
using Kernel = void (*)(const Step<W>&, Machine<W>&);

// One compiled IR node. Blocks are ranges [begin, end) of a flat Step array.
template <class W>
struct Step {
    ir::NodeKind kind = ir::NodeKind::Instr;
    Kernel<W> fn = nullptr;  // Instr
    W* dst = nullptr;
    const W* src[3] = {nullptr, nullptr, nullptr};
    uint32_t imm[3] = {0, 0, 0};
    W value = 0;                     // konst: imm[0] as a register word
    ir::Kind type = ir::Kind::F32;   // ir::Instr::type
    bool unmasked = false;           // ir::Instr::unmasked: write every lane
    const W* cond = nullptr;         // If
    uint32_t body_begin = 0, body_end = 0;  // If then / Loop body / Scope body
    uint32_t alt_begin = 0, alt_end = 0;    // If else / Loop continue block
    uint32_t callee = 0;                    // Call
    int line = 0;
};

// The Step of one instruction over a register file: `reg(r)` gives register
// r's kLanes words (the zero register for operands the op does not read).
template <class W, class RegOf>
Step<W> instr_step(const ir::Instr& in, Kernel<W> fn, RegOf&& reg) {
    Step<W> s;
    s.fn = fn;
    s.dst = in.dst == ir::kNoReg ? nullptr : reg(in.dst);
    s.unmasked = in.unmasked && !ir::has(in.op, ir::OpProp::Blends);
    s.type = in.type;
    s.value = widen<W>(in.type, in.imm[0]);
    for (int k = 0; k < 3; ++k) {
        s.src[k] = reg(in.src[k]);
        s.imm[k] = in.imm[k];
    }
    if (ir::has(in.op, ir::OpProp::Texture)) s.src[1] = reg(in.imm[0]);  // the operand block
    return s;
}

namespace kernels {

inline uint32_t clamp_index(uint64_t raw, uint32_t count) {
    int32_t i = static_cast<int32_t>(static_cast<uint32_t>(raw));
    if (i < 0) return 0;
    return std::min(static_cast<uint32_t>(i), count - 1);
}

// Runs a lane-wise body `lanes(out)` straight into the destination when every
// lane is active (or none can tell), else into a temporary that is blended in.
// Bodies must be elementwise (lane i reads only lane i) so dst may alias an
// operand.
template <class W, class Lanes>
inline void emit(const Step<W>& s, Machine<W>& m, Lanes&& lanes) {
    if (s.unmasked || m.mask.full()) {
        lanes(s.dst);
        return;
    }
    alignas(64) W out[kLanes];
    lanes(out);
    m.write(s.dst, out);
}

// Lane loop of `L::eval` (L: ir::alu::Lane<op>, or a Fast-mode lane of
// runtime/fast_kernels.h) into `out`. Operands may alias `out` lane for lane
// (dst == src), which is safe elementwise: ivdep tells GCC so.
template <class W, class L>
inline void alu_lanes(const Step<W>& s, W* out) {
    const W* a = s.src[0];
    const W* b = s.src[1];
    const W* c = s.src[2];
    if constexpr (L::arity == 1) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], W(0), W(0));
    } else if constexpr (L::arity == 2) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], b[i], W(0));
    } else {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], b[i], c[i]);
    }
}

// fpow in the fp32 modes: math::pow_batch, the common case in every lane and
// pow's special cases only where a lane needs them (ir/precise_math.h); the
// same bits as the table's ftz(math::pow(ftz(a), ftz(b))), lane by lane.
inline void pow_lanes(const Step<uint32_t>& s, uint32_t* out) {
    alignas(64) float x[kLanes], y[kLanes], r[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        x[i] = ir::ftz(std::bit_cast<float>(s.src[0][i]));
        y[i] = ir::ftz(std::bit_cast<float>(s.src[1][i]));
    }
    math::pow_batch<kLanes>(x, y, r);
    for (int i = 0; i < kLanes; ++i) out[i] = std::bit_cast<uint32_t>(ir::ftz(r[i]));
}

template <class W, ir::Op op>
void alu(const Step<W>& s, Machine<W>& m) {
    if constexpr (op == ir::Op::fpow && sizeof(W) == sizeof(uint32_t))
        emit(s, m, [&](W* out) { pow_lanes(s, out); });
    else
        emit(s, m, [&](W* out) { alu_lanes<W, ir::alu::Lane<op>>(s, out); });
}

// Straight from the source: a copy through a temporary stalls store forwarding.
template <class W>
void mov(const Step<W>& s, Machine<W>& m) {
    if (s.dst == s.src[0]) return;
    if (s.unmasked) std::memcpy(s.dst, s.src[0], sizeof(W) * kLanes);
    else m.write(s.dst, s.src[0]);
}

template <class W>
void konst(const Step<W>& s, Machine<W>& m) {
    emit(s, m, [&](W* out) {
        const W v = s.value;
        for (int i = 0; i < kLanes; ++i) out[i] = v;
    });
}

template <class W>
void sel(const Step<W>& s, Machine<W>& m) {
    emit(s, m, [&](W* out) {
        const W* c = s.src[0];
        const W* x = s.src[1];
        const W* y = s.src[2];
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) {
            W pick = W(0) - W(c[i] != 0);
            out[i] = (x[i] & pick) | (y[i] & ~pick);
        }
    });
}

template <class W>
void uniform(const Step<W>& s, Machine<W>& m) {
    emit(s, m, [&](W* out) {
        const W v = widen<W>(s.type, m.uniforms[s.imm[0]]);
        for (int i = 0; i < kLanes; ++i) out[i] = v;
    });
}

template <class W>
void uniform_ind(const Step<W>& s, Machine<W>& m) {
    alignas(64) W out[kLanes];
    for (int i = 0; i < kLanes; ++i)
        out[i] = widen<W>(s.type, m.uniforms[s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2]]);
    m.write(s.dst, out);
}

template <class W>
void load_ind(const Step<W>& s, Machine<W>& m) {
    alignas(64) W out[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        uint32_t r = s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2];
        out[i] = m.regs[size_t(r) * kLanes + i];
    }
    m.write(s.dst, out);
}

// Each lane writes its own element, so only the active lanes store.
template <class W>
void store_ind(const Step<W>& s, Machine<W>& m) {
    LaneMask active = m.mask.active();
    for (int i = 0; i < kLanes; ++i) {
        if (!((active >> i) & 1)) continue;
        uint32_t r = s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2];
        m.regs[size_t(r) * kLanes + i] = s.src[1][i];
    }
}

// Fine derivatives within each 2x2 quad: lanes 4q+0..3 are (x,y) (x+1,y)
// (x,y+1) (x+1,y+1). Each row gets its own ddx, each column its own ddy.
template <class W>
void ddx(const Step<W>& s, Machine<W>& m) {
    using F = FloatOf<W>;
    alignas(64) F out[kLanes];
    F v[kLanes];
    std::memcpy(v, s.src[0], sizeof v);
    for (int q = 0; q < kLanes; q += 4) {
        F row0 = v[q + 1] - v[q + 0], row1 = v[q + 3] - v[q + 2];
        out[q + 0] = out[q + 1] = row0;
        out[q + 2] = out[q + 3] = row1;
    }
    W words[kLanes];
    std::memcpy(words, out, sizeof words);
    m.write(s.dst, words);
}

template <class W>
void ddy(const Step<W>& s, Machine<W>& m) {
    using F = FloatOf<W>;
    alignas(64) F out[kLanes];
    F v[kLanes];
    std::memcpy(v, s.src[0], sizeof v);
    for (int q = 0; q < kLanes; q += 4) {
        F col0 = v[q + 2] - v[q + 0], col1 = v[q + 3] - v[q + 1];
        out[q + 0] = out[q + 2] = col0;
        out[q + 1] = out[q + 3] = col1;
    }
    W words[kLanes];
    std::memcpy(words, out, sizeof words);
    m.write(s.dst, words);
}

// GLSL's undefined operations (ir/undefined.h): the active lanes whose
// operands make the op undefined go to the sink, with every lane's operands.
// Out of line (runtime/undef_kernel.cpp): only checking programs have it.
template <class W>
void check_undef(const Step<W>& s, Machine<W>& m);
extern template void check_undef<uint32_t>(const Step<uint32_t>&, Machine<uint32_t>&);
extern template void check_undef<uint64_t>(const Step<uint64_t>&, Machine<uint64_t>&);

// Texture lookups (runtime/tex_kernel.cpp): src[1] points at the operand
// block (the compiler resolves imm[0]), dst at the first of four results.
// Reference mode samples with the same float sampler: coordinates are
// rounded to float, the texel widened back.
template <class W>
void tex(const Step<W>& s, Machine<W>& m);
extern template void tex<uint32_t>(const Step<uint32_t>&, Machine<uint32_t>&);
extern template void tex<uint64_t>(const Step<uint64_t>&, Machine<uint64_t>&);
// Precision::Fast's `tex`: the same lookups with the GPU's filter arithmetic
// (runtime/sampling_rules.h, "The GPU's filtering").
void tex_gpu(const Step<uint32_t>& s, Machine<uint32_t>& m);

}  // namespace kernels

// A kernel recompiled for AVX2: `flatten` inlines the generic kernel and
// everything it calls into this function, so its lane loops vectorize 8 wide.
// The generic code itself stays baseline x86-64 (no ODR clash between ISAs),
// and no FMA is enabled, so every lane computes the same bits either way.
#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_HAVE_AVX2_KERNELS 1
template <class W, Kernel<W> K>
__attribute__((target("avx2"), flatten)) void avx2_kernel(const Step<W>& s, Machine<W>& m) {
    K(s, m);
}
#endif

template <class W, bool kAvx2, Kernel<W> K>
constexpr Kernel<W> pick_kernel() {
#ifdef GLSLRUN_HAVE_AVX2_KERNELS
    if constexpr (kAvx2) return &avx2_kernel<W, K>;
#endif
    return K;
}

// The kernel of every opcode: Alu ones from the table, Special ones by name.
template <class W, bool kAvx2>
Kernel<W> kernel_for(ir::Op op) {
    switch (op) {
#define GLSLRUN_KERNEL_Alu(name) \
    case ir::Op::name: return pick_kernel<W, kAvx2, &kernels::alu<W, ir::Op::name>>();
#define GLSLRUN_KERNEL_Special(name) \
    case ir::Op::name: return pick_kernel<W, kAvx2, &kernels::name<W>>();
#define OP(name, arity, res, opnd, kind, fast, props, expr) GLSLRUN_KERNEL_##kind(name)
#include "ir/opcodes.def"
#undef OP
#undef GLSLRUN_KERNEL_Special
#undef GLSLRUN_KERNEL_Alu
    default: return nullptr;
    }
}

// Picks the kernels for the CPU that runs them, once per Interpreter.
inline Kernel<uint32_t> kernel_for(ir::Op op, bool avx2) {
    return avx2 ? kernel_for<uint32_t, true>(op) : kernel_for<uint32_t, false>(op);
}
// Reference mode: baseline kernels only (its speed is secondary, and this
// halves what the 64-bit word costs to compile).
inline Kernel<uint64_t> kernel_for(ir::Op op) { return kernel_for<uint64_t, false>(op); }

// GLSLRUN_NO_AVX2=1 forces the baseline kernels: images must not change.
// Read once per process, as cpu_has_avx512() does: every draw asks several
// times (its executors, the fused pipeline's state), and getenv's scan of
// the environment was 0.5% of many_draws' frame (perf).
inline bool cpu_has_avx2() {
#ifdef GLSLRUN_HAVE_AVX2_KERNELS
    static const bool on = [] {
        const char* off = std::getenv("GLSLRUN_NO_AVX2");
        if (off && off[0] == '1') return false;
        return bool(__builtin_cpu_supports("avx2"));
    }();
    return on;
#else
    return false;
#endif
}

}  // namespace glslrun::rt
