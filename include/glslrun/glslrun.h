// glslrun: legacy GLSL (1.10/1.20) on the CPU. The one public header.
//
//   auto prog = glslrun::Program::compile({{"a.vert", vs}}, {{"a.frag", fs}});
//   if (!prog) { fmt::print("{}", prog.error().str()); return 1; }
//   prog->set_uniform("tint", glm::vec4(1, 0, 0, 1));
//   glslrun::Framebuffer fb(256, 256);
//   glslrun::GLState gl;                       // OpenGL's defaults
//   auto st = glslrun::draw(*prog, gl, fb, glslrun::Primitive::Triangles, mesh);
//
// Every user mistake comes back as an Error value; nothing here exits.
#pragma once
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "glslrun/span.h"
#include "glslrun/version.h"

namespace glslrun {

// ---------------------------------------------------------------- errors ---
struct Diagnostic {
    std::string file;  // may be empty
    int line = 0;      // 0 when there is no line
    std::string message;
    bool warning = false;
    // "file:line: error: message" (or without the parts that are missing)
    std::string str() const;
};

struct Error {
    std::vector<Diagnostic> diagnostics;
    // The input is GLSL of a version or profile glslrun does not run (it
    // runs GLSL 1.10 and 1.20): refused before anything else, never compiled.
    bool unsupported_version = false;
    Error() = default;
    explicit Error(std::string message, std::string file = {}, int line = 0);
    std::string str() const;  // one diagnostic per line
};

// What value() throws on a Result that holds an error: what() is
// "glslrun: value() of a failed result:" and the error's diagnostics.
class BadResultAccess : public std::logic_error {
public:
    explicit BadResultAccess(const Error& e)
        : std::logic_error("glslrun: value() of a failed result:\n" + e.str()), error(e) {}
    Error error;
};

// A value or an Error. Check it (ok(), or `if (result)`) before value(), *
// or ->; those throw BadResultAccess on an error, error() throws
// std::logic_error on a value.
template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : v_(std::move(value)) {}
    Result(Error e) : v_(std::move(e)) {}
    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }
    T& value() { check(); return std::get<0>(v_); }
    const T& value() const { check(); return std::get<0>(v_); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    const Error& error() const {
        if (ok()) throw std::logic_error("glslrun: error() of a successful result");
        return std::get<1>(v_);
    }
private:
    void check() const {
        if (!ok()) throw BadResultAccess(std::get<1>(v_));
    }
    std::variant<T, Error> v_;
};

struct Ok {};
using Status = Result<Ok>;

// --------------------------------------------------------------- compile ---
struct ShaderSource {
    std::string name;  // used in diagnostics: "name:line: error: ..."
    std::string text;
};

struct CompileOptions {
    int default_version = 110;   // for sources without #version
    bool optimize = true;        // fold, copy propagation, DCE
    uint32_t inline_budget = 4000;  // IR nodes a call site may add when inlined
    // Checks the IR after every pass: a failure is an internal error naming
    // the pass. For glslrun's own tests; GLSLRUN_VERIFY=1 in the environment
    // switches it on too.
    bool verify_ir = false;
    // Preprocessor definitions, as glslangValidator's -D: "NAME" or
    // "NAME=VALUE" becomes `#define NAME VALUE` ahead of every source, line
    // numbers unchanged. NAME must be an identifier (not GL_ or __ reserved).
    std::vector<std::string> defines;
    // Compiles in checks of the operations whose result GLSL 1.10/1.20 leaves
    // undefined (pow of x < 0, division by zero, an array index out of
    // range, ...; docs/debugging.md). They report only to the shader
    // debugger (`glslrun --check-undefined`, check_undefined() in
    // glslrun/undefined.h); images do not change. Off: no check is compiled.
    bool check_undefined = false;
    // Directories for `#include "name"` and `#include <name>` (a shader
    // with `#extension GL_GOOGLE_include_directive : require`, as
    // glslangValidator's -I): a name is looked up beside the file that
    // includes it (ShaderSource::name's directory), then in these in order.
    // Errors in an included file name it and its line; included files
    // count toward the stage's 1 MiB of source and nest at most 32 deep.
    std::vector<std::string> include_dirs;
};

// How shaders evaluate floating point (docs/precision.md).
//   Reference: the whole IR in double, libm's double functions; the ground
//              truth that the error report measures against. Slow.
//   Precise:   fp32 with glslrun's own built-ins (<= 2 ULP where the docs say
//              so), identical bits on every x86-64 machine. The default.
//   Fast:      fp32 with GPU-style approximations (reciprocal and rsqrt
//              estimates, polynomial exp2/log2, pow as exp2(y*log2 x)).
enum class Precision { Reference, Precise, Fast };
// "reference", "precise", "fast" (the command line's --precision names).
const char* precision_name(Precision p);
Result<Precision> parse_precision(std::string_view name);

// Who runs the shaders (runtime/backend.h):
//   Interp: the batched interpreter, every precision mode.
//   Jit:    native vector code compiled by LLVM, the interpreter's bits;
//           Precise and Fast only (Reference runs on the interpreter), and
//           only where glslrun was built with it (GLSLRUN_JIT).
//   Auto:   the JIT where it is built in and the mode allows, else the
//           interpreter. The default.
enum class Backend { Interp, Jit, Auto };
// "interp", "jit", "auto" (the command line's --backend names).
const char* backend_name(Backend b);
Result<Backend> parse_backend(std::string_view name);

