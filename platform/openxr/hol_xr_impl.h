/* hol_xr_impl.h - internal to platform/openxr: the session's state shared
 * by its files (hol_xr.c the session and frame loop, hol_xr_gfx.c the GL
 * context and its binding, hol_xr_actions.c actions and spaces,
 * hol_xr_check.c the desktop read-back check). Not a public interface.
 *
 * Contract
 * - One hol__xr per run, zeroed at start; every XR handle not yet made is
 *   XR_NULL_HANDLE, so teardown destroys exactly what exists.
 * - HOL__XR(x, call) returns 1 from the calling function after one line on
 *   stderr naming the failed call and its XrResult.
 * - `external` set: the instance, system and GL context are the caller's
 *   (hol_xr_run_session): nothing here creates or destroys them.
 */
#ifndef HOL_XR_IMPL_H
#define HOL_XR_IMPL_H

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
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#endif
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
#include "hol_xr_session.h"

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
    hol_xr_life life; /* the lifecycle (hol_xr_room.h) */
    int reached_focused, failed;
    int is_stage;
    int external; /* the instance and GL context are the caller's */
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

int hol__fail(hol__xr *x, const char *what, XrResult r);

#define HOL__XR(x, call)                                                                      \
    do {                                                                                      \
        XrResult hol__r = (call);                                                             \
        if (XR_FAILED(hol__r))                                                                \
            return hol__fail((x), #call, hol__r);                                             \
    } while (0)

#ifdef __ANDROID__
typedef XrGraphicsBindingOpenGLESAndroidKHR hol__binding;
#else
typedef XrGraphicsBindingOpenGLXlibKHR hol__binding;
#endif

/* hol_xr_gfx.c: make the GL context current and fill the binding; load
 * the GL entry points this layer calls itself */
int hol__graphics(hol__xr *x, hol__binding *b);
int hol__load_gl(hol__xr *x);
/* hol_xr_actions.c: the action set and suggested bindings (on the
 * instance); attach, grip and reference spaces, stage bounds (on the
 * session); a boolean action's state */
int hol__actions(hol__xr *x);
int hol__spaces(hol__xr *x);
int hol__bool(hol__xr *x, int act);
#ifndef __ANDROID__
/* hol_xr_check.c: eye 0 read back against an OSMesa render of fd */
void hol__check(hol__xr *x, const hol_frame_desc *fd, int w, int h);
#endif

static inline void hol__pose_in(const XrPosef *p, float pos[3], float quat[4])
{
    pos[0] = p->position.x;
    pos[1] = p->position.y;
    pos[2] = p->position.z;
    quat[0] = p->orientation.x;
    quat[1] = p->orientation.y;
    quat[2] = p->orientation.z;
    quat[3] = p->orientation.w;
}

#endif
