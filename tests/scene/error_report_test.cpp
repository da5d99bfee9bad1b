// The error report's measuring side (scene/error_report.h) on small
// scenes: coverage, the outputs it compares, its notes, its key lines.
// The statistics themselves: float_error_test.cpp.
#include <catch2/catch.hpp>

#include <map>

#include "tests/scene/key_lines.h"
#include "glslrun/scene/error_report.h"

using namespace glslrun;
using namespace glslrun::scene;

namespace {

// An 8x8 image, the quad scaled to the middle 4x4 pixels (identity camera).
constexpr const char* kQuadScene = R"(
[output]
size = [8, 8]
clear_color = [0.25, 0.5, 0.75, 1]
[state]
depth_test = true
[[objects]]
mesh = "quad"
transform = [ { scale = [0.5, 0.5, 1] } ]
)";

constexpr const char* kVertex = R"(
varying vec3 v;
void main() {
    v = gl_Vertex.xyz * 3.0 + vec3(0.1);
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
})";

Scene quad_scene(const char* text = kQuadScene) {
    auto s = parse_scene(text, "quad.toml");
    INFO((s ? std::string() : s.error().str()));
    REQUIRE(s);
    return std::move(*s);
}

ErrorReport measure(const char* fragment, Precision mode, const Scene& scene) {
    ErrorReportOptions options;
    options.mode = mode;
    auto r = measure_error({{"t.vert", kVertex}}, {{"t.frag", fragment}}, scene, options);
    INFO((r ? std::string() : r.error().str()));
    REQUIRE(r);
    return std::move(*r);
}


}  // namespace

TEST_CASE("error report: reference against itself is exact; coverage is the quad's", "[scene][error]") {
    Scene scene = quad_scene();
    ErrorReport r = measure("varying vec3 v; void main() { gl_FragColor = vec4(sin(v), 1.0) * gl_Color; }",
                            Precision::Reference, scene);
    REQUIRE(r.outputs.size() == 2);
    CHECK(r.outputs[0].name == "gl_FragColor");
    CHECK(r.outputs[1].name == "depth");
    for (const ImageError& e : r.outputs) {
        INFO(e.name);
        CHECK(e.covered_both == 16);
        CHECK(e.covered_one == 0);
        CHECK(e.total().max_ulp == 0);
        CHECK(e.total().compared == uint64_t(16 * e.channels));
    }
    CHECK(r.outputs[0].differing_8bit == 0);
    // The clear colour fills the rest of both images, as an RGBA8 buffer holds it.
    REQUIRE(r.reference_image.rgba.size() == 8 * 8 * 4);
    CHECK(r.reference_image.rgba == r.mode_image.rgba);
    const uint8_t* corner = r.reference_image.pixel(0, 0);
    CHECK(int(corner[0]) == 64);
    CHECK(int(corner[1]) == 128);
    CHECK(int(corner[2]) == 191);
    const uint8_t* middle = r.reference_image.pixel(3, 3);
    CHECK(int(middle[3]) == 255);
    // Every vertex output of the quad's 4 vertices.
    std::map<std::string, const VaryingError*> varyings;
    for (const VaryingError& v : r.varyings) varyings[v.name] = &v;
    REQUIRE(varyings.count("v"));
    REQUIRE(varyings.count("gl_Position"));
    CHECK(varyings["v"]->components == 3);
    CHECK(varyings["v"]->error.compared == 12);
    CHECK(varyings["v"]->error.max_ulp == 0);
    CHECK(r.notes.empty());
}

TEST_CASE("error report: blending reads the clear colour, not a marker", "[scene][error]") {
    std::string text = std::string(kQuadScene) + "state = { blend = true, blend_func = [\"src_alpha\", \"one_minus_src_alpha\"] }\n";
    Scene scene = quad_scene(text.c_str());
    ErrorReport r = measure("void main() { gl_FragColor = vec4(1.0, 0.0, 0.0, 0.5); }", Precision::Precise, scene);
    REQUIRE(r.outputs.size() == 2);
    CHECK(r.outputs[0].covered_both == 16);
    CHECK(r.outputs[0].covered_one == 0);
    CHECK(r.outputs[0].total().max_ulp == 0);
    // 0.5 * red + 0.5 * the clear colour (0.25, 0.5, 0.75, 1); alpha 0.5 * 0.5 + 0.5 * 1.
    const uint8_t* middle = r.reference_image.pixel(3, 3);
    CHECK(int(middle[0]) == 159);
    CHECK(int(middle[1]) == 64);
    CHECK(int(middle[2]) == 96);
    CHECK(int(middle[3]) == 191);
    CHECK(r.reference_image.rgba == r.mode_image.rgba);
    // Blending that keeps the clear colour (zero, one) leaves the pixel as unwritten.
    std::string kept = std::string(kQuadScene) + "state = { blend = true, blend_func = [\"zero\", \"one\"] }\n";
    ErrorReport none = measure("void main() { gl_FragColor = vec4(1.0); }", Precision::Precise, quad_scene(kept.c_str()));
    CHECK(none.outputs[0].covered_both == 0);
}

TEST_CASE("error report: gl_FragDepth, unstored outputs and depth-less scenes", "[scene][error]") {
    Scene scene = quad_scene();
    ErrorReport depth = measure("void main() { gl_FragColor = vec4(1.0); gl_FragDepth = 0.25; }",
                                Precision::Precise, scene);
    REQUIRE(depth.outputs.size() == 2);
    CHECK(depth.outputs[1].name == "gl_FragDepth");
    CHECK(depth.outputs[1].total().compared == 16);

    ErrorReport data = measure("void main() { gl_FragData[0] = vec4(1.0); gl_FragData[1] = vec4(0.5); }",
                               Precision::Precise, scene);
    CHECK(data.outputs[0].name == "gl_FragData[0]");
    REQUIRE(data.notes.size() == 1);
    CHECK_THAT(data.notes[0], Catch::Contains("gl_FragData[1]"));

    scene.gl.depth_test = false;
    ErrorReport flat = measure("void main() { gl_FragColor = vec4(1.0); gl_FragDepth = 0.5; }",
                               Precision::Precise, scene);
    REQUIRE(flat.outputs.size() == 1);
    REQUIRE(flat.notes.size() == 1);
    CHECK_THAT(flat.notes[0], Catch::Contains("depth test is off"));
}

