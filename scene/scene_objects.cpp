// [[objects]]: a mesh (built-in or OBJ), its model transform, glColor,
// material overrides, uniforms and user attributes.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "glslrun/scene/meshes.h"
#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

// The keys each mesh kind takes besides the common ones; giving a sphere a
// `size` is a mistake worth naming rather than ignoring.
struct MeshKind {
    std::string_view name;
    std::vector<std::string_view> params;
};
const std::vector<MeshKind>& mesh_kinds() {
    static const std::vector<MeshKind> kinds = {
        {"teapot", {"size", "subdivisions"}},
        {"quad", {}},
        {"cube", {"size"}},
        {"sphere", {"radius", "slices", "stacks"}},
        {"torus", {"inner_radius", "outer_radius", "sides", "rings"}},
        {"plane", {"size", "subdivisions"}},
        {"obj", {"file"}},
        {"arrays", array_mesh_keys()},
    };
    return kinds;
}

const std::vector<std::string_view> kCommonKeys = {
    "name", "mesh", "transform", "color", "vertex_colors", "material", "front_material",
    "back_material", "uniforms", "attributes", "state", "textures"};

std::vector<std::string_view> all_object_keys() {
    std::vector<std::string_view> keys = kCommonKeys;
    for (const MeshKind& k : mesh_kinds())
        for (std::string_view p : k.params)
            if (std::find(keys.begin(), keys.end(), p) == keys.end()) keys.push_back(p);
    return keys;
}

const MeshKind& mesh_kind(const Section& s) {
    const toml::node& n = s.require("mesh", "teapot, quad, cube, sphere, torus, plane, obj or arrays");
    std::vector<std::string_view> names;
    for (const MeshKind& k : mesh_kinds()) names.push_back(k.name);
    return mesh_kinds()[choice(n, s.name("mesh"), names)];
}

// A parameter of another mesh kind ("radius" on a teapot) is an error.
void check_params(const Section& s, const MeshKind& kind) {
    for (auto&& [k, v] : s.table()) {
        bool common = std::find(kCommonKeys.begin(), kCommonKeys.end(), k.str()) != kCommonKeys.end();
        bool own = std::find(kind.params.begin(), kind.params.end(), k.str()) != kind.params.end();
        if (common || own) continue;
        std::string takes = kind.params.empty() ? std::string("no parameters")
                                                : fmt::format("{}", fmt::join(kind.params, ", "));
        fail(k.source(),
             fmt::format("'{}' does not apply to mesh '{}' (it takes {})", k.str(), kind.name, takes));
    }
}

double positive(const Section& s, std::string_view key, double fallback) {
    const toml::node* n = s.get(key);
    if (!n) return fallback;
    double v = number(*n, s.name(key));
    check_range(*n, s.name(key), v, {.lo = 0, .lo_open = true});
    return v;
}

int count(const Section& s, std::string_view key, int fallback, int min, int max = kMaxSubdivisions) {
    const toml::node* n = s.get(key);
    return n ? int(integer(*n, s.name(key), min, max)) : fallback;
}

Mesh load_obj_mesh(const Section& s, const std::string& scene_dir, const std::string& object,
                   std::vector<std::string>& files) {
    const toml::node& n = s.require("file", "the OBJ file, relative to the scene file");
    auto file = n.as_string();
    if (!file) fail(n, fmt::format("'{}' must be a file name (got {})", s.name("file"), describe(n)));
    std::filesystem::path path(file->get());
    if (path.is_relative() && !scene_dir.empty()) path = std::filesystem::path(scene_dir) / path;
    files.push_back(path.string());
    Result<Mesh> mesh = load_obj(path.string());
    if (mesh) return std::move(*mesh);
    // The scene's line first (which object), then the loader's own diagnostics.
    Error e(fmt::format("object '{}': cannot load the mesh file '{}'", object, path.string()),
            location(n).file, location(n).line);
    for (const Diagnostic& d : mesh.error().diagnostics) e.diagnostics.push_back(d);
    throw SceneFailure{std::move(e)};
}

Mesh build_mesh(const Section& s, const MeshKind& kind, const std::string& scene_dir,
                const std::string& object, std::vector<std::string>& files) {
    std::string_view k = kind.name;
    if (k == "teapot") return make_teapot(positive(s, "size", 1.0), count(s, "subdivisions", 10, 1, kMaxTeapotSubdivisions));
    if (k == "quad") return make_lecture_quad();
    if (k == "cube") return make_cube(positive(s, "size", 1.0));
    if (k == "sphere")
        return make_sphere(positive(s, "radius", 1.0), count(s, "slices", 32, 3), count(s, "stacks", 16, 2));
    if (k == "torus")
        return make_torus(positive(s, "inner_radius", 0.25), positive(s, "outer_radius", 1.0),
                          count(s, "sides", 16, 3), count(s, "rings", 32, 3));
    if (k == "plane") return make_plane(positive(s, "size", 1.0), count(s, "subdivisions", 1, 1));
    if (k == "arrays") return read_array_mesh(s);
    return load_obj_mesh(s, scene_dir, object, files);
}

