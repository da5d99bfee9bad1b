// Issue #5's rasterization extremes that a probe list cannot summarise:
// how much of the viewport a triangle with 1e30 coordinates covers, and a
// 1x1 viewport. tests/extremes/raster_clip.shader_test checks the other
// clipping cases on glslrun and llvmpipe; docs/extremes.md has the numbers.
#include "harness.h"

#include <string>

using namespace lang;

namespace {

const char* kVs = R"(
attribute vec4 vertex;
varying vec4 color;
void main() { gl_Position = vertex; color = vec4(0.25, 0.5, 0.75, 1.0); }
)";
const char* kFs = "varying vec4 color;\nvoid main() { gl_FragColor = color; }\n";

// Draws one triangle given in clip coordinates; returns the pixels with the
// varying's exact colour, and counts any other non-background pixel in `garbage`.
int covered(const std::vector<float>& clip, int size, int* garbage) {
    glslrun::Program prog = compile_or_fail(kVs, kFs);
    glslrun::GLState gl;
    glslrun::Framebuffer fb(size, size);
    fb.clear_color(glm::vec4(0.0f));
    auto stats = glslrun::draw(prog, gl, fb, glslrun::Primitive::Triangles, {{"vertex", 4, clip}}, 3);
    REQUIRE(stats);
    int n = 0;
    *garbage = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec4 p = fb.pixel(x, y);
            if (p == glm::vec4(64, 128, 191, 255) / 255.0f) ++n;  // 0.25, 0.5, 0.75, 1 in RGBA8
            else if (p != glm::vec4(0.0f)) ++*garbage;
        }
    return n;
}

}  // namespace

TEST_CASE("extremes: a triangle with coordinates of 1e30 covers the whole viewport", "[extremes][raster]") {
    // The triangle contains the whole view volume, so GL wants every pixel
    // drawn. Interpolating a clipped vertex cancels at this size
    // (-1e30 + 0.5 * 2e30 = 0 where the plane is at y = w): raster/clip.cpp
    // puts clipped vertices exactly on their plane. llvmpipe draws 23375.
    int garbage = 0;
    int n = covered({-1e30f, -1e30f, 0, 1, 1e30f, -1e30f, 0, 1, 0, 1e30f, 0, 1}, 250, &garbage);
    INFO(n << " of 62500 pixels covered");
    CHECK(garbage == 0);
    CHECK(n == 250 * 250);
}

TEST_CASE("extremes: a 1x1 viewport", "[extremes][raster]") {
    int garbage = 0;
    // A triangle covering the pixel centre (NDC 0, 0), then one that misses it.
    CHECK(covered({-1, -1, 0, 1, 1, -1, 0, 1, 0, 1, 0, 1}, 1, &garbage) == 1);
    CHECK(covered({-1, -1, 0, 1, -0.5f, -1, 0, 1, -1, -0.5f, 0, 1}, 1, &garbage) == 0);
    CHECK(garbage == 0);
}
