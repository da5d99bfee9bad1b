#include "tools/glref/gl_textures.h"

#include <algorithm>
#include <cmath>
#include <iterator>
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

void tex_parameters(GLenum target, const SamplerState& s) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GLint(gl_filter(s.min_filter)));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GLint(gl_filter(s.mag_filter)));
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GLint(gl_wrap(s.wrap_s)));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GLint(gl_wrap(s.wrap_t)));
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GLint(gl_wrap(s.wrap_r)));
    glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, glm::value_ptr(s.border_color));
    glTexParameterf(target, GL_TEXTURE_MIN_LOD, s.min_lod);
    glTexParameterf(target, GL_TEXTURE_MAX_LOD, s.max_lod);
    glTexParameterf(target, GL_TEXTURE_LOD_BIAS, s.lod_bias);
    glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, s.base_level);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, s.max_level);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, s.compare ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
    // CompareFunc lists the functions in GL's enum order (GL_NEVER..GL_ALWAYS).
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GLint(GL_NEVER + int(s.compare_func)));
    glTexParameteri(target, GL_DEPTH_TEXTURE_MODE, GLint(gl_depth_mode(s.depth_mode)));
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
    tex_parameters(target, t.sampler);
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
void attach_texture(const GLFunctions& gl, const scene::Scene& scene, int target, int attachment) {
    const scene::RenderTarget& t = scene.targets[size_t(target)];
    const scene::TextureSetting* sampled = nullptr;
    for (const scene::TextureSetting& s : scene.textures)
        if (s.render_target == target && s.attachment == attachment) sampled = &s;
    GLuint id = 0;
    glGenTextures(1, &id);
    gl.ActiveTexture(GLenum(GL_TEXTURE0 + (sampled ? sampled->unit : 0)));
    glBindTexture(GL_TEXTURE_2D, id);
    tex_parameters(GL_TEXTURE_2D, sampled ? sampled->texture->sampler : SamplerState{});
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
        for (int a = -1; a < t.color_buffers; ++a) attach_texture(gl, scene, int(i), a);
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
