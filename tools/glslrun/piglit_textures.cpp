// shader_runner's texture commands. Each helper below follows what piglit's
// util library uploads and sets, so that probes see the texels Mesa sees:
//  - rgbw (mip = GL_FALSE): level 0 only, quadrants red, green (bottom row),
//    blue, white (top row), NEAREST filters, CLAMP_TO_EDGE on S and T;
//  - checkerboard: level `level` only, tiles of w/2 x h/2 alternating the two
//    colours (the first one bottom-left), NEAREST, CLAMP_TO_BORDER with a red
//    border;
//  - shadow1D/shadow2D/shadowRect: a depth ramp x / (w - 1), NEAREST, CLAMP_TO_EDGE,
//    compare mode on with GL_GREATER (depth mode stays GL's LUMINANCE);
//  - rgbw 1D / 3D: fixed 4-texel and 2x2x2 images, NEAREST, CLAMP_TO_EDGE;
//  - miptree: 8x8 with levels 1..3, each level one colour (red, green, blue,
//    white), NEAREST_MIPMAP_NEAREST, NEAREST, CLAMP_TO_EDGE;
//  - rgbw 1DArray / 2DArray (piglit_array_texture, mip = GL_FALSE): level 0,
//    layer l all one colour of red, green, blue, white (l mod 4), NEAREST,
//    CLAMP_TO_EDGE on S and T;
//  - shadow1DArray / shadow2DArray: the depth ramp in every row / layer, as
//    shadow1D/shadow2D.
// All of them pass floats with internal format GL_RGBA (8-bit unorm on Mesa)
// or GL_DEPTH_COMPONENT, unless "texture rgbw" names another format.
#include "piglit_textures.h"

#include <memory>
#include <string_view>

#include <fmt/format.h>

