// What `glslrun serve` shows and computes, apart from HTTP: the program's
// sources and the scene's text as the page edits them (kept in memory; the
// user's files are only read), a render of them with its diagnostics and
// --stats, a pixel's trace, the NaN/inf findings and the error heat map.
// Images are written into the scratch directory only. Every answer is JSON
// text for the page (tools/glslrun/serve/serve.js). Not thread-safe: the
// server serialises the calls.
#pragma once
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"
#include "render_command.h"

namespace glslrun::cli {

struct ServeOptions {
    std::string host = "127.0.0.1";
    int port = 8321;                   // 0: any free port
    double time_limit = 10;            // seconds for each render, trace or search
    Precision precision = Precision::Precise;
    unsigned threads = 0;
    std::string page_dir;              // where index.html is; "" to look it up (serve_page_dir)
};

class ServeSession {
public:
    // `scratch`: an existing directory the session may write images into.
    ServeSession(const Inputs& in, std::string scene_text, const ServeOptions& options, std::string scratch);

    // {"files": [{"index", "name", "kind": vert|frag|scene, "text"}], "precision", "time_limit"}
    std::string files_json() const;
    // Replaces file `index`'s text (in memory). False for no such file.
    bool set_text(size_t index, std::string text);

    // Renders the current texts: {"ok", "generation", "width", "height", "stats", "diagnostics":
    // [{"file", "index", "line", "message", "warning"}]}; on success image_png() is the image.
    std::string render_json();
    // The last successful render's PNG file in the scratch directory ("" before one).
    const std::string& image_png() const { return image_png_; }

    // The source-level trace and pixel history of image pixel x,y (top-left
    // origin): debug::format_json's JSON, or {"error": ...}.
    std::string trace_json(int x, int y);
    // {"findings": [{"kind", "x", "y", "in_target", "vertex", "message"}], "summary"} or {"error"}:
    // the first NaN/inf and the first colour outside [0, 1] (debug::find_nan).
    std::string findings_json();
    // The error of --precision's mode against `reference` (scene::measure_error):
    // {"ok", "table", "legend"} and heat_png() the colour's ULP heat map; or {"error"}.
    std::string heat_json();
    const std::string& heat_png() const { return heat_png_; }

private:
    struct File {
        std::string name, kind, text;
    };
    struct Parsed;  // the scene and program of the current texts
    Result<scene::Scene> parse_scene_text() const;
    bool fixed_function() const;  // no shader: every draw is GL's fixed function
    Result<scene::Scene> scene_to_draw() const;
    Result<Parsed> parse_for_debugging(const std::atomic<bool>* cancel) const;
    std::vector<ShaderSource> sources(const char* kind) const;
    std::string scratch_path(const std::string& stem);

    std::vector<File> files_;  // the shaders in command-line order, then the scene
    ServeOptions options_;
    std::string scratch_, image_png_, heat_png_;
    uint64_t generation_ = 0;
};

// The directory of the page's files: share/glslrun/serve next to the
// executable's bin/ when installed, else tools/glslrun/serve in the source
// tree it was built from; "" when neither exists.
std::string serve_page_dir();

}  // namespace glslrun::cli
