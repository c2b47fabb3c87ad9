/* hol_egl_x11.h - desktop window through EGL on X11 (platform code).
 *
 * Contract
 * - Header-only (static inline), like hol_egl.h. Opens an X11 window of
 *   w x h (it works under Xvfb), creates an OpenGL ES 3 context and a
 *   window surface with 8-bit RGBA, 24-bit depth and 8-bit stencil, and
 *   makes it current. GL calls go through eglGetProcAddress (hol_egl_getproc
 *   in hol_egl.h).
 * - hol_x11_poll drains the event queue into a small key state (keys, a
 *   mouse drag, focus) and returns 0 once the window is closed or Escape/q
 *   is pressed. Every key that goes down sets its bit in keys->taps
 *   (HOL_X11_TAP(HOL_X11_K_*)) until the caller clears it, so a press and
 *   release between two polls is not lost; the keyboard's auto-repeat is
 *   not a press (detectable auto-repeat, else a release and press with the
 *   same timestamp are dropped). x->closed tells the window's end apart
 *   from Escape/q: 1 when the window manager's close button asked
 *   (WM_DELETE_WINDOW), the window was destroyed from outside
 *   (DestroyNotify, or an X error on it), or the display's connection was
 *   lost. X errors and a lost connection no longer end the process (Xlib's
 *   default), so the caller can save and leave; the handlers are per
 *   process (Xlib's are global).
 * - On failure hol_x11_create returns nonzero with a one-line reason in
 *   err and leaves nothing open.
 */
#ifndef HOL_EGL_X11_H
#define HOL_EGL_X11_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>
#include <stdio.h>
#include <string.h>

typedef struct hol_x11 {
    Display *dpy;
    Window win;
    Atom wm_delete;
    EGLDisplay edpy;
    EGLContext ctx;
    EGLSurface surf;
    int w, h;
    int closed; /* the window was closed, destroyed or its display lost */
} hol_x11;

/* Set by the X error handlers: an X error (a window destroyed under us), a
 * lost display connection. */
static volatile int hol__x11_error, hol__x11_lost;

static inline int hol__x11_on_error(Display *d, XErrorEvent *e)
{
    (void)d;
    (void)e;
    hol__x11_error = 1;
    return 0;
}

static inline int hol__x11_on_io_error(Display *d)
{
    (void)d;
    hol__x11_lost = 1;
    return 0;
}

static inline void hol__x11_on_io_exit(Display *d, void *user)
{
    (void)d;
    (void)user;
    hol__x11_lost = 1; /* returning leaves Xlib calls on d failing, not the process */
}

/* Keys held down (1) or not (0); taps: the keys that went down since the
 * caller last cleared it (bit HOL_X11_TAP(HOL_X11_K_*)); the mouse moved by
 * (mouse_dx, mouse_dy) pixels with the left button held since the caller
 * last zeroed them; focused: the window has the keyboard focus (1 until
 * told otherwise). */
enum {
    HOL_X11_K_LEFT, HOL_X11_K_RIGHT, HOL_X11_K_UP, HOL_X11_K_DOWN, HOL_X11_K_STRAFE_L,
    HOL_X11_K_STRAFE_R, HOL_X11_K_LOOK_UP, HOL_X11_K_LOOK_DOWN, HOL_X11_K_CONFIRM,
    HOL_X11_K_MENU, HOL_X11_K_RESTART, HOL_X11_K_MINIMAP, HOL_X11_K_DEBUG, HOL_X11_K_STATS,
    HOL_X11_K_COUNT
};
#define HOL_X11_TAP(k) (1u << (k))
typedef struct hol_x11_keys {
    int left, right, up, down, strafe_l, strafe_r, look_up, look_down;
    int confirm, menu, restart, minimap; /* Enter/Space, P, R, M */
    int debug, stats;                    /* F3, F2 */
    unsigned taps;
    int mouse_dx, mouse_dy, dragging, last_x, last_y;
    int unfocused;
} hol_x11_keys;

