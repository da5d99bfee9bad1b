// Edge functions and the fill rule: adjacent triangles cover every pixel
// exactly once, whatever the subpixel positions of the shared vertices.
#include <catch2/catch.hpp>

#include <functional>
#include <random>
#include <vector>

#include "raster/fragments.h"
#include "raster/triangle.h"
#include "runtime/cpu_features.h"

using namespace glslrun::raster;

namespace {

// Counts how often each pixel of a W x H target is covered.
struct HitCounter {
    int w, h;
    std::vector<int> hits;
    HitCounter(int width, int height) : w(width), h(height), hits(size_t(width) * height, 0) {}
    void draw(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
        Rect scissor{0, 0, w, h};
        auto setup = setup_triangle({a, b, c}, scissor);
        if (!setup) return;
        for_each_quad(*setup, scissor, [&](int x, int y, unsigned mask) {
            REQUIRE(x % 2 == 0);
            REQUIRE(y % 2 == 0);
            for (int i = 0; i < 4; ++i)
                if ((mask >> i) & 1u) ++hits[size_t(y + kQuadDy[i]) * w + x + kQuadDx[i]];
        });
    }
    int at(int x, int y) const { return hits[size_t(y) * w + x]; }
};

}  // namespace

TEST_CASE("a jittered grid of triangles covers every pixel exactly once", "[raster][coverage]") {
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> jitter(-2.4f, 2.4f);
        const int n = 8, cell = 7, size = 64;
        // Grid points beyond the target so the whole target is inside the mesh.
        std::vector<glm::vec2> grid;
        for (int j = 0; j <= n + 1; ++j)
            for (int i = 0; i <= n + 1; ++i) {
                bool border = i == 0 || j == 0 || i == n + 1 || j == n + 1;
                glm::vec2 p(float(i * cell) - 4.0f, float(j * cell) - 4.0f);
                if (!border) p += glm::vec2(jitter(rng), jitter(rng));
                // Some vertices exactly on pixel centres and pixel edges.
                if ((i + j) % 5 == 0) p = glm::floor(p) + glm::vec2(0.5f);
                if ((i + j) % 7 == 0) p = glm::floor(p);
                grid.push_back(p);
            }
        HitCounter counter(size, size);
        auto at = [&](int i, int j) { return grid[size_t(j) * (n + 2) + i]; };
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                // Alternate the diagonal and the winding to exercise both orientations.
                if ((i + j) % 2) {
                    counter.draw(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                    counter.draw(at(i, j), at(i, j + 1), at(i + 1, j + 1));  // clockwise
                } else {
                    counter.draw(at(i, j), at(i + 1, j), at(i, j + 1));
                    counter.draw(at(i + 1, j + 1), at(i, j + 1), at(i + 1, j));
                }
            }
        const int inside = n * cell - 8;  // the mesh's interior covers [0, inside)^2 for sure
        for (int y = 0; y < inside; ++y)
            for (int x = 0; x < inside; ++x) {
                INFO("seed " << seed << " pixel " << x << "," << y);
                REQUIRE(counter.at(x, y) == 1);
            }
    }
}

TEST_CASE("a fan around a shared centre covers the disc exactly once", "[raster][coverage]") {
    HitCounter counter(40, 40);
    glm::vec2 centre(20.0f, 20.0f);  // on a pixel corner: four pixel centres are equidistant
    const int spokes = 16;
    for (int i = 0; i < spokes; ++i) {
        float a0 = float(i) / spokes * 6.2831853f, a1 = float(i + 1) / spokes * 6.2831853f;
        counter.draw(centre, centre + 18.0f * glm::vec2(std::cos(a0), std::sin(a0)),
                     centre + 18.0f * glm::vec2(std::cos(a1), std::sin(a1)));
    }
    for (int y = 8; y < 32; ++y)
        for (int x = 8; x < 32; ++x) {
            INFO("pixel " << x << "," << y);
            REQUIRE(counter.at(x, y) == 1);
        }
}

