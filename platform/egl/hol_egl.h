/* hol_egl.h - headless GLES 3 context through EGL (platform code).
 *
 * Contract
 * - Header-only (static inline), like platform/osmesa/hol_osmesa.h. Uses
 *   Mesa's surfaceless platform (EGL_MESA_platform_surfaceless): no display,
 *   no window. It makes an OpenGL ES 3.0+ context current and binds a
 *   framebuffer object of w x h with RGBA8 colour and a 24/8 depth-stencil
 *   renderbuffer, which the renderer then draws into and reads back from.
 * - Every GL call here goes through eglGetProcAddress, so the binary may
 *   also link OSMesa (whose gl* symbols would otherwise win).
 * - hol_egl_create returns nonzero with a one-line reason in err on failure
 *   (no EGL vendor, no surfaceless platform, no ES 3 context, incomplete
 *   framebuffer); hol_egl_destroy releases everything.
 */
#ifndef HOL_EGL_H
#define HOL_EGL_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>

typedef struct hol_egl {
    EGLDisplay dpy;
    EGLContext ctx;
    unsigned int fbo, rb[2];
    int w, h;
} hol_egl;

typedef void (*hol_egl_proc)(void);

static inline hol_egl_proc hol_egl_getproc(const char *name)
{
    return (hol_egl_proc)eglGetProcAddress(name);
}

static inline void hol_egl_destroy(hol_egl *e)
{
    if (e->dpy == EGL_NO_DISPLAY)
        return;
    if (e->ctx != EGL_NO_CONTEXT) {
        typedef void (*del_fn)(int, const unsigned int *);
        del_fn del_fb = (del_fn)eglGetProcAddress("glDeleteFramebuffers");
        del_fn del_rb = (del_fn)eglGetProcAddress("glDeleteRenderbuffers");
        if (e->fbo && del_fb)
            del_fb(1, &e->fbo);
        if (e->rb[0] && del_rb)
            del_rb(2, e->rb);
        eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(e->dpy, e->ctx);
    }
    eglTerminate(e->dpy);
    e->dpy = EGL_NO_DISPLAY;
    e->ctx = EGL_NO_CONTEXT;
}

static inline int hol_egl_create(hol_egl *e, int w, int h, char *err, size_t err_cap)
{
    typedef void (*gen_fn)(int, unsigned int *);
    typedef void (*bind_fn)(unsigned int, unsigned int);
    typedef void (*storage_fn)(unsigned int, unsigned int, int, int);
    typedef void (*attach_fn)(unsigned int, unsigned int, unsigned int, unsigned int);
    typedef unsigned int (*check_fn)(unsigned int);
    e->dpy = EGL_NO_DISPLAY;
    e->ctx = EGL_NO_CONTEXT;
    e->fbo = e->rb[0] = e->rb[1] = 0;
    e->w = w;
    e->h = h;
    PFNEGLGETPLATFORMDISPLAYEXTPROC gpd =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!gpd) {
        snprintf(err, err_cap, "EGL has no eglGetPlatformDisplayEXT");
        return 1;
    }
    e->dpy = gpd(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    EGLint maj, min;
    if (e->dpy == EGL_NO_DISPLAY || !eglInitialize(e->dpy, &maj, &min)) {
        snprintf(err, err_cap, "cannot initialise an EGL surfaceless display");
        e->dpy = EGL_NO_DISPLAY;
        return 1;
    }
    static const EGLint cattr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                                   EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig cfg = NULL;
    EGLint n = 0;
    if (!eglChooseConfig(e->dpy, cattr, &cfg, 1, &n) || n < 1)
        cfg = NULL; /* EGL_KHR_no_config_context */
    eglBindAPI(EGL_OPENGL_ES_API);
    static const EGLint xattr[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                   EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    e->ctx = eglCreateContext(e->dpy, cfg, EGL_NO_CONTEXT, xattr);
    if (e->ctx == EGL_NO_CONTEXT ||
        !eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx)) {
        snprintf(err, err_cap, "cannot create an OpenGL ES 3 context through EGL");
        if (e->ctx != EGL_NO_CONTEXT)
            eglDestroyContext(e->dpy, e->ctx);
        eglTerminate(e->dpy);
        e->ctx = EGL_NO_CONTEXT;
        e->dpy = EGL_NO_DISPLAY;
        return 1;
    }
    gen_fn gen_fb = (gen_fn)eglGetProcAddress("glGenFramebuffers");
    bind_fn bind_fb = (bind_fn)eglGetProcAddress("glBindFramebuffer");
    gen_fn gen_rb = (gen_fn)eglGetProcAddress("glGenRenderbuffers");
    bind_fn bind_rb = (bind_fn)eglGetProcAddress("glBindRenderbuffer");
    storage_fn storage = (storage_fn)eglGetProcAddress("glRenderbufferStorage");
    attach_fn attach = (attach_fn)eglGetProcAddress("glFramebufferRenderbuffer");
    check_fn check = (check_fn)eglGetProcAddress("glCheckFramebufferStatus");
    if (!gen_fb || !bind_fb || !gen_rb || !bind_rb || !storage || !attach || !check) {
        snprintf(err, err_cap, "EGL context lacks framebuffer objects");
        hol_egl_destroy(e);
        return 1;
    }
    /* GLES 3.0 enums, spelled out to keep GL headers out of this file */
    const unsigned int FRAMEBUFFER = 0x8D40, RENDERBUFFER = 0x8D41, RGBA8 = 0x8058,
                       DEPTH24_STENCIL8 = 0x88F0, COLOR0 = 0x8CE0,
                       DEPTH_STENCIL_ATT = 0x821A, COMPLETE = 0x8CD5;
    gen_fb(1, &e->fbo);
    bind_fb(FRAMEBUFFER, e->fbo);
    gen_rb(2, e->rb);
    bind_rb(RENDERBUFFER, e->rb[0]);
    storage(RENDERBUFFER, RGBA8, w, h);
    attach(FRAMEBUFFER, COLOR0, RENDERBUFFER, e->rb[0]);
    bind_rb(RENDERBUFFER, e->rb[1]);
    storage(RENDERBUFFER, DEPTH24_STENCIL8, w, h);
    attach(FRAMEBUFFER, DEPTH_STENCIL_ATT, RENDERBUFFER, e->rb[1]);
    if (check(FRAMEBUFFER) != COMPLETE) {
        snprintf(err, err_cap, "the %d x %d framebuffer object is incomplete", w, h);
        hol_egl_destroy(e);
        return 1;
    }
    return 0;
}

#endif