namespace glslrun::piglit {
namespace {

const glm::vec4 kRed{1, 0, 0, 1}, kGreen{0, 1, 0, 1}, kBlue{0, 0, 1, 1}, kWhite{1, 1, 1, 1};

std::string size_text(int w, int h, int d, int dims) {
    if (dims == 1) return std::to_string(w);
    if (dims == 2) return fmt::format("{}x{}", w, h);
    return fmt::format("{}x{}x{}", w, h, d);
}

// GL_INVALID_VALUE cases, plus the runner's own memory cap.
Status check_size(int w, int h, int d, int dims) {
    std::string size = size_text(w, h, d, dims);
    if (w < 1 || h < 1 || d < 1)
        return Error(fmt::format("texture size {} is empty: every dimension must be at least 1", size));
    int max = dims == 3 ? kMax3DTextureSize : kMaxTextureSize;
    if (w > max || h > max || d > max)
        return Error(fmt::format("texture size {} exceeds the maximum texture size {}", size, max));
    int64_t texels = int64_t(w) * h * d;
    if (texels > kMaxRunnerTexels)
        return Error(fmt::format("texture size {} has {} texels; the piglit runner allows at most {}", size,
                                 texels, kMaxRunnerTexels));
    return Ok{};
}

void nearest_clamped(SamplerState& s) {
    s.min_filter = s.mag_filter = TextureFilter::Nearest;
    s.wrap_s = s.wrap_t = TextureWrap::ClampToEdge;
}

Result<Texture> finish(Result<Texture> t, void (*set_sampler)(SamplerState&)) {
    if (t) set_sampler(t->sampler);
    return t;
}

Result<Texture> make_rgbw(const TextureCommand& c) {
    if (auto st = check_size(c.width, c.height, 1, 2); !st) return st.error();
    TextureFormat format = c.float_format ? TextureFormat::RGBA32F : TextureFormat::RGBA8;
    return finish(Texture::create(TextureTarget::Tex2D, {rgbw_image(c.width, c.height)}, format), nearest_clamped);
}

Result<Texture> make_checkerboard(const TextureCommand& c) {
    if (auto st = check_size(c.width, c.height, 1, 2); !st) return st.error();
    // piglit's tile size is w/2 x h/2 and it divides by it: below 2 it would crash.
    if (c.width < 2 || c.height < 2)
        return Error(fmt::format("texture checkerboard needs at least 2x2 texels, not {}x{}", c.width, c.height));
    glm::vec4 black(c.black[0], c.black[1], c.black[2], c.black[3]);
    glm::vec4 white(c.white[0], c.white[1], c.white[2], c.white[3]);
    auto t = Texture::create(TextureTarget::Tex2D, {checkerboard_image(c.width, c.height, black, white)});
    return finish(std::move(t), [](SamplerState& s) {
        s.min_filter = s.mag_filter = TextureFilter::Nearest;
        s.wrap_s = s.wrap_t = TextureWrap::ClampToBorder;
        s.border_color = kRed;
    });
}

Result<Texture> make_miptree() {
    const glm::vec4 colors[4] = {kRed, kGreen, kBlue, kWhite};
    auto level = [&](int l) {
        const int size = 8 >> l;
        return TextureImage{size, size, 1, std::vector<glm::vec4>(size_t(size * size), colors[l])};
    };
    auto t = Texture::create(TextureTarget::Tex2D, {level(0)});
    for (int l = 1; t && l < 4; ++l)
        if (Status st = t->set_level(0, l, level(l)); !st) return st.error();
    return finish(std::move(t), [](SamplerState& s) {
        nearest_clamped(s);
        s.min_filter = TextureFilter::NearestMipmapNearest;
    });
}

Result<Texture> make_array(const TextureCommand& c, TextureTarget target) {
    const bool one_d = target == TextureTarget::Tex1DArray;
    const int h = one_d ? 1 : c.height;
    if (auto st = check_size(c.width, h, c.layers, one_d ? 2 : 3); !st) return st.error();
    if (c.layers > kMaxArrayTextureLayers)
        return Error(fmt::format("{} layers exceed GL_MAX_ARRAY_TEXTURE_LAYERS_EXT ({})", c.layers,
                                 kMaxArrayTextureLayers));
    const bool depth = c.kind == TextureCommand::Kind::Shadow1DArray || c.kind == TextureCommand::Kind::Shadow2DArray;
    const glm::vec4 colors[4] = {kRed, kGreen, kBlue, kWhite};
    TextureImage img{c.width, one_d ? c.layers : h, one_d ? 1 : c.layers, {}};
    const TextureImage ramp = depth_ramp_image(c.width, h);
    for (int layer = 0; layer < c.layers; ++layer) {
        if (depth)
            img.texels.insert(img.texels.end(), ramp.texels.begin(), ramp.texels.end());
        else
            img.texels.insert(img.texels.end(), size_t(c.width) * size_t(h), colors[layer % 4]);
    }
    auto t = Texture::create(target, {std::move(img)}, depth ? TextureFormat::Depth : TextureFormat::RGBA8);
    if (!depth) return finish(std::move(t), nearest_clamped);
    return finish(std::move(t), [](SamplerState& s) {
        nearest_clamped(s);
        s.compare = true;
        s.compare_func = CompareFunc::Greater;
    });
}

Result<Texture> make_shadow(const TextureCommand& c, TextureTarget target) {
    const bool two_d = target != TextureTarget::Tex1D;
    int h = two_d ? c.height : 1;
    if (auto st = check_size(c.width, h, 1, two_d ? 2 : 1); !st) return st.error();
    auto t = Texture::create(target, {depth_ramp_image(c.width, h)}, TextureFormat::Depth);
    return finish(std::move(t), [](SamplerState& s) {
        nearest_clamped(s);
        s.compare = true;
        s.compare_func = CompareFunc::Greater;
    });
}

// ------------------------------------------------------------ texparameter ---
template <class E>
struct NamedValue {
    std::string_view name;
    E value;
};

template <class E, size_t N>
Result<E> lookup(const NamedValue<E> (&table)[N], std::string_view name) {
    for (const auto& entry : table)
        if (entry.name == name) return entry.value;
    return Error(fmt::format("bad texture parameter value \"{}\"", name));
}

const NamedValue<CompareFunc> kCompareFuncs[] = {
    {"greater", CompareFunc::Greater}, {"gequal", CompareFunc::Gequal}, {"less", CompareFunc::Less},
    {"lequal", CompareFunc::Lequal},   {"equal", CompareFunc::Equal},   {"notequal", CompareFunc::Notequal},
    {"never", CompareFunc::Never},     {"always", CompareFunc::Always},
};
const NamedValue<DepthTextureMode> kDepthModes[] = {
    {"luminance", DepthTextureMode::Luminance},
    {"intensity", DepthTextureMode::Intensity},
    {"alpha", DepthTextureMode::Alpha},
};
const NamedValue<TextureFilter> kFilters[] = {
    {"nearest", TextureFilter::Nearest},
    {"linear", TextureFilter::Linear},
    {"nearest_mipmap_nearest", TextureFilter::NearestMipmapNearest},
    {"linear_mipmap_nearest", TextureFilter::LinearMipmapNearest},
    {"nearest_mipmap_linear", TextureFilter::NearestMipmapLinear},
    {"linear_mipmap_linear", TextureFilter::LinearMipmapLinear},
};
const NamedValue<TextureWrap> kWraps[] = {
    {"repeat", TextureWrap::Repeat},
    {"clamp_to_edge", TextureWrap::ClampToEdge},
    {"clamp_to_border", TextureWrap::ClampToBorder},
};

// Stores the looked-up value in `field`, or passes the lookup error on.
template <class E>
Status assign(E& field, Result<E> value) {
    if (!value) return value.error();
    field = *value;
    return Ok{};
}

Status set_level_param(int& field, float value, const char* name) {
    if (value < 0) return Error(fmt::format("{} must be at least 0, not {}", name, value));
    field = int(value);
    return Ok{};
}

Status apply(SamplerState& s, const TexParameter& p) {
    using N = TexParameter::Name;
    switch (p.name) {
        case N::CompareFunc: return assign(s.compare_func, lookup(kCompareFuncs, p.value));
        case N::DepthMode: return assign(s.depth_mode, lookup(kDepthModes, p.value));
        case N::Min: return assign(s.min_filter, lookup(kFilters, p.value));
        case N::Mag: {
            auto f = lookup(kFilters, p.value);
            if (f && *f != TextureFilter::Nearest && *f != TextureFilter::Linear)
                return Error("a magnification filter is nearest or linear");
            return assign(s.mag_filter, std::move(f));
        }
        case N::WrapS: return assign(s.wrap_s, lookup(kWraps, p.value));
        case N::WrapT: return assign(s.wrap_t, lookup(kWraps, p.value));
        case N::WrapR: return assign(s.wrap_r, lookup(kWraps, p.value));
        case N::LodBias: s.lod_bias = p.numbers[0]; return Ok{};
        case N::MaxLevel: return set_level_param(s.max_level, p.numbers[0], "max_level");
        case N::BaseLevel: return set_level_param(s.base_level, p.numbers[0], "base_level");
        case N::BorderColor:
            s.border_color = {p.numbers[0], p.numbers[1], p.numbers[2], p.numbers[3]};
            return Ok{};
    }
    return Error("unknown texture parameter");
}

TextureTarget to_target(TexParameter::Target t) {
    switch (t) {
        case TexParameter::Target::Tex1D: return TextureTarget::Tex1D;
        case TexParameter::Target::Tex2D: return TextureTarget::Tex2D;
        case TexParameter::Target::Tex3D: return TextureTarget::Tex3D;
        case TexParameter::Target::Cube: return TextureTarget::Cube;
        case TexParameter::Target::Rect: return TextureTarget::Rect;
        case TexParameter::Target::Tex1DArray: return TextureTarget::Tex1DArray;
        case TexParameter::Target::Tex2DArray: return TextureTarget::Tex2DArray;
    }
    return TextureTarget::Tex2D;
}

}  // namespace

// ------------------------------------------------------------------ images ---
TextureImage rgbw_image(int width, int height) {
    TextureImage img{width, height, 1, {}};
    img.texels.reserve(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            bool left = x < width / 2, bottom = y < height / 2;
            img.texels.push_back(bottom ? (left ? kRed : kGreen) : (left ? kBlue : kWhite));
        }
    return img;
}

TextureImage rgbw_1d_image() { return {4, 1, 1, {kRed, kGreen, kBlue, kWhite}}; }

TextureImage rgbw_3d_image() {
    // Layer 0: red, green / blue, white; layer 1: yellow, magenta / cyan, black.
    return {2, 2, 2, {kRed, kGreen, kBlue, kWhite, {1, 1, 0, 1}, {1, 0, 1, 1}, {0, 1, 1, 1}, {0, 0, 0, 1}}};
}

TextureImage checkerboard_image(int width, int height, const glm::vec4& black, const glm::vec4& white) {
    TextureImage img{width, height, 1, {}};
    img.texels.reserve(size_t(width) * size_t(height));
    const int tile_w = width / 2, tile_h = height / 2;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) img.texels.push_back(((x / tile_w + y / tile_h) & 1) ? white : black);
    return img;
}

