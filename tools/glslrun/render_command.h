// The render, compile-only and --compare modes of the glslrun command line.
#pragma once
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "glslrun/scene/scene.h"

namespace glslrun::cli {

struct RenderOptions {
    std::string output, size, compare, diff;
    std::string background;    // --compare: R,G,B,A or "none"; "" for the scene's clear colour or the corners'
    std::string stage;         // --stage vert|frag: the stage of shaders whose name does not say
    std::vector<std::string> defines;  // -D NAME[=VALUE]
    std::vector<std::string> include_dirs;  // -I DIR
    std::string error_report;  // --error-report DIR: measure `precision` against Reference
    std::string dump_fixed_function;  // --dump-fixed-function DIR: the generated stages' sources
    int tolerance = 0;
    double min_fraction = 1.0;  // --compare passes when this fraction of the covered pixels is within tolerance
    unsigned threads = 0;  // draw() worker threads; 0: one per core
    int bench_frames = 0;  // --bench N: render N frames and print frames/s and time per stage
    bool stats = false, dump_ir = false;
    std::vector<std::string> uniforms;  // --uniform name=value, in order
    // --frames N: N images, each with a float uniform (--time-uniform, else the
    // scene's [animation] time_uniform) = frame / fps (--fps, else the scene's).
    int frames = 0;
    std::string time_uniform;
    double frames_per_second = 0;  // 0: the scene's
    Precision precision = Precision::Precise;  // --precision
    Backend backend = Backend::Auto;           // --backend
    uint32_t specialize_after = ExecOptions{}.jit_specialize_after;  // --specialize-after
    JitTier jit_tier = JitTier::Tiered;  // --jit-tier
    double time_limit = 0;  // --time-limit SECONDS: the draws' deadline (ExecOptions::deadline); 0: none
    bool check_undefined = false;  // --check-undefined: report GLSL's undefined operations
    // --max-instructions N: the render's instruction budget, all its draws
    // and frames together (ExecOptions::max_render_instructions).
    uint64_t max_instructions = ExecOptions{}.max_render_instructions;
};

// The files on the command line, sorted by their extensions.
struct Inputs {
    std::vector<ShaderSource> vertex, fragment;
    std::string scene, image;
};
// `stage` ("vert", "frag" or ""): --stage, for shaders whose name gives none.
Result<Inputs> classify(const std::vector<std::string>& files, const std::string& stage = "");
// The scene file, with --size applied; its warnings are printed.
Result<scene::Scene> load_sized_scene(const Inputs& in, const RenderOptions& o);

// An output name ends in .png, .jpg/.jpeg, .bmp or .tga (any case): the
// format is the name's; no image is written under a misleading name.
Status check_image_name(const std::string& output);

// The program of `in`'s shaders with o.defines; without a vertex shader, an
// error about a varying notes that the vertex stage is GL's fixed function.
Result<Program> compile_program(const Inputs& in, const RenderOptions& o);

// What --stats prints: counts, time per stage, the built-in state read (matrices as rows), the textures.
std::string format_stats(const Program& prog, const scene::Scene& scene, const DrawStats& stats, double compile_ms,
                         double output_ms);

// `files`: shaders (.vert/.frag), at most one scene (.toml), and for
// --compare at most one PNG. Returns the process exit status.
int run_render_command(const std::vector<std::string>& files, const RenderOptions& options);

}  // namespace glslrun::cli
