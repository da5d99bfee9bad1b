// The shader debugger (debug/debugger.h): golden traces of the lecture's spot
// programs, replays equal to the render bit for bit, the depth outcome of
// every fragment at a pixel, and --find-nan naming the line and the pixel.
// GLSLRUN_UPDATE_GOLDEN=1 rewrites tests/scene/traces/ instead of comparing.
#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "debug/debugger.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

using namespace glslrun;

namespace {

const std::string kRoot = GLSLRUN_SOURCE_DIR;

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Sources named relative to the repository, as the golden traces print them.
ShaderSource shader(const std::string& name) { return {name, read_text(kRoot + "/" + name)}; }

struct Traced {
    debug::PixelTrace trace;
    Framebuffer fb{1, 1, true};
};

// Paths relative to the repository.
Traced trace_files(const std::string& vertex, const ShaderSource& fragment, const std::string& scene_path, int x,
                   int y, Precision precision = Precision::Precise) {
    std::vector<ShaderSource> vs{shader(vertex)};
    std::vector<ShaderSource> fs{fragment};
    auto scene = scene::load_scene(kRoot + "/" + scene_path);
    REQUIRE(scene);
    auto prog = Program::compile(vs, fs);
    REQUIRE(prog);
    prog->exec.precision = precision;
    auto dbg = debug::compile_for_debugging(vs, fs, precision);
    REQUIRE(dbg);
    Traced t;
    t.fb = Framebuffer(scene->width, scene->height, true);  // floats: the values before quantization
    debug::TraceRequest request;
    request.pixel = {x, y};
    request.sources = {vs[0], fs[0]};
    auto r = debug::trace(*prog, *dbg, *scene, t.fb, request);
    REQUIRE(r);
    t.trace = std::move(*r);
    return t;
}

Traced trace_pixel(const std::string& program, const std::string& scene_name, int x, int y,
                   const ShaderSource* fragment_override = nullptr) {
    return trace_files("shaders/" + program + ".vert",
                       fragment_override ? *fragment_override : shader("shaders/" + program + ".frag"),
                       "scenes/" + scene_name, x, y);
}

void check_golden(const std::string& name, const std::string& actual) {
    std::string path = kRoot + "/tests/scene/traces/" + name;
    const char* update = std::getenv("GLSLRUN_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    INFO("expectation: " << path << " (GLSLRUN_UPDATE_GOLDEN=1 rewrites it)");
    CHECK(actual == read_text(path));
}

// The visible fragment's traced gl_FragColor is the framebuffer's pixel, bit for bit.
void check_matches_pixel(const Traced& t) {
    const debug::FragmentTrace* visible = nullptr;
    for (const auto& f : t.trace.fragments) {
        CHECK(f.matches_render);
        if (f.outcome == debug::FragmentTrace::Outcome::Written) visible = &f;
    }
    REQUIRE(visible);
    REQUIRE_FALSE(visible->trace.outputs.empty());
    const debug::NamedValue& color = visible->trace.outputs.front();
    REQUIRE(color.name == "gl_FragColor");
    glm::vec4 pixel = t.fb.pixel(t.trace.x, t.fb.height - 1 - t.trace.y);
    for (int c = 0; c < 4; ++c)
        CHECK(std::bit_cast<uint32_t>(float(color.value.c[size_t(c)])) == std::bit_cast<uint32_t>(pixel[c]));
}

}  // namespace

TEST_CASE("golden traces of the lecture's spot programs", "[debug]") {
    struct Case {
        const char* program;
        const char* scene;
        int x, y;
    };
    // 240,172: inside the cone, facing away from the light (docs/debugging.md);
    // 256,256: lit, with a hidden back face behind it; multi_light: a loop
    // over three lights calling a function; textured and cube_map: texture
    // lookups with their levels and texels.
    for (Case c : {Case{"spot_pix_oops", "spot.toml", 240, 172}, Case{"spot_pix_fixed", "spot.toml", 240, 172},
                   Case{"spot_pix_fixed", "spot.toml", 256, 256}, Case{"multi_light", "multi_light.toml", 230, 200},
                   Case{"textured_pix", "textured.toml", 256, 256}, Case{"cube_reflect", "cube_map.toml", 256, 256}}) {
        Traced t = trace_pixel(c.program, c.scene, c.x, c.y);
        check_golden(fmt::format("{}_{}_{}.txt", c.program, c.x, c.y), debug::format_text(t.trace));
        check_matches_pixel(t);
        // Tracing never changes the image: the traced render's floats are a plain render's.
        Framebuffer plain(t.fb.width, t.fb.height, true);
        auto prog = Program::compile({shader(std::string("shaders/") + c.program + ".vert")},
                                     {shader(std::string("shaders/") + c.program + ".frag")});
        auto scene = scene::load_scene(kRoot + "/scenes/" + c.scene);
        REQUIRE((prog && scene));
        REQUIRE(scene::render_scene(*prog, *scene, plain));
        CHECK(std::ranges::equal(plain.color_data<float>(), t.fb.color_data<float>()));
        CHECK(plain.depth == t.fb.depth);
    }
}

TEST_CASE("a pixel covered by several primitives lists each with its depth outcome", "[debug]") {
    Traced t = trace_pixel("spot_pix_fixed", "spot.toml", 256, 256);
    REQUIRE(t.trace.fragments.size() >= 2);
    int written = 0, hidden = 0;
    for (const auto& f : t.trace.fragments) {
        written += f.outcome == debug::FragmentTrace::Outcome::Written;
        hidden += f.outcome == debug::FragmentTrace::Outcome::DepthFailed;
    }
    CHECK(written >= 1);
    CHECK(hidden >= 1);
    // Three vertices of the visible primitive, each replayed like the render.
    REQUIRE(t.trace.vertices.size() == 3);
    for (const auto& v : t.trace.vertices) CHECK(v.matches_render);
    std::string json = debug::format_json(t.trace);
    CHECK(json.find("\"outcome\":\"depth_failed\"") != std::string::npos);
}

TEST_CASE("a discarding shader traces its discard; late depth outcomes", "[debug]") {
    ShaderSource fs{"discard.frag",
                    "varying vec3 normal, ecPos;\n"
                    "void main() {\n"
                    "    if (normal.z < 0.5)\n"
                    "        discard;\n"
                    "    gl_FragColor = vec4(normal, 1.0);\n"
                    "}\n"};
    Traced t = trace_pixel("spot_pix_fixed", "spot.toml", 240, 172, &fs);
    REQUIRE_FALSE(t.trace.fragments.empty());
    bool saw_discard = false;
    for (const auto& f : t.trace.fragments) {
        if (f.outcome == debug::FragmentTrace::Outcome::Discarded) {
            saw_discard = true;
            CHECK(f.trace.discarded);
        }
    }
    CHECK(saw_discard);
}

TEST_CASE("--find-nan names the line and the pixel of the first NaN", "[debug]") {
    // Window pixel (100, 70) divides by zero on line 4; in the image (top-left) that is 100, H-1-70.
    ShaderSource fs{"nan.frag",
                    "void main() {\n"
                    "    float a = gl_FragCoord.x - 100.5;\n"
                    "    a += (gl_FragCoord.y - 70.5) * 1000.0;\n"
                    "    float b = 1.0 / a;\n"
                    "    gl_FragColor = vec4(b, 0.0, 0.0, 1.0);\n"
                    "}\n"};
    ShaderSource vs{"nan.vert", "void main() { gl_Position = vec4(gl_Vertex.xy * 4.0, 0.0, 1.0); }\n"};
    auto scene = scene::load_scene(kRoot + "/scenes/quad.toml");
    REQUIRE(scene);
    auto prog = Program::compile({vs}, {fs});
    REQUIRE(prog);
    auto dbg = debug::compile_for_debugging({vs}, {fs}, Precision::Precise);
    REQUIRE(dbg);
    Framebuffer fb(scene->width, scene->height);
    auto report = debug::find_nan(*prog, *dbg, *scene, fb, true);
    REQUIRE(report);
    REQUIRE(report->nan);
    CHECK_FALSE(report->nan->vertex);
    CHECK(report->nan->event.where == "nan.frag:4");
    CHECK(report->nan->event.op == "fdiv");
    CHECK(report->nan->x == 100);
    CHECK(report->nan->y == scene->height - 1 - 70);
    REQUIRE(report->out_of_range);  // b is far outside [0,1] almost everywhere
    CHECK(debug::format_text(*report).find("nan.frag:4: fdiv(1, 0) = inf") != std::string::npos);
}

TEST_CASE("--find-nan looks at the vertices first, in draw order", "[debug]") {
    // Vertex 2 of the quad (x > 0, y > 0) takes log(-x) on line 3.
    ShaderSource vs{"nan.vert",
                    "void main() {\n"
                    "    float w = 1.0;\n"
                    "    if (gl_Vertex.x > 0.0 && gl_Vertex.y > 0.0) w = log(-gl_Vertex.x);\n"
                    "    gl_Position = vec4(gl_Vertex.xy, 0.0, w);\n"
                    "}\n"};
    ShaderSource fs{"nan.frag", "void main() { gl_FragColor = vec4(1.0); }\n"};
    auto scene = scene::load_scene(kRoot + "/scenes/quad.toml");
    REQUIRE(scene);
    auto prog = Program::compile({vs}, {fs});
    REQUIRE(prog);
    auto dbg = debug::compile_for_debugging({vs}, {fs}, Precision::Precise);
    REQUIRE(dbg);
    Framebuffer fb(scene->width, scene->height);
    auto report = debug::find_nan(*prog, *dbg, *scene, fb, false);
    REQUIRE(report);
    REQUIRE(report->nan);
    CHECK(report->nan->vertex);
    CHECK(report->nan->draw == 0);
    CHECK(report->nan->event.where == "nan.vert:3");
    CHECK(report->nan->event.op == "flog");
    CHECK_FALSE(report->out_of_range);  // not asked for
    // The quad's vertex with x > 0 and y > 0.
    auto trace = debug::trace(*prog, *dbg, *scene, fb, debug::TraceRequest{std::nullopt, report->nan->vertex_index, 0, {}, {}});
    REQUIRE(trace);
    REQUIRE(trace->vertices.size() == 1);
    CHECK(trace->vertices[0].trace.first_nan);
    CHECK(trace->vertices[0].matches_render);
}

// minimal.vert and a fragment shader that loops `iterations` times (line 3),
// compiled for rendering and for debugging.
struct LongLoop {
    explicit LongLoop(int iterations) {
        std::vector<ShaderSource> vs{shader("shaders/minimal.vert")};
        std::vector<ShaderSource> fs{{"long.frag", fmt::format("void main() {{\n"
                                                               "    float s = 0.5;\n"
                                                               "    for (int i = 0; i < {}; ++i) s = fract(s * 3.7 + 0.1);\n"
                                                               "    gl_FragColor = vec4(s);\n"
                                                               "}}\n",
                                                               iterations)}};
        auto compiled = Program::compile(vs, fs);
        auto debugging = debug::compile_for_debugging(vs, fs, Precision::Precise);
        REQUIRE(compiled);
        REQUIRE(debugging);
        program = std::move(*compiled);
        debug = std::move(*debugging);
    }
    std::optional<Program> program, debug;
};

// The replays run under the debugging program's limits (debug.exec), as the
// render runs under the program's: its instruction budget stops a long replay,
// which says why, and its cancel flag ends the trace and --find-nan with an
// error. The render keeps its own limits (here the defaults: it completes).
TEST_CASE("the traced replays stop at debug.exec's instruction budget and cancel flag", "[debug]") {
    auto scene = scene::load_scene(kRoot + "/scenes/spot.toml");
    REQUIRE(scene);
    scene->width = scene->height = 8;
    LongLoop programs(30000);
    auto& [prog, dbg] = programs;
    Framebuffer fb(8, 8, true);
    debug::TraceRequest request;
    request.pixel = {4, 4};

    SECTION("within the limits the replay completes") {
        auto r = debug::trace(*prog, *dbg, *scene, fb, request);
        REQUIRE(r);
        REQUIRE_FALSE(r->fragments.empty());
        for (const debug::FragmentTrace& f : r->fragments) {
            CHECK(f.matches_render);
            CHECK_FALSE(f.trace.truncated);
            CHECK(f.trace.stopped.empty());
        }
    }
    SECTION("the instruction budget stops the replay, which says why") {
        dbg->exec.max_instructions = 5000;
        auto r = debug::trace(*prog, *dbg, *scene, fb, request);
        REQUIRE(r);
        REQUIRE_FALSE(r->fragments.empty());
        for (const debug::FragmentTrace& f : r->fragments) {
            CHECK(f.trace.truncated);
            CHECK(f.trace.stopped == "the shader executed more than 5000 instructions in one batch (calls that "
                                     "multiply, or a loop too long)");
            CHECK_FALSE(f.matches_render);
        }
        CHECK_THAT(debug::format_text(*r), Catch::Contains("... (stopped: the shader executed more than 5000"));
        CHECK_THAT(debug::format_json(*r), Catch::Contains("\"stopped\":\"the shader executed more than 5000"));
        auto nan = debug::find_nan(*prog, *dbg, *scene, fb, false);
        REQUIRE_FALSE(nan);
        CHECK_THAT(nan.error().str(), Catch::Contains("long.frag: error: the shader executed more than 5000"));
    }
    SECTION("the cancel flag ends the trace and --find-nan") {
        std::atomic<bool> cancel{true};
        dbg->exec.cancel = &cancel;
        auto r = debug::trace(*prog, *dbg, *scene, fb, request);
        REQUIRE_FALSE(r);
        CHECK_THAT(r.error().str(), Catch::Contains("cancelled: the time limit ran out"));
        auto nan = debug::find_nan(*prog, *dbg, *scene, fb, false);
        REQUIRE_FALSE(nan);
        CHECK_THAT(nan.error().str(), Catch::Contains("cancelled: the time limit ran out"));
    }
}

// Issue #17: the trace keeps every fragment at the pixel, and each could keep
// kMaxSteps steps; 20 overlapping quads with a long loop took 900 MB. The
// trace as a whole keeps kMaxTraceSteps; the replays still run to the end.
TEST_CASE("a trace keeps at most kMaxTraceSteps steps over all its invocations", "[debug]") {
    std::string quads = "[output]\nsize = [8, 8]\n";
    for (int i = 0; i < 8; ++i) quads += "[[objects]]\nmesh = \"quad\"\n";
    auto scene = scene::parse_scene(quads, "quads.toml");
    REQUIRE(scene);
    LongLoop programs(100000);
    auto& [prog, dbg] = programs;
    Framebuffer fb(8, 8, true);
    debug::TraceRequest request;
    request.pixel = {4, 4};
    auto r = debug::trace(*prog, *dbg, *scene, fb, request);
    REQUIRE(r);
    REQUIRE(r->fragments.size() == 8);
    size_t steps = 0;
    for (const debug::FragmentTrace& f : r->fragments) {
        CHECK(f.matches_render);
        CHECK(f.trace.truncated);
        CHECK(f.trace.steps.size() <= debug::InvocationTrace::kMaxSteps);
        steps += f.trace.steps.size();
    }
    for (const debug::VertexTrace& v : r->vertices) steps += v.trace.steps.size();
    CHECK(steps == debug::InvocationTrace::kMaxTraceSteps);
    CHECK(r->fragments.back().trace.steps.empty());
    CHECK_THAT(debug::format_text(*r), Catch::Contains("at most 200000 steps per invocation and 1000000 per trace"));
}

TEST_CASE("each fragment at a pixel gets the test that stopped it, with the values compared", "[debug]") {
    // One object per test over pixel 16,16 (tests/scene/data/fragment_tests.toml).
    Traced t = trace_files("shaders/colors.vert", shader("tests/scene/data/fragment_tests.frag"),
                           "tests/scene/data/fragment_tests.toml", 16, 16);
    check_golden("fragment_tests_16_16.txt", debug::format_text(t.trace));
    using O = debug::FragmentTrace::Outcome;
    using R = debug::FragmentTests::Result;
    const auto& f = t.trace.fragments;
    REQUIRE(f.size() == 5);
    CHECK(t.trace.scissored == std::vector<uint32_t>{4});  // the scissored object makes no fragment there
    // The alpha test, not the depth test (which is off), stops the first.
    CHECK(f[0].outcome == O::AlphaFailed);
    CHECK(f[0].tests.alpha_test == R::Failed);
    CHECK(f[0].tests.depth_test == R::Off);
    CHECK(f[0].tests.alpha == 0.25f);  // a float framebuffer compares the floats
    CHECK(f[0].tests.alpha_ref == 0.5f);
    CHECK(f[0].tests.alpha_func == CompareFunc::Greater);
    CHECK(f[1].outcome == O::StencilFailed);
    CHECK(f[1].tests.stencil_ref == 1);
    CHECK(f[1].tests.stored_stencil == 0);
    CHECK(f[2].outcome == O::Written);
    CHECK(f[2].tests.stencil_test == R::Passed);
    CHECK(f[2].tests.depth_test == R::Passed);
    CHECK(f[2].tests.stored_depth == 1.0f);  // the cleared depth
    CHECK(f[3].outcome == O::DepthFailed);
    CHECK(f[3].tests.stored_depth == f[2].tests.z);  // the written fragment's depth
    CHECK(f[3].tests.z > f[3].tests.stored_depth);
    CHECK(f[4].outcome == O::Discarded);
    CHECK(f[4].tests.depth_test == R::Off);
    CHECK(f[4].trace.discarded);
    std::string json = debug::format_json(t.trace);
    CHECK(json.find("\"outcome\":\"alpha_failed\",\"tests\":{\"scissor\":{\"result\":\"off\"},"
                    "\"alpha\":{\"result\":\"failed\",\"func\":\"greater\",\"alpha\":0.25,\"reference\":0.5,\"bytes\":false}") !=
          std::string::npos);
    CHECK(json.find("\"scissored\":[4]") != std::string::npos);
    // The probed tests (lane by lane, with the stored values noted) leave the image and buffers as a plain render.
    auto scene = scene::load_scene(kRoot + "/tests/scene/data/fragment_tests.toml");
    auto prog = Program::compile({shader("shaders/colors.vert")}, {shader("tests/scene/data/fragment_tests.frag")});
    REQUIRE((scene && prog));
    Framebuffer plain(t.fb.width, t.fb.height, true);
    REQUIRE(scene::render_scene(*prog, *scene, plain));
    CHECK(std::ranges::equal(plain.color_data<float>(), t.fb.color_data<float>()));
    CHECK(plain.depth == t.fb.depth);
    CHECK(plain.stencil == t.fb.stencil);
}

TEST_CASE("the pixel history covers every pass's program, in draw order", "[debug]") {
    // multi_pass.toml: every pass names its own shaders; the command line's are unused.
    Traced t = trace_files("shaders/minimal.vert", shader("shaders/minimal.frag"), "scenes/multi_pass.toml", 128, 128);
    // The passes' shaders are named by their paths: relative to the repository in the expectation.
    std::string text = debug::format_text(t.trace);
    for (size_t at; (at = text.find(kRoot + "/")) != std::string::npos;) text.erase(at, kRoot.size() + 1);
    check_golden("multi_pass_128_128.txt", text);
    const auto& f = t.trace.fragments;
    REQUIRE(f.size() >= 3);
    std::vector<std::string> passes;
    for (size_t i = 0; i < f.size(); ++i) {
        CHECK(f[i].matches_render);
        if (i) CHECK(f[i - 1].draw <= f[i].draw);
        if (passes.empty() || passes.back() != f[i].pass) passes.push_back(f[i].pass);
    }
    CHECK(passes.front() == "ambient");
    CHECK(std::ranges::find(passes, "light 0") != passes.end());
    CHECK(f.front().program == kRoot + "/scenes/passes/ambient.vert + " + kRoot + "/scenes/passes/ambient.frag");
    // The visible fragment's vertices come from its pass's vertex shader.
    REQUIRE(t.trace.vertices.size() == 3);
    for (const auto& v : t.trace.vertices) CHECK(v.matches_render);
    // --find-nan replays the passes' programs too: none computes a NaN.
    auto scene = scene::load_scene(kRoot + "/scenes/multi_pass.toml");
    auto prog = Program::compile({shader("shaders/minimal.vert")}, {shader("shaders/minimal.frag")});
    auto dbg = debug::compile_for_debugging({shader("shaders/minimal.vert")}, {shader("shaders/minimal.frag")},
                                            Precision::Precise);
    REQUIRE((scene && prog && dbg));
    Framebuffer fb(scene->width, scene->height, false);
    auto report = debug::find_nan(*prog, *dbg, *scene, fb, true);
    REQUIRE(report);
    CHECK_FALSE(report->nan);
}

// The trace's texture lookups come from the sampler itself (rt::explain_lookup,
// an observer on its steps): the result it explains is the value the shader
// got, bit for bit, with the levels and texels it took; in Fast too (the GPU's
// filtering and its one level of detail per quad).
TEST_CASE("texture lookups in the trace: operands, lod, levels, texels and the sampler's result", "[debug]") {
    struct Case {
        const char *vertex, *fragment, *scene;
        int x, y;
    };
    int lookups = 0, cube = 0, shadow = 0;
    for (Precision precision : {Precision::Precise, Precision::Fast})
    for (Case c : {Case{"shaders/textured_pix.vert", "shaders/textured_pix.frag", "scenes/textured.toml", 256, 256},
                   Case{"shaders/cube_reflect.vert", "shaders/cube_reflect.frag", "scenes/cube_map.toml", 256, 256},
                   Case{"shaders/minimal.vert", "shaders/minimal.frag", "scenes/shadow_map.toml", 128, 100},
                   Case{"shaders/minimal.vert", "shaders/minimal.frag", "scenes/blur.toml", 64, 64}}) {
        INFO(c.scene << ", precision " << int(precision));
        Traced t = trace_files(c.vertex, shader(c.fragment), c.scene, c.x, c.y, precision);
        // blur.frag's `vec4 c = 6.0 * texture2D(...)` is a product kept in a variable, which
        // Fast contracts into the next `c +=`: the trace, keeping c, fuses it too (debug/debugger.cpp).
        for (const debug::FragmentTrace& f : t.trace.fragments) {
            CHECK(f.matches_render);
            size_t steps = 0;
            for (const debug::TraceStep& s : f.trace.steps) steps += s.kind == debug::TraceStep::Kind::Lookup;
            CHECK(steps == f.trace.lookups.size());
            for (const debug::TextureLookup& l : f.trace.lookups) {
                ++lookups;
                REQUIRE(l.details.complete);
                for (int k = 0; k < 4; ++k)
                    CHECK(std::bit_cast<uint32_t>(l.details.result[k]) == std::bit_cast<uint32_t>(l.result[size_t(k)]));
                REQUIRE_FALSE(l.details.levels.empty());
                CHECK_FALSE(l.details.texels.empty());
                CHECK(l.coord.size() == l.info.dims());
                cube += l.details.face >= 0;
                shadow += l.info.shadow;
                // One texel of one level, NEAREST, no depth comparison: the result is that texel.
                if (l.details.texels.size() == 1 && !l.info.shadow)
                    CHECK(l.details.texels[0].value == l.details.result);
                // LINEAR in 2D reads four texels of each level sampled (an array's layer is not filtered).
                for (const rt::LookupLevel& level : l.details.levels)
                    if (level.linear && l.info.grad_dims() == 2)
                        CHECK(std::ranges::count_if(l.details.texels, [&](const rt::LookupTexel& x) {
                                  return x.level == level.level;
                              }) == 4);
            }
        }
    }
    CHECK(lookups > 10);
    CHECK(cube > 0);
    CHECK(shadow > 0);
    Traced t = trace_pixel("textured_pix", "textured.toml", 256, 256);
    std::string json = debug::format_json(t.trace);
    CHECK_THAT(json, Catch::Contains("\"kind\":\"lookup\""));
    CHECK_THAT(json, Catch::Contains("\"lookup\":{\"unit\":0,\"samplers\":[\"tex\"],\"target\":\"2D\""));
    // Every target has its name: a rectangle's was read past the end of the names (garbage in the trace).
    Traced rect = trace_pixel("rect_post", "rectangle.toml", 128, 128);
    CHECK_THAT(debug::format_json(rect.trace), Catch::Contains("\"target\":\"rectangle\""));
    CHECK_THAT(debug::format_text(rect.trace), Catch::Contains(" rectangle"));
}

// The pixel history's framebuffer before and after each fragment, with two
// RGBA8 colour buffers: a plain write, blending, a colour mask and a logic
// op, one object each over pixel 16,16 (tests/scene/data/color_writes.toml).
TEST_CASE("the pixel history shows every colour buffer before and after blending, mask and logic op", "[debug]") {
    std::vector<ShaderSource> vs{shader("shaders/colors.vert")}, fs{shader("tests/scene/data/color_writes.frag")};
    auto scene = scene::load_scene(kRoot + "/tests/scene/data/color_writes.toml");
    auto prog = Program::compile(vs, fs);
    auto dbg = debug::compile_for_debugging(vs, fs, Precision::Precise);
    REQUIRE((scene && prog && dbg));
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    debug::TraceRequest request;
    request.pixel = {16, 16};
    request.sources = {vs[0], fs[0]};
    auto t = debug::trace(*prog, *dbg, *scene, fb, request);
    REQUIRE(t);
    check_golden("color_writes_16_16.txt", debug::format_text(*t));
    const auto& f = t->fragments;
    REQUIRE(f.size() == 4);
    using Rgba = std::array<float, 4>;
    CHECK(f[0].before.color == std::vector<Rgba>{{0, 0, 0, 255}, {0, 0, 0, 255}});  // the clear
    CHECK(f[0].after.color == std::vector<Rgba>{{204, 51, 102, 255}, {255, 102, 51, 204}});
    // src_alpha, one_minus_src_alpha in 8-bit steps; buffer 1's source alpha is 0: unchanged.
    CHECK(f[1].writes.blend);
    CHECK(f[1].after.color == std::vector<Rgba>{{102, 153, 51, 191}, {255, 102, 51, 204}});
    // Only red and alpha written.
    CHECK(f[2].writes.mask == std::array<bool, 4>{true, false, false, true});
    CHECK(f[2].after.color == std::vector<Rgba>{{0, 153, 51, 64}, {64, 102, 51, 0}});
    // xor with 255 inverts the bytes.
    CHECK(f[3].after.color == std::vector<Rgba>{{255, 102, 204, 191}, {191, 153, 204, 255}});
    for (size_t i = 0; i < f.size(); ++i) {
        CHECK(f[i].writes.buffers == std::vector<int>{0, 1});
        if (i) CHECK(f[i].before.color == f[i - 1].after.color);
    }
    // The last fragment's after is the image.
    const size_t at = size_t(scene->height - 1 - 16) * size_t(scene->width) + 16;
    for (int b = 0; b < 2; ++b)
        for (size_t k = 0; k < 4; ++k) CHECK(f[3].after.color[size_t(b)][k] == float(fb.color_data<uint8_t>(b)[at * 4 + k]));
    std::string json = debug::format_json(*t);
    CHECK_THAT(json, Catch::Contains("\"before\":{\"format\":\"rgba8\",\"color\":[[0,0,0,255],[0,0,0,255]],\"depth\":1,"
                                     "\"stencil\":0},\"writes\":{\"buffers\":[0,1],\"blend\":null,\"logic_op\":null,"
                                     "\"mask\":[true,true,true,true]}"));
    CHECK_THAT(json, Catch::Contains("\"logic_op\":\"xor\""));
}

// --target: the pixel history of a render target, of the passes that draw
// into it. The blur's vertical pass samples target 'half': the texels its
// lookup fetched are that target's pixels as its last fragment left them.
TEST_CASE("the pixel history of a render target gives the texels a later pass samples", "[debug]") {
    std::vector<ShaderSource> vs{shader("shaders/minimal.vert")}, fs{shader("shaders/minimal.frag")};
    auto scene = scene::load_scene(kRoot + "/scenes/blur.toml");
    auto prog = Program::compile(vs, fs);
    auto dbg = debug::compile_for_debugging(vs, fs, Precision::Precise);
    REQUIRE((scene && prog && dbg));
    Framebuffer fb(scene->width, scene->height, false, scene::color_buffers(*scene));
    debug::TraceRequest request;
    request.pixel = {64, 64};
    auto image = debug::trace(*prog, *dbg, *scene, fb, request);
    REQUIRE(image);
    REQUIRE(image->fragments.size() == 1);
    REQUIRE_FALSE(image->fragments[0].trace.lookups.empty());
    const debug::TextureLookup& lookup = image->fragments[0].trace.lookups[0];
    REQUIRE(lookup.samplers == std::vector<std::string>{"image"});
    REQUIRE(lookup.details.texels.size() == 4);
    for (const rt::LookupTexel& texel : lookup.details.texels) {
        request.target = "half";
        request.pixel = {texel.i, 127 - texel.j};  // texture rows go bottom up, image rows top down
        auto half = debug::trace(*prog, *dbg, *scene, fb, request);
        REQUIRE(half);
        REQUIRE_FALSE(half->fragments.empty());
        for (const debug::FragmentTrace& f : half->fragments) CHECK(f.pass == "horizontal");
        const debug::PixelValues& after = half->fragments.back().after;
        for (int k = 0; k < 4; ++k) CHECK(after.color[0][size_t(k)] / 255.0f == texel.value[k]);
        CHECK_THAT(debug::format_text(*half), Catch::Contains("fragment 0 at render target 'half' pixel "));
        CHECK_THAT(debug::format_json(*half), Catch::Contains("\"target\":\"half\""));
    }
    request.target = "nope";
    auto missing = debug::trace(*prog, *dbg, *scene, fb, request);
    REQUIRE_FALSE(missing);
    CHECK_THAT(missing.error().str(), Catch::Contains("the scene has no render target 'nope' (it has half, image)"));
    request.target = "half";
    request.pixel = {128, 0};
    auto outside = debug::trace(*prog, *dbg, *scene, fb, request);
    REQUIRE_FALSE(outside);
    CHECK_THAT(outside.error().str(), Catch::Contains("pixel 128,0 is outside the 128x128 render target 'half'"));
}