// The JIT's tiers (docs/architecture.md), the same bits in each:
//   Tiered:    the default. The first draws run code compiled to keep each
//              compile near 100 ms (large shaders and vertex shaders with
//              LLVM's quick code generation); a stage whose draws keep
//              running is compiled again in the background with all of
//              LLVM's code-generation optimizations, and its later draws run
//              that code. A short render never starts that compile.
//   First:     the first tier's code only.
//   Optimised: the second tier's code only, from the first draw
//              (Backend::Jit waits for it to compile).
enum class JitTier { Tiered, First, Optimised };
// Whether this build has the JIT.
bool jit_available();
// The backend that runs `requested` in `precision`: Auto is the JIT where
// built in, and Reference always runs on the interpreter.
Backend effective_backend(Backend requested, Precision precision);

struct ExecOptions {
    // Iterations of all loops of one batch together; past it the draw stops
    // with a clear error instead of hanging.
    uint64_t max_loop_iterations = 1u << 22;
    // Instructions one batch may execute, counted per block as it is entered
    // (an upper bound); past it the draw stops with a clear error. It bounds
    // the work of shaders without loops too: 30 functions that each call the
    // one before twice make 2^29 calls.
    uint64_t max_instructions = uint64_t(1) << 28;
    // Instructions of one draw() or run_* call, all its batches and threads
    // together; past it the call stops with a clear error. The budgets per
    // batch alone let a loop just under them run for tens of minutes over a
    // 512x512 draw's 4096 batches. 2^32: about 20 s of one core's CPU on
    // the JIT (60 s on the interpreter), 1700 times the busiest lecture
    // scene at 1080p. Whether a draw passes depends on its total only,
    // never on the thread count.
    uint64_t max_draw_instructions = uint64_t(1) << 32;
    // Instructions of one render as a whole: every draw of a scene render
    // (all its passes and objects), and of every frame of glslrun --frames;
    // past it the draw that crosses it stops with a clear error. The budget
    // per draw alone let a scene of many draws, or many frames, each just
    // under it run for hours. 2^36: 16 draws at their budget, about 7
    // minutes of one core on the JIT. Whether a render passes depends on
    // its draws' totals only, never on the thread count.
    uint64_t max_render_instructions = uint64_t(1) << 36;
    // The render's count so far, which every draw adds its instructions to:
    // render_scene points it at its own counter for its draws when it is
    // null (a caller that renders several frames as one render points it
    // at one counter for all of them). Null outside a render: draw() and
    // run_* calls then have only their own budget.
    std::atomic<uint64_t>* render_instructions = nullptr;
    // When *cancel becomes true, a running draw or run_* call stops with an
    // error: a watchdog's flag (glslrun test --no-isolate), Ctrl-C in
    // Python. Polled every 2^16 instructions.
    const std::atomic<bool>* cancel = nullptr;
    // A draw or run_* call still running at this time stops with an error
    // ("the time limit ran out"), never a partial image passed as success.
    // Scene renders set it once for all their draws (glslrun --time-limit,
    // Python's time_limit=); set_time_limit() sets it from now. Polled
    // with cancel. The default: none.
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
    // deadline = now + seconds; none where seconds is not > 0 or passes 10^9.
    void set_time_limit(double seconds);
    // Worker threads of draw(); 0 means one per core. Images are
    // bit-identical whatever the count.
    unsigned threads = 0;
    Precision precision = Precision::Precise;
    Backend backend = Backend::Auto;
    // The JIT's machine code without LLVM's code-generation optimizations:
    // about 40% less compile time, code up to 8% slower, the same bits. For
    // runs that compile many programs and draw little (`glslrun test`).
    bool jit_quick_codegen = false;
    // The JIT's tiers (JitTier above). With jit_quick_codegen, the first
    // tier's code only.
    JitTier jit_tier = JitTier::Tiered;
    // Once a program has drawn this many times in a row with the same values
    // of the uniforms a stage reads, the JIT compiles that stage again with
    // those values as constants (ir/specialize.cpp: folding, dead branches;
    // the same bits), cached beside the unspecialized code, which serves
    // other values. 0: never, the default: on the lecture scenes it saved
    // nothing measurable (their uniform code already runs once per draw, in
    // the prologue) and costs a second compile (docs/performance.md).
    // Backend::Auto draws with the unspecialized code while the specialized
    // one compiles; Backend::Jit waits for it.
    uint32_t jit_specialize_after = 0;
    // The JIT's code cache on disk (docs/performance.md, "The code cache"):
    // machine code compiled once is stored there and loaded by later
    // programs and processes instead of compiling again (same bits). False,
    // or GLSLRUN_NO_CACHE=1 in the environment: neither read nor written.
    bool code_cache = true;
    // Its directory; empty: $GLSLRUN_CACHE_DIR, else $XDG_CACHE_HOME/glslrun,
    // else ~/.cache/glslrun. One that cannot be written is only read.
    std::string code_cache_dir;
    // Its size cap in bytes (docs/limits.md); 0: $GLSLRUN_CACHE_MAX_SIZE
    // (bytes, or with a K, M or G suffix), else 256 MiB.
    uint64_t code_cache_max_bytes = 0;
};

