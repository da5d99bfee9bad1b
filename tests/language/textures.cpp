// Texture lookups (GLSL 1.10 §8.7) through the whole pipeline: the frontend's
// lowering (projection, reference depth, bias, derivatives), the interpreter's
// `tex` kernel and the sampler units of GLState. The sampler's own arithmetic
// (filters, wraps, LOD rules) is covered in tests/runtime/sampling_test.cpp;
// here every texture is built so each lane's expected texel is known exactly:
// float texels, coordinates at texel centres, and mip levels of one colour each.
#include "harness.h"

#include <cmath>
#include <memory>

using namespace lang;
using glslrun::GLState;
using glslrun::Texture;
using glslrun::TextureFilter;
using glslrun::TextureFormat;
using glslrun::TextureImage;
using glslrun::TextureTarget;

namespace {

// A distinct, exactly representable value per texel.
glm::vec4 texel_value(int i, int j, int k) {
    return {float(i) / 8.0f, float(j) / 8.0f, float(k) / 4.0f + 0.125f, 1.0f - float(i + j + k) / 64.0f};
}

TextureImage image(int w, int h, int d) {
    TextureImage img{w, h, d, {}};
    for (int k = 0; k < d; ++k)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) img.texels.push_back(texel_value(i, j, k));
    return img;
}

TextureImage solid(int w, int h, glm::vec4 c) { return {w, h, 1, std::vector<glm::vec4>(size_t(w * h), c)}; }

std::shared_ptr<const Texture> make(TextureTarget target, std::vector<TextureImage> faces,
                                    TextureFormat format = TextureFormat::RGBA32F,
                                    TextureFilter min = TextureFilter::Nearest) {
    auto t = Texture::create(target, std::move(faces), format);
    REQUIRE(t.ok());
    t->sampler.min_filter = min;
    t->sampler.mag_filter = TextureFilter::Nearest;
    return std::make_shared<const Texture>(std::move(*t));
}

// Colour of mip level L in the mipmapped texture below.
glm::vec4 level_color(int level) { return {float(level) / 4.0f, 1.0f - float(level) / 8.0f, 0.5f, 1.0f}; }

// 16x16 with levels 16, 8, 4, 2, 1, each a solid colour.
std::shared_ptr<const Texture> mip_levels() {
    auto t = Texture::create(TextureTarget::Tex2D, {solid(16, 16, level_color(0))}, TextureFormat::RGBA32F);
    REQUIRE(t.ok());
    for (int level = 1, size = 8; size >= 1; ++level, size /= 2)
        REQUIRE(t->set_level(0, level, solid(size, size, level_color(level))).ok());
    t->sampler.min_filter = TextureFilter::NearestMipmapNearest;
    t->sampler.mag_filter = TextureFilter::Nearest;
    return std::make_shared<const Texture>(std::move(*t));
}

Outputs run_fs_with(const std::string& fs, const std::vector<glslrun::VertexAttrib>& inputs, const GLState& gl,
                    const std::vector<std::pair<std::string, int>>& units = {{"t", 0}}) {
    glslrun::Program p = compile_fs(fs, inputs);
    for (const auto& [name, unit] : units) {
        int32_t u = unit;
        REQUIRE(p.set_uniform(name, std::span<const int32_t>(&u, 1)).ok());
    }
    auto r = glslrun::run_fragments(p, inputs, kFrags, &gl);
    if (!r) FAIL(r.error().str());
    return Outputs(std::move(*r), kFrags);
}

// Texel centre (i + 0.5) / size for lane-dependent i.
float centre(uint32_t i, int size) { return (float(i % uint32_t(size)) + 0.5f) / float(size); }

}  // namespace

TEST_CASE("texture2D and texture2DProj sample the texel under the coordinate", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(0, make(TextureTarget::Tex2D, {image(4, 8, 1)})).ok());
    auto inputs = std::vector{make_attrib("c", 4, kFrags, [](uint32_t l, uint32_t comp) {
        const float q = (l % 3 == 0) ? 2.0f : (l % 3 == 1) ? 0.5f : 4.0f;  // powers of two: exact division
        return comp == 0 ? centre(l, 4) * q : comp == 1 ? centre(l / 4, 8) * q : comp == 2 ? q : q;
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler2D t;
        varying vec4 c;
        void main() {
            gl_FragData[0] = texture2D(t, c.xy / c.w);
            gl_FragData[1] = texture2DProj(t, c.xyz);
            gl_FragData[2] = texture2DProj(t, vec4(c.xy, 7.0, c.w));
        })",
                              inputs, gl);
    auto want = [](uint32_t l) { return texel_value(int(l % 4), int((l / 4) % 8), 0); };
    check_output(out, "gl_FragData[0]", 4, want);
    check_output(out, "gl_FragData[1]", 4, want);
    check_output(out, "gl_FragData[2]", 4, want);
}

