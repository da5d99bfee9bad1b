// Internal to the scene parser (scene/scene_*.cpp): typed readers over
// toml++ nodes, GL's matrix constructions, and the parser's sections.
//
// A reader that finds a mistake throws SceneFailure; parse_scene() turns it
// into the Error it returns. The first mistake ends the parse, so no reader
// needs an error path of its own and every function stays straight-line.
#pragma once
#include <cfloat>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <toml++/toml.h>

#include "glslrun/scene/scene.h"

namespace glslrun::scene::detail {

struct SceneFailure {
    Error error;
};

// Throws SceneFailure citing the region's file and line.
[[noreturn]] void fail(const toml::source_region& where, std::string message);
[[noreturn]] void fail(const toml::node& at, std::string message);
SourceLoc location(const toml::node& n);

// "a string", "an array of 2 values", ... for "(got ...)" in messages.
std::string describe(const toml::node& n);
// The candidate closest to `word` by edit distance, or "" when none is close
// enough to be a plausible typo.
std::string closest(std::string_view word, const std::vector<std::string_view>& candidates);
// "did you mean 'x'?" or "valid keys: a, b, c".
std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates,
                       std::string_view noun = "keys");

// An allowed interval for a number; messages print it as GL states it.
struct Range {
    double lo = -FLT_MAX, hi = FLT_MAX;
    bool lo_open = false, hi_open = false;  // the bound itself excluded ("> 0")
    const char* why = nullptr;  // appended in parentheses: "GL_SPOT_EXPONENT"
};
void check_range(const toml::node& at, const std::string& what, double v, const Range& r);

// Typed readers. `what` names the value in messages ("lights.0.diffuse").
// Every number must be finite and representable as a float.
double number(const toml::node& n, const std::string& what);
int64_t integer(const toml::node& n, const std::string& what, int64_t lo, int64_t hi);
bool boolean(const toml::node& n, const std::string& what);
const toml::table& table(const toml::node& n, const std::string& what);
const toml::array& array(const toml::node& n, const std::string& what);
std::vector<double> numbers(const toml::node& n, const std::string& what, size_t min, size_t max);
glm::dvec4 color(const toml::node& n, const std::string& what);  // 3 or 4; alpha 1
glm::dmat4 matrix(const toml::node& n, const std::string& what);  // 16 numbers or 4 columns
// Index of the string among `options`.
size_t choice(const toml::node& n, const std::string& what, const std::vector<std::string_view>& options);
// "0".."count-1" as a table key (lights, texture units).
int index_key(const toml::key& k, int count, const std::string& what, std::string_view limit_message);

// A TOML table being read: its keys are checked against the allowed ones,
// and optional values are read by key, leaving the output alone when absent.
class Section {
public:
    Section(const toml::table& t, std::string path) : table_(t), path_(std::move(path)) {}
    // Fails on the first key (in file order) not in `keys`, with a suggestion.
    void allow(const std::vector<std::string_view>& keys) const;
    const toml::node* get(std::string_view key) const { return table_.get(key); }
    const toml::node& require(std::string_view key, std::string_view why) const;
    std::string name(std::string_view key) const;  // "lights.0" + "diffuse"
    const std::string& path() const { return path_; }
    const toml::table& table() const { return table_; }

    bool read(std::string_view key, bool& out) const;
    bool read(std::string_view key, float& out, const Range& r = {}) const;
    bool read_color(std::string_view key, glm::vec4& out) const;
    bool read_vec(std::string_view key, glm::vec3& out) const;  // exactly 3
    bool read_vec(std::string_view key, glm::vec4& out) const;  // exactly 4
private:
    const toml::table& table_;
    std::string path_;
};

// GL's matrices, in double (GLU computes in double and GL rounds once when it
// loads the result as float).
glm::dmat4 gl_look_at(glm::dvec3 eye, glm::dvec3 center, glm::dvec3 up);
glm::dmat4 gl_perspective(double fovy, double aspect, double near, double far);
glm::dmat4 gl_ortho(double l, double r, double b, double t, double n, double f);
glm::dmat4 gl_frustum(double l, double r, double b, double t, double n, double f);
glm::dmat4 gl_rotate(double degrees, glm::dvec3 axis);  // axis non-zero
glm::dmat4 projection_of(const Camera& camera, int width, int height);