// The code cache that `options` use (ExecOptions::code_cache*).
struct CodeCacheStatus {
    bool enabled = false;  // a directory is set and the JIT is built in
    std::string dir;
    uint64_t max_bytes = 0;
    // Empty, or why the cache is not fully usable (a directory that cannot
    // be written: compiled code is then not stored; a bad
    // GLSLRUN_CACHE_MAX_SIZE): a warning to show, never an error.
    std::string warning;
};
// Creates the directory where it is missing.
CodeCacheStatus code_cache_status(const ExecOptions& options);

// Stops the JIT's background compiles for good: queued ones are dropped, the
// running one gives up at its next phase (this waits for it), later ones are
// not started; programs keep drawing, where their code is not compiled on the
// interpreter (the same bits). Call it before main returns, when a program may
// still be compiling: exit handlers registered after the first compile (static
// locals first used later, LLVM's own) would otherwise run while a compile
// does. The Python module and the glslrun command call it at exit.
void stop_background_compiles();

enum class Stage { Vertex, Fragment };

// Compiles one stage alone (glslparsertest-style checks): no link step.
Status check_shader(Stage stage, const ShaderSource& source, int default_version = 110);
// The same with `options`' default version and defines.
Status check_shader(Stage stage, const ShaderSource& source, const CompileOptions& options);

struct UniformInfo {
    std::string name;   // GL leaf name: "m", "lights[0].pos", "arr" (array_size > 1)
    std::string type;   // GLSL type name: "float", "ivec2", "bvec3", "mat4", "mat2x3"; every sampler type is "sampler"
    uint32_t array_size = 1;
    bool builtin = false;
    bool read = true;  // the optimized program reads it (built-ins that are not read are not derived)
};

class Program {
public:
    static Result<Program> compile(const std::vector<ShaderSource>& vertex,
                                   const std::vector<ShaderSource>& fragment,
                                   const CompileOptions& options = {});
    Program(Program&&) noexcept;
    Program& operator=(Program&&) noexcept;
    ~Program();
    // False once moved from; every call on such a Program then returns an Error.
    bool valid() const noexcept { return state_ != nullptr; }

    // GL semantics (glUniform*): name may be "a", "a[2]", "s.f", "s[1].f";
    // values fill consecutive elements from there. A float uniform takes
    // floats, an int/sampler uniform ints; a bool uniform takes either.
    // Unknown names and type or size mismatches are errors.
    Status set_uniform(std::string_view name, Span<const float> values);
    Status set_uniform(std::string_view name, Span<const int32_t> values);
    // One value: floating-point types set float (or bool) uniforms, integral
    // types and bool set int, bool and sampler uniforms.
    template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
    Status set_uniform(std::string_view name, T value) {
        if constexpr (std::is_floating_point_v<T>) {
            float f = float(value);
            return set_uniform(name, Span<const float>(&f, 1));
        } else {
            int32_t i = int32_t(value);
            return set_uniform(name, Span<const int32_t>(&i, 1));
        }
    }
    // glm vectors and matrices (column-major, as glUniformMatrix without transpose).
    template <glm::length_t L, class T, glm::qualifier Q,
              std::enable_if_t<std::is_same_v<T, float> || std::is_same_v<T, int32_t>, int> = 0>
    Status set_uniform(std::string_view name, const glm::vec<L, T, Q>& v) {
        return set_uniform(name, Span<const T>(&v[0], size_t(L)));
    }
    template <glm::length_t C, glm::length_t R, glm::qualifier Q>
    Status set_uniform(std::string_view name, const glm::mat<C, R, float, Q>& m) {
        return set_uniform(name, Span<const float>(&m[0][0], size_t(C) * size_t(R)));
    }
    bool has_uniform(std::string_view name) const;
    std::vector<UniformInfo> uniforms() const;
    // The inputs the optimized stage reads, as run_vertices and run_fragments
    // take them by name: attributes ("gl_Vertex", "weight") or varyings and
    // fragment built-ins ("v_normal", "gl_FragCoord"), each with its number of
    // components (a mat4 attribute: 16). An input declared but never read is
    // not listed: the optimizer removed it.
    struct Input {
        std::string name;
        uint32_t components = 0;
    };
    std::vector<Input> inputs(Stage stage) const;

    ExecOptions exec;
    // Seconds LLVM has spent compiling this program's shaders (0 without the JIT).
    double jit_compile_seconds() const;
    // The program's shaders the JIT compiled with LLVM so far, and those whose
    // code it loaded from the code cache instead (ExecOptions::code_cache).
    struct JitCompiles {
        uint32_t compiled = 0;
        uint32_t loaded = 0;
        uint32_t optimised = 0;  // of those, the JIT's second tier (JitTier)
    };
    JitCompiles jit_compiles() const;
    std::string dump_ir() const;  // the IR printer's text for both stages

    struct State;  // the IR and the uniform store: runtime/program_state.h
private:
    Program();
    // glslrun's own code reaches the State through runtime/program_state.h.
    friend State& state_of(Program& program);
    friend const State& state_of(const Program& program);
    std::unique_ptr<State> state_;
};

