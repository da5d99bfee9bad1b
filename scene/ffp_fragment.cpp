// GL's fixed-function fragment stage as GLSL 1.10 (GL 2.1 §3.8.13-3.10):
// the texture environments, the colour sum and fog, in the form of Mesa's
// ff_fragment_shader.cpp. The classic modes become combiner state as Mesa's
// texstate.c derives it from the texture's base format.
#include <fmt/format.h>

#include "scene/ffp.h"

namespace glslrun::scene::ffp {

int unit_target(const FixedFunction& f, const GLState& gl, int unit) {
    if (unit < 0 || unit >= 8 || !f.texture_env[size_t(unit)].enabled) return -1;
    // GL 2.1 §3.8.15: cube map, then 3D, then (ARB_texture_rectangle) rectangle, 2D, 1D.
    for (TextureTarget t : {TextureTarget::Cube, TextureTarget::Tex3D, TextureTarget::Rect, TextureTarget::Tex2D,
                            TextureTarget::Tex1D}) {
        const auto& bound = gl.texture_units[size_t(unit)].bound[size_t(t)];
        if (bound) return bound->complete() ? int(t) : -1;
    }
    return -1;
}

namespace {

enum class Base { Rgba, Luminance, Intensity, Alpha };

// The combiner state one unit runs, derived or as given.
struct Combiner {
    CombineFunction rgb = CombineFunction::Modulate, alpha = CombineFunction::Modulate;
    std::array<uint8_t, 3> source_rgb{0, 3, 1}, source_alpha{0, 3, 1};
    std::array<CombineOperand, 3> operand_rgb{CombineOperand::SrcColor, CombineOperand::SrcColor,
                                              CombineOperand::SrcAlpha};
    std::array<CombineOperand, 3> operand_alpha{CombineOperand::SrcAlpha, CombineOperand::SrcAlpha,
                                                CombineOperand::SrcAlpha};
    float rgb_scale = 1, alpha_scale = 1;
};

constexpr uint8_t kTexture = uint8_t(CombineSource::Texture), kConstant = uint8_t(CombineSource::Constant),
                  kPrevious = uint8_t(CombineSource::Previous);

Base base_of(const Texture& t) {
    if (!t.depth()) return Base::Rgba;
    switch (t.sampler.depth_mode) {
    case DepthTextureMode::Luminance: return Base::Luminance;
    case DepthTextureMode::Intensity: return Base::Intensity;
    case DepthTextureMode::Alpha: return Base::Alpha;
    }
    return Base::Rgba;
}

// DECAL and BLEND as combiners (GL 2.1 table 3.22).
void derive_decal_blend(TexEnvMode mode, Base base, Combiner& c, CombineFunction& rgb, CombineFunction& alpha) {
    using F = CombineFunction;
    if (mode == TexEnvMode::Decal) {
        rgb = F::Interpolate;
        alpha = F::Replace;
        c.source_alpha[0] = kPrevious;
        if (base != Base::Rgba) c.source_rgb[0] = kPrevious;
        else c.source_rgb[2] = kTexture;
        return;
    }
    rgb = base == Base::Alpha ? F::Replace : F::Interpolate;
    alpha = F::Modulate;
    if (base == Base::Alpha) return;
    if (base == Base::Intensity) {
        alpha = F::Interpolate;
        c.source_alpha[0] = kConstant;
        c.operand_alpha[2] = CombineOperand::SrcAlpha;
    }
    c.source_rgb[2] = c.source_alpha[2] = kTexture;
    c.source_rgb[0] = kConstant;
    c.operand_rgb[2] = CombineOperand::SrcColor;
}

// MODULATE, DECAL, BLEND, REPLACE and ADD as the combiner state GL's tables
// give for the texture's base format, as Mesa derives it.
Combiner derive(const TextureEnv& env, Base base) {
    using F = CombineFunction;
    Combiner c;
    if (env.mode == TexEnvMode::Combine) {
        c = {env.combine_rgb, env.combine_alpha, env.source_rgb, env.source_alpha, env.operand_rgb,
             env.operand_alpha, env.rgb_scale, env.alpha_scale};
        return c;
    }
    if (base == Base::Alpha) c.source_rgb[0] = kPrevious;
    if (base == Base::Luminance) c.source_alpha[0] = kPrevious;
    F rgb = F::Modulate, alpha = F::Modulate;
    switch (env.mode) {
    case TexEnvMode::Replace:
    case TexEnvMode::Modulate:
        alpha = env.mode == TexEnvMode::Replace ? F::Replace : F::Modulate;
        rgb = base == Base::Alpha ? F::Replace : alpha;
        break;
    case TexEnvMode::Decal:
    case TexEnvMode::Blend: derive_decal_blend(env.mode, base, c, rgb, alpha); break;
    case TexEnvMode::Add:
        rgb = base == Base::Alpha ? F::Replace : F::Add;
        alpha = base == Base::Intensity ? F::Add : F::Modulate;
        break;
    case TexEnvMode::Combine: break;
    }
    c.rgb = c.source_rgb[0] != kPrevious ? rgb : F::Replace;
    c.alpha = c.source_alpha[0] != kPrevious ? alpha : F::Replace;
    return c;
}

std::string source_name(uint8_t source, int unit) {
    switch (source) {
    case uint8_t(CombineSource::Texture): return fmt::format("texel{}", unit);
    case uint8_t(CombineSource::Constant): return fmt::format("envColor{}", unit);
    case uint8_t(CombineSource::PrimaryColor): return "gl_Color";
    case uint8_t(CombineSource::Previous): return "previous";
    default: return fmt::format("texel{}", source - kCombineTexture0);
    }
}

// An argument as vec3 (rgb) or float (alpha).
std::string argument(uint8_t source, CombineOperand op, int unit, bool alpha) {
    std::string s = source_name(source, unit);
    switch (op) {
    case CombineOperand::SrcColor: return s + ".rgb";
    case CombineOperand::OneMinusSrcColor: return fmt::format("(1.0 - {}.rgb)", s);
    case CombineOperand::SrcAlpha: return alpha ? s + ".a" : fmt::format("vec3({}.a)", s);
    case CombineOperand::OneMinusSrcAlpha:
        return alpha ? fmt::format("(1.0 - {}.a)", s) : fmt::format("vec3(1.0 - {}.a)", s);
    }
    return s;
}

std::string combine(CombineFunction f, const std::string& a0, const std::string& a1, const std::string& a2) {
    using F = CombineFunction;
    switch (f) {
    case F::Replace: return a0;
    case F::Modulate: return fmt::format("{} * {}", a0, a1);
    case F::Add: return fmt::format("{} + {}", a0, a1);
    case F::AddSigned: return fmt::format("{} + {} + -0.5", a0, a1);
    case F::Interpolate: return fmt::format("{0} * {2} + {1} * (1.0 - {2})", a0, a1, a2);
    case F::Subtract: return fmt::format("{} - {}", a0, a1);
    case F::Dot3Rgb:
    case F::Dot3Rgba: return fmt::format("vec3(dot({} * 2.0 + -1.0, {} * 2.0 + -1.0))", a0, a1);
    }
    return a0;
}

bool needs_saturate(CombineFunction f) {
    using F = CombineFunction;
    return f != F::Replace && f != F::Modulate && f != F::Interpolate;
}

// One channel group's value, clamped where the function can leave [0, 1]
// and no scale follows (the scale clamps after it).
std::string channel(const Combiner& c, int unit, bool alpha) {
    const auto& src = alpha ? c.source_alpha : c.source_rgb;
    const auto& op = alpha ? c.operand_alpha : c.operand_rgb;
    CombineFunction f = alpha ? c.alpha : c.rgb;
    std::string v = combine(f, argument(src[0], op[0], unit, alpha), argument(src[1], op[1], unit, alpha),
                            argument(src[2], op[2], unit, alpha));
    bool scaled = (alpha ? c.alpha_scale : c.rgb_scale) != 1.0f;
    return !scaled && needs_saturate(f) ? fmt::format("clamp({}, 0.0, 1.0)", v) : v;
}

std::string texenv(const Combiner& c, int unit) {
    std::string out = fmt::format("    // texture unit {}\n", unit);
    if (c.rgb == CombineFunction::Dot3Rgba) {
        out += fmt::format("    previous = vec4(({}).x);\n", channel(c, unit, false));
    } else {
        out += fmt::format("    combined.rgb = {};\n", channel(c, unit, false));
        out += fmt::format("    combined.a = {};\n", channel(c, unit, true));
        out += "    previous = combined;\n";
    }
    if (c.rgb_scale != 1.0f || c.alpha_scale != 1.0f)
        out += fmt::format("    previous = clamp(previous * vec4({0}, {0}, {0}, {1}), 0.0, 1.0);\n",
                           literal(c.rgb_scale), literal(c.alpha_scale));
    return out;
}

// The sampler type and the projective lookup of a target (GL's fixed function divides by q).
struct Sampler {
    const char* type;
    const char* function;  // nullptr: textureCube, which has no projective form
};

Sampler sampler_for(TextureTarget t, bool shadow) {
    switch (t) {
    case TextureTarget::Tex1D:
        return shadow ? Sampler{"sampler1DShadow", "shadow1DProj"} : Sampler{"sampler1D", "texture1DProj"};
    case TextureTarget::Tex2D:
        return shadow ? Sampler{"sampler2DShadow", "shadow2DProj"} : Sampler{"sampler2D", "texture2DProj"};
    case TextureTarget::Tex3D: return {"sampler3D", "texture3DProj"};
    case TextureTarget::Cube: return {"samplerCube", nullptr};
    case TextureTarget::Rect:
        return shadow ? Sampler{"sampler2DRectShadow", "shadow2DRectProj"}
                      : Sampler{"sampler2DRect", "texture2DRectProj"};
    }
    return {"sampler2D", "texture2DProj"};
}

std::string lookup(const Sampler& s, const std::string& sampler, const std::string& coord) {
    if (!s.function) return fmt::format("textureCube({0}, {1}.xyz / {1}.w)", sampler, coord);
    return fmt::format("{}({}, {})", s.function, sampler, coord);
}

const Texture& bound_texture(const GLState& gl, int unit, int target) {
    return *gl.texture_units[size_t(unit)].bound[size_t(target)];
}

// Every texel a combiner reads: its own unit's and the crossbar's.
uint8_t read_texels(const Combiner& c, int unit) {
    uint8_t units = 0;
    for (const auto* sources : {&c.source_rgb, &c.source_alpha})
        for (uint8_t s : *sources) {
            if (s == kTexture) units |= uint8_t(1u << unit);
            if (s >= kCombineTexture0) units |= uint8_t(1u << (s - kCombineTexture0));
        }
    return units;
}

std::string fog(const FixedFunction& f, const GLState& gl) {
    // Mesa's gl_FogParamsOptimizedMESA, in float as Mesa computes it.
    const float span = gl.fog.end - gl.fog.start;
    const float scale = span == 0.0f ? 1.0f : -1.0f / span;
    std::string factor;
    switch (f.fog_mode) {
    case FogMode::Linear:
        factor = fmt::format("gl_FogFragCoord * {} + {}", literal(scale), literal(gl.fog.end * -scale));
        break;
    case FogMode::Exp:
        factor = fmt::format("exp2(-(gl_FogFragCoord * {}))",
                             literal(float(double(gl.fog.density) * 1.4426950408889634)));
        break;
    case FogMode::Exp2:
        factor = fmt::format("exp2(-((gl_FogFragCoord * {0}) * (gl_FogFragCoord * {0})))",
                             literal(float(double(gl.fog.density) * 1.2011224087864498)));
        break;
    }
    return fmt::format("    float fogFactor = clamp({}, 0.0, 1.0);\n"
                       "    previous.rgb = gl_Fog.color.rgb * (1.0 - fogFactor) + previous.rgb * fogFactor;\n",
                       factor);
}

}  // namespace

std::string sampler_uniform(int unit) { return fmt::format("ffp_texture{}", unit); }

uint8_t fragment_units(const Scene& scene, const GLState& gl) {
    uint8_t units = 0;
    for (int u = 0; u < 8; ++u)
        if (unit_target(scene.fixed, gl, u) >= 0) units |= uint8_t(1u << u);
    return units;
}

std::string fragment_source(const Scene& scene, const GLState& gl) {
    const FixedFunction& f = scene.fixed;
    std::string head;
    bool rectangle = false;
    std::string body = "void main() {\n    vec4 previous = gl_Color;\n    vec4 combined;\n";
    std::array<Combiner, 8> combiners;
    uint8_t enabled = fragment_units(scene, gl), read = 0;
    for (int u = 0; u < 8; ++u)
        if (enabled >> u & 1) {
            const Texture& t = bound_texture(gl, u, unit_target(f, gl, u));
            combiners[size_t(u)] = derive(f.texture_env[size_t(u)], base_of(t));
            read |= read_texels(combiners[size_t(u)], u);
            body += fmt::format("    const vec4 envColor{} = {};\n", u, literal(f.texture_env[size_t(u)].color));
        }
    for (int u = 0; u < 8; ++u) {
        if (!(read >> u & 1)) continue;
        if (!(enabled >> u & 1)) {  // the crossbar to a disabled unit reads zero, as in Mesa
            body += fmt::format("    vec4 texel{} = vec4(0.0);\n", u);
            continue;
        }
        int target = unit_target(f, gl, u);
        const Texture& t = bound_texture(gl, u, target);
        Sampler s = sampler_for(TextureTarget(target), t.depth() && t.sampler.compare);
        rectangle = rectangle || TextureTarget(target) == TextureTarget::Rect;
        head += fmt::format("uniform {} {};\n", s.type, sampler_uniform(u));
        std::string coord = fmt::format("gl_TexCoord[{}]", u);
        body += fmt::format("    vec4 texel{} = {};\n", u, lookup(s, sampler_uniform(u), coord));
    }
    for (int u = 0; u < 8; ++u)
        if (enabled >> u & 1) body += texenv(combiners[size_t(u)], u);
    if ((f.lighting && f.separate_specular) || f.color_sum)
        body += "    previous.rgb = previous.rgb + gl_SecondaryColor.rgb;\n";
    if (f.fog) body += fog(f, gl);
    std::string out = "// GL's fixed-function fragment stage for this draw's state, generated by glslrun\n";
    if (rectangle) out += "#extension GL_ARB_texture_rectangle : enable\n";
    return out + head + body + "    gl_FragColor = previous;\n}\n";
}

}  // namespace glslrun::scene::ffp
