// glslrun against Mesa, in the same run: the lecture's per-pixel spot light
// (shaders/pos_pix.vert + spot_pix_fixed.frag) on a quad that covers the
// whole W x H framebuffer, with the spot scene of scenes/spot.toml.
//
// glslrun renders in this process. Each Mesa driver renders in a child (this
// executable re-run with --child), because Mesa reads GALLIUM_DRIVER and
// LP_NUM_THREADS once, when the driver loads. Runs are interleaved, so a
// neighbour's load hits every contender alike; ratios are taken within a run.
//
//   glslrun_mesa_bench [--size 1920x1080] [--seconds 3] [--runs 5] [--warmup 1] [--save DIR]
//                      [--only glslrun,softpipe,llvmpipe-1t,llvmpipe]
// Prints per-run lines, then a Markdown table of medians and ratios, and an
// image comparison against glslrun's (docs/performance.md).
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "glslrun/glslrun.h"

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

double process_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Options {
    int width = 1920, height = 1080;
    double seconds = 3.0;  // minimum timed time per measurement
    int runs = 5;
    int warmup = 1;        // frames before timing
    std::string save_dir;  // when set: PNGs of the last run's images
    std::string only;      // comma-separated renderer names; empty: all
};

// RGBA8, row 0 at the bottom (glReadPixels' order).
struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

struct Measurement {
    bool ok = false;
    std::string error;
    std::string renderer;
    int frames = 0;
    double seconds = 0;      // wall clock
    double cpu_seconds = 0;  // all threads of the process: robust against neighbours' load
    uint64_t fragments_per_frame = 0;
    double fragments_per_second() const { return seconds > 0 ? double(fragments_per_frame) * frames / seconds : 0; }
    double fragments_per_cpu_second() const {
        return cpu_seconds > 0 ? double(fragments_per_frame) * frames / cpu_seconds : 0;
    }
};

