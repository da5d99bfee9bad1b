// Control flow under divergence: every lane takes its own path.
#include "harness.h"

#include <algorithm>
#include <cmath>

using namespace lang;

TEST_CASE("if / else-if chains and nested ifs", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
void main() {
    float r;
    if (c.x < -1.0) r = 1.0;
    else if (c.x < 1.0) r = 2.0;
    else if (c.x == 1.0) r = 3.0;
    else r = 4.0;
    float s = 0.0;
    if (a.x > 0.0) {
        if (a.y > 0.0) { s = 10.0; } else { s = 20.0; if (a.z > 0.0) s += 1.0; }
    } else {
        if (c.z > 1.0) s = 30.0;
    }
    float t = a.w;
    if (t < 0.0) t = -t;    // if without else
    o = vec4(r, s, t, 0.0);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        float r = c.x < -1 ? 1.0f : c.x < 1 ? 2.0f : c.x == 1 ? 3.0f : 4.0f;
        float s = 0.0f;
        if (a.x > 0) s = a.y > 0 ? 10.0f : (a.z > 0 ? 21.0f : 20.0f);
        else if (c.z > 1) s = 30.0f;
        return glm::vec4(r, s, std::fabs(a.w), 0.0f);
    }, kExact);
}

TEST_CASE("for, while and do-while with lane-dependent trip counts", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
void main() {
    int n = int(c.x) + 3;            // 0..6 iterations
    float sum = 0.0;
    for (int i = 0; i < n; ++i) sum += float(i) + a.x;
    float x = abs(a.y) + 1.0;
    int halvings = 0;
    while (x > 0.3) { x *= 0.5; halvings++; }
    int m = int(c.z);                // 0..3, but do-while runs at least once
    int runs = 0;
    do { runs++; m--; } while (m > 0);
    o = vec4(sum, float(halvings), x, float(runs));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        int n = int(c.x) + 3;
        float sum = 0.0f;
        for (int i = 0; i < n; ++i) sum += float(i) + a.x;
        float x = std::fabs(a.y) + 1.0f;
        int halvings = 0;
        while (x > 0.3f) { x *= 0.5f; halvings++; }
        int runs = std::max(1, int(c.z));
        return glm::vec4(sum, float(halvings), x, float(runs));
    }, kTight);
}

TEST_CASE("break and continue in nested loops", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
void main() {
    int limit = int(c.z) + 2;       // 2..5
    float acc = 0.0;
    int inner_runs = 0;
    for (int i = 0; i < 6; ++i) {
        if (i == int(c.w) + 2) continue;          // skip one outer iteration per lane
        for (int j = 0; j < 6; ++j) {
            if (j > i) break;                      // inner break
            if (j == 1) continue;                  // inner continue
            inner_runs++;
            acc += float(i * 10 + j);
        }
        if (i >= limit) break;                     // outer break
    }
    int k = 0;
    float w = 0.0;
    while (true) {
        k++;
        if (float(k) > abs(a.x) * 2.0) break;
        if (k == 2) continue;
        w += float(k);
    }
    o = vec4(acc, float(inner_runs), float(k), w);
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        int limit = int(c.z) + 2;
        float acc = 0.0f;
        int inner_runs = 0;
        for (int i = 0; i < 6; ++i) {
            if (i == int(c.w) + 2) continue;
            for (int j = 0; j < 6; ++j) {
                if (j > i) break;
                if (j == 1) continue;
                inner_runs++;
                acc += float(i * 10 + j);
            }
            if (i >= limit) break;
        }
        int k = 0;
        float w = 0.0f;
        while (true) {
            k++;
            if (float(k) > std::fabs(a.x) * 2.0f) break;
            if (k == 2) continue;
            w += float(k);
        }
        return glm::vec4(acc, float(inner_runs), float(k), w);
    }, kExact);
}

