// The check_undef kernel (ir/undefined.h). The interpreter runs it as any
// kernel; the JIT calls it out (runtime/jit/alu.cpp), so both backends
// report the same lanes with the same operands.
#include <bit>

#include "ir/undefined.h"
#include "runtime/interp_kernels.h"
#include "runtime/undef_sink.h"

namespace glslrun::rt::kernels {

namespace {

// Register word -> its value: a float (fp32, or Reference's double) or an int.
template <class W>
double value_of(ir::Kind kind, W w) {
    if (kind == ir::Kind::I32) return double(int32_t(uint32_t(w)));
    return double(std::bit_cast<FloatOf<W>>(w));
}

}  // namespace

template <class W>
void check_undef(const Step<W>& s, Machine<W>& m) {
    if (!m.undef) return;
    const auto op = ir::UndefOp(s.imm[0]);
    const LaneMask active = m.mask.active();
    double a[kLanes], b[kLanes], c[kLanes];
    LaneMask hits = 0;
    for (int i = 0; i < kLanes; ++i) {
        a[i] = value_of<W>(s.type, s.src[0][i]);
        b[i] = value_of<W>(s.type, s.src[1][i]);
        c[i] = value_of<W>(s.type, s.src[2][i]);
        if (((active >> i) & 1) && ir::undefined_for(op, a[i], b[i], c[i], s.imm[2])) hits |= LaneMask(1) << i;
    }
    if (hits) m.undef->undefined(s.imm[1], hits, a, b, c);
}

template void check_undef<uint32_t>(const Step<uint32_t>&, Machine<uint32_t>&);
template void check_undef<uint64_t>(const Step<uint64_t>&, Machine<uint64_t>&);

}  // namespace glslrun::rt::kernels
