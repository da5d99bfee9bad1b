#include "tools/glref/gl_fixed.h"

#include <glm/gtc/type_ptr.hpp>

#include "scene/ffp.h"

namespace glslrun::glref {

namespace {

using scene::FixedFunction;

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

void set_color_material(const FixedFunction& f) {
    constexpr GLenum kModes[] = {GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE};
    GLenum face = f.color_material_front && f.color_material_back ? GL_FRONT_AND_BACK
                  : f.color_material_front                        ? GL_FRONT
                                                                  : GL_BACK;
    glColorMaterial(face, kModes[int(f.color_material_mode)]);
    enable(GL_COLOR_MATERIAL, f.color_material);
}

GLenum source_enum(uint8_t source) {
    constexpr GLenum kSources[] = {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS};
    if (source < scene::kCombineTexture0) return kSources[source];
    return GLenum(GL_TEXTURE0 + (source - scene::kCombineTexture0));
}

void set_combine(const scene::TextureEnv& e) {
    constexpr GLenum kFunctions[] = {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE,
                                     GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
    constexpr GLenum kOperands[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GLint(kFunctions[int(e.combine_rgb)]));
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GLint(kFunctions[int(e.combine_alpha)]));
    for (int i = 0; i < 3; ++i) {
        glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_SRC0_RGB + i), GLint(source_enum(e.source_rgb[size_t(i)])));
        glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_SRC0_ALPHA + i), GLint(source_enum(e.source_alpha[size_t(i)])));
        glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_OPERAND0_RGB + i), GLint(kOperands[int(e.operand_rgb[size_t(i)])]));
        glTexEnvi(GL_TEXTURE_ENV, GLenum(GL_OPERAND0_ALPHA + i), GLint(kOperands[int(e.operand_alpha[size_t(i)])]));
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, e.rgb_scale);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, e.alpha_scale);
}

void set_texture_env(const scene::TextureEnv& e) {
    constexpr GLenum kModes[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD, GL_COMBINE};
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GLint(kModes[int(e.mode)]));
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, glm::value_ptr(e.color));
    set_combine(e);
}

// The planes are eye-space already (the parser applied the view's inverse):
// with an identity modelview glTexGen stores them as given.
void set_texture_gen(const std::array<scene::TexGen, 4>& coords) {
    constexpr GLenum kCoords[] = {GL_S, GL_T, GL_R, GL_Q};
    constexpr GLenum kEnables[] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
    constexpr GLenum kModes[] = {GL_OBJECT_LINEAR, GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_NORMAL_MAP,
                                 GL_REFLECTION_MAP};
    for (int c = 0; c < 4; ++c) {
        const scene::TexGen& g = coords[size_t(c)];
        glTexGeni(kCoords[c], GL_TEXTURE_GEN_MODE, GLint(kModes[int(g.mode)]));
        glTexGenfv(kCoords[c], GL_OBJECT_PLANE, glm::value_ptr(g.object_plane));
        glTexGenfv(kCoords[c], GL_EYE_PLANE, glm::value_ptr(g.eye_plane));
        enable(kEnables[c], g.mode != scene::TexGenMode::Off);
    }
}

}  // namespace

void set_fixed_function_state(const GLFunctions& gl, const scene::Scene& scene) {
    const FixedFunction& f = scene.fixed;
    enable(GL_LIGHTING, f.lighting);
    set_color_material(f);
    enable(GL_NORMALIZE, f.normalize);
    enable(GL_RESCALE_NORMAL, f.rescale_normal);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, f.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    enable(GL_COLOR_SUM, f.color_sum);
    enable(GL_FOG, f.fog);
    constexpr GLenum kFogModes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
    glFogi(GL_FOG_MODE, GLint(kFogModes[int(f.fog_mode)]));
    glFogi(GL_FOG_COORD_SRC, f.fog_coord_from_array ? GL_FOG_COORD : GL_FRAGMENT_DEPTH);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (int unit = 0; unit < 8; ++unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        set_texture_env(f.texture_env[size_t(unit)]);
        set_texture_gen(f.texture_gen[size_t(unit)]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
}

void enable_texture_targets(const GLFunctions& gl, const scene::Scene& scene, const GLState& bound) {
    // By TextureTarget: 1D, 2D, 3D, cube map, rectangle.
    constexpr GLenum kTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                                   GL_TEXTURE_RECTANGLE};
    for (int unit = 0; unit < 8; ++unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        int target = scene::ffp::unit_target(scene.fixed, bound, unit);
        for (int t = 0; t < 5; ++t) enable(kTargets[t], t == target);
    }
    gl.ActiveTexture(GL_TEXTURE0);
}

}  // namespace glslrun::glref
