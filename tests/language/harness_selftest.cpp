// The harness itself: a wrong expectation, a compile error or a missing
// output must fail a test ([!shouldfail] turns those failures into passes),
// and odd lane counts must run.
#include "harness.h"

using namespace lang;

namespace {
const char* const kDoubler = R"(
attribute vec4 a;
varying vec4 o;
void main() { o = a * 2.0; gl_Position = vec4(0.0); }
)";
}  // namespace

TEST_CASE("harness: a wrong expected value is caught, a right one is not", "[harness]") {
    auto outs = eval_vs(kDoubler);
    auto right = [](uint32_t l) { return in_a(l) * 2.0f; };
    auto wrong_last_lane = [](uint32_t l) {
        glm::vec4 r = in_a(l) * 2.0f;
        if (l == kVerts - 1) r.w += 0.5f;   // only the last lane of the partial batch
        return r;
    };
    CHECK(count_mismatches(outs, "o", 4, right, kTight) == 0);
    CHECK(count_mismatches(outs, "o", 4, wrong_last_lane, kTight) == 1);
    CHECK(count_mismatches(outs, "o", 4, wrong_last_lane, kExact) == 1);
    // a relative error of 1e-5 passes kLoose but not kTight
    auto slightly_off = [](uint32_t l) { return in_a(l) * 2.0f * (1.0f + 1e-5f); };
    CHECK(count_mismatches(outs, "o", 4, slightly_off, kLoose) == 0);
    CHECK(count_mismatches(outs, "o", 4, slightly_off, kTight) > 0);
}

TEST_CASE("harness: compile errors and missing outputs are visible", "[harness]") {
    auto bad = glslrun::Program::compile({{"t.vert", "void main() { gl_Position = undeclared; }\n"}},
                                         {{"t.frag", "void main() { gl_FragColor = vec4(0.0); }\n"}});
    CHECK_FALSE(bad.ok());
    auto outs = eval_vs(kDoubler);
    CHECK(outs.has("o"));
    CHECK_FALSE(outs.has("no_such_output"));
}

TEST_CASE("harness: the lane inputs differ from lane to lane", "[harness]") {
    for (uint32_t l = 1; l < kVerts; ++l) {
        CHECK(in_a(l) != in_a(l - 1));
        CHECK(in_b(l) != in_b(l - 1));
        CHECK(in_c(l) != in_c(l - 1));
        CHECK(glm::all(glm::greaterThan(in_b(l), glm::vec4(0.1f))));
    }
}

TEST_CASE("lane counts: 0, 1, one batch, one batch plus one, many batches", "[harness]") {
    auto program = compile_vs(kDoubler);
    for (uint32_t count : {1u, 15u, 16u, 17u, 64u, 100u}) {
        INFO("count " << count);
        auto outs = run_vs(program, std_attribs(count), count);
        check_output(outs, "o", 4, [](uint32_t l) { return in_a(l) * 2.0f; }, kTight);
    }
    auto empty = glslrun::run_vertices(program, std_attribs(0), 0);
    INFO((empty ? std::string() : empty.error().str()));
    CHECK(empty.ok());
}

TEST_CASE("missing attributes read GL's default (0,0,0,1)", "[harness]") {
    auto program = compile_vs(R"(
attribute vec4 a;
attribute vec2 two;
varying vec4 o;
void main() { o = vec4(two, 0.0, 0.0) + a; gl_Position = vec4(0.0); }
)");
    // `two` comes with 2 components; `a` with 3: its w must read 1.
    auto outs = run_vs(program,
                       {make_attrib("a", 3, kVerts, [](uint32_t l, uint32_t c) { return in_a(l)[c]; }),
                        make_attrib("two", 2, kVerts, [](uint32_t l, uint32_t c) { return in_b(l)[c]; })},
                       kVerts);
    check_output(outs, "o", 4, [](uint32_t l) {
        glm::vec4 a = in_a(l), b = in_b(l);
        return glm::vec4(a.x + b.x, a.y + b.y, a.z, 1.0f);
    }, kTight);
}

TEST_CASE("fragment counts that are not whole quads run or fail cleanly", "[harness][fragment]") {
    auto inputs = std::vector{make_attrib("v", 4, 6, [](uint32_t l, uint32_t c) { return in_b(l)[c]; })};
    auto program = compile_fs("varying vec4 v;\nvoid main() { gl_FragColor = v * 3.0; }\n", inputs);
    auto result = glslrun::run_fragments(program, inputs, 6);
    if (!result) {
        SUCCEED("rejected: " << result.error().str());
        return;
    }
    Outputs outs(std::move(result.value()), 6);
    check_output(outs, "gl_FragColor", 4, [](uint32_t l) { return in_b(l) * 3.0f; }, kTight);
}