Measurement failure(std::string why) {
    Measurement m;
    m.error = std::move(why);
    return m;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// ------------------------------------------------------------ the scene ---
// scenes.md: gluPerspective(45, W/H, 1, 100), gluLookAt(0,0,5, 0,0,0, 0,1,0),
// spot light 0 given in world space after the camera is loaded.
struct Scene {
    glm::mat4 projection, view;
    glm::vec4 light_position{0.4f, 1.2f, 2.4f, 1};
    glm::vec3 spot_direction = glm::normalize(glm::vec3(-0.4f, -1.2f, -2.4f));
    // Slightly larger than the view at z = 0 (half height 5*tan(22.5deg) = 2.07).
    std::vector<float> positions;  // 4 corners, xyz
    std::vector<uint32_t> indices{0, 1, 2, 0, 2, 3};
};

Scene make_scene(int width, int height) {
    Scene s;
    float aspect = float(width) / float(height);
    s.projection = glm::perspective(glm::radians(45.0f), aspect, 1.0f, 100.0f);
    s.view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    float hy = 5.0f * std::tan(glm::radians(22.5f)) * 1.05f, hx = hy * aspect;
    s.positions = {-hx, -hy, 0, hx, -hy, 0, hx, hy, 0, -hx, hy, 0};
    return s;
}

struct Material {
    float ambient[4] = {0.25f, 0.20f, 0.07f, 1}, diffuse[4] = {0.75f, 0.61f, 0.23f, 1};
    float specular[4] = {0.8f, 0.8f, 0.8f, 1}, emission[4] = {0, 0, 0.05f, 1};
    float shininess = 64;
};
constexpr float kLightAmbient[4] = {0.2f, 0.2f, 0.2f, 1};
constexpr float kLightDiffuse[4] = {1, 1, 1, 1}, kLightSpecular[4] = {1, 1, 1, 1};
constexpr float kAttenuation[3] = {1, 0.05f, 0.02f};
constexpr float kSpotCutoff = 20, kSpotExponent = 12;

// ------------------------------------------------------------- glslrun ---
glslrun::GLState glslrun_state(const Scene& s) {
    glslrun::GLState gl;
    gl.projection = s.projection;
    gl.modelview = s.view;
    auto& light = gl.lights[0];
    light.ambient = glm::make_vec4(kLightAmbient);
    light.diffuse = glm::make_vec4(kLightDiffuse);
    light.specular = glm::make_vec4(kLightSpecular);
    light.position = s.view * s.light_position;  // what glLightfv does
    light.spot_direction = glm::mat3(s.view) * s.spot_direction;
    light.spot_cutoff = kSpotCutoff;
    light.spot_exponent = kSpotExponent;
    light.constant_attenuation = kAttenuation[0];
    light.linear_attenuation = kAttenuation[1];
    light.quadratic_attenuation = kAttenuation[2];
    Material m;
    gl.front_material = {glm::make_vec4(m.ambient), glm::make_vec4(m.diffuse), glm::make_vec4(m.specular),
                         glm::make_vec4(m.emission), m.shininess};
    gl.back_material = gl.front_material;
    gl.depth_test = true;
    gl.depth_func = glslrun::GLState::DepthFunc::Less;
    return gl;
}

Image to_image(const glslrun::Framebuffer& fb) {
    std::span<const uint8_t> bytes = fb.color_data<uint8_t>();  // an RGBA8 framebuffer
    return Image{fb.width, fb.height, std::vector<uint8_t>(bytes.begin(), bytes.end())};
}

Measurement measure_glslrun(const Options& opt, const std::string& shader_dir, Image* image) {
    Measurement m;
    m.renderer = "glslrun";
    auto prog = glslrun::Program::compile({{"pos_pix.vert", read_text(shader_dir + "/pos_pix.vert")}},
                                          {{"spot_pix_fixed.frag", read_text(shader_dir + "/spot_pix_fixed.frag")}});
    if (!prog) {
        m.error = prog.error().str();
        return m;
    }
    Scene scene = make_scene(opt.width, opt.height);
    glslrun::GLState gl = glslrun_state(scene);
    std::vector<glslrun::VertexAttrib> mesh = {{"gl_Vertex", 3, scene.positions},
                                               {"gl_Normal", 3, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}}};
    glslrun::Framebuffer fb(opt.width, opt.height);
    auto frame = [&]() -> bool {
        fb.clear_color({0, 0, 0, 1});
        fb.clear_depth(1.0f);
        auto st = glslrun::draw(*prog, gl, fb, glslrun::Primitive::Triangles, mesh, 4, scene.indices);
        if (!st) {
            m.error = st.error().str();
            return false;
        }
        m.fragments_per_frame = st->fragments_shaded;
        return true;
    };
    for (int i = 0; i < opt.warmup; ++i)
        if (!frame()) return m;
    auto start = Clock::now();
    double cpu_start = process_cpu_seconds();
    do {
        if (!frame()) return m;
        ++m.frames;
        m.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } while (m.seconds < opt.seconds || m.frames < 2);
    m.cpu_seconds = process_cpu_seconds() - cpu_start;
    if (image) *image = to_image(fb);
    m.ok = true;
    return m;
}

// ---------------------------------------------------------------- Mesa ---
// GL 1.5+ entry points come from eglGetProcAddress (libOpenGL exports only
// what its headers promise).
struct GLFunctions {
    PFNGLGENFRAMEBUFFERSPROC GenFramebuffers;
    PFNGLBINDFRAMEBUFFERPROC BindFramebuffer;
    PFNGLGENRENDERBUFFERSPROC GenRenderbuffers;
    PFNGLBINDRENDERBUFFERPROC BindRenderbuffer;
    PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus;
    PFNGLCREATESHADERPROC CreateShader;
    PFNGLSHADERSOURCEPROC ShaderSource;
    PFNGLCOMPILESHADERPROC CompileShader;
    PFNGLGETSHADERIVPROC GetShaderiv;
    PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
    PFNGLCREATEPROGRAMPROC CreateProgram;
    PFNGLATTACHSHADERPROC AttachShader;
    PFNGLLINKPROGRAMPROC LinkProgram;
    PFNGLGETPROGRAMIVPROC GetProgramiv;
    PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
    PFNGLUSEPROGRAMPROC UseProgram;
    PFNGLGENQUERIESPROC GenQueries;
    PFNGLBEGINQUERYPROC BeginQuery;
    PFNGLENDQUERYPROC EndQuery;
    PFNGLGETQUERYOBJECTUIVPROC GetQueryObjectuiv;
};

template <class F>
bool load(F& fn, const char* name) {
    fn = reinterpret_cast<F>(eglGetProcAddress(name));
    return fn != nullptr;
}

