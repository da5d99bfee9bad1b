#include "tools/glref/gl_textures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

namespace glslrun::glref {

namespace {

GLenum gl_target(TextureTarget t) {
    switch (t) {
    case TextureTarget::Tex1D: return GL_TEXTURE_1D;
    case TextureTarget::Tex2D: return GL_TEXTURE_2D;
    case TextureTarget::Tex3D: return GL_TEXTURE_3D;
    case TextureTarget::Cube: return GL_TEXTURE_CUBE_MAP;
    case TextureTarget::Rect: return GL_TEXTURE_RECTANGLE;
    case TextureTarget::Tex1DArray: return GL_TEXTURE_1D_ARRAY_EXT;
    case TextureTarget::Tex2DArray: return GL_TEXTURE_2D_ARRAY_EXT;
    }
    return GL_TEXTURE_2D;
}

GLenum gl_filter(TextureFilter f) {
    switch (f) {
    case TextureFilter::Nearest: return GL_NEAREST;
    case TextureFilter::Linear: return GL_LINEAR;
    case TextureFilter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
    case TextureFilter::LinearMipmapLinear: return GL_LINEAR_MIPMAP_LINEAR;
    }
    return GL_LINEAR;
}

GLenum gl_wrap(TextureWrap w) {
    switch (w) {
    case TextureWrap::Repeat: return GL_REPEAT;
    case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case TextureWrap::Clamp: return GL_CLAMP;
    case TextureWrap::ClampToBorder: return GL_CLAMP_TO_BORDER;
    case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

GLenum gl_depth_mode(DepthTextureMode m) {
    switch (m) {
    case DepthTextureMode::Luminance: return GL_LUMINANCE;
    case DepthTextureMode::Intensity: return GL_INTENSITY;
    case DepthTextureMode::Alpha: return GL_ALPHA;
    }
    return GL_LUMINANCE;
}

// glTexImage's internalformat, format and type for glslrun's formats, and
// the client data in that type.
struct Upload {
    GLint internal_format = GL_RGBA8;
    GLenum format = GL_RGBA, type = GL_UNSIGNED_BYTE;
    std::vector<uint8_t> bytes;
    std::vector<float> floats;
    const void* data() const { return bytes.empty() ? static_cast<const void*>(floats.data()) : bytes.data(); }
};

// RGBA8 texels are already k/255 in glslrun, so the bytes are exact; depth
// goes as floats (.r), as do RGBA32F and RGBA16F.
// A float format's GL internalformat: [channels][0 for 16F, 1 for 32F]
// (ARB_texture_float, ARB_texture_rg), in scene::TextureChannels' order.
constexpr GLint kFloatFormats[][2] = {
    {GL_RGBA16F, GL_RGBA32F},
    {GL_RGB16F, GL_RGB32F},
    {GL_RG16F, GL_RG32F},
    {GL_R16F, GL_R32F},
    {GL_LUMINANCE16F_ARB, GL_LUMINANCE32F_ARB},
    {GL_LUMINANCE_ALPHA16F_ARB, GL_LUMINANCE_ALPHA32F_ARB},
    {GL_INTENSITY16F_ARB, GL_INTENSITY32F_ARB},
    {GL_ALPHA16F_ARB, GL_ALPHA32F_ARB},
};
static_assert(std::size(kFloatFormats) == size_t(scene::TextureChannels::Alpha) + 1);

Upload texel_data(TextureFormat format, scene::TextureChannels channels, const TextureImage& image) {
    Upload u;
    if (format == TextureFormat::RGBA8) {
        u.bytes.reserve(image.texels.size() * 4);
        for (const glm::vec4& t : image.texels)
            for (int c = 0; c < 4; ++c)
                u.bytes.push_back(uint8_t(std::lround(std::clamp(t[c], 0.0f, 1.0f) * 255.0f)));
    } else if (format == TextureFormat::RGBA32F || format == TextureFormat::RGBA16F) {
        // Halves go as the floats they are: Mesa's conversion keeps them exactly.
        u.internal_format = kFloatFormats[size_t(channels)][format == TextureFormat::RGBA16F ? 0 : 1];
        u.type = GL_FLOAT;
        for (const glm::vec4& t : image.texels) u.floats.insert(u.floats.end(), {t.r, t.g, t.b, t.a});
    } else {
        u.internal_format = GL_DEPTH_COMPONENT;
        u.format = GL_DEPTH_COMPONENT;
        u.type = GL_FLOAT;
        for (const glm::vec4& t : image.texels) u.floats.push_back(t.r);
    }
    return u;
}

void tex_image(const GLFunctions& gl, const Texture& t, scene::TextureChannels channels, int face, int level) {
    const TextureImage& image = t.levels(face)[size_t(level)];
    Upload u = texel_data(t.format(), channels, image);
    GLenum target = gl_target(t.target());
    if (t.target() == TextureTarget::Cube) target = GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face);
    switch (t.target()) {
    case TextureTarget::Tex1D:
        glTexImage1D(target, level, u.internal_format, image.width, 0, u.format, u.type, u.data());
        break;
    case TextureTarget::Tex3D:
    case TextureTarget::Tex2DArray:  // EXT_texture_array: the layers are the depth
        gl.TexImage3D(target, level, u.internal_format, image.width, image.height, image.depth, 0, u.format, u.type,
                      u.data());
        break;
    default:
        glTexImage2D(target, level, u.internal_format, image.width, image.height, 0, u.format, u.type, u.data());
    }
}

// One glTexParameter: its value for a sampler state (an integer or enum in
// [0], or the border colour's four floats).
struct Parameter {
    const char* name;
    GLenum pname;
    enum Kind { Int, Float, Vec4 } kind;
    std::array<float, 4> (*value)(const SamplerState&);
};

std::array<float, 4> one(float v) { return {v, 0, 0, 0}; }

constexpr Parameter kParameters[] = {
    {"GL_TEXTURE_MIN_FILTER", GL_TEXTURE_MIN_FILTER, Parameter::Int, [](const SamplerState& s) { return one(float(gl_filter(s.min_filter))); }},
    {"GL_TEXTURE_MAG_FILTER", GL_TEXTURE_MAG_FILTER, Parameter::Int, [](const SamplerState& s) { return one(float(gl_filter(s.mag_filter))); }},
    {"GL_TEXTURE_WRAP_S", GL_TEXTURE_WRAP_S, Parameter::Int, [](const SamplerState& s) { return one(float(gl_wrap(s.wrap_s))); }},
    {"GL_TEXTURE_WRAP_T", GL_TEXTURE_WRAP_T, Parameter::Int, [](const SamplerState& s) { return one(float(gl_wrap(s.wrap_t))); }},
    {"GL_TEXTURE_WRAP_R", GL_TEXTURE_WRAP_R, Parameter::Int, [](const SamplerState& s) { return one(float(gl_wrap(s.wrap_r))); }},
    {"GL_TEXTURE_BORDER_COLOR", GL_TEXTURE_BORDER_COLOR, Parameter::Vec4,
     [](const SamplerState& s) { return std::array<float, 4>{s.border_color.r, s.border_color.g, s.border_color.b, s.border_color.a}; }},
    {"GL_TEXTURE_MIN_LOD", GL_TEXTURE_MIN_LOD, Parameter::Float, [](const SamplerState& s) { return one(s.min_lod); }},
    {"GL_TEXTURE_MAX_LOD", GL_TEXTURE_MAX_LOD, Parameter::Float, [](const SamplerState& s) { return one(s.max_lod); }},
    {"GL_TEXTURE_LOD_BIAS", GL_TEXTURE_LOD_BIAS, Parameter::Float, [](const SamplerState& s) { return one(s.lod_bias); }},
    {"GL_TEXTURE_BASE_LEVEL", GL_TEXTURE_BASE_LEVEL, Parameter::Int, [](const SamplerState& s) { return one(float(s.base_level)); }},
    {"GL_TEXTURE_MAX_LEVEL", GL_TEXTURE_MAX_LEVEL, Parameter::Int, [](const SamplerState& s) { return one(float(s.max_level)); }},
    {"GL_TEXTURE_COMPARE_MODE", GL_TEXTURE_COMPARE_MODE, Parameter::Int,
     [](const SamplerState& s) { return one(float(s.compare ? GL_COMPARE_R_TO_TEXTURE : GL_NONE)); }},
    // CompareFunc lists the functions in GL's enum order (GL_NEVER..GL_ALWAYS).
    {"GL_TEXTURE_COMPARE_FUNC", GL_TEXTURE_COMPARE_FUNC, Parameter::Int,
     [](const SamplerState& s) { return one(float(GL_NEVER + int(s.compare_func))); }},
    {"GL_DEPTH_TEXTURE_MODE", GL_DEPTH_TEXTURE_MODE, Parameter::Int,
     [](const SamplerState& s) { return one(float(gl_depth_mode(s.depth_mode))); }},
};

// A new texture object's state (GL 2.1 table 6.20): a rectangle texture
// starts LINEAR and clamped to its edges (ARB_texture_rectangle).
SamplerState initial_state(GLenum target) {
    SamplerState s;
    if (target == GL_TEXTURE_RECTANGLE) {
        s.min_filter = TextureFilter::Linear;
        s.wrap_s = s.wrap_t = s.wrap_r = TextureWrap::ClampToEdge;
    }
    return s;
}

// Only the parameters that differ from a new texture's are set: drivers
// differ in which mipmap parameters they accept on a rectangle texture
// (NVIDIA's refuses one that Mesa takes), and setting an initial value
// changes nothing. Each is checked on its own, so that a refusal names it.
// Empty when the driver took every parameter, else what it said.
std::string tex_parameters(GLenum target, const SamplerState& s) {
    const SamplerState initial = initial_state(target);
    for (const Parameter& p : kParameters) {
        const std::array<float, 4> v = p.value(s);
        if (v == p.value(initial)) continue;
        if (p.kind == Parameter::Int) glTexParameteri(target, p.pname, GLint(v[0]));
        else if (p.kind == Parameter::Float) glTexParameterf(target, p.pname, v[0]);
        else glTexParameterfv(target, p.pname, v.data());
        if (GLenum e = glGetError(); e != GL_NO_ERROR) return fmt::format("{} setting {}", gl_error_name(e), p.name);
    }
    return {};
}

Result<GLuint> upload_one(const GLFunctions& gl, const scene::TextureSetting& setting, bool upload_generated_levels) {
    const Texture& t = *setting.texture;
    GLenum target = gl_target(t.target());
    GLuint id = 0;
    glGenTextures(1, &id);
    gl.ActiveTexture(GLenum(GL_TEXTURE0 + setting.unit));
    glBindTexture(target, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // The parameters first: mipmap generation makes levels base_level+1 ..
    // max_level from base_level, in GL as in glslrun's generate_mipmaps().
    if (std::string refused = tex_parameters(target, t.sampler); !refused.empty())
        return Error(fmt::format("the driver reported {} on the texture of unit {}", refused, setting.unit),
                     setting.where.file, setting.where.line);
    bool generate = setting.generate_mipmap && !upload_generated_levels;
    for (int face = 0; face < t.faces(); ++face) {
        int levels = generate ? std::min(t.sampler.base_level + 1, int(t.levels(face).size()))
                              : int(t.levels(face).size());
        for (int level = 0; level < levels; ++level)
            if (t.levels(face)[size_t(level)].width > 0) tex_image(gl, t, setting.channels, face, level);  // width 0: never given
    }
    // Without a base_level image GL refuses to generate and glslrun generates nothing.
    size_t base = size_t(t.sampler.base_level);
    if (generate && base < t.levels(0).size() && t.levels(0)[base].width > 0) gl.GenerateMipmap(target);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR)
        return Error(fmt::format("Mesa reported {} while creating the texture of unit {}", gl_error_name(e), setting.unit),
                     setting.where.file, setting.where.line);
    return id;
}

constexpr GLenum kBindingQueries[] = {GL_TEXTURE_BINDING_1D, GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_3D,
                                      GL_TEXTURE_BINDING_CUBE_MAP, GL_TEXTURE_BINDING_RECTANGLE};
constexpr GLenum kTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                               GL_TEXTURE_RECTANGLE};

// An empty 2D texture of the target's size, attached to the bound FBO; the
// unit of a [textures.N] that samples it gets it with the file's sampler state.
// Empty, else the parameter the driver refused.
std::string attach_texture(const GLFunctions& gl, const scene::Scene& scene, int target, int attachment) {
    const scene::RenderTarget& t = scene.targets[size_t(target)];
    const scene::TextureSetting* sampled = nullptr;
    for (const scene::TextureSetting& s : scene.textures)
        if (s.render_target == target && s.attachment == attachment) sampled = &s;
    GLuint id = 0;
    glGenTextures(1, &id);
    gl.ActiveTexture(GLenum(GL_TEXTURE0 + (sampled ? sampled->unit : 0)));
    glBindTexture(GL_TEXTURE_2D, id);
    std::string refused = tex_parameters(GL_TEXTURE_2D, sampled ? sampled->texture->sampler : SamplerState{});
    if (attachment < 0) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, t.width, t.height, 0, GL_DEPTH_STENCIL,
                     GL_UNSIGNED_INT_24_8, nullptr);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, id, 0);
    } else {
        const GLint format = t.format == TextureFormat::RGBA16F   ? GL_RGBA16F
                             : t.format == TextureFormat::RGBA32F ? GL_RGBA32F
                                                                  : GL_RGBA8;
        glTexImage2D(GL_TEXTURE_2D, 0, format, t.width, t.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + attachment), GL_TEXTURE_2D, id, 0);
    }
    if (!sampled) glBindTexture(GL_TEXTURE_2D, 0);  // unit 0 keeps what the file bound there
    return refused;
}

}  // namespace

