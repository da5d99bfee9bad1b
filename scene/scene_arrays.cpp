// mesh = "arrays": vertex arrays given inline, as a program hands them to
// glVertexPointer, glNormalPointer, glColorPointer, ... and glDrawArrays or
// glDrawElements with any GL 2.1 primitive type (docs/scene-format.md).
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

// Names as the scene gives them, in Primitive's order (GL_POINTS .. GL_POLYGON).
const std::vector<std::string_view> kPrimitives = {"points",         "lines",          "line_strip", "line_loop",
                                                   "triangles",      "triangle_strip", "triangle_fan", "quads",
                                                   "quad_strip",     "polygon"};

// Vertices one array may hold: checked before its values are converted.
constexpr size_t kMaxArrayVertices = size_t(1) << 22;

// One conventional array, with the component counts GL 2.1's pointer call takes.
struct BuiltinArray {
    std::string_view key, attribute;
    uint32_t min_components, max_components;
    const char* call;
};
const BuiltinArray kArrays[] = {
    {"normals", "gl_Normal", 3, 3, "glNormalPointer"},
    {"colors", "gl_Color", 3, 4, "glColorPointer"},
    {"secondary_colors", "gl_SecondaryColor", 3, 3, "glSecondaryColorPointer"},
    {"fog_coords", "gl_FogCoord", 1, 1, "glFogCoordPointer"},
};

void add_array(Mesh& mesh, const toml::node& n, std::string_view attribute, const std::string& what,
               uint32_t lo, uint32_t hi, const char* call) {
    VertexAttrib a = read_attribute(n, std::string(attribute), what, mesh.vertex_count);
    if (a.components < lo || a.components > hi)
        fail(n, lo == hi ? fmt::format("'{}' needs {} components per vertex ({}); got {}", what, lo, call, a.components)
                         : fmt::format("'{}' needs {} to {} components per vertex ({}); got {}", what, lo, hi, call,
                                       a.components));
    mesh.attribs.push_back(std::move(a));
}

// tex_coords: one array (unit 0), or a table of units 0..7 to arrays.
void read_tex_coords(const Section& s, Mesh& mesh) {
    const toml::node* n = s.get("tex_coords");
    if (!n) return;
    if (!n->is_table()) {
        add_array(mesh, *n, "gl_MultiTexCoord0", s.name("tex_coords"), 1, 4, "glTexCoordPointer");
        return;
    }
    for (auto&& [k, v] : *n->as_table()) {
        std::string what = s.name("tex_coords") + "." + std::string(k.str());
        int unit = index_key(k, 8, s.name("tex_coords"), "texture coordinate sets are 0..7 (gl_MultiTexCoord0..7)");
        add_array(mesh, v, fmt::format("gl_MultiTexCoord{}", unit), what, 1, 4, "glTexCoordPointer");
    }
}

void read_indices(const Section& s, Mesh& mesh) {
    const toml::node* n = s.get("indices");
    if (!n) return;
    const toml::array& list = array(*n, s.name("indices"));
    if (list.size() > kMaxArrayVertices)
        fail(*n, fmt::format("'{}' has {} indices; at most {}", s.name("indices"), list.size(), kMaxArrayVertices));
    mesh.indices.reserve(list.size());
    for (size_t i = 0; i < list.size(); ++i) {
        const toml::node& e = list[i];
        auto v = e.as_integer();
        std::string what = fmt::format("{}[{}]", s.name("indices"), i);
        if (!v) fail(e, fmt::format("'{}' must be an integer (got {})", what, describe(e)));
        if (v->get() < 0 || v->get() >= int64_t(mesh.vertex_count))
            fail(e, fmt::format("'{}' = {} is out of range: the arrays have {} vertices (0..{})", what, v->get(),
                                mesh.vertex_count, mesh.vertex_count - 1));
        mesh.indices.push_back(uint32_t(v->get()));
    }
}

}  // namespace

const std::vector<std::string_view>& array_mesh_keys() {
    static const std::vector<std::string_view> keys = {"primitive", "vertices", "normals", "colors",
                                                       "secondary_colors", "tex_coords", "fog_coords", "indices"};
    return keys;
}

Mesh read_array_mesh(const Section& s) {
    Mesh mesh;
    const toml::node& vertices = s.require("vertices", "the positions, [[x, y], ...] to [[x, y, z, w], ...]");
    const toml::array& list = array(vertices, s.name("vertices"));
    if (list.empty() || list.size() > kMaxArrayVertices)
        fail(vertices, fmt::format("'{}' has {} vertices; arrays hold 1..{}", s.name("vertices"), list.size(),
                                   kMaxArrayVertices));
    mesh.vertex_count = uint32_t(list.size());
    if (const toml::node* p = s.get("primitive")) mesh.primitive = Primitive(choice(*p, s.name("primitive"), kPrimitives));
    add_array(mesh, vertices, "gl_Vertex", s.name("vertices"), 2, 4, "glVertexPointer");
    for (const BuiltinArray& a : kArrays)
        if (const toml::node* n = s.get(a.key))
            add_array(mesh, *n, a.attribute, s.name(a.key), a.min_components, a.max_components, a.call);
    read_tex_coords(s, mesh);
    read_indices(s, mesh);
    return mesh;
}

}  // namespace glslrun::scene::detail
