/* hol_xr_state.h - internal to platform/openxr: the session's state shared
 * by its files, and how they report. Not a public interface.
 *
 * The files, from the top down (a file calls only files below it):
 *   hol_xr.c          the entries, the instance, the run loop, teardown
 *   hol_xr_events.c   the runtime's events: lifecycle, loss, a reference
 *                     space changed, an interaction profile changed
 *   hol_xr_frame.c    one frame: the input record, the app step, both eyes
 *   hol_xr_panel.c    the world panel's quad layer (its swapchain, its image)
 *   hol_xr_hands.c    the tracked hands (XR_EXT_hand_tracking): their joints,
 *                     the hands-only recentre
 *   hol_xr_check.c    the desktop read-back check of one eye
 *   hol_xr_views.c    view configuration and swapchains
 *   hol_xr_actions.c  actions, bindings, reference spaces, stage bounds
 *   hol_xr_gfx.c      the GL context and its graphics binding
 *   hol_xr_state.c    reporting: progress lines and the one failure line
 * and the pure parts every one of them may use: hol_xr_room.h,
 * hol_xr_bind.h, hol_xr_pick.h, hol_xr_quad.h, hol_xr_text.h,
 * hol_xr_hand.h.
 *
 * Contract
 * - One hol__xr per run, zeroed at start; every XR handle not yet made is
 *   XR_NULL_HANDLE and every array NULL, so teardown destroys exactly what
 *   exists. Arrays sized by the runtime (views, swapchain images) are
 *   allocated once before the first frame.
 * - Reporting: hol__xr_say prints a progress line ("xr: ...": stdout on the
 *   desktop, logcat on Android). hol__xr_fail reports a failed call as one
 *   line in words (hol_xr_text.h; stderr, or logcat's error level on
 *   Android), marks the run failed, and returns 1; only the first failure
 *   of a run is printed, so a run ends with one clear line. A result that
 *   means the session or the instance is gone also sets `lost`.
 * - HOL__XR(x, doing, call): the call, and on failure return
 *   hol__xr_fail(x, doing, result) from the calling function; `doing` says
 *   in words what the call was for ("begin the session").
 * - `external` set: the instance, system and GL context are the caller's
 *   (hol_xr_run_session): nothing here creates or destroys them.
 */
#ifndef HOL_XR_STATE_H
#define HOL_XR_STATE_H

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

#include "../../core/hol_body.h"
#include "../../core/hol_motion.h"
#include "../../render/hol_app_frame.h"
#include "../../render/hol_render.h"
#include "hol_xr_app.h"
#include "hol_xr_bind.h"
#include "../shell/hol_xr_pick.h"
#include "../shell/hol_xr_quad.h"
#include "../shell/hol_xr_hand.h"
#include "../shell/hol_xr_room.h"
#include "hol_xr_text.h"

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
#define HOL__GL_FRAMEBUFFER_SRGB 0x8DB9
#define HOL__GL_READ_FRAMEBUFFER 0x8CA8
#define HOL__GL_DRAW_FRAMEBUFFER 0x8CA9
#define HOL__GL_COLOR_BUFFER_BIT 0x4000
#define HOL__GL_NEAREST 0x2600

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
    void (*Enable)(hol__GLenum);
    void (*Disable)(hol__GLenum);
    void (*RenderbufferStorageMultisample)(hol__GLenum, hol__GLsizei, hol__GLenum, hol__GLsizei,
                                           hol__GLsizei);
    void (*BlitFramebuffer)(hol__GLint, hol__GLint, hol__GLint, hol__GLint, hol__GLint,
                            hol__GLint, hol__GLint, hol__GLint, unsigned int, hol__GLenum);
} hol__gl;

/* metres the app's head keeps from the hedges: the motion's default margin
 * (hol_motion_desc), where the safety fade begins */
#define HOL__MARGIN 0.15
/* seconds the fit's line stays on the HUD after the first frame */
#define HOL__FIT_NOTE_S 12.0

