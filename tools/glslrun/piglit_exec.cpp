// shader_runner's [test] semantics on top of the public glslrun API.
#include "piglit_exec.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/gtc/matrix_transform.hpp>

#include "glslrun/glslrun.h"
#include "piglit_textures.h"
#include "scene/text_file.h"

namespace glslrun::piglit {
namespace {

TestResult fail(std::string message) { return {Outcome::Fail, std::move(message)}; }
TestResult skip(std::string message) { return {Outcome::Skip, std::move(message)}; }
TestResult pass() { return {Outcome::Pass, {}}; }

// An error's messages without the "error: " prefix of Error::str().
std::string messages(const Error& e) {
    std::string s;
    for (const auto& d : e.diagnostics) s += (s.empty() ? "" : "; ") + d.message;
    return s;
}

Stage to_stage(ShaderStage s) { return s == ShaderStage::Vertex ? Stage::Vertex : Stage::Fragment; }

std::optional<Primitive> primitive_from_name(const std::string& mode) {
    static const std::pair<const char*, Primitive> kModes[] = {
        {"GL_POINTS", Primitive::Points},       {"GL_LINES", Primitive::Lines},
        {"GL_LINE_STRIP", Primitive::LineStrip}, {"GL_LINE_LOOP", Primitive::LineLoop},
        {"GL_TRIANGLES", Primitive::Triangles}, {"GL_TRIANGLE_STRIP", Primitive::TriangleStrip},
        {"GL_TRIANGLE_FAN", Primitive::TriangleFan}, {"GL_QUADS", Primitive::Quads},
        {"GL_QUAD_STRIP", Primitive::QuadStrip}, {"GL_POLYGON", Primitive::Polygon},
    };
    for (const auto& [name, prim] : kModes)
        if (mode == name) return prim;
    return std::nullopt;
}

std::string fmt_color(const float* c, int n) {
    std::string s = "(";
    for (int i = 0; i < n; ++i) s += fmt::format("{}{:.4g}", i ? ", " : "", c[i]);
    return s + ")";
}

// ------------------------------------------------------------------ run ---
class ShaderTestRun {
public:
    ShaderTestRun(const ShaderTest& test, const RunOptions& options)
        : test_(test), options_(options), fb_(test.require.width, test.require.height) {
        fb_.clear_color({0, 0, 0, 0});
        fb_.clear_depth(1);
        tolerance_.fill(3.0f / 256.0f);  // piglit's 3/2^bits for an RGBA8 window
    }

    TestResult run(const std::string& dir);

private:
    std::optional<TestResult> build_program(const std::string& dir);
    std::optional<TestResult> execute(const Command& cmd);
    std::optional<TestResult> program_must_be_in_use(int line) const;
    std::optional<TestResult> draw(int line, Primitive prim, const std::vector<VertexAttrib>& attribs,
                                   uint32_t count);
    std::optional<TestResult> draw_rect(int line, const DrawRect& d);
    std::optional<TestResult> draw_arrays(int line, const DrawArrays& d);
    std::optional<TestResult> set_uniform(int line, const SetUniform& u);
    std::optional<TestResult> probe(int line, const Probe& p);
    std::optional<TestResult> probe_depth(int line, const ProbeDepth& p);
    std::optional<TestResult> enable(int line, const Enable& e);
    std::optional<TestResult> light(int line, const Light& l);
    TestResult line_fail(int line, const std::string& message) const {
        return fail("line " + std::to_string(line) + ": " + message);
    }

