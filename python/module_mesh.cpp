// Scenes from numpy arrays: Scene() with GL's defaults, meshes added from
// position, normal, texture coordinate and colour arrays (with indices), and
// textures from image arrays, so that Python draws without a scene file. The
// GL state itself comes from Scene.parse's TOML (docs/scene-format.md).
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glslrun/scene/meshes.h"
#include "module.h"

namespace glslrun::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// Primitive's names as scene files write them, in Primitive's order.
const char* const kPrimitives[] = {"points",        "lines",          "line_strip", "line_loop",
                                   "triangles",     "triangle_strip", "triangle_fan", "quads",
                                   "quad_strip",    "polygon"};

Primitive parse_primitive(const std::string& name) {
    std::string all;
    for (size_t i = 0; i < std::size(kPrimitives); ++i) {
        if (name == kPrimitives[i]) return Primitive(i);
        all += (i ? ", " : "") + std::string(kPrimitives[i]);
    }
    throw py::value_error("primitive '" + name + "' is not one of " + all);
}

// An (n, components) float array as the attribute `attribute`; components
// within lo..hi (GL's pointer call's sizes).
VertexAttrib attribute(const std::string& what, const std::string& attribute, const py::object& value, uint32_t lo,
                       uint32_t hi, int64_t rows) {
    FloatArray a = FloatArray::ensure(value);
    if (!a || a.ndim() != 2 || a.shape(1) < lo || a.shape(1) > hi || (rows >= 0 && a.shape(0) != rows))
        throw py::value_error(what + " must be an array of shape (" + (rows >= 0 ? std::to_string(rows) : "n") +
                              ", " + std::to_string(lo) + (lo == hi ? "" : ".." + std::to_string(hi)) + ")");
    return {attribute, uint32_t(a.shape(1)), std::vector<float>(a.data(), a.data() + a.size())};
}

std::vector<uint32_t> index_list(const py::object& value, uint32_t vertices) {
    py::array any = py::array::ensure(value);
    if (!any || any.ndim() != 1 || (any.dtype().kind() != 'i' && any.dtype().kind() != 'u'))
        throw py::value_error("indices must be a 1-D array of integers");
    auto a = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(any);
    std::vector<uint32_t> out(size_t(a.size()));
    for (size_t i = 0; i < out.size(); ++i) {
        int64_t v = a.data()[i];
        if (v < 0 || v >= int64_t(vertices))
            throw py::value_error("indices[" + std::to_string(i) + "] = " + std::to_string(v) + " is not a vertex (0.." +
                                  std::to_string(vertices - 1) + ")");
        out[i] = uint32_t(v);
    }
    return out;
}

size_t add_mesh(scene::Scene& s, const py::object& positions, const py::object& normals, const py::object& texcoords,
                const py::object& colors, const py::object& indices, const std::string& primitive,
                const py::object& uniforms) {
    if (!s.passes.empty())
        throw py::value_error("the scene has [[passes]], which list the objects they draw: add_mesh adds to scenes "
                              "without passes");
    scene::Object object;
    object.name = "objects[" + std::to_string(s.objects.size()) + "]";
    scene::Mesh& mesh = object.mesh;
    mesh.primitive = parse_primitive(primitive);
    mesh.attribs.push_back(attribute("positions", "gl_Vertex", positions, 2, 4, -1));
    mesh.vertex_count = uint32_t(mesh.attribs[0].data.size() / mesh.attribs[0].components);
    uint64_t total = mesh.vertex_count;
    for (const scene::Object& o : s.objects) total += o.mesh.vertex_count;
    if (s.objects.size() >= scene::kMaxSceneObjects || total > scene::kMaxSceneVertices)
        throw py::value_error("a scene holds at most " + std::to_string(scene::kMaxSceneObjects) + " objects and " +
                              std::to_string(scene::kMaxSceneVertices) + " vertices in all (docs/limits.md)");
    const int64_t n = mesh.vertex_count;
    if (!normals.is_none()) mesh.attribs.push_back(attribute("normals", "gl_Normal", normals, 3, 3, n));
    if (!texcoords.is_none())
        mesh.attribs.push_back(attribute("texcoords", "gl_MultiTexCoord0", texcoords, 1, 4, n));
    if (!colors.is_none()) mesh.attribs.push_back(attribute("colors", "gl_Color", colors, 3, 4, n));
    if (!indices.is_none()) mesh.indices = index_list(indices, mesh.vertex_count);
    object.uniforms = uniform_settings(uniforms, "add_mesh uniforms");
    s.objects.push_back(std::move(object));
    return s.objects.size() - 1;
}

TextureWrap parse_wrap(const std::string& name) {
    if (name == "repeat") return TextureWrap::Repeat;
    if (name == "clamp_to_edge") return TextureWrap::ClampToEdge;
    if (name == "clamp") return TextureWrap::Clamp;
    if (name == "clamp_to_border") return TextureWrap::ClampToBorder;
    if (name == "mirrored_repeat") return TextureWrap::MirroredRepeat;
    throw py::value_error("wrap '" + name + "' is not one of repeat, clamp_to_edge, clamp, clamp_to_border, "
                          "mirrored_repeat");
}

