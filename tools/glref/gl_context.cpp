#include "tools/glref/gl_context.h"

#include <cstdio>
#include <cstdlib>

#include <EGL/eglext.h>
#include <fmt/format.h>

namespace glslrun::glref {

namespace {

// The process's one EGL display. Not thread-safe: glref and the tests render
// from one thread.
struct DisplayState {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string driver;
};

DisplayState& display_state() {
    static DisplayState state;
    return state;
}

// Mesa's software rasterisers are the oracle; "gpu" (the first EGL device, e.g.
// NVIDIA's driver) is a second anchor for Fast's GPU rules, never the tests'
// oracle, since its images depend on the machine.
bool known_driver(const std::string& driver) {
    return driver == "llvmpipe" || driver == "softpipe" || driver == "gpu";
}

// The first EGL device (EGL_EXT_platform_device) that initialises, else the
// surfaceless platform, else the default display. GLREF_EGL_DEVICE=N picks device N.
Result<EGLDisplay> open_gpu_display() {
    auto get_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLint major = 0, minor = 0;
    if (get_display && query_devices) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (query_devices(16, devices, &count)) {
            std::fprintf(stderr, "glref: %d EGL device(s)\n", count);
            const char* pick = std::getenv("GLREF_EGL_DEVICE");
            for (EGLint i = 0; i < count; ++i) {
                if (pick && std::atoi(pick) != i) continue;
                const char* ext = query_device_string ? query_device_string(devices[i], EGL_EXTENSIONS) : nullptr;
                std::fprintf(stderr, "glref: EGL device %d extensions: %s\n", i, ext ? ext : "(none)");
                EGLDisplay dpy = get_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
                    const char* vendor = eglQueryString(dpy, EGL_VENDOR);
                    const char* version = eglQueryString(dpy, EGL_VERSION);
                    std::fprintf(stderr, "glref: EGL device %d: EGL_VENDOR=%s EGL_VERSION=%s\n", i,
                                 vendor ? vendor : "?", version ? version : "?");
                    return dpy;
                }
                std::fprintf(stderr, "glref: EGL device %d does not initialise (0x%x)\n", i, eglGetError());
            }
        }
    }
    if (get_display) {
        EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
            std::fprintf(stderr, "glref: surfaceless platform\n");
            return dpy;
        }
    }
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
        std::fprintf(stderr, "glref: default display\n");
        return dpy;
    }
    return Error(fmt::format("no EGL device, surfaceless or default display initialises (EGL error 0x{:x})",
                             eglGetError()));
}

Result<EGLDisplay> open_display(const std::string& driver) {
    DisplayState& s = display_state();
    if (s.display != EGL_NO_DISPLAY) {
        if (s.driver == driver) return s.display;
        return Error(fmt::format("Mesa already runs {} in this process and reads GALLIUM_DRIVER only once; "
                                 "render with {} in a separate process",
                                 s.driver, driver));
    }
    if (driver == "gpu") {
        auto dpy = open_gpu_display();
        if (!dpy) return dpy.error();
        s.display = *dpy;
        s.driver = driver;
        return *dpy;
    }
    // Read by Mesa's loader when the display initialises, never again.
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    setenv("GALLIUM_DRIVER", driver.c_str(), 1);
    // llvmpipe filters RGBA8 textures in 8-bit fixed point by default ("AoS
    // sampling"): bilinear weights are rounded to 1/256, and its mipmap
    // generation drifts up by about 1/2 of 1/255 per level. The reference
    // should show GL's arithmetic, so it samples in float; a GALLIVM_PERF the
    // user set is kept.
    setenv("GALLIVM_PERF", "no_aos_sampling", 0);
    auto get_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) return Error("EGL has no eglGetPlatformDisplayEXT (is Mesa's libEGL installed?)");
    EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor))
        return Error(fmt::format("cannot initialise EGL on the surfaceless platform (EGL error 0x{:x}); "
                                 "install libegl-dev and libgl1-mesa-dri",
                                 eglGetError()));
    s.display = dpy;
    s.driver = driver;
    return dpy;
}

