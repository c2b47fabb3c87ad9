/* gl_sync_count.c - a test helper (LD_PRELOAD): counts the GL calls that
 * wait for the GPU (glGetError, glFinish, glReadPixels and every glGet*)
 * that a program makes through eglGetProcAddress, the loader the desktop
 * build's renderer takes every GL entry point from (render/hol_gl.h: no
 * gl* symbol is linked). At exit it writes "NAME COUNT" lines, one per
 * function called, and "total N" to the file $HOL_GL_SYNC_OUT.
 * $HOL_GL_SYNC_AFTER=N counts only from the Nth eglSwapBuffers on (the
 * frames after the first N: init and the first frame's checks excluded).
 * tests/cli_gl_sync.sh runs `holonomy play --frames` under it.
 */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <GLES3/gl3.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void (*proc)(void);

enum { K_ERROR, K_FINISH, K_READ, K_INTV, K_FLOATV, K_BOOLV, K_STRING, K_PROGIV, K_SHADERIV,
       K_UNIFORM, K_ATTRIB, K_PROGLOG, K_SHADERLOG, K_OTHER, K_COUNT };
static const char *names[K_COUNT] = {"glGetError", "glFinish", "glReadPixels", "glGetIntegerv",
    "glGetFloatv", "glGetBooleanv", "glGetString", "glGetProgramiv", "glGetShaderiv",
    "glGetUniformLocation", "glGetAttribLocation", "glGetProgramInfoLog",
    "glGetShaderInfoLog", "glGet* (unwrapped)"};
static long counts[K_COUNT];
static proc real[K_COUNT];
static long swaps, after;

#define HIT(k) do { if (swaps >= after) counts[k]++; } while (0)

static GLenum w_error(void) { HIT(K_ERROR); return ((PFNGLGETERRORPROC)real[K_ERROR])(); }
static void w_finish(void) { HIT(K_FINISH); ((PFNGLFINISHPROC)real[K_FINISH])(); }
static void w_read(GLint x, GLint y, GLsizei w, GLsizei h, GLenum f, GLenum t, void *p)
{ HIT(K_READ); ((PFNGLREADPIXELSPROC)real[K_READ])(x, y, w, h, f, t, p); }
static void w_intv(GLenum e, GLint *v) { HIT(K_INTV); ((PFNGLGETINTEGERVPROC)real[K_INTV])(e, v); }
static void w_floatv(GLenum e, GLfloat *v) { HIT(K_FLOATV); ((PFNGLGETFLOATVPROC)real[K_FLOATV])(e, v); }
static void w_boolv(GLenum e, GLboolean *v) { HIT(K_BOOLV); ((PFNGLGETBOOLEANVPROC)real[K_BOOLV])(e, v); }
static const GLubyte *w_string(GLenum e) { HIT(K_STRING); return ((PFNGLGETSTRINGPROC)real[K_STRING])(e); }
static void w_progiv(GLuint p, GLenum e, GLint *v) { HIT(K_PROGIV); ((PFNGLGETPROGRAMIVPROC)real[K_PROGIV])(p, e, v); }
static void w_shaderiv(GLuint s, GLenum e, GLint *v) { HIT(K_SHADERIV); ((PFNGLGETSHADERIVPROC)real[K_SHADERIV])(s, e, v); }
static GLint w_uniform(GLuint p, const GLchar *n) { HIT(K_UNIFORM); return ((PFNGLGETUNIFORMLOCATIONPROC)real[K_UNIFORM])(p, n); }
static GLint w_attrib(GLuint p, const GLchar *n) { HIT(K_ATTRIB); return ((PFNGLGETATTRIBLOCATIONPROC)real[K_ATTRIB])(p, n); }
static void w_proglog(GLuint p, GLsizei b, GLsizei *l, GLchar *s)
{ HIT(K_PROGLOG); ((PFNGLGETPROGRAMINFOLOGPROC)real[K_PROGLOG])(p, b, l, s); }
static void w_shaderlog(GLuint p, GLsizei b, GLsizei *l, GLchar *s)
{ HIT(K_SHADERLOG); ((PFNGLGETSHADERINFOLOGPROC)real[K_SHADERLOG])(p, b, l, s); }

static const proc wrap[K_COUNT] = {(proc)w_error, (proc)w_finish, (proc)w_read, (proc)w_intv,
    (proc)w_floatv, (proc)w_boolv, (proc)w_string, (proc)w_progiv, (proc)w_shaderiv,
    (proc)w_uniform, (proc)w_attrib, (proc)w_proglog, (proc)w_shaderlog, NULL};

__eglMustCastToProperFunctionPointerType eglGetProcAddress(const char *name)
{
    typedef __eglMustCastToProperFunctionPointerType (*gpa_fn)(const char *);
    static gpa_fn next;
    if (!next)
        next = (gpa_fn)dlsym(RTLD_NEXT, "eglGetProcAddress");
    __eglMustCastToProperFunctionPointerType f = next ? next(name) : NULL;
    if (!f || !name)
        return f;
    for (int k = 0; k < K_OTHER; k++)
        if (!strcmp(name, names[k])) {
            real[k] = (proc)f;
            return (__eglMustCastToProperFunctionPointerType)wrap[k];
        }
    if (!strncmp(name, "glGet", 5))
        counts[K_OTHER]++; /* a glGet* this helper cannot count: told as such */
    return f;
}

EGLBoolean eglSwapBuffers(EGLDisplay dpy, EGLSurface surf)
{
    typedef EGLBoolean (*swap_fn)(EGLDisplay, EGLSurface);
    static swap_fn next;
    if (!next)
        next = (swap_fn)dlsym(RTLD_NEXT, "eglSwapBuffers");
    swaps++;
    return next ? next(dpy, surf) : EGL_FALSE;
}

__attribute__((constructor)) static void start(void)
{
    const char *a = getenv("HOL_GL_SYNC_AFTER");
    after = a ? atol(a) : 0;
}

__attribute__((destructor)) static void report(void)
{
    const char *out = getenv("HOL_GL_SYNC_OUT");
    FILE *f = out ? fopen(out, "w") : NULL;
    if (!f)
        return;
    long total = 0;
    for (int k = 0; k < K_COUNT; k++) {
        if (counts[k])
            fprintf(f, "%s %ld\n", names[k], counts[k]);
        total += k == K_OTHER ? 0 : counts[k];
    }
    fprintf(f, "swaps %ld\ntotal %ld\n", swaps, total);
    fclose(f);
}
