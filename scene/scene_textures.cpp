// [textures.N]: a texture object bound to unit N. Each key is one glTexImage
// or glTexParameter call (docs/scene-format.md); the texels come from an
// image file or a procedural pattern, and the finished glslrun::Texture is
// what both renderers use.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "scene/scene_reader.h"
#include "glslrun/scene/texture_images.h"

namespace glslrun::scene::detail {

namespace {

// Each list is in its enum's order (glslrun.h), so a choice's index is the value.
const std::vector<std::string_view> kTargets = {"1d", "2d", "3d", "cube_map", "rectangle", "1d_array", "2d_array"};
const std::vector<std::string_view> kFormats = {"rgba8", "rgba32f", "depth_component", "rgba16f"};
const std::vector<std::string_view> kFilters = {"nearest", "linear", "nearest_mipmap_nearest",
                                                "linear_mipmap_nearest", "nearest_mipmap_linear",
                                                "linear_mipmap_linear"};
const std::vector<std::string_view> kWraps = {"repeat", "clamp_to_edge", "clamp", "clamp_to_border",
                                              "mirrored_repeat"};
const std::vector<std::string_view> kDepthModes = {"luminance", "intensity", "alpha"};

// Where texels come from: exactly one per texture, or per cube face / level.
const std::vector<std::string_view> kImageSources = {"image", "checkerboard", "rgbw", "solid"};
const std::vector<std::string_view> kDepthKeys = {"compare_mode", "compare_func", "depth_texture_mode"};

const std::vector<std::string_view> kTextureKeys = {
    "target", "internal_format", "image", "checkerboard", "rgbw", "solid", "faces", "levels", "layers",
    "generate_mipmap", "min_filter", "mag_filter", "wrap_s", "wrap_t", "wrap_r", "border_color", "min_lod",
    "max_lod", "lod_bias", "base_level", "max_level", "compare_mode", "compare_func", "depth_texture_mode",
    "render_target", "attachment"};

// A render target's texture: its texels come from the passes, so no source,
// format or mipmaps (the attachment is level 0 of a 2D texture).
const std::vector<std::string_view> kTargetTextureKeys = {
    "render_target", "attachment", "min_filter", "mag_filter", "wrap_s", "wrap_t", "border_color", "min_lod",
    "max_lod", "lod_bias", "compare_mode", "compare_func", "depth_texture_mode"};

// The float formats of fewer channels: their storage and what they keep.
struct ChannelFormat {
    std::string_view name;
    TextureFormat storage;
    TextureChannels channels;
};
constexpr ChannelFormat kChannelFormats[] = {
    {"rgb16f", TextureFormat::RGBA16F, TextureChannels::Rgb},
    {"rgb32f", TextureFormat::RGBA32F, TextureChannels::Rgb},
    {"rg16f", TextureFormat::RGBA16F, TextureChannels::Rg},
    {"rg32f", TextureFormat::RGBA32F, TextureChannels::Rg},
    {"r16f", TextureFormat::RGBA16F, TextureChannels::Red},
    {"r32f", TextureFormat::RGBA32F, TextureChannels::Red},
    {"luminance16f", TextureFormat::RGBA16F, TextureChannels::Luminance},
    {"luminance32f", TextureFormat::RGBA32F, TextureChannels::Luminance},
    {"luminance_alpha16f", TextureFormat::RGBA16F, TextureChannels::LuminanceAlpha},
    {"luminance_alpha32f", TextureFormat::RGBA32F, TextureChannels::LuminanceAlpha},
    {"intensity16f", TextureFormat::RGBA16F, TextureChannels::Intensity},
    {"intensity32f", TextureFormat::RGBA32F, TextureChannels::Intensity},
    {"alpha16f", TextureFormat::RGBA16F, TextureChannels::Alpha},
    {"alpha32f", TextureFormat::RGBA32F, TextureChannels::Alpha},
};

// A texel as a format of `channels` keeps it and GL returns it (red for
// luminance and intensity, as glTexImage takes them from RGBA data).
glm::vec4 keep_channels(TextureChannels channels, glm::vec4 v) {
    switch (channels) {
    case TextureChannels::Rgba: return v;
    case TextureChannels::Rgb: return {v.r, v.g, v.b, 1.0f};
    case TextureChannels::Rg: return {v.r, v.g, 0.0f, 1.0f};
    case TextureChannels::Red: return {v.r, 0.0f, 0.0f, 1.0f};
    case TextureChannels::Luminance: return {v.r, v.r, v.r, 1.0f};
    case TextureChannels::LuminanceAlpha: return {v.r, v.r, v.r, v.a};
    case TextureChannels::Intensity: return glm::vec4(v.r);
    case TextureChannels::Alpha: return {0.0f, 0.0f, 0.0f, v.a};
    }
    return v;
}

// What every source of one texture needs to know.
struct Context {
    TextureTarget target = TextureTarget::Tex2D;
    TextureFormat format = TextureFormat::RGBA8;
    TextureChannels channels = TextureChannels::Rgba;
    std::string dir;  // the scene file's directory: image paths are relative to it
    std::vector<std::string>* files = nullptr;  // the image files read are added here
};

bool arrayed(TextureTarget t) { return t == TextureTarget::Tex1DArray || t == TextureTarget::Tex2DArray; }

// An array's layers are images of one dimension less: each layer of `layers`
// is read as a 1D or 2D texture's image.
TextureTarget layer_target(TextureTarget t) {
    return t == TextureTarget::Tex1DArray ? TextureTarget::Tex1D : t == TextureTarget::Tex2DArray ? TextureTarget::Tex2D : t;
}

int dimensions(TextureTarget t) {
    switch (t) {
    case TextureTarget::Tex1D: return 1;
    case TextureTarget::Tex3D: return 3;
    default: return 2;
    }
}

const char* size_form(TextureTarget t) {
    switch (t) {
    case TextureTarget::Tex1D: return "[width]";
    case TextureTarget::Tex3D: return "[width, height, depth]";
    default: return "[width, height]";
    }
}

// ------------------------------------------------------------ sources ---
// `size = [...]` of a procedural image, as many numbers as the target has
// dimensions, each within GL's maximum, all within kMaxTextureTexels.
Size3 read_size(const Section& s, const Context& c) {
    const toml::node& n = s.require("size", fmt::format("{} in texels", size_form(c.target)));
    int dims = dimensions(c.target);
    const toml::array* a = n.as_array();
    if (!a || int(a->size()) != dims)
        fail(n, fmt::format("'{}' must be {} for a {} texture (got {})", s.name("size"), size_form(c.target),
                            kTargets[size_t(c.target)], describe(n)));
    int max = c.target == TextureTarget::Tex3D ? kMax3DTextureSize
              : c.target == TextureTarget::Rect ? kMaxRectangleTextureSize : kMaxTextureSize;
    Size3 size{1, 1, 1};
    for (int i = 0; i < dims; ++i)
        size[size_t(i)] = int(integer((*a)[size_t(i)], fmt::format("{}[{}]", s.name("size"), i), 1, max));
    int64_t texels = int64_t(size[0]) * size[1] * size[2];
    if (texels > kMaxTextureTexels)
        fail(n, fmt::format("'{}' is {} texels; a texture may hold at most {}", s.name("size"), texels,
                            kMaxTextureTexels));
    return size;
}

// A colour for texels: 3 or 4 numbers, or one number for a grey (L, L, L, 1)
// as GL_LUMINANCE expands it (for a depth texture: the depth). Normalized
// formats store [0, 1] only, so other values would be silently clamped; the
// float formats store any (rgba16f rounds each to a half, past 65504 to
// infinity, as GL does).
glm::vec4 texel_color(const toml::node& n, const std::string& what, const Context& c) {
    glm::dvec4 v = n.is_number() ? glm::dvec4(glm::dvec3(number(n, what)), 1.0) : color(n, what);
    if (c.format == TextureFormat::RGBA32F || c.format == TextureFormat::RGBA16F) return glm::vec4(v);
    for (int i = 0; i < 4; ++i)
        if (v[i] < 0 || v[i] > 1)
            fail(n, fmt::format("'{}' must be in [0, 1]: {} stores no other values (internal_format = "
                                "\"rgba16f\" and \"rgba32f\" do); got {}", what, kFormats[size_t(c.format)], v[i]));
    return glm::vec4(v);
}

Size3 read_square_size(const Section& s, Size3 size, int dims) {
    Size3 square{1, 1, 1};
    for (int i = 0; i < dims; ++i) square[size_t(i)] = std::max(1, size[size_t(i)] / 8);  // 8 squares a side
    const toml::node* n = s.get("square_size");
    if (!n) return square;
    if (n->is_integer()) {
        int64_t v = integer(*n, s.name("square_size"), 1, kMaxTextureSize);
        for (int i = 0; i < dims; ++i) square[size_t(i)] = int(v);
        return square;
    }
    const toml::array* a = n->as_array();
    if (!a || int(a->size()) != dims)
        fail(*n, fmt::format("'{}' must be an integer or {} integers (got {})", s.name("square_size"), dims,
                             describe(*n)));
    for (int i = 0; i < dims; ++i)
        square[size_t(i)] = int(integer((*a)[size_t(i)], fmt::format("{}[{}]", s.name("square_size"), i), 1,
                                        kMaxTextureSize));
    return square;
}

TextureImage read_checkerboard(const Section& s, const Context& c) {
    s.allow({"size", "square_size", "colors"});
    Size3 size = read_size(s, c);
    Size3 square = read_square_size(s, size, dimensions(c.target));
    std::array<glm::vec4, 2> colors{glm::vec4(0, 0, 0, 1), glm::vec4(1, 1, 1, 1)};
    if (const toml::node* n = s.get("colors")) {
        const toml::array* a = n->as_array();
        if (!a || a->size() != 2)
            fail(*n, fmt::format("'{}' must be two colours (got {})", s.name("colors"), describe(*n)));
        for (size_t i = 0; i < 2; ++i)
            colors[i] = texel_color((*a)[i], fmt::format("{}[{}]", s.name("colors"), i), c);
    }
    return checkerboard_image(size, square, colors);
}

TextureImage read_rgbw(const Section& s, const Context& c) {
    s.allow({"size", "alpha"});
    Size3 size = read_size(s, c);
    bool alpha = false;
    s.read("alpha", alpha);
    return rgbw_image(size, dimensions(c.target), alpha);
}

TextureImage read_solid(const Section& s, const Context& c) {
    s.allow({"size", "color"});
    Size3 size = read_size(s, c);
    return solid_image(size, texel_color(s.require("color", "3 or 4 numbers, or one for a grey"),
                                         s.name("color"), c));
}

// 2D images are flipped so that the picture stands upright with t up; cube
// faces are not: GL's cube map face layout has t = 0 at the top of each face
// as seen from the centre, which is the first row of an image file.
TextureImage read_image_file(const toml::node& n, const std::string& what, const Context& c) {
    auto file = n.as_string();
    if (!file) fail(n, fmt::format("'{}' must be a file name (got {})", what, describe(n)));
    if (c.target == TextureTarget::Tex3D)
        fail(n, fmt::format("'{}': 3d textures take checkerboard, rgbw or solid, not image files", what));
    std::filesystem::path path(file->get());
    if (path.is_relative() && !c.dir.empty()) path = std::filesystem::path(c.dir) / path;
    if (c.files) c.files->push_back(path.string());
    Result<TextureImage> image = read_texture_image(path.string(), c.target != TextureTarget::Cube);
    if (!image) {
        // The scene's line first, then what is wrong with the file.
        Error e(fmt::format("'{}': cannot use the image", what), location(n).file, location(n).line);
        for (const Diagnostic& d : image.error().diagnostics) e.diagnostics.push_back(d);
        throw SceneFailure{std::move(e)};
    }
    if (c.target == TextureTarget::Tex1D && image->height != 1)
        fail(n, fmt::format("'{}' is {}x{}: a 1d texture needs an image 1 texel high", what, image->width,
                            image->height));
    return std::move(*image);
}

// The one source key present in `s` among `keys`, or nullptr.
const toml::key* source_key(const Section& s, const std::vector<std::string_view>& keys,
                            std::string_view needs) {
    const toml::key* found = nullptr;
    for (auto&& [k, v] : s.table()) {
        if (std::find(keys.begin(), keys.end(), k.str()) == keys.end()) continue;
        if (found)
            fail(k.source(), fmt::format("[{}] has both '{}' and '{}'; give one source of texels", s.path(),
                                         found->str(), k.str()));
        found = &k;
    }
    if (!found) fail(s.table(), fmt::format("[{}] needs {}", s.path(), needs));
    return found;
}

TextureImage with_channels(TextureImage image, const Context& c) {
    if (c.channels != TextureChannels::Rgba)
        for (glm::vec4& t : image.texels) t = keep_channels(c.channels, t);
    return image;
}

TextureImage read_image_source(const Section& s, std::string_view key, const Context& c) {
    const toml::node& n = *s.get(key);
    std::string what = s.name(key);
    if (key == "image") return with_channels(read_image_file(n, what, c), c);
    Section sub(table(n, what), what);
    if (key == "checkerboard") return with_channels(read_checkerboard(sub, c), c);
    if (key == "rgbw") return with_channels(read_rgbw(sub, c), c);
    return with_channels(read_solid(sub, c), c);
}

// All images of one texture together (faces, levels) stay within the limit
// each of them has alone.
void check_total(const toml::node& at, const std::string& texture, int64_t texels) {
    if (texels > kMaxTextureTexels)
        fail(at, fmt::format("[{}] holds {} texels in all; a texture may hold at most {}", texture, texels,
                             kMaxTextureTexels));
}

// An element of `faces` or `levels`: a file name, or a table with one source.
TextureImage read_element(const toml::node& n, const std::string& what, const Context& c) {
    if (n.is_string()) return with_channels(read_image_file(n, what, c), c);
    Section s(table(n, what), what);
    s.allow(kImageSources);
    const toml::key* k = source_key(s, kImageSources, "one of image, checkerboard, rgbw or solid");
    return read_image_source(s, k->str(), c);
}

std::vector<TextureImage> read_list(const Section& s, std::string_view key, const Context& c, size_t min,
                                    size_t max) {
    const toml::node& n = *s.get(key);
    const toml::array& a = array(n, s.name(key));
    if (a.size() < min || a.size() > max)
        fail(n, min == max ? fmt::format("'{}' must have {} elements (got {})", s.name(key), min, a.size())
                           : fmt::format("'{}' must have {} to {} elements (got {})", s.name(key), min, max,
                                         a.size()));
    std::vector<TextureImage> images;
    int64_t texels = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        images.push_back(read_element(a[i], fmt::format("{}[{}]", s.name(key), i), c));
        texels += int64_t(images.back().texels.size());
        check_total(a[i], s.path(), texels);  // before reading more
    }
    return images;
}

// ------------------------------------------------------------- target ---
Context read_context(const Section& s, const std::string& dir) {
    Context c;
    c.dir = dir;
    if (const toml::node* n = s.get("target")) {
        c.target = TextureTarget(choice(*n, s.name("target"), kTargets));
        if (s.get("faces") && c.target != TextureTarget::Cube)
            fail(*s.get("faces"), fmt::format("'{}' is for target = \"cube_map\" (this is \"{}\")",
                                              s.name("faces"), kTargets[size_t(c.target)]));
    } else if (s.get("faces")) {
        c.target = TextureTarget::Cube;  // six faces can only be a cube map
    }
    if (s.get("layers") && !arrayed(c.target))
        fail(*s.get("layers"), fmt::format("'{}' is for target = \"1d_array\" or \"2d_array\" (this is \"{}\")",
                                           s.name("layers"), kTargets[size_t(c.target)]));
    if (const toml::node* n = s.get("internal_format")) {
        std::vector<std::string_view> names = kFormats;
        for (const ChannelFormat& f : kChannelFormats) names.push_back(f.name);
        const size_t i = choice(*n, s.name("internal_format"), names);
        c.format = i < kFormats.size() ? TextureFormat(i) : kChannelFormats[i - kFormats.size()].storage;
        if (i >= kFormats.size()) c.channels = kChannelFormats[i - kFormats.size()].channels;
    }
    return c;
}

std::string first_message(const Error& e) {
    return e.diagnostics.empty() ? std::string("refused") : e.diagnostics[0].message;
}

// EXT_texture_array: `layers = [...]`, one image per layer (a file name or
// a source table, as a 1D or 2D texture's), all of one size, stacked into
// level 0 (a 1D array's layers are its rows, a 2D array's its slices).
// Mipmaps come from generate_mipmap.
Texture build_array_texture(const Section& s, const Context& c) {
    for (std::string_view key : {"image", "checkerboard", "rgbw", "solid", "levels"})
        if (const toml::node* n = s.get(key))
            fail(*n, fmt::format("'{}': an array texture takes its images from 'layers'{}", s.name(key),
                                 key == "levels" ? " (mipmaps: generate_mipmap = true)" : ""));
    if (!s.get("layers"))
        fail(s.table(), fmt::format("[{}] needs 'layers', one image per layer (target = \"{}\")", s.path(),
                                    kTargets[size_t(c.target)]));
    Context layer = c;
    layer.target = layer_target(c.target);
    std::vector<TextureImage> images = read_list(s, "layers", layer, 1, size_t(kMaxArrayTextureLayers));
    const toml::array& a = *s.get("layers")->as_array();
    TextureImage stacked{images[0].width, images[0].height, 1, {}};
    for (size_t i = 0; i < images.size(); ++i) {
        if (images[i].width != stacked.width || images[i].height != stacked.height)
            fail(a[i], fmt::format("'{}[{}]' is {}x{}; layer 0 is {}x{}: every layer has one size", s.name("layers"),
                                   i, images[i].width, images[i].height, stacked.width, stacked.height));
        stacked.texels.insert(stacked.texels.end(), images[i].texels.begin(), images[i].texels.end());
    }
    (c.target == TextureTarget::Tex1DArray ? stacked.height : stacked.depth) = int(images.size());
    Result<Texture> texture = Texture::create(c.target, {std::move(stacked)}, c.format);
    if (!texture) fail(*s.get("layers"), fmt::format("[{}]: {}", s.path(), first_message(texture.error())));
    return std::move(*texture);
}

// glTexImage for every face or level the file gives; Texture::create checks
// the sizes against the target (1D, square equal cube faces, GL's maxima).
Texture build_texture(const Section& s, const Context& c) {
    if (arrayed(c.target)) return build_array_texture(s, c);
    const toml::key* k = source_key(s, {"image", "checkerboard", "rgbw", "solid", "faces", "levels"},
                                    "a source of texels: image, checkerboard, rgbw, solid, faces (cube_map) "
                                    "or levels");
    std::string_view key = k->str();
    std::vector<TextureImage> level0, more_levels;
    if (key == "faces") {
        level0 = read_list(s, key, c, 6, 6);
    } else if (key == "levels") {
        if (c.target == TextureTarget::Cube)
            fail(*s.get(key), fmt::format("'{}': a cube_map takes 'faces' (mipmaps: generate_mipmap = true)",
                                          s.name(key)));
        more_levels = read_list(s, key, c, 1, 32);
        level0.push_back(std::move(more_levels.front()));
        more_levels.erase(more_levels.begin());
    } else {
        TextureImage image = read_image_source(s, key, c);
        size_t faces = c.target == TextureTarget::Cube ? 6 : 1;
        check_total(*s.get(key), s.path(), int64_t(image.texels.size() * faces));  // before the copies
        level0.assign(faces, image);
    }
    Result<Texture> texture = Texture::create(c.target, std::move(level0), c.format);
    if (!texture) fail(*s.get(key), fmt::format("[{}]: {}", s.path(), first_message(texture.error())));
    for (size_t i = 0; i < more_levels.size(); ++i)
        if (Status st = texture->set_level(0, int(i + 1), std::move(more_levels[i])); !st)
            fail(*s.get(key), fmt::format("'{}[{}]': {}", s.name(key), i + 1, first_message(st.error())));
    return std::move(*texture);
}

// ----------------------------------------------------------- sampling ---
void read_filters_and_wraps(const Section& s, SamplerState& st) {
    if (auto n = s.get("min_filter")) st.min_filter = TextureFilter(choice(*n, s.name("min_filter"), kFilters));
    // GL_TEXTURE_MAG_FILTER has no mipmap modes (GL_INVALID_ENUM).
    if (auto n = s.get("mag_filter"))
        st.mag_filter = TextureFilter(choice(*n, s.name("mag_filter"), {"nearest", "linear"}));
    if (auto n = s.get("wrap_s")) st.wrap_s = TextureWrap(choice(*n, s.name("wrap_s"), kWraps));
    if (auto n = s.get("wrap_t")) st.wrap_t = TextureWrap(choice(*n, s.name("wrap_t"), kWraps));
    if (auto n = s.get("wrap_r")) st.wrap_r = TextureWrap(choice(*n, s.name("wrap_r"), kWraps));
}

int read_level(const Section& s, std::string_view key, int fallback) {
    const toml::node* n = s.get(key);
    // GL_INVALID_VALUE below 0; GL takes any larger value.
    return n ? int(integer(*n, s.name(key), 0, INT32_MAX)) : fallback;
}

void read_border_color(const Section& s, SamplerState& st) {
    const toml::node* n = s.get("border_color");
    if (!n) return;
    glm::dvec4 v = color(*n, s.name("border_color"));
    // GL 2.1 clamps GL_TEXTURE_BORDER_COLOR to [0, 1]; outside is a mistake worth reporting.
    for (int i = 0; i < 4; ++i)
        check_range(*n, s.name("border_color"), v[i], {.lo = 0, .hi = 1, .why = "GL_TEXTURE_BORDER_COLOR"});
    st.border_color = glm::vec4(v);
}

void read_depth_state(const Section& s, const Context& c, SamplerState& st) {
    for (std::string_view key : kDepthKeys)
        if (const toml::node* n = s.get(key); n && c.format != TextureFormat::Depth)
            fail(*n, fmt::format("'{}' applies to depth textures only (internal_format = \"depth_component\")",
                                 s.name(key)));
    if (auto n = s.get("compare_mode"))
        st.compare = choice(*n, s.name("compare_mode"), {"none", "compare_r_to_texture"}) == 1;
    if (auto n = s.get("compare_func"))
        st.compare_func = CompareFunc(choice(*n, s.name("compare_func"), compare_func_names()));
    if (auto n = s.get("depth_texture_mode"))
        st.depth_mode = DepthTextureMode(choice(*n, s.name("depth_texture_mode"), kDepthModes));
}

SamplerState read_sampler(const Section& s, const Context& c) {
    SamplerState st;
    if (c.target == TextureTarget::Rect) {  // GL's initial state for rectangles, as Texture::create's
        st.min_filter = TextureFilter::Linear;
        st.wrap_s = st.wrap_t = st.wrap_r = TextureWrap::ClampToEdge;
    }
    read_filters_and_wraps(s, st);
    read_border_color(s, st);
    s.read("min_lod", st.min_lod);
    s.read("max_lod", st.max_lod);
    s.read("lod_bias", st.lod_bias);
    st.base_level = read_level(s, "base_level", st.base_level);
    st.max_level = read_level(s, "max_level", st.max_level);
    read_depth_state(s, c, st);
    return st;
}

bool is_mipmap_filter(TextureFilter f) { return f != TextureFilter::Nearest && f != TextureFilter::Linear; }

// ARB_texture_rectangle: what GL refuses for a rectangle (GL_INVALID_ENUM,
// GL_INVALID_VALUE) is refused here, with the key that asked for it.
void check_rectangle(const Section& s, const SamplerState& st) {
    for (std::string_view key : {"levels", "generate_mipmap"})
        if (const toml::node* n = s.get(key))
            fail(*n, fmt::format("'{}': a rectangle texture has no mipmaps", s.name(key)));
    if (const toml::node* n = s.get("min_filter"); n && is_mipmap_filter(st.min_filter))
        fail(*n, fmt::format("'{}' of a rectangle texture is \"nearest\" or \"linear\" (it has no mipmaps)",
                             s.name("min_filter")));
    for (std::string_view key : {"wrap_s", "wrap_t", "wrap_r"}) {
        const toml::node* n = s.get(key);
        if (n && (n->value_or(std::string_view{}) == "repeat" || n->value_or(std::string_view{}) == "mirrored_repeat"))
            fail(*n, fmt::format("'{}' of a rectangle texture is \"clamp\", \"clamp_to_edge\" or "
                                 "\"clamp_to_border\" (GL refuses \"{}\")", s.name(key), n->value_or(std::string_view{})));
    }
    if (const toml::node* n = s.get("base_level"); n && st.base_level != 0)
        fail(*n, fmt::format("'{}' of a rectangle texture is 0 (its only level)", s.name("base_level")));
}

// GL samples an incomplete texture as (0, 0, 0, 1) without a word; the most
// common cause is GL's default min filter on a texture without mipmaps.
void warn_if_incomplete(const Texture& t, int unit, const SourceLoc& where, Scene& scene) {
    if (t.complete()) return;
    std::string why = "its mipmap levels do not halve down to 1x1 (GL 2.1 section 3.8.10)";
    size_t base = size_t(t.sampler.base_level);
    if (base >= t.levels(0).size() || t.levels(0)[base].width == 0)
        why = fmt::format("base_level = {} has no image", base);
    else if (is_mipmap_filter(t.sampler.min_filter) && t.levels(0).size() == 1)
        why = fmt::format("min_filter = \"{}\"{} needs mipmaps; add generate_mipmap = true or set min_filter = "
                          "\"linear\"", kFilters[size_t(t.sampler.min_filter)],
                          t.sampler.min_filter == TextureFilter::NearestMipmapLinear ? " (GL's default)" : "");
    scene.warnings.push_back(Diagnostic{where.file, where.line,
                                        fmt::format("texture unit {} is incomplete and samples as (0, 0, 0, 1): {}",
                                                    unit, why),
                                        true});
}

// A render target's attachment, sampled: GL's texture object with the
// file's sampler state; the renderers replace its texels after each pass.
TextureSetting read_target_texture(const Section& s, int unit, Scene& scene) {
    s.allow(kTargetTextureKeys);
    TextureSetting setting;
    setting.unit = unit;
    setting.where = location(s.table());
    Texture texture = target_texture(s, scene, setting);
    Context c;
    c.format = texture.format();
    texture.sampler = read_sampler(s, c);
    if (auto n = s.get("min_filter"); is_mipmap_filter(texture.sampler.min_filter))
        fail(n ? *n : *s.get("render_target"),
             fmt::format("[{}]: a render target's texture has one level, so min_filter must be \"nearest\" or "
                         "\"linear\"{}", s.path(), n ? "" : " (GL's default, nearest_mipmap_linear, would make it "
                                                             "incomplete)"));
    setting.texture = std::make_shared<const Texture>(std::move(texture));
    return setting;
}

TextureSetting read_texture(const Section& s, int unit, const std::string& dir, Scene& scene) {
    if (s.get("render_target")) return read_target_texture(s, unit, scene);
    if (const toml::node* n = s.get("attachment"))
        fail(*n, fmt::format("'{}' needs render_target = \"NAME\"", s.name("attachment")));
    s.allow(kTextureKeys);
    Context c = read_context(s, dir);
    c.files = &scene.files;
    TextureSetting setting;
    setting.unit = unit;
    setting.where = location(s.table());
    s.read("generate_mipmap", setting.generate_mipmap);
    if (setting.generate_mipmap && s.get("levels"))
        fail(*s.get("levels"), fmt::format("[{}] has both 'levels' and generate_mipmap = true; give one",
                                           s.path()));
    SamplerState sampler = read_sampler(s, c);  // before the texels: cheap mistakes first
    if (c.target == TextureTarget::Rect) check_rectangle(s, sampler);
    Texture texture = build_texture(s, c);
    setting.channels = c.channels;
    texture.sampler = sampler;
    if (setting.generate_mipmap) texture.generate_mipmaps();
    warn_if_incomplete(texture, unit, setting.where, scene);
    setting.texture = std::make_shared<const Texture>(std::move(texture));
    return setting;
}

int64_t texel_count(const Texture& t) {
    int64_t count = 0;
    for (int face = 0; face < t.faces(); ++face)
        for (const TextureImage& level : t.levels(face)) count += int64_t(level.texels.size());
    return count;
}

}  // namespace

