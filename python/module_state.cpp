// A scene's legacy GL state from Python: Scene.set_state, set_camera,
// set_light, ... take the keys of the scene file's sections as keyword
// arguments (docs/scene-format.md), written out as that section's TOML and
// read by the scene parser itself (scene::update_scene_state), so every key,
// check and message is the file's.
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "module.h"

namespace glslrun::python {
namespace {

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
            continue;
        }
        out += char(c);
    }
    return out + "\"";
}

std::string toml_value(const py::handle& v, const std::string& key);

std::string toml_table(const py::dict& d, const std::string& key) {
    std::string out = "{ ";
    bool first = true;
    for (auto [k, v] : d) {
        if (!py::isinstance<py::str>(k)) throw py::type_error(key + ": table keys are strings");
        const std::string name = k.cast<std::string>();
        out += (first ? "" : ", ") + toml_string(name) + " = " + toml_value(v, key + "." + name);
        first = false;
    }
    return out + " }";
}

// Python's bool, int, float, str, dict, sequences and numpy arrays as TOML;
// anything else is a TypeError naming the key.
std::string toml_value(const py::handle& v, const std::string& key) {
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::array>(v)) return toml_value(v.attr("tolist")(), key);
    if (py::isinstance<py::int_>(v) || py::hasattr(v, "__index__")) {
        py::int_ i = py::reinterpret_borrow<py::object>(v).attr("__index__")();
        return py::str(i).cast<std::string>();
    }
    if (py::isinstance<py::float_>(v) || py::hasattr(v, "__float__")) {
        double d = py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
        if (std::isnan(d)) return "nan";  // the reader refuses them with the key's name
        if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
        return py::repr(py::float_(d)).cast<std::string>();
    }
    if (py::isinstance<py::str>(v)) return toml_string(v.cast<std::string>());
    if (py::isinstance<py::dict>(v)) return toml_table(v.cast<py::dict>(), key);
    if (py::isinstance<py::sequence>(v)) {
        std::string out = "[";
        bool first = true;
        for (py::handle item : v.cast<py::sequence>()) {
            out += (first ? "" : ", ") + toml_value(item, key);
            first = false;
        }
        return out + "]";
    }
    throw py::type_error(key + ": " + py::str(py::type::of(v).attr("__name__")).cast<std::string>() +
                         " is not a value of a scene file (a number, bool, string, list, array or dict)");
}

// [section] and its keys, read onto the scene; `call` names the method in errors.
void set_section(scene::Scene& s, const std::string& section, const py::kwargs& keys, const std::string& call) {
    std::string text = "[" + section + "]\n";
    for (auto [k, v] : keys) {
        const std::string name = k.cast<std::string>();
        text += toml_string(name) + " = " + toml_value(v, name) + "\n";
    }
    check(scene::update_scene_state(s, text, call));
}

std::string indexed(const char* section, int index, int count, const char* what) {
    if (index < 0 || index >= count)
        throw py::value_error(std::string(what) + " " + std::to_string(index) + " is not 0.." +
                              std::to_string(count - 1));
    return std::string(section) + "." + std::to_string(index);
}

}  // namespace