bool load_functions(GLFunctions& f) {
    return load(f.GenFramebuffers, "glGenFramebuffers") && load(f.BindFramebuffer, "glBindFramebuffer") &&
           load(f.GenRenderbuffers, "glGenRenderbuffers") && load(f.BindRenderbuffer, "glBindRenderbuffer") &&
           load(f.RenderbufferStorage, "glRenderbufferStorage") &&
           load(f.FramebufferRenderbuffer, "glFramebufferRenderbuffer") &&
           load(f.CheckFramebufferStatus, "glCheckFramebufferStatus") && load(f.CreateShader, "glCreateShader") &&
           load(f.ShaderSource, "glShaderSource") && load(f.CompileShader, "glCompileShader") &&
           load(f.GetShaderiv, "glGetShaderiv") && load(f.GetShaderInfoLog, "glGetShaderInfoLog") &&
           load(f.CreateProgram, "glCreateProgram") && load(f.AttachShader, "glAttachShader") &&
           load(f.LinkProgram, "glLinkProgram") && load(f.GetProgramiv, "glGetProgramiv") &&
           load(f.GetProgramInfoLog, "glGetProgramInfoLog") && load(f.UseProgram, "glUseProgram") &&
           load(f.GenQueries, "glGenQueries") && load(f.BeginQuery, "glBeginQuery") &&
           load(f.EndQuery, "glEndQuery") && load(f.GetQueryObjectuiv, "glGetQueryObjectuiv");
}

// A compatibility context on the surfaceless platform, current without a surface.
std::string make_context() {
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) return "no eglGetPlatformDisplayEXT";
    EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) return "eglInitialize failed";
    if (!eglBindAPI(EGL_OPENGL_API)) return "eglBindAPI(EGL_OPENGL_API) failed";
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count == 0) config = nullptr;
    // No attributes: Mesa gives its newest compatibility profile.
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
    if (ctx == EGL_NO_CONTEXT) return "eglCreateContext failed";
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) return "eglMakeCurrent failed";
    return {};
}

std::string make_framebuffer(const GLFunctions& gl, int width, int height) {
    GLuint fbo = 0, rb[2] = {0, 0};
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.GenRenderbuffers(2, rb);
    gl.BindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    gl.BindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return "FBO incomplete";
    return {};
}

std::string compile_program(const GLFunctions& gl, const std::string& vs, const std::string& fs) {
    GLuint prog = gl.CreateProgram();
    for (auto [type, text] : {std::pair{GLenum(GL_VERTEX_SHADER), &vs}, std::pair{GLenum(GL_FRAGMENT_SHADER), &fs}}) {
        GLuint sh = gl.CreateShader(type);
        const char* src = text->c_str();
        gl.ShaderSource(sh, 1, &src, nullptr);
        gl.CompileShader(sh);
        GLint ok = 0;
        gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[4096] = {};
            gl.GetShaderInfoLog(sh, sizeof log, nullptr, log);
            return std::string("compile: ") + log;
        }
        gl.AttachShader(prog, sh);
    }
    gl.LinkProgram(prog);
    GLint ok = 0;
    gl.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetProgramInfoLog(prog, sizeof log, nullptr, log);
        return std::string("link: ") + log;
    }
    gl.UseProgram(prog);
    return {};
}

void set_light_and_material() {
    glLightfv(GL_LIGHT0, GL_AMBIENT, kLightAmbient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, kLightDiffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, kLightSpecular);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, kSpotCutoff);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, kSpotExponent);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, kAttenuation[0]);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, kAttenuation[1]);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, kAttenuation[2]);
    Material m;
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, m.ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, m.diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, m.specular);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, m.emission);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shininess);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1.0);
}

// The per-frame sequence of scenes.md, ending in glFinish.
void mesa_frame(const Scene& s, int width, int height) {
    glViewport(0, 0, width, height);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(s.projection));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(s.view));
    glLightfv(GL_LIGHT0, GL_POSITION, glm::value_ptr(s.light_position));
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, glm::value_ptr(s.spot_direction));
    glBegin(GL_TRIANGLES);
    glNormal3f(0, 0, 1);
    for (uint32_t i : s.indices) glVertex3fv(&s.positions[3 * i]);
    glEnd();
    glFinish();
}