TEST_CASE("pixel centres and the top-left rule on an axis-aligned square", "[raster][coverage]") {
    HitCounter counter(8, 8);
    // The square [1,5]^2 split along its diagonal: exactly pixels 1..4 in x and y.
    counter.draw({1, 1}, {5, 1}, {5, 5});
    counter.draw({1, 1}, {5, 5}, {1, 5});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            INFO("pixel " << x << "," << y);
            REQUIRE(counter.at(x, y) == ((x >= 1 && x <= 4 && y >= 1 && y <= 4) ? 1 : 0));
        }
    // A triangle whose edges pass exactly through pixel centres: the left
    // edge (x = 0.5) is inside, the horizontal bottom edge (y = 0.5) is not
    // (its interior is above it), the hypotenuse walks up-left (not inside).
    HitCounter tri(8, 8);
    tri.draw({0.5f, 0.5f}, {4.5f, 0.5f}, {0.5f, 4.5f});
    std::vector<std::pair<int, int>> expected;
    for (int y = 1; y <= 3; ++y)
        for (int x = 0; x + y <= 3; ++x) expected.push_back({x, y});
    int total = 0;
    for (int i = 0; i < 64; ++i) total += tri.hits[i];
    CHECK(total == int(expected.size()));
    for (auto [x, y] : expected) CHECK(tri.at(x, y) == 1);
}

TEST_CASE("degenerate and off-screen triangles produce nothing", "[raster][coverage]") {
    Rect scissor{0, 0, 16, 16};
    CHECK_FALSE(setup_triangle({glm::vec2(1, 1), glm::vec2(5, 5), glm::vec2(9, 9)}, scissor));
    CHECK_FALSE(setup_triangle({glm::vec2(20, 1), glm::vec2(30, 1), glm::vec2(25, 9)}, scissor));
    CHECK_FALSE(setup_triangle({glm::vec2(NAN, 1), glm::vec2(30, 1), glm::vec2(25, 9)}, scissor));
    // A thin sliver between pixel centres covers nothing but must not crash.
    auto sliver = setup_triangle({glm::vec2(0.6f, 0.6f), glm::vec2(10.4f, 0.6f), glm::vec2(0.6f, 0.61f)}, scissor);
    int hits = 0;
    if (sliver) for_each_quad(*sliver, scissor, [&](int, int, unsigned) { ++hits; });
    CHECK(hits == 0);
}

TEST_CASE("plane equations give the screen-space weights and depth at pixel centres", "[raster][coverage]") {
    Rect scissor{0, 0, 16, 16};
    FsPrimitive prim;
    const glm::vec2 win[3] = {glm::vec2(0.5f, 0.5f), glm::vec2(8.5f, 0.5f), glm::vec2(0.5f, 8.5f)};
    const float z[3] = {0.25f, 0.75f, 0.5f};
    for (int i = 0; i < 3; ++i) prim.v[size_t(i)].win = win[i], prim.v[size_t(i)].z = z[i];
    auto t = setup_triangle({win[0], win[1], win[2]}, scissor);
    REQUIRE(t);
    set_triangle_planes(prim, *t);
    auto at = [&](const Plane& p, int x, int y) { return p.c + p.a * float(x - prim.ox) + p.b * float(y - prim.oy); };
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            float l[3] = {at(prim.weight[0], x, y), at(prim.weight[1], x, y), at(prim.weight[2], x, y)};
            CHECK(l[0] + l[1] + l[2] == Approx(1.0));
            CHECK(l[1] == Approx(x / 8.0).margin(1e-6));
            CHECK(l[2] == Approx(y / 8.0).margin(1e-6));
            CHECK(at(prim.z, x, y) == Approx(0.25 + 0.5 * x / 8.0 + 0.25 * y / 8.0));
        }
}