TextureImage depth_ramp_image(int width, int height) {
    TextureImage img{width, height, 1, {}};
    img.texels.reserve(size_t(width) * size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // piglit computes x / (w - 1), NaN for a 1-texel ramp; GL clamps depths to [0, 1] and we say 0.
            float d = width > 1 ? float(x) / float(width - 1) : 0.0f;
            img.texels.push_back({d, 0, 0, 1});
        }
    return img;
}

Result<Texture> make_texture(const TextureCommand& cmd) {
    using K = TextureCommand::Kind;
    switch (cmd.kind) {
        case K::Rgbw: return make_rgbw(cmd);
        case K::Rgbw1D: return finish(Texture::create(TextureTarget::Tex1D, {rgbw_1d_image()}), nearest_clamped);
        case K::Rgbw3D:
            return finish(Texture::create(TextureTarget::Tex3D, {rgbw_3d_image()}), [](SamplerState& s) {
                nearest_clamped(s);
                s.wrap_r = TextureWrap::ClampToEdge;
            });
        case K::Miptree: return make_miptree();
        case K::Checkerboard: return make_checkerboard(cmd);
        case K::Shadow1D: return make_shadow(cmd, TextureTarget::Tex1D);
        case K::Shadow2D: return make_shadow(cmd, TextureTarget::Tex2D);
        case K::ShadowRect: return make_shadow(cmd, TextureTarget::Rect);
        case K::Rgbw1DArray:
        case K::Shadow1DArray: return make_array(cmd, TextureTarget::Tex1DArray);
        case K::Rgbw2DArray:
        case K::Shadow2DArray: return make_array(cmd, TextureTarget::Tex2DArray);
    }
    return Error("unknown texture command");
}

