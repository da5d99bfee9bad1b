// GL 2.1 texture objects: image specification (§3.8.1), mipmap generation,
// completeness (§3.8.10) and glBindTexture. Sampling is sampling.cpp.
//
// Levels a texture never received are stored as default images (width 0),
// so levels_[face] can have holes; completeness decides what sampling sees.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "runtime/api_checks.h"
#include "runtime/half_float.h"
#include "runtime/texture_levels.h"

namespace glslrun {

namespace {

using rt::defined;
using rt::half_size;

constexpr std::array<const char*, 6> kFaceNames = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

const char* target_name(TextureTarget t) {
    switch (t) {
    case TextureTarget::Tex1D: return "1D texture";
    case TextureTarget::Tex2D: return "2D texture";
    case TextureTarget::Tex3D: return "3D texture";
    case TextureTarget::Cube: return "cube map";
    case TextureTarget::Rect: return "rectangle texture";
    case TextureTarget::Tex1DArray: return "1D array texture";
    case TextureTarget::Tex2DArray: return "2D array texture";
    }
    return "texture";
}

// GL_MAX_TEXTURE_SIZE, or the 3D or rectangle maximum.
int max_size(TextureTarget t) {
    return t == TextureTarget::Tex3D ? kMax3DTextureSize
                                     : t == TextureTarget::Rect ? kMaxRectangleTextureSize : kMaxTextureSize;
}
const char* max_size_name(TextureTarget t) {
    return t == TextureTarget::Tex3D ? "GL_MAX_3D_TEXTURE_SIZE"
                                     : t == TextureTarget::Rect ? "GL_MAX_RECTANGLE_TEXTURE_SIZE" : "GL_MAX_TEXTURE_SIZE";
}

// ARB_texture_rectangle: a rectangle has no mipmaps, and GL refuses the wrap
// modes and min filters that would need them (GL_INVALID_ENUM) and any base
// level but 0 (GL_INVALID_VALUE). Those states cannot arise in GL; here a
// SamplerState holding one makes the texture incomplete.
bool rectangle_sampler_ok(const SamplerState& st) {
    auto clamps = [](TextureWrap w) { return w != TextureWrap::Repeat && w != TextureWrap::MirroredRepeat; };
    return clamps(st.wrap_s) && clamps(st.wrap_t) && clamps(st.wrap_r) && !rt::is_mipmap_filter(st.min_filter) &&
           st.base_level == 0;
}

// Levels 0 .. log2(max size): glTexImage refuses others (GL_INVALID_VALUE).
int level_limit(TextureTarget t) { return int(std::bit_width(unsigned(max_size(t)))); }

// [0, 1], NaN to 0: what a normalized fixed-point format can hold.
float unorm(float x) { return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; }

// How the internal format stores a texel (§3.8.1): GL_RGBA8 keeps the nearest
// k/255 (round half to even, as Mesa's float-to-unorm does), GL_RGBA32F the
// float, GL_RGBA16F the nearest binary16 value, a depth format a depth
// clamped to [0, 1] (only .r is meaningful).
glm::vec4 store_texel(TextureFormat format, const glm::vec4& v) {
    switch (format) {
    case TextureFormat::RGBA8: {
        glm::vec4 out;
        for (int c = 0; c < 4; ++c) out[c] = std::nearbyint(unorm(v[c]) * 255.0f) / 255.0f;
        return out;
    }
    case TextureFormat::Depth: return {unorm(v.r), 0.0f, 0.0f, 1.0f};
    case TextureFormat::RGBA16F:
        return {rt::round_to_half(v.r), rt::round_to_half(v.g), rt::round_to_half(v.b), rt::round_to_half(v.a)};
    case TextureFormat::RGBA32F: break;
    }
    return v;
}

void store_image(TextureFormat format, TextureImage& image) {
    for (glm::vec4& t : image.texels) t = store_texel(format, t);
}

std::string size_str(const TextureImage& i) { return fmt::format("{}x{}x{}", i.width, i.height, i.depth); }

bool arrayed(TextureTarget t) { return t == TextureTarget::Tex1DArray || t == TextureTarget::Tex2DArray; }

// An array's layers: the height of a 1D array, the depth of a 2D array.
int layers(TextureTarget t, const TextureImage& image) {
    return t == TextureTarget::Tex1DArray ? image.height : t == TextureTarget::Tex2DArray ? image.depth : 1;
}

// The checks glTexImage makes on one image of `level` (§3.8.1): the target's
// dimensionality, square cube faces, GL's maxima (an array's layer count
// against GL_MAX_ARRAY_TEXTURE_LAYERS_EXT at every level), and the texel
// count. Empty when the image is acceptable.
std::string check_image(TextureTarget target, const TextureImage& image, int level) {
    if (image.width < 1 || image.height < 1 || image.depth < 1)
        return fmt::format("a texture image needs width, height and depth of at least 1 (got {})", size_str(image));
    if (target == TextureTarget::Tex1D && (image.height != 1 || image.depth != 1))
        return fmt::format("a 1D texture image has height = depth = 1 (got {})", size_str(image));
    if ((target == TextureTarget::Tex2D || target == TextureTarget::Cube || target == TextureTarget::Rect ||
         target == TextureTarget::Tex1DArray) &&
        image.depth != 1)
        return fmt::format("a {} image has depth = 1 (got {})", target_name(target), size_str(image));
    if (target == TextureTarget::Cube && image.width != image.height)
        return fmt::format("cube map faces are square (got {}x{})", image.width, image.height);
    const int limit = max_size(target) >> level;
    if (arrayed(target) && layers(target, image) > kMaxArrayTextureLayers)
        return fmt::format("{} has {} layers, more than GL_MAX_ARRAY_TEXTURE_LAYERS_EXT ({})", size_str(image),
                           layers(target, image), kMaxArrayTextureLayers);
    const int dims = rt::texture_dims(target);
    if (image.width > limit || (dims > 1 && image.height > limit) || (dims > 2 && image.depth > limit))
        return fmt::format("{} is larger than {} ({}) allows at level {} (at most {})", size_str(image),
                           max_size_name(target), max_size(target), level, limit);
    const uint64_t want = uint64_t(image.width) * uint64_t(image.height) * uint64_t(image.depth);
    if (image.texels.size() != want)
        return fmt::format("a {} image has {} texels (got {})", size_str(image), want, image.texels.size());
    return {};
}

// ------------------------------------------------------------ mipmaps ---
// One step of the box filter along `axis`: n texels become m = max(1, n/2),
// each the average of the source texels its footprint [o*n/m, (o+1)*n/m)
// covers, weighted by the part covered. For even n that is the plain 2-texel
// mean; for odd n (3 -> 1, 5 -> 2, ...) no source texel is dropped.
std::vector<glm::vec4> reduce_axis(const std::vector<glm::vec4>& in, std::array<int, 3>& size, int axis) {
    const int n = size[size_t(axis)], m = half_size(n);
    std::array<int, 3> out = size;
    out[size_t(axis)] = m;
    const size_t stride = axis == 0 ? 1 : axis == 1 ? size_t(size[0]) : size_t(size[0]) * size_t(size[1]);
    std::vector<glm::vec4> result(size_t(out[0]) * size_t(out[1]) * size_t(out[2]));
    size_t at = 0;
    for (int k = 0; k < out[2]; ++k)
        for (int j = 0; j < out[1]; ++j)
            for (int i = 0; i < out[0]; ++i, ++at) {
                std::array<int, 3> c = {i, j, k};
                const int o = c[size_t(axis)];
                c[size_t(axis)] = 0;
                const size_t row = size_t(c[0]) + size_t(size[0]) * (size_t(c[1]) + size_t(size[1]) * size_t(c[2]));
                // In units of 1/m source texels: texel t spans [t*m, (t+1)*m), output o spans [o*n, (o+1)*n).
                glm::vec4 sum(0.0f);
                for (int t = o * n / m; t * m < (o + 1) * n; ++t) {
                    const int covered = std::min((t + 1) * m, (o + 1) * n) - std::max(t * m, o * n);
                    sum += in[row + size_t(t) * stride] * (float(covered) / float(n));
                }
                result[at] = sum;
            }
    size = out;
    return result;
}

// The level below `src`: each of the target's dimensions halves (§3.8.10's sizes).
TextureImage reduce(const TextureImage& src, int dims) {
    std::array<int, 3> size = {src.width, src.height, src.depth};
    std::vector<glm::vec4> texels = src.texels;
    for (int axis = 0; axis < dims; ++axis)
        if (size[size_t(axis)] > 1) texels = reduce_axis(texels, size, axis);
    return TextureImage{size[0], size[1], size[2], std::move(texels)};
}

// Levels base+1 .. q of one face follow the sizes of §3.8.10 and are defined:
// each of the first `dims` sizes halves, the others (an array's layers) stay.
bool chain_complete(const std::vector<TextureImage>& chain, int base, int q, int dims) {
    if (q >= int(chain.size())) return false;
    auto next = [dims](int size, int axis) { return axis < dims ? half_size(size) : size; };
    for (int level = base + 1; level <= q; ++level) {
        const TextureImage& above = chain[size_t(level - 1)];
        const TextureImage& image = chain[size_t(level)];
        if (!defined(image) || image.width != next(above.width, 0) || image.height != next(above.height, 1) ||
            image.depth != next(above.depth, 2))
            return false;
    }
    return true;
}

}  // namespace

// ------------------------------------------------------------ Texture ---
Result<Texture> Texture::create(TextureTarget target, std::vector<TextureImage> faces, TextureFormat format) {
    if (Status st = rt::check_texture_enums(target, format); !st) return st.error();
    const bool cube = target == TextureTarget::Cube;
    const size_t want = cube ? 6 : 1;
    if (faces.size() != want)
        return Error(fmt::format("a {} takes {} image{} for level 0 (got {})", target_name(target), want,
                                 cube ? "s, one per face (+X, -X, +Y, -Y, +Z, -Z)" : "", faces.size()));
    // §3.8.1: DEPTH_COMPONENT images are for TEXTURE_1D and TEXTURE_2D only in
    // GL 2.1, and rectangles (ARB_texture_rectangle with ARB_depth_texture).
    if (format == TextureFormat::Depth && (target == TextureTarget::Tex3D || target == TextureTarget::Cube))
        return Error(fmt::format("a depth texture is 1D, 2D or a rectangle in GL 2.1 (this is a {})",
                                 target_name(target)));
    for (size_t f = 0; f < faces.size(); ++f) {
        std::string why = check_image(target, faces[f], 0);
        if (!why.empty()) return Error(cube ? fmt::format("cube map face {}: {}", kFaceNames[f], why) : why);
        if (cube && faces[f].width != faces[0].width)
            return Error(fmt::format("cube map faces all have one size: face {} is {}x{}, face +X is {}x{}",
                                     kFaceNames[f], faces[f].width, faces[f].height, faces[0].width,
                                     faces[0].height));
    }
    return rt::without_throwing("Texture::create", [&] {
        Texture t;
        t.target_ = target;
        t.format_ = format;
        t.levels_.resize(want);
        if (target == TextureTarget::Rect) {  // GL's initial state for rectangles
            t.sampler.min_filter = TextureFilter::Linear;
            t.sampler.wrap_s = t.sampler.wrap_t = t.sampler.wrap_r = TextureWrap::ClampToEdge;
        }
        for (size_t f = 0; f < want; ++f) {
            store_image(format, faces[f]);
            t.levels_[f].push_back(std::move(faces[f]));
        }
        return Result<Texture>(std::move(t));
    });
}

Status Texture::set_level(int face, int level, TextureImage image) {
    if (face < 0 || face >= faces())
        return Error(fmt::format("face {} does not exist: a {} has {} face{}", face, target_name(target_), faces(),
                                 faces() > 1 ? "s (0..5: +X, -X, +Y, -Y, +Z, -Z)" : " (0)"));
    if (target_ == TextureTarget::Rect && level != 0)
        return Error(fmt::format("mipmap level {} of a rectangle texture: rectangles have level 0 only "
                                 "(GL_INVALID_VALUE)", level));
    if (level < 0 || level >= level_limit(target_))
        return Error(fmt::format("mipmap level {} is outside 0..{} for a {}", level, level_limit(target_) - 1,
                                 target_name(target_)));
    if (std::string why = check_image(target_, image, level); !why.empty())
        return Error(fmt::format("level {}: {}", level, why));
    return rt::without_throwing("Texture::set_level", [&]() -> Status {
        store_image(format_, image);
        std::vector<TextureImage>& chain = levels_[size_t(face)];
        if (chain.size() <= size_t(level)) chain.resize(size_t(level) + 1);  // the levels between stay undefined
        chain[size_t(level)] = std::move(image);
        return Ok{};
    });
}

// GenerateMipmap (GL 3.0 §3.8.8, GL 2.1's GENERATE_MIPMAP alike): levels
// level_base+1 .. q are derived from level_base, so sampler.base_level and
// max_level as they are now choose the levels. Where GL would refuse
// (no level_base image, cube faces of different sizes) nothing changes.
void Texture::generate_mipmaps() {
    if (target_ == TextureTarget::Rect) return;  // rectangles have no mipmaps (GL_INVALID_ENUM)
    const int base = sampler.base_level;
    for (int f = 0; f < faces(); ++f) {
        const TextureImage* image = rt::level_image(*this, f, base);
        if (!image || image->width != levels_[0][size_t(base)].width ||
            image->height != levels_[0][size_t(base)].height)
            return;
    }
    const int dims = rt::texture_dims(target_);
    const int q = rt::last_mip_level(levels_[0][size_t(base)], sampler, dims);
    for (std::vector<TextureImage>& chain : levels_) {
        if (chain.size() <= size_t(std::max(q, base))) chain.resize(size_t(std::max(q, base)) + 1);
        for (int level = base + 1; level <= q; ++level) {
            TextureImage image = reduce(chain[size_t(level - 1)], dims);
            store_image(format_, image);
            chain[size_t(level)] = std::move(image);
        }
    }
}

// §3.8.10. A texture is complete when level_base is defined (on every face,
// all of one square size for a cube map: "cube complete") and, when the min
// filter needs a mipmap, level_base <= level_max and levels level_base+1 .. q
// each halve the one above (per face: "cube mipmap complete").
bool Texture::complete() const {
    const int base = sampler.base_level;
    const TextureImage* first = rt::level_image(*this, 0, base);
    if (!first) return false;
    if (target_ == TextureTarget::Rect) return rectangle_sampler_ok(sampler);
    for (int f = 1; f < faces(); ++f) {
        const TextureImage* image = rt::level_image(*this, f, base);
        if (!image || image->width != first->width || image->height != first->height) return false;
    }
    if (!rt::is_mipmap_filter(sampler.min_filter)) return true;
    if (base > sampler.max_level) return false;
    const int dims = rt::texture_dims(target_);
    const int q = rt::last_mip_level(*first, sampler, dims);
    for (const std::vector<TextureImage>& chain : levels_)
        if (!chain_complete(chain, base, q, dims)) return false;
    return true;
}

// ------------------------------------------------------------ binding ---
// glBindTexture: the texture takes its own target's slot on the unit. A null
// texture unbinds every target of the unit (GL's texture object 0 has no
// images, so it samples as (0, 0, 0, 1) just like nothing bound). A unit
// outside [0, kMaxTextureUnits) is ignored, as glActiveTexture refuses it.
Status GLState::bind_texture(int unit, std::shared_ptr<const Texture> texture) {
    if (unit < 0 || unit >= kMaxTextureUnits)
        return Error(fmt::format("texture unit {} does not exist (units are 0..{})", unit, kMaxTextureUnits - 1));
    auto& bound = texture_units[size_t(unit)].bound;
    if (!texture) {
        bound.fill(nullptr);
        return Ok{};
    }
    if (Status st = rt::check_texture_enums(texture->target(), texture->format()); !st) return st;
    const size_t target = size_t(texture->target());
    bound[target] = std::move(texture);
    return Ok{};
}

}  // namespace glslrun