TEST_CASE("texture1D, texture3D and their Proj forms", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(0, make(TextureTarget::Tex1D, {image(8, 1, 1)})).ok());
    REQUIRE(gl.bind_texture(1, make(TextureTarget::Tex3D, {image(2, 4, 2)})).ok());
    auto inputs = std::vector{make_attrib("c", 4, kFrags, [](uint32_t l, uint32_t comp) {
        return comp == 0 ? centre(l, 8) : comp == 1 ? centre(l / 2, 4) : comp == 2 ? centre(l / 3, 2) : 1.0f;
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler1D t;
        uniform sampler3D v;
        varying vec4 c;
        void main() {
            gl_FragData[0] = texture1D(t, c.x);
            gl_FragData[1] = texture1DProj(t, vec2(c.x * 2.0, 2.0));
            gl_FragData[2] = texture1DProj(t, vec4(c.x * 4.0, 9.0, 9.0, 4.0));
            gl_FragData[3] = texture3D(v, c.yyz);
            gl_FragData[4] = texture3DProj(v, vec4(c.yyz, 1.0) * 2.0);
        })",
                              inputs, gl, {{"t", 0}, {"v", 1}});
    check_output(out, "gl_FragData[0]", 4, [](uint32_t l) { return texel_value(int(l % 8), 0, 0); });
    check_output(out, "gl_FragData[1]", 4, [](uint32_t l) { return texel_value(int(l % 8), 0, 0); });
    check_output(out, "gl_FragData[2]", 4, [](uint32_t l) { return texel_value(int(l % 8), 0, 0); });
    // (s, t, r) = (c.y, c.y, c.z): s over 2 texels, t over 4.
    auto want3d = [](uint32_t l) {
        float s = centre(l / 2, 4), r = centre(l / 3, 2);
        return texel_value(int(std::floor(s * 2.0f)), int((l / 2) % 4), int(std::floor(r * 2.0f)));
    };
    check_output(out, "gl_FragData[3]", 4, want3d);
    check_output(out, "gl_FragData[4]", 4, want3d);
}

TEST_CASE("textureCube selects the face of the major axis", "[texture]") {
    const glm::vec4 face_color[6] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1},
                                     {1, 1, 0, 1}, {0, 1, 1, 1}, {1, 0, 1, 0.5f}};
    std::vector<TextureImage> faces;
    for (const glm::vec4& c : face_color) faces.push_back(solid(2, 2, c));
    GLState gl;
    REQUIRE(gl.bind_texture(2, make(TextureTarget::Cube, faces)).ok());
    // Lane l points mostly along face l % 6, with small lane-dependent minor components.
    auto dir = [](uint32_t l, uint32_t comp) {
        const uint32_t face = l % 6, axis = face / 2;
        const float sign = face % 2 ? -1.0f : 1.0f;
        if (comp == axis) return sign * (1.0f + float(l % 5));
        return 0.1f * float(int(l % 7) - 3) * float(comp + 1) / 3.0f;
    };
    auto inputs = std::vector{make_attrib("d", 3, kFrags, dir)};
    Outputs out = run_fs_with(R"(
        uniform samplerCube t;
        varying vec3 d;
        void main() { gl_FragColor = textureCube(t, d); })",
                              inputs, gl, {{"t", 2}});
    check_output(out, "gl_FragColor", 4, [&](uint32_t l) { return face_color[l % 6]; });
}