Measurement measure_mesa(const Options& opt, const std::string& shader_dir, Image* image) {
    Measurement m;
    GLFunctions gl{};
    if (m.error = make_context(); !m.error.empty()) return m;
    if (!load_functions(gl)) {
        m.error = "missing GL entry points";
        return m;
    }
    m.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (m.error = make_framebuffer(gl, opt.width, opt.height); !m.error.empty()) return m;
    m.error = compile_program(gl, read_text(shader_dir + "/pos_pix.vert"),
                              read_text(shader_dir + "/spot_pix_fixed.frag"));
    if (!m.error.empty()) return m;
    set_light_and_material();
    Scene scene = make_scene(opt.width, opt.height);
    for (int i = 0; i < opt.warmup; ++i) mesa_frame(scene, opt.width, opt.height);
    auto start = Clock::now();
    double cpu_start = process_cpu_seconds();
    do {
        mesa_frame(scene, opt.width, opt.height);
        ++m.frames;
        m.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } while (m.seconds < opt.seconds || m.frames < 2);
    m.cpu_seconds = process_cpu_seconds() - cpu_start;
    // One more frame, untimed, counts the fragments that passed the depth test.
    GLuint query = 0;
    gl.GenQueries(1, &query);
    gl.BeginQuery(GL_SAMPLES_PASSED, query);
    mesa_frame(scene, opt.width, opt.height);
    gl.EndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    gl.GetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    m.fragments_per_frame = samples;
    if (image) {
        *image = {opt.width, opt.height, std::vector<uint8_t>(size_t(opt.width) * opt.height * 4)};
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, opt.width, opt.height, GL_RGBA, GL_UNSIGNED_BYTE, image->rgba.data());
    }
    m.ok = glGetError() == GL_NO_ERROR;
    if (!m.ok) m.error = "GL error";
    return m;
}

// ------------------------------------------------------ child processes ---
bool write_raw(const std::string& path, const Image& img) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(img.rgba.data()), std::streamsize(img.rgba.size()));
    return bool(out);
}

bool read_raw(const std::string& path, int width, int height, Image* img) {
    *img = {width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(img->rgba.data()), std::streamsize(img->rgba.size()));
    return in.gcount() == std::streamsize(img->rgba.size());
}

// The child's answer: one "key<TAB>value" line each.
int run_child(const Options& opt, const std::string& shader_dir, const std::string& image_path) {
    Image img;
    Measurement m = measure_mesa(opt, shader_dir, &img);
    if (m.ok && !write_raw(image_path, img)) m = failure("cannot write " + image_path);
    for (char& c : m.error) c = c == '\n' || c == '\t' ? ' ' : c;
    std::printf("ok\t%d\nerror\t%s\nrenderer\t%s\nframes\t%d\nseconds\t%.9f\ncpu\t%.9f\nfragments\t%llu\n", m.ok ? 1 : 0,
                m.error.c_str(), m.renderer.c_str(), m.frames, m.seconds, m.cpu_seconds,
                static_cast<unsigned long long>(m.fragments_per_frame));
    return m.ok ? 0 : 1;
}

struct Contender {
    std::string name;
    std::vector<std::pair<std::string, std::string>> env;  // empty value: unset
    bool mesa = true;
};

std::vector<std::string> child_environment(const Contender& c) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) {
        std::string entry = *e;
        bool overridden = std::any_of(c.env.begin(), c.env.end(),
                                      [&](const auto& kv) { return entry.rfind(kv.first + "=", 0) == 0; });
        if (!overridden) env.push_back(entry);
    }
    for (const auto& [key, value] : c.env)
        if (!value.empty()) env.push_back(key + "=" + value);
    return env;
}

Measurement parse_child_output(const std::string& text) {
    std::map<std::string, std::string> fields;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (auto tab = line.find('\t'); tab != std::string::npos) fields[line.substr(0, tab)] = line.substr(tab + 1);
    Measurement m;
    m.ok = fields["ok"] == "1";
    m.error = fields.count("ok") ? fields["error"] : "child printed nothing: " + text;
    m.renderer = fields["renderer"];
    m.frames = std::atoi(fields["frames"].c_str());
    m.seconds = std::atof(fields["seconds"].c_str());
    m.cpu_seconds = std::atof(fields["cpu"].c_str());
    m.fragments_per_frame = std::strtoull(fields["fragments"].c_str(), nullptr, 10);
    return m;
}

