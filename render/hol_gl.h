/* hol_gl.h - the GLES 3.0 entry points the renderer uses, loaded at run
 * time through the platform's get-proc-address.
 *
 * Contract
 * - render/ never links GL symbols directly (GL_GLES_PROTOTYPES is 0, so a
 *   direct call does not compile): every call goes through a hol_gl table
 *   filled by hol_gl_load from the platform's loader (OSMesaGetProcAddress,
 *   eglGetProcAddress, ...). So one binary can hold several GL platforms
 *   (OSMesa and EGL) without their gl* symbols clashing.
 * - hol_gl_load fails with HOL_EUNSUPPORTED naming no function it could not
 *   find; the table is then unusable.
 */
#ifndef HOL_GL_H
#define HOL_GL_H

#ifndef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 0
#endif
#include <GLES3/gl3.h>

#include "../core/hol_err.h"

typedef void (*hol_gl_proc)(void);
typedef hol_gl_proc (*hol_gl_getproc)(const char *name);

#define HOL_GL_FUNCS(X) \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture, "glActiveTexture") \
    X(PFNGLATTACHSHADERPROC, AttachShader, "glAttachShader") \
    X(PFNGLBINDBUFFERPROC, BindBuffer, "glBindBuffer") \
    X(PFNGLBINDTEXTUREPROC, BindTexture, "glBindTexture") \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, "glBindVertexArray") \
    X(PFNGLBLENDCOLORPROC, BlendColor, "glBlendColor") \
    X(PFNGLBLENDFUNCPROC, BlendFunc, "glBlendFunc") \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate, "glBlendFuncSeparate") \
    X(PFNGLBUFFERDATAPROC, BufferData, "glBufferData") \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData, "glBufferSubData") \
    X(PFNGLCLEARPROC, Clear, "glClear") \
    X(PFNGLCLEARCOLORPROC, ClearColor, "glClearColor") \
    X(PFNGLCLEARDEPTHFPROC, ClearDepthf, "glClearDepthf") \
    X(PFNGLCLEARSTENCILPROC, ClearStencil, "glClearStencil") \
    X(PFNGLCOLORMASKPROC, ColorMask, "glColorMask") \
    X(PFNGLCOMPILESHADERPROC, CompileShader, "glCompileShader") \
    X(PFNGLCOPYBUFFERSUBDATAPROC, CopyBufferSubData, "glCopyBufferSubData") \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram, "glCreateProgram") \
    X(PFNGLCREATESHADERPROC, CreateShader, "glCreateShader") \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, "glDeleteBuffers") \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram, "glDeleteProgram") \
    X(PFNGLDELETESHADERPROC, DeleteShader, "glDeleteShader") \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures, "glDeleteTextures") \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, "glDeleteVertexArrays") \
    X(PFNGLDEPTHFUNCPROC, DepthFunc, "glDepthFunc") \
    X(PFNGLDEPTHMASKPROC, DepthMask, "glDepthMask") \
    X(PFNGLDISABLEPROC, Disable, "glDisable") \
    X(PFNGLDRAWELEMENTSPROC, DrawElements, "glDrawElements") \
    X(PFNGLENABLEPROC, Enable, "glEnable") \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, "glEnableVertexAttribArray") \
    X(PFNGLFINISHPROC, Finish, "glFinish") \
    X(PFNGLGENBUFFERSPROC, GenBuffers, "glGenBuffers") \
    X(PFNGLGENTEXTURESPROC, GenTextures, "glGenTextures") \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, "glGenVertexArrays") \
    X(PFNGLGETERRORPROC, GetError, "glGetError") \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv, "glGetProgramiv") \
    X(PFNGLGETSHADERIVPROC, GetShaderiv, "glGetShaderiv") \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, "glGetUniformLocation") \
    X(PFNGLLINKPROGRAMPROC, LinkProgram, "glLinkProgram") \
    X(PFNGLPIXELSTOREIPROC, PixelStorei, "glPixelStorei") \
    X(PFNGLREADPIXELSPROC, ReadPixels, "glReadPixels") \
    X(PFNGLSCISSORPROC, Scissor, "glScissor") \
    X(PFNGLSHADERSOURCEPROC, ShaderSource, "glShaderSource") \
    X(PFNGLSTENCILFUNCPROC, StencilFunc, "glStencilFunc") \
    X(PFNGLSTENCILMASKPROC, StencilMask, "glStencilMask") \
    X(PFNGLSTENCILOPPROC, StencilOp, "glStencilOp") \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D, "glTexImage2D") \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri, "glTexParameteri") \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D, "glTexSubImage2D") \
    X(PFNGLUNIFORM1FPROC, Uniform1f, "glUniform1f") \
    X(PFNGLUNIFORM1IPROC, Uniform1i, "glUniform1i") \
    X(PFNGLUNIFORM3FPROC, Uniform3f, "glUniform3f") \
    X(PFNGLUNIFORM4FPROC, Uniform4f, "glUniform4f") \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv, "glUniform4fv") \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv, "glUniformMatrix3fv") \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv, "glUniformMatrix4fv") \
    X(PFNGLUSEPROGRAMPROC, UseProgram, "glUseProgram") \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, "glVertexAttribPointer") \
    X(PFNGLVIEWPORTPROC, Viewport, "glViewport")

typedef struct hol_gl {
#define HOL__GL_FIELD(type, name, str) type name;
    HOL_GL_FUNCS(HOL__GL_FIELD)
#undef HOL__GL_FIELD
} hol_gl;

hol_err hol_gl_load(hol_gl *gl, hol_gl_getproc getproc);

#endif