    const ShaderTest& test_;
    const RunOptions& options_;
    GLState gl_;
    TextureState textures_;
    Framebuffer fb_;
    glm::vec4 clear_color_{0, 0, 0, 0};
    float clear_depth_ = 1;
    bool clear_color_bit_ = false, clear_depth_bit_ = false;
    std::array<float, 4> tolerance_{};
    std::optional<Program> program_;
    std::string link_log_;
    bool link_error_expected_ = false;
    bool warned_ = false;
    std::string warning_;
    std::vector<VertexAttrib> vertex_data_;
};

std::optional<TestResult> ShaderTestRun::build_program(const std::string& dir) {
    if (test_.shaders.empty()) {
        link_log_ = "the test has no shaders";
        return std::nullopt;
    }
    if (test_.require.glsl_version == 0) return fail("GLSL version requirement missing");
    std::vector<ShaderSource> vs, fs;
    std::vector<std::pair<Stage, ShaderSource>> all;
    std::vector<const ShaderSection*> sections;
    // The compiler sees a section's text alone, as shader_runner's GL does
    // (__LINE__ counts from the section), under a name unique to the section;
    // its diagnostics then move to the test file's own lines.
    std::vector<std::pair<std::string, int>> moved;  // source name, lines to add
    for (const auto& section : test_.shaders) {
        ShaderSource src;
        if (!section.file.empty()) {
            src.name = (std::filesystem::path(dir) / section.file).string();
            auto loaded = scene::read_text_file(src.name, "shader file");
            if (!loaded) return fail(loaded.error().diagnostics[0].message);
            src.text = effective_source(*loaded, test_.require);
        } else {
            src = {section.label, effective_source(section.text, test_.require)};
            for (int k = 2; std::any_of(moved.begin(), moved.end(), [&](const auto& m) { return m.first == src.name; });
                 ++k)
                src.name = fmt::format("{} #{}", section.label, k);
            // A #version line put first is not in the file.
            const bool version_added = src.text.size() != section.text.size();
            if (section.text != passthrough_vertex_shader())
                moved.emplace_back(src.name, section.first_line - 1 - (version_added ? 1 : 0));
        }
        (section.stage == ShaderStage::Vertex ? vs : fs).push_back(src);
        all.emplace_back(to_stage(section.stage), src);
        sections.push_back(&section);
    }
    auto at_file_lines = [&](Error e) {
        if (options_.file.empty()) return e;
        for (Diagnostic& d : e.diagnostics)
            for (const auto& [name, offset] : moved)
                if (d.file == name) {
                    d.file = options_.file;
                    if (d.line > 0) d.line = std::max(1, d.line + offset);
                    break;
                }
        return e;
    };
    CompileOptions copts;
    copts.default_version = test_.require.glsl_version;
    auto prog = Program::compile(vs, fs, copts);
    if (!prog && prog.error().unsupported_version) return skip(prog.error().diagnostics.front().str());
    if (prog) {
        program_.emplace(std::move(prog.value()));
        if (options_.max_loop_iterations) program_->exec.max_loop_iterations = options_.max_loop_iterations;
        program_->exec.precision = options_.precision;
        program_->exec.backend = options_.backend;
        program_->exec.jit_quick_codegen = true;  // many programs, few draws: see docs/performance.md
        program_->exec.cancel = options_.cancel;
        return std::nullopt;
    }
    // Program::compile compiles and links; piglit fails on a compile error but
    // only records a link error (the test may expect it). Tell them apart.
    for (size_t i = 0; i < all.size(); ++i) {
        auto st = check_shader(all[i].first, all[i].second, test_.require.glsl_version);
        if (!st) return fail("failed to compile " + sections[i]->label + ": " + at_file_lines(st.error()).str());
    }
    link_log_ = at_file_lines(prog.error()).str();
    return std::nullopt;
}

std::optional<TestResult> ShaderTestRun::program_must_be_in_use(int line) const {
    if (program_) return std::nullopt;
    return line_fail(line, "failed to link: " + link_log_);
}

TestResult ShaderTestRun::run(const std::string& dir) {
    if (auto r = build_program(dir)) return *r;
    if (!test_.has_test_section) return pass();
    if (program_ && test_.vertex_data) {
        const VertexData& vd = *test_.vertex_data;
        for (size_t c = 0; c < vd.columns.size(); ++c)
            vertex_data_.push_back({vd.columns[c].name, vd.columns[c].components, vd.per_column[c]});
    }
    auto start = std::chrono::steady_clock::now();
    for (const auto& cmd : test_.commands) {
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > options_.time_limit_s)
            return line_fail(cmd.line, fmt::format("time limit of {} s exceeded", options_.time_limit_s));
        if (auto r = execute(cmd)) return *r;
    }
    if (!program_ && !link_error_expected_) return fail("failed to link: " + link_log_);
    if (warned_) return {Outcome::Pass, "warn: " + warning_};
    return pass();
}

std::optional<TestResult> ShaderTestRun::execute(const Command& cmd) {
    const int line = cmd.line;
    return std::visit(
        [&](const auto& c) -> std::optional<TestResult> {
            using T = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<T, ClearColor>) {
                clear_color_ = {c.rgba[0], c.rgba[1], c.rgba[2], c.rgba[3]};
                clear_color_bit_ = true;
            } else if constexpr (std::is_same_v<T, ClearDepth>) {
                clear_depth_ = c.depth;
                clear_depth_bit_ = true;
            } else if constexpr (std::is_same_v<T, Clear>) {
                // glClear with the bits piglit has collected from "clear color"/"clear depth".
                if (clear_color_bit_) fb_.clear_color(clear_color_);
                if (clear_depth_bit_) fb_.clear_depth(std::clamp(clear_depth_, 0.0f, 1.0f));
            } else if constexpr (std::is_same_v<T, DrawRect>) {
                return draw_rect(line, c);
            } else if constexpr (std::is_same_v<T, DrawArrays>) {
                return draw_arrays(line, c);
            } else if constexpr (std::is_same_v<T, Ortho>) {
                auto [l, r, b, t] = c.lrbt.value_or(
                    std::array<float, 4>{0, float(fb_.width), 0, float(fb_.height)});
                gl_.projection = glm::ortho(l, r, b, t, -1.0f, 1.0f);
                gl_.modelview = glm::mat4(1.0f);
            } else if constexpr (std::is_same_v<T, Frustum>) {
                const auto& f = c.lrbtnf;
                gl_.projection = glm::frustum(f[0], f[1], f[2], f[3], f[4], f[5]);
                gl_.modelview = glm::mat4(1.0f);
            } else if constexpr (std::is_same_v<T, SetUniform>) {
                return set_uniform(line, c);
            } else if constexpr (std::is_same_v<T, Probe>) {
                return probe(line, c);
            } else if constexpr (std::is_same_v<T, ProbeDepth>) {
                return probe_depth(line, c);
            } else if constexpr (std::is_same_v<T, LinkCheck>) {
                if (c.expect_success) return program_must_be_in_use(line);
                if (program_) return line_fail(line, "shader link error expected, but it was successful");
                link_error_expected_ = true;
            } else if constexpr (std::is_same_v<T, Enable>) {
                return enable(line, c);
            } else if constexpr (std::is_same_v<T, DepthFunc>) {
                gl_.depth_func = c.func;
            } else if constexpr (std::is_same_v<T, ClipPlane>) {
                if (c.index < 0 || c.index >= int(gl_.clip_planes.size()))
                    return line_fail(line, fmt::format("clip plane id {} out of range", c.index));
                glm::vec4 plane(c.plane[0], c.plane[1], c.plane[2], c.plane[3]);
                gl_.clip_planes[c.index] = plane * glm::inverse(gl_.modelview);  // as glClipPlane
            } else if constexpr (std::is_same_v<T, ShadeModel>) {
                gl_.flat_shading = c.flat;
            } else if constexpr (std::is_same_v<T, CurrentColor>) {
                gl_.current_color = {c.rgba[0], c.rgba[1], c.rgba[2], c.rgba[3]};
            } else if constexpr (std::is_same_v<T, Light>) {
                return light(line, c);
            } else if constexpr (std::is_same_v<T, Tolerance>) {
                tolerance_ = c.tol;
            } else if constexpr (std::is_same_v<T, TextureCommand>) {
                if (auto st = run_texture_command(gl_, textures_, c); !st) return line_fail(line, messages(st.error()));
            } else if constexpr (std::is_same_v<T, TexParameter>) {
                if (auto st = run_texparameter(gl_, textures_, c); !st) return line_fail(line, messages(st.error()));
            } else if constexpr (std::is_same_v<T, Unsupported>) {
                return skip(c.reason);
            }
            return std::nullopt;
        },
        cmd.data);
}