// [objects.material] is glMaterial(GL_FRONT_AND_BACK) for this object, then
// the sided tables; they start from the scene's materials.
void read_object_materials(const Section& s, const Scene& scene, Object& object) {
    for (std::string_view key : {"material", "front_material", "back_material"}) {
        const toml::node* n = s.get(key);
        if (!n) continue;
        Section m(table(*n, s.name(key)), s.name(key));
        if (key != "back_material") {
            if (!object.front_material) object.front_material = scene.gl.front_material;
            read_material(m, *object.front_material);
        }
        if (key != "front_material") {
            if (!object.back_material) object.back_material = scene.gl.back_material;
            read_material(m, *object.back_material);
        }
    }
}

void read_vertex_colors(const Section& s, Mesh& mesh) {
    const toml::node* n = s.get("vertex_colors");
    if (n && choice(*n, s.name("vertex_colors"), {"normal"}) == 0) add_normal_colors(mesh);
}

std::string object_name(const Section& s, size_t index) {
    const toml::node* n = s.get("name");
    if (!n) return fmt::format("objects[{}]", index);
    auto str = n->as_string();
    if (!str) fail(*n, fmt::format("'{}' must be a string (got {})", s.name("name"), describe(*n)));
    return str->get();
}

Object read_object(const toml::node& n, size_t index, const std::string& scene_dir, const Scene& scene,
                   std::vector<std::string>& files) {
    std::string what = fmt::format("objects[{}]", index);
    Section s(table(n, what), what);
    s.allow(all_object_keys());
    const MeshKind& kind = mesh_kind(s);
    check_params(s, kind);
    Object object;
    object.name = object_name(s, index);
    object.where = location(n);
    object.mesh = build_mesh(s, kind, scene_dir, object.name, files);
    read_vertex_colors(s, object.mesh);
    if (auto t = s.get("transform")) object.model = glm::mat4(transform_list(*t, s.name("transform")));
    if (auto c = s.get("color")) object.color = glm::vec4(color(*c, s.name("color")));
    read_object_materials(s, scene, object);
    if (auto u = s.get("uniforms")) read_uniforms(*u, s.name("uniforms"), object.uniforms);
    if (auto a = s.get("attributes"))
        for (VertexAttrib& attrib : read_attributes(*a, s.name("attributes"), object.mesh.vertex_count))
            object.mesh.attribs.push_back(std::move(attrib));
    return object;
}

}  // namespace

void read_objects(const toml::node& n, const std::string& scene_dir, Scene& scene) {
    const toml::array* list = n.as_array();
    if (!list || (!list->empty() && !list->is_array_of_tables()))
        fail(n, fmt::format("'objects' must be an array of tables ([[objects]]) (got {})", describe(n)));
    if (list->size() > kMaxSceneObjects)
        fail(n, fmt::format("the scene has {} objects; a scene may have at most {} (docs/limits.md)", list->size(),
                            kMaxSceneObjects));
    uint64_t vertices = 0;
    int64_t texels = 0;
    for (const TextureSetting& t : scene.textures)
        for (int face = 0; face < t.texture->faces(); ++face)
            for (const TextureImage& level : t.texture->levels(face)) texels += int64_t(level.texels.size());
    for (size_t i = 0; i < list->size(); ++i) {
        std::vector<std::string> files;
        scene.objects.push_back(read_object((*list)[i], i, scene_dir, scene, files));
        scene.files.insert(scene.files.end(), files.begin(), files.end());
        // glBindTexture before this object's draw: its own texture objects.
        if (const toml::node* t = (*list)[i].as_table()->get("textures"))
            read_texture_units(*t, fmt::format("objects[{}].textures", i), scene_dir, scene,
                               scene.objects.back().textures, texels);
        vertices += scene.objects.back().mesh.vertex_count;
        if (vertices > kMaxSceneVertices)
            fail((*list)[i], fmt::format("the objects up to objects[{}] have {} vertices in all; a scene may have at "
                                         "most {} (docs/limits.md)",
                                         i, vertices, kMaxSceneVertices));
    }
}

void read_object_states(const toml::node& n, Scene& scene) {
    const toml::array& list = *n.as_array();  // read_objects checked it
    for (size_t i = 0; i < list.size() && i < scene.objects.size(); ++i) {
        const toml::node* state = list[i].as_table()->get("state");
        if (!state) continue;
        std::string what = fmt::format("objects[{}].state", i);
        GLState gl = scene.gl;
        read_state_section(Section(table(*state, what), what), scene.view, gl);
        scene.objects[i].state = std::move(gl);
    }
}

}  // namespace glslrun::scene::detail
