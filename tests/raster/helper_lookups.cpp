// Helper lanes (a partial quad's uncovered pixels) skip their texture
// lookups where no derivative or branch reads one (ir::Shader::
// helper_lookups_matter, raster/fragments.cpp): the images must be those of
// draws that run every lookup. Many small triangles (many partial quads),
// trilinear mipmapping over a random texture, on both backends (the JIT
// warmed up, so its draws take the fused pipeline).
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <random>

#include "glslrun/glslrun.h"
#include "raster/fused/pipeline.h"
#include "runtime/program_state.h"

using namespace glslrun;

namespace {

const char* kVs = R"(
varying vec2 uv;
void main() { uv = gl_MultiTexCoord0.xy; gl_Position = gl_Vertex; }
)";
const char* kFs = R"(
uniform sampler2D t;
varying vec2 uv;
void main() { gl_FragColor = texture2D(t, uv) * vec4(1.0, 0.9, 0.8, 1.0) + vec4(dFdx(uv.x)); }
)";

std::shared_ptr<const Texture> random_texture() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    TextureImage image{16, 16, 1, {}};
    for (int i = 0; i < 16 * 16; ++i) image.texels.push_back({unit(rng), unit(rng), unit(rng), unit(rng)});
    auto texture = Texture::create(TextureTarget::Tex2D, {image});
    REQUIRE(texture.ok());
    texture->generate_mipmaps();
    texture->sampler.min_filter = TextureFilter::LinearMipmapLinear;
    texture->sampler.mag_filter = TextureFilter::Linear;
    return std::make_shared<Texture>(std::move(*texture));
}

// 600 triangles of a few pixels each over 96x64, their (s, t) spread so
// that the level of detail varies.
struct Geometry {
    VertexAttrib pos{"gl_Vertex", 4, {}};
    VertexAttrib uv{"gl_MultiTexCoord0", 4, {}};
    uint32_t count = 0;
    Geometry() {
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> centre(-1.0f, 1.0f), step(-0.08f, 0.08f), coord(-2.0f, 2.0f);
        for (int t = 0; t < 600; ++t) {
            const float cx = centre(rng), cy = centre(rng), s0 = coord(rng), t0 = coord(rng), scale = 1.0f + 6.0f * (t % 5);
            for (int v = 0; v < 3; ++v) {
                const float dx = step(rng), dy = step(rng);
                pos.data.insert(pos.data.end(), {cx + dx, cy + dy, 0.0f, 1.0f});
                uv.data.insert(uv.data.end(), {s0 + dx * scale, t0 + dy * scale, 0.0f, 1.0f});
                ++count;
            }
        }
    }
};

Framebuffer render(Program& p, const Geometry& g) {
    GLState gl;
    REQUIRE(gl.bind_texture(0, random_texture()).ok());
    Framebuffer fb(96, 64);
    fb.clear_color({0.1f, 0.2f, 0.3f, 1.0f});
    auto stats = draw(p, gl, fb, Primitive::Triangles, {g.pos, g.uv}, g.count);
    if (!stats) FAIL(stats.error().str());
    return fb;
}

}  // namespace

TEST_CASE("helper lanes skip their lookups only where no one reads them: the same images", "[raster][helper_lookups]") {
    const Geometry g;
    for (Backend backend : {Backend::Interp, Backend::Jit}) {
        INFO("backend " << int(backend));
        auto compiled = Program::compile({{"vs", kVs}}, {{"fs", kFs}});
        REQUIRE(compiled.ok());
        Program& p = *compiled;
        p.exec.backend = backend;
        REQUIRE(p.set_uniform("t", std::array{0}).ok());
        if (backend == Backend::Jit) {  // warmed up past raster::fused::kPipelineAfterFragments: the fused pipeline
            Framebuffer big(1024, 1024);
            VertexAttrib quad{"gl_Vertex", 4, {-1, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1, -1, -1, 0, 1, 1, 1, 0, 1, -1, 1, 0, 1}};
            VertexAttrib uv{"gl_MultiTexCoord0", 4, std::vector<float>(24, 0.5f)};
            REQUIRE(draw(p, GLState{}, big, Primitive::Triangles, {quad, uv}, 6).ok());
        }
        ir::Shader& fs = state_of(p).ir.fragment;
        REQUIRE_FALSE(fs.helper_lookups_matter);  // dFdx(uv.x) reads no lookup
        const Framebuffer skipping = render(p, g);
        fs.helper_lookups_matter = true;
        const Framebuffer all = render(p, g);
        fs.helper_lookups_matter = false;
        REQUIRE(skipping.color_data<uint8_t>().size() == all.color_data<uint8_t>().size());
        CHECK(std::memcmp(skipping.color_data<uint8_t>().data(), all.color_data<uint8_t>().data(),
                          all.color_data<uint8_t>().size()) == 0);
    }
}
