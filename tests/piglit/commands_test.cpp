// [test] command lines: probes, uniforms, draws, state.
#include <catch2/catch.hpp>

#include "tests/piglit/command_helpers.h"

using namespace glslrun::piglit;

TEST_CASE("probe syntax", "[piglit][commands]") {
    Probe p = cmd<Probe>("probe rgb 25 30 0.0 1.0 0.5");
    CHECK(p.region == Probe::Region::Pixel);
    CHECK_FALSE(p.rgba);
    CHECK_FALSE(p.relative);
    CHECK(p.rect[0] == 25);
    CHECK(p.rect[1] == 30);
    CHECK(p.color == std::array<float, 4>{0, 1, 0.5f, 0});

    p = cmd<Probe>("probe rgba 1 2 0.1 0.2 0.3 0.4");
    CHECK(p.rgba);
    CHECK(p.color == std::array<float, 4>{0.1f, 0.2f, 0.3f, 0.4f});

    p = cmd<Probe>("probe rect rgba (10, 20, 30, 40) (1.0, 0.0, 0.0, 1.0)");
    CHECK(p.region == Probe::Region::Rect);
    CHECK(p.rect == std::array<float, 4>{10, 20, 30, 40});
    CHECK(p.color == std::array<float, 4>{1, 0, 0, 1});

    p = cmd<Probe>("probe rect rgb (1,2,3,4)(0.5,0.25,0.125)");
    CHECK(p.region == Probe::Region::Rect);
    CHECK_FALSE(p.rgba);
    CHECK(p.color == std::array<float, 4>{0.5f, 0.25f, 0.125f, 0});

    p = cmd<Probe>("relative probe rgba (0.25, 0.75) (0.0, 1.0, 0.0, 1.0)");
    CHECK(p.relative);
    CHECK(p.region == Probe::Region::Pixel);
    CHECK(p.rect[0] == 0.25f);
    CHECK(p.rect[1] == 0.75f);

    p = cmd<Probe>("relative probe rect rgb (0.0, 0.0, 0.5, 0.5) (0.0, 1.0, 0.0)");
    CHECK(p.relative);
    CHECK(p.region == Probe::Region::Rect);
    CHECK(p.rect == std::array<float, 4>{0, 0, 0.5f, 0.5f});

    p = cmd<Probe>("probe all rgba 0.0 1.0 0.0 1.0");
    CHECK(p.region == Probe::Region::All);
    CHECK(p.rgba);
    p = cmd<Probe>("probe all rgb 1 0 1");
    CHECK_FALSE(p.rgba);
    CHECK(p.color == std::array<float, 4>{1, 0, 1, 0});

    p = cmd<Probe>("probe warn all rgba 0.0 1.0 0.0 1.0");
    CHECK(p.warn);
    CHECK(p.region == Probe::Region::All);

    ProbeDepth d = cmd<ProbeDepth>("probe depth 10 0 0.5");
    CHECK(d.x == 10);
    CHECK(d.y == 0);
    CHECK(d.depth == 0.5f);

    CHECK(is_error("probe depth inf 0 0.5"));  // found by fuzz_piglit: inf converted to int
    CHECK(is_error("probe depth 0 -1e30 0.5"));
    CHECK(is_error("probe rgba 1 2 3"));
    CHECK(is_error("probe rect rgba (1, 2, 3) (1, 1, 1, 1)"));
    CHECK(is_error("probe rect rgba (1, 2, 3, 4) (1, 1, 1)"));
    p = cmd<Probe>("relative probe rgb (0.0, 0.0) (1.0, 0.0, 0.5, 1.0)");  // sscanf ignores the extra value
    CHECK(p.color == std::array<float, 4>{1, 0, 0.5f, 0});
    CHECK(is_error("relative probe rgb (0.5, 0.5 (1, 1, 1)"));
    CHECK(is_error("probe purple 1 2"));
}

TEST_CASE("uniform values", "[piglit][commands]") {
    SetUniform u = cmd<SetUniform>("uniform vec4 color 0.25 0.5 0.75 1.0");
    CHECK(u.type == "vec4");
    CHECK(u.name == "color");
    CHECK_FALSE(u.integer);
    CHECK(u.floats == std::vector<float>{0.25f, 0.5f, 0.75f, 1.0f});

    u = cmd<SetUniform>("uniform float c 1;");
    CHECK(u.floats == std::vector<float>{1});

    u = cmd<SetUniform>("uniform int i -7");
    CHECK(u.integer);
    CHECK(u.ints == std::vector<int32_t>{-7});
    u = cmd<SetUniform>("uniform ivec3 v[2] 1 0x10 -3");
    CHECK(u.name == "v[2]");
    CHECK(u.ints == std::vector<int32_t>{1, 16, -3});
    u = cmd<SetUniform>("uniform bvec2 b 1 0");
    CHECK(u.integer);
    CHECK(u.ints == std::vector<int32_t>{1, 0});
    u = cmd<SetUniform>("uniform bool s.f 1");
    CHECK(u.name == "s.f");

    // Matrices: piglit hands the values to glUniformMatrix* as written (column-major).
    u = cmd<SetUniform>("uniform mat2x3 m 1 2 3 4 5 6");
    CHECK(u.floats == std::vector<float>{1, 2, 3, 4, 5, 6});
    u = cmd<SetUniform>("uniform mat3x2 m 1 2 3 4 5 6 7");  // extra values are ignored
    CHECK(u.floats.size() == 6);
    u = cmd<SetUniform>("uniform mat4 m 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1");
    CHECK(u.floats.size() == 16);
    u = cmd<SetUniform>("uniform mat4x4 m[1] 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1");
    CHECK(u.floats.size() == 16);
    u = cmd<SetUniform>("uniform mat3 m 1 2 3 4 5 6 7 8 9");
    CHECK(u.floats.size() == 9);

    u = cmd<SetUniform>("uniform mat3x3 m 1 2 3");  // piglit pads short lists
    CHECK(u.floats == std::vector<float>{1, 2, 3, 0, 0, 0, 0, 0, 0});
    u = cmd<SetUniform>("uniform ivec4 v 5");
    CHECK(u.ints == std::vector<int32_t>{5, 0, 0, 0});
    CHECK(is_error("uniform vec4 v"));
    CHECK(is_error("uniform float v x"));
    CHECK(is_error("uniform vec2"));
    CHECK(is_error("uniform sampler2D s 0"));
    u = cmd<SetUniform>("uniform uvec2 u 1 0xffffffff");
    CHECK(u.integer);
    CHECK(u.ints == std::vector<int32_t>{1, -1});  // the bit pattern of 0xffffffff
    CHECK(cmd<SetUniform>("uniform uint use_discard 1").ints == std::vector<int32_t>{1});
    CHECK(std::holds_alternative<Unsupported>(std::get<CommandData>(parse_command("uniform double d 1"))));
}