Status run_texture_command(GLState& gl, TextureState& state, const TextureCommand& cmd) {
    if (cmd.unit < 0 || cmd.unit >= kMaxTextureUnits)
        return Error(fmt::format("texture unit {} is out of range: GL_MAX_TEXTURE_IMAGE_UNITS is {}", cmd.unit,
                                 kMaxTextureUnits));
    state.active_unit = cmd.unit;
    if (cmd.kind == TextureCommand::Kind::Checkerboard && cmd.level != 0) {
        // piglit binds a new texture whose only image is at `level`: it has no
        // level 0, so it is incomplete and samples as (0, 0, 0, 1), exactly
        // like an empty binding.
        gl.texture_units[size_t(cmd.unit)].bound[size_t(TextureTarget::Tex2D)] = nullptr;
        return Ok{};
    }
    auto texture = make_texture(cmd);
    if (!texture) return texture.error();
    return gl.bind_texture(cmd.unit, std::make_shared<const Texture>(std::move(*texture)));
}

Status run_texparameter(GLState& gl, const TextureState& state, const TexParameter& p) {
    TextureTarget target = to_target(p.target);
    auto& slot = gl.texture_units[size_t(state.active_unit)].bound[size_t(target)];
    if (!slot) return Ok{};
    // Bound textures are immutable (draws may share them), so change a copy.
    auto changed = std::make_shared<Texture>(*slot);
    if (auto st = apply(changed->sampler, p); !st) return st;
    slot = std::move(changed);
    return Ok{};
}

}  // namespace glslrun::piglit
