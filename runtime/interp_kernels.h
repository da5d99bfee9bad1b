// The interpreter's instruction kernels: one function per opcode, each a loop
// over the kLanes lanes of a batch. Alu kernels are generated from the opcode
// table (ir/opcodes.def via ir/alu_eval.h); the Special ones are written by
// name. Dispatch happens once per instruction (a function pointer per Step).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "glslrun/glslrun.h"
#include "ir/alu_eval.h"
#include "runtime/exec_mask.h"

namespace glslrun::rt {

struct Step;

// Bit i of a 32-lane mask word: testing against a table (not shifting by the
// lane index) lets the blend vectorize without AVX2's variable shifts.
inline constexpr std::array<uint32_t, 32> kLaneBit = [] {
    std::array<uint32_t, 32> bits{};
    for (int i = 0; i < 32; ++i) bits[size_t(i)] = 1u << i;
    return bits;
}();

// What a kernel can touch: the register file, the uniform store, the bound
// textures, the mask.
struct Machine {
    uint32_t* regs = nullptr;  // register r lane i at regs[r * kLanes + i]
    const uint32_t* uniforms = nullptr;
    const GLState::TextureUnit* textures = nullptr;  // kMaxTextureUnits units, or none at all
    ExecMask mask;

    // Masked register write: inactive lanes keep their old value.
    void write(uint32_t* __restrict dst, const uint32_t* __restrict value) {
        const LaneMask active = mask.active();
        if (active == kAllLanes) {
            std::memcpy(dst, value, sizeof(uint32_t) * kLanes);
            return;
        }
        for (int base = 0; base < kLanes; base += 32) {
            const uint32_t bits = uint32_t(active >> base);
            const int n = kLanes - base < 32 ? kLanes - base : 32;
            for (int i = 0; i < n; ++i) {
                const uint32_t pick = 0u - uint32_t((bits & kLaneBit[size_t(i)]) != 0);
                dst[base + i] = (value[base + i] & pick) | (dst[base + i] & ~pick);
            }
        }
    }
};

using Kernel = void (*)(const Step&, Machine&);

// One compiled IR node. Blocks are ranges [begin, end) of a flat Step array.
struct Step {
    ir::NodeKind kind = ir::NodeKind::Instr;
    Kernel fn = nullptr;  // Instr
    uint32_t* dst = nullptr;
    const uint32_t* src[3] = {nullptr, nullptr, nullptr};
    uint32_t imm[3] = {0, 0, 0};
    bool unmasked = false;           // ir::Instr::unmasked: write every lane
    const uint32_t* cond = nullptr;  // If
    uint32_t body_begin = 0, body_end = 0;  // If then / Loop body / Scope body
    uint32_t alt_begin = 0, alt_end = 0;    // If else / Loop continue block
    uint32_t callee = 0;                    // Call
    int line = 0;
};

namespace kernels {

inline uint32_t clamp_index(uint32_t raw, uint32_t count) {
    int32_t i = static_cast<int32_t>(raw);
    if (i < 0) return 0;
    return std::min(static_cast<uint32_t>(i), count - 1);
}

// Runs a lane-wise body `lanes(out)` straight into the destination when every
// lane is active (or none can tell), else into a temporary that is blended in.
// Bodies must be elementwise (lane i reads only lane i) so dst may alias an
// operand.
template <class Lanes>
inline void emit(const Step& s, Machine& m, Lanes&& lanes) {
    if (s.unmasked || m.mask.full()) {
        lanes(s.dst);
        return;
    }
    alignas(64) uint32_t out[kLanes];
    lanes(out);
    m.write(s.dst, out);
}

// Lane loop of an Alu op into `out`. Operands may alias `out` lane for lane
// (dst == src), which is safe elementwise: ivdep tells GCC so.
template <ir::Op op>
inline void alu_lanes(const Step& s, uint32_t* out) {
    using L = ir::alu::Lane<op>;
    const uint32_t* a = s.src[0];
    const uint32_t* b = s.src[1];
    const uint32_t* c = s.src[2];
    if constexpr (L::arity == 1) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], 0, 0);
    } else if constexpr (L::arity == 2) {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], b[i], 0);
    } else {
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) out[i] = L::eval(a[i], b[i], c[i]);
    }
}

template <ir::Op op>
void alu(const Step& s, Machine& m) {
    emit(s, m, [&](uint32_t* out) { alu_lanes<op>(s, out); });
}

// Straight from the source: a copy through a temporary stalls store forwarding.
inline void mov(const Step& s, Machine& m) {
    if (s.dst == s.src[0]) return;
    if (s.unmasked) std::memcpy(s.dst, s.src[0], sizeof(uint32_t) * kLanes);
    else m.write(s.dst, s.src[0]);
}

inline void konst(const Step& s, Machine& m) {
    emit(s, m, [&](uint32_t* out) {
        const uint32_t v = s.imm[0];
        for (int i = 0; i < kLanes; ++i) out[i] = v;
    });
}

inline void sel(const Step& s, Machine& m) {
    emit(s, m, [&](uint32_t* out) {
        const uint32_t* c = s.src[0];
        const uint32_t* x = s.src[1];
        const uint32_t* y = s.src[2];
#pragma GCC ivdep
        for (int i = 0; i < kLanes; ++i) {
            uint32_t pick = 0u - (c[i] != 0);
            out[i] = (x[i] & pick) | (y[i] & ~pick);
        }
    });
}