// ------------------------------------------------------------- textures ---
// GL 2.1 texture objects: images, mipmaps and sampling state. A Texture is
// immutable once bound (GLState holds shared_ptr<const Texture>), so draws on
// many threads can share it.
enum class CompareFunc : uint8_t { Never, Less, Equal, Lequal, Greater, Notequal, Gequal, Always };
// Rect: GL_TEXTURE_RECTANGLE (ARB_texture_rectangle): one 2D image addressed
// by unnormalized coordinates (s in [0, width]), no mipmaps; its sampler state
// starts as GL's for rectangles (LINEAR, CLAMP_TO_EDGE), and a state GL would
// refuse for it (REPEAT, MIRRORED_REPEAT, a mipmap min filter) makes it
// incomplete.
// Tex1DArray, Tex2DArray: EXT_texture_array's arrays of 1D and 2D images,
// stored as one image whose height (1D) or depth (2D) counts the layers; a
// lookup picks layer clamp(floor(r + 1/2), 0, layers - 1) and filters within
// it; mipmap levels halve width (and height) and keep the layer count.
enum class TextureTarget : uint8_t { Tex1D, Tex2D, Tex3D, Cube, Rect, Tex1DArray, Tex2DArray };
enum class TextureFilter : uint8_t { Nearest, Linear, NearestMipmapNearest, LinearMipmapNearest,
                                     NearestMipmapLinear, LinearMipmapLinear };
enum class TextureWrap : uint8_t { Repeat, ClampToEdge, Clamp, ClampToBorder, MirroredRepeat };
enum class DepthTextureMode : uint8_t { Luminance, Intensity, Alpha };
// Internal formats: how texels are stored. RGBA8 rounds every texel (given or
// generated by mipmapping) to k/255 as GL_RGBA8 does; RGBA32F keeps floats;
// Depth keeps a depth in [0, 1] in .r (GL_DEPTH_COMPONENT); RGBA16F rounds
// every texel to the nearest binary16 value (ties to even; past 65504 to
// infinity), as GL_RGBA16F_ARB stores it.
enum class TextureFormat : uint8_t { RGBA8, RGBA32F, Depth, RGBA16F };

// glTexParameter state, with GL 2.1's defaults.
struct SamplerState {
    TextureFilter min_filter = TextureFilter::NearestMipmapLinear;
    TextureFilter mag_filter = TextureFilter::Linear;
    TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat, wrap_r = TextureWrap::Repeat;
    glm::vec4 border_color{0, 0, 0, 0};
    float min_lod = -1000, max_lod = 1000;
    float lod_bias = 0;  // GL_TEXTURE_LOD_BIAS (per texture object)
    int base_level = 0, max_level = 1000;
    bool compare = false;  // GL_TEXTURE_COMPARE_MODE == GL_COMPARE_R_TO_TEXTURE
    CompareFunc compare_func = CompareFunc::Lequal;
    DepthTextureMode depth_mode = DepthTextureMode::Luminance;
};

// One mipmap level of one face. Texel (i, j, k) is texels[i + width * (j + height * k)];
// j = 0 is the first row glTexImage receives (t = 0, the bottom of an image).
// Callers expand other colour formats to RGBA as GL does (luminance L -> (L, L, L, 1), ...);
// a depth texture keeps its depth in .r.
struct TextureImage {
    int width = 0, height = 1, depth = 1;
    std::vector<glm::vec4> texels;
};

inline constexpr int kMaxTextureSize = 16384;   // GL_MAX_TEXTURE_SIZE
inline constexpr int kMax3DTextureSize = 2048;  // GL_MAX_3D_TEXTURE_SIZE
inline constexpr int kMaxRectangleTextureSize = 16384;  // GL_MAX_RECTANGLE_TEXTURE_SIZE
inline constexpr int kMaxArrayTextureLayers = 2048;  // GL_MAX_ARRAY_TEXTURE_LAYERS_EXT (llvmpipe's)
inline constexpr int kMaxTextureUnits = 16;     // GL_MAX_TEXTURE_IMAGE_UNITS

class Texture {
public:
    // `faces` holds level 0: one image, or six for a cube map in GL's face
    // order (+X, -X, +Y, -Y, +Z, -Z). Sizes are checked against the target
    // (1D: height = depth = 1; cube: square, equal faces; 1D array: depth = 1)
    // and GL's maxima.
    static Result<Texture> create(TextureTarget target, std::vector<TextureImage> faces,
                                  TextureFormat format = TextureFormat::RGBA8);
    // glTexImage with level > 0: sizes are not checked here (GL accepts any);
    // an inconsistent chain makes the texture mipmap-incomplete when sampled.
    Status set_level(int face, int level, TextureImage image);
    // glGenerateMipmap: every level down to 1x1 as a box filter of the one above.
    void generate_mipmaps();

    TextureTarget target() const { return target_; }
    TextureFormat format() const { return format_; }
    bool depth() const { return format_ == TextureFormat::Depth; }
    int faces() const { return int(levels_.size()); }
    const std::vector<TextureImage>& levels(int face) const { return levels_[size_t(face)]; }
    // GL 2.1 §3.8.10: whether sampling with this state sees the texture at
    // all; an incomplete texture samples as (0, 0, 0, 1).
    bool complete() const;