#ifdef __ANDROID__
typedef XrSwapchainImageOpenGLESKHR hol__image;
#define HOL__XR_TYPE_IMAGE XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_ES_KHR
typedef XrGraphicsBindingOpenGLESAndroidKHR hol__binding;
#else
typedef XrSwapchainImageOpenGLKHR hol__image;
#define HOL__XR_TYPE_IMAGE XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR
typedef XrGraphicsBindingOpenGLXlibKHR hol__binding;
#endif

typedef struct hol__eye {
    XrSwapchain swapchain;
    int32_t w, h;
    uint32_t nimages;
    hol__image *images; /* nimages, from the runtime */
    hol__GLuint *fbo;   /* one per image */
    hol__GLuint depth;
    int samples;        /* hol_xr_pick_samples; > 1: drawn into msaa_fbo,
                           resolved into the image's fbo */
    hol__GLuint msaa_fbo, msaa_color, msaa_depth;
} hol__eye;

/* One hand as xrLocateHandJointsEXT gave it (stage space). */
typedef struct hol__xr_hand_raw {
    int active;
    float pos[HOL_XR_HAND_JOINTS][3];
    float radius[HOL_XR_HAND_JOINTS];
    unsigned flags[HOL_XR_HAND_JOINTS];
} hol__xr_hand_raw;