TEST_CASE("draw commands", "[piglit][commands]") {
    DrawRect r = cmd<DrawRect>("draw rect -1 -1 2 2");
    CHECK_FALSE(r.ortho);
    CHECK(r.rect == std::array<float, 4>{-1, -1, 2, 2});
    r = cmd<DrawRect>("draw rect ortho 0 0 250 250");
    CHECK(r.ortho);
    CHECK(r.rect == std::array<float, 4>{0, 0, 250, 250});
    r = cmd<DrawRect>("draw rect tex -1 -1 2 2 0 0 1 1");
    CHECK(r.tex);
    CHECK(r.tex_rect == std::array<float, 4>{0, 0, 1, 1});
    DrawArrays a = cmd<DrawArrays>("draw arrays GL_TRIANGLE_FAN 2 4");
    CHECK(a.mode == "GL_TRIANGLE_FAN");
    CHECK(a.first == 2);
    CHECK(a.count == 4);
    CHECK(is_error("draw arrays GL_TRIANGLES -1 3"));
    CHECK(is_error("draw arrays GL_TRIANGLES 0 0"));
    CHECK(is_error("draw arrays GL_TRIANGLES"));
    CHECK(is_error("draw circle 1 2 3"));
}

TEST_CASE("state commands", "[piglit][commands]") {
    CHECK(cmd<ClearDepth>("clear depth 0.25").depth == 0.25f);
    CHECK_FALSE(cmd<Ortho>("ortho").lrbt.has_value());
    CHECK(cmd<Ortho>("ortho 0 10 0 20").lrbt.value() == std::array<float, 4>{0, 10, 0, 20});
    CHECK(cmd<Frustum>("frustum -1.0 1.0 -1.0 1.0 1.0 3.0").lrbtnf ==
          std::array<float, 6>{-1, 1, -1, 1, 1, 3});
    Enable e = cmd<Enable>("enable GL_CLIP_PLANE3");
    CHECK(e.on);
    CHECK(e.cap == "GL_CLIP_PLANE3");
    CHECK_FALSE(cmd<Enable>("disable GL_VERTEX_PROGRAM_TWO_SIDE").on);
    ClipPlane c = cmd<ClipPlane>("clip plane 2 0.0 1.0 0.0 -0.5");
    CHECK(c.index == 2);
    CHECK(c.plane == std::array<double, 4>{0, 1, 0, -0.5});
    CHECK(cmd<ShadeModel>("shade model flat").flat);
    CHECK_FALSE(cmd<ShadeModel>("shade model smooth").flat);
    CHECK(cmd<CurrentColor>("color 0.25 0.75 0.5 0.25").rgba == std::array<float, 4>{0.25f, 0.75f, 0.5f, 0.25f});
    Light l = cmd<Light>("light 1 GL_DIFFUSE float 0.3 0.2 0.1 0.4");
    CHECK(l.index == 1);
    CHECK(l.param == "GL_DIFFUSE");
    CHECK(l.values == std::vector<float>{0.3f, 0.2f, 0.1f, 0.4f});
    CHECK(cmd<LinkCheck>("link error").expect_success == false);
    CHECK(cmd<LinkCheck>("link success").expect_success == true);
    CHECK(cmd<Tolerance>("tolerance 0.1 0.1 0.1 0.1").tol[2] == 0.1f);
    cmd<Ignored>("hint GL_FRAGMENT_SHADER_DERIVATIVE_HINT GL_NICEST");
    cmd<Ignored>("   # a comment");
    cmd<Ignored>("");
    CHECK(cmd<Unsupported>("texture junk 2DArray 0 (8, 8, 2)").reason == "unsupported command \"texture junk\"");
    CHECK(is_error("shade model phong"));
    CHECK(is_error("light 9 GL_DIFFUSE float 1 1 1 1"));
    CHECK(is_error("clip plane 1 2"));
    CHECK(is_error("frustum 1 2 3"));
}

TEST_CASE("depthfunc takes glDepthFunc's eight names", "[piglit][commands]") {
    using glslrun::CompareFunc;
    CHECK(cmd<DepthFunc>("depthfunc GL_LESS").func == CompareFunc::Less);
    CHECK(cmd<DepthFunc>("depthfunc GL_GEQUAL").func == CompareFunc::Gequal);
    CHECK(cmd<DepthFunc>("depthfunc  GL_ALWAYS ").func == CompareFunc::Always);
    CHECK(cmd<DepthFunc>("depthfunc GL_NEVER").func == CompareFunc::Never);
    CHECK(is_error("depthfunc GL_LESSER"));
    CHECK(is_error("depthfunc"));
}