    SamplerState sampler;
private:
    Texture() = default;
    TextureTarget target_ = TextureTarget::Tex2D;
    TextureFormat format_ = TextureFormat::RGBA8;
    std::vector<std::vector<TextureImage>> levels_;  // [face][level]
};

// ------------------------------------------------ per-fragment state ---
// GL 2.1 §4.1's enums, each in GL's own order (GL_KEEP.., GL_ZERO.., GL_CLEAR..
// GL_SET), so a renderer maps them to GL by position or a table.
enum class StencilOp : uint8_t { Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap };
enum class BlendFactor : uint8_t { Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor, SrcAlpha,
                                   OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha, ConstantColor,
                                   OneMinusConstantColor, ConstantAlpha, OneMinusConstantAlpha, SrcAlphaSaturate };
enum class BlendEquation : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };
// glPolygonMode's modes in GL's enum order (GL_POINT, GL_LINE, GL_FILL).
enum class PolygonMode : uint8_t { Point, Line, Fill };
enum class LogicOp : uint8_t { Clear, And, AndReverse, Copy, AndInverted, Noop, Xor, Or, Nor, Equiv, Invert,
                               OrReverse, CopyInverted, OrInverted, Nand, Set };

inline constexpr int kStencilBits = 8;       // GL_STENCIL_BITS: values 0..255
inline constexpr int kMaxDrawBuffers = 8;    // GL_MAX_DRAW_BUFFERS (the size of gl_FragData)

// One face's stencil state: glStencilFuncSeparate, glStencilOpSeparate,
// glStencilMaskSeparate. Masks and the reference use the low kStencilBits.
struct StencilFace {
    CompareFunc func = CompareFunc::Always;
    int ref = 0;
    uint32_t value_mask = 0xFF, write_mask = 0xFF;
    StencilOp fail = StencilOp::Keep, depth_fail = StencilOp::Keep, depth_pass = StencilOp::Keep;
};

// glBlendFuncSeparate, glBlendEquationSeparate, glBlendColor.
struct BlendState {
    BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
    BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
    BlendEquation equation_rgb = BlendEquation::Add, equation_alpha = BlendEquation::Add;
    glm::vec4 color{0, 0, 0, 0};  // GL clamps it to [0, 1]
};

