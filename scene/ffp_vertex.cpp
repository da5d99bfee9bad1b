// GL's fixed-function vertex stage as GLSL 1.10 (GL 2.1 §2.11-2.14): the
// terms of Mesa's ffvertex_prog.c in its order, so that the colours match
// Mesa's within rounding. Each function writes one part of main().
#include <fmt/format.h>

#include "scene/ffp.h"

namespace glslrun::scene::ffp {

std::string literal(float v) {
    std::string s = fmt::format("{}", v);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string literal(const glm::vec4& v) {
    return fmt::format("vec4({}, {}, {}, {})", literal(v.x), literal(v.y), literal(v.z), literal(v.w));
}

bool two_sided_lighting(const Scene& scene, const GLState& gl) {
    return scene.fixed.lighting && gl.light_model_two_side;
}

namespace {

struct Side {
    const char* name;  // "Front", "Back"
    const MaterialState& material;
    bool tracks;       // GL_COLOR_MATERIAL applies to this side
    const char* sign;  // the back face lights the negated normal
};

bool tracked(const FixedFunction& f, const Side& side, ColorMaterialMode property) {
    if (!f.color_material || !side.tracks) return false;
    if (f.color_material_mode == ColorMaterialMode::AmbientAndDiffuse)
        return property == ColorMaterialMode::Ambient || property == ColorMaterialMode::Diffuse;
    return f.color_material_mode == property;
}

// The material's property: the uniform, or gl_Color where GL_COLOR_MATERIAL tracks it.
std::string material(const FixedFunction& f, const Side& side, ColorMaterialMode property, const char* field) {
    return tracked(f, side, property) ? "gl_Color" : fmt::format("gl_{}Material.{}", side.name, field);
}

// Light i's ambient, diffuse or specular product with the material.
std::string product(const FixedFunction& f, const Side& side, int light, ColorMaterialMode property,
                    const char* field) {
    if (tracked(f, side, property)) return fmt::format("(gl_LightSource[{}].{} * gl_Color)", light, field);
    return fmt::format("gl_{}LightProduct[{}].{}", side.name, light, field);
}

// Emission + ambient * the model's ambient, with the diffuse alpha (GL 2.1 eq. 2.1).
std::string scene_color(const FixedFunction& f, const Side& side) {
    using M = ColorMaterialMode;
    if (!tracked(f, side, M::Emission) && !tracked(f, side, M::Ambient) && !tracked(f, side, M::Diffuse))
        return fmt::format("gl_{}LightModelProduct.sceneColor", side.name);
    return fmt::format("vec4(gl_LightModel.ambient.rgb * {}.rgb + {}.rgb, {}.a)",
                       material(f, side, M::Ambient, "ambient"), material(f, side, M::Emission, "emission"),
                       material(f, side, M::Diffuse, "diffuse"));
}

bool positional(const LightState& l) { return l.position.w != 0.0f; }
bool attenuated(const LightState& l) {
    return l.constant_attenuation != 1.0f || l.linear_attenuation != 0.0f || l.quadratic_attenuation != 0.0f;
}

// VP (the unit vector to the light) and att, the distance and spot attenuation.
std::string light_direction(int i, const LightState& l) {
    std::string out;
    if (!positional(l)) {
        out += fmt::format("    VP = normalize(gl_LightSource[{}].position.xyz);\n    att = 1.0;\n", i);
    } else {
        out += fmt::format("    VP = gl_LightSource[{}].position.xyz - eye.xyz;\n", i);
        out += "    rdist = inversesqrt(dot(VP, VP));\n    VP = VP * rdist;\n    att = 1.0;\n";
        if (attenuated(l))
            out += fmt::format("    dist = 1.0 / rdist;\n    att = 1.0 / dot(vec3(1.0, dist, dist * dist), "
                               "vec3(gl_LightSource[{0}].constantAttenuation, gl_LightSource[{0}].linearAttenuation, "
                               "gl_LightSource[{0}].quadraticAttenuation));\n", i);
    }
    if (l.spot_cutoff != 180.0f)
        out += fmt::format("    spot = dot(-VP, normalize(gl_LightSource[{0}].spotDirection));\n"
                           "    att = att * (gl_LightSource[{0}].spotCosCutoff < spot ? "
                           "pow(spot, gl_LightSource[{0}].spotExponent) : 0.0);\n", i);
    return out;
}

// The half vector for the specular term: the local or the infinite viewer's.
std::string half_vector(int i, const LightState& l, const GLState& gl) {
    if (gl.light_model_local_viewer) return "    halfV = normalize(VP - normalize(eye.xyz));\n";
    if (!positional(l)) return fmt::format("    halfV = gl_LightSource[{}].halfVector.xyz;\n", i);
    return "    halfV = normalize(VP + vec3(0.0, 0.0, 1.0));\n";
}

// One side's terms of light i, added to `color` (and `specular` with the separate specular colour).
std::string light_side(const FixedFunction& f, const Side& side, int i, const std::string& color,
                       const std::string& specular) {
    using M = ColorMaterialMode;
    std::string n_vp = fmt::format("{}nDotVP", side.sign), n_h = fmt::format("{}nDotH", side.sign);
    std::string out = fmt::format("    {}.rgb = att * {}.rgb + {}.rgb;\n", color,
                                  product(f, side, i, M::Ambient, "ambient"), color);
    out += fmt::format("    {}.rgb = (max({}, 0.0) * att) * {}.rgb + {}.rgb;\n", color, n_vp,
                       product(f, side, i, M::Diffuse, "diffuse"), color);
    std::string factor = side.material.shininess == 0.0f
                             ? fmt::format("({} > 0.0 ? 1.0 : 0.0)", n_vp)
                             : fmt::format("({} > 0.0 ? pow(max({}, 0.0), gl_{}Material.shininess) : 0.0)", n_vp,
                                           n_h, side.name);
    out += fmt::format("    {}.rgb = ({} * att) * {}.rgb + {}.rgb;\n", specular, factor,
                       product(f, side, i, M::Specular, "specular"), specular);
    return out;
}

std::string lighting(const Scene& scene, const GLState& gl) {
    const FixedFunction& f = scene.fixed;
    const bool two = two_sided_lighting(scene, gl), separate = f.separate_specular;
    Side front{"Front", gl.front_material, f.color_material_front, ""};
    Side back{"Back", gl.back_material, f.color_material_back, "-"};
    std::string out = "    vec3 VP, halfV;\n    float att, rdist, dist, spot, nDotVP, nDotH;\n";
    out += fmt::format("    vec4 front = {};\n", scene_color(f, front));
    out += "    vec4 frontSpecular = vec4(0.0, 0.0, 0.0, 1.0);\n";
    if (two) out += fmt::format("    vec4 back = {};\n    vec4 backSpecular = vec4(0.0, 0.0, 0.0, 1.0);\n",
                                scene_color(f, back));
    for (int i = 0; i < 8; ++i) {
        if (!scene.lights[size_t(i)].enabled) continue;
        const LightState& l = gl.lights[size_t(i)];
        out += fmt::format("    // GL_LIGHT{}\n", i) + light_direction(i, l) + half_vector(i, l, gl);
        out += "    nDotVP = dot(normal, VP);\n    nDotH = dot(normal, halfV);\n";
        out += light_side(f, front, i, "front", separate ? "frontSpecular" : "front");
        if (two) out += light_side(f, back, i, "back", separate ? "backSpecular" : "back");
    }
    out += "    gl_FrontColor = front;\n    gl_FrontSecondaryColor = frontSpecular;\n";
    out += two ? "    gl_BackColor = back;\n    gl_BackSecondaryColor = backSpecular;\n"
               : "    gl_BackColor = front;\n    gl_BackSecondaryColor = frontSpecular;\n";
    return out;
}

std::string unlit_colors() {
    return "    gl_FrontColor = gl_Color;\n    gl_BackColor = gl_Color;\n"
           "    gl_FrontSecondaryColor = gl_SecondaryColor;\n    gl_BackSecondaryColor = gl_SecondaryColor;\n";
}

// One texture coordinate of texgen: s, t, r or q of unit `unit`.
std::string texgen_coord(const TexGen& g, int unit, int c) {
    const char* xyzw = "xyzw";
    switch (g.mode) {
    case TexGenMode::Off: return fmt::format("gl_MultiTexCoord{}.{}", unit, xyzw[c]);
    case TexGenMode::ObjectLinear: return fmt::format("dot(gl_Vertex, {})", literal(g.object_plane));
    case TexGenMode::EyeLinear: return fmt::format("dot(eye, {})", literal(g.eye_plane));
    case TexGenMode::SphereMap: return fmt::format("sphere.{}", xyzw[c]);
    case TexGenMode::ReflectionMap: return fmt::format("reflection.{}", xyzw[c]);
    case TexGenMode::NormalMap: return fmt::format("normal.{}", xyzw[c]);
    }
    return "0.0";
}

bool uses_mode(const FixedFunction& f, uint8_t units, TexGenMode mode) {
    for (int u = 0; u < 8; ++u)
        for (const TexGen& g : f.texture_gen[size_t(u)])
            if ((units >> u & 1) && g.mode == mode) return true;
    return false;
}

// The reflection vector and the sphere map's (s, t), as Mesa computes them.
std::string texgen_vectors(const FixedFunction& f, uint8_t units) {
    const bool sphere = uses_mode(f, units, TexGenMode::SphereMap);
    if (!sphere && !uses_mode(f, units, TexGenMode::ReflectionMap)) return {};
    std::string out = "    vec3 eyeHat = normalize(eye.xyz);\n"
                      "    vec3 reflection = eyeHat - (2.0 * dot(normal, eyeHat)) * normal;\n";
    if (sphere)
        out += "    vec3 sphereR = reflection + vec3(0.0, 0.0, 1.0);\n"
               "    vec2 sphere = reflection.xy * (inversesqrt(dot(sphereR, sphereR)) * 0.5) + 0.5;\n";
    return out;
}

std::string texcoords(const FixedFunction& f, uint8_t units) {
    std::string out = texgen_vectors(f, units);
    for (int u = 0; u < 8; ++u) {
        if (!(units >> u & 1)) continue;
        const auto& gen = f.texture_gen[size_t(u)];
        bool any = false;
        for (const TexGen& g : gen) any = any || g.mode != TexGenMode::Off;
        std::string coord = fmt::format("gl_MultiTexCoord{}", u);
        if (any)
            coord = fmt::format("vec4({}, {}, {}, {})", texgen_coord(gen[0], u, 0), texgen_coord(gen[1], u, 1),
                                texgen_coord(gen[2], u, 2), texgen_coord(gen[3], u, 3));
        out += fmt::format("    gl_TexCoord[{0}] = gl_TextureMatrix[{0}] * {1};\n", u, coord);
    }
    return out;
}

// The normal in eye space, normalized or rescaled as GL_NORMALIZE and GL_RESCALE_NORMAL say.
std::string eye_normal(const FixedFunction& f) {
    if (f.normalize) return "    vec3 normal = normalize(gl_NormalMatrix * gl_Normal);\n";
    if (f.rescale_normal) return "    vec3 normal = (gl_NormalMatrix * gl_Normal) * gl_NormalScale;\n";
    return "    vec3 normal = gl_NormalMatrix * gl_Normal;\n";
}

// GL 1.4's distance attenuation, as Mesa's fixed-function program computes
// it (d = |eye z|, the RSQ of |x|) and only where the attenuation is not
// (1, 0, 0); the rasterizer then takes the size (ir::Program::fixed_function_vertex).
std::string point_size(const GLState& gl) {
    if (gl.point_distance_attenuation == glm::vec3(1, 0, 0)) return {};
    return "    float d = abs(eye.z);\n"
           "    float size = gl_Point.size * inversesqrt(abs(gl_Point.distanceConstantAttenuation + d * "
           "(gl_Point.distanceLinearAttenuation + d * gl_Point.distanceQuadraticAttenuation)));\n"
           "    gl_PointSize = min(max(size, gl_Point.sizeMin), gl_Point.sizeMax);\n";
}

}  // namespace

std::string vertex_source(const Scene& scene, const GLState& gl, const VertexNeeds& needs) {
    const FixedFunction& f = scene.fixed;
    std::string out = "// GL's fixed-function vertex stage for this draw's state, generated by glslrun\n"
                      "void main() {\n"
                      "    vec4 eye = gl_ModelViewMatrix * gl_Vertex;\n";
    out += eye_normal(f);
    out += "    gl_Position = ftransform();\n";
    if (gl.clip_plane_enabled) out += "    gl_ClipVertex = eye;\n";
    out += f.lighting ? lighting(scene, gl) : unlit_colors();
    out += texcoords(f, needs.texcoords);
    out += f.fog_coord_from_array ? "    gl_FogFragCoord = gl_FogCoord;\n" : "    gl_FogFragCoord = abs(eye.z);\n";
    return out + point_size(gl) + "}\n";
}

}  // namespace glslrun::scene::ffp
