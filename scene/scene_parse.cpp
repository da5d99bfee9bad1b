// parse_scene / load_scene: the top level of a scene file (docs/scene-format.md).
// The sections are read in dependency order, not file order: the size before
// the camera (aspect), the camera before clip planes and lights (view), the
// scene's materials before the objects' overrides.
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "scene/scene_reader.h"
#include "scene/text_file.h"

namespace glslrun::scene {

namespace {

using detail::Section;

void read_output(const Section& s, Scene& scene) {
    s.allow({"size", "clear_color", "clear_depth", "clear_stencil"});
    if (const toml::node* n = s.get("size")) {
        const toml::array* a = n->as_array();
        if (!a || a->size() != 2)
            detail::fail(*n, fmt::format("'output.size' must be [width, height] (got {})",
                                         detail::describe(*n)));
        // Checked as 64-bit integers before anything is sized by them.
        int64_t w = detail::integer((*a)[0], "output.size[0]", INT64_MIN, INT64_MAX);
        int64_t h = detail::integer((*a)[1], "output.size[1]", INT64_MIN, INT64_MAX);
        if (std::string why = detail::size_problem(w, h); !why.empty()) detail::fail(*n, why);
        scene.width = int(w);
        scene.height = int(h);
    }
    s.read_color("clear_color", scene.clear_color);
    s.read("clear_depth", scene.clear_depth, {.lo = 0, .hi = 1, .why = "glClearDepth"});
    if (const toml::node* n = s.get("clear_stencil"))
        scene.clear_stencil = int(detail::integer(*n, "output.clear_stencil (stencil values are 8 bits)", 0,
                                                  (1 << kStencilBits) - 1));
}

void read_animation(const Section& s, Animation& animation) {
    s.allow({"time_uniform", "frames_per_second"});
    if (const toml::node* n = s.get("time_uniform")) {
        auto name = n->as_string();
        if (!name || name->get().empty() || name->get().starts_with("gl_"))
            detail::fail(*n, fmt::format("'animation.time_uniform' must name a user uniform (a non-empty string not "
                                         "starting with gl_; got {})", detail::describe(*n)));
        animation.time_uniform = name->get();
    }
    if (const toml::node* n = s.get("frames_per_second")) {
        animation.frames_per_second = detail::number(*n, "animation.frames_per_second");
        detail::check_range(*n, "animation.frames_per_second", animation.frames_per_second,
                            {.lo = 0, .lo_open = true});
    }
}

Section section(const toml::node& n, const char* name) { return Section(detail::table(n, name), name); }

// Lights the file leaves out keep GL's eye-space defaults; no transform.
Scene build_scene(const toml::table& root, const std::string& path) {
    Section top(root, "");
    top.allow({"output", "camera", "light_model", "lights", "material", "front_material", "back_material",
               "current", "state", "fog", "texture_matrix", "textures", "uniforms", "objects", "passes", "animation",
               "render_targets", "fixed_function", "texture_env", "texture_gen"});
    Scene scene;
    scene.path = path;
    if (const toml::node* n = top.get("output")) read_output(section(*n, "output"), scene);
    if (const toml::node* n = top.get("camera")) detail::read_camera(section(*n, "camera"), scene);
    if (const toml::node* n = top.get("animation")) read_animation(section(*n, "animation"), scene.animation);
    if (const toml::node* n = top.get("lights")) detail::read_lights(*n, scene);
    detail::read_render_state(top, scene);
    std::string dir = std::filesystem::path(path).parent_path().string();
    if (const toml::node* n = top.get("render_targets")) detail::read_render_targets(*n, scene);
    if (const toml::node* n = top.get("textures")) detail::read_textures(*n, dir, scene);
    if (const toml::node* n = top.get("uniforms")) detail::read_uniforms(*n, "uniforms", scene.uniforms);
    if (const toml::node* n = top.get("objects")) detail::read_objects(*n, dir, scene);
    derive_eye_space_lights(scene);
    if (const toml::node* n = top.get("objects")) detail::read_object_states(*n, scene);
    if (const toml::node* n = top.get("passes")) detail::read_passes(*n, top.get("objects"), dir, scene);
    return scene;
}

}  // namespace

namespace {

// toml++'s "Error while parsing array: expected comma or closing ']', saw '0'"
// after "scene.toml:3: error:" reads as two errors and says not where on the
// line: "TOML syntax error at column 20 (in an array): expected comma ...".
std::string toml_syntax_message(const toml::parse_error& e) {
    std::string what(e.description()), context;
    constexpr std::string_view kPrefix = "Error while parsing ";
    if (size_t colon = what.find(": "); what.starts_with(kPrefix) && colon != std::string::npos) {
        std::string noun = what.substr(kPrefix.size(), colon - kPrefix.size());
        const bool vowel = !noun.empty() && std::string_view("aeiou").find(noun[0]) != std::string_view::npos;
        context = fmt::format(" (in {} {})", vowel ? "an" : "a", noun);
        what = what.substr(colon + 2);
    }
    return fmt::format("TOML syntax error at column {}{}: {}", e.source().begin.column, context, what);
}

}  // namespace

Result<Scene> parse_scene(std::string_view toml_text, const std::string& path) {
    if (toml_text.size() > uint64_t(kMaxSceneFileBytes))
        return Error(fmt::format("a scene is {} bytes; the limit is {} MiB (its TOML tree takes about 45 bytes per "
                                 "byte)", toml_text.size(), kMaxSceneFileBytes >> 20),
                     path);
    try {
        toml::table root = toml::parse(toml_text, path);
        return build_scene(root, path);
    } catch (const toml::parse_error& e) {
        return Error(toml_syntax_message(e), path, int(e.source().begin.line));
    } catch (const detail::SceneFailure& f) {
        return f.error;
    } catch (const std::bad_alloc&) {
        return Error("out of memory parsing the scene", path);
    }
}

Status update_scene_state(Scene& scene, std::string_view toml_text, const std::string& what) {
    static const std::vector<std::string_view> kStateSections = {
        "light_model", "material", "front_material", "back_material", "current", "state", "fog", "texture_matrix",
        "fixed_function", "texture_env", "texture_gen"};
    // What the sections write, restored when one fails: no half-set state.
    auto saved = std::tuple(scene.camera, scene.view, scene.projection, scene.lights, scene.gl,
                            scene.current_attributes, scene.fixed);
    auto restore = [&] {
        std::tie(scene.camera, scene.view, scene.projection, scene.lights, scene.gl, scene.current_attributes,
                 scene.fixed) = std::move(saved);
    };
    try {
        toml::table root = toml::parse(toml_text, what);
        Section top(root, "");
        std::vector<std::string_view> allowed = kStateSections;
        allowed.insert(allowed.end(), {"camera", "lights"});
        top.allow(allowed);
        const bool own_states = !scene.passes.empty() ||
                                std::any_of(scene.objects.begin(), scene.objects.end(),
                                            [](const Object& o) { return o.state.has_value(); });
        for (std::string_view key : kStateSections)
            if (own_states && top.get(key))
                detail::fail(*top.get(key),
                             fmt::format("[{}]: the scene's {} state of their own from its file, which this "
                                         "would not reach: set it in the file",
                                         key, scene.passes.empty() ? "objects have" : "passes have"));
        if (const toml::node* n = top.get("camera")) detail::read_camera(section(*n, "camera"), scene);
        if (const toml::node* n = top.get("lights")) detail::read_lights(*n, scene);
        detail::read_render_state(top, scene);
        derive_eye_space_lights(scene);
        return Ok{};
    } catch (const toml::parse_error& e) {
        return Error(toml_syntax_message(e), what, int(e.source().begin.line));
    } catch (const detail::SceneFailure& f) {
        restore();
        return f.error;
    }
}

Result<std::vector<UniformSetting>> parse_uniform_override(std::string_view arg) {
    size_t eq = arg.find('=');
    std::string_view name = arg.substr(0, eq);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    if (eq == std::string_view::npos || name.empty() || name.find_first_of("\"\\\n") != std::string_view::npos)
        return Error(fmt::format("--uniform '{}': expected name=value, the value written as in a scene's "
                                 "[uniforms] (3, 0.5, [1, 0, 0], true)", arg));
    // The value is TOML, read exactly as a scene's [uniforms] entry; a bare
    // list "1,0,0" is what a shell user writes for [1, 0, 0].
    std::string value(arg.substr(eq + 1));
    size_t first = value.find_first_not_of(' ');
    if (value.find(',') != std::string::npos && first != std::string::npos && value[first] != '[')
        value = "[" + value + "]";
    std::string text = fmt::format("[uniforms]\n\"{}\" = {}\n", name, value);
    if (value.find('\n') != std::string::npos) text.clear();  // one value, not more TOML
    bool syntax_ok = !text.empty();
    try {
        if (syntax_ok) (void)toml::parse(std::string_view(text), std::string_view("--uniform"));
    } catch (const toml::parse_error&) {
        syntax_ok = false;
    }
    // toml++'s own message speaks of TOML's grammar, which the user did not write.
    if (!syntax_ok)
        return Error(fmt::format("--uniform '{}': '{}' is not a value: write a number (0.5, 3), a list "
                                 "(1,0,0 or [1, 0, 0]) or true/false", arg, arg.substr(eq + 1)));
    auto scene = parse_scene(text, "--uniform");
    if (!scene) {
        std::string why = scene.error().diagnostics.empty() ? "invalid" : scene.error().diagnostics[0].message;
        return Error(fmt::format("--uniform '{}': {}", arg, why));
    }
    for (UniformSetting& u : scene->uniforms) u.where = {"--uniform " + std::string(arg), 0};
    return std::move(scene->uniforms);
}

void override_uniforms(Scene& scene, const std::vector<UniformSetting>& settings) {
    // After the file's own settings, the scene's and each object's: the command line wins everywhere.
    scene.uniforms.insert(scene.uniforms.end(), settings.begin(), settings.end());
    for (Object& o : scene.objects)
        if (!o.uniforms.empty()) o.uniforms.insert(o.uniforms.end(), settings.begin(), settings.end());
}

Result<Scene> load_scene(const std::string& path) {
    Result<std::string> text = read_text_file(path, "scene file", kMaxSceneFileBytes);
    if (!text) return text.error();
    return parse_scene(*text, path);
}

}  // namespace glslrun::scene