// An H x W x {1, 3, 4} image (uint8: n/255 into RGBA8; float32: RGBA32F) as
// A rectangle texture (target "rectangle") has no mipmaps and clamps; its
// defaults are GL's for rectangles, and asking for what GL refuses is an error.
void rectangle_options(const std::optional<std::string>& wrap, std::optional<bool>& mipmaps) {
    if (mipmaps.value_or(false)) throw py::value_error("a rectangle texture has no mipmaps: mipmaps must be False");
    if (wrap && (*wrap == "repeat" || *wrap == "mirrored_repeat"))
        throw py::value_error("a rectangle texture's wrap is clamp_to_edge, clamp or clamp_to_border, not " + *wrap);
    mipmaps = false;
}

// set_texture's targets, by their names in scene files.
TextureTarget parse_texture_target(const std::string& name) {
    if (name == "2d") return TextureTarget::Tex2D;
    if (name == "rectangle") return TextureTarget::Rect;
    if (name == "1d_array") return TextureTarget::Tex1DArray;
    if (name == "2d_array") return TextureTarget::Tex2DArray;
    throw py::value_error("target '" + name + "' is not one of 2d, rectangle, 1d_array, 2d_array");
}

// The image of set_texture as level 0: an H x W picture (2d, rectangle), L
// layers of a W-texel row (1d_array: layer l is row l) or of an H x W
// picture (2d_array), each with an optional last axis of 1, 3 or 4
// channels; a picture's row 0 is its top unless `top_down`. Sizes are
// checked on the array as given, before anything is copied.
TextureImage texture_level(TextureTarget target, const py::array& any, bool bytes, bool top_down) {
    const int grid = target == TextureTarget::Tex2DArray ? 3 : 2;  // the axes before the channels
    const bool layered = target == TextureTarget::Tex1DArray || target == TextureTarget::Tex2DArray;
    const char* shape = target == TextureTarget::Tex1DArray   ? "L x W (luminance), L x W x 3 or L x W x 4 (L layers)"
                        : target == TextureTarget::Tex2DArray ? "L x H x W, L x H x W x 3 or L x H x W x 4 (L layers)"
                                                              : "H x W, H x W x 3 or H x W x 4";
    bool ok = any.ndim() == grid || any.ndim() == grid + 1;
    for (int axis = 0; ok && axis < grid; ++axis) {
        const bool layers = layered && axis == 0;
        ok = any.shape(axis) >= 1 && any.shape(axis) <= (layers ? kMaxArrayTextureLayers : kMaxTextureSize);
    }
    if (ok && any.ndim() == grid + 1) ok = any.shape(grid) == 1 || any.shape(grid) == 3 || any.shape(grid) == 4;
    if (!ok)
        throw py::type_error(std::string("a texture is an ") + shape + " array of uint8 or floats, each side 1.." +
                             std::to_string(kMaxTextureSize) + (layered ? ", layers 1.." +
                             std::to_string(kMaxArrayTextureLayers) : std::string()));
    const int layers = layered ? int(any.shape(0)) : 1;
    const int h = target == TextureTarget::Tex1DArray ? 1 : int(any.shape(grid - 2));
    const int w = int(any.shape(grid - 1)), c = any.ndim() == grid + 1 ? int(any.shape(grid)) : 1;
    if (int64_t(layers) * h * w > scene::kMaxTextureTexels)
        throw py::value_error("a texture holds at most " + std::to_string(scene::kMaxTextureTexels) +
                              " texels, layers included (docs/limits.md)");
    FloatArray a = FloatArray::ensure(any);
    const float scale = bytes ? 1.0f / 255.0f : 1.0f;
    TextureImage level{w, target == TextureTarget::Tex1DArray ? layers : h,
                       target == TextureTarget::Tex2DArray ? layers : 1,
                       std::vector<glm::vec4>(size_t(layers) * size_t(h) * size_t(w))};
    for (int l = 0; l < layers; ++l)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t at = (size_t(l) * size_t(h) + size_t(y)) * size_t(w) + size_t(x);
                const float* p = a.data() + at * size_t(c);
                glm::vec4 t = c == 1 ? glm::vec4(p[0], p[0], p[0], 1) : glm::vec4(p[0], p[1], p[2], c == 4 ? p[3] : 1);
                const size_t row = size_t(top_down ? y : h - 1 - y);
                level.texels[(size_t(l) * size_t(h) + row) * size_t(w) + size_t(x)] =
                    t * glm::vec4(scale, scale, scale, c == 4 ? scale : 1);
            }
    return level;
}