static inline void hol_x11_destroy(hol_x11 *x)
{
    if (x->edpy != EGL_NO_DISPLAY) {
        eglMakeCurrent(x->edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (x->surf != EGL_NO_SURFACE)
            eglDestroySurface(x->edpy, x->surf);
        if (x->ctx != EGL_NO_CONTEXT)
            eglDestroyContext(x->edpy, x->ctx);
        eglTerminate(x->edpy);
    }
    if (x->dpy && !hol__x11_lost) {
        if (x->win)
            XDestroyWindow(x->dpy, x->win);
        XCloseDisplay(x->dpy);
    }
    memset(x, 0, sizeof *x);
    x->edpy = EGL_NO_DISPLAY;
    x->ctx = EGL_NO_CONTEXT;
    x->surf = EGL_NO_SURFACE;
}

static inline int hol_x11_create(hol_x11 *x, int w, int h, const char *title, char *err,
                                 size_t err_cap)
{
    memset(x, 0, sizeof *x);
    x->edpy = EGL_NO_DISPLAY;
    x->ctx = EGL_NO_CONTEXT;
    x->surf = EGL_NO_SURFACE;
    x->w = w;
    x->h = h;
    x->dpy = XOpenDisplay(NULL);
    if (!x->dpy) {
        snprintf(err, err_cap, "cannot open the X display (is DISPLAY set?)");
        return 1;
    }
    XSetErrorHandler(hol__x11_on_error);
    XSetIOErrorHandler(hol__x11_on_io_error);
    XSetIOErrorExitHandler(x->dpy, hol__x11_on_io_exit, NULL);
    x->edpy = eglGetDisplay((EGLNativeDisplayType)x->dpy);
    EGLint maj, min;
    if (x->edpy == EGL_NO_DISPLAY || !eglInitialize(x->edpy, &maj, &min)) {
        snprintf(err, err_cap, "cannot initialise EGL on the X display");
        x->edpy = EGL_NO_DISPLAY;
        hol_x11_destroy(x);
        return 1;
    }
    static const EGLint cattr[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_ES3_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                   EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
                                   EGL_NONE};
    EGLConfig cfg;
    EGLint n = 0;
    if (!eglChooseConfig(x->edpy, cattr, &cfg, 1, &n) || n < 1) {
        snprintf(err, err_cap, "no EGL window config with GLES 3, depth and stencil");
        hol_x11_destroy(x);
        return 1;
    }
    EGLint vid = 0;
    eglGetConfigAttrib(x->edpy, cfg, EGL_NATIVE_VISUAL_ID, &vid);
    XVisualInfo tmpl, *vi;
    int nvi = 0;
    memset(&tmpl, 0, sizeof tmpl);
    tmpl.visualid = (VisualID)vid;
    vi = XGetVisualInfo(x->dpy, VisualIDMask, &tmpl, &nvi);
    Window root = DefaultRootWindow(x->dpy);
    XSetWindowAttributes swa;
    memset(&swa, 0, sizeof swa);
    swa.event_mask = KeyPressMask | KeyReleaseMask | StructureNotifyMask | ExposureMask |
                     ButtonPressMask | ButtonReleaseMask | PointerMotionMask |
                     FocusChangeMask;
    unsigned long mask = CWEventMask;
    int depth = CopyFromParent;
    Visual *visual = CopyFromParent;
    if (vi) {
        swa.colormap = XCreateColormap(x->dpy, root, vi->visual, AllocNone);
        swa.border_pixel = 0;
        mask |= CWColormap | CWBorderPixel;
        depth = vi->depth;
        visual = vi->visual;
    }
    x->win = XCreateWindow(x->dpy, root, 0, 0, (unsigned)w, (unsigned)h, 0, depth,
                           InputOutput, visual, mask, &swa);
    if (vi)
        XFree(vi);
    XStoreName(x->dpy, x->win, title);
    x->wm_delete = XInternAtom(x->dpy, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(x->dpy, x->win, &x->wm_delete, 1);
    XMapWindow(x->dpy, x->win);
    XFlush(x->dpy);
    eglBindAPI(EGL_OPENGL_ES_API);
    static const EGLint xattr[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                   EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    x->ctx = eglCreateContext(x->edpy, cfg, EGL_NO_CONTEXT, xattr);
    x->surf = eglCreateWindowSurface(x->edpy, cfg, (EGLNativeWindowType)x->win, NULL);
    if (x->ctx == EGL_NO_CONTEXT || x->surf == EGL_NO_SURFACE ||
        !eglMakeCurrent(x->edpy, x->surf, x->surf, x->ctx)) {
        snprintf(err, err_cap, "cannot create a GLES 3 window surface through EGL");
        hol_x11_destroy(x);
        return 1;
    }
    eglSwapInterval(x->edpy, 1);
    Bool detectable = False;
    XkbSetDetectableAutoRepeat(x->dpy, True, &detectable);
    return 0;
}

static inline void hol_x11_swap(hol_x11 *x)
{
    /* a connection lost since the poll is found here, before the swap:
     * Mesa's software swap loops for ever on a lost connection (its put
     * image sees a maximum request length of 0); NoOp and a read make
     * Xlib notice (the IO handlers set hol__x11_lost) */
    if (!x->closed && !hol__x11_lost) {
        XNoOp(x->dpy);
        (void)XPending(x->dpy);
    }
    if (hol__x11_error || hol__x11_lost)
        x->closed = 1;
    if (!x->closed)
        eglSwapBuffers(x->edpy, x->surf);
}

/* Key k's state: a press while up is a tap. */
static inline void hol__x11_key(hol_x11_keys *keys, int *state, int k, int down)
{
    if (down && !*state)
        keys->taps |= HOL_X11_TAP(k);
    *state = down;
}

/* The release of an auto-repeat without detectable auto-repeat: the next
 * event is the same key's press at the same time (both are dropped). */
static inline int hol__x11_repeat(Display *dpy, const XEvent *ev)
{
    if (ev->type != KeyRelease || !XEventsQueued(dpy, QueuedAfterReading))
        return 0;
    XEvent nx;
    XPeekEvent(dpy, &nx);
    if (nx.type != KeyPress || nx.xkey.keycode != ev->xkey.keycode ||
        nx.xkey.time != ev->xkey.time)
        return 0;
    XNextEvent(dpy, &nx);
    return 1;
}

/* Drain pending events into keys; 0 when the user asked to quit. */
static inline int hol_x11_poll(hol_x11 *x, hol_x11_keys *keys)
{
    int run = 1;
    while (!hol__x11_lost && XPending(x->dpy)) {
        XEvent ev;
        XNextEvent(x->dpy, &ev);
        if (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == x->wm_delete)
            x->closed = 1;
        else if (ev.type == DestroyNotify && ev.xdestroywindow.window == x->win) {
            x->closed = 1;
            x->win = 0; /* gone: not destroyed again */
        }
        else if (ev.type == FocusIn || ev.type == FocusOut)
            keys->unfocused = ev.type == FocusOut;
        else if (ev.type == ButtonPress || ev.type == ButtonRelease) {
            if (ev.xbutton.button == Button1) {
                keys->dragging = ev.type == ButtonPress;
                keys->last_x = ev.xbutton.x;
                keys->last_y = ev.xbutton.y;
            }
        } else if (ev.type == MotionNotify) {
            if (keys->dragging) {
                keys->mouse_dx += ev.xmotion.x - keys->last_x;
                keys->mouse_dy += ev.xmotion.y - keys->last_y;
            }
            keys->last_x = ev.xmotion.x;
            keys->last_y = ev.xmotion.y;
        } else if (ev.type == ConfigureNotify) {
            x->w = ev.xconfigure.width;
            x->h = ev.xconfigure.height;
        } else if ((ev.type == KeyPress || ev.type == KeyRelease) &&
                   !hol__x11_repeat(x->dpy, &ev)) {
            int down = ev.type == KeyPress;
            KeySym k = XLookupKeysym(&ev.xkey, 0);
            switch (k) {
            case XK_Escape:
            case XK_q: if (down) run = 0; break;
            case XK_Left: hol__x11_key(keys, &keys->left, HOL_X11_K_LEFT, down); break;
            case XK_Right: hol__x11_key(keys, &keys->right, HOL_X11_K_RIGHT, down); break;
            case XK_Up: case XK_w: hol__x11_key(keys, &keys->up, HOL_X11_K_UP, down); break;
            case XK_Down: case XK_s: hol__x11_key(keys, &keys->down, HOL_X11_K_DOWN, down); break;
            case XK_a: hol__x11_key(keys, &keys->strafe_l, HOL_X11_K_STRAFE_L, down); break;
            case XK_d: hol__x11_key(keys, &keys->strafe_r, HOL_X11_K_STRAFE_R, down); break;
            case XK_Page_Up: hol__x11_key(keys, &keys->look_up, HOL_X11_K_LOOK_UP, down); break;
            case XK_Page_Down:
                hol__x11_key(keys, &keys->look_down, HOL_X11_K_LOOK_DOWN, down);
                break;
            case XK_Return:
            case XK_KP_Enter:
            case XK_space: hol__x11_key(keys, &keys->confirm, HOL_X11_K_CONFIRM, down); break;
            case XK_p: hol__x11_key(keys, &keys->menu, HOL_X11_K_MENU, down); break;
            case XK_r: hol__x11_key(keys, &keys->restart, HOL_X11_K_RESTART, down); break;
            case XK_m: hol__x11_key(keys, &keys->minimap, HOL_X11_K_MINIMAP, down); break;
            case XK_F3: hol__x11_key(keys, &keys->debug, HOL_X11_K_DEBUG, down); break;
            case XK_F2: hol__x11_key(keys, &keys->stats, HOL_X11_K_STATS, down); break;
            default: break;
            }
        }
    }
    if (hol__x11_error || hol__x11_lost)
        x->closed = 1;
    return run && !x->closed;
}

#endif
