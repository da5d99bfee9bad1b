// The fixed-function keys (docs/scene-format.md): [fixed_function], [light_model]
// color_control, [fog] mode and coord_src, [texture_env.N], [texture_gen.N].
// Only the stages scene/ffp_*.cpp generate read them.
#include <fmt/format.h>

#include "scene/scene_reader.h"

namespace glslrun::scene {

std::array<std::array<TexGen, 4>, 8> FixedFunction::default_texture_gen() {
    // GL 2.1's GL_OBJECT_PLANE and GL_EYE_PLANE: s (1, 0, 0, 0), t (0, 1, 0, 0), r and q zero.
    std::array<std::array<TexGen, 4>, 8> units{};
    for (auto& coords : units) {
        coords[0].object_plane = coords[0].eye_plane = {1, 0, 0, 0};
        coords[1].object_plane = coords[1].eye_plane = {0, 1, 0, 0};
    }
    return units;
}

namespace detail {

namespace {

void read_color_material(const Section& s, FixedFunction& f) {
    const toml::node* n = s.get("color_material");
    if (!n) return;
    if (n->is_boolean()) {
        f.color_material = boolean(*n, s.name("color_material"));
        return;
    }
    f.color_material = true;
    f.color_material_mode = ColorMaterialMode(
        choice(*n, s.name("color_material"), {"emission", "ambient", "diffuse", "specular", "ambient_and_diffuse"}));
}

}  // namespace

void read_fixed_function(const Section& s, FixedFunction& f) {
    s.allow({"lighting", "color_material", "color_material_face", "normalize", "rescale_normal", "color_sum", "fog"});
    s.read("lighting", f.lighting);
    read_color_material(s, f);
    if (const toml::node* n = s.get("color_material_face")) {
        size_t face = choice(*n, s.name("color_material_face"), {"front", "back", "front_and_back"});
        f.color_material_front = face != 1;
        f.color_material_back = face != 0;
    }
    s.read("normalize", f.normalize);
    s.read("rescale_normal", f.rescale_normal);
    s.read("color_sum", f.color_sum);
    s.read("fog", f.fog);
}

void read_light_model_fixed(const Section& s, FixedFunction& f) {
    if (const toml::node* n = s.get("color_control"))
        f.separate_specular =
            choice(*n, s.name("color_control"), {"single_color", "separate_specular_color"}) == 1;
}

void read_fog_fixed(const Section& s, FixedFunction& f) {
    if (const toml::node* n = s.get("mode"))
        f.fog_mode = FogMode(choice(*n, s.name("mode"), {"linear", "exp", "exp2"}));
    if (const toml::node* n = s.get("coord_src"))
        f.fog_coord_from_array = choice(*n, s.name("coord_src"), {"fragment_depth", "fog_coord"}) == 1;
}

namespace {

constexpr std::string_view kUnitLimit = "texture units are 0..7 (fixed function has 8 texture coordinate sets)";

// texture, constant, primary_color, previous, texture0..texture7.
uint8_t combine_source(const toml::node& n, const std::string& what) {
    return uint8_t(choice(n, what, {"texture", "constant", "primary_color", "previous", "texture0", "texture1",
                                    "texture2", "texture3", "texture4", "texture5", "texture6", "texture7"}));
}

CombineOperand combine_operand(const toml::node& n, const std::string& what, bool alpha) {
    if (alpha) return CombineOperand(2 + choice(n, what, {"src_alpha", "one_minus_src_alpha"}));
    return CombineOperand(choice(n, what, {"src_color", "one_minus_src_color", "src_alpha", "one_minus_src_alpha"}));
}

float combine_scale(const Section& s, std::string_view key, float current) {
    const toml::node* n = s.get(key);
    if (!n) return current;
    double v = number(*n, s.name(key));
    if (v != 1 && v != 2 && v != 4)
        fail(*n, fmt::format("'{}' must be 1, 2 or 4 (GL's values; GL_INVALID_VALUE otherwise); got {}",
                             s.name(key), v));
    return float(v);
}

// source0_rgb .. operand2_alpha: each an array of up to 3 values would hide
// which is which; GL names them one by one, and so do the keys.
void read_combine(const Section& s, TextureEnv& env) {
    auto function = [&](std::string_view key, bool alpha) {
        const toml::node* n = s.get(key);
        if (!n) return;
        std::vector<std::string_view> names = {"replace", "modulate", "add", "add_signed", "interpolate", "subtract"};
        if (!alpha) names.insert(names.end(), {"dot3_rgb", "dot3_rgba"});
        auto f = CombineFunction(choice(*n, s.name(key), names));
        (alpha ? env.combine_alpha : env.combine_rgb) = f;
    };
    function("combine_rgb", false);
    function("combine_alpha", true);
    for (int i = 0; i < 3; ++i) {
        for (bool alpha : {false, true}) {
            std::string key = fmt::format("source{}_{}", i, alpha ? "alpha" : "rgb");
            if (const toml::node* n = s.get(key))
                (alpha ? env.source_alpha : env.source_rgb)[size_t(i)] = combine_source(*n, s.name(key));
            key = fmt::format("operand{}_{}", i, alpha ? "alpha" : "rgb");
            if (const toml::node* n = s.get(key))
                (alpha ? env.operand_alpha : env.operand_rgb)[size_t(i)] = combine_operand(*n, s.name(key), alpha);
        }
    }
    env.rgb_scale = combine_scale(s, "rgb_scale", env.rgb_scale);
    env.alpha_scale = combine_scale(s, "alpha_scale", env.alpha_scale);
}

void read_texture_env(const Section& s, TextureEnv& env) {
    std::vector<std::string_view> keys = {"enabled", "mode", "color", "combine_rgb", "combine_alpha", "rgb_scale",
                                          "alpha_scale"};
    static const char* const kNames[] = {"source0_rgb", "source1_rgb", "source2_rgb", "source0_alpha",
                                         "source1_alpha", "source2_alpha", "operand0_rgb", "operand1_rgb",
                                         "operand2_rgb", "operand0_alpha", "operand1_alpha", "operand2_alpha"};
    for (const char* k : kNames) keys.push_back(k);
    s.allow(keys);
    env.enabled = true;
    s.read("enabled", env.enabled);
    if (const toml::node* n = s.get("mode"))
        env.mode = TexEnvMode(choice(*n, s.name("mode"), {"modulate", "decal", "blend", "replace", "add", "combine"}));
    s.read_color("color", env.color);
    for (int c = 0; c < 4; ++c)
        if (env.color[c] < 0 || env.color[c] > 1)
            fail(*s.get("color"),
                 fmt::format("'{}' must be in [0, 1] (GL clamps GL_TEXTURE_ENV_COLOR)", s.name("color")));
    read_combine(s, env);
    bool combine_keys = false;
    for (std::string_view k : keys)
        combine_keys = combine_keys || (s.get(k) && k != "enabled" && k != "mode" && k != "color");
    if (combine_keys && env.mode != TexEnvMode::Combine)
        fail(s.table(), fmt::format("[{}] sets combiner keys, which only mode = \"combine\" reads", s.path()));
}

// A coordinate's texgen: a mode name, or { mode, object_plane, eye_plane }.
void read_texgen_coord(const Section& s, std::string_view key, const glm::mat4& view, bool world, TexGen& gen) {
    const toml::node* n = s.get(key);
    if (!n) return;
    const std::vector<std::string_view> modes = {"object_linear", "eye_linear", "sphere_map", "normal_map",
                                                 "reflection_map"};
    if (n->is_string()) {
        gen.mode = TexGenMode(1 + choice(*n, s.name(key), modes));
    } else {
        Section c(table(*n, s.name(key)), s.name(key));
        c.allow({"mode", "object_plane", "eye_plane"});
        gen.mode = TexGenMode(1 + choice(c.require("mode", "the texgen mode"), c.name("mode"), modes));
        c.read_vec("object_plane", gen.object_plane);
        glm::vec4 plane = gen.eye_plane;
        if (c.read_vec("eye_plane", plane))
            // glTexGen(GL_EYE_PLANE) stores p * inverse(modelview) (GL 2.1 §2.12.4), a row vector.
            gen.eye_plane = world ? glm::vec4(glm::dvec4(plane) * glm::inverse(glm::dmat4(view))) : plane;
    }
    if ((key == "r" && gen.mode == TexGenMode::SphereMap) || (key == "q" && gen.mode >= TexGenMode::SphereMap))
        fail(*n, fmt::format("'{}': GL refuses {} for {} (GL_INVALID_ENUM)", s.name(key),
                             modes[size_t(gen.mode) - 1], key));
}

void read_texture_gen(const Section& s, const glm::mat4& view, std::array<TexGen, 4>& coords) {
    s.allow({"s", "t", "r", "q", "space"});
    bool world = true;
    if (const toml::node* n = s.get("space")) world = choice(*n, s.name("space"), {"world", "eye"}) == 0;
    if (world && glm::determinant(glm::dmat4(view)) == 0)
        fail(s.table(), fmt::format("[{}]: the view matrix is singular, so world-space planes have no eye-space "
                                    "form; give them in eye space (space = \"eye\")", s.path()));
    const char* names[] = {"s", "t", "r", "q"};
    for (int c = 0; c < 4; ++c) read_texgen_coord(s, names[c], view, world, coords[size_t(c)]);
}

}  // namespace

void read_texture_units_fixed(const toml::table& top, const glm::mat4& view, FixedFunction& f) {
    if (const toml::node* n = top.get("texture_env"))
        for (auto&& [k, v] : table(*n, "texture_env")) {
            int unit = index_key(k, 8, "texture_env", kUnitLimit);
            std::string what = fmt::format("texture_env.{}", unit);
            read_texture_env(Section(table(v, what), what), f.texture_env[size_t(unit)]);
        }
    if (const toml::node* n = top.get("texture_gen"))
        for (auto&& [k, v] : table(*n, "texture_gen")) {
            int unit = index_key(k, 8, "texture_gen", kUnitLimit);
            std::string what = fmt::format("texture_gen.{}", unit);
            read_texture_gen(Section(table(v, what), what), view, f.texture_gen[size_t(unit)]);
        }
}

}  // namespace detail
}  // namespace glslrun::scene
