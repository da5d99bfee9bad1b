// The lecture's minimal colour program on its quad (red, green, blue, yellow
// corners), rendered through the public API only. Checks a few pixels,
// writes the image to argv[1] as PNG, and exits non-zero on any failure.
#include <cmath>
#include <cstdio>
#include <string>

#include "glslrun/glslrun.h"

namespace {

const char* kVertexShader = R"(
void main() {
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
)";

const char* kFragmentShader = R"(
void main() {
    gl_FragColor = gl_Color;
}
)";

bool near(glm::vec4 a, glm::vec4 b, float tolerance) {
    for (int i = 0; i < 4; ++i)
        if (std::fabs(a[i] - b[i]) > tolerance) return false;
    return true;
}

bool check_pixel(const glslrun::Framebuffer& fb, int x, int y, glm::vec4 expected) {
    glm::vec4 got = fb.pixel(x, y);
    if (near(got, expected, 2.5f / 255.0f)) return true;
    std::fprintf(stderr, "pixel (%d,%d): expected (%.3f %.3f %.3f %.3f), got (%.3f %.3f %.3f %.3f)\n", x, y,
                 expected.r, expected.g, expected.b, expected.a, got.r, got.g, got.b, got.a);
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s output.png\n", argv[0]);
        return 2;
    }
    auto program = glslrun::Program::compile({{"quad.vert", kVertexShader}}, {{"quad.frag", kFragmentShader}});
    if (!program) {
        std::fprintf(stderr, "%s\n", program.error().str().c_str());
        return 1;
    }
    const int size = 64;
    glslrun::Framebuffer fb(size, size);
    fb.clear_color({0, 0, 0, 1});
    glslrun::GLState gl;  // identity matrices: the quad fills the viewport
    std::vector<glslrun::VertexAttrib> mesh = {
        {"gl_Vertex", 3, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}},
        {"gl_Color", 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0}},
    };
    auto stats = glslrun::draw(*program, gl, fb, glslrun::Primitive::Quads, mesh, 4);
    if (!stats) {
        std::fprintf(stderr, "%s\n", stats.error().str().c_str());
        return 1;
    }
    bool ok = stats->fragments_written == uint64_t(size) * size;
    if (!ok) std::fprintf(stderr, "%llu fragments written, expected %d\n",
                          (unsigned long long)stats->fragments_written, size * size);
    // Pixel centres (x + 0.5) / size across the quad; llvmpipe's 0-2 split means
    // the lower-right triangle blends red, green, blue and the upper-left red, blue, yellow.
    auto at = [&](int x, int y) {
        float s = (x + 0.5f) / size, t = (y + 0.5f) / size;
        glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1), yellow(1, 1, 0);
        glm::vec3 c = s >= t ? red * (1 - s) + green * (s - t) + blue * t
                             : red * (1 - t) + blue * s + yellow * (t - s);
        return glm::vec4(c, 1.0f);
    };
    const int probes[][2] = {{0, 0}, {size - 1, 0}, {size - 1, size - 1}, {0, size - 1}, {size / 2, size / 2},
                             {10, 40}, {40, 10}, {5, 6}};
    for (const auto& p : probes) ok = check_pixel(fb, p[0], p[1], at(p[0], p[1])) && ok;
    if (auto written = glslrun::write_png(fb, argv[1]); !written) {
        std::fprintf(stderr, "%s\n", written.error().str().c_str());
        return 1;
    }
    if (!ok) return 1;
    std::printf("wrote %s (%dx%d)\n", argv[1], size, size);
    return 0;
}