TEST_CASE("return from inside loops in a function", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
int first_over(float start, float step, float limit) {
    float x = start;
    for (int i = 0; i < 100; ++i) {
        for (int j = 0; j < 2; ++j) {
            x += step;
            if (x > limit) return i * 2 + j;     // leaves both loops
        }
    }
    return -1;
}
float find(vec4 v, float key) {
    int i = 0;
    while (i < 4) {
        if (v[i] == key) return float(i);
        i++;
    }
    return 9.0;
}
void main() {
    o = vec4(float(first_over(a.x, 0.25, 1.0)), find(c, 1.0), find(c, -2.0),
             float(first_over(0.0, -1.0, 1.0)));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        auto first_over = [](float x, float step, float limit) {
            for (int i = 0; i < 100; ++i)
                for (int j = 0; j < 2; ++j) {
                    x += step;
                    if (x > limit) return i * 2 + j;
                }
            return -1;
        };
        auto find = [](glm::vec4 v, float key) {
            for (int i = 0; i < 4; ++i)
                if (v[i] == key) return float(i);
            return 9.0f;
        };
        glm::vec4 c = in_c(l);
        return glm::vec4(float(first_over(in_a(l).x, 0.25f, 1.0f)), find(c, 1.0f), find(c, -2.0f), -1.0f);
    }, kExact);
}

TEST_CASE("return in main skips the rest for some lanes", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a;
varying vec4 o;
void main() {
    o = vec4(1.0);
    gl_Position = vec4(0.0);
    if (a.x < 0.0) return;
    o = vec4(2.0, a.x, 0.0, 0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        float x = in_a(l).x;
        return x < 0 ? glm::vec4(1.0f) : glm::vec4(2.0f, x, 0.0f, 0.0f);
    }, kExact);
}

TEST_CASE("discard in a fragment shader", "[control][fragment]") {
    auto inputs = std::vector{make_attrib("v", 4, kFrags, [](uint32_t l, uint32_t c) {
        return in_a(l)[c];
    })};
    auto outs = eval_fs(R"(
varying vec4 v;
void main() {
    gl_FragColor = v;
    if (v.x * v.y < 0.0) discard;
    gl_FragColor = v * 2.0;
})", inputs);
    check_output(outs, "discarded", 1, [](uint32_t l) {
        return glm::vec4(b2f(in_a(l).x * in_a(l).y < 0.0f));
    }, kExact);
    // Only the fragments that survive have a defined colour.
    auto expected = [&](uint32_t l) {
        return in_a(l).x * in_a(l).y < 0.0f ? outs.vec("gl_FragColor", l) : in_a(l) * 2.0f;
    };
    check_output(outs, "gl_FragColor", 4, expected, kTight);
}

TEST_CASE("discard inside a loop and inside a function", "[control][fragment]") {
    auto inputs = std::vector{make_attrib("v", 4, kFrags, [](uint32_t l, uint32_t c) {
        return in_c(l)[c];
    })};
    auto outs = eval_fs(R"(
varying vec4 v;
void check(float x) { if (x > 3.5) discard; }
void main() {
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        sum += v[i];
        if (sum < -5.0) discard;
    }
    check(v.x + v.z);
    gl_FragColor = vec4(sum);
})", inputs);
    auto discarded = [](uint32_t l) {
        glm::vec4 v = in_c(l);
        float sum = 0.0f;
        for (int i = 0; i < 4; ++i) {
            sum += v[i];
            if (sum < -5.0f) return true;
        }
        return v.x + v.z > 3.5f;
    };
    check_output(outs, "discarded", 1, [&](uint32_t l) { return glm::vec4(b2f(discarded(l))); }, kExact);
    check_output(outs, "gl_FragColor", 4, [&](uint32_t l) {
        glm::vec4 v = in_c(l);
        return discarded(l) ? outs.vec("gl_FragColor", l) : glm::vec4(v.x + v.y + v.z + v.w);
    }, kExact);
    // The inputs really do give both outcomes, or this test proves nothing.
    int count = 0;
    for (uint32_t l = 0; l < kFrags; ++l) count += discarded(l);
    CHECK(count > 0);
    CHECK(count < int(kFrags));
}

