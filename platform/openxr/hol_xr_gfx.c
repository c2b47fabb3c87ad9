/* hol_xr_gfx.c - the headset's GL context and its OpenXR graphics binding
 * (GLX on Linux, EGL on Android; see hol_xr_state.h). */
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- graphics: the GL context and its binding ---------------------------- */

/* The runtime's requirements for the GL (gl: "OpenGL" or "OpenGL ES"),
 * read through the extension's function fn (the runtime must be asked
 * before the session is made): 0, or 1 reported. */
static int hol__gl_requirements(hol__xr *x, const char *gl, const char *fn, void *req)
{
    typedef XrResult (*req_fn)(XrInstance, XrSystemId, void *);
    PFN_xrVoidFunction f = NULL;
    char doing[64];
    snprintf(doing, sizeof doing, "find the runtime's %s support", gl);
    HOL__XR(x, doing, xrGetInstanceProcAddr(x->instance, fn, &f));
    snprintf(doing, sizeof doing, "read the runtime's %s requirements", gl);
    HOL__XR(x, doing, ((req_fn)(void (*)(void))f)(x->instance, x->system, req));
    return 0;
}

#ifdef __ANDROID__
int hol__xr_graphics(hol__xr *x, hol__binding *b)
{
    XrGraphicsRequirementsOpenGLESKHR req = {XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_ES_KHR};
    if (hol__gl_requirements(x, "OpenGL ES", "xrGetOpenGLESGraphicsRequirementsKHR", &req))
        return 1;
    x->edpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (!eglInitialize(x->edpy, NULL, NULL))
        return hol__xr_error(x, "cannot initialise EGL (error 0x%x)", (unsigned)eglGetError());
    const EGLint attr[] = {EGL_RENDERABLE_TYPE, 0x40 /* EGL_OPENGL_ES3_BIT */, EGL_SURFACE_TYPE,
                           EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                           EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(x->edpy, attr, &cfg, 1, &n) || n < 1)
        return hol__xr_error(x, "EGL has no OpenGL ES 3 configuration with depth and stencil");
    const EGLint cattr[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
    x->ectx = eglCreateContext(x->edpy, cfg, EGL_NO_CONTEXT, cattr);
    const EGLint sattr[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    x->esurf = eglCreatePbufferSurface(x->edpy, cfg, sattr);
    if (x->ectx == EGL_NO_CONTEXT || !eglMakeCurrent(x->edpy, x->esurf, x->esurf, x->ectx))
        return hol__xr_error(x, "cannot make an OpenGL ES 3 context current (EGL error 0x%x)",
                             (unsigned)eglGetError());
    x->getproc = (hol_render_getproc)eglGetProcAddress;
    b->type = XR_TYPE_GRAPHICS_BINDING_OPENGL_ES_ANDROID_KHR;
    b->next = NULL;
    b->display = x->edpy;
    b->config = cfg;
    b->context = x->ectx;
    return 0;
}
#else
typedef GLXContext (*hol__create_ctx_fn)(Display *, GLXFBConfig, GLXContext, Bool, const int *);

int hol__xr_graphics(hol__xr *x, hol__binding *b)
{
    XrGraphicsRequirementsOpenGLKHR req = {XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
    if (hol__gl_requirements(x, "OpenGL", "xrGetOpenGLGraphicsRequirementsKHR", &req))
        return 1;
    x->dpy = XOpenDisplay(NULL);
    if (!x->dpy) {
        return hol__xr_error(x, "cannot open the X display (DISPLAY=%s)",
                             getenv("DISPLAY") ? getenv("DISPLAY") : "");
    }
    const int attr[] = {GLX_X_RENDERABLE, True, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT,
                        GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                        GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8, GLX_DEPTH_SIZE, 24,
                        GLX_STENCIL_SIZE, 8, GLX_DOUBLEBUFFER, True, None};
    int n = 0;
    GLXFBConfig *cfgs = glXChooseFBConfig(x->dpy, DefaultScreen(x->dpy), attr, &n);
    if (!cfgs || n < 1) {
        return hol__xr_error(x, "no GLX frame buffer configuration with depth and stencil");
    }
    x->cfg = cfgs[0];
    XFree(cfgs);
    XVisualInfo *vi = glXGetVisualFromFBConfig(x->dpy, x->cfg);
    if (!vi) {
        return hol__xr_error(x, "no X visual for the GLX configuration");
    }
    XSetWindowAttributes swa;
    memset(&swa, 0, sizeof swa);
    x->cmap = XCreateColormap(x->dpy, RootWindow(x->dpy, vi->screen), vi->visual, AllocNone);
    swa.colormap = x->cmap;
    x->win = XCreateWindow(x->dpy, RootWindow(x->dpy, vi->screen), 0, 0, 16, 16, 0, vi->depth,
                           InputOutput, vi->visual, CWColormap, &swa);
    VisualID visualid = vi->visualid;
    XFree(vi);
    hol__create_ctx_fn create = (hol__create_ctx_fn)glXGetProcAddressARB(
        (const GLubyte *)"glXCreateContextAttribsARB");
    if (!create) {
        return hol__xr_error(x, "GLX has no glXCreateContextAttribsARB");
    }
    /* a core context at the runtime's minimum or 4.5, whichever is higher */
    int major = (int)XR_VERSION_MAJOR(req.minApiVersionSupported);
    int minor = (int)XR_VERSION_MINOR(req.minApiVersionSupported);
    if (major < 4 || (major == 4 && minor < 5))
        major = 4, minor = 5;
    const int cattr[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, major, GLX_CONTEXT_MINOR_VERSION_ARB,
                         minor, GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB,
                         None};
    x->ctx = create(x->dpy, x->cfg, NULL, True, cattr);
    if (!x->ctx || !glXMakeCurrent(x->dpy, x->win, x->ctx)) {
        return hol__xr_error(x, "cannot make a GL %d.%d core context current", major, minor);
    }
    x->getproc = (hol_render_getproc)glXGetProcAddressARB;
    b->type = XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR;
    b->next = NULL;
    b->xDisplay = x->dpy;
    b->visualid = (uint32_t)visualid;
    b->glxFBConfig = x->cfg;
    b->glxDrawable = x->win;
    b->glxContext = x->ctx;
    return 0;
}
#endif

int hol__xr_load_gl(hol__xr *x)
{
#define HOL__LOAD(f)                                                                          \
    do {                                                                                      \
        hol_render_proc p = x->getproc("gl" #f);                                              \
        if (!p) {                                                                             \
            return hol__xr_error(x, "GL has no gl%s", #f);                                       \
        }                                                                                     \
        memcpy(&x->gl.f, &p, sizeof p);                                                       \
    } while (0)
    HOL__LOAD(GenFramebuffers);
    HOL__LOAD(BindFramebuffer);
    HOL__LOAD(FramebufferTexture2D);
    HOL__LOAD(GenRenderbuffers);
    HOL__LOAD(BindRenderbuffer);
    HOL__LOAD(RenderbufferStorage);
    HOL__LOAD(FramebufferRenderbuffer);
    HOL__LOAD(CheckFramebufferStatus);
    HOL__LOAD(DeleteFramebuffers);
    HOL__LOAD(DeleteRenderbuffers);
    HOL__LOAD(Viewport);
    HOL__LOAD(Enable);
    HOL__LOAD(Disable);
    HOL__LOAD(RenderbufferStorageMultisample);
    HOL__LOAD(BlitFramebuffer);
#undef HOL__LOAD
    return 0;
}