// Sections of the file (scene_camera.cpp, scene_state.cpp, scene_uniforms.cpp,
// scene_objects.cpp, scene_textures.cpp).
glm::dmat4 transform_list(const toml::node& n, const std::string& what);
void read_camera(const Section& camera, Scene& scene);
// [camera]'s keys into a camera, view and projection (left alone when absent).
void read_camera_into(const Section& s, Camera& camera, glm::mat4& view, glm::mat4& projection, int width,
                      int height);
// [render_targets.NAME] (scene_targets.cpp), before the textures that sample them.
void read_render_targets(const toml::node& n, Scene& scene);
// A [textures.N] with `render_target`: its attachment's texture, cleared.
Texture target_texture(const Section& s, const Scene& scene, TextureSetting& setting);
// A pass's `target`, `clear` and `camera` (its projection goes to pass.state).
void read_pass_target(const Section& s, const Scene& scene, Pass& pass);
void read_lights(const toml::node& n, Scene& scene);
void read_material(const Section& s, MaterialState& m);
void read_render_state(const Section& top, Scene& scene);
// The keys of one [state] table into `gl`; world-space clip planes go through `view`.
void read_state_section(const Section& s, const glm::mat4& view, GLState& gl);
// CompareFunc's names in its order: GL_NEVER .. GL_ALWAYS without GL_ (scene_fragment_state.cpp).
const std::vector<std::string_view>& compare_func_names();
// [state]'s per-fragment operations (scene_fragment_state.cpp).
const std::vector<std::string_view>& fragment_state_keys();
void read_fragment_state(const Section& s, GLState& gl);
// [state]'s point parameters, line and polygon stipples (scene_stipple_state.cpp).
const std::vector<std::string_view>& stipple_state_keys();
void read_stipple_state(const Section& s, GLState& gl);
// [objects.state]: each object's state is the scene's final state with its own keys on top.
void read_object_states(const toml::node& objects, Scene& scene);
void read_uniforms(const toml::node& n, const std::string& what, std::vector<UniformSetting>& out);
// [[passes]] (scene_passes.cpp), after the objects and their states: `objects` is the file's [[objects]] array.
void read_passes(const toml::node& n, const toml::node* objects, const std::string& scene_dir, Scene& scene);
// One attribute array of `vertex_count` values, each a number or 1..4 numbers, all alike.
VertexAttrib read_attribute(const toml::node& n, const std::string& name, const std::string& what,
                            uint32_t vertex_count);
// mesh = "arrays" (scene_arrays.cpp): its keys, and the mesh they give.
const std::vector<std::string_view>& array_mesh_keys();
Mesh read_array_mesh(const Section& s);
std::vector<VertexAttrib> read_attributes(const toml::node& n, const std::string& what,
                                          uint32_t vertex_count);
void read_objects(const toml::node& n, const std::string& scene_dir, Scene& scene);
void read_textures(const toml::node& n, const std::string& scene_dir, Scene& scene);  // scene_textures.cpp
// `what` = { N = texture table, ... } into `out` (scene.textures or an
// object's), adding their texels to `texels` (checked against kMaxSceneTexels).
void read_texture_units(const toml::node& n, const std::string& what, const std::string& scene_dir, Scene& scene,
                        std::vector<TextureSetting>& out, int64_t& texels);
// The fixed-function keys (scene_fixed.cpp): [fixed_function], [light_model]
// color_control, [fog] mode and coord_src, [texture_env.N] and
// [texture_gen.N] (world-space eye planes go through `view`).
void read_fixed_function(const Section& s, FixedFunction& f);
void read_light_model_fixed(const Section& s, FixedFunction& f);
void read_fog_fixed(const Section& s, FixedFunction& f);
void read_texture_units_fixed(const toml::table& top, const glm::mat4& view, FixedFunction& f);
// "" when width x height is acceptable, else why not.
std::string size_problem(int64_t width, int64_t height);

}  // namespace glslrun::scene::detail