std::optional<TestResult> ShaderTestRun::draw(int line, Primitive prim,
                                              const std::vector<VertexAttrib>& attribs, uint32_t count) {
    if (auto r = program_must_be_in_use(line)) return r;
    auto st = glslrun::draw(*program_, gl_, fb_, prim, attribs, count);
    if (!st) return line_fail(line, "draw failed: " + st.error().str());
    return std::nullopt;
}

std::optional<TestResult> ShaderTestRun::draw_rect(int line, const DrawRect& d) {
    float x = d.rect[0], y = d.rect[1], w = d.rect[2], h = d.rect[3];
    if (d.ortho) {  // window coordinates -> clip space, as shader_runner does
        x = -1.0f + 2.0f * x / fb_.width;
        y = -1.0f + 2.0f * y / fb_.height;
        w = 2.0f * w / fb_.width;
        h = 2.0f * h / fb_.height;
    }
    // piglit_draw_rect: a 4-vertex triangle strip, z = 0, w = 1.
    std::vector<float> pos = {x, y, 0, 1, x + w, y, 0, 1, x, y + h, 0, 1, x + w, y + h, 0, 1};
    std::vector<VertexAttrib> attribs = {{"gl_Vertex", 4, pos}, {"piglit_vertex", 4, pos}};
    if (d.tex) {
        float s = d.tex_rect[0], t = d.tex_rect[1], sw = d.tex_rect[2], th = d.tex_rect[3];
        std::vector<float> tc = {s, t, 0, 1, s + sw, t, 0, 1, s, t + th, 0, 1, s + sw, t + th, 0, 1};
        attribs.push_back({"gl_MultiTexCoord0", 4, tc});
        attribs.push_back({"piglit_texcoord", 4, tc});
    }
    return draw(line, Primitive::TriangleStrip, attribs, 4);
}