Measurement measure_in_child(const Options& opt, const Contender& c, const std::string& image_path) {
    char self[4096] = {};
    if (readlink("/proc/self/exe", self, sizeof self - 1) <= 0) return failure("readlink /proc/self/exe");
    std::vector<std::string> args = {self, "--child", image_path,
                                     "--size", std::to_string(opt.width) + "x" + std::to_string(opt.height),
                                     "--seconds", std::to_string(opt.seconds), "--warmup", std::to_string(opt.warmup)};
    std::vector<std::string> env = child_environment(c);
    std::vector<char*> argv, envp;
    for (auto& a : args) argv.push_back(a.data());
    for (auto& e : env) envp.push_back(e.data());
    argv.push_back(nullptr);
    envp.push_back(nullptr);
    int fds[2];
    if (pipe(fds) != 0) return failure("pipe");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    pid_t pid = 0;
    int err = posix_spawn(&pid, self, &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    std::string out;
    if (err == 0) {
        char buf[4096];
        for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, size_t(n));
        int status = 0;
        waitpid(pid, &status, 0);
    }
    close(fds[0]);
    if (err != 0) return failure(std::string("posix_spawn: ") + std::strerror(err));
    return parse_child_output(out);
}

// ---------------------------------------------------------- the report ---
struct Difference {
    int max_channel = 0;
    uint64_t pixels_over_one = 0;  // pixels with some channel off by more than 1/255
};

