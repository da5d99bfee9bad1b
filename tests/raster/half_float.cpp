// Half-float colour buffers and textures (GL_RGBA16F): rt::round_to_half
// (texel uploads) and rt::truncate_to_half (colour buffer stores) against
// the CPU's own conversion (F16C's vcvtps2ph, round to nearest even and
// toward zero) on every tie between two halves and their neighbours, and
// the storage of draws and clears into a half-float framebuffer.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <cpuid.h>
#include <immintrin.h>

#include "raster/fragment_ops.h"
#include "raster/framebuffer.h"
#include "runtime/half_float.h"

using namespace glslrun;

namespace {

__attribute__((target("f16c"))) float hardware_half(float v) {
    return _mm_cvtss_f32(_mm_cvtph_ps(_mm_cvtps_ph(_mm_set_ss(v), _MM_FROUND_TO_NEAREST_INT)));
}
__attribute__((target("f16c"))) float hardware_half_toward_zero(float v) {
    return _mm_cvtss_f32(_mm_cvtph_ps(_mm_cvtps_ph(_mm_set_ss(v), _MM_FROUND_TO_ZERO)));
}

__attribute__((target("f16c"))) float hardware_float(uint32_t h) {
    return _mm_cvtss_f32(_mm_cvtph_ps(_mm_cvtsi32_si128(int(h & 0xFFFFu))));
}

// cpuid rather than __builtin_cpu_supports: clang (the sanitizer build's
// compiler) knows no "f16c" feature string.
bool cpu_has_f16c() {
    unsigned a = 0, b = 0, c = 0, d = 0;
    return __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C) != 0;
}

bool same_bits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

}  // namespace

TEST_CASE("round_to_half rounds to the nearest half, ties to even, past 65504 to infinity", "[raster][half]") {
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(rt::round_to_half(1.0f + 0x1p-11f) == 1.0f);                 // a tie: to the even 1
    CHECK(rt::round_to_half(1.0f + 0x3p-11f) == 1.0f + 0x2p-10f);      // a tie: to the even 1 + 2^-9
    CHECK(rt::round_to_half(1.0f + 0x1p-11f + 0x1p-20f) == 1.0f + 0x1p-10f);
    CHECK(rt::round_to_half(65504.0f) == 65504.0f);
    CHECK(rt::round_to_half(65519.99f) == 65504.0f);
    CHECK(rt::round_to_half(65520.0f) == inf);
    CHECK(rt::round_to_half(-70000.0f) == -inf);
    CHECK(rt::round_to_half(inf) == inf);
    CHECK(std::isnan(rt::round_to_half(std::numeric_limits<float>::quiet_NaN())));
    CHECK(rt::round_to_half(0x3p-25f) == 0x1p-23f);                    // subnormal tie: 1.5 units to 2
    CHECK(rt::round_to_half(0x1p-25f) == 0.0f);                        // half a unit: to the even 0
    CHECK(std::signbit(rt::round_to_half(-0x1p-30f)));                 // a zero of v's sign
    CHECK(rt::round_to_half(0x1p-14f - 0x1p-26f) == 0x1p-14f);         // the last subnormal rounds up to 2^-14
}

TEST_CASE("truncate_to_half cuts toward zero, past 65504 to 65504", "[raster][half]") {
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(rt::truncate_to_half(1.0f + 0x1p-11f + 0x1p-20f) == 1.0f);
    CHECK(rt::truncate_to_half(-(1.0f + 0x3p-11f)) == -(1.0f + 0x1p-10f));
    CHECK(rt::truncate_to_half(70000.0f) == 65504.0f);
    CHECK(rt::truncate_to_half(-1e30f) == -65504.0f);
    CHECK(rt::truncate_to_half(inf) == inf);
    CHECK(std::isnan(rt::truncate_to_half(std::numeric_limits<float>::quiet_NaN())));
    CHECK(rt::truncate_to_half(0x3p-25f) == 0x1p-24f);
    CHECK(rt::truncate_to_half(0x1p-24f - 0x1p-40f) == 0.0f);
}

