// [render_targets.NAME] and what refers to them: a pass's `target`, `clear`
// and `camera`, and a [textures.N] whose texels are a target's attachment
// (render to texture through framebuffer objects, as a GL 2.1 program with
// EXT_framebuffer_object draws a shadow map or a post-processing chain).
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

// Every target is allocated when the scene is drawn (its colour buffers,
// depth and stencil); the sum is bounded like one framebuffer's.
constexpr size_t kMaxRenderTargets = 16;

RenderTarget read_target(const Section& s, std::string name) {
    s.allow({"size", "color_buffers", "internal_format"});
    RenderTarget t;
    t.name = std::move(name);
    t.where = location(s.table());
    const toml::node& n = s.require("size", "a render target needs its size = [width, height]");
    const toml::array* a = n.as_array();
    if (!a || a->size() != 2)
        fail(n, fmt::format("'{}' must be [width, height] (got {})", s.name("size"), describe(n)));
    int64_t w = integer((*a)[0], s.name("size") + "[0]", INT64_MIN, INT64_MAX);
    int64_t h = integer((*a)[1], s.name("size") + "[1]", INT64_MIN, INT64_MAX);
    if (std::string why = size_problem(w, h); !why.empty()) fail(n, why);
    t.width = int(w);
    t.height = int(h);
    if (const toml::node* c = s.get("color_buffers"))
        t.color_buffers = int(integer(*c, s.name("color_buffers") + " (GL_MAX_DRAW_BUFFERS)", 1, kMaxDrawBuffers));
    if (const toml::node* f = s.get("internal_format")) {
        constexpr TextureFormat kColorFormats[] = {TextureFormat::RGBA8, TextureFormat::RGBA16F, TextureFormat::RGBA32F};
        t.format = kColorFormats[choice(*f, s.name("internal_format"), {"rgba8", "rgba16f", "rgba32f"})];
    }
    return t;
}

size_t target_index(const toml::node& n, const std::string& what, const Scene& scene) {
    auto name = n.as_string();
    if (!name) fail(n, fmt::format("'{}' must name a render target (got {})", what, describe(n)));
    std::vector<std::string_view> known;
    for (size_t i = 0; i < scene.targets.size(); ++i) {
        if (scene.targets[i].name == name->get()) return i;
        known.push_back(scene.targets[i].name);
    }
    fail(n, fmt::format("'{}': there is no [render_targets.{}]; {}", what, name->get(),
                        known.empty() ? std::string("the scene declares no render target")
                                      : suggestion(name->get(), known, "render targets")));
}

}  // namespace

void read_render_targets(const toml::node& n, Scene& scene) {
    const toml::table& all = table(n, "render_targets");
    int64_t pixels = 0;
    for (auto&& [k, v] : all) {
        std::string what = fmt::format("render_targets.{}", k.str());
        if (scene.targets.size() == kMaxRenderTargets)
            fail(v, fmt::format("[{}]: a scene has at most {} render targets (docs/limits.md)", what,
                                kMaxRenderTargets));
        scene.targets.push_back(read_target(Section(table(v, what), what), std::string(k.str())));
        const RenderTarget& t = scene.targets.back();
        // A float colour pixel takes 16 bytes, an RGBA8 one 4: counted as 4 pixels, the bound stays one of memory.
        const int64_t color_weight = t.format == TextureFormat::RGBA8 ? 1 : 4;
        pixels += int64_t(t.width) * t.height * (t.color_buffers * color_weight + 1);
        if (pixels > kMaxFramebufferPixels)
            fail(v, fmt::format("the render targets up to [{}] hold {} pixels in all (colour buffers, float ones "
                                "counted 4 times, and depth); "
                                "a scene may hold at most {} (docs/limits.md)", what, pixels, kMaxFramebufferPixels));
    }
}

// `render_target = "NAME"` with `attachment = "color"` (colour buffer 0),
// "color1".."color7", or "depth". The texture has the target's size and
// format (or depth texels), cleared (0, 0, 0, 0) and depth 1 until a pass
// draws into the target.
Texture target_texture(const Section& s, const Scene& scene, TextureSetting& setting) {
    const toml::node& n = *s.get("render_target");
    setting.render_target = int(target_index(n, s.name("render_target"), scene));
    const RenderTarget& t = scene.targets[size_t(setting.render_target)];
    setting.attachment = 0;
    if (const toml::node* a = s.get("attachment")) {
        static_assert(kMaxDrawBuffers == 8);
        setting.attachment = int(choice(*a, s.name("attachment"), {"depth", "color", "color1", "color2", "color3",
                                                                   "color4", "color5", "color6", "color7"})) - 1;
        if (setting.attachment >= t.color_buffers)
            fail(*a, fmt::format("'{}': render target '{}' has {} colour buffer(s)", s.name("attachment"), t.name,
                                 t.color_buffers));
    }
    for (const TextureSetting& other : scene.textures)
        if (other.render_target == setting.render_target && other.attachment == setting.attachment)
            fail(n, fmt::format("[{}]: texture unit {} already samples this attachment of '{}'; one texture object "
                                "has one sampler state, so bind it to one unit", s.path(), other.unit, t.name));
    bool depth = setting.attachment < 0;
    TextureImage image{t.width, t.height, 1,
                       std::vector<glm::vec4>(size_t(t.width) * size_t(t.height),
                                              depth ? glm::vec4(1, 0, 0, 1) : glm::vec4(0))};
    Result<Texture> texture = Texture::create(TextureTarget::Tex2D, {std::move(image)},
                                              depth ? TextureFormat::Depth : t.format);
    if (!texture) fail(n, fmt::format("[{}]: {}", s.path(), texture.error().str()));
    return std::move(*texture);
}

void read_pass_target(const Section& s, const Scene& scene, Pass& pass) {
    if (const toml::node* n = s.get("target")) pass.target = int(target_index(*n, s.name("target"), scene));
    if (const toml::node* n = s.get("clear")) {
        Section c(table(*n, s.name("clear")), s.name("clear"));
        c.allow({"color", "depth", "stencil"});
        if (c.get("color")) pass.clear.color = glm::vec4(color(*c.get("color"), c.name("color")));
        float depth = 1;
        if (c.read("depth", depth, {.lo = 0, .hi = 1, .why = "glClearDepth"})) pass.clear.depth = depth;
        if (const toml::node* st = c.get("stencil"))
            pass.clear.stencil = int(integer(*st, c.name("stencil") + " (stencil values are 8 bits)", 0,
                                             (1 << kStencilBits) - 1));
    }
    if (const toml::node* n = s.get("camera")) {
        Section cam(table(*n, s.name("camera")), s.name("camera"));
        int w = pass.target < 0 ? scene.width : scene.targets[size_t(pass.target)].width;
        int h = pass.target < 0 ? scene.height : scene.targets[size_t(pass.target)].height;
        glm::mat4 view = scene.view;
        Camera unused;
        read_camera_into(cam, unused, view, pass.state.projection, w, h);
        pass.view = view;
        for (std::string_view k : {"perspective", "ortho", "frustum", "projection_matrix"})
            pass.own_projection = pass.own_projection || cam.get(k);
    }
}

}  // namespace glslrun::scene::detail