void read_texture_units(const toml::node& n, const std::string& what, const std::string& scene_dir, Scene& scene,
                        std::vector<TextureSetting>& out, int64_t& texels) {
    const toml::table& units = table(n, what);
    for (auto&& [k, v] : units) {
        int unit = index_key(k, kMaxTextureUnits, what,
                             "texture units are 0..15 ([textures.0] .. [textures.15], GL_TEXTURE0..15)");
        std::string unit_what = fmt::format("{}.{}", what, unit);
        Section s(table(v, unit_what), unit_what);
        if (&out != &scene.textures && s.get("render_target"))
            fail(*s.get("render_target"), fmt::format("'{}': a render target's texture is bound in [textures.N], "
                                                      "for the whole scene", s.name("render_target")));
        out.push_back(read_texture(s, unit, scene_dir, scene));
        texels += texel_count(*out.back().texture);
        if (texels > kMaxSceneTexels)
            fail(v, fmt::format("the textures up to [{}] hold {} texels in all, mipmaps included; a scene may hold "
                                "at most {} (docs/limits.md)",
                                unit_what, texels, kMaxSceneTexels));
    }
    std::sort(out.begin(), out.end(), [](const TextureSetting& a, const TextureSetting& b) { return a.unit < b.unit; });
}

void read_textures(const toml::node& n, const std::string& scene_dir, Scene& scene) {
    int64_t texels = 0;
    read_texture_units(n, "textures", scene_dir, scene, scene.textures, texels);
}

}  // namespace glslrun::scene::detail