std::optional<TestResult> ShaderTestRun::draw_arrays(int line, const DrawArrays& d) {
    auto prim = primitive_from_name(d.mode);
    if (!prim) return line_fail(line, "unknown drawing mode \"" + d.mode + "\"");
    if (auto r = program_must_be_in_use(line)) return r;
    if (!test_.vertex_data) return line_fail(line, "draw arrays without a [vertex data] section");
    uint32_t rows = test_.vertex_data->rows;
    if (uint32_t(d.first) >= rows) return line_fail(line, fmt::format("draw arrays 'first' must be < {}", rows));
    if (uint32_t(d.count) > rows - uint32_t(d.first))
        return line_fail(line, fmt::format("draw arrays cannot draw beyond {}", rows));
    std::vector<VertexAttrib> slice;
    for (const auto& a : vertex_data_) {
        auto begin = a.data.begin() + size_t(d.first) * a.components;
        slice.push_back({a.name, a.components,
                         std::vector<float>(begin, begin + size_t(d.count) * a.components)});
    }
    return draw(line, *prim, slice, uint32_t(d.count));
}

std::optional<TestResult> ShaderTestRun::set_uniform(int line, const SetUniform& u) {
    if (auto r = program_must_be_in_use(line)) return r;
    auto st = u.integer ? program_->set_uniform(u.name, std::span<const int32_t>(u.ints))
                        : program_->set_uniform(u.name, std::span<const float>(u.floats));
    if (!st) return line_fail(line, "uniform " + u.name + ": " + st.error().str());
    return std::nullopt;
}

namespace {

// The probe's region in pixels, checked while still floating point: a cast
// of 3e9 (or of NaN) to int is undefined, and x86 turned it into INT_MIN,
// whose sum with the width wrapped into the window, and a wrong region passed.
// nullopt when any part lies outside the W x H window.
std::optional<std::array<int, 4>> probe_region(const Probe& p, int W, int H) {
    double x = 0, y = 0, w = 1, h = 1;
    if (p.region == Probe::Region::All) {
        w = W;
        h = H;
    } else if (p.relative) {
        x = std::trunc(double(p.rect[0]) * W);
        y = std::trunc(double(p.rect[1]) * H);
        if (p.region == Probe::Region::Rect) {
            w = std::trunc(double(p.rect[2]) * W);
            h = std::trunc(double(p.rect[3]) * H);
        } else {
            x = std::min(x, double(W - 1));
            y = std::min(y, double(H - 1));
        }
    } else {
        x = std::trunc(double(p.rect[0]));
        y = std::trunc(double(p.rect[1]));
        if (p.region == Probe::Region::Rect) {
            w = std::trunc(double(p.rect[2]));
            h = std::trunc(double(p.rect[3]));
        }
    }
    // Written so that NaN fails every comparison.
    if (!(x >= 0 && y >= 0 && w >= 0 && h >= 0 && x + w <= W && y + h <= H)) return std::nullopt;
    return std::array<int, 4>{int(x), int(y), int(w), int(h)};
}

}  // namespace

