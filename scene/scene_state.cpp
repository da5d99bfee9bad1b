// The legacy GL state of a scene: lights, light model, materials, current
// attributes, render state, clip planes, fog and texture matrices. Each key
// is one glLight/glMaterial/glEnable/... call; its checks are the ones GL
// makes (GL_INVALID_VALUE becomes an error citing the line).
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene::detail {

namespace {

constexpr Range kNonNegative{.lo = 0, .why = "GL_INVALID_VALUE below 0"};

void check_spot_cutoff(const Section& s) {
    const toml::node* n = s.get("spot_cutoff");
    if (!n) return;
    double v = number(*n, s.name("spot_cutoff"));
    if ((v >= 0 && v <= 90) || v == 180) return;
    fail(*n, fmt::format("'{}' must be in [0, 90] or exactly 180 (GL's allowed values for "
                         "GL_SPOT_CUTOFF; 180 turns the spot off); got {}", s.name("spot_cutoff"), v));
}

void read_light(const Section& s, LightSetting& light) {
    s.allow({"enabled", "space", "ambient", "diffuse", "specular", "position", "spot_direction",
             "spot_exponent", "spot_cutoff", "constant_attenuation", "linear_attenuation",
             "quadratic_attenuation"});
    light.enabled = true;  // a light the file describes is meant to shine
    s.read("enabled", light.enabled);
    if (auto n = s.get("space")) light.world_space = choice(*n, s.name("space"), {"world", "eye"}) == 0;
    LightState& l = light.as_given;
    s.read_color("ambient", l.ambient);
    s.read_color("diffuse", l.diffuse);
    s.read_color("specular", l.specular);
    light.has_position = s.read_vec("position", l.position);
    light.has_spot_direction = s.read_vec("spot_direction", l.spot_direction);
    s.read("spot_exponent", l.spot_exponent, {.lo = 0, .hi = 128, .why = "GL_SPOT_EXPONENT"});
    check_spot_cutoff(s);
    s.read("spot_cutoff", l.spot_cutoff);
    s.read("constant_attenuation", l.constant_attenuation, kNonNegative);
    s.read("linear_attenuation", l.linear_attenuation, kNonNegative);
    s.read("quadratic_attenuation", l.quadratic_attenuation, kNonNegative);
}

void read_light_model(const Section& s, GLState& gl) {
    s.allow({"ambient", "local_viewer", "two_side", "color_control"});
    s.read_color("ambient", gl.light_model_ambient);
    s.read("local_viewer", gl.light_model_local_viewer);
    s.read("two_side", gl.light_model_two_side);
}

// glVertexAttrib*f / glMultiTexCoord*f: 1..4 numbers, the rest GL's (0, 0, 0, 1).
CurrentAttribute current_value(const toml::node& n, std::string name, const std::string& what) {
    std::vector<double> v = n.is_array() ? numbers(n, what, 1, 4) : std::vector<double>{number(n, what)};
    CurrentAttribute a{std::move(name), {0, 0, 0, 1}, location(n)};
    for (size_t i = 0; i < v.size(); ++i) a.value[int(i)] = float(v[i]);
    return a;
}

void read_current(const Section& s, GLState& gl, Scene& scene) {
    s.allow({"color", "secondary_color", "normal", "tex_coords", "fog_coord", "attributes"});
    s.read_color("color", gl.current_color);
    s.read_color("secondary_color", gl.current_secondary_color);
    s.read_vec("normal", gl.current_normal);
    if (const toml::node* n = s.get("tex_coords"))
        for (auto&& [k, v] : table(*n, s.name("tex_coords"))) {
            int unit = index_key(k, 8, s.name("tex_coords"), "texture coordinate sets are 0..7 (GL_TEXTURE0..7)");
            scene.current_attributes.push_back(current_value(v, fmt::format("gl_MultiTexCoord{}", unit),
                                                             fmt::format("{}.{}", s.name("tex_coords"), unit)));
        }
    if (const toml::node* n = s.get("fog_coord"))
        scene.current_attributes.push_back({"gl_FogCoord", {float(number(*n, s.name("fog_coord"))), 0, 0, 1},
                                            location(*n)});
    if (const toml::node* n = s.get("attributes"))
        for (auto&& [k, v] : table(*n, s.name("attributes"))) {
            std::string what = fmt::format("{}.{}", s.name("attributes"), k.str());
            if (k.str().starts_with("gl_"))
                fail(v, fmt::format("'{}': built-in attributes have keys of their own (color, normal, tex_coords, "
                                    "...)", what));
            scene.current_attributes.push_back(current_value(v, std::string(k.str()), what));
        }
}

void read_fog(const Section& s, GLState& gl) {
    s.allow({"color", "density", "start", "end", "mode", "coord_src"});
    s.read_color("color", gl.fog.color);
    s.read("density", gl.fog.density, {.lo = 0, .why = "GL_FOG_DENSITY; GL_INVALID_VALUE below 0"});
    s.read("start", gl.fog.start);
    s.read("end", gl.fog.end);
}

bool planes_in_world(const Section& s) {
    const toml::node* space = s.get("clip_planes_space");
    return !space || choice(*space, s.name("clip_planes_space"), {"world", "eye"}) == 0;
}

glm::dmat4 inverse_view(const Section& s, const toml::node& planes, const glm::mat4& view) {
    if (glm::determinant(glm::dmat4(view)) == 0)
        fail(planes, fmt::format("'{}': the view matrix is singular, so world-space planes have no "
                                 "eye-space form; give them in eye space (clip_planes_space = \"eye\")",
                                 s.name("clip_planes")));
    return glm::inverse(glm::dmat4(view));
}

// glClipPlane transforms the plane by the inverse of the modelview current at
// the call (GL 2.1 §2.12): p_eye = p_world * inverse(view), a row vector.
void read_clip_planes(const Section& s, const glm::mat4& view, GLState& gl) {
    bool world = planes_in_world(s);
    const toml::node* n = s.get("clip_planes");
    if (!n) return;
    const toml::array& planes = array(*n, s.name("clip_planes"));
    if (planes.size() > gl.clip_planes.size())
        fail(*n, fmt::format("'{}' has {} planes; GL has 6 (GL_CLIP_PLANE0..5)", s.name("clip_planes"),
                             planes.size()));
    glm::dmat4 to_eye = world ? inverse_view(s, *n, view) : glm::dmat4(1.0);
    gl.clip_plane_enabled = 0;  // the list replaces the planes enabled before (an object's list the scene's)
    for (size_t i = 0; i < planes.size(); ++i) {
        std::vector<double> v = numbers(planes[i], fmt::format("{}[{}]", s.name("clip_planes"), i), 4, 4);
        gl.clip_planes[i] = glm::vec4(glm::dvec4(v[0], v[1], v[2], v[3]) * to_eye);
        gl.clip_plane_enabled |= 1u << i;
    }
}

void read_depth_range(const Section& s, GLState& gl) {
    const toml::node* n = s.get("depth_range");
    if (!n) return;
    std::vector<double> v = numbers(*n, s.name("depth_range"), 2, 2);
    // GL clamps to [0, 1]; a value outside is a mistake worth reporting.
    for (size_t i = 0; i < 2; ++i)
        check_range((*n->as_array())[i], fmt::format("{}[{}]", s.name("depth_range"), i), v[i],
                    {.lo = 0, .hi = 1, .why = "glDepthRange"});
    gl.depth_near = float(v[0]);
    gl.depth_far = float(v[1]);
}

void read_cull_face(const Section& s, GLState& gl) {
    const toml::node* n = s.get("cull_face");
    if (!n) return;
    size_t c = choice(*n, s.name("cull_face"), {"off", "back", "front", "front_and_back"});
    gl.cull_face = c != 0;
    gl.cull_back = c != 2;
    gl.cull_front_and_back = c == 3;
}

// glPolygonMode: one mode for both faces (GL_FRONT_AND_BACK), or [front, back].
void read_polygon_mode(const Section& s, GLState& gl) {
    const toml::node* n = s.get("polygon_mode");
    if (!n) return;
    const std::vector<std::string_view> modes = {"point", "line", "fill"};
    if (!n->as_array()) {
        gl.polygon_mode[0] = gl.polygon_mode[1] = PolygonMode(choice(*n, s.name("polygon_mode"), modes));
        return;
    }
    const toml::array& a = *n->as_array();
    if (a.size() != 2)
        fail(*n, fmt::format("'{}' must be one mode for both faces or [front, back] (got {})",
                             s.name("polygon_mode"), describe(*n)));
    for (size_t i = 0; i < 2; ++i)
        gl.polygon_mode[i] = PolygonMode(choice(a[i], fmt::format("{}[{}]", s.name("polygon_mode"), i), modes));
}

// glPolygonOffset(factor, units) and the three enables.
void read_polygon_offset(const Section& s, GLState& gl) {
    if (const toml::node* n = s.get("polygon_offset")) {
        std::vector<double> v = numbers(*n, s.name("polygon_offset"), 2, 2);
        gl.polygon_offset_factor = float(v[0]);
        gl.polygon_offset_units = float(v[1]);
    }
    s.read("polygon_offset_fill", gl.polygon_offset_fill);
    s.read("polygon_offset_line", gl.polygon_offset_line);
    s.read("polygon_offset_point", gl.polygon_offset_point);
}

// Point sprites: GL_POINT_SPRITE, and the texture units whose GL_COORD_REPLACE is on.
void read_point_sprite(const Section& s, GLState& gl) {
    s.read("point_sprite", gl.point_sprite);
    const toml::node* n = s.get("coord_replace");
    if (!n) return;
    const toml::array& units = array(*n, s.name("coord_replace"));
    gl.coord_replace = 0;
    for (size_t i = 0; i < units.size(); ++i)
        gl.coord_replace |= 1u << integer(units[i], fmt::format("{}[{}] (texture units 0..7)", s.name("coord_replace"), i), 0, 7);
}

// glViewport(x, y, width, height). GL clamps the size to
// GL_MAX_VIEWPORT_DIMS; a size of 0 draws nothing in GL, while glslrun's
// GLState reads 0 as "the whole framebuffer", so sizes start at 1.
void read_viewport(const Section& s, GLState& gl) {
    const toml::node* n = s.get("viewport");
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 4)
        fail(*n, fmt::format("'{}' must be [x, y, width, height] (got {})", s.name("viewport"), describe(*n)));
    constexpr int64_t kFar = int64_t(1) << 30;
    for (size_t i = 0; i < 4; ++i) {
        std::string what = fmt::format("{}[{}]", s.name("viewport"), i);
        gl.viewport[i] = i < 2 ? int(integer((*a)[i], what, -kFar, kFar))
                               : int(integer((*a)[i], what + " (GL_MAX_VIEWPORT_DIMS)", 1, kMaxFramebufferSide));
    }
}

void read_texture_matrices(const toml::node& n, GLState& gl) {
    const toml::table& units = table(n, "texture_matrix");
    for (auto&& [k, v] : units) {
        int unit = index_key(k, int(gl.texture_matrix.size()), "texture_matrix",
                             "texture units are 0..7 ([texture_matrix.0] .. [texture_matrix.7])");
        std::string what = fmt::format("texture_matrix.{}", unit);
        Section s(table(v, what), what);
        s.allow({"transform", "matrix"});
        if (s.get("transform") && s.get("matrix"))
            fail(*s.get("matrix"), fmt::format("[{}] has both 'transform' and 'matrix'; give one", what));
        glm::mat4& m = gl.texture_matrix[size_t(unit)];
        if (auto t = s.get("transform")) m = glm::mat4(transform_list(*t, s.name("transform")));
        if (auto t = s.get("matrix")) m = glm::mat4(matrix(*t, s.name("matrix")));
    }
}

void read_material_section(const Section& top, std::string_view key, Scene& scene) {
    const toml::node* n = top.get(key);
    if (!n) return;
    Section s(table(*n, std::string(key)), std::string(key));
    if (key != "back_material") read_material(s, scene.gl.front_material);
    if (key != "front_material") read_material(s, scene.gl.back_material);
}

}  // namespace

