// glref: renders a scene file with Mesa (llvmpipe or softpipe) through EGL,
// as the oracle for glslrun's images.
//
//   glref [--driver llvmpipe|softpipe|gpu] shader.vert shader.frag scene.toml [-o out.png] [--size WxH]
//         [--upload-mipmaps] [--frames N | --bench N]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tools/glref/gl_render.h"
#include "scene/bench_report.h"
#include "glslrun/scene/image_compare.h"
#include "glslrun/scene/render.h"
#include "glslrun/scene/scene.h"

namespace {

using namespace glslrun;

constexpr const char* kUsage =
    "usage: glref [--driver llvmpipe|softpipe|gpu] [shader.vert] [shader.frag] scene.toml [-o out.png] [--size WxH]\n"
    "             [--upload-mipmaps] [--frames N | --bench N]\n"
    "Renders the scene with Mesa through EGL (no X server) the way a GL 2.1 program would,\n"
    "for comparison with glslrun's image (glslrun --compare). A shader left out is Mesa's fixed function.\n"
    "  --driver D   Mesa's software rasteriser: llvmpipe (default) or softpipe; gpu: the first\n"
    "               EGL device (a hardware driver, e.g. NVIDIA's; GLREF_EGL_DEVICE=N picks device N)\n"
    "  -o FILE      output PNG (default: <scene>-<driver>.png)\n"
    "  --size WxH   override the scene's size\n"
    "  --upload-mipmaps  give Mesa glslrun's generated mipmap levels instead of calling\n"
    "               glGenerateMipmap (generate_mipmap = true textures)\n"
    "  --bench N    draw the scene N more times after the first and print `key value` lines\n"
    "               as `glslrun --bench` does: compile_ms (glCompileShader and glLinkProgram),\n"
    "               first_draw_ms (llvmpipe compiles its shaders there), median_ms, fps, ...\n"
    "  --frames N   the same with N frames in all (N >= 2 prints the timings)\n"
    "LP_NUM_THREADS sets llvmpipe's rasterizer threads (reported as `threads`).\n";

struct Options {
    std::string driver = "llvmpipe";
    std::vector<std::string> inputs;  // vertex shader, fragment shader, scene
    std::string output;
    std::optional<std::pair<int, int>> size;
    glref::MesaOptions mesa;
};

bool parse_size(const std::string& text, std::pair<int, int>& size) {
    char x = 0, extra = 0;
    return std::sscanf(text.c_str(), "%d%c%d%c", &size.first, &x, &size.second, &extra) == 3 && x == 'x';
}

// Empty on success, else the message for the user.
std::string parse_options(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        bool has_value = i + 1 < argc;
        if ((a == "--driver" || a == "-o" || a == "--size" || a == "--frames" || a == "--bench") && !has_value)
            return a + " needs a value";
        if (a == "--driver") {
            o.driver = argv[++i];
        } else if (a == "-o") {
            o.output = argv[++i];
        } else if (a == "--size") {
            std::pair<int, int> size;
            if (!parse_size(argv[++i], size)) return fmt::format("--size '{}' is not WxH", argv[i]);
            o.size = size;
        } else if (a == "--frames" || a == "--bench") {
            char extra = 0;
            int n = 0;
            if (std::sscanf(argv[++i], "%d%c", &n, &extra) != 1 || n < 1 || n > 100000)
                return fmt::format("{} '{}' is not a count 1..100000", a, argv[i]);
            o.mesa.frames = a == "--bench" ? n + 1 : n;
        } else if (a == "--upload-mipmaps") {
            o.mesa.upload_generated_mipmaps = true;
        } else if (a.size() > 1 && a[0] == '-') {
            return "unknown option " + a;
        } else {
            o.inputs.push_back(a);
        }
    }
    if (o.driver != "llvmpipe" && o.driver != "softpipe" && o.driver != "gpu")
        return fmt::format("--driver '{}': use llvmpipe, softpipe or gpu", o.driver);
    if (o.inputs.empty() || o.inputs.size() > 3 || !o.inputs.back().ends_with(".toml"))
        return fmt::format("expected [shader.vert] [shader.frag] scene.toml, got {} file(s)", o.inputs.size());
    if (o.output.empty()) o.output = std::filesystem::path(o.inputs.back()).stem().string() + "-" + o.driver + ".png";
    return {};
}

Result<ShaderSource> read_shader(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error(fmt::format("cannot read shader '{}'", path));
    std::stringstream text;
    text << in.rdbuf();
    return ShaderSource{path, text.str()};
}

int fail(const Error& e) {
    std::fprintf(stderr, "%s\n", e.str().c_str());
    return 1;
}

// The first frame apart (llvmpipe compiles there), in glslrun --bench's format.
void print_frames(const glref::MesaRender& render, const scene::Scene& scene, const std::string& driver) {
    scene::BenchReport r;
    r.renderer = render.renderer;
    r.width = scene.width;
    r.height = scene.height;
    const char* threads = std::getenv("LP_NUM_THREADS");
    r.threads = driver == "softpipe" ? "1" : threads ? threads : "auto";
    r.compile_s = render.compile_seconds;
    r.first_draw_s = render.frame_seconds.at(0);
    r.frame_s.assign(render.frame_seconds.begin() + 1, render.frame_seconds.end());
    r.frame_cpu_s.assign(render.frame_cpu_seconds.begin() + 1, render.frame_cpu_seconds.end());
    std::fputs(scene::format_bench(r).c_str(), stdout);
}

// A shader's stage by its name: .vert/.vs or .frag/.fs (also before .glsl).
bool is_vertex(const std::string& path) {
    std::string name = path.ends_with(".glsl") ? path.substr(0, path.size() - 5) : path;
    return name.ends_with(".vert") || name.ends_with(".vs");
}

int run(const Options& o) {
    std::vector<ShaderSource> vertex, fragment;
    for (size_t i = 0; i + 1 < o.inputs.size(); ++i) {
        auto source = read_shader(o.inputs[i]);
        if (!source) return fail(source.error());
        (is_vertex(o.inputs[i]) || (o.inputs.size() == 3 && i == 0) ? vertex : fragment).push_back(*source);
    }
    auto scene = scene::load_scene(o.inputs.back());
    if (!scene) return fail(scene.error());
    if (o.size)
        if (Status st = scene::resize_scene(*scene, o.size->first, o.size->second); !st) return fail(st.error());
    for (const Diagnostic& w : scene->warnings) std::fprintf(stderr, "%s\n", w.str().c_str());
    auto render = glref::render_with_mesa(o.driver, vertex, fragment, *scene, o.mesa);
    if (!render) return fail(render.error());
    if (Status st = scene::write_png(render->image, o.output); !st) return fail(st.error());
    for (size_t i = 0; i < render->more_images.size(); ++i)
        if (Status st = scene::write_png(render->more_images[i], scene::color_buffer_path(o.output, int(i) + 1)); !st)
            return fail(st.error());
    std::printf("%s: %dx%d, %s\n", o.output.c_str(), scene->width, scene->height, render->renderer.c_str());
    if (o.mesa.frames > 1) print_frames(*render, *scene, o.driver);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
    Options o;
    if (std::string why = parse_options(argc, argv, o); !why.empty()) {
        std::fprintf(stderr, "glref: %s\n%s", why.c_str(), kUsage);
        return 2;
    }
    return run(o);
}
