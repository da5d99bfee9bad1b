// Mesa through EGL on the surfaceless platform: a fresh OpenGL compatibility
// context per render (so every render starts from GL's default state), an
// RGBA8 (one per draw buffer) + DEPTH24_STENCIL8 framebuffer object, and the entry points beyond GL 1.1.
#pragma once
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <memory>
#include <string>

#include "glslrun/glslrun.h"

namespace glslrun::glref {

// Entry points after GL 1.1: libGL does not promise to export them, so they
// come from eglGetProcAddress. X(type, name) for each; the member is `name`
// and the GL function "gl" name.
#define GLREF_GL_FUNCTIONS(X)                                                               \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                            \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                            \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                          \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                          \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                                    \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                            \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                  \
    X(PFNGLFOGCOORDFPROC, FogCoordf)                                                        \
    X(PFNGLVERTEXATTRIB4FVPROC, VertexAttrib4fv)                                            \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                              \
    X(PFNGLCREATESHADERPROC, CreateShader)                                                  \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                  \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                                \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                    \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                          \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                                  \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                    \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                  \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                        \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                      \
    X(PFNGLGETACTIVEUNIFORMPROC, GetActiveUniform)                                          \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                      \
    X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                                      \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                                      \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                      \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                      \
    X(PFNGLUNIFORM1IVPROC, Uniform1iv)                                                      \
    X(PFNGLUNIFORM2IVPROC, Uniform2iv)                                                      \
    X(PFNGLUNIFORM3IVPROC, Uniform3iv)                                                      \
    X(PFNGLUNIFORM4IVPROC, Uniform4iv)                                                      \
    X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv)                                          \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                          \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                          \
    X(PFNGLUNIFORMMATRIX2X3FVPROC, UniformMatrix2x3fv)                                      \
    X(PFNGLUNIFORMMATRIX3X2FVPROC, UniformMatrix3x2fv)                                      \
    X(PFNGLUNIFORMMATRIX2X4FVPROC, UniformMatrix2x4fv)                                      \
    X(PFNGLUNIFORMMATRIX4X2FVPROC, UniformMatrix4x2fv)                                      \
    X(PFNGLUNIFORMMATRIX3X4FVPROC, UniformMatrix3x4fv)                                      \
    X(PFNGLUNIFORMMATRIX4X3FVPROC, UniformMatrix4x3fv)                                      \
    X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                                        \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                            \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)                          \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                    \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                      \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                      \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                      \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                \
    X(PFNGLCLIENTACTIVETEXTUREARBPROC, ClientActiveTexture)                                 \
    X(PFNGLSECONDARYCOLORPOINTERPROC, SecondaryColorPointer)                                \
    X(PFNGLSECONDARYCOLOR3FVPROC, SecondaryColor3fv)                                        \
    X(PFNGLFOGCOORDPOINTERPROC, FogCoordPointer)                                            \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                      \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                                              \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                    \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                        \
    X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate)                                \
    X(PFNGLBLENDCOLORPROC, BlendColor)                                                      \
    X(PFNGLSTENCILFUNCSEPARATEPROC, StencilFuncSeparate)                                    \
    X(PFNGLSTENCILOPSEPARATEPROC, StencilOpSeparate)                                        \
    X(PFNGLSTENCILMASKSEPARATEPROC, StencilMaskSeparate)                                    \
    X(PFNGLPOINTPARAMETERFPROC, PointParameterf)                                            \
    X(PFNGLPOINTPARAMETERFVPROC, PointParameterfv)                                          \
    X(PFNGLPOINTPARAMETERIPROC, PointParameteri)

struct GLFunctions {
#define GLREF_DECLARE(type, name) type name = nullptr;
    GLREF_GL_FUNCTIONS(GLREF_DECLARE)
#undef GLREF_DECLARE
};

// A current context on `driver` ("llvmpipe" or "softpipe"), destroyed with
// this object. Mesa reads GALLIUM_DRIVER once per process, when EGL first
// initialises: a later request for another driver is an error, not a silent
// render with the first one.
class MesaContext {
public:
    static Result<std::unique_ptr<MesaContext>> create(const std::string& driver);
    ~MesaContext();
    MesaContext(const MesaContext&) = delete;
    MesaContext& operator=(const MesaContext&) = delete;

    const GLFunctions& gl() const { return gl_; }
    const std::string& renderer() const { return renderer_; }  // GL_RENDERER
    // Creates and binds an FBO of `color_buffers` RGBA8 colour attachments
    // and 24-bit depth with 8-bit stencil, single-sampled.
    Status make_framebuffer(int width, int height, int color_buffers = 1);

private:
    MesaContext() = default;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    GLFunctions gl_;
    std::string renderer_;
};

// "GL_INVALID_ENUM" etc. for messages.
std::string gl_error_name(GLenum error);

}  // namespace glslrun::glref
