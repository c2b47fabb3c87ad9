/* hol_xr.c - the OpenXR session (see hol_xr.h). */
#define _GNU_SOURCE
#include "hol_xr.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef __ANDROID__
#include <EGL/egl.h>
#include <jni.h>
#define XR_USE_PLATFORM_ANDROID
#define XR_USE_GRAPHICS_API_OPENGL_ES
#else
#include <X11/Xlib.h>
#include <GL/glx.h>
#include <sys/wait.h>
#include <unistd.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include "../image/hol_png_file.h"
#include "../osmesa/hol_osmesa.h"
#endif
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "../../core/hol_motion.h"
#include "../../render/hol_app_frame.h"
#include "../../render/hol_render.h"
#include "hol_xr_bind.h"
#include "hol_xr_room.h"

/* GL entry points this layer calls itself (the renderer loads its own) */
typedef unsigned int hol__GLenum;
typedef unsigned int hol__GLuint;
typedef int hol__GLint;
typedef int hol__GLsizei;
#define HOL__GL_FRAMEBUFFER 0x8D40
#define HOL__GL_RENDERBUFFER 0x8D41
#define HOL__GL_COLOR_ATTACHMENT0 0x8CE0
#define HOL__GL_DEPTH_STENCIL_ATTACHMENT 0x821A
#define HOL__GL_DEPTH24_STENCIL8 0x88F0
#define HOL__GL_TEXTURE_2D 0x0DE1
#define HOL__GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define HOL__GL_RGBA8 0x8058
#define HOL__GL_SRGB8_ALPHA8 0x8C43
#define HOL__GL_COLOR_BUFFER_BIT 0x4000
#define HOL__GL_DEPTH_BUFFER_BIT 0x0100
#define HOL__GL_STENCIL_BUFFER_BIT 0x0400

typedef struct hol__gl {
    void (*GenFramebuffers)(hol__GLsizei, hol__GLuint *);
    void (*BindFramebuffer)(hol__GLenum, hol__GLuint);
    void (*FramebufferTexture2D)(hol__GLenum, hol__GLenum, hol__GLenum, hol__GLuint, hol__GLint);
    void (*GenRenderbuffers)(hol__GLsizei, hol__GLuint *);
    void (*BindRenderbuffer)(hol__GLenum, hol__GLuint);
    void (*RenderbufferStorage)(hol__GLenum, hol__GLenum, hol__GLsizei, hol__GLsizei);
    void (*FramebufferRenderbuffer)(hol__GLenum, hol__GLenum, hol__GLenum, hol__GLuint);
    hol__GLenum (*CheckFramebufferStatus)(hol__GLenum);
    void (*DeleteFramebuffers)(hol__GLsizei, const hol__GLuint *);
    void (*DeleteRenderbuffers)(hol__GLsizei, const hol__GLuint *);
    void (*Viewport)(hol__GLint, hol__GLint, hol__GLsizei, hol__GLsizei);
    void (*ClearColor)(float, float, float, float);
    void (*Clear)(unsigned int);
    void (*Finish)(void);
} hol__gl;

#define HOL__MAX_IMAGES 8
/* metres the app's head keeps from the hedges: the motion's default margin
 * (hol_motion_desc), where the safety fade begins */
#define HOL__MARGIN 0.15

typedef struct hol__eye {
    XrSwapchain swapchain;
    int32_t w, h;
    uint32_t nimages;
    hol__GLuint fbo[HOL__MAX_IMAGES], depth;
#ifdef __ANDROID__
    XrSwapchainImageOpenGLESKHR images[HOL__MAX_IMAGES];
#else
    XrSwapchainImageOpenGLKHR images[HOL__MAX_IMAGES];
#endif
} hol__eye;

typedef struct hol__xr {
    const hol_xr_desc *d;
    const hol_xr_app_fns *fns;
    XrInstance instance;
    XrSystemId system;
    XrSession session;
    XrSpace stage, view_space, grip[2];
    XrActionSet set;
    XrAction grip_action, act[HOL_XR_ACT_COUNT];
    XrPath hand_path[2];
    hol__eye eye[2];
    int state, running, focused, quit_requested, done, reached_focused;
    int is_stage;
    hol_xr_calib calib;
    hol__gl gl;
    hol_render *rnd;
    hol_render_getproc getproc;
    long submitted;
    XrTime t0;
    double last_t;
    unsigned prev_buttons;
    int grips_located[2];
    long faded; /* frames drawn with the safety fade */
    int bounds_small;
    double cpu_ms[4096], step_ms[4096];
    long ncpu;
    double step_now;
    long draws[2], tris[2];
#ifdef __ANDROID__
    EGLDisplay edpy;
    EGLContext ectx;
    EGLSurface esurf;
#else
    Display *dpy;
    Window win;
    GLXContext ctx;
    GLXFBConfig cfg;
    Colormap cmap;
#endif
} hol__xr;

static int hol__fail(hol__xr *x, const char *what, XrResult r)
{
    char name[XR_MAX_RESULT_STRING_SIZE] = "";
    if (x->instance != XR_NULL_HANDLE)
        xrResultToString(x->instance, r, name);
    fprintf(stderr, "holonomy xr: %s failed: %s (%d)\n", what, name[0] ? name : "?", (int)r);
    return 1;
}