TEST_CASE("a loop that never ends is an error, not a hang", "[control]") {
    auto program = compile_vs(R"(
attribute vec4 a;
varying vec4 o;
void main() {
    float x = a.x;
    while (x > -1000.0 || a.y > -1000.0) { x += 1.0; }   // never ends on any lane
    o = vec4(x);
    gl_Position = vec4(0.0);
})");
    program.exec.max_loop_iterations = 1000;
    auto result = glslrun::run_vertices(program, std_attribs(), kVerts);
    REQUIRE_FALSE(result.ok());
    INFO(result.error().str());
    CHECK_FALSE(result.error().diagnostics.empty());
}

TEST_CASE("a loop that ends on some lanes only is still an error", "[control]") {
    auto program = compile_vs(R"(
attribute vec4 a;
varying vec4 o;
void main() {
    float x = 0.0;
    for (;;) {
        if (a.x > 0.0) break;       // lanes with a.x <= 0 never leave
        x += 1.0;
    }
    o = vec4(x);
    gl_Position = vec4(0.0);
})");
    program.exec.max_loop_iterations = 500;
    auto result = glslrun::run_vertices(program, std_attribs(), kVerts);
    CHECK_FALSE(result.ok());
}

TEST_CASE("a long but finite loop under the cap runs to the end", "[control]") {
    auto program = compile_vs(R"(
attribute vec4 c;
varying vec4 o;
void main() {
    int n = 100 + int(c.z) * 50;     // up to 250 iterations
    float x = 0.0;
    for (int i = 0; i < n; ++i) x += 1.0;
    o = vec4(x);
    gl_Position = vec4(0.0);
})");
    program.exec.max_loop_iterations = 300;
    auto outs = run_vs(program, std_attribs());
    check_output(outs, "o", 1, [](uint32_t l) { return glm::vec4(100.0f + in_c(l).z * 50.0f); }, kExact);
}

TEST_CASE("scopes: shadowing in blocks and loops", "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 a, c;
varying vec4 o;
float x = 100.0;                 // global, shadowed below
void main() {
    float r = x;
    float x = a.x;               // shadows the global
    {
        float x = 2.0;           // shadows the local
        r += x;
    }
    float sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        float x = float(i);      // a fresh x each iteration
        sum += x;
    }
    int i = int(c.z);            // the loop's i is gone
    if (c.x > 0.0) { float x = -1.0; r += x; }
    o = vec4(r, x, sum, float(i));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), c = in_c(l);
        return glm::vec4(102.0f - (c.x > 0 ? 1.0f : 0.0f), a.x, 3.0f, c.z);
    }, kExact);
}

TEST_CASE("continue in do-while goes to the condition; side effects in loop conditions",
          "[control]") {
    auto outs = eval_vs(R"(
attribute vec4 c;
varying vec4 o;
int calls;
int next(inout int i) { calls++; i++; return i; }
void main() {
    int i = 0, odds = 0, n = int(c.z) + 3;    // 3..6
    do {
        i++;
        if (i == (i / 2) * 2) continue;       // skip the rest for even i
        odds--;
    } while (i < n);
    calls = 0;
    int j = int(c.w);
    int seen = 0;
    while (next(j) < 3) seen++;
    o = vec4(float(i), float(odds), float(seen), float(calls));
    gl_Position = vec4(0.0);
})");
    check_output(outs, "o", 4, [](uint32_t l) {
        int n = int(in_c(l).z) + 3, i = 0, odd = 0;
        do { i++; if (i % 2 == 0) continue; odd--; } while (i < n);
        int j = int(in_c(l).w), seen = 0, calls = 0;
        while ((++calls, ++j) < 3) seen++;
        return glm::vec4(float(i), float(odd), float(seen), float(calls));
    }, kExact);
}