void read_state_section(const Section& s, const glm::mat4& view, GLState& gl) {
    std::vector<std::string_view> keys = {"depth_test", "depth_func", "cull_face", "front_face", "shade_model",
                                          "vertex_program_two_side", "point_size", "vertex_program_point_size",
                                          "clip_planes", "clip_planes_space", "depth_range", "polygon_mode",
                                          "polygon_offset", "polygon_offset_fill", "polygon_offset_line",
                                          "polygon_offset_point", "line_width", "point_sprite", "coord_replace",
                                          "viewport"};
    keys.insert(keys.end(), fragment_state_keys().begin(), fragment_state_keys().end());
    keys.insert(keys.end(), stipple_state_keys().begin(), stipple_state_keys().end());
    s.allow(keys);
    s.read("depth_test", gl.depth_test);
    if (auto n = s.get("depth_func"))
        gl.depth_func = GLState::DepthFunc(choice(*n, s.name("depth_func"), compare_func_names()));
    read_cull_face(s, gl);
    if (auto n = s.get("front_face")) gl.front_ccw = choice(*n, s.name("front_face"), {"ccw", "cw"}) == 0;
    if (auto n = s.get("shade_model"))
        gl.flat_shading = choice(*n, s.name("shade_model"), {"smooth", "flat"}) == 1;
    s.read("vertex_program_two_side", gl.vertex_program_two_side);
    s.read("point_size", gl.point_size, {.lo = 0, .lo_open = true, .why = "glPointSize"});
    s.read("vertex_program_point_size", gl.vertex_program_point_size);
    read_clip_planes(s, view, gl);
    read_depth_range(s, gl);
    read_polygon_mode(s, gl);
    read_polygon_offset(s, gl);
    s.read("line_width", gl.line_width, {.lo = 0, .lo_open = true, .why = "glLineWidth"});
    read_point_sprite(s, gl);
    read_viewport(s, gl);
    read_fragment_state(s, gl);
    read_stipple_state(s, gl);
}