TEST_CASE("shadow1D, shadow2D and shadow2DProj compare the reference with the depth", "[texture]") {
    TextureImage depths{4, 2, 1, {}};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) depths.texels.push_back({0.125f + 0.25f * float(i) + 0.0625f * float(j), 0, 0, 1});
    auto t2 = Texture::create(TextureTarget::Tex2D, {depths}, TextureFormat::Depth);
    auto t1 = Texture::create(TextureTarget::Tex1D, {TextureImage{4, 1, 1, {depths.texels.begin(), depths.texels.begin() + 4}}},
                              TextureFormat::Depth);
    REQUIRE(t1.ok());
    REQUIRE(t2.ok());
    for (Texture* t : {&*t1, &*t2}) {
        t->sampler.min_filter = t->sampler.mag_filter = TextureFilter::Nearest;
        t->sampler.compare = true;
        t->sampler.compare_func = glslrun::CompareFunc::Lequal;
    }
    GLState gl;
    REQUIRE(gl.bind_texture(0, std::make_shared<const Texture>(std::move(*t2))).ok());
    REQUIRE(gl.bind_texture(1, std::make_shared<const Texture>(std::move(*t1))).ok());
    auto inputs = std::vector{make_attrib("c", 4, kFrags, [](uint32_t l, uint32_t comp) {
        return comp == 0 ? centre(l, 4) : comp == 1 ? centre(l / 4, 2) : comp == 2 ? 0.0625f * float(l % 16) : 1.0f;
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler2DShadow t;
        uniform sampler1DShadow u;
        varying vec4 c;
        void main() {
            gl_FragData[0] = shadow2D(t, c.xyz);
            gl_FragData[1] = shadow2DProj(t, c * 2.0);
            gl_FragData[2] = shadow1D(u, vec3(c.x, 5.0, c.z));
            gl_FragData[3] = shadow1DProj(u, vec4(c.x, 5.0, c.z, 1.0) * 4.0);
        })",
                              inputs, gl, {{"t", 0}, {"u", 1}});
    auto lit = [&](float ref, float depth) {
        float r = ref <= depth ? 1.0f : 0.0f;
        return glm::vec4(r, r, r, 1.0f);  // DEPTH_TEXTURE_MODE LUMINANCE
    };
    auto want2d = [&](uint32_t l) {
        return lit(0.0625f * float(l % 16), depths.texels[size_t(l % 4 + 4 * ((l / 4) % 2))].r);
    };
    auto want1d = [&](uint32_t l) { return lit(0.0625f * float(l % 16), depths.texels[l % 4].r); };
    check_output(out, "gl_FragData[0]", 4, want2d);
    check_output(out, "gl_FragData[1]", 4, want2d);
    check_output(out, "gl_FragData[2]", 4, want1d);
    check_output(out, "gl_FragData[3]", 4, want1d);
}

// Quad q scales the coordinates by 2^(q % 4), so its rho is 2^(q % 4) texels
// per pixel and its level of detail q % 4; the bias adds to it.
TEST_CASE("implicit level of detail from quad derivatives, with bias", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(0, mip_levels()).ok());
    auto inputs = std::vector{make_attrib("c", 2, kFrags, [](uint32_t l, uint32_t comp) {
        const float scale = float(1u << ((l / 4) % 4));
        const glm::vec2 p = frag_xy(l);
        return (p[int(comp)] + 0.5f) * scale / 16.0f;
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler2D t;
        varying vec2 c;
        void main() {
            gl_FragData[0] = texture2D(t, c);
            gl_FragData[1] = texture2D(t, c, 1.0);
            gl_FragData[2] = texture2D(t, c, -8.0);
            gl_FragData[3] = texture2DProj(t, vec3(c * 0.5, 0.5), 2.0);
        })",
                              inputs, gl);
    auto level = [](uint32_t l, int bias) { return level_color(std::clamp(int((l / 4) % 4) + bias, 0, 4)); };
    check_output(out, "gl_FragData[0]", 4, [&](uint32_t l) { return level(l, 0); });
    check_output(out, "gl_FragData[1]", 4, [&](uint32_t l) { return level(l, 1); });
    check_output(out, "gl_FragData[2]", 4, [&](uint32_t l) { return level(l, -8); });
    check_output(out, "gl_FragData[3]", 4, [&](uint32_t l) { return level(l, 2); });
}