TEST_CASE("round_to_half and truncate_to_half give the CPU's vcvtps2ph bits on every tie and its neighbours", "[raster][half]") {
    if (!cpu_has_f16c()) {
        // The fixed cases above still hold; this CPU has nothing to compare with.
        WARN("no F16C on this CPU: the comparison with vcvtps2ph did not run");
        return;
    }
    // Every half h (both signs, NaNs and infinities too), the float half way
    // to the next one, and the floats one and two ulps around each.
    for (uint32_t h = 0; h < 0x10000u; ++h) {
        const float here = hardware_float(h), next = hardware_float(h + 1);
        const float mid = here + (next - here) * 0.5f;
        for (float v : {here, mid, std::nextafter(mid, 0.0f), std::nextafter(mid, 2.0f * mid),
                        std::nextafter(std::nextafter(mid, 2.0f * mid), 2.0f * mid)}) {
            if (std::isnan(v)) {
                REQUIRE(std::isnan(rt::round_to_half(v)));
                continue;
            }
            INFO("v = " << v << " (bits " << std::bit_cast<uint32_t>(v) << ")");
            REQUIRE(same_bits(rt::round_to_half(v), hardware_half(v)));
            REQUIRE(same_bits(rt::truncate_to_half(v), hardware_half_toward_zero(v)));
        }
    }
    // And a million random bit patterns.
    std::mt19937 rng(25);
    for (int i = 0; i < 1000000; ++i) {
        const float v = std::bit_cast<float>(uint32_t(rng()));
        if (std::isnan(v)) continue;
        REQUIRE(same_bits(rt::round_to_half(v), hardware_half(v)));
        REQUIRE(same_bits(rt::truncate_to_half(v), hardware_half_toward_zero(v)));
    }
}

TEST_CASE("a half-float framebuffer stores clears and pixels truncated to halves, a float one as floats", "[raster][half]") {
    Framebuffer half(4, 2, true), full(4, 2, true);
    half.half_float = true;
    const glm::vec4 c{1.0f + 0x1p-11f + 0x1p-20f, 70000.0f, -3.0000001f, 0x3p-25f};
    half.clear_color(c);
    full.clear_color(c);
    CHECK(half.pixel(3, 1) == glm::vec4(1.0f, 65504.0f, -3.0f, 0x1p-24f));
    CHECK(full.pixel(3, 1) == c);
    raster::write_color(half, 1, 0, glm::vec4(2.5f, 1e-9f, 1000.3f, 1.0f));
    CHECK(half.pixel(1, 0) == glm::vec4(2.5f, 0.0f, 1000.0f, 1.0f));
}

TEST_CASE("float buffers keep the blend colour and alpha reference unclamped, RGBA8 ones clamp them", "[raster][half]") {
    // GL_CLAMP_FRAGMENT_COLOR_ARB's FIXED_ONLY (Mesa's BlendColorUnclamped, AlphaRefUnclamped).
    GLState gl;
    gl.blend = true;
    gl.blend_state.color = {1.7f, -0.2f, 0.5f, 2.0f};
    gl.alpha_test = true;
    gl.alpha_ref = 1.5f;
    const raster::FragmentOps fixed(gl, Framebuffer(2, 2)), floats(gl, Framebuffer(2, 2, true));
    CHECK(fixed.blend_state.color == glm::vec4(1.0f, 0.0f, 0.5f, 1.0f));
    CHECK(fixed.alpha_ref == 1.0f);
    CHECK(floats.blend_state.color == gl.blend_state.color);
    CHECK(floats.alpha_ref == 1.5f);
    CHECK_FALSE(floats.half_float);
    Framebuffer half(2, 2, true);
    half.half_float = true;
    CHECK(raster::FragmentOps(gl, half).half_float);
}
