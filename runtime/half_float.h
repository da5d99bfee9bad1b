// binary16 storage (GL_RGBA16F, ARB_texture_float / ARB_half_float_pixel) as
// floats: the value a half-float texel or colour channel holds, read back as
// a float. Mesa converts by two rules, measured through glref on llvmpipe
// (tests/reference/float_targets_test.cpp): texels that glTexImage uploads
// are rounded to nearest even (round_to_half), while what a draw, a blend or
// a clear stores in a half-float colour buffer is truncated toward zero
// (truncate_to_half: llvmpipe's float-to-half conversion, vcvtps2ph in its
// round-toward-zero mode, as D3D10 allows for render targets).
#pragma once
#include <bit>
#include <cstdint>

namespace glslrun::rt {

// `v` rounded to the nearest binary16 value, ties to even, as x86's
// vcvtps2ph (imm 0) and Mesa's float-to-half conversion round: magnitudes
// from 65520 (half way past the largest half, 65504) become infinity, an
// infinity stays one, a NaN stays a quiet NaN (its payload cut to the
// half's 10 bits), and magnitudes below 2^-14 round to multiples of 2^-24
// (the half's subnormals; under 2^-25 to a zero of v's sign). Integer
// arithmetic only, so the MXCSR's FTZ/DAZ (set while shading) changes
// nothing.
inline float round_to_half(float v) {
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    const uint32_t sign = bits & 0x80000000u, mag = bits & 0x7FFFFFFFu;
    if (mag > 0x7F800000u) return std::bit_cast<float>(sign | 0x7FC00000u | (mag & 0x007FE000u));
    if (mag >= 0x477FF000u) return std::bit_cast<float>(sign | 0x7F800000u);  // >= 65520: infinity
    if (mag >= 0x38800000u) {  // a normal half (>= 2^-14): keep 10 of the 23 fraction bits
        const uint32_t odd = (mag >> 13) & 1u;
        return std::bit_cast<float>(sign | ((mag + 0xFFFu + odd) & ~0x1FFFu));
    }
    // A subnormal half: a multiple of 2^-24. The float's significand (with its
    // implicit bit) shifted so that bit 0 is worth 2^-24, rounded half to even.
    const int exponent = int(mag >> 23);  // 0 for float subnormals: far below 2^-25
    if (exponent < 102) return std::bit_cast<float>(sign);  // < 2^-25: zero
    const uint32_t significand = (mag & 0x7FFFFFu) | 0x800000u;
    const int shift = 126 - exponent;  // 14..24: value = significand * 2^(exponent - 150)
    const uint32_t half_way = 1u << (shift - 1), rest = significand & ((1u << shift) - 1u);
    uint32_t units = significand >> shift;  // multiples of 2^-24
    if (rest > half_way || (rest == half_way && (units & 1u))) ++units;
    // units <= 1024 = 2^-14 exactly: representable as a float by scaling.
    return std::bit_cast<float>(sign | std::bit_cast<uint32_t>(float(units) * 0x1p-24f));
}

// `v` truncated toward zero to a binary16 value: finite magnitudes from
// 65504 on become 65504 (round toward zero never reaches infinity), an
// infinity stays one, a NaN stays a quiet NaN (as round_to_half), and
// magnitudes below 2^-14 keep their whole multiples of 2^-24.
inline float truncate_to_half(float v) {
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    const uint32_t sign = bits & 0x80000000u, mag = bits & 0x7FFFFFFFu;
    if (mag > 0x7F800000u) return std::bit_cast<float>(sign | 0x7FC00000u | (mag & 0x007FE000u));
    if (mag == 0x7F800000u) return v;
    if (mag >= 0x477FE000u) return std::bit_cast<float>(sign | 0x477FE000u);  // the largest half, 65504
    if (mag >= 0x38800000u) return std::bit_cast<float>(sign | (mag & ~0x1FFFu));
    const int exponent = int(mag >> 23);
    if (exponent < 103) return std::bit_cast<float>(sign);  // < 2^-24: zero
    const uint32_t units = ((mag & 0x7FFFFFu) | 0x800000u) >> (126 - exponent);
    return std::bit_cast<float>(sign | std::bit_cast<uint32_t>(float(units) * 0x1p-24f));
}

}  // namespace glslrun::rt