Result<std::vector<GLTarget>> make_render_targets(const GLFunctions& gl, const scene::Scene& scene) {
    GLint output = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &output);
    std::vector<GLTarget> targets;
    for (size_t i = 0; i < scene.targets.size(); ++i) {
        const scene::RenderTarget& t = scene.targets[i];
        GLTarget made{0, t.width, t.height, t.color_buffers};
        gl.GenFramebuffers(1, &made.fbo);
        gl.BindFramebuffer(GL_FRAMEBUFFER, made.fbo);
        for (int a = -1; a < t.color_buffers; ++a)
            if (std::string refused = attach_texture(gl, scene, int(i), a); !refused.empty())
                return Error(fmt::format("the driver reported {} on render target '{}'", refused, t.name), t.where.file,
                             t.where.line);
        GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            return Error(fmt::format("Mesa's FBO for render target '{}' is incomplete (0x{:x})", t.name, status),
                         t.where.file, t.where.line);
        targets.push_back(made);
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, GLuint(output));
    gl.ActiveTexture(GL_TEXTURE0);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) return Error(fmt::format("Mesa reported {} while making the render targets", gl_error_name(e)));
    return targets;
}

Status upload_textures(const GLFunctions& gl, const scene::Scene& scene, bool upload_generated_levels) {
    for (const scene::TextureSetting& setting : scene.textures)
        if (setting.render_target < 0)
            if (auto id = upload_one(gl, setting, upload_generated_levels); !id) return id.error();
    gl.ActiveTexture(GL_TEXTURE0);
    return Ok{};
}

}  // namespace glslrun::glref