// ------------------------------------------------------ legacy GL state ---
// The fixed-function state that GLSL 1.10's built-in uniforms (§7.5) read.
// Defaults are OpenGL 2.1's. apply_builtin_uniforms() derives everything a
// program reads (gl_ModelViewProjectionMatrix, gl_NormalMatrix, inverses,
// light products, halfVector, spotCosCutoff, ...).
struct LightState {
    glm::vec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
    glm::vec4 position{0, 0, 1, 0};  // eye space, as after glLightfv
    glm::vec3 spot_direction{0, 0, -1};  // eye space
    float spot_exponent = 0, spot_cutoff = 180;
    float constant_attenuation = 1, linear_attenuation = 0, quadratic_attenuation = 0;
};
struct MaterialState {
    glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1}, diffuse{0.8f, 0.8f, 0.8f, 1};
    glm::vec4 specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
    float shininess = 0;
};
struct GLState {
    GLState();  // light 0 gets its special diffuse/specular defaults
    static constexpr std::array<uint32_t, 32> filled_stipple() {
        std::array<uint32_t, 32> rows{};
        for (uint32_t& r : rows) r = 0xFFFFFFFFu;
        return rows;
    }
    glm::mat4 modelview{1.0f}, projection{1.0f};
    std::array<glm::mat4, 8> texture_matrix;
    std::array<LightState, 8> lights;
    glm::vec4 light_model_ambient{0.2f, 0.2f, 0.2f, 1};
    MaterialState front_material, back_material;
    std::array<glm::vec4, 6> clip_planes{};  // eye space (as after glClipPlane)
    uint32_t clip_plane_enabled = 0;         // bit i: GL_CLIP_PLANEi
    float depth_near = 0, depth_far = 1;
    float point_size = 1;
    // glEnable(GL_VERTEX_PROGRAM_POINT_SIZE): points take the vertex shader's
    // gl_PointSize; off (GL's default), point_size (glPointSize).
    bool vertex_program_point_size = false;
    // glPointParameter (GL 1.4): without the vertex shader's size, a point's
    // is point_size clamped to [point_size_min, point_size_max]; GL's
    // fixed-function vertex stage first multiplies it by 1 / sqrt(a + b d +
    // c d^2), d the eye distance (as Mesa: |z| in eye space), a b c
    // point_distance_attenuation. The fade threshold only matters with
    // multisampling (GL 2.1 §3.3), which glslrun does not have: it reaches
    // shaders as gl_Point.fadeThresholdSize. All of them are >= 0.
    float point_size_min = 0, point_size_max = 255;  // 255: the largest point Mesa draws
    glm::vec3 point_distance_attenuation{1, 0, 0};
    float point_fade_threshold_size = 1;
    // GL_POINT_SPRITE_COORD_ORIGIN: gl_PointCoord's t runs down from the
    // top (GL_UPPER_LEFT, GL's default) or up from the bottom (GL_LOWER_LEFT).
    bool point_sprite_coord_lower_left = false;
    // glEnable(GL_LINE_STIPPLE) + glLineStipple(repeat, pattern): the
    // fragments of a line whose bit (counter / repeat) % 16 of the pattern
    // is 0 are not drawn (GL 2.1 §3.5.2); repeat in [1, 256].
    bool line_stipple = false;
    int line_stipple_repeat = 1;
    uint16_t line_stipple_pattern = 0xFFFF;
    // glEnable(GL_POLYGON_STIPPLE) + glPolygonStipple: filled polygons keep
    // the pixels (x, y) whose bit 31 - x % 32 of row y % 32 is set (rows
    // bottom up; bit 31 is the leftmost pixel, as glPolygonStipple's first byte's high bit).
    bool polygon_stipple = false;
    std::array<uint32_t, 32> polygon_stipple_pattern = filled_stipple();
    struct Fog { glm::vec4 color{0, 0, 0, 0}; float density = 1, start = 0, end = 1; } fog;
    // glTexGen's GL_OBJECT_PLANE and GL_EYE_PLANE per texture unit and
    // coordinate (s, t, r, q), the eye plane as glTexGen stores it (the given
    // plane times the inverse of the modelview at that call, GL 2.1 §2.12.4),
    // and glTexEnv's GL_TEXTURE_ENV_COLOR per unit: the values of
    // gl_ObjectPlaneS..Q[], gl_EyePlaneS..Q[] and gl_TextureEnvColor[]. GL's
    // defaults: s (1, 0, 0, 0), t (0, 1, 0, 0), r, q and the colour zero.
    static std::array<std::array<glm::vec4, 4>, 8> default_texgen_planes() {
        std::array<std::array<glm::vec4, 4>, 8> units{};
        for (auto& coords : units) coords = {glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0), glm::vec4(0)};
        return units;
    }
    std::array<std::array<glm::vec4, 4>, 8> object_planes = default_texgen_planes();
    std::array<std::array<glm::vec4, 4>, 8> eye_planes = default_texgen_planes();
    std::array<glm::vec4, 8> texture_env_color{};
    bool light_model_local_viewer = false, light_model_two_side = false;  // fixed function only
    glm::vec4 current_color{1, 1, 1, 1};     // glColor, for gl_Color without an array
    glm::vec4 current_secondary_color{0, 0, 0, 1};
    glm::vec3 current_normal{0, 0, 1};
    // render state
    bool depth_test = false;
    using DepthFunc = CompareFunc;
    DepthFunc depth_func = DepthFunc::Less;
    bool vertex_program_two_side = false;
    bool flat_shading = false;
    bool cull_face = false;
    bool cull_back = true;   // GL_BACK; false: GL_FRONT
    bool cull_front_and_back = false;  // GL_FRONT_AND_BACK: every polygon (cull_back aside); points and lines stay
    bool front_ccw = true;   // GL_CCW
    // glPolygonMode: [0] front-facing, [1] back-facing polygons. Line and point
    // modes draw the polygon's boundary edges and vertices (the diagonals that
    // split quads and polygons are not edges), with the polygon's facing.
    std::array<PolygonMode, 2> polygon_mode{PolygonMode::Fill, PolygonMode::Fill};
    // glPolygonOffset and GL_POLYGON_OFFSET_FILL/LINE/POINT (by the polygon's
    // mode): depth += factor * max(|dz/dx|, |dz/dy|) + units * 2^-24 (the
    // resolution of a 24-bit depth buffer).
    float polygon_offset_factor = 0, polygon_offset_units = 0;
    bool polygon_offset_fill = false, polygon_offset_line = false, polygon_offset_point = false;
    float line_width = 1;  // glLineWidth, > 0; non-antialiased: rounded, at least 1
    // glEnable(GL_POINT_SPRITE): bit i of coord_replace (glTexEnv(GL_POINT_SPRITE,
    // GL_COORD_REPLACE) on unit i) makes gl_TexCoord[i] the point's (s, t, 0, 1),
    // gl_PointCoord's values (origin upper left, GL's default).
    bool point_sprite = false;
    uint32_t coord_replace = 0;
    std::array<int, 4> viewport{0, 0, 0, 0};  // x y w h; w == 0: the whole framebuffer
    // Per-fragment operations (GL 2.1 §4.1), applied in this order after the
    // fragment shader: scissor, alpha test, stencil, depth, blending, logic op,
    // colour mask; gl_FragData[i] goes to colour buffer i of the framebuffer.
    bool scissor_test = false;
    std::array<int, 4> scissor_box{0, 0, 1 << 30, 1 << 30};  // glScissor x y w h; GL's default: the window
    bool alpha_test = false;
    CompareFunc alpha_func = CompareFunc::Always;
    float alpha_ref = 0;                     // glAlphaFunc; clamped to [0, 1]
    bool stencil_test = false;
    std::array<StencilFace, 2> stencil;      // [0] front faces (and points, lines), [1] back faces
    bool depth_mask = true;                  // glDepthMask
    bool blend = false;
    BlendState blend_state;
    bool color_logic_op = false;             // ignored by float colour buffers, as GL does
    LogicOp logic_op = LogicOp::Copy;
    std::array<bool, 4> color_mask{true, true, true, true};
    // glDrawBuffers(n, {GL_COLOR_ATTACHMENT0 .. n-1}): gl_FragData[i] is
    // written to colour buffer i, gl_FragColor to all n of them.
    int draw_buffers = 1;
    // glBindTexture per unit and target. A sampler reads the binding of its
    // own target on the unit its uniform names; none there samples as (0, 0, 0, 1).
    struct TextureUnit { std::array<std::shared_ptr<const Texture>, 7> bound; };  // by TextureTarget
    std::array<TextureUnit, kMaxTextureUnits> texture_units;
    // glActiveTexture(unit) + glBindTexture: fills the slot of the texture's
    // target; null unbinds every target of the unit. A unit outside
    // [0, kMaxTextureUnits) is an error, as GL_INVALID_ENUM is.
    Status bind_texture(int unit, std::shared_ptr<const Texture> texture);
};
Status apply_builtin_uniforms(Program& program, const GLState& gl);