Difference compare(const Image& a, const Image& b) {
    Difference d;
    if (a.rgba.size() != b.rgba.size()) return {255, uint64_t(-1)};
    for (size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (size_t c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        d.max_channel = std::max(d.max_channel, worst);
        d.pixels_over_one += worst > 1;
    }
    return d;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void save_png(const Image& img, const std::string& path) {
    glslrun::Framebuffer fb(img.width, img.height);
    std::copy(img.rgba.begin(), img.rgba.end(), fb.color_data<uint8_t>().begin());
    if (auto st = glslrun::write_png(fb, path); !st) std::fprintf(stderr, "%s\n", st.error().str().c_str());
}

bool parse_options(int argc, char** argv, Options* opt, std::string* child_image) {
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        bool has_value = i + 1 < argc;
        if (a == "--size" && has_value) {
            if (std::sscanf(argv[++i], "%dx%d", &opt->width, &opt->height) != 2) return false;
        } else if (a == "--seconds" && has_value) {
            opt->seconds = std::atof(argv[++i]);
        } else if (a == "--runs" && has_value) {
            opt->runs = std::atoi(argv[++i]);
        } else if (a == "--warmup" && has_value) {
            opt->warmup = std::atoi(argv[++i]);
        } else if (a == "--save" && has_value) {
            opt->save_dir = argv[++i];
        } else if (a == "--only" && has_value) {
            opt->only = argv[++i];
        } else if (a == "--child" && has_value) {
            *child_image = argv[++i];
        } else {
            return false;
        }
    }
    return opt->width > 0 && opt->height > 0 && opt->width <= 8192 && opt->height <= 8192 && opt->runs > 0 &&
           opt->warmup >= 0;
}

// glslrun first: the ratios divide by the others. `only` (comma-separated
// names) keeps some, e.g. to profile one of them.
std::vector<Contender> contenders(const std::string& only) {
    const std::vector<Contender> all = {
        {"glslrun", {}, false},
        {"softpipe", {{"GALLIUM_DRIVER", "softpipe"}, {"LIBGL_ALWAYS_SOFTWARE", "1"}, {"LP_NUM_THREADS", ""}}},
        {"llvmpipe-1t", {{"GALLIUM_DRIVER", "llvmpipe"}, {"LIBGL_ALWAYS_SOFTWARE", "1"}, {"LP_NUM_THREADS", "1"}}},
        {"llvmpipe", {{"GALLIUM_DRIVER", "llvmpipe"}, {"LIBGL_ALWAYS_SOFTWARE", "1"}, {"LP_NUM_THREADS", ""}}},
    };
    std::vector<Contender> chosen;
    for (const Contender& c : all)
        if (only.empty() || ("," + only + ",").find("," + c.name + ",") != std::string::npos) chosen.push_back(c);
    return chosen;
}

struct Summary {
    double median = 0, min = 0, max = 0, ratio = 0;  // ratio: median of glslrun / it within each run
    bool ok = false;
};

Summary summarize(const std::vector<std::vector<Measurement>>& runs, size_t c, bool has_glslrun,
                  double (Measurement::*rate)() const) {
    std::vector<double> rates, ratios;
    for (const auto& run : runs) {
        if (!run[c].ok) continue;
        rates.push_back((run[c].*rate)() / 1e6);
        if (has_glslrun && run[0].ok) ratios.push_back((run[0].*rate)() / (run[c].*rate)());
    }
    if (rates.empty()) return {};
    return {median(rates), *std::min_element(rates.begin(), rates.end()),
            *std::max_element(rates.begin(), rates.end()), median(ratios), true};
}

void print_summary(const Options& opt, const std::vector<Contender>& list,
                   const std::vector<std::vector<Measurement>>& runs, const std::vector<Image>& images) {
    bool has_glslrun = !list.empty() && !list[0].mesa;
    std::printf("\n%d runs; M fragments/s: median [min, max]; glslrun/x: median of the per-run ratios\n",
                int(runs.size()));
    std::printf("| renderer | wall clock | glslrun/x (wall) | per CPU-second | glslrun/x (CPU) |\n");
    std::printf("|---|---|---|---|---|\n");
    for (size_t c = 0; c < list.size(); ++c) {
        Summary wall = summarize(runs, c, has_glslrun, &Measurement::fragments_per_second);
        Summary cpu = summarize(runs, c, has_glslrun, &Measurement::fragments_per_cpu_second);
        if (!wall.ok) {
            std::printf("| %s | failed | | | |\n", list[c].name.c_str());
            continue;
        }
        std::printf("| %s | %.3f [%.3f, %.3f] | %.3f | %.3f [%.3f, %.3f] | %.3f |\n", list[c].name.c_str(),
                    wall.median, wall.min, wall.max, wall.ratio, cpu.median, cpu.min, cpu.max, cpu.ratio);
    }
    if (!has_glslrun || images[0].rgba.empty()) return;
    std::printf("\nImages (%dx%d, last run) against glslrun's:\n", opt.width, opt.height);
    for (size_t c = 1; c < list.size(); ++c) {
        if (images[c].rgba.empty()) continue;
        Difference d = compare(images[0], images[c]);
        std::printf("  %-12s max channel difference %d/255, %llu of %d pixels differ by more than 1/255\n",
                    list[c].name.c_str(), d.max_channel, static_cast<unsigned long long>(d.pixels_over_one),
                    opt.width * opt.height);
    }
}

void print_measurement(int run, const std::string& name, const Measurement& m) {
    if (!m.ok) {
        std::printf("run %d %-12s FAILED: %s\n", run, name.c_str(), m.error.c_str());
    } else {
        std::printf("run %d %-12s %8.3f M fragments/s, %8.3f per CPU-s  (%d frames in %.2f s, %.2f CPU-s, %llu "
                    "fragments/frame; %s)\n",
                    run, name.c_str(), m.fragments_per_second() / 1e6, m.fragments_per_cpu_second() / 1e6, m.frames,
                    m.seconds, m.cpu_seconds, static_cast<unsigned long long>(m.fragments_per_frame),
                    m.renderer.c_str());
    }
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    std::string child_image;
    if (!parse_options(argc, argv, &opt, &child_image)) {
        std::fprintf(stderr,
                     "usage: %s [--size WxH] [--seconds S] [--runs N] [--warmup K] [--save DIR] "
                     "[--only glslrun,softpipe,llvmpipe-1t,llvmpipe]\n",
                     argv[0]);
        return 2;
    }
    const std::string shader_dir = GLSLRUN_SHADER_DIR;
    if (!child_image.empty()) return run_child(opt, shader_dir, child_image);

    const std::vector<Contender> list = contenders(opt.only);
    if (list.empty()) {
        std::fprintf(stderr, "--only %s: no such renderer\n", opt.only.c_str());
        return 2;
    }
    std::vector<std::vector<Measurement>> runs;
    std::vector<Image> images(list.size());
    std::string raw = "/tmp/glslrun_mesa_bench." + std::to_string(getpid()) + ".rgba";
    for (int r = 0; r < opt.runs; ++r) {
        std::vector<Measurement> run(list.size());
        // Rotate the order each run so that no contender always goes first.
        for (size_t k = 0; k < list.size(); ++k) {
            size_t c = (k + size_t(r)) % list.size();
            if (!list[c].mesa) {
                run[c] = measure_glslrun(opt, shader_dir, &images[c]);
            } else {
                run[c] = measure_in_child(opt, list[c], raw);
                if (run[c].ok && !read_raw(raw, opt.width, opt.height, &images[c])) run[c] = failure("no image");
            }
            print_measurement(r, list[c].name, run[c]);
        }
        runs.push_back(std::move(run));
    }
    std::remove(raw.c_str());
    print_summary(opt, list, runs, images);
    if (!opt.save_dir.empty())
        for (size_t c = 0; c < list.size(); ++c)
            if (!images[c].rgba.empty()) save_png(images[c], opt.save_dir + "/" + list[c].name + ".png");
    return 0;
}
