// [[passes]]: an ordered list of passes over the scene's objects, each with
// its own program (shader files), render state and uniforms.
#include <filesystem>

#include <fmt/format.h>

#include "glslrun/scene/meshes.h"
#include "scene/scene_reader.h"
#include "scene/text_file.h"

namespace glslrun::scene::detail {

namespace {

std::string pass_name(const Section& s, size_t index) {
    const toml::node* n = s.get("name");
    if (!n) return fmt::format("passes[{}]", index);
    auto str = n->as_string();
    if (!str) fail(*n, fmt::format("'{}' must be a string (got {})", s.name("name"), describe(*n)));
    return str->get();
}

// One file name or a list of them, each read as one shader source named by its path.
std::vector<ShaderSource> read_shaders(const Section& s, std::string_view key, const std::string& scene_dir) {
    const toml::node* n = s.get(key);
    if (!n) return {};
    std::vector<const toml::node*> names;
    if (const toml::array* list = n->as_array())
        for (const toml::node& e : *list) names.push_back(&e);
    else
        names.push_back(n);
    if (names.empty()) fail(*n, fmt::format("'{}' names no shader file", s.name(key)));
    std::vector<ShaderSource> sources;
    for (const toml::node* name : names) {
        auto file = name->as_string();
        if (!file)
            fail(*name, fmt::format("'{}' must be a shader file name or a list of them (got {})", s.name(key),
                                    describe(*name)));
        std::filesystem::path path(file->get());
        if (path.is_relative() && !scene_dir.empty()) path = std::filesystem::path(scene_dir) / path;
        Result<std::string> text = read_text_file(path.string(), "shader");
        if (!text) {
            Error e(fmt::format("'{}': cannot read the shader", s.name(key)), location(*name).file,
                    location(*name).line);
            for (const Diagnostic& d : text.error().diagnostics) e.diagnostics.push_back(d);
            throw SceneFailure{std::move(e)};
        }
        sources.push_back({path.string(), std::move(*text)});
    }
    return sources;
}

// `objects = ["floor", "teapot", "floor"]`: the objects of those names in
// the list's order, as a program's draw calls; a name listed twice is drawn
// twice. A name several objects share draws each of them, in scene order.
std::vector<size_t> pass_objects(const Section& s, const Scene& scene) {
    const toml::node* n = s.get("objects");
    std::vector<size_t> picked;
    if (!n) {
        for (size_t i = 0; i < scene.objects.size(); ++i) picked.push_back(i);
        return picked;
    }
    const toml::array& names = array(*n, s.name("objects"));
    std::vector<std::string_view> known;
    for (const Object& o : scene.objects) known.push_back(o.name);
    for (const toml::node& e : names) {
        auto name = e.as_string();
        if (!name) fail(e, fmt::format("'{}' must list object names (got {})", s.name("objects"), describe(e)));
        size_t before = picked.size();
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (scene.objects[i].name == name->get()) picked.push_back(i);
        if (picked.size() == before)
            fail(e, fmt::format("'{}': there is no object named '{}'; {}", s.name("objects"), name->get(),
                                suggestion(name->get(), known, "objects")));
        // Each draw is bounded like an object (its vertices are the mesh's, already counted).
        if (picked.size() > kMaxSceneObjects)
            fail(e, fmt::format("'{}' draws more than {} objects (docs/limits.md)", s.name("objects"),
                                kMaxSceneObjects));
    }
    return picked;
}

Pass read_pass(const toml::node& n, size_t index, const toml::array* objects, const std::string& scene_dir,
               const Scene& scene) {
    std::string what = fmt::format("passes[{}]", index);
    Section s(table(n, what), what);
    s.allow({"name", "program", "vertex", "fragment", "state", "uniforms", "objects", "target", "clear", "camera"});
    Pass pass;
    pass.name = pass_name(s, index);
    pass.where = location(n);
    if (const toml::node* p = s.get("program")) {
        choice(*p, s.name("program"), {"fixed"});
        if (s.get("vertex") || s.get("fragment"))
            fail(*p, fmt::format("pass '{}': program = \"fixed\" draws with GL's fixed function alone; leave out "
                                 "'{}' (a pass of one shader has the fixed function for the other stage)",
                                 pass.name, s.get("vertex") ? "vertex" : "fragment"));
        pass.fixed_function = true;
    }
    pass.vertex = read_shaders(s, "vertex", scene_dir);
    pass.fragment = read_shaders(s, "fragment", scene_dir);
    pass.state = scene.gl;
    if (auto st = s.get("state")) read_state_section(Section(table(*st, s.name("state")), s.name("state")), scene.view, pass.state);
    read_pass_target(s, scene, pass);  // the camera's projection goes into pass.state, before the objects' copies
    if (auto u = s.get("uniforms")) read_uniforms(*u, s.name("uniforms"), pass.uniforms);
    pass.objects = pass_objects(s, scene);
    pass.object_states.resize(scene.objects.size());
    for (size_t i = 0; objects && i < objects->size() && i < scene.objects.size(); ++i) {
        const toml::node* state = (*objects)[i].as_table()->get("state");
        if (!state) continue;
        std::string object_what = fmt::format("objects[{}].state", i);
        GLState gl = pass.state;
        read_state_section(Section(table(*state, object_what), object_what), scene.view, gl);
        pass.object_states[i] = std::move(gl);
    }
    return pass;
}

}  // namespace

void read_passes(const toml::node& n, const toml::node* objects, const std::string& scene_dir, Scene& scene) {
    const toml::array* list = n.as_array();
    if (!list || (!list->empty() && !list->is_array_of_tables()))
        fail(n, fmt::format("'passes' must be an array of tables ([[passes]]) (got {})", describe(n)));
    const toml::array* object_list = objects ? objects->as_array() : nullptr;
    for (size_t i = 0; i < list->size(); ++i)
        scene.passes.push_back(read_pass((*list)[i], i, object_list, scene_dir, scene));
}

}  // namespace glslrun::scene::detail
