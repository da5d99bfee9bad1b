// Runs undefined.frag on the first EGL device's GL driver (NVIDIA's, on the
// GPU machine) without glref: a compatibility context, a pbuffer of one pixel
// per case, a full-screen quad, glReadPixels. Prints "x 0xBITS" per column,
// which decode.py reads (docs/debugging.md, "What GPUs return").
//   g++ -O1 -o gpu_probe gpu_probe.cpp -lEGL -lGL
//   ./gpu_probe probe.vert undefined.frag 40 > gpu.txt
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

int die(const char* what) {
    std::fprintf(stderr, "gpu_probe: %s (EGL 0x%x, GL 0x%x)\n", what, eglGetError(), glGetError());
    return 1;
}

EGLDisplay device_display() {
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint major = 0, minor = 0;
    if (get_display && query_devices) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (query_devices(16, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay dpy = get_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) return dpy;
            }
    }
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    return dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor) ? dpy : EGL_NO_DISPLAY;
}

GLuint shader(GLenum stage, const char* path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    const char* s = source.c_str();
    GLuint sh = glCreateShader(stage);
    glShaderSource(sh, 1, &s, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    char log[4096] = {};
    glGetShaderInfoLog(sh, sizeof log, nullptr, log);
    if (!ok || log[0]) std::fprintf(stderr, "gpu_probe: %s: %s\n", path, log);
    return ok ? sh : 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) return die("usage: gpu_probe probe.vert undefined.frag WIDTH");
    const int width = std::atoi(argv[3]);
    EGLDisplay dpy = device_display();
    if (dpy == EGL_NO_DISPLAY) return die("no EGL display");
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
    EGLConfig config;
    EGLint configs = 0;
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &configs) || configs < 1) return die("no EGL config");
    const EGLint surface_attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, 1, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, surface_attribs);
    if (surface == EGL_NO_SURFACE) return die("no pbuffer");
    if (!eglBindAPI(EGL_OPENGL_API)) return die("no OpenGL API");
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, surface, surface, ctx)) return die("no context");
    std::fprintf(stderr, "gpu_probe: GL_RENDERER=%s | GL_VERSION=%s | GLSL=%s\n", glGetString(GL_RENDERER),
                 glGetString(GL_VERSION), glGetString(GL_SHADING_LANGUAGE_VERSION));
    GLuint vs = shader(GL_VERTEX_SHADER, argv[1]), fs = shader(GL_FRAGMENT_SHADER, argv[2]);
    if (!vs || !fs) return die("a shader does not compile");
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) return die("the program does not link");
    glUseProgram(program);
    glUniform1f(glGetUniformLocation(program, "z"), 0.0f);
    glUniform1i(glGetUniformLocation(program, "zi"), 0);
    glViewport(0, 0, width, 1);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    std::vector<unsigned char> pixels(size_t(width) * 4);
    glReadPixels(0, 0, width, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    if (glGetError() != GL_NO_ERROR) return die("GL error");
    for (int x = 0; x < width; ++x) {
        const unsigned char* p = &pixels[size_t(x) * 4];
        std::printf("%d 0x%08x\n", x, unsigned(p[0]) | unsigned(p[1]) << 8 | unsigned(p[2]) << 16 | unsigned(p[3]) << 24);
    }
    return 0;
}