namespace glslrun::glref {

Result<TextureBindings> upload_object_textures(const GLFunctions& gl, const scene::Scene& scene,
                                               bool upload_generated_levels) {
    TextureBindings b;
    for (int unit = 0; unit < kMaxTextureUnits; ++unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        for (size_t t = 0; t < std::size(kTargets); ++t) {
            GLint id = 0;
            glGetIntegerv(kBindingQueries[t], &id);
            b.initial[size_t(unit)][t] = GLuint(id);
        }
    }
    for (const scene::Object& o : scene.objects) {
        b.objects.emplace_back();
        for (const scene::TextureSetting& setting : o.textures) {
            auto id = upload_one(gl, setting, upload_generated_levels);
            if (!id) return id.error();
            b.objects.back().push_back(*id);
        }
    }
    restore_bindings(gl, b);  // uploading bound each texture; the scene's bindings come first
    return b;
}

void restore_bindings(const GLFunctions& gl, const TextureBindings& b) {
    for (int unit = 0; unit < kMaxTextureUnits; ++unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        for (size_t t = 0; t < std::size(kTargets); ++t) glBindTexture(kTargets[t], b.initial[size_t(unit)][t]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
}

void bind_object_textures(const GLFunctions& gl, const scene::Object& o, const std::vector<GLuint>& ids) {
    for (size_t i = 0; i < o.textures.size(); ++i) {
        const scene::TextureSetting& setting = o.textures[i];
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + setting.unit));
        glBindTexture(kTargets[int(setting.texture->target())], ids[i]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
}

}  // namespace glslrun::glref