// A small triangle's weight planes (set_triangle_planes with `snapped`)
// against the exact barycentric weights with respect to `expected`'s
// positions, at the pixel centres it covers.
static void check_weight_planes(bool snapped, const std::function<glm::dvec2(glm::vec2)>& expected) {
    Rect scissor{0, 0, 16, 16};
    FsPrimitive prim;
    const glm::vec2 win[3] = {glm::vec2(0.5013f, 0.4991f), glm::vec2(4.5017f, 0.5021f), glm::vec2(0.4987f, 4.4981f)};
    for (int i = 0; i < 3; ++i) prim.v[size_t(i)].win = win[i];
    auto t = setup_triangle({win[0], win[1], win[2]}, scissor);
    REQUIRE(t);
    set_triangle_planes(prim, *t, snapped);
    auto at = [&](const Plane& p, int x, int y) { return p.c + p.a * float(x - prim.ox) + p.b * float(y - prim.oy); };
    const glm::dvec2 pos[3] = {expected(win[0]), expected(win[1]), expected(win[2])};
    auto exact = [&](int i, double px, double py) {
        const glm::dvec2 a = pos[i], b = pos[(i + 1) % 3], c = pos[(i + 2) % 3];
        auto cross = [](glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; };
        return cross(b - glm::dvec2(px, py), c - glm::dvec2(px, py)) / cross(b - a, c - a);
    };
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4 - y; ++x)
            for (int i = 0; i < 3; ++i)
                CHECK(at(prim.weight[size_t(i)], x, y) == Approx(exact(i, x + 0.5, y + 0.5)).margin(1e-6));
}

// Coverage snaps the vertices to 1/256 pixel, but the attributes follow the
// triangle the vertex stage computed, as llvmpipe's: from the snapped
// positions a small triangle's weights were off by the snap over its size
// (here up to 5e-4; a texture coordinate 5e-5 off on the era programs).
TEST_CASE("plane equations weigh the unsnapped vertex positions", "[raster][coverage]") {
    check_weight_planes(false, [](glm::vec2 w) { return glm::dvec2(w); });
}

// Fast's planes (snapped = true) weigh the vertices as snapped to the
// subpixel grid, the triangle the coverage test draws, as NVIDIA's driver
// interpolates (docs/precision.md, "The GPU's interpolation").
TEST_CASE("snapped plane equations weigh the snapped vertex positions", "[raster][coverage]") {
    check_weight_planes(true, [](glm::vec2 w) {
        return glm::dvec2(double(snap(w.x)), double(snap(w.y))) / double(kSubpixelOne);
    });
}

TEST_CASE("8x8 blocks inside or outside a triangle cover what the per-pixel test covers", "[raster][coverage]") {
    std::mt19937 rng(17);
    // Near vertices give edge values of 32 bits (coverage_mask's 4-wide
    // path); two far ones give values that need 64 bits, with the edges from
    // the near one still crossing the window.
    const float reach = GENERATE(140.0f, 3.0e5f);
    std::uniform_real_distribution<float> near(-20.0f, 140.0f), far(-reach, reach);
    const Rect scissor{3, 5, 117, 101};  // odd edges: blocks cut by the scissor
    for (int n = 0; n < 200; ++n) {
        auto t = setup_triangle({glm::vec2(near(rng), near(rng)), glm::vec2(far(rng), far(rng)),
                                 glm::vec2(far(rng), far(rng))},
                                scissor);
        if (!t) continue;
        std::vector<int> hits(size_t(128 * 128), 0);
        for_each_quad(*t, scissor, [&](int x, int y, unsigned mask) {
            for (int i = 0; i < 4; ++i)
                if ((mask >> i) & 1u) ++hits[size_t(y + kQuadDy[i]) * 128 + size_t(x + kQuadDx[i])];
        });
        int wrong = 0;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                bool inside = x >= scissor.x0 && x < scissor.x1 && y >= scissor.y0 && y < scissor.y1 &&
                              covers(*t, edge_values(*t, x, y));
                wrong += hits[size_t(y) * 128 + size_t(x)] != (inside ? 1 : 0);
            }
        INFO("triangle " << n);
        CHECK(wrong == 0);
    }
}