std::optional<TestResult> ShaderTestRun::probe(int line, const Probe& p) {
    const int W = fb_.width, H = fb_.height;
    auto region = probe_region(p, W, H);
    if (!region)
        return line_fail(line, fmt::format("probe region ({}) is outside the {}x{} window",
                                           fmt::join(p.rect.begin(), p.rect.begin() + (p.region == Probe::Region::Rect ? 4 : 2), ", "), W, H));
    const auto [x, y, w, h] = *region;
    const int n = p.rgba ? 4 : 3;
    for (int j = y; j < y + h; ++j) {
        for (int i = x; i < x + w; ++i) {
            const glm::vec4 v = fb_.pixel(i, j);  // RGBA8: n / 255
            const float observed[4] = {v.r, v.g, v.b, v.a};
            bool ok = true;
            for (int k = 0; k < n; ++k)
                if (!(std::fabs(observed[k] - p.color[k]) <= tolerance_[k])) ok = false;
            if (ok) continue;
            std::string msg = fmt::format("probe {} at ({}, {}): expected {}, observed {}",
                                          p.rgba ? "rgba" : "rgb", i, j, fmt_color(p.color.data(), n),
                                          fmt_color(observed, n));
            if (p.warn) {
                if (!warned_) warning_ = "line " + std::to_string(line) + ": " + msg;
                warned_ = true;
                return std::nullopt;
            }
            return line_fail(line, msg);
        }
    }
    return std::nullopt;
}

std::optional<TestResult> ShaderTestRun::probe_depth(int line, const ProbeDepth& p) {
    if (p.x < 0 || p.y < 0 || p.x >= fb_.width || p.y >= fb_.height)
        return line_fail(line, fmt::format("probe depth at ({}, {}) is outside the window", p.x, p.y));
    float d = fb_.depth[size_t(p.y) * fb_.width + p.x];
    if (std::fabs(d - p.depth) >= 0.01f)  // piglit_probe_pixel_depth's tolerance
        return line_fail(line, fmt::format("probe depth at ({}, {}): expected {:.4g}, observed {:.4g}",
                                           p.x, p.y, p.depth, d));
    return std::nullopt;
}

std::optional<TestResult> ShaderTestRun::enable(int line, const Enable& e) {
    const std::string& cap = e.cap;
    if (cap == "GL_VERTEX_PROGRAM_TWO_SIDE") gl_.vertex_program_two_side = e.on;
    else if (cap == "GL_DEPTH_TEST") gl_.depth_test = e.on;
    else if (cap == "GL_CULL_FACE") gl_.cull_face = e.on;
    else if (cap == "GL_PROGRAM_POINT_SIZE" || cap == "GL_VERTEX_PROGRAM_POINT_SIZE") gl_.vertex_program_point_size = e.on;
    else if (cap.rfind("GL_CLIP_PLANE", 0) == 0 && cap.size() == 14 && std::isdigit((unsigned char)cap[13])) {
        int i = cap[13] - '0';
        if (i >= int(gl_.clip_planes.size()))
            return line_fail(line, fmt::format("clip plane id {} out of range", i));
        if (e.on) gl_.clip_plane_enabled |= 1u << i;
        else gl_.clip_plane_enabled &= ~(1u << i);
    } else {
        return line_fail(line, "bad enable/disable enum \"" + cap + "\"");
    }
    return std::nullopt;
}

std::optional<TestResult> ShaderTestRun::light(int line, const Light& l) {
    LightState& s = gl_.lights[l.index];
    const auto& v = l.values;
    auto vec4 = [&] { return glm::vec4(v[0], v[1], v[2], v[3]); };
    auto need = [&](size_t n) { return v.size() == n; };
    if ((l.param == "GL_AMBIENT" || l.param == "GL_DIFFUSE" || l.param == "GL_SPECULAR" ||
         l.param == "GL_POSITION") && need(4)) {
        if (l.param == "GL_AMBIENT") s.ambient = vec4();
        else if (l.param == "GL_DIFFUSE") s.diffuse = vec4();
        else if (l.param == "GL_SPECULAR") s.specular = vec4();
        else s.position = gl_.modelview * vec4();  // glLightfv stores eye coordinates
    } else if (l.param == "GL_SPOT_DIRECTION" && need(3)) {
        s.spot_direction = glm::mat3(gl_.modelview) * glm::vec3(v[0], v[1], v[2]);
    } else if (need(1) && l.param == "GL_SPOT_EXPONENT") s.spot_exponent = v[0];
    else if (need(1) && l.param == "GL_SPOT_CUTOFF") s.spot_cutoff = v[0];
    else if (need(1) && l.param == "GL_CONSTANT_ATTENUATION") s.constant_attenuation = v[0];
    else if (need(1) && l.param == "GL_LINEAR_ATTENUATION") s.linear_attenuation = v[0];
    else if (need(1) && l.param == "GL_QUADRATIC_ATTENUATION") s.quadratic_attenuation = v[0];
    else return line_fail(line, "bad light parameter " + l.param + fmt::format(" with {} values", v.size()));
    return std::nullopt;
}