void read_material(const Section& s, MaterialState& m) {
    s.allow({"ambient", "diffuse", "ambient_and_diffuse", "specular", "emission", "shininess"});
    if (auto n = s.get("ambient_and_diffuse")) {
        if (s.get("ambient") || s.get("diffuse"))
            fail(*n, fmt::format("[{}]: 'ambient_and_diffuse' sets both; do not also give 'ambient' or "
                                 "'diffuse'", s.path()));
        m.ambient = m.diffuse = glm::vec4(color(*n, s.name("ambient_and_diffuse")));
    }
    s.read_color("ambient", m.ambient);
    s.read_color("diffuse", m.diffuse);
    s.read_color("specular", m.specular);
    s.read_color("emission", m.emission);
    s.read("shininess", m.shininess, {.lo = 0, .hi = 128, .why = "GL_SHININESS"});
}

void read_lights(const toml::node& n, Scene& scene) {
    const toml::table& lights = table(n, "lights");
    for (auto&& [k, v] : lights) {
        int i = index_key(k, int(scene.lights.size()), "lights",
                          "there are at most 8 lights, 0..7 (GL_LIGHT0..GL_LIGHT7)");
        std::string what = fmt::format("lights.{}", i);
        read_light(Section(table(v, what), what), scene.lights[size_t(i)]);
    }
}

void read_render_state(const Section& top, Scene& scene) {
    auto section = [&](std::string_view key, auto reader) {
        const toml::node* n = top.get(key);
        if (n) reader(Section(table(*n, std::string(key)), std::string(key)));
    };
    section("light_model", [&](const Section& s) {
        read_light_model(s, scene.gl);
        read_light_model_fixed(s, scene.fixed);
    });
    // [material] is glMaterial(GL_FRONT_AND_BACK); the sided tables come after it.
    read_material_section(top, "material", scene);
    read_material_section(top, "front_material", scene);
    read_material_section(top, "back_material", scene);
    section("current", [&](const Section& s) { read_current(s, scene.gl, scene); });
    section("state", [&](const Section& s) { read_state_section(s, scene.view, scene.gl); });
    section("fog", [&](const Section& s) {
        read_fog(s, scene.gl);
        read_fog_fixed(s, scene.fixed);
    });
    section("fixed_function", [&](const Section& s) { read_fixed_function(s, scene.fixed); });
    read_texture_units_fixed(top.table(), scene.view, scene.fixed);
    if (const toml::node* n = top.get("texture_matrix")) read_texture_matrices(*n, scene.gl);
}

}  // namespace glslrun::scene::detail