TEST_CASE("covered_blocks finds the same blocks with AVX-512 as without", "[raster][coverage]") {
    if (!glslrun::rt::cpu_has_avx512()) return;
    std::mt19937 rng(29);
    const float reach = GENERATE(40.0f, 140.0f, 3.0e5f);
    std::uniform_real_distribution<float> near(-20.0f, 140.0f), far(-reach, reach);
    std::uniform_int_distribution<int> edge(0, 60);
    for (int n = 0; n < 2000; ++n) {
        auto t = setup_triangle({glm::vec2(near(rng), near(rng)), glm::vec2(far(rng), far(rng)),
                                 glm::vec2(far(rng), far(rng))},
                                Rect{0, 0, 128, 128});
        if (!t) continue;
        // Rectangles with odd and even edges, as a tile's clip cuts the bounds.
        const Rect clip{edge(rng), edge(rng), 128 - edge(rng), 128 - edge(rng)};
        Rect r{std::max(t->bbox.x0, clip.x0), std::max(t->bbox.y0, clip.y0), std::min(t->bbox.x1, clip.x1),
               std::min(t->bbox.y1, clip.y1)};
        if (r.x0 >= r.x1 || r.y0 >= r.y1) continue;
        std::vector<CoveredBlock> wide(blocks_spanned(r)), narrow(blocks_spanned(r));
        const size_t w = covered_blocks(*t, r, wide.data(), true), m = covered_blocks(*t, r, narrow.data(), false);
        INFO("triangle " << n);
        REQUIRE(w == m);
        for (size_t i = 0; i < w; ++i) {
            CHECK(wide[i].x == narrow[i].x);
            CHECK(wide[i].y == narrow[i].y);
            CHECK(wide[i].pixels == narrow[i].pixels);
        }
    }
}

TEST_CASE("small triangles' coverage visits the quads for_each_quad visits, in its order", "[raster][coverage]") {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> corner(0.0f, 40.0f), offset(-4.5f, 4.5f);
    std::uniform_int_distribution<int> edge(0, 44);
    using Visits = std::vector<std::array<int, 3>>;
    int small = 0, empty = 0, nonempty = 0;
    for (int n = 0; n < 4000; ++n) {
        glm::vec2 a(corner(rng), corner(rng));
        glm::vec2 b = a + glm::vec2(offset(rng), offset(rng)), c = a + glm::vec2(offset(rng), offset(rng));
        const Rect scissor{edge(rng) / 4, edge(rng) / 4, 48 - edge(rng) / 4, 48 - edge(rng) / 4};
        auto t = setup_triangle({a, b, c}, scissor);
        if (!t) continue;
        auto cover = small_coverage(*t);
        if (!cover) continue;
        ++small;
        // Clip rectangles with odd and even edges, inside and across the square.
        const Rect clip{edge(rng), edge(rng), edge(rng) + 2, edge(rng) + 2};
        for (const Rect& r : {scissor, clip}) {
            Visits walk, direct;
            for_each_quad(*t, r, [&](int x, int y, unsigned m) { walk.push_back({x, y, int(m)}); });
            for_each_small_quad(*cover, r, [&](int x, int y, unsigned m) { direct.push_back({x, y, int(m)}); });
            INFO("triangle " << n);
            REQUIRE(walk == direct);
        }
        Visits all;
        for_each_quad(*t, scissor, [&](int x, int y, unsigned m) { all.push_back({x, y, int(m)}); });
        CHECK((cover->mask == 0) == all.empty());
        ++(all.empty() ? empty : nonempty);
    }
    // The cases the test is about occurred: small triangles with and without pixels.
    CHECK(small > 1000);
    CHECK(empty > 50);
    CHECK(nonempty > 500);
}