#define HOL__XR(x, call)                                                                      \
    do {                                                                                      \
        XrResult hol__r = (call);                                                             \
        if (XR_FAILED(hol__r))                                                                \
            return hol__fail((x), #call, hol__r);                                             \
    } while (0)

static double hol__thread_cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static const char *hol__state_name(int s)
{
    static const char *const n[] = {"UNKNOWN", "IDLE", "READY", "SYNCHRONIZED", "VISIBLE",
                                    "FOCUSED", "STOPPING", "LOSS_PENDING", "EXITING"};
    return s >= 0 && s <= 8 ? n[s] : "?";
}

/* ---- graphics: the GL context and its binding ---------------------------- */

#ifdef __ANDROID__
static int hol__graphics(hol__xr *x, XrGraphicsBindingOpenGLESAndroidKHR *b)
{
    PFN_xrGetOpenGLESGraphicsRequirementsKHR req_fn = NULL;
    HOL__XR(x, xrGetInstanceProcAddr(x->instance, "xrGetOpenGLESGraphicsRequirementsKHR",
                                     (PFN_xrVoidFunction *)&req_fn));
    XrGraphicsRequirementsOpenGLESKHR req = {XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_ES_KHR};
    HOL__XR(x, req_fn(x->instance, x->system, &req));
    x->edpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (!eglInitialize(x->edpy, NULL, NULL))
        return hol__fail(x, "eglInitialize", XR_ERROR_RUNTIME_FAILURE);
    const EGLint attr[] = {EGL_RENDERABLE_TYPE, 0x40 /* EGL_OPENGL_ES3_BIT */, EGL_SURFACE_TYPE,
                           EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                           EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(x->edpy, attr, &cfg, 1, &n) || n < 1)
        return hol__fail(x, "eglChooseConfig", XR_ERROR_RUNTIME_FAILURE);
    const EGLint cattr[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
    x->ectx = eglCreateContext(x->edpy, cfg, EGL_NO_CONTEXT, cattr);
    const EGLint sattr[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    x->esurf = eglCreatePbufferSurface(x->edpy, cfg, sattr);
    if (x->ectx == EGL_NO_CONTEXT || !eglMakeCurrent(x->edpy, x->esurf, x->esurf, x->ectx))
        return hol__fail(x, "eglMakeCurrent", XR_ERROR_RUNTIME_FAILURE);
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

static int hol__graphics(hol__xr *x, XrGraphicsBindingOpenGLXlibKHR *b)
{
    PFN_xrGetOpenGLGraphicsRequirementsKHR req_fn = NULL;
    HOL__XR(x, xrGetInstanceProcAddr(x->instance, "xrGetOpenGLGraphicsRequirementsKHR",
                                     (PFN_xrVoidFunction *)&req_fn));
    XrGraphicsRequirementsOpenGLKHR req = {XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
    HOL__XR(x, req_fn(x->instance, x->system, &req));
    x->dpy = XOpenDisplay(NULL);
    if (!x->dpy) {
        fprintf(stderr, "holonomy xr: cannot open the X display (DISPLAY=%s)\n",
                getenv("DISPLAY") ? getenv("DISPLAY") : "");
        return 1;
    }
    const int attr[] = {GLX_X_RENDERABLE, True, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT,
                        GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                        GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8, GLX_DEPTH_SIZE, 24,
                        GLX_STENCIL_SIZE, 8, GLX_DOUBLEBUFFER, True, None};
    int n = 0;
    GLXFBConfig *cfgs = glXChooseFBConfig(x->dpy, DefaultScreen(x->dpy), attr, &n);
    if (!cfgs || n < 1) {
        fprintf(stderr, "holonomy xr: no GLX frame buffer configuration with depth and stencil\n");
        return 1;
    }
    x->cfg = cfgs[0];
    XFree(cfgs);
    XVisualInfo *vi = glXGetVisualFromFBConfig(x->dpy, x->cfg);
    if (!vi) {
        fprintf(stderr, "holonomy xr: no X visual for the GLX configuration\n");
        return 1;
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
        fprintf(stderr, "holonomy xr: GLX has no glXCreateContextAttribsARB\n");
        return 1;
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
        fprintf(stderr, "holonomy xr: cannot make a GL %d.%d core context current\n", major,
                minor);
        return 1;
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

static int hol__load_gl(hol__xr *x)
{
#define HOL__LOAD(f)                                                                          \
    do {                                                                                      \
        hol_render_proc p = x->getproc("gl" #f);                                              \
        if (!p) {                                                                             \
            fprintf(stderr, "holonomy xr: GL has no gl%s\n", #f);                             \
            return 1;                                                                         \
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
    HOL__LOAD(ClearColor);
    HOL__LOAD(Clear);
    HOL__LOAD(Finish);
#undef HOL__LOAD
    return 0;
}

/* ---- actions -------------------------------------------------------------- */

static XrPath hol__path(hol__xr *x, const char *s)
{
    XrPath p = XR_NULL_PATH;
    xrStringToPath(x->instance, s, &p);
    return p;
}

static int hol__action(hol__xr *x, XrAction *out, const char *name, const char *local,
                       XrActionType type, int hands)
{
    XrActionCreateInfo ai = {XR_TYPE_ACTION_CREATE_INFO};
    snprintf(ai.actionName, sizeof ai.actionName, "%s", name);
    snprintf(ai.localizedActionName, sizeof ai.localizedActionName, "%s", local);
    ai.actionType = type;
    if (hands) {
        ai.countSubactionPaths = 2;
        ai.subactionPaths = x->hand_path;
    }
    HOL__XR(x, xrCreateAction(x->set, &ai, out));
    return 0;
}

static int hol__actions(hol__xr *x)
{
    XrActionSetCreateInfo si = {XR_TYPE_ACTION_SET_CREATE_INFO};
    snprintf(si.actionSetName, sizeof si.actionSetName, "game");
    snprintf(si.localizedActionSetName, sizeof si.localizedActionSetName, "Game");
    HOL__XR(x, xrCreateActionSet(x->instance, &si, &x->set));
    x->hand_path[0] = hol__path(x, "/user/hand/left");
    x->hand_path[1] = hol__path(x, "/user/hand/right");
    if (hol__action(x, &x->grip_action, "grip", "Hand pose", XR_ACTION_TYPE_POSE_INPUT, 1))
        return 1;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        if (hol__action(x, &x->act[a], hol_xr_action_name(a), hol_xr_action_label(a),
                        XR_ACTION_TYPE_BOOLEAN_INPUT, 0))
            return 1;
    /* the suggested bindings (hol_xr_bind.h): every one must be accepted */
    const hol_xr_profile *binds = hol_xr_profiles();
    for (int i = 0; i < HOL_XR_NPROFILES; i++) {
        XrActionSuggestedBinding sb[HOL_XR_ACT_COUNT + 2];
        uint32_t n = 0;
        for (int h = 0; h < 2; h++) {
            sb[n].action = x->grip_action;
            sb[n++].binding = hol__path(x, hol_xr_grip_path(h));
        }
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
            sb[n].action = x->act[a];
            sb[n++].binding = hol__path(x, binds[i].path[a]);
        }
        XrInteractionProfileSuggestedBinding ps = {
            XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        ps.interactionProfile = hol__path(x, binds[i].profile);
        ps.countSuggestedBindings = n;
        ps.suggestedBindings = sb;
        XrResult r = xrSuggestInteractionProfileBindings(x->instance, &ps);
        if (XR_FAILED(r))
            return hol__fail(x, binds[i].profile, r);
        printf("xr: bindings accepted %s\n", binds[i].profile + 22);
    }
    return 0;
}

static int hol__spaces(hol__xr *x)
{
    XrSessionActionSetsAttachInfo at = {XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    at.countActionSets = 1;
    at.actionSets = &x->set;
    HOL__XR(x, xrAttachSessionActionSets(x->session, &at));
    for (int h = 0; h < 2; h++) {
        XrActionSpaceCreateInfo ai = {XR_TYPE_ACTION_SPACE_CREATE_INFO};
        ai.action = x->grip_action;
        ai.subactionPath = x->hand_path[h];
        ai.poseInActionSpace.orientation.w = 1;
        HOL__XR(x, xrCreateActionSpace(x->session, &ai, &x->grip[h]));
    }
    uint32_t n = 0;
    XrReferenceSpaceType types[16];
    HOL__XR(x, xrEnumerateReferenceSpaces(x->session, 16, &n, types));
    x->is_stage = 0;
    for (uint32_t i = 0; i < n; i++)
        x->is_stage |= types[i] == XR_REFERENCE_SPACE_TYPE_STAGE;
    XrReferenceSpaceCreateInfo ri = {XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    ri.referenceSpaceType = x->is_stage ? XR_REFERENCE_SPACE_TYPE_STAGE
                                        : XR_REFERENCE_SPACE_TYPE_LOCAL;
    ri.poseInReferenceSpace.orientation.w = 1;
    HOL__XR(x, xrCreateReferenceSpace(x->session, &ri, &x->stage));
    ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    HOL__XR(x, xrCreateReferenceSpace(x->session, &ri, &x->view_space));
    printf("xr: reference space %s\n", x->is_stage ? "STAGE" : "LOCAL");
    if (x->is_stage) {
        XrExtent2Df b = {0, 0};
        XrResult r = xrGetReferenceSpaceBoundsRect(x->session, XR_REFERENCE_SPACE_TYPE_STAGE, &b);
        if (r == XR_SUCCESS) {
            x->bounds_small = !hol_xr_bounds_hold_room(b.width, b.height);
            printf("xr: stage bounds %.2f x %.2f m%s\n", b.width, b.height,
                   x->bounds_small ? " (smaller than the 3 x 3 m room)" : "");
        } else {
            printf("xr: stage bounds not given by the runtime\n");
        }
    }
    return 0;
}

/* ---- swapchains ----------------------------------------------------------- */

static int hol__swapchains(hol__xr *x)
{
    XrViewConfigurationView vc[2] = {{XR_TYPE_VIEW_CONFIGURATION_VIEW},
                                     {XR_TYPE_VIEW_CONFIGURATION_VIEW}};
    uint32_t n = 0;
    HOL__XR(x, xrEnumerateViewConfigurationViews(x->instance, x->system,
                                                 XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2,
                                                 &n, vc));
    int64_t formats[64];
    uint32_t nf = 0;
    HOL__XR(x, xrEnumerateSwapchainFormats(x->session, 64, &nf, formats));
    int64_t fmt = nf ? formats[0] : HOL__GL_RGBA8;
    for (uint32_t i = 0; i < nf; i++)
        if (formats[i] == HOL__GL_RGBA8)
            fmt = formats[i]; /* the same bytes as the OSMesa reference */
    for (int e = 0; e < 2; e++) {
        hol__eye *ey = &x->eye[e];
        XrSwapchainCreateInfo ci = {XR_TYPE_SWAPCHAIN_CREATE_INFO};
        ci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
        ci.format = fmt;
        ci.sampleCount = 1;
        ci.width = vc[e].recommendedImageRectWidth;
        ci.height = vc[e].recommendedImageRectHeight;
        ci.faceCount = 1;
        ci.arraySize = 1;
        ci.mipCount = 1;
        HOL__XR(x, xrCreateSwapchain(x->session, &ci, &ey->swapchain));
        ey->w = (int32_t)ci.width;
        ey->h = (int32_t)ci.height;
        uint32_t ni = 0;
        for (int k = 0; k < HOL__MAX_IMAGES; k++) {
#ifdef __ANDROID__
            ey->images[k].type = XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_ES_KHR;
#else
            ey->images[k].type = XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR;
#endif
            ey->images[k].next = NULL;
        }
        HOL__XR(x, xrEnumerateSwapchainImages(ey->swapchain, HOL__MAX_IMAGES, &ni,
                                              (XrSwapchainImageBaseHeader *)ey->images));
        ey->nimages = ni;
        x->gl.GenRenderbuffers(1, &ey->depth);
        x->gl.BindRenderbuffer(HOL__GL_RENDERBUFFER, ey->depth);
        x->gl.RenderbufferStorage(HOL__GL_RENDERBUFFER, HOL__GL_DEPTH24_STENCIL8, ey->w, ey->h);
        x->gl.GenFramebuffers((hol__GLsizei)ni, ey->fbo);
        for (uint32_t k = 0; k < ni; k++) {
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->fbo[k]);
            x->gl.FramebufferTexture2D(HOL__GL_FRAMEBUFFER, HOL__GL_COLOR_ATTACHMENT0,
                                       HOL__GL_TEXTURE_2D, ey->images[k].image, 0);
            x->gl.FramebufferRenderbuffer(HOL__GL_FRAMEBUFFER, HOL__GL_DEPTH_STENCIL_ATTACHMENT,
                                          HOL__GL_RENDERBUFFER, ey->depth);
            if (x->gl.CheckFramebufferStatus(HOL__GL_FRAMEBUFFER) != HOL__GL_FRAMEBUFFER_COMPLETE) {
                fprintf(stderr, "holonomy xr: swapchain framebuffer incomplete\n");
                return 1;
            }
        }
        x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    }
    printf("xr: swapchains %dx%d per eye, format 0x%llx, %u images, two passes\n", x->eye[0].w,
           x->eye[0].h, (unsigned long long)fmt, x->eye[0].nimages);
    return 0;
}

/* ---- the frame ------------------------------------------------------------ */

static void hol__pose_in(const XrPosef *p, float pos[3], float quat[4])
{
    pos[0] = p->position.x;
    pos[1] = p->position.y;
    pos[2] = p->position.z;
    quat[0] = p->orientation.x;
    quat[1] = p->orientation.y;
    quat[2] = p->orientation.z;
    quat[3] = p->orientation.w;
}

static int hol__bool(hol__xr *x, int a)
{
    XrActionStateGetInfo gi = {XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = x->act[a];
    XrActionStateBoolean st = {XR_TYPE_ACTION_STATE_BOOLEAN};
    if (XR_FAILED(xrGetActionStateBoolean(x->session, &gi, &st)))
        return 0;
    return st.isActive && st.currentState;
}

#ifndef __ANDROID__
/* The OSMesa render of the same eye, in a child process (it must not share
 * this process's GLX state), against the swapchain's read back. */
static void hol__check(hol__xr *x, const hol_frame_desc *fd, int w, int h)
{
    size_t bytes = (size_t)w * (size_t)h * 4;
    uint8_t *got = malloc(bytes), *ref = malloc(bytes);
    if (!got || !ref) {
        free(got);
        free(ref);
        return;
    }
    hol_render_read_rgba(x->rnd, w, h, got);
    char path[600];
    snprintf(path, sizeof path, "%s/xr-eye0.png", x->d->check_dir);
    hol_png_write_file(path, got, w, h, 0);
    /* the same eye for `holonomy render` (the host's check in make xr-test) */
    const hol_camera *c = &fd->cam;
    printf("xr: check eye 0 render --eye %.9g,%.9g,%.9g --orient %.9g,%.9g,%.9g,%.9g "
           "--tan %.17g,%.17g,%.17g,%.17g --size %dx%d\n",
           c->eye[0], c->eye[1], c->eye[2], c->orient[0], c->orient[1], c->orient[2],
           c->orient[3], c->tan_left, c->tan_right, c->tan_down, c->tan_up, w, h);
    snprintf(path, sizeof path, "%s/osmesa-eye0.png", x->d->check_dir);
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        hol_osmesa o;
        char msg[256];
        hol_render *r = NULL;
        hol_render_desc rd;
        memset(&rd, 0, sizeof rd);
        rd.getproc = (hol_render_getproc)hol_osmesa_getproc;
        rd.world = x->fns->world(x->fns->user);
        if (hol_osmesa_create(&o, w, h, msg, sizeof msg) || hol_render_create(&rd, &r) ||
            hol_render_frame(r, fd, NULL))
            _exit(1);
        hol_render_read_rgba(r, w, h, ref);
        _exit(hol_png_write_file(path, ref, w, h, 0) ? 1 : 0);
    }
    int st = 1;
    if (pid > 0)
        waitpid(pid, &st, 0);
    uint8_t *ref2 = NULL;
    int rw = 0, rh = 0;
    if (pid < 0 || st != 0 || hol_png_read_file(path, &ref2, &rw, &rh) || rw != w || rh != h) {
        printf("xr: check: the OSMesa reference render failed\n");
    } else {
        long bad = 0;
        int worst = 0;
        for (size_t p = 0; p < (size_t)w * (size_t)h; p++) {
            int dmax = 0;
            for (int k = 0; k < 3; k++) {
                int dd = abs((int)got[4 * p + k] - (int)ref2[4 * p + k]);
                dmax = dd > dmax ? dd : dmax;
            }
            worst = dmax > worst ? dmax : worst;
            bad += dmax > 8;
        }
        printf("xr: check frame %ld eye 0 %dx%d: %ld pixels differ by more than 8/255 "
               "(%.3f %%), largest difference %d\n",
               x->d->check_frame, w, h, bad, 100.0 * (double)bad / ((double)w * h), worst);
    }
    free(ref2);
    free(got);
    free(ref);
}
#endif

static int hol__frame(hol__xr *x)
{
    XrFrameWaitInfo wi = {XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState fs = {XR_TYPE_FRAME_STATE};
    HOL__XR(x, xrWaitFrame(x->session, &wi, &fs));
    double c0 = hol__thread_cpu_ms();
    XrFrameBeginInfo bi = {XR_TYPE_FRAME_BEGIN_INFO};
    HOL__XR(x, xrBeginFrame(x->session, &bi));
    if (!x->t0)
        x->t0 = fs.predictedDisplayTime;
    XrViewLocateInfo li = {XR_TYPE_VIEW_LOCATE_INFO};
    li.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    li.displayTime = fs.predictedDisplayTime;
    li.space = x->stage;
    XrViewState vs = {XR_TYPE_VIEW_STATE};
    XrView views[2] = {{XR_TYPE_VIEW}, {XR_TYPE_VIEW}};
    uint32_t nv = 0;
    HOL__XR(x, xrLocateViews(x->session, &li, &vs, 2, &nv, views));
    int views_ok = nv == 2 && (vs.viewStateFlags & XR_VIEW_STATE_POSITION_VALID_BIT) &&
                   (vs.viewStateFlags & XR_VIEW_STATE_ORIENTATION_VALID_BIT);
    /* the input record */
    hol_input in;
    memset(&in, 0, sizeof in);
    double t = (double)(fs.predictedDisplayTime - x->t0) * 1e-9;
    in.time_s = t > x->last_t ? t : x->last_t;
    x->last_t = in.time_s;
    if (x->focused)
        in.flags |= HOL_INPUT_FOCUSED;
    if (x->bounds_small)
        in.flags |= HOL_INPUT_BOUNDS_SMALL;
    XrSpaceLocation loc = {XR_TYPE_SPACE_LOCATION};
    float hp[3] = {0, 1.6f, 0}, hq[4] = {0, 0, 0, 1};
    if (XR_SUCCEEDED(xrLocateSpace(x->view_space, x->stage, fs.predictedDisplayTime, &loc)) &&
        (loc.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) &&
        (loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT)) {
        hol__pose_in(&loc.pose, hp, hq);
        in.flags |= HOL_INPUT_HEAD_VALID;
    }
    if (x->focused) {
        XrActiveActionSet as = {x->set, XR_NULL_PATH};
        XrActionsSyncInfo sy = {XR_TYPE_ACTIONS_SYNC_INFO};
        sy.countActiveActionSets = 1;
        sy.activeActionSets = &as;
        HOL__XR(x, xrSyncActions(x->session, &sy));
        int held[HOL_XR_ACT_COUNT];
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
            held[a] = hol__bool(x, a);
        in.buttons |= hol_xr_buttons(held);
        for (int h = 0; h < 2; h++) {
            XrSpaceLocation gl = {XR_TYPE_SPACE_LOCATION};
            if (XR_SUCCEEDED(xrLocateSpace(x->grip[h], x->stage, fs.predictedDisplayTime, &gl)) &&
                (gl.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT)) {
                float gp[3], gq[4];
                hol__pose_in(&gl.pose, gp, gq);
                hol_xr_to_room(&x->calib, gp, gq, &in.hand[h]);
                in.flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
                if (!x->grips_located[h]++)
                    printf("xr: grip %s located\n", h ? "right" : "left");
            }
        }
    }
    if ((in.buttons & HOL_BTN_RECENTRE) && !(x->prev_buttons & HOL_BTN_RECENTRE) &&
        (in.flags & HOL_INPUT_HEAD_VALID))
        hol_xr_recentre(&x->calib, hp, hq);
    x->prev_buttons = in.buttons;
    hol_xr_to_room(&x->calib, hp, hq, &in.head);
    /* scripted head motion (the simulated headset does not move): the
     * recorded record's head pose, in room coordinates */
    float room_from_stage_shift[3] = {0, 0, 0};
    if (x->d->nscript > 0) {
        const hol_input *s = &x->d->script[x->submitted % x->d->nscript];
        if (s->flags & HOL_INPUT_HEAD_VALID) {
            for (int k = 0; k < 3; k++)
                room_from_stage_shift[k] = s->head.pos[k] - in.head.pos[k];
            in.head = s->head;
            in.flags |= HOL_INPUT_HEAD_VALID;
        }
        in.buttons |= s->buttons;
    }
    const hol_app_view *v = NULL;
    double s0 = hol__thread_cpu_ms();
    int st = x->fns->step(x->fns->user, &in, &v);
    x->step_now = hol__thread_cpu_ms() - s0;
    if (st < 0)
        return 1;
    if (x->fns->level_started(x->fns->user))
        hol_render_invalidate(x->rnd);
    if (st > 0 || (x->d->frames > 0 && x->submitted + 1 >= x->d->frames)) {
        if (!x->quit_requested) {
            HOL__XR(x, xrRequestExitSession(x->session));
            printf("xr: exit requested after %ld frames\n", x->submitted + 1);
            x->quit_requested = 1;
        }
    }
    /* render each eye */
    XrCompositionLayerProjectionView pv[2];
    memset(pv, 0, sizeof pv);
    int rendered = 0;
    if (fs.shouldRender && views_ok && v) {
        /* both eyes where they are (the world never moves), and the safety
         * fade from how far they are beyond where the app's head may go */
        hol_pose eroom[2];
        double eyes[2][3];
        for (int e = 0; e < 2; e++) {
            float ep[3], eq[4];
            hol__pose_in(&views[e].pose, ep, eq);
            hol_xr_to_room(&x->calib, ep, eq, &eroom[e]);
            for (int k = 0; k < 3; k++)
                eyes[e][k] = eroom[e].pos[k] += room_from_stage_shift[k];
        }
        double fade = hol_xr_fade(eyes, HOL__MARGIN);
        for (int e = 0; e < 2; e++) {
            hol__eye *ey = &x->eye[e];
            uint32_t idx = 0;
            XrSwapchainImageAcquireInfo ai = {XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
            HOL__XR(x, xrAcquireSwapchainImage(ey->swapchain, &ai, &idx));
            XrSwapchainImageWaitInfo wi2 = {XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
            wi2.timeout = XR_INFINITE_DURATION;
            HOL__XR(x, xrWaitSwapchainImage(ey->swapchain, &wi2));
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->fbo[idx]);
            x->gl.Viewport(0, 0, ey->w, ey->h);
            hol_frame_desc fd;
            hol_app_frame_desc(v, e, ey->w, ey->h, 0, &fd);
            for (int k = 0; k < 3; k++)
                fd.cam.eye[k] = eroom[e].pos[k];
            fd.cam.has_pose = 1;
            for (int k = 0; k < 4; k++)
                fd.cam.orient[k] = eroom[e].quat[k];
            fd.cam.tan_left = tan(views[e].fov.angleLeft);
            fd.cam.tan_right = tan(views[e].fov.angleRight);
            fd.cam.tan_down = tan(views[e].fov.angleDown);
            fd.cam.tan_up = tan(views[e].fov.angleUp);
            if (in.flags & HOL_INPUT_HAND_L_VALID && (fd.flags & HOL_RENDER_MINIMAP_HAND)) {
                for (int k = 0; k < 3; k++)
                    fd.hand_pos[k] = in.hand[0].pos[k];
                for (int k = 0; k < 4; k++)
                    fd.hand_orient[k] = in.hand[0].quat[k];
            }
            /* the eye's own room state: the cell its position lies in;
             * none (outside the room): the boundary colour alone */
            int inside = fade < 1 &&
                         hol_motion_eye_state(&v->user, v->head, fd.cam.eye, &fd.user) == HOL_OK;
            fd.fade = inside ? fade : 1;
            hol_render_stats rs;
            memset(&rs, 0, sizeof rs);
            if (hol_render_frame(x->rnd, &fd, &rs)) {
                fd.fade = 1; /* never a stale image */
                hol_render_frame(x->rnd, &fd, &rs);
            }
            x->faded += fd.fade > 0 && e == 0;
            if (fade == 0) { /* the figures of a full view */
                x->draws[e] = rs.draw_calls;
                x->tris[e] = rs.triangles;
            }
#ifndef __ANDROID__
            if (e == 0 && x->d->check_dir && x->submitted == x->d->check_frame && inside &&
                fd.fade == 0)
                hol__check(x, &fd, ey->w, ey->h);
#endif
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
            XrSwapchainImageReleaseInfo ri = {XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
            HOL__XR(x, xrReleaseSwapchainImage(ey->swapchain, &ri));
            pv[e].type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
            pv[e].pose = views[e].pose;
            pv[e].fov = views[e].fov;
            pv[e].subImage.swapchain = ey->swapchain;
            pv[e].subImage.imageRect.extent.width = ey->w;
            pv[e].subImage.imageRect.extent.height = ey->h;
        }
        rendered = fade > 0 ? 2 : 1; /* 2: faded (cheaper; not in the CPU figures) */
    }
    XrCompositionLayerProjection layer = {XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    layer.space = x->stage;
    layer.viewCount = 2;
    layer.views = pv;
    const XrCompositionLayerBaseHeader *layers[1] = {(const XrCompositionLayerBaseHeader *)&layer};
    XrFrameEndInfo ei = {XR_TYPE_FRAME_END_INFO};
    ei.displayTime = fs.predictedDisplayTime;
    ei.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ei.layerCount = rendered ? 1 : 0;
    ei.layers = layers;
    HOL__XR(x, xrEndFrame(x->session, &ei));
    x->submitted++;
    /* the check frame's OSMesa reference is not the app's time */
    if (rendered == 1 && x->submitted - 1 != x->d->check_frame &&
        x->ncpu < (long)(sizeof x->cpu_ms / sizeof x->cpu_ms[0])) {
        x->step_ms[x->ncpu] = x->step_now;
        x->cpu_ms[x->ncpu++] = hol__thread_cpu_ms() - c0;
    }
    return 0;
}

static void hol__events(hol__xr *x)
{
    XrEventDataBuffer ev = {XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(x->instance, &ev) == XR_SUCCESS) {
        if (ev.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
            const XrEventDataSessionStateChanged *e = (const XrEventDataSessionStateChanged *)&ev;
            x->state = (int)e->state;
            printf("xr: state %s\n", hol__state_name(x->state));
            x->reached_focused |= x->state == HOL_XR_STATE_FOCUSED;
            hol_xr_do d = hol_xr_lifecycle(x->state, &x->running, &x->focused);
            if (d == HOL_XR_DO_BEGIN) {
                XrSessionBeginInfo sb = {XR_TYPE_SESSION_BEGIN_INFO};
                sb.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
                XrResult r = xrBeginSession(x->session, &sb);
                if (XR_FAILED(r)) {
                    hol__fail(x, "xrBeginSession", r);
                    x->done = 1;
                }
            } else if (d == HOL_XR_DO_END) {
                XrResult r = xrEndSession(x->session);
                if (XR_FAILED(r))
                    hol__fail(x, "xrEndSession", r);
                else
                    printf("xr: session ended after STOPPING\n");
                if (!x->quit_requested) /* the runtime stopped us: leave */
                    x->done = 1;
            } else if (d == HOL_XR_DO_TEAR_DOWN) {
                x->done = 1;
            }
        } else if (ev.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
            printf("xr: instance loss pending\n");
            x->done = 1;
        }
        ev.type = XR_TYPE_EVENT_DATA_BUFFER;
        ev.next = NULL;
    }
}

static int hol__cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int hol__run(hol__xr *x)
{
    XrInstanceCreateInfo ic = {XR_TYPE_INSTANCE_CREATE_INFO};
#ifdef __ANDROID__
    /* the Android loader needs the VM and the activity before anything */
    PFN_xrInitializeLoaderKHR init_loader = NULL;
    HOL__XR(x, xrGetInstanceProcAddr(XR_NULL_HANDLE, "xrInitializeLoaderKHR",
                                     (PFN_xrVoidFunction *)&init_loader));
    XrLoaderInitInfoAndroidKHR li = {XR_TYPE_LOADER_INIT_INFO_ANDROID_KHR};
    li.applicationVM = x->d->android_vm;
    li.applicationContext = x->d->android_activity;
    HOL__XR(x, init_loader((const XrLoaderInitInfoBaseHeaderKHR *)&li));
    XrInstanceCreateInfoAndroidKHR ai = {XR_TYPE_INSTANCE_CREATE_INFO_ANDROID_KHR};
    ai.applicationVM = x->d->android_vm;
    ai.applicationActivity = x->d->android_activity;
    ic.next = &ai;
    const char *ext[] = {XR_KHR_OPENGL_ES_ENABLE_EXTENSION_NAME,
                         XR_KHR_ANDROID_CREATE_INSTANCE_EXTENSION_NAME};
    ic.enabledExtensionCount = 2;
#else
    const char *ext[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
    ic.enabledExtensionCount = 1;
#endif
    ic.enabledExtensionNames = ext;
    snprintf(ic.applicationInfo.applicationName, sizeof ic.applicationInfo.applicationName, "%s",
             x->d->app_name ? x->d->app_name : "Holonomy");
    ic.applicationInfo.applicationVersion = 1;
    snprintf(ic.applicationInfo.engineName, sizeof ic.applicationInfo.engineName, "holonomy");
    ic.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    HOL__XR(x, xrCreateInstance(&ic, &x->instance));
    XrInstanceProperties ip = {XR_TYPE_INSTANCE_PROPERTIES};
    if (XR_SUCCEEDED(xrGetInstanceProperties(x->instance, &ip)))
        printf("xr: runtime %s %u.%u.%u\n", ip.runtimeName, XR_VERSION_MAJOR(ip.runtimeVersion),
               XR_VERSION_MINOR(ip.runtimeVersion), XR_VERSION_PATCH(ip.runtimeVersion));
    XrSystemGetInfo sg = {XR_TYPE_SYSTEM_GET_INFO};
    sg.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    HOL__XR(x, xrGetSystem(x->instance, &sg, &x->system));
#ifdef __ANDROID__
    XrGraphicsBindingOpenGLESAndroidKHR binding;
#else
    XrGraphicsBindingOpenGLXlibKHR binding;
#endif
    if (hol__graphics(x, &binding) || hol__load_gl(x) || hol__actions(x))
        return 1;
    XrSessionCreateInfo sc = {XR_TYPE_SESSION_CREATE_INFO};
    sc.next = &binding;
    sc.systemId = x->system;
    HOL__XR(x, xrCreateSession(x->instance, &sc, &x->session));
    if (hol__spaces(x) || hol__swapchains(x))
        return 1;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = x->getproc;
    rd.world = x->fns->world(x->fns->user);
    if (hol_render_create(&rd, &x->rnd)) {
        fprintf(stderr, "holonomy xr: cannot initialise the renderer on this GL context\n");
        return 1;
    }
    while (!x->done) {
        if (x->fns->poll_platform && x->fns->poll_platform(x->fns->user) &&
            !x->quit_requested && x->session != XR_NULL_HANDLE) {
            if (x->running)
                xrRequestExitSession(x->session);
            else
                x->done = 1;
            x->quit_requested = 1;
        }
        hol__events(x);
        if (x->done)
            break;
        if (x->running) {
            if (hol__frame(x))
                return 1;
        } else {
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
        }
    }
    printf("xr: frames submitted %ld, reached FOCUSED %s, faded at the boundary %ld\n",
           x->submitted, x->reached_focused ? "yes" : "no", x->faded);
    if (x->ncpu) {
        qsort(x->cpu_ms, (size_t)x->ncpu, sizeof x->cpu_ms[0], hol__cmp);
        qsort(x->step_ms, (size_t)x->ncpu, sizeof x->step_ms[0], hol__cmp);
        printf("xr: app thread CPU per stereo frame (step, both eyes, submit; without "
               "xrWaitFrame; unfaded frames): median %.2f ms, p99 %.2f ms over %ld frames; of it the app "
               "step median %.3f ms, p99 %.3f ms\n",
               x->cpu_ms[x->ncpu / 2], x->cpu_ms[x->ncpu * 99 / 100], x->ncpu,
               x->step_ms[x->ncpu / 2], x->step_ms[x->ncpu * 99 / 100]);
        printf("xr: per eye: %ld / %ld draw calls, %ld / %ld triangles (left / right)\n",
               x->draws[0], x->draws[1], x->tris[0], x->tris[1]);
    }
    return 0;
}

static void hol__destroy(hol__xr *x)
{
    hol_render_destroy(x->rnd);
    for (int e = 0; e < 2; e++) {
        if (x->eye[e].nimages && x->gl.DeleteFramebuffers) {
            x->gl.DeleteFramebuffers((hol__GLsizei)x->eye[e].nimages, x->eye[e].fbo);
            x->gl.DeleteRenderbuffers(1, &x->eye[e].depth);
        }
        if (x->eye[e].swapchain != XR_NULL_HANDLE)
            xrDestroySwapchain(x->eye[e].swapchain);
    }
    for (int h = 0; h < 2; h++)
        if (x->grip[h] != XR_NULL_HANDLE)
            xrDestroySpace(x->grip[h]);
    if (x->view_space != XR_NULL_HANDLE)
        xrDestroySpace(x->view_space);
    if (x->stage != XR_NULL_HANDLE)
        xrDestroySpace(x->stage);
    if (x->session != XR_NULL_HANDLE)
        xrDestroySession(x->session);
    if (x->set != XR_NULL_HANDLE)
        xrDestroyActionSet(x->set);
    if (x->instance != XR_NULL_HANDLE)
        xrDestroyInstance(x->instance);
#ifdef __ANDROID__
    if (x->edpy != EGL_NO_DISPLAY) {
        eglMakeCurrent(x->edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglTerminate(x->edpy);
    }
#else
    if (x->dpy) {
        glXMakeCurrent(x->dpy, None, NULL);
        if (x->ctx)
            glXDestroyContext(x->dpy, x->ctx);
        if (x->win)
            XDestroyWindow(x->dpy, x->win);
        if (x->cmap)
            XFreeColormap(x->dpy, x->cmap);
        XCloseDisplay(x->dpy);
    }
#endif
}

int hol_xr_run(const hol_xr_desc *desc, const hol_xr_app_fns *fns)
{
    hol__xr *x = calloc(1, sizeof *x); /* the platform's one allocation */
    if (!x) {
        fprintf(stderr, "holonomy xr: out of memory\n");
        return 1;
    }
    x->d = desc;
    x->fns = fns;
#ifdef __ANDROID__
    x->edpy = EGL_NO_DISPLAY;
#endif
    int rc = hol__run(x);
    hol__destroy(x);
    free(x);
    fflush(stdout);
    return rc;
}