// ------------------------------------------------------------ execution ---
// One attribute array: `components` floats per vertex (1..4; missing ones are
// GL's (0,0,0,1)). Name is the GLSL name: "gl_Vertex", "gl_Color", "myAttr".
struct VertexAttrib {
    std::string name;
    uint32_t components = 4;
    std::vector<float> data;
};

struct ShaderOutput {
    std::string name;  // "gl_Position", "gl_FrontColor", "gl_TexCoord[0]", "v_normal", ...
    uint32_t components = 0;
    std::vector<float> data;  // count * components; ints and bools as floats
};

// Runs the vertex shader on `count` vertices; every VS output comes back.
// `gl` supplies the bound textures and current attribute values (default: GL's defaults).
Result<std::vector<ShaderOutput>> run_vertices(const Program& program,
                                               const std::vector<VertexAttrib>& attribs,
                                               uint32_t count, const GLState* gl = nullptr);
// Runs the fragment shader on `count` fragments, inputs by name (varyings,
// "gl_FragCoord", "gl_FrontFacing", "gl_Color", ...). Fragments are grouped
// in 2x2 quads in order (4 consecutive fragments = one quad:
// (x,y) (x+1,y) (x,y+1) (x+1,y+1)), so derivatives are meaningful.
// Returns outputs plus "discarded" (1 or 0 per fragment). `gl` as for run_vertices.
Result<std::vector<ShaderOutput>> run_fragments(const Program& program,
                                                const std::vector<VertexAttrib>& inputs,
                                                uint32_t count, const GLState* gl = nullptr);

// ---------------------------------------------------------- rendering ---
// Framebuffer limits, checked before anything is allocated (docs/limits.md):
// each side 1..16384 (GL_MAX_VIEWPORT_DIMS) and 64M pixels in all (1.25 GiB
// of colour and depth).
inline constexpr int kMaxFramebufferSide = 16384;
inline constexpr int64_t kMaxFramebufferPixels = int64_t(1) << 26;
Status check_framebuffer_size(int width, int height);

// The colour buffers store RGBA8 (4 bytes a pixel: R, G, B, A, each n/255,
// as GL_RGBA8; values are clamped and rounded on write) or, with
// float_color, 4 floats a pixel (unclamped: the error report's precision).
// Readers call pixel(); writers take a typed view of a buffer or a row
// (uint8_t channels for RGBA8, float for float colour) after checking
// float_color(). Rows go bottom up (GL's convention), width * 4 channels each.
// How RGBA8 storage turns a colour channel v (clamped to [0, 1]) into its
// byte n. GL 2.1 (§2.14.9) leaves the rounding to the implementation.
//   Nearest: n = v * 255 rounded to nearest, ties to even (Mesa's llvmpipe
//            and softpipe).
//   Gpu:     v truncated to 12 fraction bits, then rounded to nearest with
//            ties down: n = ceil(floor(v * 4096) * 255 / 4096 - 1/2), as
//            NVIDIA's OpenGL driver stores it (measured on all 2^18 values
//            of a probe; docs/precision.md, "The GPU's colour conversion").
enum class ColorRounding : uint8_t { Nearest, Gpu };
// The rounding that matches a precision mode: Gpu for Fast (the GPU's
// arithmetic), Nearest otherwise.
inline ColorRounding color_rounding_for(Precision p) {
    return p == Precision::Fast ? ColorRounding::Gpu : ColorRounding::Nearest;
}

class Framebuffer {
public:
    // color_buffers: 1..kMaxDrawBuffers colour buffers, all of one format.
    // A size that check_framebuffer_size refuses gives an empty (0x0)
    // framebuffer, which draw() refuses; create() returns the reason, and
    // out of memory, as an Error instead.
    Framebuffer(int width, int height, bool float_color = false, int color_buffers = 1);
    static Result<Framebuffer> create(int width, int height, bool float_color = false, int color_buffers = 1);
    int width = 0, height = 0;
    std::vector<float> depth;  // [0,1]
    std::vector<uint8_t> stencil;  // kStencilBits per pixel
    // How colours are stored as RGBA8 bytes, by clears, draws and blending
    // alike; float colour buffers ignore it. The scene renderers set it from
    // the program's precision (color_rounding_for).
    ColorRounding rounding = ColorRounding::Nearest;
    // Float colour buffers only: clears, draws and blending store each channel
    // truncated toward zero to binary16 (GL_RGBA16F, as llvmpipe stores it;
    // finite values past 65504 to 65504), not the float itself (GL_RGBA32F).
    bool half_float = false;