inline void uniform(const Step& s, Machine& m) {
    emit(s, m, [&](uint32_t* out) {
        const uint32_t v = m.uniforms[s.imm[0]];
        for (int i = 0; i < kLanes; ++i) out[i] = v;
    });
}

inline void uniform_ind(const Step& s, Machine& m) {
    alignas(64) uint32_t out[kLanes];
    for (int i = 0; i < kLanes; ++i)
        out[i] = m.uniforms[s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2]];
    m.write(s.dst, out);
}

inline void load_ind(const Step& s, Machine& m) {
    alignas(64) uint32_t out[kLanes];
    for (int i = 0; i < kLanes; ++i) {
        uint32_t r = s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2];
        out[i] = m.regs[size_t(r) * kLanes + i];
    }
    m.write(s.dst, out);
}

// Each lane writes its own element, so only the active lanes store.
inline void store_ind(const Step& s, Machine& m) {
    LaneMask active = m.mask.active();
    for (int i = 0; i < kLanes; ++i) {
        if (!((active >> i) & 1)) continue;
        uint32_t r = s.imm[0] + clamp_index(s.src[0][i], s.imm[1]) * s.imm[2];
        m.regs[size_t(r) * kLanes + i] = s.src[1][i];
    }
}

// Fine derivatives within each 2x2 quad: lanes 4q+0..3 are (x,y) (x+1,y)
// (x,y+1) (x+1,y+1). Each row gets its own ddx, each column its own ddy.
inline void ddx(const Step& s, Machine& m) {
    alignas(64) float out[kLanes];
    float v[kLanes];
    std::memcpy(v, s.src[0], sizeof v);
    for (int q = 0; q < kLanes; q += 4) {
        float row0 = v[q + 1] - v[q + 0], row1 = v[q + 3] - v[q + 2];
        out[q + 0] = out[q + 1] = row0;
        out[q + 2] = out[q + 3] = row1;
    }
    uint32_t words[kLanes];
    std::memcpy(words, out, sizeof words);
    m.write(s.dst, words);
}

inline void ddy(const Step& s, Machine& m) {
    alignas(64) float out[kLanes];
    float v[kLanes];
    std::memcpy(v, s.src[0], sizeof v);
    for (int q = 0; q < kLanes; q += 4) {
        float col0 = v[q + 2] - v[q + 0], col1 = v[q + 3] - v[q + 1];
        out[q + 0] = out[q + 2] = col0;
        out[q + 1] = out[q + 3] = col1;
    }
    uint32_t words[kLanes];
    std::memcpy(words, out, sizeof words);
    m.write(s.dst, words);
}

// Texture lookups (runtime/tex_kernel.cpp): src[1] points at the operand
// block (the compiler resolves imm[0]), dst at the first of four results.
void tex(const Step& s, Machine& m);

}  // namespace kernels

// A kernel recompiled for AVX2: `flatten` inlines the generic kernel and
// everything it calls into this function, so its lane loops vectorize 8 wide.
// The generic code itself stays baseline x86-64 (no ODR clash between ISAs),
// and no FMA is enabled, so every lane computes the same bits either way.
#if defined(__x86_64__) && defined(__GNUC__)
#define GLSLRUN_HAVE_AVX2_KERNELS 1
template <Kernel K>
__attribute__((target("avx2"), flatten)) void avx2_kernel(const Step& s, Machine& m) {
    K(s, m);
}
#endif

template <bool kAvx2, Kernel K>
constexpr Kernel pick_kernel() {
#ifdef GLSLRUN_HAVE_AVX2_KERNELS
    if constexpr (kAvx2) return &avx2_kernel<K>;
#endif
    return K;
}

// The kernel of every opcode: Alu ones from the table, Special ones by name.
template <bool kAvx2>
Kernel kernel_for(ir::Op op) {
    switch (op) {
#define GLSLRUN_KERNEL_Alu(name) \
    case ir::Op::name: return pick_kernel<kAvx2, &kernels::alu<ir::Op::name>>();
#define GLSLRUN_KERNEL_Special(name) \
    case ir::Op::name: return pick_kernel<kAvx2, &kernels::name>();
#define OP(name, arity, res, opnd, kind, expr) GLSLRUN_KERNEL_##kind(name)
#include "ir/opcodes.def"
#undef OP
#undef GLSLRUN_KERNEL_Special
#undef GLSLRUN_KERNEL_Alu
    default: return nullptr;
    }
}

// Picks the kernels for the CPU that runs them, once per Interpreter.
inline Kernel kernel_for(ir::Op op, bool avx2) { return avx2 ? kernel_for<true>(op) : kernel_for<false>(op); }

// GLSLRUN_NO_AVX2=1 forces the baseline kernels: images must not change.
inline bool cpu_has_avx2() {
#ifdef GLSLRUN_HAVE_AVX2_KERNELS
    const char* off = std::getenv("GLSLRUN_NO_AVX2");
    if (off && off[0] == '1') return false;
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

}  // namespace glslrun::rt