typedef struct hol__xr {
    const hol_xr_desc *d;
    const hol_xr_app_fns *fns;
    XrInstance instance;
    XrSystemId system;
    XrSession session;
    XrSpace stage, view_space, grip[2];
    int space_type;  /* HOL_XR_SPACE_STAGE or _LOCAL (hol_xr_pick.h) */
    double origin_y; /* the room space's origin in that space (LOCAL: -1.6) */
    XrActionSet set;
    XrAction grip_action, act[HOL_XR_ACT_COUNT];
    XrAction haptic_action; /* vibration output, per hand (hol_xr_haptic_path) */
    XrAction stick_action;  /* seated (desc.seated): the sticks, per hand
                               (hol_xr_stick_path) */
    int seat_latch;         /* hol_shell_seat's */
    int haptic_failed;      /* a pulse failed once: said once, not again */
    long pulses, pulses_hit; /* pulses played (all; of them into a hedge or trunk) */
    XrPath hand_path[2];
    uint32_t nviews;  /* of the stereo configuration: 2 */
    XrView *views;    /* nviews, located each frame */
    hol__eye eye[2];
    int srgb;         /* the swapchains store sRGB */
    hol_xr_life life; /* the lifecycle (hol_xr_room.h) */
    hol_xr_keys keys; /* the action layer (hol_xr_bind.h) */
    int in_menu;      /* the app's pause menu was open after the last step */
    int profile[2];   /* the hands' interaction profiles (hol_xr_bind.h), -1 none */
    int any_profile;  /* a hand has a profile not in hol_xr_bind.h's list */
    int reached_focused;
    int hand_interaction; /* XR_EXT_hand_interaction enabled (the runtime lists it) */
    int fb_refresh;   /* XR_FB_display_refresh_rate enabled (the runtime lists it) */
    /* the tracked hands (hol_xr_hands.c) */
    int hand_ext;     /* XR_EXT_hand_tracking enabled (the runtime lists it) */
    int hands_on;     /* both trackers made: the joints are located */
    XrHandTrackerEXT hand_tracker[2];
    PFN_xrCreateHandTrackerEXT hand_create;
    PFN_xrLocateHandJointsEXT hand_locate;
    PFN_xrDestroyHandTrackerEXT hand_destroy;
    hol__xr_hand_raw hand_raw[2]; /* this frame's */
    long hands_located[2];        /* frames each hand was tracked */
    hol_gesture gesture;          /* the hands-only recentre (core/hol_body.h) */
    double refresh_fb; /* its rate, Hz (0: not known) */
    double period_ns; /* predictedDisplayPeriod summed over the first frames */
    long periods;     /* how many (up to HOL_XR_REFRESH_FRAMES) */
    int env_told;     /* fns->environment was called */
    int failed;       /* a failure was reported: the run ends with status 1 */
    int lost;         /* the session or the instance is gone */
    int external;     /* the instance and GL context are the caller's */
    hol_xr_calib calib;
    int have_bounds;  /* the runtime gave the stage bounds: */
    float bounds_w, bounds_d; /* full width (x) and depth (z), metres */
    int bounds_small; /* the room in play (or the fit) is larger than them */
    hol_fit fit;      /* with have_bounds: what they hold (core/hol_fit.h) */
    char fit_text[160]; /* its line (hol_fit_text) */
    char runtime[160];  /* the runtime's name and version */
    char prompt[HOL_APP_HINT_MAX]; /* the prompt line said last */
    double room_w, room_d; /* the room in play, metres (0: not known yet) */
    hol_app_view note;  /* the view drawn while the fit is told on the HUD */
    hol__gl gl;
    hol_render *rnd;
    hol_render_getproc getproc;
    long submitted;
    XrTime t0;
    double last_t;
    unsigned prev_buttons;
    int grips_located[2];
    long faded; /* frames drawn with the safety fade */
    double fade_now; /* this frame's safety fade (1: the view is gone) */
    double cpu_ms[4096], step_ms[4096];
    long ncpu;
    double step_now;
    long draws[2], tris[2];
    double panel_left[2], panel_pred[2]; /* the check frame's UI panel */
    int64_t format;   /* the eyes' swapchain format (the quad's too) */
    /* the world panel as a quad layer (hol_xr_panel.c): quad_on 0 draws
     * it in the scene (--panel scene, or no quad swapchain) */
    int quad_on;
    XrSwapchain quad_chain;
    uint32_t quad_nimages;
    hol__image *quad_images;
    hol__GLuint *quad_fbo;
    int quad_w, quad_h;      /* the image (hol_xr_quad_image) */
    hol_xr_quad_cache quad_cache;
    long quad_frames;        /* frames that submitted it */
    int quad_covered;        /* this frame: the panel in the eyes instead */
    long quad_covered_frames; /* frames it was */
    hol_xr_quad quad_last;   /* the last submitted */
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

/* hol_xr_state.c: reporting (see the contract) */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void hol__xr_say(hol__xr *x, const char *fmt, ...);
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
int hol__xr_error(hol__xr *x, const char *fmt, ...); /* one failure line; returns 1;
                                                   x may be NULL */
int hol__xr_fail(hol__xr *x, const char *doing, XrResult r);
/* A destroy call's result at teardown: reported (hol__xr_fail) unless the
 * session or the instance is already gone, when failures are expected. */
void hol__xr_gone(hol__xr *x, const char *doing, XrResult r);

#define HOL__XR(x, doing, call)                                                               \
    do {                                                                                      \
        XrResult hol__r = (call);                                                             \
        if (XR_FAILED(hol__r))                                                                \
            return hol__xr_fail((x), (doing), hol__r);                                        \
    } while (0)

/* hol_xr_gfx.c: make the GL context current and fill the binding; load
 * the GL entry points this layer calls itself */
int hol__xr_graphics(hol__xr *x, hol__binding *b);
int hol__xr_load_gl(hol__xr *x);
/* hol_xr_actions.c: the action set and suggested bindings (on the
 * instance); attach, grip and reference spaces (on the session); the
 * stage bounds (read again after a change); a boolean action's state
 * (*out_held); the hands' current interaction profiles */
int hol__xr_actions(hol__xr *x);
int hol__xr_spaces(hol__xr *x);
int hol__xr_bounds(hol__xr *x);
int hol__xr_bool(hol__xr *x, int act, int *out_held);
/* Seated: hand h's stick (x right, y ahead; 0, 0 when not bound). */
int hol__xr_stick(hol__xr *x, int h, float out[2]);
int hol__xr_haptics(hol__xr *x);
int hol__xr_profiles_now(hol__xr *x);
/* hol_xr_views.c: the stereo view configuration (x->nviews, x->views) and
 * one swapchain per eye with a framebuffer per image */
int hol__xr_views(hol__xr *x);
int hol__xr_swapchains(hol__xr *x);
void hol__xr_views_free(hol__xr *x);
/* a colour swapchain of w x h in x->format, one sample, one layer (the
 * eyes', the panel's): xrCreateSwapchain's result */
XrResult hol__xr_chain_create(hol__xr *x, int w, int h, XrSwapchain *out);
/* a swapchain's framebuffers deleted, its image and framebuffer arrays
 * freed and it destroyed (doing: the teardown's words, hol__xr_gone);
 * the next image acquired and waited for (*out_idx; 1 reported: a failed
 * call, an index out of 0..n-1) */
void hol__xr_chain_free(hol__xr *x, XrSwapchain *chain, hol__image **images, hol__GLuint **fbo,
                        uint32_t *n, const char *doing);
int hol__xr_chain_acquire(hol__xr *x, XrSwapchain chain, uint32_t n, const char *doing,
                          uint32_t *out_idx);
#ifndef __ANDROID__
/* hol_xr_check.c: eye 0 read back against an OSMesa render of fd */
void hol__xr_check(hol__xr *x, const hol_frame_desc *fd, int w, int h);
/* The check frame's eye e (bound to fbo): drawn without the HUD and read
 * back (eye 0: hol__xr_check on it), then drawn as shown (the UI panel) and
 * read back; the panel's pixels (where the two differ) measured against a
 * pinhole model of the eye: "xr: check panel ..." lines. */
void hol__xr_check_eye(hol__xr *x, int e, const hol_frame_desc *fd, unsigned fbo, int w, int h);
#endif
/* hol_xr_panel.c: the world panel's quad layer: its swapchain (made once
 * after the eyes'; a failure falls back to the panel in the scene, said
 * in one line, not a failure of the run), its layer for this frame (the
 * image drawn again only when the panel's content changed;
 * *out_submit 0: no panel this frame), the figures, teardown;
 * hol__xr_quad_covered: 1 when this frame's panel goes in the eyes,
 * depth-tested, instead of the quad (scenery nearer than it can come:
 * core/hol_panel.h), said when it changes */
int hol__xr_quad_setup(hol__xr *x);
int hol__xr_quad_covered(hol__xr *x, const hol_app_view *v);
int hol__xr_quad_layer(hol__xr *x, const hol_app_view *v, const float shift[3],
                       XrCompositionLayerQuad *out, int *out_submit);
void hol__xr_quad_free(hol__xr *x);
/* hol_xr_hands.c: the hand trackers made after the session (where the
 * runtime lists XR_EXT_hand_tracking, x->hand_ext, and the system tracks
 * hands; else one line says why and the controllers are drawn: never a
 * failure); destroyed at teardown; this frame's joints located (t: the
 * display time; 1 a failure, reported); the hands-only recentre from them
 * (HOL_BTN_RECENTRE once per hold, hol_gesture_step; nothing while not
 * focused); the joints into the record in room coordinates (after a
 * recentre has placed the room) */
int hol__xr_hands_setup(hol__xr *x);
void hol__xr_hands_free(hol__xr *x);
int hol__xr_hands_locate(hol__xr *x, XrTime t);
uint32_t hol__xr_hands_gesture(hol__xr *x, int focused, double t);
void hol__xr_hands_room(hol__xr *x, hol_hand_joints out[2]);
/* hol_xr_frame.c: fns->environment once what it tells is known (last: the
 * run ends, tell what is known now) */
void hol__xr_tell_env(hol__xr *x, int last);
/* hol_xr_frame.c: one frame (xrWaitFrame to xrEndFrame); 0 ok, 1 failure */
int hol__xr_frame(hol__xr *x);
/* hol_xr_events.c: every waiting event; sets x->life.done to leave */
void hol__xr_events(hol__xr *x);

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