    bool float_color() const { return float_color_; }
    int color_buffers() const { return int(float_color_ ? float_colors_.size() : rgba8_colors_.size()); }
    // Colour buffer `buffer`'s channels (width * height * 4), as T: uint8_t
    // for RGBA8, float for float colour. Empty for the other type or a
    // buffer that does not exist.
    template <class T, std::enable_if_t<std::is_same_v<T, uint8_t> || std::is_same_v<T, float>, int> = 0>
    View<T> color_data(int buffer = 0) { return data_of<T>(*this, buffer); }
    template <class T, std::enable_if_t<std::is_same_v<T, uint8_t> || std::is_same_v<T, float>, int> = 0>
    View<const T> color_data(int buffer = 0) const { return data_of<const T>(*this, buffer); }
    // Row y of it (0 = bottom): width * 4 channels; null where color_data is empty.
    template <class T>
    T* color_row(int buffer, int y) {
        View<T> all = color_data<T>(buffer);
        return all.empty() ? nullptr : all.data() + size_t(y) * size_t(width) * 4;
    }
    template <class T>
    const T* color_row(int buffer, int y) const {
        View<const T> all = color_data<T>(buffer);
        return all.empty() ? nullptr : all.data() + size_t(y) * size_t(width) * 4;
    }

    void clear_color(glm::vec4 c);  // every colour buffer, as glClear does
    void clear_depth(float d);
    void clear_stencil(int s);      // the low kStencilBits of s
    // The stored colour: RGBA8 channels as n / 255.0f; (0, 0, 0, 0) outside.
    glm::vec4 pixel(int x, int y, int buffer = 0) const;

private:
    template <class T, class Self>
    static View<T> data_of(Self& self, int buffer) {
        auto& list = [&]() -> auto& {
            if constexpr (std::is_same_v<std::remove_const_t<T>, float>) return self.float_colors_;
            else return self.rgba8_colors_;
        }();
        if (buffer < 0 || size_t(buffer) >= list.size()) return {};
        return list[size_t(buffer)];
    }
    bool float_color_ = false;
    // The colour buffers of the framebuffer's format; the other list is empty.
    std::vector<std::vector<uint8_t>> rgba8_colors_;
    std::vector<std::vector<float>> float_colors_;
};

enum class Primitive { Points, Lines, LineStrip, LineLoop, Triangles, TriangleStrip,
                       TriangleFan, Quads, QuadStrip, Polygon };

struct DrawStats {
    uint64_t vertices = 0, triangles = 0, fragments_shaded = 0, fragments_written = 0;
    // Of the fragments shaded, those drawn by the JIT's fused fragment
    // pipeline (one native function set per draw state); the others took
    // the interpreter's or the C++ per-fragment path.
    uint64_t fragments_fused = 0;
    // Wall time per stage: vertex shading; "raster" is assembly, clipping,
    // triangle setup and binning into tiles; "fragment" is the tiles'
    // work (rasterization, shading, depth test and colour writes).
    double vertex_seconds = 0, raster_seconds = 0, fragment_seconds = 0;
    // Shader instructions executed, as ExecOptions::max_draw_instructions counts them.
    uint64_t instructions = 0;
    DrawStats& operator+=(const DrawStats& other);
};

// Draws with the program's current uniforms. Built-in uniforms are taken
// from `gl` (apply_builtin_uniforms is called for you). Attributes the mesh
// lacks take GL's current values (gl.current_color, ...). `indices` may be empty.
// The program keeps the draw's working memory for its next draw (no page
// faults on fresh buffers per draw), so one Program draws on one thread at a
// time: a draw or set_uniform on another thread meanwhile returns an Error.
// Separate Programs may draw at once.
Result<DrawStats> draw(Program& program, const GLState& gl, Framebuffer& fb, Primitive prim,
                       const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                       Span<const uint32_t> indices = {});

// glClear followed by a draw, as one call: from 4 worker threads the tile
// jobs clear their tiles in cache before rendering them (and the untouched
// tiles too); with fewer, one sequential clear comes first, which measured
// faster (raster/tiles.cpp). Either way all of fb is cleared when draw()
// returns, even when it fails: fb.clear_color(), fb.clear_depth(), draw().
struct ClearValues {
    std::optional<glm::vec4> color;
    std::optional<float> depth;
    std::optional<int> stencil;
};
Result<DrawStats> draw(Program& program, const GLState& gl, Framebuffer& fb, const ClearValues& clear,
                       Primitive prim, const std::vector<VertexAttrib>& attribs, uint32_t vertex_count,
                       Span<const uint32_t> indices = {});

// PNG output (RGBA8, top row first as images expect) of one colour buffer.
Status write_png(const Framebuffer& fb, const std::string& path, int buffer = 0);

}  // namespace glslrun
