// Alpha-test cases at the RGBA8 buffer's rounding boundaries, where comparing
// the shader's float with the reference gives the other answer from GL 2.1
// §4.1.4, which compares the bytes that both would be stored as. Shared by
// the unit test (both backends) and the comparison with Mesa.
#pragma once
#include <array>
#include <cstdio>
#include <string>

namespace alpha_boundaries {

struct Case {
    float alpha;       // the fragment's alpha (a uniform)
    const char* func;  // alpha_test_func
    float ref;         // alpha_test_ref
    bool passes;       // in GL with an RGBA8 colour buffer
};

// Bytes: round(255 x) with ties to even, after clamping to [0, 1].
inline constexpr std::array<Case, 12> kCases{{
    {0.1005f, "greater", 0.1f, false},        // 26 > 26 (floats: passes)
    {128.0f / 255.0f, "equal", 0.5f, true},   // 128 == 128 (127.5 ties to even)
    {0.5f, "equal", 128.0f / 255.0f, true},   // the same, the other way round
    {0.5f, "less", 0.5019f, false},           // 128 < 128 (floats: passes)
    {0.0019f, "equal", 0.0f, true},           // 0 == 0
    {0.9985f, "gequal", 1.0f, true},          // 255 >= 255
    {1.5f, "equal", 1.0f, true},              // clamped to 1
    {-0.5f, "equal", 0.0f, true},             // clamped to 0
    {0.2f, "notequal", 0.2008f, false},       // 51 != 51
    {0.3f, "lequal", 0.299f, true},           // 76.5 ties to 76 <= 76
    {0.6f, "greater", 0.598f, true},          // 153 > 152 (as floats)
    {0.25f, "less", 0.2509f, false},          // 64 < 64 (floats: passes)
}};

// 4 x 3 cells of 32 x 32 pixels, one quad of about 26 x 24 pixels in each.
inline constexpr int kWidth = 128, kHeight = 96, kColumns = 4, kCell = 32;

// The window position of case i's centre.
inline std::array<int, 2> centre(size_t i) {
    return {int(i % kColumns) * kCell + kCell / 2, kHeight - 1 - (int(i / kColumns) * kCell + kCell / 2)};
}

// The scene: one quad per case with its alpha as uniform `alpha`; black clear.
inline std::string scene() {
    std::string s = "[output]\nsize = [" + std::to_string(kWidth) + ", " + std::to_string(kHeight) +
                    "]\nclear_color = [0, 0, 0, 1]\n";
    for (size_t i = 0; i < kCases.size(); ++i) {
        const Case& c = kCases[i];
        char object[512];
        std::snprintf(object, sizeof object,
                      "\n[[objects]]\nmesh = \"quad\"\ntransform = [ { translate = [%.4f, %.4f, 0] }, "
                      "{ scale = [0.2, 0.25, 1] } ]\nuniforms = { alpha = %.9g }\n"
                      "state = { alpha_test = true, alpha_test_func = \"%s\", alpha_test_ref = %.9g }\n",
                      -0.75 + 0.5 * double(i % kColumns), 2.0 / 3.0 - 2.0 / 3.0 * double(i / kColumns),
                      double(c.alpha), c.func, double(c.ref));
        s += object;
    }
    return s;
}

}  // namespace alpha_boundaries