std::string extension_of(const std::string& path) {
    return std::filesystem::path(path).extension().string();
}

}  // namespace

TestResult run_shader_test(const std::string& text, const std::string& dir, const RunOptions& options) {
    auto parsed = parse_shader_test(text);
    if (!parsed_ok(parsed)) return fail(std::get<ParseError>(parsed).str());
    const ShaderTest& test = std::get<ShaderTest>(parsed);
    if (auto reason = skip_reason(test, options.caps)) return skip(*reason);
    ShaderTestRun run(test, options);
    return run.run(dir);
}

TestResult run_parser_test(const std::string& text, const std::string& ext, const std::string& name,
                           const RunOptions& options) {
    if (ext != ".vert" && ext != ".frag") return skip(ext.substr(1) + " shaders are not supported");
    auto parsed = parse_parser_test(text);
    if (!parsed_ok(parsed)) return fail(std::get<ParseError>(parsed).str());
    const ParserTest& t = std::get<ParserTest>(parsed);
    if (t.glsl_es) return skip("GLSL ES is not supported");
    if (t.glsl_version > options.caps.max_glsl_version)
        return skip(fmt::format("requires GLSL {}.{:02}", t.glsl_version / 100, t.glsl_version % 100));
    for (const auto& e : t.extensions) {
        bool absent = !e.empty() && e[0] == '!';
        if (options.caps.has_extension(absent ? e.substr(1) : e) == absent)
            return skip(absent ? "requires " + e.substr(1) + " to be absent" : "extension " + e + " is not supported");
    }
    Stage stage = ext == ".vert" ? Stage::Vertex : Stage::Fragment;
    ShaderSource src{name, text};
    std::string log;
    bool ok;
    if (t.check_link) {  // glslparsertest links the shader alone into a program
        std::vector<ShaderSource> one{src}, none;
        auto prog = stage == Stage::Vertex ? Program::compile(one, none) : Program::compile(none, one);
        if (!prog && prog.error().unsupported_version) return skip(prog.error().diagnostics.front().str());
        ok = prog.ok();
        if (!ok) log = prog.error().str();
    } else {
        auto st = check_shader(stage, src, 110);  // the file is compiled as written
        if (!st && st.error().unsupported_version) return skip(st.error().diagnostics.front().str());
        ok = st.ok();
        if (!ok) log = st.error().str();
    }
    if (ok == t.expect_pass) return pass();
    if (ok) return fail(t.check_link ? "compiled and linked, but failure was expected"
                                     : "compiled, but failure was expected");
    return fail("failed to compile: " + log);
}

TestResult run_test_file(const std::string& path, const RunOptions& options) {
    auto text = scene::read_text_file(path, "test file");
    if (!text) return fail(text.error().diagnostics[0].message);
    std::string ext = extension_of(path);
    if (ext == ".shader_test") {
        RunOptions named = options;
        if (named.file.empty()) named.file = path;
        return run_shader_test(*text, std::filesystem::path(path).parent_path().string(), named);
    }
    return run_parser_test(*text, ext, std::filesystem::path(path).filename().string(), options);
}

void warm_up_compiler(Backend backend) {
    const ShaderSource vs{"warm-up.vert", "void main() { gl_Position = ftransform(); }\n"};
    const ShaderSource fs{"warm-up.frag", "void main() { gl_FragColor = gl_Color; }\n"};
    for (int version : {110, 120}) {
        CompileOptions options;
        options.default_version = version;
        auto program = Program::compile({vs}, {fs}, options);
        if (!program || backend != Backend::Jit || version != 110) continue;
        program->exec.backend = Backend::Jit;
        program->exec.jit_quick_codegen = true;  // as run_test_file's
        program->exec.threads = 1;
        Framebuffer pixel(1, 1);
        (void)draw(*program, GLState{}, pixel, Primitive::Triangles, {{"gl_Vertex", 2, {-1, -1, 3, -1, -1, 3}}}, 3);
    }
}

}  // namespace glslrun::piglit
