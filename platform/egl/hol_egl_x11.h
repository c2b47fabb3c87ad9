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
 *   is pressed.
 * - On failure hol_x11_create returns nonzero with a one-line reason in
 *   err and leaves nothing open.
 */
#ifndef HOL_EGL_X11_H
#define HOL_EGL_X11_H

#include <EGL/egl.h>
#include <EGL/eglext.h>
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
} hol_x11;

/* Keys held down (1) or not (0); the mouse moved by (mouse_dx, mouse_dy)
 * pixels with the left button held since the caller last zeroed them;
 * focused: the window has the keyboard focus (1 until told otherwise). */
typedef struct hol_x11_keys {
    int left, right, up, down, strafe_l, strafe_r, look_up, look_down;
    int confirm, menu, restart, minimap; /* Enter/Space, P, R, M */
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
    if (x->dpy) {
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
    return 0;
}

static inline void hol_x11_swap(hol_x11 *x)
{
    eglSwapBuffers(x->edpy, x->surf);
}

/* Drain pending events into keys; 0 when the user asked to quit. */
static inline int hol_x11_poll(hol_x11 *x, hol_x11_keys *keys)
{
    int run = 1;
    while (XPending(x->dpy)) {
        XEvent ev;
        XNextEvent(x->dpy, &ev);
        if (ev.type == ClientMessage && (Atom)ev.xclient.data.l[0] == x->wm_delete)
            run = 0;
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
        } else if (ev.type == KeyPress || ev.type == KeyRelease) {
            int down = ev.type == KeyPress;
            KeySym k = XLookupKeysym(&ev.xkey, 0);
            switch (k) {
            case XK_Escape:
            case XK_q: if (down) run = 0; break;
            case XK_Left: keys->left = down; break;
            case XK_Right: keys->right = down; break;
            case XK_Up: case XK_w: keys->up = down; break;
            case XK_Down: case XK_s: keys->down = down; break;
            case XK_a: keys->strafe_l = down; break;
            case XK_d: keys->strafe_r = down; break;
            case XK_Page_Up: keys->look_up = down; break;
            case XK_Page_Down: keys->look_down = down; break;
            case XK_Return: case XK_space: keys->confirm = down; break;
            case XK_p: keys->menu = down; break;
            case XK_r: keys->restart = down; break;
            case XK_m: keys->minimap = down; break;
            default: break;
            }
        }
    }
    return run;
}

#endif