TEST_CASE("vertex shaders sample level 0, or the level their Lod form names", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(1, mip_levels()).ok());
    glslrun::Program p = compile_vs(R"(
        uniform sampler2D t;
        attribute vec4 a;
        varying vec4 base, lod, proj;
        void main() {
            float level = mod(floor(abs(a.x) * 3.0), 6.0);
            base = texture2D(t, a.yz);
            lod = texture2DLod(t, a.yz, level);
            proj = texture2DProjLod(t, vec3(a.yz, 1.0) * 4.0, level);
            gl_Position = vec4(0.0);
        })");
    int32_t unit = 1;
    REQUIRE(p.set_uniform("t", std::span<const int32_t>(&unit, 1)).ok());
    auto r = glslrun::run_vertices(p, std_attribs(), kVerts, &gl);
    if (!r) FAIL(r.error().str());
    Outputs out(std::move(*r), kVerts);
    auto level = [](uint32_t l) { return std::min(int(std::fmod(std::floor(std::fabs(in_a(l).x) * 3.0f), 6.0f)), 4); };
    check_output(out, "base", 4, [](uint32_t) { return level_color(0); });
    check_output(out, "lod", 4, [&](uint32_t l) { return level_color(level(l)); });
    check_output(out, "proj", 4, [&](uint32_t l) { return level_color(level(l)); });
}

TEST_CASE("samplers pick their unit: uniforms, arrays, function parameters, nothing bound", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(0, make(TextureTarget::Tex2D, {solid(1, 1, {1, 0, 0, 1})})).ok());
    REQUIRE(gl.bind_texture(3, make(TextureTarget::Tex2D, {solid(1, 1, {0, 0.5f, 0, 1})})).ok());
    REQUIRE(gl.bind_texture(5, make(TextureTarget::Tex3D, {image(1, 1, 1)})).ok());  // wrong target for a sampler2D
    auto inputs = std::vector{make_attrib("c", 2, kFrags, [](uint32_t l, uint32_t comp) {
        return 0.03f * float(l) + 0.5f * float(comp);
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler2D t, arr[2], none, wrong;
        varying vec2 c;
        vec4 look(sampler2D s, vec2 p) { return texture2D(s, p) * 0.5; }
        void main() {
            gl_FragData[0] = texture2D(t, c);
            gl_FragData[1] = texture2D(arr[0], c) + texture2D(arr[1], c);
            gl_FragData[2] = look(arr[1], c);
            gl_FragData[3] = texture2D(none, c);
            gl_FragData[4] = texture2D(wrong, c);
        })",
                              inputs, gl, {{"t", 3}, {"arr[0]", 0}, {"arr[1]", 3}, {"none", 7}, {"wrong", 5}});
    glslrun::Program p = compile_fs("uniform sampler2D s; void main() { gl_FragColor = texture2D(s, vec2(0.5)); }", {});
    int32_t bad = 99;
    CHECK_FALSE(p.set_uniform("s", std::span<const int32_t>(&bad, 1)).ok());  // GL: INVALID_VALUE
    check_output(out, "gl_FragData[0]", 4, [](uint32_t) { return glm::vec4(0, 0.5f, 0, 1); });
    check_output(out, "gl_FragData[1]", 4, [](uint32_t) { return glm::vec4(1, 0.5f, 0, 2); });
    check_output(out, "gl_FragData[2]", 4, [](uint32_t) { return glm::vec4(0, 0.25f, 0, 0.5f); });
    check_output(out, "gl_FragData[3]", 4, [](uint32_t) { return glm::vec4(0, 0, 0, 1); });
    check_output(out, "gl_FragData[4]", 4, [](uint32_t) { return glm::vec4(0, 0, 0, 1); });
}

TEST_CASE("lookups under divergent control flow write only their lanes", "[texture]") {
    GLState gl;
    REQUIRE(gl.bind_texture(0, make(TextureTarget::Tex2D, {image(4, 8, 1)})).ok());
    auto inputs = std::vector{make_attrib("c", 2, kFrags, [](uint32_t l, uint32_t comp) {
        return comp == 0 ? centre(l, 4) : centre(l / 4, 8);
    })};
    Outputs out = run_fs_with(R"(
        uniform sampler2D t;
        varying vec2 c;
        void main() {
            vec4 r = vec4(-1.0);
            if (c.x > 0.5) r = texture2D(t, c);
            else if (c.y < 0.5) r = texture2DProj(t, vec3(c, 1.0));
            gl_FragColor = r;
        })",
                              inputs, gl);
    check_output(out, "gl_FragColor", 4, [](uint32_t l) {
        if (centre(l, 4) > 0.5f || centre(l / 4, 8) < 0.5f) return texel_value(int(l % 4), int((l / 4) % 8), 0);
        return glm::vec4(-1.0f);
    });
}