// Desktop OpenGL 2.1: Mesa answers with its newest compatibility profile,
// which keeps all of 2.1's fixed-function state.
Result<EGLContext> create_context(EGLDisplay dpy) {
    if (!eglBindAPI(EGL_OPENGL_API)) return Error("eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless rendering needs no config (EGL_KHR_no_config_context).
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count == 0) config = nullptr;
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, attribs);
    if (ctx == EGL_NO_CONTEXT) return Error(fmt::format("eglCreateContext failed (EGL error 0x{:x})", eglGetError()));
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        return Error(fmt::format("eglMakeCurrent without a surface failed (EGL error 0x{:x})", eglGetError()));
    }
    return ctx;
}

Status load_functions(GLFunctions& gl) {
    std::string missing;
#define GLREF_LOAD(type, name)                                                  \
    gl.name = reinterpret_cast<type>(eglGetProcAddress("gl" #name));           \
    if (!gl.name) missing += " gl" #name;
    GLREF_GL_FUNCTIONS(GLREF_LOAD)
#undef GLREF_LOAD
    if (!missing.empty()) return Error("Mesa lacks GL entry points:" + missing);
    return Ok{};
}

}  // namespace

Result<std::unique_ptr<MesaContext>> MesaContext::create(const std::string& driver) {
    if (!known_driver(driver))
        return Error(fmt::format("unknown driver '{}': use llvmpipe, softpipe or gpu", driver));
    auto dpy = open_display(driver);
    if (!dpy) return dpy.error();
    auto ctx = create_context(*dpy);
    if (!ctx) return ctx.error();
    std::unique_ptr<MesaContext> c(new MesaContext);
    c->display_ = *dpy;
    c->context_ = *ctx;
    if (Status st = load_functions(c->gl_); !st) return st.error();
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    c->renderer_ = renderer ? renderer : "";
    if (driver == "gpu") {
        auto str = [](GLenum name) {
            const char* v = reinterpret_cast<const char*>(glGetString(name));
            return std::string(v ? v : "?");
        };
        std::fprintf(stderr, "glref: GL_VENDOR=%s | GL_RENDERER=%s | GL_VERSION=%s | GLSL=%s\n",
                     str(GL_VENDOR).c_str(), str(GL_RENDERER).c_str(), str(GL_VERSION).c_str(),
                     str(GL_SHADING_LANGUAGE_VERSION).c_str());
        return c;
    }
    // A hardware or wrong software driver would compare against the wrong oracle.
    if (c->renderer_.find(driver) == std::string::npos)
        return Error(fmt::format("asked Mesa for {} but got renderer '{}'", driver, c->renderer_));
    return c;
}

MesaContext::~MesaContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);  // frees the context's buffers, FBO and programs
}

Status MesaContext::make_framebuffer(int width, int height, int color_buffers) {
    GLint max_size = 0, max_buffers = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &max_buffers);
    if (width > max_size || height > max_size)
        return Error(fmt::format("{}x{} exceeds Mesa's largest renderbuffer ({})", width, height, max_size));
    if (color_buffers < 1 || color_buffers > max_buffers)
        return Error(fmt::format("{} colour buffers: Mesa draws to 1..{}", color_buffers, max_buffers));
    GLuint fbo = 0;
    gl_.GenFramebuffers(1, &fbo);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    auto attach = [&](GLenum format, GLenum attachment) {
        GLuint rb = 0;
        gl_.GenRenderbuffers(1, &rb);
        gl_.BindRenderbuffer(GL_RENDERBUFFER, rb);
        gl_.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
        gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, rb);
    };
    for (int i = 0; i < color_buffers; ++i) attach(GL_RGBA8, GLenum(GL_COLOR_ATTACHMENT0 + i));
    attach(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) return Error(fmt::format("Mesa's FBO is incomplete (0x{:x})", status));
    return Ok{};
}

std::string gl_error_name(GLenum error) {
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: return fmt::format("GL error 0x{:x}", error);
    }
}

}  // namespace glslrun::glref