void bind_state(py::module_& m) {
    py::class_<scene::Scene> scene = py::reinterpret_borrow<py::class_<scene::Scene>>(m.attr("Scene"));
    scene.def(
        "set_state", [](scene::Scene& s, const py::kwargs& k) { set_section(s, "state", k, "set_state"); },
        "Sets render state as a scene file's [state] does (docs/scene-format.md), each key a keyword. "
        "Depth: depth_test, depth_func, depth_writemask, depth_range; blending: blend, blend_func, "
        "blend_equation, blend_color; alpha_test, alpha_test_func, alpha_test_ref; stencil_test, stencil_func, "
        "stencil_ref, stencil_value_mask, stencil_writemask, stencil_fail, stencil_pass_depth_fail, "
        "stencil_pass_depth_pass and their stencil_back_ forms; scissor_test, scissor_box; color_writemask, "
        "color_logic_op, logic_op_mode, draw_buffers; cull_face, front_face, shade_model, polygon_mode, "
        "polygon_offset and polygon_offset_fill/line/point, line_width, point_size, point_sprite, "
        "coord_replace, point_sprite_coord_origin, point_size_min, point_size_max, point_distance_attenuation, "
        "point_fade_threshold_size, line_stipple, line_stipple_pattern, line_stipple_repeat, polygon_stipple, "
        "polygon_stipple_pattern, vertex_program_point_size, vertex_program_two_side, clip_planes, clip_planes_space, "
        "viewport. Values as in the file: set_state(depth_test=True, depth_func=\"lequal\", blend=True, "
        "blend_func=[\"src_alpha\", \"one_minus_src_alpha\"]). Keys left out keep their value. A misspelt key "
        "or a bad value raises glslrun.Error and changes nothing. A scene whose objects or passes have state of "
        "their own in its file refuses it: set it in the file.");
    scene.def(
        "set_camera", [](scene::Scene& s, const py::kwargs& k) { set_section(s, "camera", k, "set_camera"); },
        "Sets the view and projection matrices as a scene file's [camera] does: look_at={\"eye\": [0, 0, 5], "
        "\"center\": [0, 0, 0], \"up\": [0, 1, 0]} or view_matrix=, and one of perspective={\"fovy\": 45, "
        "\"near\": 1, \"far\": 100}, ortho=, frustum= or projection_matrix=. A matrix is 16 numbers in GL's "
        "column-major order or 4 columns: for a numpy matrix M in math notation (M @ v) pass M.T. Lights keep "
        "their world-space settings and follow the new view.");
    scene.def(
        "set_light",
        [](scene::Scene& s, int light, const py::kwargs& k) {
            set_section(s, indexed("lights", light, 8, "light"), k, "set_light");
        },
        py::arg("light"),
        "Sets light `light` (0..7, GL_LIGHT0 + light) as a scene file's [lights.N] does: enabled, space "
        "(\"world\" or \"eye\"), ambient, diffuse, specular, position, spot_direction, spot_exponent, "
        "spot_cutoff, constant_attenuation, linear_attenuation, quadratic_attenuation.");
    scene.def(
        "set_light_model",
        [](scene::Scene& s, const py::kwargs& k) { set_section(s, "light_model", k, "set_light_model"); },
        "glLightModel as a scene file's [light_model]: ambient, local_viewer, two_side.");
    scene.def(
        "set_material",
        [](scene::Scene& s, const std::string& face, const py::kwargs& k) {
            if (face != "front_and_back" && face != "front" && face != "back")
                throw py::value_error("face '" + face + "' is not front_and_back, front or back");
            set_section(s, face == "front_and_back" ? "material" : face + "_material", k, "set_material");
        },
        py::arg("face") = "front_and_back",
        "glMaterial as a scene file's [material] (face \"front_and_back\"), [front_material] or "
        "[back_material]: ambient, diffuse, ambient_and_diffuse, specular, emission, shininess.");
    scene.def(
        "set_fog", [](scene::Scene& s, const py::kwargs& k) { set_section(s, "fog", k, "set_fog"); },
        "glFog as a scene file's [fog] (gl_Fog): color, density, start, end.");
    scene.def(
        "set_current", [](scene::Scene& s, const py::kwargs& k) { set_section(s, "current", k, "set_current"); },
        "The current vertex attributes, as a scene file's [current]: color, secondary_color, normal, "
        "tex_coords, fog_coord, attributes; what a mesh lacks is read from them.");
    scene.def(
        "set_texture_matrix",
        [](scene::Scene& s, int unit, const py::kwargs& k) {
            const int units = int(std::tuple_size_v<decltype(GLState::texture_matrix)>);
            set_section(s, indexed("texture_matrix", unit, units, "texture unit"), k, "set_texture_matrix");
        },
        py::arg("unit"),
        "gl_TextureMatrix[unit] as a scene file's [texture_matrix.N]: transform=[{\"scale\": [2, 2, 1]}, ...] "
        "or matrix= (16 numbers, column-major).");
}

}  // namespace glslrun::python