// A 2D, rectangle or array texture on `unit`.
void set_texture(scene::Scene& s, int unit, const py::object& image, bool linear, std::optional<std::string> wrap,
                 std::optional<bool> mipmaps_opt, bool top_down, const std::string& target_name) {
    const TextureTarget target = parse_texture_target(target_name);
    if (target == TextureTarget::Rect) rectangle_options(wrap, mipmaps_opt);
    const bool mipmaps = mipmaps_opt.value_or(true);
    if (unit < 0 || unit >= kMaxTextureUnits)
        throw py::value_error("texture units are 0.." + std::to_string(kMaxTextureUnits - 1));
    py::array any = py::array::ensure(image);
    char kind = any ? any.dtype().kind() : 'O';
    bool bytes = kind == 'u' && any.itemsize() == 1;
    if (!any || (!bytes && kind != 'f'))
        throw py::type_error("a texture is an array of uint8 or floats (H x W, H x W x 3 or H x W x 4; arrays: a "
                             "leading axis of layers)");
    Texture texture = take(Texture::create(target, {texture_level(target, any, bytes, top_down)},
                                           bytes ? TextureFormat::RGBA8 : TextureFormat::RGBA32F));
    if (mipmaps) texture.generate_mipmaps();
    texture.sampler.mag_filter = linear ? TextureFilter::Linear : TextureFilter::Nearest;
    texture.sampler.min_filter = mipmaps ? (linear ? TextureFilter::LinearMipmapLinear : TextureFilter::NearestMipmapNearest)
                                         : texture.sampler.mag_filter;
    texture.sampler.wrap_s = texture.sampler.wrap_t =
        wrap ? parse_wrap(*wrap) : target == TextureTarget::Rect ? TextureWrap::ClampToEdge : TextureWrap::Repeat;
    scene::TextureSetting setting{unit, std::make_shared<const Texture>(std::move(texture)),
                                  scene::TextureChannels::Rgba, mipmaps, -1, 0,
                                  {"set_texture", 0}};
    for (scene::TextureSetting& t : s.textures)
        if (t.unit == unit) {
            t = std::move(setting);
            return;
        }
    s.textures.push_back(std::move(setting));
    std::sort(s.textures.begin(), s.textures.end(),
              [](const scene::TextureSetting& a, const scene::TextureSetting& b) { return a.unit < b.unit; });
}

}  // namespace

void bind_mesh(py::module_& m) {
    py::class_<scene::Scene> scene = py::reinterpret_borrow<py::class_<scene::Scene>>(m.attr("Scene"));
    scene.def(py::init<>(),
              "An empty 512 x 512 scene in OpenGL 2.1's default state (identity camera, no object); "
              "Scene.parse(toml) gives one with state of its own.");
    scene.def("add_mesh", &add_mesh, py::arg("positions"), py::kw_only(), py::arg("normals") = py::none(),
              py::arg("texcoords") = py::none(), py::arg("colors") = py::none(), py::arg("indices") = py::none(),
              py::arg("primitive") = "triangles", py::arg("uniforms") = py::none(),
              "Adds an object drawn from numpy arrays, as glVertexPointer & co. and glDrawElements would: positions "
              "(n, 2..4) as gl_Vertex, normals (n, 3) as gl_Normal, texcoords (n, 1..4) as gl_MultiTexCoord0, "
              "colors (n, 3..4) as gl_Color, indices (m,) into them (None: vertices in order), primitive as in scene "
              "files (\"triangles\", \"triangle_strip\", \"lines\", ...), uniforms ({name: value}) for this object. "
              "Its model matrix is the identity: transform positions in numpy. Returns the object's index.");
    scene.def("set_texture", &set_texture, py::arg("unit"), py::arg("image"), py::kw_only(), py::arg("linear") = true,
              py::arg("wrap") = py::none(), py::arg("mipmaps") = py::none(), py::arg("top_down") = false,
              py::arg("target") = "2d",
              "Binds an image array to texture unit `unit` as a 2D texture (target=\"rectangle\": a rectangle "
              "texture, sampler2DRect, addressed in texels, without mipmaps, wrap clamp_to_edge unless given): "
              "H x W (luminance), H x W x 3 or H x W x 4; target=\"2d_array\" or \"1d_array\": "
              "EXT_texture_array's sampler2DArray and sampler1DArray, the array with a leading axis of L layers "
              "(L x H x W[ x C], a list of L images works too; L x W[ x C] for 1d_array, layer l its row l), "
              "mipmaps generated per layer; "
              "uint8 as n/255 into RGBA8, floats into RGBA32F. Row 0 of the array is the top of the picture, so "
              "t = 0 is its bottom row (top_down=True: row 0 at t = 0). mipmaps generates every level (GL's default "
              "minifying filter needs them; without, the filter is linear or nearest; default True for 2d); wrap is "
              "repeat (the 2d default), clamp_to_edge, clamp, clamp_to_border or mirrored_repeat.");
}

}  // namespace glslrun::python