TEST_CASE("error report: discarded fragments are not covered", "[scene][error]") {
    Scene scene = quad_scene();
    // The left half of the quad (2 of 4 columns) is discarded.
    ErrorReport r = measure("void main() { if (gl_FragCoord.x < 4.0) discard; gl_FragColor = vec4(1.0); }",
                            Precision::Precise, scene);
    CHECK(r.outputs[0].covered_both == 8);
}

TEST_CASE("error report: key lines, once each", "[scene][error]") {
    Scene scene = quad_scene();
    ErrorReport r = measure("void main() { gl_FragColor = vec4(0.5); }", Precision::Fast, scene);
    auto keys = scene_test::parse_key_lines(format_error_keys(r));
    CHECK(keys["mode"] == "fast");
    CHECK(keys["size"] == "8x8");
    CHECK(keys["frag.gl_FragColor.covered_both"] == "16");
    CHECK(keys.count("frag.gl_FragColor.r.max_ulp") == 1);
    CHECK(keys.count("frag.gl_FragColor.max_8bit") == 1);
    CHECK(keys.count("frag.depth.max_ulp") == 1);
    CHECK(keys.count("frag.depth.max_8bit") == 0);
    CHECK(keys.count("vertex.gl_Position.max_ulp") == 1);
    std::string table = format_error_table(r, {"d/reference.png"});
    CHECK_THAT(table, Catch::Contains("fast against reference"));
    CHECK_THAT(table, Catch::Contains("log2"));
}

TEST_CASE("error report: Fast's ablation finds the op class that causes the error", "[scene][error]") {
    Scene scene = quad_scene();
    REQUIRE(resize_scene(scene, 64, 64));  // 32x32 covered pixels, 1024 different sin arguments
    // Only sin runs of the ops Fast approximates (at a few ULP of error).
    ErrorReport r = measure("varying vec3 v; void main() { gl_FragColor = vec4(sin(v * 2.0) * 0.5, 1.0); }",
                            Precision::Fast, scene);
    REQUIRE(r.ablation.size() == 7);
    std::map<std::string, const AblationRow*> rows;
    for (const AblationRow& a : r.ablation) rows[a.ops] = &a;
    for (const char* name : {"none", "inversesqrt", "exp_log", "pow", "sin_cos", "fma", "all"}) {
        INFO(name);
        REQUIRE(rows.count(name) == 1);
        CHECK(rows[name]->color.compared == 32 * 32 * 4);
    }
    const AblationRow& none = *rows["none"];
    CHECK(rows["sin_cos"]->color.max_ulp >= none.color.max_ulp);
    CHECK(rows["sin_cos"]->color.sum_ulp > none.color.sum_ulp);
    // The classes the shader does not use change no bit: their rows are precise's.
    for (const char* name : {"inversesqrt", "exp_log", "pow", "fma"}) {
        INFO(name);
        CHECK(rows[name]->color.max_ulp == none.color.max_ulp);
        CHECK(rows[name]->color.sum_ulp == none.color.sum_ulp);
    }
    // "all" is the report's own Fast render.
    CHECK(rows["all"]->color.sum_ulp == r.outputs[0].total().sum_ulp);
    CHECK(rows["all"]->color.sum_ulp == rows["sin_cos"]->color.sum_ulp);
    auto keys = scene_test::parse_key_lines(format_error_keys(r));
    CHECK(keys.count("ablation.sin_cos.max_ulp") == 1);
    CHECK(keys.count("ablation.none.max_8bit") == 1);
    CHECK_THAT(format_error_table(r, {}), Catch::Contains("where fast's error comes from"));

    // Precise and Reference have no ablation.
    CHECK(measure("void main() { gl_FragColor = vec4(0.5); }", Precision::Precise, scene).ablation.empty());
}

TEST_CASE("error report: normalize's error is in the inversesqrt class", "[scene][error]") {
    Scene scene = quad_scene();
    REQUIRE(resize_scene(scene, 64, 64));
    // Fast computes normalize as v * rsqrt(dot(v, v)) (ir/sqrt_divisor.cpp).
    ErrorReport r = measure("varying vec3 v; void main() { gl_FragColor = vec4(normalize(v + 0.1) * 0.5 + 0.5, 1.0); }",
                            Precision::Fast, scene);
    std::map<std::string, const AblationRow*> rows;
    for (const AblationRow& a : r.ablation) rows[a.ops] = &a;
    REQUIRE(rows.size() == 7);
    const AblationRow& none = *rows["none"];
    CHECK(rows["inversesqrt"]->color.sum_ulp != none.color.sum_ulp);
    for (const char* name : {"exp_log", "pow", "sin_cos"}) {
        INFO(name);
        CHECK(rows[name]->color.sum_ulp == none.color.sum_ulp);
    }
    // dot(v, v) and the scale and bias are contracted multiply-adds: the fma
    // class (one rounding) moves the error too, and "all" is both.
    CHECK(rows["fma"]->color.sum_ulp != none.color.sum_ulp);
    CHECK(rows["all"]->color.sum_ulp != rows["inversesqrt"]->color.sum_ulp);
}
