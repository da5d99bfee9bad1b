// `glslrun --error-report DIR`: a scene rendered in one precision mode and in
// Precision::Reference with the same state, and every shader output of the
// one measured against the other (docs/precision.md, "Error report").
//
// Fragment outputs are read from a float framebuffer before 8-bit
// quantization: the colour (gl_FragColor or gl_FragData[0], the one colour
// buffer draw() writes) and, where the depth test stores it, the depth
// (gl_FragDepth's value where the shader writes it). Vertex outputs come from
// run_vertices() over every object's vertices with the object's state.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "glslrun/scene/float_error.h"
#include "glslrun/scene/scene.h"

namespace glslrun::scene {

// One vertex shader output over every vertex of every object. worst.x is the
// vertex, worst.y the object (its index in the scene).
struct VaryingError {
    std::string name;
    uint32_t components = 0;
    ChannelError error;  // all components together
    WorstPlace worst;
};

// Where Fast's error comes from: the colour rendered with one class of Fast's
// approximations (rt::FastOps) and Precise kernels for every other op,
// against the reference. "none" is Precise, "all" is Fast.
struct AblationRow {
    std::string ops;  // none, inversesqrt (with normalize, x / sqrt(y)), exp_log, pow, sin_cos, all
    ChannelError color;  // all channels
    uint64_t covered_one = 0, differing_8bit = 0;
    WorstPlace worst_8bit;
};

struct ErrorReport {
    Precision mode = Precision::Precise;
    std::string scene;
    int width = 0, height = 0;
    double reference_ms = 0, mode_ms = 0;  // the two renders, wall time
    std::vector<ImageError> outputs;       // the colour, then the depth where it is stored
    std::vector<VaryingError> varyings;
    std::vector<AblationRow> ablation;     // mode Fast only
    Image reference_image, mode_image;     // as the PNGs of a normal render would hold them
    std::vector<std::string> notes;        // what is not compared, and why
    std::vector<Diagnostic> warnings;      // the scene's, as a render prints them (ScenePrograms::warnings)
};

struct ErrorReportOptions {
    Precision mode = Precision::Precise;
    unsigned threads = 0;  // ExecOptions::threads; the images do not depend on it
    // Seconds for every render of the report together (ExecOptions::set_time_limit, from the
    // compile on); past it the report is an Error. 0: none.
    double time_limit = 0;
    // The sources' -D macros and -I directories (the other fields are the report's own).
    CompileOptions compile;
};

// Compiles the program once per mode and renders `scene` in both; in Fast,
// also once per class of approximations (ErrorReport::ablation).
Result<ErrorReport> measure_error(const std::vector<ShaderSource>& vertex, const std::vector<ShaderSource>& fragment,
                                  const Scene& scene, const ErrorReportOptions& options);

// Writes DIR/reference.png, DIR/<mode>.png and per pixel output
// DIR/<output>_ulp.png (heat map) and, for the colour, DIR/<output>_diff8.png
// (scene::diff_image). Returns the paths written. DIR must exist.
// `check_path`, when given, may refuse a path before it is written.
Result<std::vector<std::string>> write_error_images(
    const ErrorReport& report, const std::string& dir,
    const std::function<Status(const std::string&)>& check_path = {});

// The table for people, and `key value` lines for scripts (bench/precision.py).
std::string format_error_table(const ErrorReport& report, const std::vector<std::string>& files);
std::string format_error_keys(const ErrorReport& report);

}  // namespace glslrun::scene
