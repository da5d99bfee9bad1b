// Scene files: the legacy GL state a program reads, as TOML (docs/scene-format.md).
//
// A scene states only what differs from OpenGL 2.1's defaults. load_scene()
// parses and validates a file into a Scene; every mistake comes back as an
// Error citing the TOML file and line. render_scene() draws it with glslrun;
// tools/glref draws the same Scene with Mesa through EGL, so the two images
// differ only by the pipeline.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glslrun/glslrun.h"

namespace glslrun::scene {

// Where a value came from, for messages about it after parsing.
struct SourceLoc {
    std::string file;
    int line = 0;
};

// Geometry ready for glslrun::draw and for glDrawElements alike: attribute
// arrays named by their GLSL names ("gl_Vertex", "gl_Normal", "gl_Color",
// "gl_MultiTexCoord0", or a user attribute's name).
struct Mesh {
    Primitive primitive = Primitive::Triangles;
    std::vector<VertexAttrib> attribs;
    uint32_t vertex_count = 0;
    std::vector<uint32_t> indices;  // empty: draw vertices 0..vertex_count-1 in order
    const VertexAttrib* find(std::string_view name) const;
};

// A user uniform as the scene sets it, applied with glUniform*'s semantics by
// name ("u", "arr[2]", "s.f", "lights[1].pos"). The file's numbers are kept
// as given; the renderer converts them to the program's declared type (an
// integral value may set a float uniform; a fractional one may not set an int).
struct UniformSetting {
    std::string name;
    std::vector<double> values;  // flattened: vectors, then matrix columns, then array elements
    bool integral = true;        // every value is an integer or a boolean
    SourceLoc where;
};

// One light as the file gives it. GL transforms position and spot direction by
// the modelview current at glLightfv: the view matrix for "world" lights (the
// lecture's order: gluLookAt, then glLightfv), the identity for "eye" lights.
struct LightSetting {
    bool enabled = false;  // GL_LIGHTi enabled (only fixed function reads it)
    bool world_space = true;
    LightState as_given;   // position and spot_direction before the transform
    // Whether the file gave GL_POSITION / GL_SPOT_DIRECTION. GL transforms
    // only what glLightfv sets: a parameter left out keeps its eye-space
    // default ((0,0,1,0), (0,0,-1)), which no modelview ever transformed.
    // A position or direction that differs from GL's default counts as given
    // even where the flag was left false (a scene built in code).
    bool has_position = false, has_spot_direction = false;
};
// GL 2.1's lights as a scene without [lights] has them: every light off, light
// 0 with its white diffuse and specular, nothing given.
std::array<LightSetting, 8> default_light_settings();

// A [current] attribute value that no array gives: glMultiTexCoord4f
// ("gl_MultiTexCoord0".."7"), glFogCoordf ("gl_FogCoord") or glVertexAttrib4f
// (a user attribute's name). Missing components are GL's (0, 0, 0, 1).
struct CurrentAttribute {
    std::string name;
    glm::vec4 value{0, 0, 0, 1};
    SourceLoc where;
};


// One [textures.N] table: a texture object bound to unit N. The texels are
// final (read, generated, rounded to the internal format) and shared by every
// renderer: render_scene binds the object itself, tools/glref uploads its
// texels to Mesa, so both sample identical data.
// The channels a float texture's internal format keeps (ARB_texture_float's
// luminance, intensity and alpha formats, ARB_texture_rg's red and
// red-green, RGB): the texels are stored expanded to RGBA as GL returns them
// (missing green and blue 0, alpha 1; luminance and intensity repeat red),
// and glref uploads them in the real format.
enum class TextureChannels : uint8_t { Rgba, Rgb, Rg, Red, Luminance, LuminanceAlpha, Intensity, Alpha };

struct TextureSetting {
    int unit = 0;
    std::shared_ptr<const Texture> texture;
    TextureChannels channels = TextureChannels::Rgba;  // the float formats' (internal_format)
    // GL_GENERATE_MIPMAP: levels 1.. were generated from level 0. glref then
    // uploads level 0 only and lets Mesa generate the rest (glGenerateMipmap),
    // so the comparison also covers glslrun's mipmap generation.
    bool generate_mipmap = false;
    // `render_target`: the texture is an attachment of a render target (an
    // FBO's texture), not texels of its own: `texture` holds its sampler
    // state, and what the passes drew into the target replaces its texels
    // after every pass into it. attachment: 0..7 colour, -1 depth.
    int render_target = -1;
    int attachment = 0;
    SourceLoc where;
};

// Fixed-function state that only GL's fixed-function stages read: a draw
// without a vertex or fragment shader (a pass's `program = "fixed"`, or a
// program of one stage) runs stages that scene/ffp_*.cpp generate from it as
// GLSL 1.10, as Mesa generates its own. Scene-wide: [fixed_function],
// [light_model] color_control, [fog] mode and coord_src, [texture_env.N],
// [texture_gen.N] (docs/scene-format.md). Shaders never see it.
enum class TexEnvMode : uint8_t { Modulate, Decal, Blend, Replace, Add, Combine };
// GL_COMBINE_RGB / GL_COMBINE_ALPHA (DOT3 for RGB only).
enum class CombineFunction : uint8_t { Replace, Modulate, Add, AddSigned, Interpolate, Subtract, Dot3Rgb, Dot3Rgba };
// GL_SRCn_RGB / GL_SRCn_ALPHA: texture, constant, primary_color, previous,
// then texture0..texture7 (the crossbar) as kCombineTexture0 + n.
enum class CombineSource : uint8_t { Texture, Constant, PrimaryColor, Previous };
inline constexpr uint8_t kCombineTexture0 = 4;
enum class CombineOperand : uint8_t { SrcColor, OneMinusSrcColor, SrcAlpha, OneMinusSrcAlpha };
struct TextureEnv {
    bool enabled = false;  // glEnable of the bound texture's target on the unit
    TexEnvMode mode = TexEnvMode::Modulate;
    glm::vec4 color{0, 0, 0, 0};  // GL_TEXTURE_ENV_COLOR
    CombineFunction combine_rgb = CombineFunction::Modulate, combine_alpha = CombineFunction::Modulate;
    std::array<uint8_t, 3> source_rgb{0, 3, 1}, source_alpha{0, 3, 1};  // texture, previous, constant
    std::array<CombineOperand, 3> operand_rgb{CombineOperand::SrcColor, CombineOperand::SrcColor,
                                              CombineOperand::SrcAlpha};
    std::array<CombineOperand, 3> operand_alpha{CombineOperand::SrcAlpha, CombineOperand::SrcAlpha,
                                                CombineOperand::SrcAlpha};
    float rgb_scale = 1, alpha_scale = 1;  // 1, 2 or 4
};
enum class TexGenMode : uint8_t { Off, ObjectLinear, EyeLinear, SphereMap, NormalMap, ReflectionMap };
struct TexGen {
    TexGenMode mode = TexGenMode::Off;  // Off: GL_TEXTURE_GEN_x disabled
    glm::vec4 object_plane{0, 0, 0, 0};
    glm::vec4 eye_plane{0, 0, 0, 0};  // eye space, as glTexGen stores it
};
enum class FogMode : uint8_t { Linear, Exp, Exp2 };
enum class ColorMaterialMode : uint8_t { Emission, Ambient, Diffuse, Specular, AmbientAndDiffuse };
struct FixedFunction {
    bool lighting = false;        // glEnable(GL_LIGHTING)
    bool color_material = false;  // glEnable(GL_COLOR_MATERIAL) with glColorMaterial(face, mode)
    bool color_material_front = true, color_material_back = true;
    ColorMaterialMode color_material_mode = ColorMaterialMode::AmbientAndDiffuse;
    bool normalize = false, rescale_normal = false;  // GL_NORMALIZE, GL_RESCALE_NORMAL
    bool separate_specular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL = GL_SEPARATE_SPECULAR_COLOR
    bool color_sum = false;          // glEnable(GL_COLOR_SUM)
    bool fog = false;                // glEnable(GL_FOG)
    FogMode fog_mode = FogMode::Exp;
    bool fog_coord_from_array = false;  // GL_FOG_COORD_SRC = GL_FOG_COORD (else GL_FRAGMENT_DEPTH)
    std::array<TextureEnv, 8> texture_env;
    std::array<std::array<TexGen, 4>, 8> texture_gen = default_texture_gen();
    static std::array<std::array<TexGen, 4>, 8> default_texture_gen();
};

struct Object {
    std::string name;              // for messages; "objects[2]" when unnamed
    Mesh mesh;
    glm::mat4 model{1.0f};         // translate/rotate/scale in GL's order of application
    std::optional<glm::vec4> color;  // glColor for gl_Color when the mesh has no colours
    std::optional<MaterialState> front_material, back_material;  // overrides
    std::vector<UniformSetting> uniforms;
    // [objects.textures.N]: glBindTexture on unit N before this object's draw.
    // Bindings are context state: they stay for the objects drawn after it.
    std::vector<TextureSetting> textures;
    // [objects.state]: the scene's GL state with this object's render state
    // keys on top (lights, materials and textures stay the scene's).
    std::optional<GLState> state;
    SourceLoc where;
};

// One [render_targets.NAME]: a framebuffer object whose colour and depth
// attachments are textures (GL_RGBA8 and GL_DEPTH24_STENCIL8) of its own
// size. Passes draw into it (`target`), [textures.N] sample it.
struct RenderTarget {
    std::string name;
    int width = 0, height = 0;
    int color_buffers = 1;  // GL_COLOR_ATTACHMENT0 .. n-1
    // The colour attachments' internal format: RGBA8, RGBA16F or RGBA32F
    // (ARB_texture_float; float ones are drawn unclamped, ARB_color_buffer_float).
    TextureFormat format = TextureFormat::RGBA8;
    SourceLoc where;
};


// One [[passes]] entry: the objects drawn again with a program and state of
// the pass's own, as a multi-pass GL program does (a depth pre-pass, then a
// blended pass; one pass per light). Passes run in file order into one
// framebuffer, cleared once before the first.
struct Pass {
    std::string name;  // for messages; "passes[1]" when unnamed
    // The pass's shaders, read from the files it names (relative to the scene
    // file). Both empty: the program given with the scene (the command line's).
    // One of them empty: that stage is GL's fixed function (generated per
    // draw); both empty: the scene's program, or fixed function for both
    // stages where `fixed_function` (`program = "fixed"`).
    std::vector<ShaderSource> vertex, fragment;
    bool fixed_function = false;
    GLState state;  // the scene's [state] with the pass's `state` keys on top
    std::vector<UniformSetting> uniforms;  // set on the pass's program before its objects
    std::vector<size_t> objects;           // indices into Scene::objects, in scene order
    // Per object (by index into Scene::objects): its `state` keys on top of
    // the pass's state; empty for objects without a state of their own.
    std::vector<std::optional<GLState>> object_states;
    int target = -1;  // index into Scene::targets; -1: the output framebuffer
    // A glClear before its first draw, with GL's default masks and no
    // scissor; a buffer left out is not cleared.
    ClearValues clear;
    // `camera`: the view under the objects' transforms for this pass (the
    // projection is in `state` and object_states). Lights and clip planes
    // keep the scene camera's eye space, as GL stored them at glLightfv.
    std::optional<glm::mat4> view;
    bool own_projection = false;  // `camera` gave one: the output's size does not change it
    SourceLoc where;
};

// [animation]: what `glslrun --frames N` sets per frame: the float uniform
// `time_uniform` = frame / frames_per_second seconds.
struct Animation {
    std::string time_uniform = "time";
    double frames_per_second = 30;
};

struct Camera {
    enum class Kind { Matrix, Perspective, Ortho, Frustum } kind = Kind::Matrix;
    float fovy = 45, aspect = 0;  // aspect 0: width / height, kept when the size changes
    float left = -1, right = 1, bottom = -1, top = 1, near = -1, far = 1;  // ortho, frustum; near/far also perspective
};

struct Scene {
    std::string path;
    Camera camera;
    int width = 512, height = 512;
    glm::vec4 clear_color{0, 0, 0, 0};  // GL's default
    float clear_depth = 1.0f;
    int clear_stencil = 0;
    // The one source of the matrices and the lights: every draw takes
    // modelview = view * model, projection, and the lights transformed to eye
    // space by `view` (derive_eye_space_lights) from these fields.
    glm::mat4 view{1.0f};        // the camera: modelview before any object transform
    glm::mat4 projection{1.0f};
    std::array<LightSetting, 8> lights = default_light_settings();
    // Everything else of the GL state. Its modelview, projection and lights
    // are copies that load_scene fills in for readers; leave them at GL's
    // defaults in a scene built in code. A copy that differs from both its
    // default and what the fields above give is refused by render_scene
    // (it would be ignored), never drawn silently.
    GLState gl;
    FixedFunction fixed;  // what generated fixed-function stages read
    std::vector<TextureSetting> textures;  // by unit, ascending
    std::vector<RenderTarget> targets;     // [render_targets.NAME], in file order
    std::vector<UniformSetting> uniforms;  // for every object
    // [current] tex_coords, fog_coord and attributes: what a draw reads for
    // those attributes when its mesh has no array of them.
    std::vector<CurrentAttribute> current_attributes;
    std::vector<Object> objects;
    // [[passes]]; empty: one pass of every object with the scene's program and state.
    std::vector<Pass> passes;
    Animation animation;
    // The image and mesh files the scene read (its textures, OBJ meshes), as
    // opened; a pass's shader files are its sources' names. The command line
    // never writes an output over any of them.
    std::vector<std::string> files;
    // Legal but probably unintended settings, e.g. a texture that GL 2.1's
    // completeness rules make sample as (0, 0, 0, 1). Renderers print them.
    std::vector<Diagnostic> warnings;
};

// Sizes beyond this are refused before anything is allocated.
constexpr int kMaxImageSide = 16384;

Result<Scene> parse_scene(std::string_view toml_text, const std::string& path);
Result<Scene> load_scene(const std::string& path);  // relative mesh paths are relative to the file

// `--uniform name=value`: the value as a scene's [uniforms] entry writes it
// ("0.5", "[1, 0, 0]", "3", "true"); errors name the argument.
Result<std::vector<UniformSetting>> parse_uniform_override(std::string_view arg);
// Appends `settings` after the scene's and every object's own uniforms, so they win.
void override_uniforms(Scene& scene, const std::vector<UniformSetting>& settings);

// The eye-space lights every draw uses: scene.lights transformed by scene.view
// as glLightfv after gluLookAt would.
std::array<LightState, 8> eye_space_lights(const Scene& scene);
// Sets scene.gl's copies (modelview, projection, lights) from view,
// projection and lights, for code that reads scene.gl; rendering does not
// need it (load_scene and resize_scene call it).
void derive_eye_space_lights(Scene& scene);

// Sets GL state on a scene as a scene file's sections set it, on top of
// what the scene holds: `toml_text` holds any of [camera], [lights.N],
// [light_model], [material], [front_material], [back_material], [current],
// [state], [fog] and [texture_matrix.N] (docs/scene-format.md), read and
// checked exactly as in a file; errors name `what` and the line. scene.gl's
// eye-space copies are derived again. The camera and lights reach every
// draw; the other sections change the scene's own state, so a scene whose
// [[passes]] or objects have state of their own refuses them (those draws
// would not see it). Python's Scene.set_state & co.
Status update_scene_state(Scene& scene, std::string_view toml_text, const std::string& what);

// Changes the output size (--size) and keeps a perspective camera's aspect
// ratio equal to width/height when the file gave no explicit aspect.
Status resize_scene(Scene& scene, int width, int height);

}  // namespace glslrun::scene
